//! Whether two pictures match: pixel by pixel, exactly by default, or within a colour
//! distance and a number of differing pixels, as Playwright's `toHaveScreenshot` and
//! pixelmatch allow for another renderer's anti-aliasing; and the picture of a difference.

use image::{Rgb, RgbImage};

use crate::render::dirty::Rect;
use crate::render::palette::{IndexedFrame, Palette};
use crate::render::to_rgb;

/// How far a handed-in picture may be from the expected one and still match.
#[derive(Clone, Copy, Debug, Default)]
pub struct Tolerance {
    /// The colour distance, 0 to 1, under which two pixels count as the same (pixelmatch's
    /// YIQ distance; 0: only the same colour).
    pub threshold: f64,
    /// How many pixels may differ.
    pub max_diff_pixels: Option<u64>,
    /// What share of the pixels may differ, 0 to 1.
    pub max_diff_pixel_ratio: Option<f64>,
}

impl Tolerance {
    /// Whether `differing` pixels of `total` are few enough (with both limits given, the
    /// smaller counts, as in Playwright).
    pub(crate) fn admits(&self, differing: u64, total: u64) -> bool {
        let by_ratio = self.max_diff_pixel_ratio.map(|r| r * total as f64);
        let most = match (self.max_diff_pixels.map(|n| n as f64), by_ratio) {
            (Some(a), Some(b)) => a.min(b),
            (a, b) => a.or(b).unwrap_or(0.0),
        };
        differing as f64 <= most
    }

    /// Pixelmatch's largest squared YIQ distance at this threshold (35215 is the greatest).
    fn max_delta(&self) -> f64 {
        35215.0 * self.threshold * self.threshold
    }
}

/// The pixels of a picture that differ from the expected one, and the box around them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Difference {
    pub pixels: u64,
    /// The first and last differing column and row.
    pub x: (u32, u32),
    pub y: (u32, u32),
}

/// What differs between the `expected` frame (palette indices) and `theirs` within
/// `region`, beyond the tolerance's colour distance; `None` if no pixel does.
pub(crate) fn difference(
    expected: &IndexedFrame,
    palette: &Palette,
    theirs: &RgbImage,
    tolerance: &Tolerance,
    region: Rect,
) -> Option<Difference> {
    let colours = palette.colours();
    let max_delta = tolerance.max_delta();
    let mut found: Option<Difference> = None;
    let (ours, their_bytes) = (expected.as_raw(), theirs.as_raw());
    for (y, row) in (region.top..).zip(region.rows(expected.width())) {
        let their_row = &their_bytes[row.start * 3..row.end * 3];
        for (x, (&index, their)) in
            (region.left..).zip(ours[row].iter().zip(their_row.chunks_exact(3)))
        {
            let (ours, their) = (colours[usize::from(index)], [their[0], their[1], their[2]]);
            if ours == their || !differs(ours, their, max_delta) {
                continue;
            }
            let d = found.get_or_insert(Difference {
                pixels: 0,
                x: (x, x),
                y: (y, y),
            });
            d.pixels += 1;
            d.x = (d.x.0.min(x), d.x.1.max(x));
            d.y.1 = y;
        }
    }
    found
}

/// Whether two colours are further apart than `max_delta`, pixelmatch's squared YIQ distance.
fn differs(a: [u8; 3], b: [u8; 3], max_delta: f64) -> bool {
    let [y, i, q] = yiq([0, 1, 2].map(|k| f64::from(a[k]) - f64::from(b[k])));
    0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q > max_delta
}

/// A colour (or a difference of colours) in YIQ: brightness, then two colour axes.
fn yiq([r, g, b]: [f64; 3]) -> [f64; 3] {
    [
        r * 0.29889531 + g * 0.58662247 + b * 0.11448223,
        r * 0.59597799 - g * 0.27417610 - b * 0.32180189,
        r * 0.21147017 - g * 0.52261711 + b * 0.31114694,
    ]
}

/// Expected | theirs | difference, side by side: the difference is the expected frame faded
/// towards white with the differing pixels in red, as pixelmatch draws it.
pub(crate) fn diff_picture(
    expected: &IndexedFrame,
    palette: &Palette,
    theirs: &RgbImage,
    tolerance: &Tolerance,
) -> RgbImage {
    let ours = to_rgb(expected, palette);
    let (width, height) = ours.dimensions();
    let max_delta = tolerance.max_delta();
    let mut picture = RgbImage::new(width * 3, height);
    for (x, y, &Rgb(colour)) in ours.enumerate_pixels() {
        let their = theirs.get_pixel(x, y).0;
        let marked = if colour != their && differs(colour, their, max_delta) {
            [255, 0, 0]
        } else {
            let luma = yiq(colour.map(f64::from))[0];
            let faded = (255.0 + (luma - 255.0) * 0.1) as u8;
            [faded; 3]
        };
        picture.put_pixel(x, y, Rgb(colour));
        picture.put_pixel(x + width, y, Rgb(their));
        picture.put_pixel(x + 2 * width, y, Rgb(marked));
    }
    picture
}
