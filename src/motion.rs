//! How a frame is solved: which integrator, how many substeps, and how collisions with walls
//! and floors are resolved. The default is the lesson's: one semi-implicit Euler step per
//! frame, then clamp-then-reflect.

use crate::ball::Ball;
use crate::effects::Effects;
use crate::integrator::Integrator;

/// How a ball's contact with a wall or floor is resolved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum CollisionMode {
    /// The lesson's: after the step, clamp the ball back to the wall and reflect its velocity.
    #[default]
    Clamp,
}

/// The solver settings for one frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Motion {
    pub integrator: Integrator,
    /// Each frame is split into this many equal steps (at least 1).
    pub substeps: u32,
    pub collisions: CollisionMode,
}

impl Default for Motion {
    fn default() -> Self {
        Motion {
            integrator: Integrator::default(),
            substeps: 1,
            collisions: CollisionMode::default(),
        }
    }
}

impl Motion {
    /// Advances `ball` by one frame under `effects` (its trail is the caller's business).
    pub fn advance(&self, ball: &mut Ball, effects: &Effects) {
        let dt = 1.0 / f64::from(self.substeps);
        for _ in 0..self.substeps {
            let from = [ball.x, ball.y];
            self.integrator.step(ball, effects, dt);
            effects.clamp_and_reflect(ball, from);
        }
    }
}
