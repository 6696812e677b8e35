//! The lesson's named mistakes, each a variant of the lesson's step that can be simulated:
//! the starter example (`examples/starter.rs`) names the one a learner's ball follows, and
//! `check` names the one a handed-in GIF or trajectory shows. A new pitfall is one more entry
//! here, and both learn it.

use crate::physics::ball::Ball;
use crate::physics::walls::Walls;

/// A mistake the lesson warns about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pitfall {
    NothingMoves,
    NoClamp,
    GravityTwice,
    GravityAtBounce,
    PositionFirst,
    TrailBeforeMove,
    /// Drawing the trail after the ball: the physics is right, only the picture shows it.
    TrailOverBall,
}

impl Pitfall {
    pub(crate) const ALL: [Pitfall; 7] = [
        Pitfall::NothingMoves,
        Pitfall::NoClamp,
        Pitfall::GravityTwice,
        Pitfall::GravityAtBounce,
        Pitfall::PositionFirst,
        Pitfall::TrailBeforeMove,
        Pitfall::TrailOverBall,
    ];

    /// Its name on the command line and in JSON (`tools/lesson.py gif --pitfall NAME`).
    pub(crate) fn name(self) -> &'static str {
        match self {
            Pitfall::NothingMoves => "nothing-moves",
            Pitfall::NoClamp => "no-clamp",
            Pitfall::GravityTwice => "gravity-twice",
            Pitfall::GravityAtBounce => "gravity-at-bounce",
            Pitfall::PositionFirst => "position-first",
            Pitfall::TrailBeforeMove => "trail-before-move",
            Pitfall::TrailOverBall => "trail-over-ball",
        }
    }

    /// The mistake in a learner's words, and what to do instead.
    pub fn explain(self) -> &'static str {
        match self {
            Pitfall::NothingMoves => "nothing moves the ball yet: the TODOs are still empty",
            Pitfall::NoClamp => {
                "reflecting the velocity without clamping the position: the ball sinks into \
                 the wall and jitters there (put it back on the wall, then flip the velocity)"
            }
            Pitfall::GravityTwice => "adding gravity twice in one step",
            Pitfall::GravityAtBounce => {
                "adding gravity again in the wall response: the ball speeds up at every bounce"
            }
            Pitfall::PositionFirst => {
                "moving the ball before adding gravity: the lesson changes the velocity first"
            }
            Pitfall::TrailBeforeMove => {
                "appending to the trail before the move: the trail lags a frame behind the ball"
            }
            Pitfall::TrailOverBall => {
                "drawing the trail after the ball: the trail covers the ball (draw the trail \
                 first, the ball last)"
            }
        }
    }

    /// Whether the mistake changes where the ball goes (else it shows only in pictures or
    /// in the trail).
    pub(crate) fn shows_in_trajectory(self) -> bool {
        !matches!(self, Pitfall::TrailBeforeMove | Pitfall::TrailOverBall)
    }

    /// One step of the lesson ([`Ball::step`]) with this mistake in it.
    pub(crate) fn step(self, ball: &mut Ball, gravity: f64, walls: &Walls) {
        match self {
            Pitfall::NothingMoves => {
                ball.record_trail();
                return;
            }
            Pitfall::TrailOverBall => return ball.step(gravity, walls),
            Pitfall::TrailBeforeMove => ball.record_trail(),
            _ => {}
        }
        let kicks = if self == Pitfall::GravityTwice { 2 } else { 1 };
        if self != Pitfall::PositionFirst {
            for _ in 0..kicks {
                ball.vy += gravity;
            }
        }
        ball.x += ball.vx;
        ball.y += ball.vy;
        if self == Pitfall::PositionFirst {
            ball.vy += gravity;
        }
        let r = ball.radius;
        let axes = [
            (&mut ball.x, &mut ball.vx, walls.width, 0.0),
            (&mut ball.y, &mut ball.vy, walls.height, gravity),
        ];
        for (position, velocity, size, pull) in axes {
            let wall = if *position - r < 0.0 {
                r
            } else if *position + r > size {
                size - r
            } else {
                continue;
            };
            if self != Pitfall::NoClamp {
                *position = wall;
            }
            *velocity = -*velocity * walls.damping;
            if self == Pitfall::GravityAtBounce {
                *velocity += pull;
            }
        }
        if self != Pitfall::TrailBeforeMove {
            ball.record_trail();
        }
    }

    /// The pitfall whose step turns `before` into `after`, if one does (the first in
    /// `Pitfall::ALL`).
    pub fn of_step(before: &Ball, after: &Ball, gravity: f64, walls: &Walls) -> Option<Pitfall> {
        Pitfall::ALL.into_iter().find(|pitfall| {
            let mut ball = before.clone();
            pitfall.step(&mut ball, gravity, walls);
            ball == *after
        })
    }
}
