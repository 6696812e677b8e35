//! `bouncing_ball`: a bouncing-ball simulation drawn to an animated GIF and a still PNG,
//! ported from a teaching script.
//!
//! One concept per module: [`ball`] and [`walls`] are the lesson's physics, [`simulation`]
//! advances a [`scene`], [`render`] draws a frame into [`palette`] indices, [`delta`] finds
//! what changed since the last frame, [`lzw`] compresses it, [`encode`] writes GIF and PNG,
//! [`output`] makes files appear whole, [`trace`] writes the CSV, [`progress`] shows how far
//! a long run is, and [`run`] ties them together for the command line. Beyond the lesson,
//! [`motion`] chooses an [`integrator`], substeps and a collision mode ([`exact`] bounces at
//! the time of impact, found with [`poly`]), [`collisions`] and [`grid`] handle ball-ball
//! contacts, and [`accuracy`] measures the solver choices against closed forms.

pub mod accuracy;
pub mod ball;
pub mod collisions;
pub mod delta;
pub mod effects;
pub mod encode;
pub mod exact;
pub mod floor;
pub mod grid;
pub mod integrator;
pub mod lzw;
pub mod motion;
pub mod output;
pub mod overrides;
pub mod palette;
pub mod poly;
pub mod progress;
pub mod random;
pub mod render;
pub mod run;
pub mod scene;
pub mod scene_file;
pub mod simulation;
pub mod trace;
pub mod walls;
pub mod work;

pub use run::{run, Outputs, RunError, Summary};
pub use scene::{BallSpec, Scene};
