//! Polynomials of low degree in time: the flights of the integrators, and the distances
//! between a ball and a wall along them. Owns one question: when does such a distance first
//! drop below zero?
//!
//! The method needs no formula per degree: a polynomial is monotone between the roots of its
//! derivative, so on each of those pieces it crosses zero at most once, and a search by false
//! position finds that crossing to the last bit. The derivative's roots are found the same way, one degree down.
//! A polynomial further from zero than it can move in the interval (`reach`) has no crossing,
//! and its derivatives' roots are not looked for.
//!
//! `+`, `−` and `·` work on polynomials and with numbers, so a squared distance reads
//! `x·x + y·y − reach²` (`x * x + y * y - reach * reach`).

use std::ops::{Add, Mul, Sub};

use crate::physics::tolerances::{HORNER_ROUNDING, LINE_ROOT_ROUNDINGS};

/// The highest degree held: RK4's flight is a quartic, and a squared distance along two
/// such flights is of degree 8.
const MAX_DEGREE: usize = 8;

/// `c[0] + c[1]·t + c[2]·t² + …`
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Poly {
    c: [f64; MAX_DEGREE + 1],
    /// Index of the highest non-zero coefficient (0 for a constant).
    degree: usize,
}

/// At most `MAX_DEGREE` roots, in increasing order, without allocating.
struct Roots {
    t: [f64; MAX_DEGREE],
    len: usize,
}

impl Poly {
    /// The polynomial with coefficients `c`, lowest degree first.
    pub(crate) fn new(c: &[f64]) -> Poly {
        let mut p = Poly {
            c: [0.0; MAX_DEGREE + 1],
            degree: 0,
        };
        p.c[..c.len()].copy_from_slice(c);
        p.trim();
        p
    }

    fn trim(&mut self) {
        self.degree = self.c.iter().rposition(|&c| c != 0.0).unwrap_or(0);
    }

    /// The value at `t` (Horner's rule).
    pub(crate) fn at(&self, t: f64) -> f64 {
        self.c[..=self.degree]
            .iter()
            .rev()
            .fold(0.0, |sum, &c| sum * t + c)
    }

    /// The coefficient of `t^i` (0 beyond the degree).
    pub(crate) fn coefficient(&self, i: usize) -> f64 {
        self.c.get(i).copied().unwrap_or(0.0)
    }

    /// The highest power with a non-zero coefficient.
    pub(crate) fn degree(&self) -> usize {
        self.degree
    }

    /// The derivative's value at `t`.
    pub(crate) fn slope(&self, t: f64) -> f64 {
        self.derivative().at(t)
    }

    fn derivative(&self) -> Poly {
        let mut c = [0.0; MAX_DEGREE + 1];
        for i in 1..=self.degree {
            c[i - 1] = self.c[i] * i as f64;
        }
        let mut d = Poly { c, degree: 0 };
        d.trim();
        d
    }

    /// The largest `|self(t) − self(0)|` can be for `t` in `[0, end]`: a cheap bound that
    /// lets a wall far from the ball be skipped without looking for roots.
    pub(crate) fn reach(&self, end: f64) -> f64 {
        self.c[1..=self.degree.max(1)]
            .iter()
            .rev()
            .fold(0.0, |sum, &c| (sum + c.abs()) * end)
    }

    /// The first time in `[0, end]` at which the polynomial is below zero, if any, as the last
    /// time it was still ≥ 0 (so a ball moved there is touching, not inside). Assumes `at(0) ≥ 0`.
    pub(crate) fn first_negative(&self, end: f64) -> Option<f64> {
        self.first_crossing(end).map(|(before, _)| before)
    }

