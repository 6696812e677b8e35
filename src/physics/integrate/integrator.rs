//! Integrators: how one step of length `dt` (frames) turns forces into velocity and velocity
//! into position. The lesson's is semi-implicit Euler: velocity first, then position.
//!
//! The forces are gravity `g` and the lesson's drag, `v *= 1 - drag` once a frame. As a
//! differential equation that drag is `dv/dt = g − λ·v` with `λ = −ln(1 − drag)` per frame:
//! over one frame it keeps exactly `e^(−λ) = 1 − drag` of the speed, as the lesson does.
//!
//! Every step is written as three parts, so that exact collisions (`super::exact`) can stop
//! the ball in the middle of it: a velocity change before the flight (a *kick*), the flight,
//! a kick after. The Euler methods put all of gravity and drag into one kick and fly in a
//! straight line; velocity Verlet and RK4 have no kicks and fly along a curve.

use super::poly::Poly;
use crate::physics::ball::Ball;
use crate::physics::effects::Effects;
use crate::physics::maths;
use crate::physics::vec2::Vec2;
use crate::work::{tally, Work};

/// What the integrators move: a centre and a velocity. A [`Ball`] is one; the contact solver
/// moves a compact copy of its balls, without their trails (`Body`, in
/// `crate::physics::contacts::contact`).
pub(crate) trait Movable {
    /// Centre and velocity, `[x, y, vx, vy]` in px and px/frame, to change in place.
    fn motion(&mut self) -> [&mut f64; 4];
}

impl Movable for Ball {
    fn motion(&mut self) -> [&mut f64; 4] {
        [&mut self.x, &mut self.y, &mut self.vx, &mut self.vy]
    }
}

/// Which integration method advances the balls.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Integrator {
    /// Position first with the old velocity, then velocity: `x += v·dt`, `v += a·dt`.
    ExplicitEuler,
    /// The lesson's: `v += a·dt`, then `x += v·dt`.
    #[default]
    SemiImplicitEuler,
    /// `x += v·dt + a·dt²/2`, then `v` by the average of the old and new acceleration.
    VelocityVerlet,
    /// The classic fourth-order Runge–Kutta method.
    Rk4,
}

/// Gravity and drag for steps of length `dt`, worked out once per frame, not once per step.
/// Drag costs one logarithm per ball-frame (and one power with substeps); no drag costs nothing.
/// The default is no force over no time, for a solver before its first frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Forces {
    /// Step length, frames.
    pub dt: f64,
    /// px/frame²; `None` costs nothing.
    pub gravity: Option<Vec2>,
    /// `None` costs nothing.
    pub drag: Option<Drag>,
}

/// The lesson's drag in the two forms the integrators need.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Drag {
    /// `λ = −ln(1 − drag)`, per frame (infinite for drag 1: the air stops the ball dead).
    pub rate: f64,
    /// Share of velocity one step of `dt` keeps: `(1 − drag)^dt`, which is `e^(−λ·dt)`.
    pub keep: f64,
}

impl Forces {
    /// The forces of `effects` for one step per frame (`dt = 1`).
    pub(crate) fn new(effects: &Effects) -> Forces {
        Forces {
            dt: 1.0,
            gravity: effects.gravity,
            drag: effects.drag.map(|drag| Drag {
                rate: -maths::ln_1p(-drag),
                keep: 1.0 - drag,
            }),
        }
    }

    /// The same forces for a frame split into `steps` equal steps. With one step nothing
    /// changes, so the lesson's `1 - drag` is kept to the last bit.
    pub(crate) fn split(self, steps: u32) -> Forces {
        if steps == 1 {
            return self;
        }
        let dt = 1.0 / f64::from(steps);
        Forces {
            dt,
            drag: self.drag.map(|drag| Drag {
                keep: maths::powf(drag.keep, dt),
                ..drag
            }),
            ..self
        }
    }

    /// Counts this step's gravity and drag work (with the `work-tally` feature; see `crate::work`).
    fn tally(&self) {
        if self.gravity.is_some() {
            tally(Work::Gravity);
        }
        if self.drag.is_some() {
            tally(Work::Drag);
        }
    }

    /// Acceleration along one axis at velocity `v`: gravity minus drag.
    fn accel(&self, axis: usize, v: f64) -> f64 {
        let g = self.gravity.map_or(0.0, |g| g.axis(axis));
        match self.drag {
            Some(drag) => g - drag.rate * v,
            None => g,
        }
    }

    /// Drag 1 removes all speed at once: `λ` is infinite and no formula with it is finite.
    fn stops_dead(&self) -> bool {
        self.drag.is_some_and(|drag| drag.rate.is_infinite())
    }
}

impl Integrator {
    /// Advances `ball` by one step of `forces.dt` frames under gravity and drag (no collisions).
    pub(crate) fn step(self, ball: &mut impl Movable, forces: &Forces) {
        self.kick_before(ball, forces);
        self.fly(ball, forces, forces.dt);
        self.kick_after(ball, forces);
    }

    /// The velocity change at the start of a step (semi-implicit Euler's whole `v += a·dt`).
    pub(crate) fn kick_before(self, ball: &mut impl Movable, forces: &Forces) {
        if self == Integrator::SemiImplicitEuler {
            kick(ball, forces);
        }
    }

    /// The velocity change at the end of a step (explicit Euler's whole `v += a·dt`).
    pub(crate) fn kick_after(self, ball: &mut impl Movable, forces: &Forces) {
        if self == Integrator::ExplicitEuler {
            kick(ball, forces);
        }
    }

