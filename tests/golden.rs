//! Golden frames: the default scene's frames 0, 1, 57, 120 and 199 must match the committed
//! PNGs pixel for pixel. Re-bless on purpose only: `UPDATE_GOLDEN=1 cargo test --test golden`.

mod common;

use common::{assert_golden, lesson_scene, render_frames};

#[test]
fn lesson_frames_match_the_golden_pngs_pixel_for_pixel() {
    let frames = render_frames(&lesson_scene());
    for n in [0, 1, 57, 120, 199] {
        assert_golden(&format!("lesson_frame_{n:03}"), &frames[n]);
    }
}
