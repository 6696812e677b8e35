//! A collision of two balls in exact mode: the bounce along the line through their centres,
//! and the rules for inelastic collapse that act on it (the TC model, waking a sleeping ball
//! struck hard, the rest rule on a held ball). See `super` for the rules.

use super::EventDriven;
use crate::physics::ball::{mass, Ball};
use crate::physics::integrate::exact;
use crate::physics::integrate::integrator::Forces;
use crate::physics::tolerances::{REST_SPEED, TC_DURATION};
use crate::physics::vec2::Vec2;

impl EventDriven {
    /// Bounces balls `i` and `j`, which touch now, along the line through their centres.
    ///
    /// Both get the same impulse in opposite directions, so momentum is kept; the relative
    /// normal speed `u < 0` becomes `−e·u`, so with `e ≤ 1` kinetic energy never rises. The
    /// TC model chooses `e`; a sleeping ball struck hard wakes; and with `e < 1` a rebound
    /// slower than `REST_SPEED` may end in rest instead (the rest rule).
    pub(super) fn collide(
        &mut self,
        balls: &mut [Ball],
        i: usize,
        j: usize,
        forces: &Forces,
        now: f64,
    ) {
        let (a, b) = (&balls[i], &balls[j]);
        let offset = b.position() - a.position();
        let distance = offset.length_squared().sqrt();
        if distance == 0.0 {
            return;
        }
        let n = offset / distance;
        let approach = (b.velocity() - a.velocity()).dot(n);
        if approach >= 0.0 {
            return;
        }
        let e = self.restitution_now([i, j], now);
        let rebound = -e * approach;
        self.wake_if_struck_hard([i, j], rebound, forces);
        if e < 1.0 && rebound < REST_SPEED && self.come_to_rest(balls, [i, j], n, forces) {
            return;
        }
        self.exchange_impulse(balls, [i, j], n, (1.0 + e) * approach);
    }

    /// The restitution of a collision of balls `i` and `j` now, by the TC model: elastic
    /// within [`TC_DURATION`] of either ball's previous collision, the scene's otherwise.
    /// Notes the time of this one for both (unless the scene's is 1: then no time matters).
    fn restitution_now(&mut self, [i, j]: [usize; 2], now: f64) -> f64 {
        if self.restitution == 1.0 {
            // Elastic either way: the times are not needed, nor their cache lines touched.
            return 1.0;
        }
        let time = self.elapsed + now;
        let recent = [i, j].map(|k| time - self.last_collision[k] < TC_DURATION);
        self.last_collision[i] = time;
        self.last_collision[j] = time;
        if recent[0] || recent[1] {
            1.0
        } else {
            self.restitution
        }
    }

    /// Wakes each sleeping ball of the pair struck hard enough to rebound at the rest speed,
    /// `rebound` px/frame or more (and it falls again); struck softer it stays put, as a wall
    /// would.
    fn wake_if_struck_hard(&mut self, pair: [usize; 2], rebound: f64, forces: &Forces) {
        for k in pair {
            if self.asleep[k] && rebound >= REST_SPEED {
                self.asleep[k] = false;
                self.held[k] = false;
                self.flight[k] = *forces;
            }
        }
    }

    /// The rest rule: a ball of the pair that gravity presses onto the other, a held ball,
    /// comes to rest on it as on a wall: it loses its normal speed relative to the held ball,
    /// which is part of what holds it and is not pushed (the floor below takes the impulse, as
    /// a wall does). `n` is the normal from `i` to `j`. Returns whether one came to rest.
    fn come_to_rest(
        &mut self,
        balls: &mut [Ball],
        [i, j]: [usize; 2],
        n: Vec2,
        forces: &Forces,
    ) -> bool {
        let resting = if self.held[i] && exact::pressed(forces, n) {
            Some((i, j, n))
        } else if self.held[j] && exact::pressed(forces, -n) {
            Some((j, i, -n))
        } else {
            None
        };
        let Some((holder, resting, n)) = resting else {
            return false;
        };
        let under = balls[holder].velocity();
        let ball = &mut balls[resting];
        let into = (ball.velocity() - under).dot(n);
        let velocity = ball.velocity() - into * n;
        (ball.vx, ball.vy) = (velocity.x, velocity.y);
        // From now on gravity no longer presses it into the held ball, as on a wall: on a
        // curved flight (Verlet's, RK4's) it would press in again at once.
        self.lean_on(resting, n, forces);
        // Nor the held ball into it, if what holds the held ball lets it slide that way: the
        // two then hold each other, or it would meet the resting ball again every few
        // ten-thousandths of a frame (as soon as it closes the rebound gap), for the rest of
        // the step.
        if self.flight[holder].gravity.is_some_and(|g| g.dot(n) > 0.0) {
            self.lean_on(holder, -n, forces);
        }
        self.held[i] = true;
        self.held[j] = true;
        true
    }

    /// Takes from ball `k`'s flight gravity's push into a ball it rests against through the
    /// normal `n` (pointing to `k`), as a wall takes it; a sleeping ball has none to take.
    fn lean_on(&mut self, k: usize, n: Vec2, forces: &Forces) {
        if !self.asleep[k] {
            self.support[k].push(n);
            self.flight[k] = self.support[k].hold(forces);
        }
    }

    /// Gives balls `i` and `j` opposite impulses along `n` (from `i` to `j`) that change
    /// their relative normal speed by `change`, shared by mass; a sleeping ball is not moved,
    /// and the other takes all of it.
    fn exchange_impulse(&self, balls: &mut [Ball], [i, j]: [usize; 2], n: Vec2, change: f64) {
        let (mass_a, mass_b) = (mass(balls[i].radius), mass(balls[j].radius));
        let total = mass_a + mass_b;
        let (kick_a, kick_b) = match (self.asleep[i], self.asleep[j]) {
            (true, _) => (0.0, change),
            (_, true) => (change, 0.0),
            _ => (change * mass_b / total, change * mass_a / total),
        };
        let a = &mut balls[i];
        let velocity = a.velocity() + kick_a * n;
        (a.vx, a.vy) = (velocity.x, velocity.y);
        let b = &mut balls[j];
        let velocity = b.velocity() - kick_b * n;
        (b.vx, b.vy) = (velocity.x, velocity.y);
    }
}
