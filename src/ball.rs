//! The ball: its state, the lesson's `step()` and its bounded trail.
//!
//! Physics only: nothing here knows about pixels or files.

use std::collections::VecDeque;

use crate::effects::Effects;
use crate::motion::Motion;

/// One ball, in the lesson's units: pixels and frames.
#[derive(Clone, Debug, PartialEq)]
pub struct Ball {
    /// Centre, px (x grows rightwards, y grows downwards).
    pub x: f64,
    pub y: f64,
    /// Velocity, px/frame.
    pub vx: f64,
    pub vy: f64,
    /// Radius, px.
    pub radius: f64,
    /// The last positions, oldest first.
    pub trail: Trail,
}

impl Ball {
    /// A ball at rest-or-moving at `(x, y)` with an empty trail of at most `trail_len` points.
    pub fn new(x: f64, y: f64, vx: f64, vy: f64, radius: f64, trail_len: usize) -> Ball {
        Ball {
            x,
            y,
            vx,
            vy,
            radius,
            trail: Trail::new(trail_len),
        }
    }

    /// One frame: `motion` moves the ball under `effects` (the default is the lesson's:
    /// gravity changes the velocity, the velocity moves the ball, walls clamp and reflect;
    /// see `Integrator::step` and `Walls::bounce`), then the new position joins the trail.
    pub fn step(&mut self, effects: &Effects, motion: &Motion) {
        motion.advance(self, effects);
        self.record_trail();
    }

    /// Appends the current position to the trail. After the move, so the trail ends where the
    /// ball is drawn (reflection question 3).
    pub fn record_trail(&mut self) {
        self.trail.push(self.x, self.y);
    }
}

/// The last few positions of a ball, oldest first, never more than its capacity.
#[derive(Clone, Debug, PartialEq)]
pub struct Trail {
    points: VecDeque<(f64, f64)>,
    capacity: usize,
}

impl Trail {
    /// An empty trail that keeps at most `capacity` points (0 keeps none).
    pub fn new(capacity: usize) -> Trail {
        Trail {
            points: VecDeque::new(),
            capacity,
        }
    }

    /// Adds the newest point and drops the oldest beyond capacity, so memory stays bounded.
    pub fn push(&mut self, x: f64, y: f64) {
        self.points.push_back((x, y));
        if self.points.len() > self.capacity {
            self.points.pop_front();
        }
    }

    /// How many points the trail holds now.
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether the trail holds no point.
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// The points, oldest first.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = &(f64, f64)> + '_ {
        self.points.iter()
    }
}
