//! Exact collisions with the walls and floors: instead of clamping after the step, find the
//! moment in the step at which the ball's flight touches a wall, a floor's face or a floor's
//! end point, bounce there, and fly on for the rest of it.
//!
//! "The flight" is the integrator's own (`Integrator::path`): for velocity Verlet and RK4 under
//! gravity alone it is the true parabola, so every bounce is exact to rounding. The Euler
//! methods move in a straight line between velocity kicks, so for them exact mode removes the
//! clamp's error but keeps Euler's: the bounce happens where *their* ball meets the wall.
//!
//! A floor is a segment: the ball meets its face when the centre comes within `r` of the
//! segment's line with its foot on the segment, and an end point when the centre comes within
//! `r` of it (`super::toi`). Nothing is clamped, so a ball can never be left inside a floor,
//! nor inside a floor where it meets a wall.
//!
//! Two rules make every step finish:
//! - **Rest.** A ball dropped with damping `e < 1` bounces infinitely often before
//!   `t∞ = √(2h/g)·(1+e)/(1−e)` (Zeno). A bounce whose rebound speed would be below
//!   [`REST_SPEED`], on a wall or floor gravity presses the ball into, ends in rest instead
//!   (elastic bounces never shrink, so `e = 1` never rests):
//!   the ball stays touching with no normal speed, and while it rests the surface holds the
//!   part of gravity that pushes into it (on a slope the ball slides along the rest).
//! - **A cap.** After [`MAX_EVENTS_PER_STEP`] bounces in one step (a ball moving thousands of
//!   box widths a frame, or wedged in a corner), the rest of the step is dropped: the ball
//!   stays where the last bounce left it, touching and never inside. [`step`] returns whether
//!   that happened, so callers can report it.

use super::integrator::{Forces, Integrator};
use super::poly::Poly;
use super::toi;
use crate::physics::ball::Ball;
use crate::physics::effects::Effects;
use crate::physics::floor::Floor;
use crate::physics::tolerances::{
    FLOOR_TOUCH_GAP, MAX_EVENTS_PER_STEP, MAX_SUPPORTS, REST_SPEED, TOUCH_SPEED,
};
use crate::physics::vec2::Vec2;
use crate::physics::walls::Walls;

/// One wall of the box, seen from a ball of a given radius.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Side {
    /// 0 for the left and right walls (they stop x), 1 for the top and bottom ones.
    axis: usize,
    /// The coordinate of the centre when the ball touches the wall.
    contact: f64,
    /// +1 for the wall at the high end of the axis (right, bottom), −1 for the low end, so
    /// the distance to the wall is `outward · (contact − centre)`.
    outward: f64,
    damping: f64,
}

impl Side {
    /// The four walls for `ball`, with the same contact coordinates as `Ball::bounce_off_walls`.
    pub(crate) fn all(walls: &Walls, ball: &Ball) -> [Side; 4] {
        let r = ball.radius;
        // Four calls, not a `map` over four tuples: this runs at every prediction, and the
        // map was not inlined.
        let side = |axis, contact, outward| Side {
            axis,
            contact,
            outward,
            damping: walls.damping,
        };
        [
            side(0, r, -1.0),
            side(0, walls.width - r, 1.0),
            side(1, r, -1.0),
            side(1, walls.height - r, 1.0),
        ]
    }

    /// The component of `v` along the wall's axis.
    fn component(&self, v: Vec2) -> f64 {
        v.axis(self.axis)
    }

    fn distance(&self, ball: &Ball) -> f64 {
        self.outward * (self.contact - self.component(ball.position()))
    }

    /// The wall's unit normal, pointing into the box.
    fn normal(&self) -> Vec2 {
        let mut n = [0.0; 2];
        n[self.axis] = -self.outward;
        Vec2::from(n)
    }

    /// Puts the ball exactly on the wall and bounces it, or lets it come to rest there.
    fn bounce(&self, ball: &mut Ball, forces: &Forces) {
        let damping = self.damping;
        let (coordinate, velocity) = match self.axis {
            0 => (&mut ball.x, &mut ball.vx),
            _ => (&mut ball.y, &mut ball.vy),
        };
        *coordinate = self.contact;
        let into = *velocity * self.outward;
        if into < 0.0 {
            return; // already leaving (it was a rounding error inside the wall): just put back
        }
        let rebound = damping * into;
        *velocity = if rests(rebound, damping, forces, self.normal()) {
            0.0
        } else {
            -*velocity * damping
        };
    }
}

/// The rest rule: whether a bounce with rebound speed `rebound` off a surface of unit normal
/// `n` that keeps `damping` of the speed ends in rest. Elastic bounces never shrink, so they
/// never need it.
pub(crate) fn rests(rebound: f64, damping: f64, forces: &Forces, n: Vec2) -> bool {
    damping < 1.0 && rebound < REST_SPEED && pressed(forces, n)
}

