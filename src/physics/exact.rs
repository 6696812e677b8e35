//! Exact collisions with the walls: instead of clamping after the step, find the moment in the
//! step at which the ball's flight touches a wall, bounce there, and fly on for the rest of it.
//!
//! "The flight" is the integrator's own (`Integrator::path`): for velocity Verlet and RK4 under
//! gravity alone it is the true parabola, so every bounce is exact to rounding. The Euler
//! methods move in a straight line between velocity kicks, so for them exact mode removes the
//! clamp's error but keeps Euler's: the bounce happens where *their* ball meets the wall.
//!
//! Two rules make every step finish:
//! - **Rest.** A ball dropped with damping `e < 1` bounces infinitely often before
//!   `t∞ = √(2h/g)·(1+e)/(1−e)` (Zeno). A bounce whose rebound speed would be below
//!   [`REST_SPEED`], on a wall gravity presses the ball into, ends in rest instead: the ball
//!   stays touching with no normal speed, and while it rests the wall cancels gravity's push.
//! - **A cap.** After [`MAX_EVENTS_PER_STEP`] bounces in one step (a ball moving thousands of
//!   box widths a frame), the rest of the step is flown and clamped as in the lesson.
//!
//! Floors are not handled here: in exact mode they keep the lesson's clamp-then-reflect.

use super::ball::Ball;
use super::integrator::{Forces, Integrator};
use super::poly::Poly;
use super::walls::Walls;

/// Rebound speed below which a bounce ends in rest, px/frame.
///
/// Box2D and Rapier stop bouncing below 1 m/s. This program has no metres, but its gravity
/// fixes a scale: if the lesson's 0.5 px/frame² at 30 ms a frame is Earth's 9.81 m/s², then
/// 1 m = 0.5 / (9.81 · 0.03²) = 56.6 px and 1 m/s = 56.6 · 0.03 = 1.7 px/frame. Such a rebound
/// rises v²/2g = 2.9 px (5 cm) and lasts 2v/g = 6.8 frames (0.2 s).
pub const REST_SPEED: f64 = 1.7;

/// The most bounces resolved exactly in one step.
pub const MAX_EVENTS_PER_STEP: u32 = 64;

/// One wall of the box, seen from a ball of a given radius.
#[derive(Clone, Copy)]
struct Side {
    /// 0 for the left and right walls (they stop x), 1 for the top and bottom ones.
    axis: usize,
    /// The coordinate of the centre when the ball touches the wall.
    contact: f64,
    /// +1 for the wall at the high end of the axis (right, bottom), −1 for the low end, so
    /// the distance to the wall is `outward · (contact − centre)`.
    outward: f64,
}

impl Side {
    /// The four walls for `ball`, with the same contact coordinates as `Ball::bounce_off_walls`.
    fn all(walls: &Walls, ball: &Ball) -> [Side; 4] {
        let r = ball.radius;
        [
            (0, r, -1.0),
            (0, walls.width - r, 1.0),
            (1, r, -1.0),
            (1, walls.height - r, 1.0),
        ]
        .map(|(axis, contact, outward)| Side {
            axis,
            contact,
            outward,
        })
    }

    fn distance(&self, ball: &Ball) -> f64 {
        self.outward * (self.contact - position(ball)[self.axis])
    }

    /// Whether gravity pushes the ball into this wall.
    fn pressed(&self, forces: &Forces) -> bool {
        forces
            .gravity
            .is_some_and(|g| g[self.axis] * self.outward > 0.0)
    }

    /// Puts the ball exactly on the wall and bounces it, or lets it come to rest there.
    fn bounce(&self, ball: &mut Ball, damping: f64, forces: &Forces) {
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
        *velocity = if rebound < REST_SPEED && self.pressed(forces) {
            0.0
        } else {
            -*velocity * damping
        };
    }
}

fn position(ball: &Ball) -> [f64; 2] {
    [ball.x, ball.y]
}

fn velocity(ball: &Ball) -> [f64; 2] {
    [ball.vx, ball.vy]
}

/// One step of `forces.dt` frames with exact bounces off `walls`.
pub fn step(integrator: Integrator, ball: &mut Ball, forces: &Forces, walls: &Walls) {
    // A ball that starts the step inside a wall (spawned there, or left there by a capped
    // step) is put back first, so every distance below starts at zero or more.
    ball.bounce_off_walls(walls);
    let sides = Side::all(walls, ball);
    // Resting can only begin or end at a bounce, so these forces hold until the next one.
    let mut flight = supported(ball, forces, &sides);
    integrator.kick_before(ball, &flight);
    let mut left = forces.dt;
    for _ in 0..MAX_EVENTS_PER_STEP {
        let path = integrator.path(ball, &flight);
        match first_contact(&sides, ball, &path, left) {
            Some((time, side)) => {
                integrator.fly(ball, &flight, time);
                left -= time;
                side.bounce(ball, walls.damping, forces);
                flight = supported(ball, forces, &sides);
            }
            None => {
                integrator.fly(ball, &flight, left);
                left = 0.0;
                break;
            }
        }
    }
    if left > 0.0 {
        integrator.fly(ball, &flight, left);
        ball.bounce_off_walls(walls);
        flight = supported(ball, forces, &sides);
    }
    integrator.kick_after(ball, &flight);
}

/// The forces with gravity's push removed on every wall the ball rests on: touching it, not
/// moving through it, pressed into it. The wall holds the ball up, so it stays exactly there.
fn supported(ball: &Ball, forces: &Forces, sides: &[Side; 4]) -> Forces {
    let mut held = *forces;
    for side in sides {
        let resting = side.distance(ball) == 0.0 && velocity(ball)[side.axis] == 0.0;
        if resting && side.pressed(forces) {
            if let Some(g) = held.gravity.as_mut() {
                g[side.axis] = 0.0;
            }
        }
    }
    held
}

/// The earliest wall the flight `path` touches within `left` frames, and when.
fn first_contact(
    sides: &[Side; 4],
    ball: &Ball,
    path: &[Poly; 2],
    left: f64,
) -> Option<(f64, Side)> {
    // How far the flight can carry the centre along each axis: walls further away are skipped
    // without looking for roots.
    let reach = path.map(|p| p.reach(left));
    sides
        .iter()
        .filter(|side| reach[side.axis] >= side.distance(ball))
        .filter_map(|side| {
            let gap = path[side.axis]
                .scale(-side.outward)
                .plus(side.outward * side.contact);
            gap.first_negative(left).map(|time| (time, *side))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
}
