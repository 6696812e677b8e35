//! Each frame's cheapest lossless encoding: a few ways to write the same picture are
//! compressed, and the fewest bytes win. The choice depends only on the frame's pixels, so
//! the output is the same on any number of threads.
//!
//! First the layouts, each with the plain LZW coder:
//! - the changed rectangle as it is; with its mixed stretches of unchanged pixels
//!   transparent; or with every unchanged pixel transparent ([`super::transparency`]). The
//!   mixed-stretch layout is tried when an index is free to mean transparent and the marking
//!   leaves at least [`MIN_RUNS_SAVED`] fewer runs of one index (else it is skipped); the
//!   every-pixel layout only after the mixed-stretch one was tried;
//! - each in normal or interlaced row order ([`super::interlace`]).
//!
//! Each also with a full dictionary kept to the end ([`Choices::KEEP_FULL`]) instead of
//! cleared, when the dictionary fills; and the winning layout with a small dictionary
//! ([`Choices::SMALL`]), when its coding held more than [`SMALL_DICTIONARY_FROM`] codes.
//! These start where the greedy coding's dictionary reached their size, since up to there
//! the two write the same bytes.
//! Every candidate uses the smallest code size its indices allow, and gives up as soon as it
//! is no smaller than the best so far.

use std::mem::swap;

use super::interlace::interlace;
use super::lzw::{min_code_size, Choices, Lzw};
use super::transparency::{
    count_neighbours, mark_mixed_stretches, mark_unchanged, mixed_neighbours, transparent_index,
};

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
    /// Made on the first frame, by the thread that codes (its 2 MB are written out then).
    lzw: Option<Lzw>,
    /// A marked layout's indices, in normal row order.
    layout: Vec<u8>,
    /// The same in interlaced order.
    interlaced: Vec<u8>,
    /// The winning layout so far, in the order it is stored, when the small dictionary is
    /// to be tried on it.
    winner: Vec<u8>,
    /// A candidate's compressed bytes, and another's made from the first part of them.
    candidate: Vec<u8>,
    other: Vec<u8>,
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
        let lzw = self.lzw.get_or_insert_with(Lzw::new);
        let runs_as_is = runs(current);
        // Marking removes at most one run per pair of neighbouring unchanged pixels of two
        // colours: when those are too few, no marked layout can pass its test, so none is made.
        let marking_can_pay = |under: &[u8]| {
            let at_best = runs_as_is.saturating_sub(mixed_neighbours(current, under));
            saves_runs(runs_as_is, at_best)
        };
        let transparent = beneath
            .filter(|under| marking_can_pay(under))
            .and_then(|under| Some((under, transparent_index(current, under, table_len)?)));
        let mut chosen = Encoding::default();
        let mut code_size = 0;
        let mut budget = usize::MAX;
        let mut winner_small_fork = None;
        let mut mixed_tried = false;
        for layout in [Layout::AsIs, Layout::MixedStretches, Layout::AllUnchanged] {
            let largest_index = match (layout, transparent) {
                (Layout::AsIs, _) => largest(current),
                (_, None) => continue,
                (_, Some((under, index))) => {
                    let marked = match layout {
                        Layout::MixedStretches => {
                            let marked =
                                mark_mixed_stretches(current, under, index, &mut self.layout);
                            if !saves_runs(runs_as_is, runs(&self.layout)) {
                                continue;
                            }
                            mixed_tried = true;
                            marked
                        }
                        // Where marking mixed stretches does not pay, marking more never did.
                        // (Marking every unchanged pixel seldom removes runs; it pays by making
                        // the rectangle's runs mostly one index, which LZW repeats well.)
                        _ if !mixed_tried => continue,
                        _ => mark_unchanged(current, under, index, &mut self.layout),
                    };
                    // Nothing marked is the layout already tried.
                    if marked == 0 {
                        continue;
                    }
                    largest(&self.layout).max(index)
                }
            };
            let size = min_code_size(usize::from(largest_index) + 1);
            let normal = match layout {
                Layout::AsIs => current,
                _ => &self.layout[..],
            };
            interlace(normal, width, &mut self.interlaced);
            for interlaced in [false, true] {
                let pixels = if interlaced { &self.interlaced } else { normal };
                let greedy = Choices::GREEDY;
                let coded = lzw.compress(size, pixels, greedy, budget, &mut self.candidate);
                let forks = lzw.forks();
                let mut won = coded.is_some();
                let mut codes = coded.unwrap_or(0);
                if won {
                    swap(best, &mut self.candidate);
                    budget = best.len();
                }
                // A dictionary kept full only differs once it fills (big frames), so it is
                // tried on every layout; a given-up coding still holds the bytes up to there.
                if let Some(fork) = forks.full {
                    let first = if won { &best[..] } else { &self.candidate[..] };
                    let keep_full = Choices::KEEP_FULL;
                    let coded = lzw.compress_from(
                        fork,
                        keep_full,
                        size,
                        pixels,
                        first,
                        budget,
                        &mut self.other,
                    );
                    if let Some(kept) = coded {
                        swap(best, &mut self.other);
                        budget = best.len();
                        won = true;
                        codes = kept;
                    }
                }
                if won {
                    winner_small_fork = forks.small.filter(|_| codes > SMALL_DICTIONARY_FROM);
                    if winner_small_fork.is_some() {
                        self.winner.clear();
                        self.winner.extend_from_slice(pixels);
                    }
                    code_size = size;
                    chosen = Encoding {
                        transparent: match layout {
                            Layout::AsIs => None,
                            _ => transparent.map(|(_, index)| index),
                        },
                        interlaced,
                    };
                }
            }
        }
        // The best coding's bytes are the greedy coding's up to the small fork.
        if let Some(fork) = winner_small_fork {
            let coded = lzw.compress_from(
                fork,
                Choices::SMALL,
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

/// The small dictionary is tried only on a frame whose best coding held more codes than
/// this, one and a half times its own size: on frames below it saved a few bytes at most
/// (the lesson's 200 frames: 29 B of 119 kB) for a sixth of the encoder's time.
pub const SMALL_DICTIONARY_FROM: u16 = 768;

/// Which pixels of the changed rectangle a layout writes as transparent.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Layout {
    /// None.
    AsIs,
    /// Stretches of unchanged pixels that hold more than one colour.
    MixedStretches,
    /// Every unchanged pixel.
    AllUnchanged,
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
    1 + count_neighbours(pixels, pixels, |[now, next, _, _]| now != next)
}

/// The largest index in `pixels` (0 for none).
fn largest(pixels: &[u8]) -> u8 {
    pixels.iter().copied().max().unwrap_or(0)
}