/// Whether gravity pushes a ball into a surface whose unit normal (pointing at the ball) is `n`.
pub(crate) fn pressed(forces: &Forces, n: Vec2) -> bool {
    forces.gravity.is_some_and(|g| g.dot(n) < 0.0)
}

/// Something fixed a ball can touch.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Contact {
    Wall(Side),
    /// A floor's face; `normal` points from the floor to the ball.
    Face {
        normal: Vec2,
        damping: f64,
    },
    /// A floor's end point, bounced off like a ball of radius 0 that never moves.
    End {
        point: Vec2,
        damping: f64,
    },
}

impl Contact {
    /// Bounces `ball`, which touches this contact now, or lets it come to rest there.
    pub(crate) fn bounce(&self, ball: &mut Ball, forces: &Forces) {
        match *self {
            Contact::Wall(side) => side.bounce(ball, forces),
            Contact::Face { normal, damping } => bounce_along(ball, normal, damping, forces),
            Contact::End { point, damping } => {
                let offset = ball.position() - point;
                let distance = offset.length();
                if distance > 0.0 {
                    bounce_along(ball, offset / distance, damping, forces);
                }
            }
        }
    }
}

/// Reflects the velocity's component into a surface of unit normal `n` (pointing at the ball)
/// with `damping`, or removes it (rest) when the rebound would be slower than [`REST_SPEED`]
/// and gravity presses the ball into the surface. The tangential component is kept.
fn bounce_along(ball: &mut Ball, n: Vec2, damping: f64, forces: &Forces) {
    let normal_speed = ball.velocity().dot(n);
    if normal_speed >= 0.0 {
        return;
    }
    let keep = if rests(-damping * normal_speed, damping, forces, n) {
        0.0
    } else {
        damping
    };
    let change = (1.0 + keep) * normal_speed;
    let velocity = ball.velocity() - change * n;
    (ball.vx, ball.vy) = (velocity.x, velocity.y);
}

/// The surfaces a ball rests on, as unit normals pointing at the ball (walls, floors, and in
/// `crate::physics::events` other balls): they hold the part of gravity that presses into
/// them.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Support {
    normals: [Vec2; MAX_SUPPORTS],
    len: usize,
}

impl Support {
    /// Adds a surface the ball rests on (beyond [`MAX_SUPPORTS`], the ball is held
    /// completely).
    pub(crate) fn push(&mut self, n: Vec2) {
        if self.len < MAX_SUPPORTS {
            self.normals[self.len] = n;
        }
        self.len += 1;
    }

    /// Whether these surfaces hold a ball up completely against gravity `g`, leaving it no
    /// way to slide: "up" (against `g`) is a sum of the surfaces' normals with weights no
    /// less than 0, so pushes along the normals alone can balance gravity (the equilibrium
    /// of a frictionless disc). In two dimensions that is: along one normal, or between two
    /// normals less than half a turn apart (a wall beside the ball counts: it stops a slide
    /// towards it, and so does a ball above it on the side it would slide to).
    pub(crate) fn hold_completely(&self, g: Vec2) -> bool {
        if self.len > MAX_SUPPORTS {
            return true;
        }
        let up = -g;
        let normals = &self.normals[..self.len];
        let cross = |a: Vec2, b: Vec2| a.x * b.y - a.y * b.x;
        normals.iter().enumerate().any(|(k, &a)| {
            let along = cross(a, up) == 0.0 && a.dot(up) > 0.0;
            along
                || normals[k + 1..].iter().any(|&b| {
                    // up = α·a + β·b, by Cramer's rule; both weights must be at least 0.
                    let det = cross(a, b);
                    det != 0.0 && cross(up, b) / det >= 0.0 && cross(a, up) / det >= 0.0
                })
        })
    }

    /// `forces` with gravity's push into every surface removed. On one surface gravity keeps
    /// its tangential part (a ball rests on a slope by sliding down it); if what is left still
    /// presses into another surface, the ball is wedged and held completely.
    pub(crate) fn hold(&self, forces: &Forces) -> Forces {
        let mut held = *forces;
        if self.len == 0 {
            return held;
        }
        let Some(gravity) = held.gravity.as_mut() else {
            return held;
        };
        if self.len > MAX_SUPPORTS {
            *gravity = Vec2::ZERO;
            return held;
        }
        let normals = &self.normals[..self.len];
        let mut g = *gravity;
        for &n in normals {
            let push = g.dot(n);
            if push < 0.0 {
                g -= push * n;
            }
        }
        if normals.iter().any(|&n| g.dot(n) < -TOUCH_SPEED) {
            g = Vec2::ZERO;
        }
        *gravity = g;
        held
    }
}

