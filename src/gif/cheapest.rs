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
//! - each in normal and in interlaced row order ([`super::interlace`]), in that order, so
//!   that the normal order wins a tie.
//!
//! Each also with a full dictionary kept to the end ([`Choices::KEEP_FULL`]) instead of
//! cleared, when the dictionary fills; and the winning layout with half the dictionary
//! ([`Choices::HALF`]), on the first frame when its coding reached that size, and with a
//! small dictionary ([`Choices::SMALL`]), when its coding held more than
//! [`SMALL_DICTIONARY_FROM`] codes.
//! These start where the greedy coding's dictionary reached their size, since up to there
//! the two write the same bytes.
//! Every candidate uses the smallest code size its indices allow, and gives up as soon as it
//! is no smaller than the best so far.

use std::mem::swap;

use super::interlace::interlace;
use super::lzw::{min_code_size, Choices, Fork, Lzw};
use super::transparency::{
    count_neighbours, mark_mixed_stretches, mark_unchanged, mixed_neighbours, transparent_index,
};

/// How a frame was encoded, for its header.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Encoding {
    /// The index that means "unchanged, show what is beneath", if the encoding uses one.
    pub transparent: Option<u8>,
    /// Whether the rows are stored in interlaced order.
    pub interlaced: bool,
}

/// One thread's tools for choosing and compressing, kept for the whole run so that no frame
/// allocates once warmed up: the LZW coder and scratch buffers.
#[derive(Default)]
pub(crate) struct Coder {
    /// The LZW coder. Made on the first frame, by the thread that codes (its table is
    /// written out then, 2 MB at most).
    lzw: Option<Lzw>,
    /// A marked layout's indices, in normal row order.
    layout: Vec<u8>,
    /// The same in interlaced order.
    interlaced: Vec<u8>,
    /// The winning layout so far, in the order it is stored, when the small dictionary is
    /// to be tried on it.
    winner: Vec<u8>,
    /// A row order's compressed bytes, and another candidate's made from the first part of
    /// them.
    candidate: Vec<u8>,
    other: Vec<u8>,
}

impl Coder {
    /// Compresses `current`, a rectangle `width` px wide of indices into a table of
    /// `table_len` colours, into `best` in as few bytes as the candidates allow. `beneath`
    /// is what the viewer shows under the rectangle (the same size), or `None` for the first
    /// frame, which has nothing to show through.
    pub(crate) fn encode_cheapest(
        &mut self,
        current: &[u8],
        width: usize,
        beneath: Option<&[u8]>,
        table_len: usize,
        best: &mut Vec<u8>,
    ) -> Encoding {
        // The coder's parts one by one, so that the search can use the coder and its
        // buffers while a marked layout is read from `layout`.
        let Coder {
            lzw,
            layout,
            interlaced,
            winner,
            candidate,
            other,
        } = self;
        let mut search = Search {
            lzw: lzw.get_or_insert_with(Lzw::new),
            winner,
            candidate,
            other,
            best,
            budget: usize::MAX,
            encoding: Encoding::default(),
            first_frame: beneath.is_none(),
            half_fork: None,
            small_fork: None,
        };
        search.code_layout(current, width, None, interlaced);
        if let Some(marking) = Marking::worth_trying(current, beneath, table_len) {
            let Marking { under, index, .. } = marking;
            let marked = mark_mixed_stretches(current, under, index, layout);
            // Where marking mixed stretches does not pay, marking more never did. (Marking
            // every unchanged pixel seldom removes runs; it pays by making the rectangle's
            // runs mostly one index, which LZW repeats well.)
            if marking.saves_runs(layout) {
                // A layout with nothing marked is the one already tried.
                if marked > 0 {
                    search.code_layout(layout, width, Some(index), interlaced);
                }
                if mark_unchanged(current, under, index, layout) > 0 {
                    search.code_layout(layout, width, Some(index), interlaced);
                }
            }
        }
        search.try_smaller_dictionaries()
    }
}

/// What the marked layouts are made from: the picture beneath the rectangle, the index that
/// means transparent, and how many runs of one index the rectangle holds unmarked.
#[derive(Clone, Copy)]
struct Marking<'a> {
    under: &'a [u8],
    index: u8,
    runs_as_is: usize,
}

