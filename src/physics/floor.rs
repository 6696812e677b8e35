//! Floors: line segments the balls bounce off (the lesson's "sloped floor" extension).
//!
//! The reflection is the walls' idea in 2D: clamp the ball back along the segment's normal,
//! flip the normal component of its velocity with damping, keep the tangential one.

use super::ball::Ball;
use super::vec2::Vec2;

/// A line segment from `from` to `to` (px) and the share of normal speed a bounce keeps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Floor {
    pub from: Vec2,
    pub to: Vec2,
    pub damping: f64,
}

impl Floor {
    /// The end points `from` and `to`.
    pub(crate) fn ends(&self) -> [Vec2; 2] {
        [self.from, self.to]
    }

    /// The unit normal (left of `from → to`); which side a ball is on is the sign along it.
    pub(crate) fn normal(&self) -> Vec2 {
        let [from, to] = self.ends();
        let d = to - from;
        -d.perp() / d.length()
    }

    /// Where along the segment the point's projection falls: 0 at `from`, 1 at `to`.
    pub(crate) fn along(&self, point: Vec2) -> f64 {
        let [from, to] = self.ends();
        let d = to - from;
        (point - from).dot(d) / d.length_squared()
    }

    /// The unit normal from the segment towards `centre` and how far the centre is from the
    /// segment (its nearest point, which may be an end). A centre on the segment gets the
    /// face's normal. The contact solver builds its floor contacts from this.
    pub(crate) fn nearest(&self, centre: Vec2) -> (Vec2, f64) {
        let t = self.along(centre).clamp(0.0, 1.0);
        let [from, to] = self.ends();
        let point = from + t * (to - from);
        let offset = centre - point;
        let distance = offset.length();
        let normal = if distance > 0.0 {
            offset / distance
        } else {
            self.normal()
        };
        (normal, distance)
    }

    /// Resolves contact for a ball that moved from centre `from` to its current centre this step.
    ///
    /// Swept: if the ball's path crossed the segment's face (even moving many diameters per
    /// frame), it is put back on the side it came from. Otherwise a ball overlapping an end
    /// point bounces off it as off a point.
    pub(crate) fn bounce(&self, ball: &mut Ball, from: Vec2) {
        let (now, start, normal) = (ball.position(), self.from, self.normal());
        let before = (from - start).dot(normal);
        let after = (now - start).dot(normal);
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
                from + t * (now - from)
            } else {
                now
            };
            if (0.0..=1.0).contains(&self.along(contact)) {
                self.resolve(ball, normal * side, ball.radius - after);
                return;
            }
        }
        self.bounce_off_end(ball);
    }

    /// Puts back a ball whose centre crossed the segment's face on its way from `from`: a
    /// ball thrown through the floor within one step (struck by another harder than its own
    /// contacts could see coming). It goes back to the side it came from, touching the face,
    /// its velocity reflected as in a bounce. Anything short of a crossing is left alone.
    pub fn undo_crossing(&self, ball: &mut Ball, from: Vec2) {
        let (now, start, normal) = (ball.position(), self.from, self.normal());
        let (before, after) = ((from - start).dot(normal), (now - start).dot(normal));
        if before == 0.0 || before * after > 0.0 {
            return; // the centre stayed on its side
        }
        let met = from + before / (before - after) * (now - from);
        if (0.0..=1.0).contains(&self.along(met)) {
            let side = before.signum();
            self.resolve(ball, normal * side, ball.radius - after * side);
        }
    }

    /// A ball overlapping the nearer end point is pushed out and reflected about the line
    /// from that point to its centre.
    fn bounce_off_end(&self, ball: &mut Ball) {
        let [from, to] = self.ends();
        let end = if self.along(ball.position()) < 0.5 {
            from
        } else {
            to
        };
        let offset = ball.position() - end;
        let distance = offset.length();
        if distance >= ball.radius || distance == 0.0 {
            return;
        }
        self.resolve(ball, offset / distance, ball.radius - distance);
    }

    /// Moves the ball `depth` along `n` and, if it is moving into the floor, reflects the
    /// normal component of its velocity with damping.
    fn resolve(&self, ball: &mut Ball, n: Vec2, depth: f64) {
        let position = ball.position() + n * depth;
        (ball.x, ball.y) = (position.x, position.y);
        let normal_speed = ball.velocity().dot(n);
        if normal_speed < 0.0 {
            let change = (1.0 + self.damping) * normal_speed;
            let velocity = ball.velocity() - change * n;
            (ball.vx, ball.vy) = (velocity.x, velocity.y);
        }
    }
}