/// One step of `forces.dt` frames with exact bounces off the walls and floors of `effects`.
/// Returns `false` if the step hit [`MAX_EVENTS_PER_STEP`] and its rest was dropped.
pub(crate) fn step(
    integrator: Integrator,
    ball: &mut Ball,
    forces: &Forces,
    effects: &Effects,
) -> bool {
    put_back(ball, effects);
    let bounds = BallBounds::of(ball, effects);
    let mut flight = bounds.supported(ball, forces);
    integrator.kick_before(ball, &flight);
    let mut left = forces.dt;
    let mut finished = false;
    for _ in 0..MAX_EVENTS_PER_STEP {
        let path = integrator.path(ball, &flight);
        match bounds.first_contact(ball, &path, left) {
            Some((time, contact)) => {
                integrator.fly(ball, &flight, time);
                left -= time;
                contact.bounce(ball, forces);
                flight = bounds.supported(ball, forces);
            }
            None => {
                integrator.fly(ball, &flight, left);
                finished = true;
                break;
            }
        }
    }
    integrator.kick_after(ball, &flight);
    finished
}

/// A ball that starts a step inside a wall (spawned there) is put back first, as the lesson
/// would, so every distance to a wall starts at zero or more.
pub(crate) fn put_back(ball: &mut Ball, effects: &Effects) {
    if let Some(walls) = &effects.walls {
        ball.bounce_off_walls(walls);
    }
}

/// The bounds of one ball's flight: the walls and floors it can touch during a step, as it
/// (its radius) sees them.
pub(crate) struct BallBounds<'a> {
    sides: Option<[Side; 4]>,
    floors: &'a [Floor],
}

