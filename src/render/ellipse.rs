//! Solid circles drawn exactly as the lesson draws them: the pixels Pillow's
//! `ImageDraw.ellipse([x - r, y - r, x + r, y + r], fill=...)` fills, for float `x`, `y`, `r`.
//!
//! Pillow's rule (read in its `_imaging.c` and `libImaging/Draw.c`, written anew here):
//! 1. The float box is cut to whole pixels by truncation towards zero (C's `(int)`), so
//!    `-0.7` becomes `0`, not `-1`. The box spans `a = x1 - x0` by `b = y1 - y0` pixels.
//!    A box with `a = b = 0` fills nothing.
//! 2. On a grid of half pixels the outline of the ellipse `X²/a² + Y²/b² = 1` is traced
//!    through one quarter, from `(a, b mod 2)` up to `(a mod 2, b)`, in steps of 2 (so every
//!    point keeps the parity of `a` and `b`): each step goes up, diagonally up-left or left,
//!    whichever lands nearest the curve (the smallest `|b²X² + a²Y² - a²b²|`; ties prefer
//!    up, then diagonal).
//! 3. The first point the trace reaches on each grid row `Y` sets that row's half width
//!    `X`. Rows `±Y` are filled from column `x0 + (a - X) / 2` to `x0 + (a + X) / 2`,
//!    inclusive, on pixel rows `y0 + (b ± Y) / 2`.
//!
//! Only what is on the canvas costs anything: a circle whose box misses the canvas is
//! dismissed in floating point, before any conversion to integers, and each row is clipped
//! (to the canvas, or to a smaller rectangle when only part of a frame is drawn again).

use super::dirty::Rect;
use super::palette::IndexedFrame;
use crate::work::{tally_many, Work};

/// Circles this wide or wider are not drawn. A scene's radius is under half its canvas side
/// (at most 8,192 px), so this is never reached; it keeps the trace's sums of products
/// such as `a²Y²` (below 2.4e18) inside `i64`.
pub(crate) const MAX_DIAMETER: f64 = 32_768.0;

/// Fills the circle of centre `(x, y)` and radius `radius` (px, floats) with `index`,
/// pixel for pixel as Pillow's `ImageDraw.ellipse` fills its bounding box. A negative radius
/// (a box Pillow refuses) fills nothing.
pub fn fill_circle(frame: &mut IndexedFrame, x: f64, y: f64, radius: f64, index: u8) {
    if let Some(pixels) = PixelBox::of(x, y, radius, frame) {
        fill_box(frame, pixels, index, Rect::whole(frame));
    }
}

/// Fills the circle whose box of whole pixels is `pixels`, as [`fill_circle`] does, but only
/// where it lies inside `clip` (a rectangle of the canvas): drawn piece by piece, a circle
/// covers what it would whole.
pub(crate) fn fill_box(frame: &mut IndexedFrame, pixels: PixelBox, index: u8, clip: Rect) {
    let [x0, y0] = [pixels.x0, pixels.y0].map(i64::from);
    let [a, b] = [pixels.a, pixels.b].map(i64::from);
    let (left, top) = (i64::from(clip.left), i64::from(clip.top));
    let (right, bottom) = (left + i64::from(clip.width), top + i64::from(clip.height));
    let columns = i64::from(frame.width());
    let frame: &mut [u8] = frame;
    let mut fill_row = |row: i64, half_width: i64| {
        let first = (x0 + (a - half_width) / 2).max(left);
        let last = (x0 + (a + half_width) / 2).min(right - 1);
        if (top..bottom).contains(&row) && first <= last {
            let start = (row * columns) as usize;
            frame[start + first as usize..=start + last as usize].fill(index);
            tally_many(Work::PixelsDrawn, (last - first + 1) as u64);
        }
    };
    for (half_width, grid_row) in QuarterTrace::new(a, b) {
        fill_row(y0 + (b + grid_row) / 2, half_width);
        if grid_row != 0 {
            // Grid row 0 is the middle pixel row (of an even box): filled once, not twice.
            fill_row(y0 + (b - grid_row) / 2, half_width);
        }
    }
}

