//! A scene in motion: the balls and the effects acting on them, advanced one frame at a time.

use super::ball::Ball;
use super::collisions::Collisions;
use super::effects::Effects;
use super::events::system::{EventCounts, EventDriven};
use super::motion::{CollisionMode, Motion};

/// The moving state of a scene.
#[derive(Clone, Debug)]
pub struct Simulation {
    balls: Vec<Ball>,
    effects: Effects,
    motion: Motion,
    /// Present only if the scene calls for ball-ball collisions (it owns the grid).
    collisions: Option<Collisions>,
    /// Instead of `collisions` in exact mode: every contact at its moment (`super::events`).
    events: Option<EventDriven>,
}

impl Simulation {
    /// A simulation of `balls` under `effects`, moved by `motion`; `restitution` turns on
    /// ball-ball collisions (and so the broad-phase grid).
    pub fn new(
        balls: Vec<Ball>,
        effects: Effects,
        motion: Motion,
        restitution: Option<f64>,
    ) -> Simulation {
        let exact = motion.collisions == CollisionMode::Exact;
        Simulation {
            balls,
            effects,
            motion,
            collisions: restitution.filter(|_| !exact).map(Collisions::new),
            events: restitution.filter(|_| exact).map(EventDriven::new),
        }
    }

    /// Advances every ball by one frame: each step (substep) moves every ball, then resolves
    /// ball-ball contacts if the scene has them, so more substeps also catch faster pairs;
    /// the trails record where the balls ended the frame. The step's forces are worked out
    /// once per frame, for all balls.
    pub fn step(&mut self) {
        let (steps, forces) = self.motion.plan(&self.effects);
        if let Some(events) = &mut self.events {
            // Exact mode with ball-ball collisions: every contact at its moment.
            let integrator = self.motion.integrator;
            events.frame(&mut self.balls, integrator, steps, &forces, &self.effects);
            for ball in &mut self.balls {
                ball.record_trail();
            }
            return;
        }
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
        for ball in &mut self.balls {
            ball.record_trail();
        }
    }

    /// Whether ball-ball collisions (and so a broad-phase grid) exist in this simulation.
    pub fn has_ball_collisions(&self) -> bool {
        self.collisions.is_some() || self.events.is_some()
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
