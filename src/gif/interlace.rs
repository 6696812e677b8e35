//! GIF's interlaced row order: rows 0, 8, 16, …, then 4, 12, …, then 2, 6, …, then the odd
//! rows. Meant for showing a coarse picture early on slow links; here it is only another
//! order for LZW to read the same pixels in, which sometimes compresses better (rows eight
//! apart often look more alike than neighbouring rows of a ball do). Every decoder puts the
//! rows back.

/// The four passes: first row and step.
const PASSES: [(usize, usize); 4] = [(0, 8), (4, 8), (2, 4), (1, 2)];

/// Copies the rows of `pixels` (rows `width` long) into `out`, cleared first, in interlaced
/// order.
pub fn interlace(pixels: &[u8], width: usize, out: &mut Vec<u8>) {
    out.clear();
    let rows = pixels.len() / width.max(1);
    for (first, step) in PASSES {
        for row in (first..rows).step_by(step) {
            out.extend_from_slice(&pixels[row * width..(row + 1) * width]);
        }
    }
}