impl<'a> BallBounds<'a> {
    /// The walls and floors of `effects` as `ball` (its radius) sees them.
    pub(crate) fn of(ball: &Ball, effects: &'a Effects) -> BallBounds<'a> {
        BallBounds {
            sides: effects.walls.as_ref().map(|walls| Side::all(walls, ball)),
            floors: &effects.floors,
        }
    }

    /// The walls and floor faces `ball` rests on now: touching, not moving through them.
    pub(crate) fn support(&self, ball: &Ball) -> Support {
        self.surfaces(
            |side| side.distance(ball) == 0.0 && side.component(ball.velocity()) == 0.0,
            |floor| resting_on_face(floor, ball),
        )
    }

    /// The walls and floor faces within `gap` (a share of the radius) of `ball`, whatever its
    /// speed: what may hold up a ball that sleeps (`crate::physics::events::system`).
    pub(crate) fn near(&self, ball: &Ball, gap: f64) -> Support {
        self.surfaces(
            |side| side.distance(ball) <= gap * ball.radius,
            |floor| face_within(floor, ball, gap),
        )
    }

    /// The walls `wall` accepts and the floor faces `face` gives a normal for.
    fn surfaces(
        &self,
        wall: impl Fn(&Side) -> bool,
        face: impl Fn(&Floor) -> Option<Vec2>,
    ) -> Support {
        let mut support = Support::default();
        for side in self.sides.iter().flatten().filter(|side| wall(side)) {
            support.push(side.normal());
        }
        for n in self.floors.iter().filter_map(face) {
            support.push(n);
        }
        support
    }

    /// The forces with gravity's push removed on every surface the ball rests on. Resting can
    /// only begin or end at a bounce, so these forces hold until the next one.
    pub(crate) fn supported(&self, ball: &Ball, forces: &Forces) -> Forces {
        if forces.gravity.is_none() {
            return *forces;
        }
        self.support(ball).hold(forces)
    }

    /// The earliest wall, floor face or floor end the flight `path` touches within `left`
    /// frames, and when.
    pub(crate) fn first_contact(
        &self,
        ball: &Ball,
        path: &[Poly; 2],
        left: f64,
    ) -> Option<(f64, Contact)> {
        // How far the flight can carry the centre along each axis: walls and floors further
        // away are skipped without looking for roots.
        let reach = Vec2::from(path.map(|p| p.reach(left)));
        let mut first: Option<(f64, Contact)> = None;
        let mut keep_earliest = |found: Option<(f64, Contact)>| {
            if let Some((time, contact)) = found {
                if first.is_none_or(|(earliest, _)| time < earliest) {
                    first = Some((time, contact));
                }
            }
        };
        // Plain loops rather than an iterator chain: this runs after every event.
        for side in self.sides.iter().flatten() {
            if reach.axis(side.axis) < side.distance(ball) {
                continue;
            }
            let gap = path[side.axis] * -side.outward + side.outward * side.contact;
            keep_earliest(
                gap.first_negative(left)
                    .map(|time| (time, Contact::Wall(*side))),
            );
        }
        for floor in self.floors {
            keep_earliest(floor_contact(floor, ball, path, left, reach));
        }
        first
    }
}

/// The signed distance of the flight's centre from the floor's line, along its normal.
fn line_distance(floor: &Floor, path: &[Poly; 2]) -> Poly {
    let (n, [from, _]) = (floor.normal(), floor.ends());
    path[0] * n.x + path[1] * n.y - n.dot(from)
}

/// Whether a point's foot on the floor's line falls on the segment.
fn on_segment(floor: &Floor, point: Vec2) -> bool {
    (0.0..=1.0).contains(&floor.along(point))
}

/// The normal of the floor's face `ball` rests on, if it touches the face with no normal speed.
fn resting_on_face(floor: &Floor, ball: &Ball) -> Option<Vec2> {
    face_within(floor, ball, FLOOR_TOUCH_GAP)
        .filter(|&n| ball.velocity().dot(n).abs() <= TOUCH_SPEED)
}

/// The normal (pointing at the ball) of the floor's face, if `ball` is within `gap` (a share
/// of its radius) of touching it, with its foot on the segment.
fn face_within(floor: &Floor, ball: &Ball, gap: f64) -> Option<Vec2> {
    let (n, [from, _]) = (floor.normal(), floor.ends());
    let distance = (ball.position() - from).dot(n);
    let n = if distance < 0.0 { -n } else { n };
    let touching = (distance.abs() - ball.radius).abs() <= gap * ball.radius;
    (touching && on_segment(floor, ball.position())).then_some(n)
}

/// When the flight `path` of `ball` first touches the floor's face or one of its end points
/// within `left` frames, and which.
fn floor_contact(
    floor: &Floor,
    ball: &Ball,
    path: &[Poly; 2],
    left: f64,
    reach: Vec2,
) -> Option<(f64, Contact)> {
    let r = ball.radius;
    let distance = line_distance(floor, path);
    let now = distance.at(0.0);
    if now.abs() - r > reach.x + reach.y {
        return None; // the line, so the whole segment, is out of reach this step
    }
    let side = if now < 0.0 { -1.0 } else { 1.0 };
    let gap = distance * side - r;
    let approaching = |time: f64| gap.slope(time) < -TOUCH_SPEED;
    let at = |time: f64| Vec2::new(path[0].at(time), path[1].at(time));
    let face_time = if gap.at(0.0) >= 0.0 {
        gap.first_negative(left)
            .filter(|&time| approaching(time) && on_segment(floor, at(time)))
    } else {
        // Within `r` of the line: beside the segment (only its ends can be met), or on the face
        // by a rounding error (bounce now if moving into it).
        (on_segment(floor, at(0.0)) && approaching(0.0)).then_some(0.0)
    };
    let face = face_time.map(|time| {
        let normal = floor.normal() * side;
        (
            time,
            Contact::Face {
                normal,
                damping: floor.damping,
            },
        )
    });
    let ends = floor.ends().map(|point| {
        let offset = [path[0] - point.x, path[1] - point.y];
        toi::first_touch(&offset, r, left).map(|time| {
            (
                time,
                Contact::End {
                    point,
                    damping: floor.damping,
                },
            )
        })
    });
    face.into_iter()
        .chain(ends.into_iter().flatten())
        .min_by(|a, b| a.0.total_cmp(&b.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Gravity as in the lesson, straight down.
    const G: Vec2 = Vec2::new(0.0, 0.5);

    fn support(normals: &[Vec2]) -> Support {
        let mut support = Support::default();
        for &n in normals {
            support.push(n / n.length());
        }
        support
    }

    #[test]
    fn a_ball_is_held_completely_only_where_pushes_along_the_normals_can_balance_gravity() {
        // Resting a little right of the top of the ball below, it slides off to the right...
        let below = Vec2::new(0.01, -1.0);
        // ...unless a ball on that side, even one a little higher, stops it.
        let higher_on_the_right = Vec2::new(-0.93, 0.37);
        let higher_on_the_left = Vec2::new(0.93, 0.37);
        let cases = [
            ("on a flat floor", vec![Vec2::new(0.0, -1.0)], true),
            (
                "between two walls",
                vec![Vec2::new(1.0, 0.0), Vec2::new(-1.0, 0.0)],
                false,
            ),
            ("just off the top of a ball", vec![below], false),
            (
                "off the top, stopped on the side it slides to",
                vec![below, higher_on_the_right],
                true,
            ),
            (
                "off the top, touching the other side",
                vec![below, higher_on_the_left],
                false,
            ),
        ];
        for (name, normals, expected) in cases {
            let held = support(&normals).hold_completely(G);
            assert_eq!(
                held, expected,
                "{name}: expected held = {expected}, got {held}"
            );
        }
    }
}
