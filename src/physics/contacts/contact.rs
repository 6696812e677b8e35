//! The contacts the solver works on (ball with ball, ball with a wall or floor) and what one
//! contact does in each stage: its velocity pass, its push apart, when it first touches. The
//! stages that sweep over a step's contacts are `super::contact_solver`'s. Also the solver's
//! compact copy of a ball, [`Body`], as Box2D v3 keeps a body state apart from the body.

use crate::physics::ball::Ball;
use crate::physics::integrate::integrator::Movable;
use crate::physics::maths;
use crate::physics::tolerances::{PUSH, SLOP};
use crate::physics::vec2::Vec2;

/// The golden angle, radians: successive multiples of it spread evenly round a circle.
const GOLDEN_ANGLE: f64 = 2.399_963_229_728_653;

/// A ball as the solver moves it: centre, velocity and radius, without the trail (which
/// the solver never reads), so its copy of the balls in grid order is all it sweeps.
#[derive(Clone, Copy, Debug)]
pub(super) struct Body {
    /// Centre, px.
    pub position: Vec2,
    /// Velocity, px/frame.
    pub velocity: Vec2,
    /// Radius, px.
    pub radius: f64,
}

impl Body {
    pub(crate) fn of(ball: &Ball) -> Body {
        Body {
            position: ball.position(),
            velocity: ball.velocity(),
            radius: ball.radius,
        }
    }
}

impl Movable for Body {
    fn motion(&mut self) -> [&mut f64; 4] {
        let Body {
            position, velocity, ..
        } = self;
        [
            &mut position.x,
            &mut position.y,
            &mut velocity.x,
            &mut velocity.y,
        ]
    }
}

/// The step's contacts, and the grid's pairs they were found among.
#[derive(Clone, Debug, Default)]
pub(super) struct Contacts {
    /// The pairs the grid finds, as places in its order.
    pub places: Vec<[u32; 2]>,
    /// Of those, the pairs that could not touch as the step began (the restitution stage
    /// looks at them again at its end).
    pub unlisted: Vec<[u32; 2]>,
    /// This step's contacts, island by island once sorted.
    pub pairs: Vec<PairContact>,
    pub fixed: Vec<FixedContact>,
}

/// A contact between balls `a` and `b`, the normal pointing from `a` to `b`.
#[derive(Clone, Copy, Debug)]
pub(super) struct PairContact {
    pub a: usize,
    pub b: usize,
    /// Sum of the radii, px.
    pub reach: f64,
    pub state: ContactState,
    /// 1 / mass of each ball.
    pub inverse_a: f64,
    pub inverse_b: f64,
}

/// A contact between ball `ball` and a wall or floor, seen as a line that does not move:
/// the gap is `centre · normal − offset`, the normal pointing into the free side.
#[derive(Clone, Copy, Debug)]
pub(super) struct FixedContact {
    pub ball: usize,
    pub offset: f64,
    pub state: ContactState,
}

/// What every contact tracks while it is solved.
#[derive(Clone, Copy, Debug)]
pub(super) struct ContactState {
    pub normal: Vec2,
    /// Gap at the start of the sub-step, px (negative: overlap).
    separation: f64,
    /// The relative normal speed, px/frame, that a contact which does not bounce is brought
    /// to: closing by no more than the gap within the sub-step (0 if it touches). It is the
    /// same in each of a sub-step's velocity passes, so it is worked out once, with the gap.
    resting_target: f64,
    restitution: f64,
    /// `1 / (1/m_a + 1/m_b)`: the impulse that changes the relative normal speed by 1.
    pub mass: f64,
    /// Total impulse along the normal in this sub-step, never negative.
    pub impulse: f64,
    /// Names the contact from step to step, for the warm start.
    pub key: u64,
}

/// The gap between two balls, px (negative: overlap), and the normal from the first to the
/// second.
#[derive(Clone, Copy, Debug)]
pub(super) struct Gap {
    pub separation: f64,
    pub normal: Vec2,
}

/// The sub-step the velocity pass works in.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct SubStep {
    /// Length, frames.
    pub h: f64,
    /// Whether gravity presses the balls together. Only then does a contact carry a load
    /// from one sub-step to the next: without it every contact's push is an impact, and
    /// pushing again would only add energy for the next pass to take back.
    pub loaded: bool,
    /// Below this parting speed, px/frame, a contact does not bounce.
    pub rest_speed: f64,
}

