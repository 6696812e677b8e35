//! Unchanged pixels as transparent: a frame's rectangle laid over the last frame may leave
//! any pixel that did not change transparent, and the viewer still shows the same picture.
//!
//! Which unchanged pixels to make transparent is a bet on LZW: a transparent stretch can
//! join runs that were different colours, but it can also cut a run of one colour in two
//! (the background around a moving ball is unchanged on one side of it and changed on the
//! other). So, as gifsicle does, only stretches of unchanged pixels that hold more than one
//! colour become transparent; a stretch of one colour stays that colour, so it can run on
//! into changed pixels of the same colour. Where what stays is more varied than what changes
//! (a heap of resting balls round a few moving ones), marking every unchanged pixel pays
//! instead; it never does on a flat background. The encoder keeps a marking only when it
//! compresses smaller.
//!
//! Knows rectangles of palette indices (this frame's and the last one's), nothing of GIF.

/// Writes `current` into `out` (cleared first) with every stretch of unchanged pixels (in
/// reading order, across rows) that holds more than one colour set to `transparent`.
/// `beneath` is what lies under `current`, the same size. Returns how many pixels it marked.
pub fn mark_mixed_stretches(
    current: &[u8],
    beneath: &[u8],
    transparent: u8,
    out: &mut Vec<u8>,
) -> usize {
    out.clear();
    out.extend_from_slice(current);
    let mut marked = 0;
    let mut at = 0;
    while at < current.len() {
        if current[at] != beneath[at] {
            at += 1;
            continue;
        }
        let (start, first) = (at, current[at]);
        let mut mixed = false;
        while at < current.len() && current[at] == beneath[at] {
            mixed |= current[at] != first;
            at += 1;
        }
        if mixed {
            out[start..at].fill(transparent);
            marked += at - start;
        }
    }
    marked
}

/// Writes `current` into `out` (cleared first) with every unchanged pixel set to
/// `transparent`: the better marking when what stays the same is more varied than what
/// changes (a heap of resting balls round a few moving ones). Returns how many it marked.
pub fn mark_unchanged(current: &[u8], beneath: &[u8], transparent: u8, out: &mut Vec<u8>) -> usize {
    out.clear();
    let mut marked = 0;
    out.extend(current.iter().zip(beneath).map(|(&now, &before)| {
        if now == before {
            marked += 1;
            transparent
        } else {
            now
        }
    }));
    marked
}

/// How many neighbouring pairs of pixels (in reading order) are both unchanged and of two
/// colours: marking removes at most this many runs, so it is the cheap test of whether
/// marking can pay at all (on the lesson it never can).
pub fn mixed_neighbours(current: &[u8], beneath: &[u8]) -> usize {
    count_neighbours(current, beneath, |[now, next, under_now, under_next]| {
        (now == under_now) & (next == under_next) & (now != next)
    })
}

/// How many neighbouring pixels `i`, `i + 1` (in reading order) make `pair` true, given
/// `[current[i], current[i + 1], beneath[i], beneath[i + 1]]`. Counted in blocks of 255
/// pairs, so each block's sum fits a byte and the compiler counts many pairs per instruction.
pub(crate) fn count_neighbours(
    current: &[u8],
    beneath: &[u8],
    pair: impl Fn([u8; 4]) -> bool,
) -> usize {
    let len = current.len().min(beneath.len()).saturating_sub(1);
    if len == 0 {
        return 0; // no pair (and an empty row has no `[1..]`)
    }
    let (now, next) = (current[..len].chunks(255), current[1..=len].chunks(255));
    let (under_now, under_next) = (beneath[..len].chunks(255), beneath[1..=len].chunks(255));
    now.zip(next)
        .zip(under_now.zip(under_next))
        .map(|((now, next), (under_now, under_next))| {
            let block = now.iter().zip(next).zip(under_now.iter().zip(under_next));
            let hits = block.map(|((&a, &b), (&c, &d))| u8::from(pair([a, b, c, d])));
            usize::from(hits.sum::<u8>())
        })
        .sum()
}

/// The index to mark transparent: the lowest one that no changed pixel uses (a low index
/// keeps the frame's code size small), below `table_len`. `None` when changed pixels use
/// every index of the table.
pub fn transparent_index(current: &[u8], beneath: &[u8], table_len: usize) -> Option<u8> {
    let mut used = [false; 256];
    for (&now, &before) in current.iter().zip(beneath) {
        if now != before {
            used[usize::from(now)] = true;
        }
    }
    let free = used[..table_len.min(256)].iter().position(|&u| !u)?;
    u8::try_from(free).ok()
}