/// A circle's float box cut to whole pixels (rule 1): from column `x0`, row `y0`, spanning
/// `a` by `b` pixels (so columns `x0..=x0 + a`, rows `y0..=y0 + b`). Everything after rule 1
/// is whole numbers: two circles with the same box fill the same pixels, however their
/// centres and radii differ below a pixel.
///
/// Twelve bytes: a canvas remembers one for every circle it drew ([`super::redraw`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct PixelBox {
    x0: i32,
    y0: i32,
    a: u16,
    b: u16,
}

impl PixelBox {
    /// What a circle that fills nothing is remembered as: no circle that fills a pixel has
    /// this box (a box of 0 by 0 pixels fills nothing).
    pub(crate) const NOTHING: PixelBox = PixelBox {
        x0: 0,
        y0: 0,
        a: 0,
        b: 0,
    };

    /// The box of the circle of centre `(x, y)` and radius `radius` (px); `None` when the
    /// circle fills nothing on `frame`.
    pub(crate) fn of(x: f64, y: f64, radius: f64, frame: &IndexedFrame) -> Option<PixelBox> {
        let (width, height) = (f64::from(frame.width()), f64::from(frame.height()));
        let (left, right, top, bottom) = (x - radius, x + radius, y - radius, y + radius);
        // Truncation puts pixel 0 within reach of any edge above -1; NaN fails every test.
        let on_canvas = right > -1.0 && left < width && bottom > -1.0 && top < height;
        if !(on_canvas && (0.0..MAX_DIAMETER).contains(&(2.0 * radius))) {
            return None;
        }
        // Within 32,768 px of the canvas now, so `as` truncates towards zero exactly as C's
        // (int) does, the corner fits `i32` and the sides (at most 32,768) `u16`.
        let (x0, y0) = (left as i32, top as i32);
        let (a, b) = ((right as i32 - x0) as u16, (bottom as i32 - y0) as u16);
        (a != 0 || b != 0).then_some(PixelBox { x0, y0, a, b })
    }

    /// The part of the box on `frame`: every pixel the circle may fill. `None` when empty.
    pub(crate) fn on(self, frame: &IndexedFrame) -> Option<Rect> {
        if self == PixelBox::NOTHING {
            return None;
        }
        let [x0, y0] = [self.x0, self.y0].map(i64::from);
        let [a, b] = [self.a, self.b].map(i64::from);
        let (left, top) = (x0.max(0), y0.max(0));
        let right = (x0 + a + 1).min(i64::from(frame.width()));
        let bottom = (y0 + b + 1).min(i64::from(frame.height()));
        (left < right && top < bottom).then(|| Rect {
            left: left as u32,
            top: top as u32,
            width: (right - left) as u32,
            height: (bottom - top) as u32,
        })
    }
}

/// Pillow's trace of a quarter ellipse on the half-pixel grid (rule 2 above), yielding the
/// first point of each grid row: `(half width X, grid row Y)`, from `Y = b mod 2` up to `b`.
struct QuarterTrace {
    a2: i64,
    b2: i64,
    a2b2: i64,
    b: i64,
    x: i64,
    y: i64,
    done: bool,
}

impl QuarterTrace {
    fn new(a: i64, b: i64) -> QuarterTrace {
        QuarterTrace {
            a2: a * a,
            b2: b * b,
            a2b2: a * a * b * b,
            b,
            x: a,
            y: b % 2,
            done: false,
        }
    }

    /// How far the point `(x, y)` is off the curve.
    fn miss(&self, x: i64, y: i64) -> i64 {
        (self.a2 * y * y + self.b2 * x * x - self.a2b2).abs()
    }

    /// Follows the trace up to the next grid row: left while a left step lands nearest the
    /// curve, then up or diagonally up-left, whichever is nearer (up on a tie, and always up
    /// once at the axis).
    fn climb(&mut self) {
        while self.x > 1 {
            let up = self.miss(self.x, self.y + 2);
            let diagonal = self.miss(self.x - 2, self.y + 2);
            let left = self.miss(self.x - 2, self.y);
            if left < up.min(diagonal) {
                self.x -= 2;
                continue;
            }
            if diagonal < up {
                self.x -= 2;
            }
            break;
        }
        self.y += 2;
    }
}

impl Iterator for QuarterTrace {
    type Item = (i64, i64);