impl<'a> Marking<'a> {
    /// The marking of `current` over `beneath`, or `None` when there is nothing beneath, no
    /// marked layout could remove enough runs, or no index is free to mean transparent.
    fn worth_trying(
        current: &[u8],
        beneath: Option<&'a [u8]>,
        table_len: usize,
    ) -> Option<Marking<'a>> {
        let under = beneath?;
        let runs_as_is = runs(current);
        // Marking removes at most one run per pair of neighbouring unchanged pixels of two
        // colours: when those are too few, no marked layout can pass its test, so none is made.
        let at_best = runs_as_is.saturating_sub(mixed_neighbours(current, under));
        if !saves_runs(runs_as_is, at_best) {
            return None;
        }
        let index = transparent_index(current, under, table_len)?;
        Some(Marking {
            under,
            index,
            runs_as_is,
        })
    }

    /// Whether the marked `layout` holds at least [`MIN_RUNS_SAVED`] fewer runs than the
    /// rectangle as it is: only then is it worth coding.
    fn saves_runs(&self, layout: &[u8]) -> bool {
        saves_runs(self.runs_as_is, runs(layout))
    }
}

/// One frame's search for its smallest coding: the coder and buffers it borrows, and the
/// best coding so far. Every candidate gives up once it is no smaller than the best.
struct Search<'a> {
    /// The LZW coder, which codes every candidate in turn.
    lzw: &'a mut Lzw,
    /// The winning layout so far, when a smaller dictionary is to be tried on it.
    winner: &'a mut Vec<u8>,
    /// A row order's compressed bytes, and another candidate's made from the first part of
    /// them.
    candidate: &'a mut Vec<u8>,
    other: &'a mut Vec<u8>,
    /// The best coding's bytes.
    best: &'a mut Vec<u8>,
    /// Where a candidate gives up: the best's length, or no limit before the first.
    budget: usize,
    /// How the best coding is encoded, for the frame's header.
    encoding: Encoding,
    /// Whether this is the first frame, the whole canvas (nothing beneath it).
    first_frame: bool,
    /// Where the best's greedy coding reached half the dictionary's size, and the small
    /// dictionary's, when each is worth trying on it.
    half_fork: Option<Fork>,
    small_fork: Option<Fork>,
}

impl Search<'_> {
    /// Codes one layout, `normal` in normal row order, in both row orders. `transparent` is
    /// the index the layout marks unchanged pixels with, if any; `interlaced` is scratch.
    fn code_layout(
        &mut self,
        normal: &[u8],
        width: usize,
        transparent: Option<u8>,
        interlaced: &mut Vec<u8>,
    ) {
        let largest_index = largest(normal).max(transparent.unwrap_or(0));
        let code_size = min_code_size(usize::from(largest_index) + 1);
        interlace(normal, width, interlaced);
        // The normal order first: it wins a tie.
        for (pixels, is_interlaced) in [(normal, false), (&interlaced[..], true)] {
            let choices = Choices::GREEDY;
            let greedy = self
                .lzw
                .compress(code_size, pixels, choices, self.budget, self.candidate);
            let encoding = Encoding {
                transparent,
                interlaced: is_interlaced,
            };
            self.take_candidate(pixels, greedy, encoding);
        }
    }

    /// Takes the greedy coding of `pixels` just made (`greedy`: the most codes its
    /// dictionary held, if it finished within the budget), and codes it again with the full
    /// dictionary kept if it filled; whichever is smaller than the best becomes the best,
    /// encoded as `encoding`.
    fn take_candidate(&mut self, pixels: &[u8], greedy: Option<u16>, encoding: Encoding) {
        let forks = self.lzw.forks();
        if greedy.is_some() {
            swap(self.best, self.candidate);
            self.budget = self.best.len();
        }
        // A dictionary kept full only differs once it fills (big frames), so it is tried on
        // every layout.
        let kept_full = forks
            .full
            .and_then(|fork| self.keep_full(fork, pixels, greedy.is_some()));
        // The most codes the winning coding's dictionary held, if it won.
        let Some(codes) = kept_full.or(greedy) else {
            return;
        };
        // Half the dictionary is tried on the first frame only, the whole canvas, often empty
        // above and busy below (a pile, a pyramid): tried on every big frame, it won on 4 of
        // the 29 of `pile` and on none of the 197 of `many`, for 2 to 4 % more work.
        self.half_fork = forks.half.filter(|_| self.first_frame);
        self.small_fork = forks.small.filter(|_| codes > SMALL_DICTIONARY_FROM);
        // (A coding that reached half the size held more codes than the small threshold.)
        if self.small_fork.is_some() {
            self.winner.clear();
            self.winner.extend_from_slice(pixels);
        }
        self.encoding = encoding;
    }

    /// Codes `pixels` with the full dictionary kept, from `fork`, where their greedy coding
    /// first filled it, and keeps it if it is the smallest. The greedy coding is the best
    /// when `greedy_won`, else the candidate: a given-up coding still holds the bytes up to
    /// the fork. Returns the most codes the dictionary held, if it won.
    fn keep_full(&mut self, fork: Fork, pixels: &[u8], greedy_won: bool) -> Option<u16> {
        let first = if greedy_won {
            &self.best[..]
        } else {
            &self.candidate[..]
        };
        let choices = Choices::KEEP_FULL;
        let coded =
            self.lzw
                .compress_from(fork, choices, pixels, first, self.budget, self.other)?;
        swap(self.best, self.other);
        self.budget = self.best.len();
        Some(coded)
    }

    /// Codes the winning layout again with half the dictionary and with the small one, each
    /// from its greedy coding's fork, and keeps whichever is smallest. Returns how the best
    /// coding is encoded.
    fn try_smaller_dictionaries(mut self) -> Encoding {
        // The best coding's bytes are the greedy coding's up to the half fork, and the small
        // fork comes earlier: so they still are up to there once half the dictionary won.
        for (choices, fork) in [
            (Choices::HALF, self.half_fork),
            (Choices::SMALL, self.small_fork),
        ] {
            let Some(fork) = fork else {
                continue;
            };
            // (A fork into a smaller dictionary needs none of the one it forks from.)
            let coded = self.lzw.compress_from(
                fork,
                choices,
                self.winner,
                self.best,
                self.budget,
                self.other,
            );
            if coded.is_some() {
                swap(self.best, self.other);
                self.budget = self.best.len();
            }
        }
        self.encoding
    }
}

