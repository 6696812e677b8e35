//! A 2-D vector: a position in px, a velocity in px/frame, an offset or a direction. With it
//! the formulas read as `docs/` writes them: `(b.position - a.position).dot(normal)`.
//!
//! Each operation is the plain arithmetic written out in one fixed order (`dot` is
//! `x·x' + y·y'`), so code written with it gives the same bits as the same formula written on
//! the components.

use std::ops::{Add, AddAssign, Div, Mul, Neg, Sub, SubAssign};

use super::maths;

/// A vector with `x` rightwards and `y` downwards, as on the canvas.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Vec2 {
    pub x: f64,
    pub y: f64,
}

impl Vec2 {
    pub const ZERO: Vec2 = Vec2 { x: 0.0, y: 0.0 };

    pub const fn new(x: f64, y: f64) -> Vec2 {
        Vec2 { x, y }
    }

    /// `x·x' + y·y'`.
    pub(crate) fn dot(self, other: Vec2) -> f64 {
        self.x * other.x + self.y * other.y
    }

    /// `x² + y²`: compare it with a squared distance and no square root is needed.
    pub fn length_squared(self) -> f64 {
        self.dot(self)
    }

    /// `√(x² + y²)`, the same on every system (`super::maths::hypot`).
    pub fn length(self) -> f64 {
        maths::hypot(self.x, self.y)
    }

    /// The vector turned a quarter turn: `(−y, x)`.
    pub(crate) fn perp(self) -> Vec2 {
        Vec2::new(-self.y, self.x)
    }

    /// The component along `axis`: `x` for 0, `y` for 1, for code that works one axis at a
    /// time.
    pub(crate) fn axis(self, axis: usize) -> f64 {
        self.to_array()[axis]
    }

    /// The vector with `along` on `axis` (0 for `x`, 1 for `y`) and `across` on the other:
    /// [`Vec2::axis`] the other way round.
    pub(crate) fn from_axes(axis: usize, along: f64, across: f64) -> Vec2 {
        match axis {
            0 => Vec2::new(along, across),
            _ => Vec2::new(across, along),
        }
    }

    /// As an array `[x, y]`, for code that indexes by axis.
    pub(crate) fn to_array(self) -> [f64; 2] {
        [self.x, self.y]
    }
}

impl From<[f64; 2]> for Vec2 {
    fn from([x, y]: [f64; 2]) -> Vec2 {
        Vec2 { x, y }
    }
}

impl Add for Vec2 {
    type Output = Vec2;
    fn add(self, other: Vec2) -> Vec2 {
        Vec2::new(self.x + other.x, self.y + other.y)
    }
}

impl Sub for Vec2 {
    type Output = Vec2;
    fn sub(self, other: Vec2) -> Vec2 {
        Vec2::new(self.x - other.x, self.y - other.y)
    }
}

impl Mul<f64> for Vec2 {
    type Output = Vec2;
    fn mul(self, k: f64) -> Vec2 {
        Vec2::new(self.x * k, self.y * k)
    }
}

impl Mul<Vec2> for f64 {
    type Output = Vec2;
    fn mul(self, v: Vec2) -> Vec2 {
        Vec2::new(self * v.x, self * v.y)
    }
}

/// Each component divided by `k`: `offset / length` is the direction of `offset`. (A division
/// each, not a multiplication by `1 / k`, which would round differently.)
impl Div<f64> for Vec2 {
    type Output = Vec2;
    fn div(self, k: f64) -> Vec2 {
        Vec2::new(self.x / k, self.y / k)
    }
}

impl Neg for Vec2 {
    type Output = Vec2;
    fn neg(self) -> Vec2 {
        Vec2::new(-self.x, -self.y)
    }
}

impl AddAssign for Vec2 {
    fn add_assign(&mut self, other: Vec2) {
        *self = *self + other;
    }
}

impl SubAssign for Vec2 {
    fn sub_assign(&mut self, other: Vec2) {
        *self = *self - other;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operations_match_the_formulas_on_the_components_to_the_bit() {
        let (a, b) = (Vec2::new(0.1, -2.7), Vec2::new(3.3, 1e-3));
        assert_eq!(a.dot(b).to_bits(), (0.1 * 3.3 + -2.7 * 1e-3f64).to_bits());
        assert_eq!(a + b, Vec2::new(0.1 + 3.3, -2.7 + 1e-3));
        assert_eq!(a - b, Vec2::new(0.1 - 3.3, -2.7 - 1e-3));
        assert_eq!(a * 0.5, 0.5 * a);
        assert_eq!(a / 3.0, Vec2::new(0.1 / 3.0, -2.7 / 3.0));
        assert_eq!(-a, Vec2::new(-0.1, 2.7));
        assert_eq!(a.perp().dot(a), 0.0);
        assert_eq!(Vec2::new(3.0, 4.0).length(), 5.0);
        assert_eq!(Vec2::from([1.0, 2.0]).to_array(), [1.0, 2.0]);
        assert_eq!((a.axis(0), a.axis(1)), (a.x, a.y));
        assert_eq!(
            (Vec2::from_axes(0, 1.0, 2.0), Vec2::from_axes(1, 1.0, 2.0)),
            (Vec2::new(1.0, 2.0), Vec2::new(2.0, 1.0))
        );
    }
}
