#!/usr/bin/env bash
# Peak memory and wall time against the number of frames: the release binary, whole
# process, on the lesson's scene (the ball comes to rest, so late frames merge into one)
# and on the elastic preset (it bounces forever, so every frame has real work).
# Memory should stay flat and time grow in step with the frames. Wall times include
# starting /usr/bin/time itself; bench/benches/ and examples/bench_vs_python.rs time more finely.
#
# Usage: bench/memory.sh [RUNS]   (RUNS per point, median kept; default 3)
# Needs GNU time at /usr/bin/time (Debian: apt-get install -y time).
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
if [ ! -x /usr/bin/time ]; then
    echo "needs GNU time at /usr/bin/time (Debian: apt-get install -y time)" >&2
    exit 1
fi
cargo build --release --quiet
bin="$PWD/target/release/bouncing_ball"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "| scene   |  frames | wall (ms) | per frame (µs) | peak RSS (MB) | GIF bytes |"
echo "|---------|--------:|----------:|---------------:|--------------:|----------:|"
for preset in lesson elastic; do
    for frames in 200 1000 10000 100000; do
        : > "$out/walls"
        : > "$out/rss"
        for _ in $(seq "$runs"); do
            start=$EPOCHREALTIME
            /usr/bin/time -f "%M" -o "$out/time" "$bin" --preset "$preset" --frames "$frames" \
                --quiet --gif "$out/a.gif" --png "$out/a.png"
            end=$EPOCHREALTIME
            awk -v a="$start" -v b="$end" 'BEGIN { print (b - a) * 1000 }' >> "$out/walls"
            cat "$out/time" >> "$out/rss"
        done
        wall_ms=$(median < "$out/walls")
        rss_kb=$(median < "$out/rss")
        awk -v p="$preset" -v f="$frames" -v ms="$wall_ms" -v kb="$rss_kb" -v bytes="$(wc -c < "$out/a.gif")" \
            'BEGIN { printf "| %-7s | %7d | %9.1f | %14.1f | %13.1f | %9d |\n", p, f, ms, ms * 1000 / f, kb / 1024, bytes }'
    done
done
