//! Time of impact between two round things along their flights: two balls, or a ball and a
//! floor's end point (a ball of radius 0 that never moves). Owns one question: when does the
//! distance between two centres, moving along polynomial flights, first fall to `reach`?
//!
//! Two balls under the same gravity (and the same drag) move in a straight line relative to
//! each other for every integrator: the shared acceleration cancels, so the relative flight
//! is `Δx + Δv·τ` and first contact is the smaller root of a quadratic. That root is taken in
//! the form that cannot cancel (Bannerman et al., "Stable algorithm for event detection in
//! event-driven particle dynamics", 2014): `τ = c / (−b + √(b² − a·c))`. When the accelerations
//! differ (one ball rests on a wall, so the wall holds its weight), the squared distance is a
//! polynomial of degree up to 8 and `Poly::first_negative` finds its first root.
//!
//! Rounding can leave two touching things a hair inside each other. The stable rule is: a pair
//! that overlaps and approaches collides now; a pair that overlaps and parts is left alone; a
//! pair whose approach is slower than `TOUCH_SPEED` is not approaching (it is resting or
//! sliding against the other), so rounding can never make it collide again and again.

use super::poly::Poly;
use crate::physics::tolerances::{REBOUND_GAP, TOUCH_SPEED};
use crate::physics::vec2::Vec2;

/// The first time in `[0, end]` at which two centres whose offset (second minus first) moves
/// as `relative` come within `reach` of each other while approaching, if they do.
pub(crate) fn first_touch(relative: &[Poly; 2], reach: f64, end: f64) -> Option<f64> {
    if relative[0].degree() <= 1 && relative[1].degree() <= 1 {
        // The offset now is the constant term, its velocity the linear one.
        let term = |i| Vec2::new(relative[0].coefficient(i), relative[1].coefficient(i));
        straight(term(0), term(1), reach, end)
    } else {
        curved(relative, reach, end)
    }
}

/// `first_touch` for centres whose offset moves in a straight line, `offset + velocity·τ`:
/// the smaller root of `a·τ² + 2b·τ + c = 0`.
pub fn straight(offset: Vec2, velocity: Vec2, reach: f64, end: f64) -> Option<f64> {
    let b = offset.dot(velocity);
    if b >= -TOUCH_SPEED * reach {
        return None; // parting, or too slow to count as approaching: never closer in a line
    }
    let c = offset.length_squared() - reach * reach;
    if c <= 0.0 {
        return Some(0.0); // touching or a hair inside, and approaching
    }
    let a = velocity.length_squared();
    let discriminant = b * b - a * c;
    if discriminant < 0.0 {
        return None; // they pass each other
    }
    let time = c / (-b + discriminant.sqrt());
    (time <= end).then_some(time)
}

/// Relative motion along a curve: the first root of `|Δ(τ)|² − reach²`.
fn curved(relative: &[Poly; 2], reach: f64, end: f64) -> Option<f64> {
    let [x, y] = *relative;
    let gap = x * x + y * y - reach * reach;
    // d/dτ of the squared distance is 2·Δ·Δ'; approaching means it is negative.
    let approaching = |time: f64| gap.slope(time) < -2.0 * TOUCH_SPEED * reach;
    let start = gap.at(0.0);
    if start > 0.0 {
        return gap.first_negative(end).filter(|&time| approaching(time));
    }
    if approaching(0.0) {
        return Some(0.0);
    }
    // Touching (a hair inside, from rounding) and parting or at rest: unlike a straight
    // flight, a curved one can bring them together again, so look for the gap falling a hair
    // below where it is now.
    let slack = REBOUND_GAP * reach * reach - start;
    (gap + slack)
        .first_negative(end)
        .filter(|&time| approaching(time))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_head_on_approach_touches_when_the_gap_closes() {
        // 10 px apart, reach 4, closing at 2 px/frame: touch at τ = 3.
        let relative = [Poly::new(&[10.0, -2.0]), Poly::new(&[0.0])];
        let time = first_touch(&relative, 4.0, 5.0).expect("a touch");
        assert!((time - 3.0).abs() < 1e-15, "expected 3, got {time}");
    }

    #[test]
    fn parting_or_passing_pairs_never_touch() {
        let parting = [Poly::new(&[10.0, 2.0]), Poly::new(&[0.0])];
        assert_eq!(first_touch(&parting, 4.0, 100.0), None);
        let passing = [Poly::new(&[10.0, -2.0]), Poly::new(&[5.0])];
        assert_eq!(first_touch(&passing, 4.0, 100.0), None, "miss by 1 px");
    }

    #[test]
    fn a_curved_approach_agrees_with_the_straight_formula() {
        // The same straight approach, written with a zero-coefficient curve to force the
        // polynomial path: 10 − 2τ + 1e-30·τ² is straight to rounding.
        let relative = [Poly::new(&[10.0, -2.0, 1e-30]), Poly::new(&[0.0])];
        let time = first_touch(&relative, 4.0, 5.0).expect("a touch");
        assert!((time - 3.0).abs() < 1e-12, "expected 3, got {time}");
    }
}
