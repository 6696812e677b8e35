//! Physics: balls, the forces and boundaries acting on them, and how a frame moves them.
//! Knows nothing of scene files, pixels or GIFs.
//!
//! **The lesson** comes first, in this folder:
//!
//! - [`ball`]: the ball's state, its trail, and [`ball::Ball::step`], the lesson's whole loop
//!   (gravity, move, clamp-then-reflect off the walls, record the trail).
//! - [`walls`]: the box; [`floor`]: sloped segments (the lesson's "slope" extension).
//! - [`effects`], [`motion`], [`simulation`]: which forces and boundaries a scene has (an
//!   absent one costs nothing), how a frame is solved, and all balls advanced one frame: by
//!   the lesson's own step when the scene is the lesson's, by a solver below otherwise;
//!   [`replay`]: frames already stepped (by the budget's pilot), shown again unstepped.
//!
//! **Beyond the lesson**, each in a folder whose `mod.rs` says what it adds and when a scene
//! needs it:
//!
//! - [`integrate`]: other integrators, substeps, bouncing at the exact time of impact.
//! - [`contacts`]: ball-ball collisions in clamp mode: the grid and the contact solver that
//!   lets piles rest.
//! - `events`: ball-ball collisions in exact mode, event by event.
//!
//! Shared by all: `vec2` (the 2-D vector), [`maths`] (transcendental functions, the same
//! bits on every system), [`tolerances`] (every tolerance with its unit and reason). The work
//! each effect does is counted for the tests in `crate::work`.

pub mod ball;
pub mod contacts;
pub mod effects;
pub(crate) mod events;
pub mod floor;
pub mod integrate;
pub mod maths;
pub mod motion;
pub mod replay;
pub mod simulation;
pub mod tolerances;
pub(crate) mod vec2;
pub mod walls;

pub use ball::{Ball, Trail};
pub use effects::Effects;
pub use floor::Floor;
pub use integrate::integrator::Integrator;
pub use motion::{CollisionMode, Motion};
pub use simulation::Simulation;
pub use vec2::Vec2;
pub use walls::Walls;
