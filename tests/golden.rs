//! Golden frames from the lesson: chosen frames of the default scene and of the single-ball
//! presets elastic, heavy and moon must equal, pixel for pixel, the PNGs the lesson's script
//! draws with Pillow (`tests/golden/`, made by `python3 tools/lesson.py bless`).

mod common;

use bouncing_ball::scene::file as scene_file;
use common::{assert_golden, lesson_scene, render_frames};

/// The frames `tools/lesson.py bless` writes (its GOLDEN_FRAMES).
const GOLDEN_FRAMES: [(&str, &[usize]); 4] = [
    ("lesson", &[0, 1, 57, 120, 199]),
    ("elastic", &[10, 100, 199]),
    ("heavy", &[10, 100, 199]),
    ("moon", &[10, 100, 199]),
];

#[test]
fn chosen_frames_equal_the_lesson_scripts_pngs_pixel_for_pixel() {
    for (name, wanted) in GOLDEN_FRAMES {
        let scene = if name == "lesson" {
            lesson_scene()
        } else {
            scene_file::preset(name, 1).unwrap()
        };
        let frames = render_frames(&scene);
        for &n in wanted {
            assert_golden(&format!("{name}_frame_{n:03}"), &frames[n]);
        }
    }
}
