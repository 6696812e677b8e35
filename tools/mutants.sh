#!/usr/bin/env bash
# Mutation testing, one group of files at a time (docs/tests.md has the scores). cargo-mutants
# changes one operator or return value at a time and runs the tests that could notice it. Each
# group runs the test files that exercise its code (and the library's unit tests where its
# files have some), so that a mutant builds and tests in seconds rather than the whole suite's
# minute:
#
#   bash tools/mutants.sh lesson            # the lesson's physics: ball, floor, simulation
#   bash tools/mutants.sh render            # circles and trail
#   bash tools/mutants.sh palette           # the frames' colour table
#   bash tools/mutants.sh gif               # LZW, frame deltas, transparency
#   bash tools/mutants.sh solvers 0         # integrators, contacts, events: shard 0 of 4
#
# Then what those tests missed is tried against the whole suite (all but the doctests); cargo
# mutants' --iterate skips what was caught:
#
#   bash tools/mutants.sh lesson --iterate --all-tests
#
# Extra arguments go to cargo-mutants (for example -j2, or --list). Results land in
# target/mutants-GROUP/mutants.out (target/mutants-solvers-SHARD/ for the solvers): caught.txt,
# missed.txt, timeout.txt, unviable.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
group=${1:?usage: tools/mutants.sh lesson|render|palette|gif|solvers SHARD [cargo-mutants args]}
shift

physics_tests="accuracy allocations ball collisions contacts exact_contacts floors golden lesson_pixels lesson_step
    off_canvas pitfalls presets properties scenes sleep stability unchanged_frames"
picture_tests="docs_images encode golden lesson_pixels off_canvas plot presets unchanged_frames"
sample=()
unit_tests=()
out=target/mutants-$group
case $group in
lesson)
    files=(src/physics/ball.rs src/physics/floor.rs src/physics/simulation.rs)
    tests=$physics_tests ;;
render)
    files=(src/render/ellipse.rs src/render/raster.rs)
    unit_tests=(--cargo-arg=--lib)
    tests=$picture_tests ;;
palette)
    files=(src/render/palette.rs)
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
    unit_tests=(--cargo-arg=--lib)
    tests=$physics_tests ;;
*)
    echo "tools/mutants.sh: unknown group '$group' (lesson, render, palette, gif or solvers)" >&2
    exit 2 ;;
esac

args=(--output "$out")
if [ "${1:-}" = --iterate ] && [ "${2:-}" = --all-tests ]; then
    # Every test but the doctests, on what the group's own tests missed.
    shift 2
    args+=(--iterate --cargo-arg=--lib --cargo-arg=--tests)
else
    args+=("${unit_tests[@]}")
    for test in $tests; do
        args+=("--cargo-arg=--test=$test")
    done
fi
for file in "${files[@]}"; do
    args+=(--file "$file")
done
exec cargo mutants "${args[@]}" "${sample[@]}" "$@"
