//! What stops a comparison midway, as it stops a run: a signal, or balls that left the
//! finite numbers (so no NaN is measured or drawn).

use crate::physics::Ball;
use crate::run::RunError;
use crate::scene::Scene;
use crate::stop::Stop;

use super::methods::Method;

/// `1 ball, 200 frames`.
pub fn balls_and_frames(scene: &Scene) -> String {
    let balls = scene.balls.len();
    let s = if balls == 1 { "" } else { "s" };
    format!("{balls} ball{s}, {} frames", scene.frames)
}

/// Returns `Stopped` if a signal has come.
pub fn stop_if_asked(stop: &Stop, frame: u32, frames: u32) -> Result<(), RunError> {
    RunError::if_stopped(stop, frame, frames, || {
        "any of the comparison's files".to_string()
    })
}

/// Refuses balls that left the finite numbers, so no NaN is measured or drawn.
pub fn check_finite(
    scene: &Scene,
    method: Method,
    balls: &[Ball],
    frame: u32,
) -> Result<(), RunError> {
    RunError::if_not_finite(balls, frame, |_| {
        format!("{} solved by {method}", balls_and_frames(scene))
    })
}
