//! The step context: everything the stages of one step share, handed to each of them as
//! Box2D v3 hands its `b2StepContext` (`solver.h`) to every stage. It holds how the step moves
//! the balls ([`Stepping`]), the solver's copy of the balls, and the step's contacts and
//! islands.

use super::contact::{Body, Contacts, SubStep};
use super::grid::Grid;
use super::island::{Island, Islands};
use crate::physics::effects::Effects;
use crate::physics::integrate::integrator::{Forces, Integrator};
use crate::physics::motion::Motion;
use crate::physics::tolerances::{LESSON_GRAVITY, LOADED_VELOCITY_PASSES, REST_SPEED, SLEEP_SPEED};

/// What the stages of a step share. The prepare stage refills it at the start of every step;
/// its buffers are kept only so that a step allocates nothing. No number in it carries from
/// one step to the next: what does (the warm-start memory, the sleeping islands) is kept
/// beside it, by the solver.
#[derive(Clone, Debug, Default)]
pub(super) struct StepContext {
    /// How this frame's steps move the balls, worked out as the frame begins.
    pub stepping: Stepping,
    /// Ball-ball restitution (0 to 1; the scene checks it), fixed when the scene builds the
    /// solver.
    pub restitution: f64,
    /// The grid the contacts are found with. Its order is the bodies': `grid.order()[k]` is
    /// the scene's index of `bodies[k]`.
    pub grid: Grid,
    /// The balls as the solver moves them, in the grid's order: contacts then touch balls
    /// close together in memory, which keeps 100,000 balls fast.
    pub bodies: Vec<Body>,
    /// Whether each body sleeps this step; empty while none sleeps (a scene where none
    /// sleeps pays nothing for it).
    pub asleep: Vec<bool>,
    /// The step's contacts.
    pub contacts: Contacts,
    /// The balls with a contact, island by island.
    pub islands: Islands,
}

impl StepContext {
    /// Moves each of `island`'s balls by `motion`, given the step's settings.
    pub fn move_each_ball(
        &mut self,
        island: &Island,
        mut motion: impl FnMut(&Stepping, &mut Body),
    ) {
        for &i in &self.islands.balls[island.balls.clone()] {
            motion(&self.stepping, &mut self.bodies[i]);
        }
    }
}

/// How the steps of one frame move the balls, worked out once per frame.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Stepping {
    /// The scene's integrator, and its iterations (sub-steps) per step.
    pub integrator: Integrator,
    pub iterations: u32,
    /// Steps in the frame.
    pub steps: u32,
    /// Length of a step, frames.
    pub dt: f64,
    /// The strength of the scene's gravity, px/frame² (0 without).
    pub gravity: f64,
    /// Gravity and drag over a whole step, and over one sub-step.
    pub whole: Forces,
    pub forces: Forces,
    pub sub: SubStep,
    /// Whether no gravity or drag acts, so every ball flies straight between contacts.
    pub free: bool,
    /// Below this speed, px/frame, a ball counts as still (0 without gravity: nothing sleeps).
    pub sleep_speed: f64,
}

impl Stepping {
    pub(crate) fn new(effects: &Effects, motion: &Motion) -> Stepping {
        let (steps, whole) = motion.plan(effects);
        let forces = Forces::new(effects).split(steps * motion.iterations);
        let gravity = effects.gravity.map_or(0.0, |g| g.length());
        Stepping {
            integrator: motion.integrator,
            iterations: motion.iterations,
            steps,
            dt: 1.0 / f64::from(steps),
            gravity,
            whole,
            forces,
            sub: SubStep {
                h: forces.dt,
                loaded: gravity > 0.0,
                rest_speed: REST_SPEED * gravity / LESSON_GRAVITY,
            },
            free: whole.gravity.is_none() && whole.drag.is_none(),
            sleep_speed: SLEEP_SPEED * gravity / LESSON_GRAVITY,
        }
    }

    /// Velocity passes per sub-step: [`LOADED_VELOCITY_PASSES`] when gravity loads the
    /// contacts, else the one a bounce needs.
    pub(crate) fn velocity_passes(&self) -> u32 {
        if self.sub.loaded {
            LOADED_VELOCITY_PASSES
        } else {
            1
        }
    }
}