    fn next(&mut self) -> Option<(i64, i64)> {
        if self.done {
            return None;
        }
        let row_start = (self.x, self.y);
        if self.y >= self.b {
            self.done = true;
        } else {
            self.climb();
        }
        Some(row_start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn filled(side: u32, x: f64, y: f64, r: f64) -> Vec<(u32, u32)> {
        let mut frame = IndexedFrame::new(side, side);
        fill_circle(&mut frame, x, y, r, 1);
        frame
            .enumerate_pixels()
            .filter(|p| p.2[0] == 1)
            .map(|p| (p.0, p.1))
            .collect()
    }

    #[test]
    fn a_box_under_one_pixel_wide_and_tall_fills_nothing() {
        assert_eq!(filled(8, 3.5, 3.5, 0.2), vec![]);
    }

    #[test]
    fn a_negative_radius_fills_nothing() {
        assert_eq!(filled(8, 4.0, 4.0, -2.0), vec![]);
    }

    #[test]
    fn a_box_one_pixel_wide_fills_its_two_columns() {
        // Box [2.6, 3.4] x [2.6, 3.4] truncates to (2, 2)-(3, 3): a = b = 1, four pixels.
        assert_eq!(
            filled(8, 3.0, 3.0, 0.4),
            vec![(2, 2), (3, 2), (2, 3), (3, 3)]
        );
    }

    #[test]
    fn a_circle_whose_box_ends_short_of_the_canvas_or_is_too_wide_has_no_box() {
        // An 8 x 8 canvas. Truncation puts an edge above -1 on pixel 0, so a box whose right
        // edge is exactly -1 ends off the canvas, as does one starting exactly at column 8;
        // the same for rows. Each of these lies beside the canvas on one side only.
        let frame = IndexedFrame::new(8, 8);
        for (x, y, r) in [
            (-3.0, 4.0, 2.0),
            (10.0, 4.0, 2.0),
            (4.0, -3.0, 2.0),
            (4.0, 10.0, 2.0),
        ] {
            assert_eq!(PixelBox::of(x, y, r, &frame), None, "({x}, {y}) r {r}");
        }
        // Just inside those edges, a box.
        for (x, y, r) in [
            (-2.5, 4.0, 2.0),
            (9.5, 4.0, 2.0),
            (4.0, -2.5, 2.0),
            (4.0, 9.5, 2.0),
        ] {
            assert!(PixelBox::of(x, y, r, &frame).is_some(), "({x}, {y}) r {r}");
        }
        // A diameter of MAX_DIAMETER is too wide; just under it is drawn.
        let r = MAX_DIAMETER / 2.0;
        assert_eq!(PixelBox::of(4.0, 4.0, r, &frame), None, "r {r}");
        assert!(
            PixelBox::of(4.0, 4.0, r - 0.5, &frame).is_some(),
            "r {r} - 0.5"
        );
    }

    #[test]
    fn the_part_of_a_box_on_the_canvas_is_the_box_cut_to_the_canvas() {
        let frame = IndexedFrame::new(8, 8);
        let on = |x0, y0, a, b| PixelBox { x0, y0, a, b }.on(&frame);
        let rect = |left, top, width, height| Rect {
            left,
            top,
            width,
            height,
        };
        // Columns 2..=5 and rows 3..=4: inside, whole.
        assert_eq!(on(2, 3, 3, 1), Some(rect(2, 3, 4, 2)));
        // Columns 5..=9 and rows -2..=1: cut at the right and the top.
        assert_eq!(on(5, -2, 4, 3), Some(rect(5, 0, 3, 2)));
        // Ending at column -1 or row -1, or starting at column or row 8: nothing on it.
        for (x0, y0) in [(-3, 2), (2, -3), (8, 2), (2, 8)] {
            assert_eq!(on(x0, y0, 2, 2), None, "box at ({x0}, {y0})");
        }
    }

    #[test]
    fn negative_box_edges_truncate_towards_zero() {
        // Box [-0.9, 0.5] x [2.3, 3.7]: both x edges truncate to 0 (a = 0, b = 1), so a
        // column of two pixels, where rounding down would have drawn a 2 x 2 square.
        assert_eq!(filled(8, -0.2, 3.0, 0.7), vec![(0, 2), (0, 3)]);
    }
}
