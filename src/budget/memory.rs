//! The memory model: the most a run's buffers can grow to, worked out from the scene alone
//! (before anything is allocated), so it errs on the high side.

use std::collections::HashMap;
use std::mem::size_of;

use super::pilot::PILOT_FRAMES;
use crate::gif::encoder::queue_frames;
use crate::physics::contacts::ContactSolver;
use crate::physics::events::system::EventDriven;
use crate::physics::motion::CollisionMode;
use crate::physics::replay::{frames_that_fit, BYTES_PER_BALL_FRAME};
use crate::physics::{Ball, Trail};
use crate::render::Canvas;
use crate::scene::{BallSpec, Rgb, Scene};

/// What the program itself takes before any scene: code, stacks, the threads' arenas and
/// their LZW coders (measured: 7 to 20 MB peak for the small presets).
const BASE_BYTES: u64 = 20 << 20;
/// Bytes per pixel of frame buffers outside the GIF queue: the frame being drawn, the
/// background it is cleared to, the frame the GIF shows, and at the end the RGB copy and the
/// PNG being compressed.
const FRAME_BYTES_PER_PIXEL: u64 = 7;
/// Bytes per queued GIF pixel: the cropped indices and their LZW codes (12-bit codes on
/// 8-bit pixels are at most 1.5 bytes each).
const QUEUED_BYTES_PER_PIXEL: f64 = 2.5;
/// The palette indices one ball is drawn with (a colour and a shared table of shades).
const STYLE_BYTES_PER_BALL: u64 = 24;

/// The memory `scene` needs at most, bytes, and the part that dominates it, for the message.
pub(crate) fn memory_of(scene: &Scene) -> (u64, &'static str) {
    let pixels = u64::from(scene.width) * u64::from(scene.height);
    let per_ball = (size_of::<BallSpec>() + size_of::<Ball>()) as u64 + STYLE_BYTES_PER_BALL;
    // Each solver says what it keeps per ball.
    let solver = match (scene.ball_collisions, scene.motion.collisions) {
        (None, _) => 0,
        (Some(_), CollisionMode::Clamp) => ContactSolver::BYTES_PER_BALL,
        (Some(_), CollisionMode::Exact) => EventDriven::BYTES_PER_BALL,
    };
    let balls = scene
        .balls
        .iter()
        .map(|b| per_ball + solver + Trail::heap_bytes(b.trail) + Canvas::bytes_per_ball(b.trail));
    let balls: u64 = balls.sum();
    let shades = shade_table_bytes(&scene.balls);
    let queued = queue_frames(scene.width, scene.height) as f64 * pixels as f64;
    let frames = pixels * FRAME_BYTES_PER_PIXEL + (queued * QUEUED_BYTES_PER_PIXEL) as u64;
    let parts = [
        (balls, "the balls and their trails"),
        (shades, "the trails' shades"),
        (frames, "the frame buffers"),
        (kept_frames_bytes(scene), "the pilot's kept frames"),
    ];
    let biggest = parts.iter().max_by_key(|p| p.0).map_or("", |p| p.1);
    (BASE_BYTES + parts.iter().map(|p| p.0).sum::<u64>(), biggest)
}

/// The pilot's frames kept for the run (`crate::physics::replay`): their motions, and the
/// second set of balls they are played back into, whose trails grow over those frames.
pub fn kept_frames_bytes(scene: &Scene) -> u64 {
    let balls = scene.balls.len();
    let frames = frames_that_fit(balls, scene.frames.min(PILOT_FRAMES) as usize);
    let motions = (frames * balls * BYTES_PER_BALL_FRAME) as u64;
    let replayed = scene
        .balls
        .iter()
        .map(|b| size_of::<Ball>() as u64 + Trail::heap_bytes(b.trail.min(frames)));
    motions + replayed.sum::<u64>()
}

/// The renderer's shade tables: one per trail colour, as long as its longest trail needs.
fn shade_table_bytes(balls: &[BallSpec]) -> u64 {
    let mut longest: HashMap<Rgb, u64> = HashMap::new();
    for ball in balls {
        let len = longest.entry(ball.trail_colour).or_default();
        *len = (*len).max(ball.trail as u64);
    }
    longest.values().map(|&n| n * (n + 1) / 2).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::file::{parse, preset};

    #[test]
    fn the_estimate_grows_with_the_frames_by_the_kept_frames_alone() {
        // The pile for its 300 frames and for 1: only the frames the pilot keeps differ.
        let long = preset("pile", 1).unwrap();
        let short = Scene {
            frames: 1,
            ..long.clone()
        };
        let grown = i128::from(memory_of(&long).0) - i128::from(memory_of(&short).0);
        let kept = i128::from(kept_frames_bytes(&long)) - i128::from(kept_frames_bytes(&short));
        assert!(kept > 0, "300 frames keep more than 1");
        assert_eq!(grown, kept);
        assert_eq!(memory_of(&long).1, "the frame buffers");
    }

    #[test]
    fn kept_frames_are_counted_up_to_the_size_they_stop_at() {
        // 100,000 balls keep 3.2 MB a frame: two of the ten frames fit in 8 MiB.
        let text = "width = 1000\nheight = 1000\nframes = 10\n\
                    [spawn]\ncount = 100000\nradius = 0.5\nmax_speed = 1.0\ntrail = 5\n";
        let scene = parse("crowd.toml", text, 1).unwrap();
        let motions = 2 * 100_000 * BYTES_PER_BALL_FRAME as u64;
        let balls = 100_000 * (size_of::<Ball>() as u64 + Trail::heap_bytes(2));
        assert_eq!(kept_frames_bytes(&scene), motions + balls);
    }
}
