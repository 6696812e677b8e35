//! Integrators: how one step of length `dt` (frames) turns forces into velocity and velocity
//! into position. The lesson's is semi-implicit Euler: velocity first, then position.

use crate::ball::Ball;
use crate::effects::Effects;
use crate::work::{tally, Work};

/// Which integration method advances the balls.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum, serde::Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Integrator {
    /// The lesson's: `v += a·dt`, then `x += v·dt`.
    #[default]
    SemiImplicitEuler,
}

impl Integrator {
    /// Advances `ball` by `dt` frames under gravity and drag (no collisions).
    pub fn step(self, ball: &mut Ball, effects: &Effects, dt: f64) {
        match self {
            Integrator::SemiImplicitEuler => semi_implicit_euler(ball, effects, dt),
        }
    }
}

/// With `dt = 1` this is exactly the lesson's arithmetic (`x * 1.0` and `powf(1.0)` are exact).
fn semi_implicit_euler(ball: &mut Ball, effects: &Effects, dt: f64) {
    if let Some([gx, gy]) = effects.gravity {
        tally(Work::Gravity);
        ball.vx += gx * dt;
        ball.vy += gy * dt;
    }
    if let Some(drag) = effects.drag {
        tally(Work::Drag);
        let keep = (1.0 - drag).powf(dt);
        ball.vx *= keep;
        ball.vy *= keep;
    }
    ball.x += ball.vx * dt;
    ball.y += ball.vy * dt;
}