/// How far the position pass moves balls that overlap beyond the slop.
#[derive(Clone, Copy, Debug)]
pub(super) enum Push {
    /// [`PUSH`] of the overlap beyond the slop: a sub-step's share, so that a ball pushed by
    /// many contacts does not overshoot.
    Part,
    /// All of it, to touching: for the few pairs of an island solved touch by touch.
    Whole,
}

impl Push {
    /// The distance to move two balls (or a ball and a wall) apart that are `separation`
    /// apart (negative), where `allowed` is the slop.
    fn distance(self, separation: f64, allowed: f64) -> f64 {
        match self {
            Push::Part => -(separation + allowed) * PUSH,
            Push::Whole => -separation,
        }
    }
}

impl ContactState {
    /// A contact along `normal`, touching until its gap is measured ([`ContactState::measure`]),
    /// as every stage that solves a contact does first.
    pub(crate) fn new(normal: Vec2, restitution: f64, mass: f64, key: u64) -> ContactState {
        ContactState {
            normal,
            separation: 0.0,
            resting_target: 0.0,
            restitution,
            mass,
            impulse: 0.0,
            key,
        }
    }

    /// Takes `separation` as the gap at the start of a sub-step of `h` frames.
    pub(crate) fn measure(&mut self, separation: f64, h: f64) {
        self.separation = separation;
        // Resting, or speculative: close by no more than the gap within the sub-step.
        self.resting_target = -separation.max(0.0) / h;
    }

    /// The velocity pass for one contact whose relative normal speed is `speed` (negative:
    /// closing): updates the running total and returns the impulse to apply now.
    fn impulse_change(&mut self, speed: f64, sub: SubStep) -> f64 {
        // It bounces if it touches within the sub-step closing fast enough for its rebound,
        // `e` times the approach speed now, to beat the rest speed. Now, not when the contact
        // was found: a ball struck in this step passes the blow on to the next (a resting
        // ball hit from above bounces off the floor and throws the striker back up).
        let rebound = -self.restitution * speed;
        let bounces = rebound > sub.rest_speed && self.separation + speed * sub.h < 0.0;
        let target = if bounces {
            rebound
        } else {
            self.resting_target
        };
        let total = (self.impulse + self.mass * (target - speed)).max(0.0);
        let change = total - self.impulse;
        // A bounce is over once the balls part: it is not pushed again in the next sub-step.
        self.impulse = if bounces || !sub.loaded { 0.0 } else { total };
        change
    }
}

impl PairContact {
    /// The velocity pass for this contact.
    pub(crate) fn solve_velocity(&mut self, a: &mut Body, b: &mut Body, sub: SubStep) {
        let speed = (b.velocity - a.velocity).dot(self.state.normal);
        let change = self.state.impulse_change(speed, sub);
        self.push_velocities(a, b, change);
    }

    /// The position pass for this contact: if the balls overlap beyond the slop, they move
    /// apart by `push`, each its share (the lighter one more), positions only.
    pub(crate) fn relax(&self, a: &mut Body, b: &mut Body, push: Push) {
        if !deeper_than_slop(a, b, self.reach) {
            return; // the common case, without a square root
        }
        let allowed = SLOP * self.reach / 2.0;
        let gap = pair_gap(a, b, self.reach, || self.state.normal);
        if gap.separation < -allowed {
            let push = push.distance(gap.separation, allowed) * self.state.mass;
            let (share_a, share_b) = (push * self.inverse_a, push * self.inverse_b);
            a.position -= share_a * gap.normal;
            b.position += share_b * gap.normal;
        }
    }

