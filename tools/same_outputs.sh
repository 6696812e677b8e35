#!/usr/bin/env bash
# Runs every preset, and the exact and RK4 variants of many, billiards and pile, with two
# builds of the program, and says which GIFs, PNGs and traces differ. Use it to show that a
# change keeps every byte (or which bytes it changes on purpose):
#
#   git worktree add ../before HEAD~1 && (cd ../before && cargo build --release)
#   cargo build --release
#   bash tools/same_outputs.sh ../before/target/release/bouncing_ball target/release/bouncing_ball
#
# Writes only inside a temporary folder; exits 1 if anything differs.
set -euo pipefail
before=$(realpath "$1")
after=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

runs=()
for preset in $(cd "$(dirname "$0")/../scenes" && ls -- *.toml | sed 's/\.toml$//'); do
    runs+=("$preset|--preset $preset")
done
for preset in many billiards pile; do
    runs+=("$preset-exact|--preset $preset --collisions exact --integrator velocity-verlet")
    runs+=("$preset-rk4|--preset $preset --integrator rk4 --substeps 3")
    runs+=("$preset-rk4-exact|--preset $preset --collisions exact --integrator rk4")
done

differ=0
for run in "${runs[@]}"; do
    name=${run%%|*}
    flags=${run#*|}
    for build in before after; do
        mkdir -p "$work/$build"
        binary=$before
        [ "$build" = after ] && binary=$after
        # shellcheck disable=SC2086 # the flags are words
        (cd "$work/$build" && "$binary" $flags -q --gif "$name.gif" --png "$name.png" --trace "$name.csv")
    done
    for file in "$name.gif" "$name.png" "$name.csv"; do
        if ! cmp -s "$work/before/$file" "$work/after/$file"; then
            echo "differs: $file ($flags)"
            differ=1
        fi
    done
done
if [ "$differ" = 0 ]; then
    echo "same: every GIF, PNG and trace of ${#runs[@]} runs"
fi
exit "$differ"