/// The small dictionary is tried only on a frame whose best coding held more codes than
/// this, one and a half times its own size: on frames below it saved a few bytes at most
/// (the lesson's 200 frames: 29 B of 119 kB) for a sixth of the encoder's time.
pub(crate) const SMALL_DICTIONARY_FROM: u16 = 768;

/// The share of a frame's runs that marking must remove before the marked layout is coded:
/// one in a hundred. Marking that removes fewer never won on a bundled scene (docs/gif.md),
/// and coding it costs two more passes.
pub(crate) const MIN_RUNS_SAVED: f64 = 0.01;

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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::random::Random;

    #[test]
    fn a_tie_between_the_row_orders_goes_to_the_normal_order() {
        // One index throughout: both orders read the same pixels and code to the same bytes.
        let frame = vec![3; 64 * 64];
        let mut best = Vec::new();
        let encoding = Coder::default().encode_cheapest(&frame, 64, None, 16, &mut best);
        assert_eq!(
            encoding,
            Encoding::default(),
            "normal order, nothing transparent"
        );
    }

    #[test]
    fn a_frame_whose_first_part_holds_the_rest_keeps_its_full_dictionary() {
        // Noise fills the dictionary, and the same noise again is coded best with the strings
        // it left there; cleared, the dictionary would learn them afresh.
        let mut random = Random::new(4);
        let part: Vec<u8> = (0..200 * 100)
            .map(|_| (random.next_u64() % 16) as u8)
            .collect();
        let frame = [&part[..], &part[..]].concat();
        let (mut lzw, mut greedy, mut kept) = (Lzw::new(), Vec::new(), Vec::new());
        lzw.compress(4, &frame, Choices::GREEDY, usize::MAX, &mut greedy);
        lzw.compress(4, &frame, Choices::KEEP_FULL, usize::MAX, &mut kept);
        assert!(kept.len() < greedy.len(), "the repeat is cheaper kept full");
        let mut best = Vec::new();
        Coder::default().encode_cheapest(&frame, 200, None, 16, &mut best);
        assert!(
            best.len() <= kept.len(),
            "{} B chosen, where the full dictionary kept takes {} B (cleared: {} B)",
            best.len(),
            kept.len(),
            greedy.len()
        );
    }
}
