//! Circle outlines, one pixel wide: where a ball should be, drawn over where it is (the
//! reference in `bouncing_ball compare`). The lesson draws only solid circles
//! ([`super::ellipse`]); an outline lets the ball beneath show through.

use super::ellipse::MAX_DIAMETER;
use super::palette::IndexedFrame;

/// Sets the pixels on the circle of centre `(x, y)` and `radius` (px, floats) to `index`:
/// in every column the circle crosses, the two pixels it passes through, and the same in
/// every row, so steep and flat parts alike are unbroken. Only the columns and rows on the
/// canvas are visited, so a circle far off it costs nothing.
pub(crate) fn outline_circle(frame: &mut IndexedFrame, x: f64, y: f64, radius: f64, index: u8) {
    if !(x.is_finite() && y.is_finite() && radius > 0.0 && 2.0 * radius < MAX_DIAMETER) {
        return;
    }
    let centre = [x, y];
    let size = [f64::from(frame.width()), f64::from(frame.height())];
    // Axis 0 walks the columns and finds the circle's two rows in each; axis 1 the rows.
    for axis in [0, 1] {
        let (along, across) = (centre[axis], centre[1 - axis]);
        let first = (along - radius).floor().max(0.0);
        let last = (along + radius).floor().min(size[axis] - 1.0);
        let mut at = first;
        while at <= last {
            let offset = at + 0.5 - along;
            let half = (radius * radius - offset * offset).max(0.0).sqrt();
            for edge in [(across - half).floor(), (across + half).floor()] {
                if (0.0..size[1 - axis]).contains(&edge) {
                    let mut pixel = [0u32; 2];
                    pixel[axis] = at as u32;
                    pixel[1 - axis] = edge as u32;
                    frame.put_pixel(pixel[0], pixel[1], image::Luma([index]));
                }
            }
            at += 1.0;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_outline_is_a_closed_ring_with_its_centre_left_alone() {
        let mut frame = IndexedFrame::new(40, 40);
        outline_circle(&mut frame, 20.0, 20.0, 10.0, 1);
        assert_eq!(frame.get_pixel(20, 20)[0], 0, "the centre stays clear");
        // Each row and column through the centre meets the ring twice, about 10 px out.
        for (x, y) in [(10, 20), (29, 20), (20, 10), (20, 29)] {
            assert_eq!(frame.get_pixel(x, y)[0], 1, "({x}, {y}) is on the ring");
        }
        let set = frame.pixels().filter(|p| p[0] == 1).count();
        // A one-pixel ring of radius 10 has about 2π·10 ≈ 63 pixels (a few more at the
        // diagonals, where columns and rows both put one).
        assert!((56..=90).contains(&set), "{set} pixels on the ring");
    }

    #[test]
    fn an_outline_off_the_canvas_draws_nothing() {
        let mut frame = IndexedFrame::new(10, 10);
        outline_circle(&mut frame, -1e30, 5.0, 4.0, 1);
        outline_circle(&mut frame, f64::NAN, 5.0, 4.0, 1);
        assert!(frame.pixels().all(|p| p[0] == 0));
    }
}
