//! How a frame is solved: which integrator, how many substeps, and how collisions with walls
//! and floors are resolved. The default is the lesson's: one semi-implicit Euler step per
//! frame, then clamp-then-reflect.

use super::ball::Ball;
use super::effects::Effects;
use super::integrate::exact;
use super::integrate::integrator::{Forces, Integrator};

/// How a ball's contact with a wall or floor is resolved.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum CollisionMode {
    /// The lesson's: after the step, clamp the ball back to the wall and reflect its velocity.
    #[default]
    Clamp,
    /// Bounce off walls, floors and (in a `Simulation`) other balls at the moment of impact
    /// within the step.
    Exact,
}

/// Iterations of the contact solver per step unless the scene says otherwise: each is a
/// sub-step with one velocity and one position pass (`docs/contacts.md` has the measurements
/// behind the number).
pub const DEFAULT_ITERATIONS: u32 = 12;

/// The solver settings for one frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Motion {
    pub integrator: Integrator,
    /// Each frame is split into this many equal steps (at least 1).
    pub substeps: u32,
    pub collisions: CollisionMode,
    /// Iterations (sub-steps) of the contact solver per step, at least 1; used only by scenes
    /// with ball-ball collisions in clamp mode.
    pub iterations: u32,
}

impl Default for Motion {
    fn default() -> Self {
        Motion {
            integrator: Integrator::default(),
            substeps: 1,
            collisions: CollisionMode::default(),
            iterations: DEFAULT_ITERATIONS,
        }
    }
}

impl Motion {
    /// Advances `ball` by one frame under `effects` (its trail is the caller's business).
    pub fn advance(&self, ball: &mut Ball, effects: &Effects) {
        let (steps, forces) = self.plan(effects);
        for _ in 0..steps {
            self.step(ball, effects, &forces);
        }
    }

    /// How many steps a frame takes (the substeps, or more where strong drag needs them) and
    /// the forces of one step. The same for every ball, so worked out once per frame.
    pub(crate) fn plan(&self, effects: &Effects) -> (u32, Forces) {
        let frame = Forces::new(effects);
        let steps = self.integrator.steps_per_frame(self.substeps, &frame);
        (steps, frame.split(steps))
    }

    /// One step of `forces.dt` frames: integrate, then resolve walls and floors.
    pub(crate) fn step(&self, ball: &mut Ball, effects: &Effects, forces: &Forces) {
        match self.collisions {
            CollisionMode::Exact => {
                // Whether the step hit the cap is not reported on this path (one ball, no
                // ball-ball collisions); `Simulation::event_counts` reports it with them.
                exact::step(self.integrator, ball, forces, effects);
            }
            CollisionMode::Clamp => {
                let from = ball.position();
                self.integrator.step(ball, forces);
                effects.clamp_and_reflect(ball, from);
            }
        }
    }
}
