//! Beyond the lesson's step: other integrators, substeps, and bouncing at the exact time of
//! impact.
//!
//! The lesson moves a ball with one semi-implicit Euler step a frame and clamps it back when it
//! crosses a wall (`super::ball::Ball::step`). That is cheap and stable, but its arcs drift and
//! a fast ball bounces from where it overshot, not from where it met the wall. This stage adds:
//!
//! - `integrator`: explicit and semi-implicit Euler, velocity Verlet and RK4, any number of
//!   substeps, and the lesson's drag as an exact exponential. A scene needs another integrator
//!   when its arcs must stay true over long runs (`--integrator rk4`).
//! - `exact`: `--collisions exact` for walls and floors: the moment in the step at which the
//!   ball's own flight touches them, the bounce there, the flight on. A scene needs it when
//!   bounce heights matter (the clamp loses or gains a little each bounce).
//! - [`toi`], `poly`: the times of impact those bounces (and exact ball-ball contacts,
//!   `super::events`) are found at: roots of polynomials in the step's time.

pub(crate) mod exact;
pub(crate) mod integrator;
pub(crate) mod poly;
pub mod toi;
