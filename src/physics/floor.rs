//! Floors: line segments the balls bounce off (the lesson's "sloped floor" extension).
//!
//! The reflection is the walls' idea in 2D: clamp the ball back along the segment's normal,
//! flip the normal component of its velocity with damping, keep the tangential one.

use super::ball::Ball;
use super::maths;

/// A line segment from `from` to `to` (px) and the share of normal speed a bounce keeps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Floor {
    pub from: [f64; 2],
    pub to: [f64; 2],
    pub damping: f64,
}

/// `a − b`.
pub fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

/// `a · b`.
pub fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

impl Floor {
    /// The unit normal (left of `from → to`); which side a ball is on is the sign along it.
    pub fn normal(&self) -> [f64; 2] {
        let [dx, dy] = sub(self.to, self.from);
        let length = maths::hypot(dx, dy);
        [dy / length, -dx / length]
    }

    /// Where along the segment the point's projection falls: 0 at `from`, 1 at `to`.
    pub fn along(&self, point: [f64; 2]) -> f64 {
        let d = sub(self.to, self.from);
        dot(sub(point, self.from), d) / dot(d, d)
    }

    /// The unit normal from the segment towards `centre` and how far the centre is from the
    /// segment (its nearest point, which may be an end). A centre on the segment gets the
    /// face's normal. The contact solver builds its floor contacts from this.
    pub fn nearest(&self, centre: [f64; 2]) -> ([f64; 2], f64) {
        let t = self.along(centre).clamp(0.0, 1.0);
        let point = [
            self.from[0] + t * (self.to[0] - self.from[0]),
            self.from[1] + t * (self.to[1] - self.from[1]),
        ];
        let offset = sub(centre, point);
        let distance = maths::hypot(offset[0], offset[1]);
        if distance > 0.0 {
            ([offset[0] / distance, offset[1] / distance], distance)
        } else {
            (self.normal(), 0.0)
        }
    }

    /// Resolves contact for a ball that moved from centre `from` to its current centre this step.
    ///
    /// Swept: if the ball's path crossed the segment's face (even moving many diameters per
    /// frame), it is put back on the side it came from. Otherwise a ball overlapping an end
    /// point bounces off it as off a point.
    pub fn bounce(&self, ball: &mut Ball, from: [f64; 2]) {
        let normal = self.normal();
        let now = [ball.x, ball.y];
        let before = dot(sub(from, self.from), normal);
        let after = dot(sub(now, self.from), normal);
        // The side the ball came from; distances below are measured towards that side.
        let side = if before != 0.0 {
            before.signum()
        } else {
            after.signum().max(0.0) * 2.0 - 1.0
        };
        let (before, after) = (before * side, after * side);
        if after < ball.radius {
            // Where the path first touched the face's line (or now, if it started touching).
            let contact = if before > ball.radius {
                let t = (before - ball.radius) / (before - after);
                [
                    from[0] + t * (now[0] - from[0]),
                    from[1] + t * (now[1] - from[1]),
                ]
            } else {
                now
            };
            if (0.0..=1.0).contains(&self.along(contact)) {
                let n = [normal[0] * side, normal[1] * side];
                self.resolve(ball, n, ball.radius - after);
                return;
            }
        }
        self.bounce_off_end(ball);
    }

    /// A ball overlapping the nearer end point is pushed out and reflected about the line
    /// from that point to its centre.
    fn bounce_off_end(&self, ball: &mut Ball) {
        let end = if self.along([ball.x, ball.y]) < 0.5 {
            self.from
        } else {
            self.to
        };
        let offset = sub([ball.x, ball.y], end);
        let distance = maths::hypot(offset[0], offset[1]);
        if distance >= ball.radius || distance == 0.0 {
            return;
        }
        let n = [offset[0] / distance, offset[1] / distance];
        self.resolve(ball, n, ball.radius - distance);
    }

    /// Moves the ball `depth` along `n` and, if it is moving into the floor, reflects the
    /// normal component of its velocity with damping.
    fn resolve(&self, ball: &mut Ball, n: [f64; 2], depth: f64) {
        ball.x += n[0] * depth;
        ball.y += n[1] * depth;
        let normal_speed = ball.vx * n[0] + ball.vy * n[1];
        if normal_speed < 0.0 {
            let change = (1.0 + self.damping) * normal_speed;
            ball.vx -= change * n[0];
            ball.vy -= change * n[1];
        }
    }
}
