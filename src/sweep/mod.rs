//! `bouncing_ball sweep KEY=V1,V2,...`: one scene run once per value of one setting (or once
//! per preset), the runs tiled side by side into one GIF, each panel under its label
//! (`damping = 0.88`). The lesson's "Tune the physics" exercise in one picture.
//!
//! Each panel is, pixel for pixel, the run the main command makes with that value typed as a
//! flag: the scene is built the same way, drawn by the same renderer, and its colours are
//! only renumbered into the tiling's palette (`crate::render::tile`). As in [`crate::run()`],
//! everything that can be refused is refused before the first frame: the values, each
//! panel's scene, the tiled canvas's size and colours, the memory, time and GIF size, and the
//! output paths; the files go into place only once every byte is written.
//!
//! - `values`: `KEY=V1,V2,...`, each value read by its setting's own flag parser.
//! - [`run`](mod@run): the panels run side by side and written as one GIF.
//! - `error`: why a sweep cannot run.

pub(crate) mod error;
pub mod run;
pub(crate) mod values;

pub(crate) use error::SweepError;
pub use run::run;
pub(crate) use values::{Change, Sweep};
