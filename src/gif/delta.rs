//! What changed between two frames: the smallest rectangle holding every changed pixel
//! (of the whole frame, or of the areas the renderer drew again), cut out to be laid over
//! the previous frame.
//!
//! Knows frames of palette indices, nothing of balls and nothing of GIF.

pub use crate::render::dirty::{paste, Rect};
use crate::render::IndexedFrame;
use crate::work::{tally_many, Work};

/// The smallest rectangle outside which `previous` and `current` are equal; `None` when the
/// two frames are identical. Both must be the same size.
pub fn changed_rect(previous: &IndexedFrame, current: &IndexedFrame) -> Option<Rect> {
    changed_rect_within(previous, current, Rect::whole(current))
}

/// The smallest rectangle holding every pixel of `area` where `previous` and `current`
/// differ; `None` when they are equal there. Pixels outside `area` are not looked at.
pub fn changed_rect_within(
    previous: &IndexedFrame,
    current: &IndexedFrame,
    area: Rect,
) -> Option<Rect> {
    tally_many(Work::PixelsCompared, area.area());
    let rows = area.rows(current.width()).map(|span| {
        let old = &previous.as_raw()[span.clone()];
        (old, &current.as_raw()[span])
    });
    let width = area.width as usize;
    // Columns left..right and rows top..bottom of `area` hold every change seen so far.
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
        left: area.left + left as u32,
        top: area.top + top as u32,
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
pub(crate) fn crop(frame: &IndexedFrame, rect: Rect, out: &mut Vec<u8>) {
    out.clear();
    for span in rect.rows(frame.width()) {
        out.extend_from_slice(&frame.as_raw()[span]);
    }
}
