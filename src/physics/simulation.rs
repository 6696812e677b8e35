//! A scene in motion: the balls and the effects acting on them, advanced one frame at a time.

use super::ball::Ball;
use super::collisions::Collisions;
use super::contacts::ContactSolver;
use super::effects::Effects;
use super::motion::{CollisionMode, Motion};

/// The moving state of a scene.
#[derive(Clone, Debug)]
pub struct Simulation {
    balls: Vec<Ball>,
    effects: Effects,
    motion: Motion,
    /// Present only if the scene calls for ball-ball collisions in exact mode (it owns the grid).
    collisions: Option<Collisions>,
    /// Present only if the scene calls for ball-ball collisions in clamp mode: then it moves
    /// the balls and solves every contact (it owns the grid).
    contacts: Option<ContactSolver>,
}

impl Simulation {
    /// A simulation of `balls` under `effects`, moved by `motion`; `restitution` turns on
    /// ball-ball collisions (and so the broad-phase grid), solved by the contact solver in
    /// clamp mode.
    pub fn new(
        balls: Vec<Ball>,
        effects: Effects,
        motion: Motion,
        restitution: Option<f64>,
    ) -> Simulation {
        let clamp = motion.collisions == CollisionMode::Clamp;
        Simulation {
            balls,
            effects,
            motion,
            collisions: restitution.filter(|_| !clamp).map(Collisions::new),
            contacts: restitution.filter(|_| clamp).map(ContactSolver::new),
        }
    }

    /// Advances every ball by one frame, then the trails record where the balls ended it.
    /// With ball-ball collisions in clamp mode the contact solver moves the balls; otherwise
    /// each step (substep) moves every ball on its own, then (exact mode) resolves ball-ball
    /// contacts once, so more substeps also catch faster pairs. The step's forces are worked
    /// out once per frame, for all balls.
    pub fn step(&mut self) {
        if let Some(contacts) = &mut self.contacts {
            contacts.step(&mut self.balls, &self.effects, &self.motion);
        } else {
            self.step_each_ball();
        }
        for ball in &mut self.balls {
            ball.record_trail();
        }
    }

    /// The frame of a scene without the contact solver: every ball on its own, then (exact
    /// mode) one pass over the ball-ball contacts per step.
    fn step_each_ball(&mut self) {
        let (steps, forces) = self.motion.plan(&self.effects);
        for _ in 0..steps {
            for ball in &mut self.balls {
                self.motion.step(ball, &self.effects, &forces);
            }
            if let Some(collisions) = &mut self.collisions {
                collisions.resolve(&mut self.balls);
                if let Some(walls) = &self.effects.walls {
                    for ball in &mut self.balls {
                        ball.keep_inside(walls);
                    }
                }
            }
        }
    }

    /// Whether ball-ball collisions (and so the broad-phase grid) exist in this simulation.
    pub fn has_ball_collisions(&self) -> bool {
        self.collisions.is_some() || self.contacts.is_some()
    }

    /// Whether the contact solver exists in this simulation.
    pub fn has_contact_solver(&self) -> bool {
        self.contacts.is_some()
    }

    /// The balls as they are now, in scene order.
    pub fn balls(&self) -> &[Ball] {
        &self.balls
    }
}