    /// When the balls, flying straight, first touch (infinite if never, 0 if they touch
    /// now); `None` if they overlap by more than the slop, which the position pass handles.
    pub(crate) fn touch_time(&self, balls: &[Body]) -> Option<f64> {
        let (a, b) = (&balls[self.a], &balls[self.b]);
        let p = b.position - a.position;
        let v = b.velocity - a.velocity;
        // |p + v·t| = reach: a quadratic in t, whose smaller root is the touch.
        let gap = p.length_squared() - self.reach * self.reach;
        let closing = p.dot(v);
        if gap <= 0.0 {
            // A pair that has just bounced touches still, or overlaps by a rounding error.
            let closest = self.reach * (1.0 - SLOP / 2.0);
            return match closing {
                _ if p.length_squared() < closest * closest => None,
                c if c < 0.0 => Some(0.0),
                _ => Some(f64::INFINITY),
            };
        }
        let discriminant = closing * closing - v.length_squared() * gap;
        if closing >= 0.0 || discriminant < 0.0 {
            return Some(f64::INFINITY);
        }
        // `gap / (−p·v + √…)` is that root without cancellation.
        Some(gap / (-closing + discriminant.sqrt()))
    }

    /// Gives `b` the impulse `impulse` along the normal and `a` the opposite one.
    pub(crate) fn push_velocities(&self, a: &mut Body, b: &mut Body, impulse: f64) {
        let normal = self.state.normal;
        let (da, db) = (impulse * self.inverse_a, impulse * self.inverse_b);
        a.velocity -= da * normal;
        b.velocity += db * normal;
    }
}

impl FixedContact {
    /// The velocity pass for this contact.
    pub(crate) fn solve_velocity(&mut self, ball: &mut Body, sub: SubStep) {
        let normal = self.state.normal;
        let change = self.state.impulse_change(ball.velocity.dot(normal), sub) / self.state.mass;
        ball.velocity += change * normal;
    }

    /// The position pass for this contact: if the ball is past the line by more than the
    /// slop, it moves back by `push`, position only.
    pub(crate) fn relax(&self, ball: &mut Body, push: Push) {
        let separation = self.gap(ball);
        let allowed = SLOP * ball.radius;
        if separation < -allowed {
            let push = push.distance(separation, allowed);
            ball.position += push * self.state.normal;
        }
    }

    /// When the ball, flying straight, reaches the line (infinite if never, 0 if it touches
    /// now); `None` if it is past the line by more than the slop.
    pub(crate) fn touch_time(&self, ball: &Body) -> Option<f64> {
        let separation = self.gap(ball);
        let approach = ball.velocity.dot(self.state.normal);
        match separation {
            s if s < -SLOP * ball.radius => None,
            _ if approach >= 0.0 => Some(f64::INFINITY),
            s => Some((-s / approach).max(0.0)),
        }
    }

    /// The gap between the ball and the line, px.
    pub(crate) fn gap(&self, ball: &Body) -> f64 {
        ball.position.dot(self.state.normal) - self.offset
    }
}

/// Whether balls `a` and `b`, whose radii add up to `reach`, overlap by more than the slop
/// ([`SLOP`] of their mean radius). Compared squared, without a square root.
pub(super) fn deeper_than_slop(a: &Body, b: &Body, reach: f64) -> bool {
    let closest = reach - SLOP * reach / 2.0;
    (b.position - a.position).length_squared() < closest * closest
}

/// The gap between two balls whose radii add up to `reach`, and the normal from `a` to `b`
/// (`fallback()` if their centres coincide).
pub(super) fn pair_gap(a: &Body, b: &Body, reach: f64, fallback: impl FnOnce() -> Vec2) -> Gap {
    let d = b.position - a.position;
    let distance = d.length_squared().sqrt();
    if distance > 0.0 {
        let normal = d / distance;
        Gap {
            separation: distance - reach,
            normal,
        }
    } else {
        Gap {
            separation: -reach,
            normal: fallback(),
        }
    }
}

/// Bodies `a` and `b` (`a < b`), both mutable.
pub(super) fn both_mut(bodies: &mut [Body], a: usize, b: usize) -> (&mut Body, &mut Body) {
    let (head, tail) = bodies.split_at_mut(b);
    (&mut head[a], &mut tail[0])
}

/// The normal for two balls at exactly the same centre, where the line between centres has
/// no direction. Any fixed direction would separate a pair, but a heap spawned on one spot
/// would then spread along a single line; so ball `j` leaves at `j` golden angles, which
/// fans successive balls out evenly round the circle, and depends on nothing but `j`.
pub(super) fn coincident_normal(j: usize) -> Vec2 {
    let angle = GOLDEN_ANGLE * j as f64;
    Vec2::new(maths::cos(angle), maths::sin(angle))
}
