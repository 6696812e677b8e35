//! Each frame's cheapest lossless encoding: a few ways to write the same picture are
//! compressed, and the fewest bytes win. The choice depends only on the frame's pixels, so
//! the output is the same on any number of threads.
//!
//! First the layouts, each with the plain LZW coder:
//! - the changed rectangle as it is, or with its mixed stretches of unchanged pixels
//!   transparent ([`super::transparency`]), when an index is free to mean that and the
//!   marking leaves at least [`MIN_RUNS_SAVED`] fewer runs of one index (else it is skipped);
//! - each in normal or interlaced row order ([`super::interlace`]).
//!
//! Then the winning layout once more with a small dictionary ([`Choices::SMALL`]), when its
//! first coding used more codes than that (else the two are the same); that coding starts
//! where the first one's dictionary reached the small size, since up to there the two write
//! the same bytes. Every candidate uses the smallest code size its indices allow, and gives
//! up as soon as it is no smaller than the best so far.

use std::mem::swap;

use super::interlace::interlace;
use super::lzw::{min_code_size, Choices, Fork, Lzw};
use super::transparency::{mark_mixed_stretches, transparent_index};

/// How a frame was encoded, for its header.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Encoding {
    /// The index that means "unchanged, show what is beneath", if the encoding uses one.
    pub transparent: Option<u8>,
    /// Whether the rows are stored in interlaced order.
    pub interlaced: bool,
}

/// One thread's tools for choosing and compressing, kept for the whole run so that no frame
/// allocates once warmed up: the LZW coder and scratch buffers.
#[derive(Default)]
pub struct Coder {
    lzw: Lzw,
    /// A layout's indices, in normal row order.
    layout: Vec<u8>,
    /// The same in interlaced order.
    interlaced: Vec<u8>,
    /// The winning layout so far, in the order it is stored.
    winner: Vec<u8>,
    /// A candidate's compressed bytes.
    candidate: Vec<u8>,
}

impl Coder {
    /// Compresses `current`, a rectangle `width` px wide of indices into a table of
    /// `table_len` colours, into `best` in as few bytes as the candidates allow. `beneath`
    /// is what the viewer shows under the rectangle (the same size), or `None` for the first
    /// frame, which has nothing to show through.
    pub fn encode_cheapest(
        &mut self,
        current: &[u8],
        width: usize,
        beneath: Option<&[u8]>,
        table_len: usize,
        best: &mut Vec<u8>,
    ) -> Encoding {
        let transparent =
            beneath.and_then(|under| Some((under, transparent_index(current, under, table_len)?)));
        let mut chosen = Encoding::default();
        let mut code_size = 0;
        let mut budget = usize::MAX;
        let mut winner_fork: Option<Fork> = None;
        for marked in std::iter::once(None).chain(transparent.map(Some)) {
            let largest_index = match marked {
                None => {
                    self.layout.clear();
                    self.layout.extend_from_slice(current);
                    largest(current)
                }
                Some((under, index)) => {
                    // Nothing marked is the layout already tried.
                    if mark_mixed_stretches(current, under, index, &mut self.layout) == 0
                        || !saves_runs(runs(current), runs(&self.layout))
                    {
                        continue;
                    }
                    largest(&self.layout).max(index)
                }
            };
            let size = min_code_size(usize::from(largest_index) + 1);
            interlace(&self.layout, width, &mut self.interlaced);
            for interlaced in [false, true] {
                let pixels = if interlaced {
                    &self.interlaced
                } else {
                    &self.layout
                };
                let plain = Choices::GREEDY;
                let coded = self
                    .lzw
                    .compress(size, pixels, plain, budget, &mut self.candidate);
                if coded.is_some() {
                    swap(best, &mut self.candidate);
                    budget = best.len();
                    winner_fork = self.lzw.fork();
                    self.winner.clone_from(pixels);
                    code_size = size;
                    chosen = Encoding {
                        transparent: marked.map(|(_, index)| index),
                        interlaced,
                    };
                }
            }
        }
        if let Some(fork) = winner_fork {
            let coded = self.lzw.compress_small_from(
                fork,
                code_size,
                &self.winner,
                best,
                budget,
                &mut self.candidate,
            );
            if coded.is_some() {
                swap(best, &mut self.candidate);
            }
        }
        chosen
    }
}

/// The share of a frame's runs that marking must remove before the marked layout is coded:
/// one in a hundred. Marking that removes fewer never won on a bundled scene (docs/gif.md),
/// and coding it costs two more passes.
pub const MIN_RUNS_SAVED: f64 = 0.01;

/// Whether going from `before` runs to `after` removes at least [`MIN_RUNS_SAVED`] of them.
fn saves_runs(before: usize, after: usize) -> bool {
    (after as f64) <= (before as f64) * (1.0 - MIN_RUNS_SAVED)
}

/// How many runs of one index `pixels` holds.
fn runs(pixels: &[u8]) -> usize {
    1 + pixels.windows(2).filter(|pair| pair[0] != pair[1]).count()
}

/// The largest index in `pixels` (0 for none).
fn largest(pixels: &[u8]) -> u8 {
    pixels.iter().copied().max().unwrap_or(0)
}
