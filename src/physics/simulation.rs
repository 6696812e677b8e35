//! A scene in motion: the balls and the effects acting on them, advanced one frame at a time.
//!
//! A scene that is the lesson's (one semi-implicit Euler step a frame, gravity straight down or
//! none, clamp-then-reflect walls, nothing else) moves every ball with the lesson's own
//! [`Ball::step`], so a change to that method shows in every such run. Anything beyond the
//! lesson picks the solver that handles it.

use super::ball::Ball;
use super::contacts::ContactSolver;
use super::effects::Effects;
use super::events::system::{EventCounts, EventDriven};
use super::integrate::integrator::Integrator;
use super::motion::{CollisionMode, Motion};
use super::walls::Walls;
use crate::work::{tally, Work};

/// The moving state of a scene.
#[derive(Clone, Debug)]
pub struct Simulation {
    balls: Vec<Ball>,
    effects: Effects,
    motion: Motion,
    stepper: Stepper,
    /// Whether any ball keeps a trail. Without one the pass that records trails is skipped:
    /// at 100,000 balls it reads 8 MB a frame only to find nothing to record.
    trails: bool,
}

/// What moves the balls each frame: the lesson's step, or the solver the scene calls for
/// (boxed: each solver's buffers take hundreds of bytes, the lesson's step a few).
#[derive(Clone, Debug)]
enum Stepper {
    /// [`Ball::step`] for every ball, which also records its trail.
    Lesson { gravity: f64, walls: Walls },
    /// Each ball on its own, by `Motion::step`: any integrator, substeps, drag, floors, exact
    /// bounces off walls and floors.
    IndependentBalls,
    /// Ball-ball collisions in clamp mode: the contact solver moves the balls and solves every
    /// contact (it owns the grid).
    Contacts(Box<ContactSolver>),
    /// Ball-ball collisions in exact mode: every contact resolved at its moment.
    Events(Box<EventDriven>),
}

impl Stepper {
    fn new(effects: &Effects, motion: &Motion, restitution: Option<f64>) -> Stepper {
        match (restitution, motion.collisions) {
            (Some(e), CollisionMode::Clamp) => {
                return Stepper::Contacts(Box::new(ContactSolver::new(e)))
            }
            (Some(e), CollisionMode::Exact) => {
                return Stepper::Events(Box::new(EventDriven::new(e)))
            }
            (None, _) => {}
        }
        let gravity = match effects.gravity {
            None => Some(0.0),
            Some(g) => (g.x == 0.0).then_some(g.y),
        };
        match (gravity, effects.walls) {
            (Some(gravity), Some(walls))
                if motion.integrator == Integrator::SemiImplicitEuler
                    && motion.substeps == 1
                    && motion.collisions == CollisionMode::Clamp
                    && effects.drag.is_none()
                    && effects.floors.is_empty() =>
            {
                Stepper::Lesson { gravity, walls }
            }
            _ => Stepper::IndependentBalls,
        }
    }
}

impl Simulation {
    /// A simulation of `balls` under `effects`, moved by `motion`; `restitution` turns on
    /// ball-ball collisions (and so the broad-phase grid), solved by the contact solver in
    /// clamp mode and event by event in exact mode.
    pub fn new(
        balls: Vec<Ball>,
        effects: Effects,
        motion: Motion,
        restitution: Option<f64>,
    ) -> Simulation {
        let trails = balls.iter().any(|ball| ball.trail.keeps_points());
        Simulation {
            stepper: Stepper::new(&effects, &motion, restitution),
            balls,
            effects,
            motion,
            trails,
        }
    }

    /// Advances every ball by one frame, and the trails record where the balls ended it.
    pub fn step(&mut self) {
        match &mut self.stepper {
            Stepper::Lesson { gravity, walls } => {
                for ball in &mut self.balls {
                    ball.step(*gravity, walls);
                }
                self.tally_lesson_steps();
                return; // `Ball::step` records the trail
            }
            Stepper::IndependentBalls => {
                let (steps, forces) = self.motion.plan(&self.effects);
                for _ in 0..steps {
                    for ball in &mut self.balls {
                        self.motion.step(ball, &self.effects, &forces);
                    }
                }
            }
            Stepper::Contacts(contacts) => {
                // The solver plans its own steps.
                contacts.step(&mut self.balls, &self.effects, &self.motion);
            }
            Stepper::Events(events) => {
                let (steps, forces) = self.motion.plan(&self.effects);
                let integrator = self.motion.integrator;
                events.frame(&mut self.balls, integrator, steps, &forces, &self.effects);
            }
        }
        if self.trails {
            for ball in &mut self.balls {
                ball.record_trail();
                tally(Work::TrailPoint);
            }
        }
    }

    /// The lesson's gravity and walls, if every ball moves by the lesson's own step
    /// ([`Ball::step`]): then a variant of that step (a learner's mistake) can move them too.
    pub(crate) fn lesson_step(&self) -> Option<(f64, Walls)> {
        match &self.stepper {
            Stepper::Lesson { gravity, walls } => Some((*gravity, *walls)),
            _ => None,
        }
    }

    /// Counts the lesson's steps, and the gravity and walls they applied (with the
    /// `work-tally` feature; see `crate::work`).
    fn tally_lesson_steps(&self) {
        for _ in &self.balls {
            tally(Work::LessonStep);
            if self.effects.gravity.is_some() {
                tally(Work::Gravity);
            }
            tally(Work::Walls);
        }
    }

    /// Whether ball-ball collisions (and so a broad-phase grid) exist in this simulation.
    pub fn has_ball_collisions(&self) -> bool {
        matches!(self.stepper, Stepper::Contacts(_) | Stepper::Events(_))
    }

    /// Whether the contact solver exists in this simulation.
    pub fn has_contact_solver(&self) -> bool {
        matches!(self.stepper, Stepper::Contacts(_))
    }

    /// Whether every ball takes the lesson's own step, [`Ball::step`].
    pub fn takes_the_lessons_step(&self) -> bool {
        matches!(self.stepper, Stepper::Lesson { .. })
    }

    /// In exact mode with ball-ball collisions, what the last frame's events were.
    pub fn event_counts(&self) -> Option<EventCounts> {
        match &self.stepper {
            Stepper::Events(events) => Some(events.counts()),
            _ => None,
        }
    }

    /// How many balls sleep: resting balls the solver no longer moves (the contact solver's
    /// sleeping islands, exact mode's sleep rule). The lesson's step never lets a ball sleep.
    pub fn sleeping_balls(&self) -> usize {
        match &self.stepper {
            Stepper::Contacts(contacts) => contacts.sleeping(),
            Stepper::Events(events) => events.sleeping(),
            Stepper::Lesson { .. } | Stepper::IndependentBalls => 0,
        }
    }

    /// The balls as they are now, in scene order.
    pub fn balls(&self) -> &[Ball] {
        &self.balls
    }
}
