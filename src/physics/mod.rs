//! Physics: balls, the forces and boundaries acting on them, and how a frame moves them.
//!
//! Knows nothing of scene files, pixels or GIFs. The lesson's whole loop is [`ball::Ball::step`];
//! the rest generalises it:
//!
//! - [`ball`], [`walls`], [`floor`]: a ball's state and trail, the box, sloped segments.
//! - [`effects`]: which forces and boundaries a scene has (an absent one costs nothing).
//! - [`integrator`], [`motion`], [`exact`], [`poly`]: turning forces into motion; substeps;
//!   bouncing at the exact time of impact.
//! - [`grid`]: the broad phase that finds which balls can touch.
//! - [`contacts`]: ball-ball collisions in clamp mode: the iterative contact solver that
//!   piles and stacks need.
//! - [`toi`], [`events`]: exact mode's ball-ball contacts: times of impact, and the
//!   event-driven step that resolves every contact at its moment.
//! - [`simulation`]: all balls advanced one frame, in the order above.
//! - [`accuracy`]: closed forms and measures (energy, overlap) to check the solver against;
//!   [`work`]: counting effect work.

pub mod accuracy;
pub mod ball;
pub mod contacts;
pub mod effects;
pub mod events;
pub mod floor;
pub mod integrate;
pub mod maths;
pub mod motion;
pub mod simulation;
pub mod tolerances;
pub mod vec2;
pub mod walls;
pub mod work;

pub use ball::{Ball, Trail};
pub use effects::Effects;
pub use floor::Floor;
pub use integrate::integrator::Integrator;
pub use motion::{CollisionMode, Motion};
pub use simulation::Simulation;
pub use vec2::Vec2;
pub use walls::Walls;