    /// Moves `ball` along the step's flight for `time` frames (`time ≤ forces.dt`).
    pub(crate) fn fly(self, ball: &mut impl Movable, forces: &Forces, time: f64) {
        let [x, y, vx, vy] = ball.motion();
        match self {
            Integrator::ExplicitEuler | Integrator::SemiImplicitEuler => {
                *x += *vx * time;
                *y += *vy * time;
            }
            Integrator::VelocityVerlet | Integrator::Rk4 if forces.stops_dead() => {
                *vx = 0.0;
                *vy = 0.0;
            }
            Integrator::VelocityVerlet => {
                forces.tally();
                (*x, *vx) = verlet(*x, *vx, time, 0, forces);
                (*y, *vy) = verlet(*y, *vy, time, 1, forces);
            }
            Integrator::Rk4 => {
                forces.tally();
                (*x, *vx) = rk4(*x, *vx, time, 0, forces);
                (*y, *vy) = rk4(*y, *vy, time, 1, forces);
            }
        }
    }

    /// Where the flight takes the centre after `τ` frames, as a polynomial in `τ` per axis:
    /// exactly the position `fly(…, τ)` computes, so its roots are the flight's times of impact.
    pub(crate) fn path(self, ball: &Ball, forces: &Forces) -> [Poly; 2] {
        // Two plain calls, not a `map` over the axes: predicting events builds a path after
        // every event, and the compiler inlines these.
        [
            self.axis_path(ball.x, ball.vx, 0, forces),
            self.axis_path(ball.y, ball.vy, 1, forces),
        ]
    }

    /// `path` along one axis, from position `x` and velocity `v`.
    #[inline]
    fn axis_path(self, x: f64, v: f64, axis: usize, forces: &Forces) -> Poly {
        match self {
            Integrator::ExplicitEuler | Integrator::SemiImplicitEuler => Poly::new(&[x, v]),
            Integrator::VelocityVerlet | Integrator::Rk4 if forces.stops_dead() => Poly::new(&[x]),
            Integrator::VelocityVerlet => Poly::new(&[x, v, forces.accel(axis, v) / 2.0]),
            // RK4's four stages add up to the Taylor series of the exact flight to τ⁴.
            Integrator::Rk4 => {
                let a = forces.accel(axis, v);
                let rate = forces.drag.map_or(0.0, |drag| drag.rate);
                Poly::new(&[x, v, a / 2.0, -a * rate / 6.0, a * rate * rate / 24.0])
            }
        }
    }

    /// How many steps a frame of `substeps` needs so that this method stays stable under the
    /// drag of `frame` (the forces for one step per frame).
    ///
    /// The Euler kicks multiply by `1 − drag` exactly, which is stable for any drag. Verlet and
    /// RK4 treat drag as a force, which overshoots once `λ·dt` passes 2 (Verlet) or 2.78 (RK4);
    /// keeping `λ·dt ≤ 1` also keeps drag from ever reversing a velocity. The lesson's drag
    /// (λ = 0.002) never needs more steps; a drag of 0.99 (λ = 4.6) needs 5 a frame.
    pub(crate) fn steps_per_frame(self, substeps: u32, frame: &Forces) -> u32 {
        let curved = matches!(self, Integrator::VelocityVerlet | Integrator::Rk4);
        match frame.drag {
            Some(drag) if curved && drag.rate.is_finite() => {
                let per_substep = (drag.rate / f64::from(substeps)).ceil().max(1.0);
                // λ is at most −ln(2⁻⁵³) ≈ 37 when finite, so this product is small.
                substeps.saturating_mul(per_substep as u32)
            }
            _ => substeps,
        }
    }
}

/// Euler's velocity change: all of a step's gravity, then all of its drag. With dt = 1 this
/// is exactly the lesson's arithmetic.
fn kick(ball: &mut impl Movable, forces: &Forces) {
    forces.tally();
    let [_, _, vx, vy] = ball.motion();
    if let Some(g) = forces.gravity {
        *vx += g.x * forces.dt;
        *vy += g.y * forces.dt;
    }
    if let Some(drag) = forces.drag {
        *vx *= drag.keep;
        *vy *= drag.keep;
    }
}

/// One velocity Verlet step along one axis. Drag depends on the new velocity, so the second
/// half-kick `v₁ = v½ + (g − λ·v₁)·h/2` is solved for `v₁` (it is linear: one division).
fn verlet(x: f64, v: f64, h: f64, axis: usize, forces: &Forces) -> (f64, f64) {
    let half = v + forces.accel(axis, v) * h / 2.0;
    let g = forces.gravity.map_or(0.0, |g| g.axis(axis));
    let v1 = match forces.drag {
        Some(drag) => (half + g * h / 2.0) / (1.0 + drag.rate * h / 2.0),
        None => half + g * h / 2.0,
    };
    (x + half * h, v1)
}

/// One classic Runge–Kutta step along one axis: `x' = v`, `v' = g − λ·v`.
fn rk4(x: f64, v: f64, h: f64, axis: usize, forces: &Forces) -> (f64, f64) {
    let a = |v: f64| forces.accel(axis, v);
    let (k1x, k1v) = (v, a(v));
    let (k2x, k2v) = (v + k1v * h / 2.0, a(v + k1v * h / 2.0));
    let (k3x, k3v) = (v + k2v * h / 2.0, a(v + k2v * h / 2.0));
    let (k4x, k4v) = (v + k3v * h, a(v + k3v * h));
    (
        x + (k1x + 2.0 * k2x + 2.0 * k3x + k4x) * h / 6.0,
        v + (k1v + 2.0 * k2v + 2.0 * k3v + k4v) * h / 6.0,
    )
}
