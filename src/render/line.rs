//! Floor segments: a one-pixel line between two points, Bresenham's way, in single precision
//! as the imageproc crate draws it (so floors look as they always have). The lesson has no
//! floors, so there is no Pillow picture to match here.

use super::palette::IndexedFrame;

/// Sets every pixel of the line from `start` to `end` (px) that lies on `frame` to `index`.
/// It walks the longer axis one pixel at a time, so callers cut the line to the canvas first.
pub(crate) fn draw_line(frame: &mut IndexedFrame, start: (f32, f32), end: (f32, f32), index: u8) {
    let (mut x0, mut y0, mut x1, mut y1) = (start.0, start.1, end.0, end.1);
    // Walk along x; a steep line is walked with its axes swapped.
    let steep = (y1 - y0).abs() > (x1 - x0).abs();
    if steep {
        (x0, y0, x1, y1) = (y0, x0, y1, x1);
    }
    if x0 > x1 {
        (x0, y0, x1, y1) = (x1, y1, x0, y0);
    }
    let (dx, dy) = (x1 - x0, (y1 - y0).abs());
    let y_step = if y0 < y1 { 1 } else { -1 };
    let (mut y, mut error) = (y0 as i32, dx / 2.0);
    let (width, height) = (frame.width() as i32, frame.height() as i32);
    for x in (x0 as i32)..=(x1 as i32) {
        let (px, py) = if steep { (y, x) } else { (x, y) };
        if (0..width).contains(&px) && (0..height).contains(&py) {
            frame.put_pixel(px as u32, py as u32, image::Luma([index]));
        }
        // The error says when the line has drifted half a pixel off this row: step across.
        error -= dy;
        if error < 0.0 {
            y += y_step;
            error += dx;
        }
    }
}
