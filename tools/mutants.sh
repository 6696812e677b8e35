#!/usr/bin/env bash
# Mutation testing, one group of files at a time (docs/tests.md has the scores). cargo-mutants
# changes one operator or return value at a time and runs the tests that could notice it; each
# group runs the library's unit tests and the test files that exercise its code, so that a
# mutant builds and tests in seconds rather than the whole suite's minute.
#
#   bash tools/mutants.sh lesson            # the lesson's physics: ball, floor, simulation
#   bash tools/mutants.sh render            # circles, trail and palette
#   bash tools/mutants.sh gif               # LZW, frame deltas, transparency
#   bash tools/mutants.sh solvers 0         # integrators, contacts, events: shard 0 of 4
#
# Extra arguments go to cargo-mutants (for example -j2, or --list). Results land in
# target/mutants-GROUP/mutants.out (GROUP-SHARD for the solvers) (caught.txt, missed.txt, timeout.txt, unviable.txt).
set -euo pipefail
cd "$(dirname "$0")/.."
group=${1:?usage: tools/mutants.sh lesson|render|gif|solvers SHARD [cargo-mutants args]}
shift

physics_tests="accuracy allocations ball collisions contacts exact_contacts floors golden lesson_pixels lesson_step
    off_canvas pitfalls presets properties scenes sleep stability unchanged_frames"
picture_tests="docs_images encode golden lesson_pixels off_canvas plot presets unchanged_frames"
sample=()
out=target/mutants-$group
case $group in
lesson)
    files=(src/physics/ball.rs src/physics/floor.rs src/physics/simulation.rs)
    tests=$physics_tests ;;
render)
    files=(src/render/ellipse.rs src/render/raster.rs src/render/palette.rs)
    tests=$picture_tests ;;
gif)
    files=(src/gif/lzw.rs src/gif/delta.rs src/gif/transparency.rs)
    tests="$picture_tests allocations" ;;
solvers)
    # About 1,700 mutants: a fixed sample of every 4th (round-robin shard SHARD of 4).
    shard=${1:?usage: tools/mutants.sh solvers SHARD (0 to 3)}
    shift
    files=('src/physics/integrate/**' 'src/physics/contacts/**' 'src/physics/events/**')
    sample=(--shard "$shard/4" --sharding round-robin)
    out=$out-$shard
    tests=$physics_tests ;;
*)
    echo "tools/mutants.sh: unknown group '$group' (lesson, render, gif or solvers)" >&2
    exit 2 ;;
esac

args=(--output "$out" --cargo-arg=--lib)
for test in $tests; do
    args+=("--cargo-arg=--test=$test")
done
for file in "${files[@]}"; do
    args+=(--file "$file")
done
exec cargo mutants "${args[@]}" "${sample[@]}" "$@"
