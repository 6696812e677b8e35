//! What changed between two frames: the smallest rectangle holding every changed pixel,
//! cut out to be laid over the previous frame.
//!
//! Knows frames of palette indices, nothing of balls and nothing of GIF.

use std::ops::Range;

use crate::render::IndexedFrame;

/// A rectangle of a frame, px from the top-left corner.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rect {
    pub left: u32,
    pub top: u32,
    pub width: u32,
    pub height: u32,
}

impl Rect {
    /// The whole of `frame`.
    pub fn whole(frame: &IndexedFrame) -> Rect {
        Rect {
            left: 0,
            top: 0,
            width: frame.width(),
            height: frame.height(),
        }
    }

    /// The top-left pixel only: what a frame identical to the last one still writes, so
    /// that it still counts as a frame and keeps its time on screen.
    pub fn corner() -> Rect {
        Rect {
            left: 0,
            top: 0,
            width: 1,
            height: 1,
        }
    }

    /// Where each of its rows lies in the bytes of a frame `frame_width` px wide, top first.
    fn rows(self, frame_width: u32) -> impl Iterator<Item = Range<usize>> {
        let (width, left) = (frame_width as usize, self.left as usize);
        let top = self.top as usize;
        (top..top + self.height as usize).map(move |y| {
            let start = y * width + left;
            start..start + self.width as usize
        })
    }
}

/// The smallest rectangle outside which `previous` and `current` are equal; `None` when the
/// two frames are identical. Both must be the same size.
pub fn changed_rect(previous: &IndexedFrame, current: &IndexedFrame) -> Option<Rect> {
    let width = current.width() as usize;
    let rows = previous
        .as_raw()
        .chunks_exact(width)
        .zip(current.as_raw().chunks_exact(width));
    // Columns left..right and rows top..bottom hold every change seen so far.
    let (mut left, mut right) = (width, 0);
    let (mut top, mut bottom) = (None, 0);
    for (y, (old, new)) in rows.enumerate() {
        // Whole rows compare as one memcmp; most rows of a frame did not change.
        if old == new {
            continue;
        }
        top.get_or_insert(y);
        bottom = y + 1;
        // Only a change outside left..right can widen the rectangle, so only look there.
        if let Some(x) = first_difference(&old[..left], &new[..left]) {
            left = x;
        }
        let outside = right.max(left);
        if let Some(x) = last_difference(&old[outside..], &new[outside..]) {
            right = outside + x + 1;
        }
    }
    let top = top?;
    Some(Rect {
        left: left as u32,
        top: top as u32,
        width: (right - left) as u32,
        height: (bottom - top) as u32,
    })
}

/// Where `a` and `b` first differ. One memcmp answers the common case, that they do not;
/// otherwise whole 16-byte blocks are skipped before looking byte by byte.
fn first_difference(a: &[u8], b: &[u8]) -> Option<usize> {
    if a == b {
        return None;
    }
    let (a_blocks, b_blocks) = (a.as_chunks::<16>().0, b.as_chunks::<16>().0);
    let same = a_blocks.iter().zip(b_blocks).take_while(|(x, y)| x == y);
    let skip = 16 * same.count();
    let mut rest = a[skip..].iter().zip(&b[skip..]);
    rest.position(|(x, y)| x != y).map(|at| skip + at)
}

/// Where `a` and `b` last differ (likewise, from the end).
fn last_difference(a: &[u8], b: &[u8]) -> Option<usize> {
    if a == b {
        return None;
    }
    let (a_blocks, b_blocks) = (a.as_rchunks::<16>().1, b.as_rchunks::<16>().1);
    let same = a_blocks
        .iter()
        .zip(b_blocks)
        .rev()
        .take_while(|(x, y)| x == y);
    let end = a.len() - 16 * same.count();
    a[..end].iter().zip(&b[..end]).rposition(|(x, y)| x != y)
}

/// Copies `rect` of `frame` into `out` (cleared first), row after row.
pub fn crop(frame: &IndexedFrame, rect: Rect, out: &mut Vec<u8>) {
    out.clear();
    for span in rect.rows(frame.width()) {
        out.extend_from_slice(&frame.as_raw()[span]);
    }
}

/// Copies `rect` of `from` onto the same place in `onto` (both the same size).
pub fn paste(from: &IndexedFrame, rect: Rect, onto: &mut IndexedFrame) {
    let onto: &mut [u8] = onto;
    for span in rect.rows(from.width()) {
        onto[span.clone()].copy_from_slice(&from.as_raw()[span]);
    }
}