    /// The first crossing below zero in `[0, end]` as two adjacent times: the last one still
    /// ≥ 0 and the first one below. Assumes `at(0) ≥ 0`.
    pub(crate) fn first_crossing(&self, end: f64) -> Option<(f64, f64)> {
        if self.stays_positive(end) {
            return None;
        }
        if self.degree == 1 {
            return self.line_crossing(end);
        }
        let mut left = 0.0;
        let derivative_roots = self.derivative().roots(end);
        for &right in derivative_roots.t[..derivative_roots.len]
            .iter()
            .chain([end].iter())
        {
            if self.at(right) < 0.0 {
                return Some(self.crossing_between(left, right));
            }
            left = right;
        }
        None
    }

    /// Whether the value cannot fall below zero in `[0, end]`: then the search would find no
    /// crossing, and the roots of the derivatives need not be found. Most near pairs of balls
    /// are far enough apart for it.
    fn stays_positive(&self, end: f64) -> bool {
        self.c[0] > 0.0 && self.keeps_sign(end)
    }

    /// Whether the value keeps the sign it has at 0 everywhere in `[0, end]`, as evaluated: it
    /// is further from zero than `reach` lets it move, with room for Horner's rounding.
    fn keeps_sign(&self, end: f64) -> bool {
        let (value, reach) = (self.c[0].abs(), self.reach(end));
        value - reach > HORNER_ROUNDING * (value + reach)
    }

    /// `first_crossing` for a straight line: the root by one division, checked against its
    /// neighbours. When the line changes less than its own rounding from one number to the
    /// next (a gentle slope far ahead), the root is only known to a few units of rounding
    /// divided by the slope: the search narrows that small bracket down to adjacent numbers.
    /// `end` may be infinite (a straight flight predicted without a horizon).
    fn line_crossing(&self, end: f64) -> Option<(f64, f64)> {
        let (value, slope) = (self.c[0], self.c[1]);
        if slope >= 0.0 || value + slope * end >= 0.0 {
            return None;
        }
        let root = (value / -slope).clamp(0.0, end);
        let after = root.next_up();
        if self.at(root) >= 0.0 && self.at(after) < 0.0 {
            return Some((root, after));
        }
        let (low, high) = self.line_bracket(root, end);
        if self.at(low) >= 0.0 && self.at(high) < 0.0 {
            return Some(self.crossing_between(low, high));
        }
        Some(self.crossing_between(0.0, end.min(f64::MAX)))
    }

    /// The times around `root`, a falling line's root by division, within which its rounding
    /// lets the crossing lie, inside `[0, end]`: a few units of the value's rounding divided
    /// by the slope, and of the root's own.
    fn line_bracket(&self, root: f64, end: f64) -> (f64, f64) {
        let (value, slope) = (self.c[0], self.c[1]);
        // Relative rounding, and near 0 the underflow of a product to the nearest subnormal.
        let rounding = f64::EPSILON * (value.abs() + (slope * root).abs()) + SMALLEST_SUBNORMAL;
        let spread = LINE_ROOT_ROUNDINGS * (rounding / -slope + f64::EPSILON * root);
        ((root - spread).max(0.0), (root + spread).min(end))
    }

    /// Every root strictly inside `(0, end)` where the sign changes, in increasing order.
    fn roots(&self, end: f64) -> Roots {
        let mut roots = Roots {
            t: [0.0; MAX_DEGREE],
            len: 0,
        };
        if self.degree == 0 || self.keeps_sign(end) {
            return roots;
        }
        let turns = self.derivative().roots(end);
        let mut left = 0.0;
        for &right in turns.t[..turns.len].iter().chain([end].iter()) {
            let (a, b) = (self.at(left), self.at(right));
            if (a < 0.0) != (b < 0.0) && a != 0.0 && b != 0.0 {
                let (root, _) = if a > 0.0 {
                    self.crossing_between(left, right)
                } else {
                    (*self * -1.0).crossing_between(left, right)
                };
                roots.t[roots.len] = root;
                roots.len += 1;
            }
            left = right;
        }
        roots
    }

