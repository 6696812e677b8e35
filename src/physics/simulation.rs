//! A scene in motion: the balls and the effects acting on them, advanced one frame at a time.

use super::ball::Ball;
use super::contacts::ContactSolver;
use super::effects::Effects;
use super::events::system::{EventCounts, EventDriven};
use super::motion::{CollisionMode, Motion};

/// The moving state of a scene.
#[derive(Clone, Debug)]
pub struct Simulation {
    balls: Vec<Ball>,
    effects: Effects,
    motion: Motion,
    /// Present only if the scene calls for ball-ball collisions in clamp mode: then it moves
    /// the balls and solves every contact (it owns the grid).
    contacts: Option<ContactSolver>,
    /// Present only if the scene calls for ball-ball collisions in exact mode: then every
    /// contact is resolved at its moment (`super::events`).
    events: Option<EventDriven>,
    /// Whether any ball keeps a trail. Without one the pass that records trails is skipped:
    /// at 100,000 balls it reads 8 MB a frame only to find nothing to record.
    trails: bool,
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
        let trails = balls.iter().any(|ball| ball.trail.keeps_points());
        Simulation {
            balls,
            effects,
            motion,
            contacts: restitution.filter(|_| clamp).map(ContactSolver::new),
            events: restitution.filter(|_| !clamp).map(EventDriven::new),
            trails,
        }
    }

    /// Advances every ball by one frame, then the trails record where the balls ended it.
    /// With ball-ball collisions, clamp mode's contact solver or exact mode's event-driven
    /// step moves the balls; without them each step (substep) moves every ball on its own.
    /// The step's forces are worked out once per frame, for all balls.
    pub fn step(&mut self) {
        if let Some(contacts) = &mut self.contacts {
            // The solver plans its own steps.
            contacts.step(&mut self.balls, &self.effects, &self.motion);
        } else {
            let (steps, forces) = self.motion.plan(&self.effects);
            if let Some(events) = &mut self.events {
                let integrator = self.motion.integrator;
                events.frame(&mut self.balls, integrator, steps, &forces, &self.effects);
            } else {
                for _ in 0..steps {
                    for ball in &mut self.balls {
                        self.motion.step(ball, &self.effects, &forces);
                    }
                }
            }
        }
        if self.trails {
            for ball in &mut self.balls {
                ball.record_trail();
            }
        }
    }

    /// Whether ball-ball collisions (and so a broad-phase grid) exist in this simulation.
    pub fn has_ball_collisions(&self) -> bool {
        self.contacts.is_some() || self.events.is_some()
    }

    /// Whether the contact solver exists in this simulation.
    pub fn has_contact_solver(&self) -> bool {
        self.contacts.is_some()
    }

    /// In exact mode with ball-ball collisions, what the last frame's events were.
    pub fn event_counts(&self) -> Option<EventCounts> {
        self.events.as_ref().map(EventDriven::counts)
    }

    /// The balls as they are now, in scene order.
    pub fn balls(&self) -> &[Ball] {
        &self.balls
    }
}
