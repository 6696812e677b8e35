//! The ball: its state, the lesson's `step()` and its bounded trail.
//!
//! `Ball::step` is the lesson's loop, line for line: gravity changes the velocity, the velocity
//! moves the ball, the four walls clamp then reflect, the new position joins the trail. Beyond
//! the lesson, `motion` and `simulation` pick the general solver a scene needs and run it: the
//! integrators and substeps in `integrate`, the floors in `floor`, ball-ball contacts in
//! `contacts` and `events`. With the default settings it gives the same numbers. Last come a
//! ball's mass and the balls' kinetic energy, which those solvers and `compare` work with.

use std::collections::VecDeque;

use super::vec2::Vec2;
use super::walls::Walls;

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
    /// A ball at `(x, y)` moving at `(vx, vy)` with an empty trail of at most `trail_len` points.
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

    /// One frame of the lesson: `gravity` in px/frame², pulling down.
    pub fn step(&mut self, gravity: f64, walls: &Walls) {
        self.vy += gravity; // 1. constant force → velocity change
        self.x += self.vx; // 2. velocity → position change
        self.y += self.vy;
        self.bounce_off_walls(walls); // 3. collision: clamp, then reflect
        self.record_trail(); // after the move, so the trail ends where the ball is
    }

    /// The lesson's collision response: clamp the ball back inside the box, then reflect the
    /// velocity component normal to the wall it crossed, losing some energy. Clamping first
    /// means the ball ends the frame touching the wall, never inside it, so the next frame
    /// cannot flip it back (the jitter bug). `else if` keeps both walls of an axis from
    /// triggering in one frame, as in the lesson's hint.
    pub(crate) fn bounce_off_walls(&mut self, walls: &Walls) {
        if self.x - self.radius < 0.0 {
            self.x = self.radius;
            self.vx = -self.vx * walls.damping;
        } else if self.x + self.radius > walls.width {
            self.x = walls.width - self.radius;
            self.vx = -self.vx * walls.damping;
        }
        if self.y - self.radius < 0.0 {
            self.y = self.radius;
            self.vy = -self.vy * walls.damping;
        } else if self.y + self.radius > walls.height {
            self.y = walls.height - self.radius;
            self.vy = -self.vy * walls.damping;
        }
    }

    /// Puts a ball that something other than its own motion pushed out of the box (a
    /// neighbour, in a ball-ball collision) back inside, without touching its velocity: it
    /// did not hit the wall, it was shoved.
    pub(crate) fn keep_inside(&mut self, walls: &Walls) {
        self.x = self.x.clamp(self.radius, walls.width - self.radius);
        self.y = self.y.clamp(self.radius, walls.height - self.radius);
    }

    /// The centre, px.
    pub fn position(&self) -> Vec2 {
        Vec2::new(self.x, self.y)
    }

    /// The velocity, px/frame.
    pub fn velocity(&self) -> Vec2 {
        Vec2::new(self.vx, self.vy)
    }

    /// Whether position and velocity are all finite numbers (a run stops if not).
    pub(crate) fn is_finite(&self) -> bool {
        [self.x, self.y, self.vx, self.vy]
            .iter()
            .all(|v| v.is_finite())
    }

    /// Appends the current position to the trail. After the move, so the trail ends where the
    /// ball is drawn (reflection question 3).
    pub fn record_trail(&mut self) {
        self.trail.push(self.position());
    }
}

/// The last few positions of a ball, oldest first, never more than its capacity.
///
/// A trail that keeps no points is a single empty pointer, so a ball without one is 48 bytes
/// rather than 80: the event-driven step reads balls in an order no cache can foresee, and the
/// fewer bytes a ball, the fewer of them are far away (`docs/exact.md`).
#[derive(Clone, Debug, PartialEq)]
pub struct Trail {
    ring: Option<Box<Ring>>,
}

/// The points of a trail that keeps some, and how many it keeps.
#[derive(Clone, Debug, PartialEq)]
struct Ring {
    points: VecDeque<Vec2>,
    capacity: usize,
}

/// The points of a trail that keeps none.
static NO_POINTS: VecDeque<Vec2> = VecDeque::new();

impl Trail {
    /// An empty trail that keeps at most `capacity` points (0 keeps none).
    pub fn new(capacity: usize) -> Trail {
        let ring = (capacity > 0).then(|| {
            Box::new(Ring {
                points: VecDeque::new(),
                capacity,
            })
        });
        Trail { ring }
    }

    /// The memory a trail of `capacity` points takes besides the ball once full, bytes: its
    /// ring and the ring's buffer (a power of two above `capacity`).
    pub fn heap_bytes(capacity: usize) -> u64 {
        if capacity == 0 {
            return 0;
        }
        let buffer = (capacity as u64 + 1).next_power_of_two().max(4);
        size_of::<Ring>() as u64 + buffer * size_of::<Vec2>() as u64
    }

    /// Whether it keeps any points at all (its capacity is not 0).
    pub(crate) fn keeps_points(&self) -> bool {
        self.ring.is_some()
    }

    /// Adds the newest point and drops the oldest beyond capacity, so memory stays bounded.
    pub fn push(&mut self, point: Vec2) {
        let Some(ring) = &mut self.ring else {
            return; // a trail that keeps nothing: not even a buffer to cycle through
        };
        ring.points.push_back(point);
        if ring.points.len() > ring.capacity {
            ring.points.pop_front();
        }
    }

    /// How many points the trail holds now.
    pub fn len(&self) -> usize {
        self.points().len()
    }

    /// Whether the trail holds no point.
    pub fn is_empty(&self) -> bool {
        self.points().is_empty()
    }

    /// The points, oldest first.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = &Vec2> + '_ {
        self.points().iter()
    }

    fn points(&self) -> &VecDeque<Vec2> {
        self.ring.as_ref().map_or(&NO_POINTS, |ring| &ring.points)
    }
}

/// The mass of a ball of `radius` px: balls are flat discs of one density, so mass grows as
/// the radius squared (the unit cancels in every collision, so none is named).
pub(crate) fn mass(radius: f64) -> f64 {
    radius * radius
}

/// Total kinetic energy, `Σ ½·m·|v|²` with the balls' `mass` (flat discs of equal density):
/// it never rises in a collision with restitution ≤ 1 (the tests and the soak run check it).
pub fn kinetic_energy(balls: &[Ball]) -> f64 {
    balls
        .iter()
        .map(|b| 0.5 * mass(b.radius) * b.velocity().length_squared())
        .sum()
}
