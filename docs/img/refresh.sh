#!/bin/sh
# Rewrites every picture under docs/img/ (run from the repository's root):
# the accuracy study's two plots, the --plot pictures of the runs that
# tests/docs_images.rs lists, and the README's sweep GIF (tests/sweep.rs).
# The tests then check that they are current.
set -e
cargo run --release --example accuracy -- docs/img
UPDATE_GOLDEN=1 cargo test --release --test docs_images
cargo test --release --test docs_images
UPDATE_GOLDEN=1 cargo test --release --test sweep the_readmes_sweep_gif
cargo test --release --test sweep the_readmes_sweep_gif