    /// Narrows `[left, right]` (`≥ 0` at `left`, `< 0` at `right`, both times, so not
    /// negative) down to adjacent numbers and returns them: the last point not below zero and
    /// the first one below.
    ///
    /// Each try is where the chord between the two ends crosses zero (false position), with
    /// the Illinois rule: an end kept twice in a row has its value halved, so that the next
    /// chord lands beyond the root and both ends close in. Where the polynomial is monotone,
    /// that takes a handful of tries where halving the bracket takes up to 64. Once the left
    /// end's value rounds to exactly zero the chord cannot move it: the numbers after it are
    /// tried 1, 2, 4, … apart, since the first one below zero is usually a few numbers on
    /// (where it is far, this costs up to halving's tries again). Those steps stay below the
    /// `midpoint`, compared as bit patterns (which order times as numbers), so they never
    /// leave the bracket. A try that would not land strictly inside the bracket is replaced by
    /// the midpoint, as are chords after [`MAX_CHORDS`]: at most 64 chords, 64 steps and 64
    /// halvings, so the search always ends.
    fn crossing_between(&self, left: f64, right: f64) -> (f64, f64) {
        self.narrow(left, right).0
    }

    /// `crossing_between`, and how many points it evaluated on the way.
    fn narrow(&self, mut left: f64, mut right: f64) -> ((f64, f64), u32) {
        let mut tries = 0;
        let (mut at_left, mut at_right) = (self.at(left), self.at(right));
        let (mut kept, mut chords, mut stride) = (Kept::Neither, 0, 1);
        loop {
            let mid = midpoint(left, right);
            if mid <= left || mid >= right {
                return ((left, right), tries);
            }
            tries += 1;
            let chord = left + (right - left) * (at_left / (at_left - at_right));
            let ahead = left.to_bits().saturating_add(stride);
            let t = if at_left == 0.0 && ahead < mid.to_bits() {
                stride *= 2;
                f64::from_bits(ahead)
            } else if chords < MAX_CHORDS && chord > left && chord < right {
                chords += 1;
                chord
            } else {
                mid
            };
            let value = self.at(t);
            if value < 0.0 {
                (right, at_right) = (t, value);
                if kept == Kept::Left {
                    at_left /= 2.0;
                }
                kept = Kept::Left;
            } else {
                (left, at_left) = (t, value);
                if kept == Kept::Right {
                    at_right /= 2.0;
                }
                kept = Kept::Right;
            }
        }
    }
}

/// The most chords `Poly::crossing_between` tries before it only halves: as many as halving needs.
const MAX_CHORDS: u32 = 64;

/// The smallest positive `f64`: the most a product rounds by near 0, where it underflows.
const SMALLEST_SUBNORMAL: f64 = f64::from_bits(1);

/// Which end of its bracket `Poly::crossing_between`'s last try kept.
#[derive(Clone, Copy, PartialEq)]
enum Kept {
    Neither,
    Left,
    Right,
}

/// A number between `left` and `right` that halves the count of numbers between them: for
/// times that are not negative, the mean of their bit patterns, whose order is the numbers'
/// order. Bisection then ends in at most 64 halvings, where halving the interval takes over a
/// thousand to narrow a root at or near 0 down to adjacent (subnormal) numbers.
fn midpoint(left: f64, right: f64) -> f64 {
    if left.is_sign_positive() && right.is_sign_positive() {
        f64::from_bits((left.to_bits() + right.to_bits()) / 2)
    } else {
        left + (right - left) / 2.0
    }
}

/// `p + q`, coefficient by coefficient.
impl Add for Poly {
    type Output = Poly;
    fn add(mut self, other: Poly) -> Poly {
        self.c.iter_mut().zip(other.c).for_each(|(c, o)| *c += o);
        self.trim();
        self
    }
}

/// `p − q`, coefficient by coefficient.
impl Sub for Poly {
    type Output = Poly;
    fn sub(mut self, other: Poly) -> Poly {
        self.c.iter_mut().zip(other.c).for_each(|(c, o)| *c -= o);
        self.trim();
        self
    }
}

