#!/bin/sh
# Rewrites every picture under docs/img/ (run from the repository's root):
# the accuracy study's two plots, then the --plot pictures of the runs that
# tests/docs_images.rs lists. The test then checks that they are current.
set -e
cargo run --release --example accuracy -- docs/img
UPDATE_GOLDEN=1 cargo test --release --test docs_images
cargo test --release --test docs_images
