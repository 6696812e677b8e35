//! What stops a comparison midway, besides a signal: balls that left the finite numbers (so
//! no NaN is measured or drawn).

use crate::job::RunError;
use crate::physics::Ball;
use crate::scene::Scene;

use super::methods::Method;

/// `1 ball, 200 frames`.
pub(crate) fn balls_and_frames(scene: &Scene) -> String {
    let balls = scene.balls.len();
    let s = if balls == 1 { "" } else { "s" };
    format!("{balls} ball{s}, {} frames", scene.frames)
}

/// Refuses balls that left the finite numbers, so no NaN is measured or drawn.
pub(crate) fn check_finite(
    scene: &Scene,
    method: Method,
    balls: &[Ball],
    frame: u32,
) -> Result<(), RunError> {
    RunError::if_not_finite(balls, frame, |_| {
        format!("{} solved by {method}", balls_and_frames(scene))
    })
}
