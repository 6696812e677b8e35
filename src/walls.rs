//! The box the ball bounces in: clamp-then-reflect with damping, the lesson's concept 2.

use crate::ball::Ball;

/// The four walls of a `width` × `height` box (px) and the share of speed a bounce keeps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Walls {
    pub width: f64,
    pub height: f64,
    /// 1.0 is perfectly elastic, 0.0 stops the ball dead.
    pub damping: f64,
}

impl Walls {
    /// Clamps the ball back inside the box, then reflects the velocity component normal to
    /// the wall it crossed, losing some energy. Clamping first means the ball ends the frame
    /// touching the wall, never inside it, so the next frame cannot flip it back (the jitter bug).
    /// Left/right is one if/else and top/bottom another, as in the lesson's hint.
    pub fn bounce(&self, ball: &mut Ball) {
        if ball.x - ball.radius < 0.0 {
            ball.x = ball.radius;
            ball.vx = -ball.vx * self.damping;
        } else if ball.x + ball.radius > self.width {
            ball.x = self.width - ball.radius;
            ball.vx = -ball.vx * self.damping;
        }
        if ball.y - ball.radius < 0.0 {
            ball.y = ball.radius;
            ball.vy = -ball.vy * self.damping;
        } else if ball.y + ball.radius > self.height {
            ball.y = self.height - ball.radius;
            ball.vy = -ball.vy * self.damping;
        }
    }

    /// Puts a ball that something other than its own motion pushed out of the box (a
    /// neighbour, in a ball-ball collision) back inside, without touching its velocity: it
    /// did not hit the wall, it was shoved.
    pub fn contain(&self, ball: &mut Ball) {
        ball.x = ball.x.clamp(ball.radius, self.width - ball.radius);
        ball.y = ball.y.clamp(ball.radius, self.height - ball.radius);
    }
}