/// `p · q`; the degrees must add up to at most `MAX_DEGREE`.
impl Mul for Poly {
    type Output = Poly;
    fn mul(self, other: Poly) -> Poly {
        assert!(
            self.degree + other.degree <= MAX_DEGREE,
            "product degree too high"
        );
        let mut c = [0.0; MAX_DEGREE + 1];
        for i in 0..=self.degree {
            for j in 0..=other.degree {
                c[i + j] += self.c[i] * other.c[j];
            }
        }
        let mut p = Poly { c, degree: 0 };
        p.trim();
        p
    }
}

/// `p · k`: every coefficient times `k`.
impl Mul<f64> for Poly {
    type Output = Poly;
    fn mul(mut self, k: f64) -> Poly {
        self.c.iter_mut().for_each(|c| *c *= k);
        self.trim();
        self
    }
}

/// `p + k`: the constant term plus `k`.
impl Add<f64> for Poly {
    type Output = Poly;
    fn add(mut self, k: f64) -> Poly {
        self.c[0] += k;
        self.trim();
        self
    }
}

/// `p − k`: the constant term minus `k` (the same bits as `p + (−k)`).
impl Sub<f64> for Poly {
    type Output = Poly;
    fn sub(mut self, k: f64) -> Poly {
        self.c[0] -= k;
        self.trim();
        self
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_operators_are_the_formulas_on_the_coefficients_to_the_bit() {
        let (p, q) = (Poly::new(&[0.1, -2.7, 3.3]), Poly::new(&[1e-3, 0.7]));
        assert_eq!(p + q, Poly::new(&[0.1 + 1e-3, -2.7 + 0.7, 3.3]));
        assert_eq!(p - q, p + q * -1.0, "subtracting is adding the negative");
        assert_eq!(p - 0.3, p + -0.3);
        assert_eq!(p * 0.5, Poly::new(&[0.1 * 0.5, -2.7 * 0.5, 3.3 * 0.5]));
        let product = p * q;
        assert_eq!(product.degree(), 3);
        assert_eq!(
            product.coefficient(1).to_bits(),
            (0.1 * 0.7 + -2.7 * 1e-3f64).to_bits()
        );
    }

    #[test]
    fn a_falling_parabola_first_drops_below_zero_at_its_root() {
        // 1 + 0·t − t²/2 · 2 = 1 − t²: root at t = 1.
        let p = Poly::new(&[1.0, 0.0, -1.0]);
        let t = p.first_negative(2.0).expect("a root in [0, 2]");
        assert!((t - 1.0).abs() < 1e-15, "expected 1, got {t}");
    }

    #[test]
    fn a_falling_line_crosses_between_two_adjacent_numbers() {
        // 1 − 3t crosses at 1/3, which no f64 holds exactly.
        let p = Poly::new(&[1.0, -3.0]);
        let (before, after) = p.first_crossing(1.0).expect("a crossing");
        assert!(
            p.at(before) >= 0.0 && p.at(after) < 0.0,
            "{before} and {after} must bracket it"
        );
        assert_eq!(before.next_up(), after, "adjacent numbers");
        assert!(
            (before - 1.0 / 3.0).abs() < 1e-15,
            "expected 1/3, got {before}"
        );
        assert_eq!(p.first_crossing(0.3), None, "not yet by 0.3");
    }

    #[test]
    fn a_dip_below_zero_between_two_positive_ends_is_found() {
        // (t − 1)(t − 2) = 2 − 3t + t²: positive at 0 and 3, negative between 1 and 2.
        let p = Poly::new(&[2.0, -3.0, 1.0]);
        let t = p.first_negative(3.0).expect("the dip");
        assert!((t - 1.0).abs() < 1e-15, "expected 1, got {t}");
    }

    #[test]
    fn a_polynomial_that_stays_positive_has_no_crossing() {
        let p = Poly::new(&[1.0, -1.0, 1.0]);
        assert_eq!(p.first_negative(10.0), None, "t² − t + 1 > 0 everywhere");
        assert_eq!(
            Poly::new(&[0.0]).first_negative(1.0),
            None,
            "zero stays zero"
        );
    }

    #[test]
    fn the_bound_skips_the_search_only_where_no_crossing_can_be() {
        // 1 − k·t² falls to 0 at 1/√k: within reach of [0, 1] only once k ≥ 1.
        for k in [0.5, 0.999_999, 1.0, 1.5] {
            let p = Poly::new(&[1.0, 0.0, -k]);
            let (skipped, crossing) = (p.stays_positive(1.0), p.first_negative(1.0));
            assert!(
                !(skipped && crossing.is_some()),
                "k = {k}: skipped though it crosses at {crossing:?}"
            );
            assert_eq!(
                skipped,
                k < 0.999_999_9,
                "k = {k}: expected the bound to skip"
            );
        }
    }

    #[test]
    fn a_quartic_root_is_found_after_two_turns() {
        // (t − 0.5)(t − 1.5)(t − 2.5)(t − 3.5) is positive at 0; first root 0.5.
        let p = Poly::new(&[6.5625, -22.0, 21.5, -8.0, 1.0]);
        let t = p.first_negative(4.0).expect("a root");
        assert!((t - 0.5).abs() < 1e-14, "expected 0.5, got {t}");
    }

    #[test]
    fn a_gentle_line_far_ahead_crosses_at_adjacent_numbers_around_its_root() {
        // 2.14… − 0.18…·t: from one number to the next near the root the value changes less
        // than its rounding, so the root by division alone is not the last point ≥ 0.
        let p = Poly::new(&[2.1438598071437838, -0.1814002630556213]);
        let (before, after) = p.first_crossing(f64::INFINITY).expect("a crossing");
        assert!(
            p.at(before) >= 0.0 && p.at(after) < 0.0 && after == before.next_up(),
            "expected adjacent times around the root 11.82, got {before} and {after}"
        );
    }

    /// Bisection by `midpoint` alone, the search `Poly::crossing_between` replaced: the same
    /// answer on a monotone piece, in up to 64 halvings.
    fn halving(p: &Poly, mut left: f64, mut right: f64) -> ((f64, f64), u32) {
        let mut tries = 0;
        loop {
            let mid = midpoint(left, right);
            if mid <= left || mid >= right {
                return ((left, right), tries);
            }
            tries += 1;
            if p.at(mid) < 0.0 {
                right = mid;
            } else {
                left = mid;
            }
        }
    }

    /// Monotone pieces met by exact mode's pile (a wall along a parabola, two balls along
    /// Verlet and RK4 flights), each with the bracket `Poly::first_crossing` gave it and the
    /// tries false position took when measured (halving takes 53 to 62).
    const PIECES: [(&[f64], f64, f64, u32); 6] = [
        (&[1.240051333910273, -3.163254841543085, -0.25], 0.0, 1.0, 9),
        (
            &[
                1.7629330774629235,
                -6.413664614649425,
                0.7439453960051885,
                0.25,
            ],
            0.0,
            0.7500357291111417,
            8,
        ),
        (
            &[
                1.44e-7,
                1.132498770353152e-4,
                -1.1068719212921576,
                0.5950276547632827,
                0.0625,
            ],
            5.115973538622624e-5,
            0.6257723500324519,
            20,
        ),
        (
            &[
                0.7634887473197978,
                1.6351345822148975,
                -4.032546890990853,
                0.0524300345572801,
            ],
            0.20375414432086553,
            0.9748985108052092,
            15,
        ),
        (
            &[
                2.108108662923769e-5,
                0.00581311836711329,
                -4.700638652709018,
                -0.1667232087938,
            ],
            6.183124927972044e-4,
            1.0,
            20,
        ),
        (&[1e-300, -1.0], 0.0, 1.0, 2),
    ];

    #[test]
    fn false_position_ends_where_halving_does_in_the_tries_it_took_when_measured() {
        // Each piece's count is a bound: a search that lost the Illinois rule on either end,
        // or its nudge past a zero, takes more on at least one of them.
        for (c, left, right, most) in PIECES {
            let p = Poly::new(c);
            let (found, tries) = p.narrow(left, right);
            let (expected, halvings) = halving(&p, left, right);
            assert_eq!(found, expected, "{c:?}: expected the crossing {expected:?}");
            assert!(
                tries > 0 && tries <= most && 2 * tries <= halvings,
                "{c:?}: {tries} tries (at most {most}), against {halvings} halvings"
            );
        }
    }

    #[test]
    fn a_left_end_rounding_to_zero_is_left_by_steps_that_double() {
        // Near its root at 4.898e-5 this cubic rounds to exactly 0 for a few numbers: the
        // chord cannot move past them, halving from the far end takes 40 tries.
        let p = Poly::new(&[
            2.6586541278206255e-4,
            -5.427972804619163,
            -0.9488056506823281,
            0.25,
        ]);
        let (found, tries) = p.narrow(0.0, 3.7348344252490485e-2);
        let (expected, halvings) = halving(&p, 0.0, 3.7348344252490485e-2);
        assert_eq!(found, expected, "expected the crossing {expected:?}");
        assert!(
            tries > 0 && tries <= 10,
            "{tries} tries, against {halvings} halvings"
        );
    }

    #[test]
    fn a_line_through_zero_is_bracketed_where_its_products_underflow() {
        // A ball at rest against a wall: the distance starts at 0 and falls. Below about 1e-319
        // the product rounds to −0, which is not below zero: the crossing lies there, and the
        // bracket must hold it, a few hundred thousand numbers wide rather than all of them.
        let p = Poly::new(&[0.0, -5.397933131283671e-6]);
        let (low, high) = p.line_bracket(0.0, 0.83);
        assert!(
            p.at(low) >= 0.0 && p.at(high) < 0.0,
            "[{low:e}, {high:e}] must hold the crossing"
        );
        assert!(
            high.to_bits() - low.to_bits() < 1 << 20,
            "{high:e} is too far"
        );
    }

    #[test]
    fn a_gentle_lines_bracket_holds_its_crossing_a_few_hundred_numbers_wide() {
        // The line of the test above: the root by division is a few numbers off the crossing.
        let p = Poly::new(&[2.1438598071437838, -0.1814002630556213]);
        let root = 2.1438598071437838 / 0.1814002630556213;
        let (low, high) = p.line_bracket(root, f64::INFINITY);
        assert!(
            p.at(low) >= 0.0 && p.at(high) < 0.0,
            "[{low}, {high}] must hold the crossing"
        );
        assert!(
            low < root && root < high,
            "{root} must lie inside [{low}, {high}]"
        );
        assert!(
            high.to_bits() - low.to_bits() < 1000,
            "[{low}, {high}] is too wide"
        );
    }

    #[test]
    fn a_left_end_at_zero_far_from_the_crossing_takes_at_most_twice_halvings_tries() {
        // −1e−300·t rounds to −0 (not below zero) up to 2.5e−24: the crossing lies most of
        // the way from 0 to 1 counted in numbers, where steps that double cost as many tries
        // as halving, and halving then as many again.
        let p = Poly::new(&[0.0, -1e-300]);
        let (found, tries) = p.narrow(0.0, 1.0);
        let (expected, halvings) = halving(&p, 0.0, 1.0);
        assert_eq!(found, expected, "expected the crossing {expected:?}");
        assert!(
            tries <= 2 * halvings,
            "{tries} tries, against {halvings} halvings"
        );
    }
}
