//! `bouncing_ball`: a bouncing-ball simulation drawn to an animated GIF and a still PNG,
//! ported from a teaching script.
//!
//! One folder per stage, and data flows one way, each stage using only those before it:
//!
//! - [`physics`]: balls, forces, walls and floors, integrators, contacts. `Ball::step` is the
//!   lesson's loop; `Simulation` advances many balls with any solver setting.
//! - [`scene`]: what to simulate, from the lesson's constants, a TOML file or a preset.
//! - [`render`]: a frame drawn into palette indices; the still PNG.
//! - [`gif`]: the animated GIF, streamed out.
//! - [`plot`]: height, speed and energy of the run against frame, as SVG or PNG.
//!
//! At the top, four commands are peers that never import each other: [`run`](mod@run) (the main
//! command) ties the stages together, [`compare`] runs one scene by several methods side by
//! side against a reference, [`sweep`] runs it once per value of one setting and tiles the
//! runs into one GIF, [`check`] grades a learner's GIF, PNG or trajectory against the scene.
//! Under all four, [`job`] does what they share: it opens and commits the
//! outputs, checks for a stop, shows the progress and sums up what was written. [`budget`]
//! works out before the first frame what a scene will cost, [`output`] makes files appear
//! whole or not at all and only where a file belongs, [`stop`] ends a run cleanly on a
//! signal, [`trace`] writes the CSV, [`progress`] shows how far a long run is. Beneath every
//! stage, `work` counts the work each does, for the tests. Above them all, [`cli`] reads the
//! command line and [`messages`] says what went wrong in one line.
//! What only the integration tests reach into, and no program needs, is gathered in
//! `testing`, outside the documented API.
//!
//! # Example
//!
//! The moon preset, simulated and written as a GIF and a still PNG:
//!
//! ```
//! use bouncing_ball::{run, scene, Job};
//!
//! let folder = tempfile::tempdir()?;
//! let gif = folder.path().join("moon.gif");
//! let moon = scene::preset("moon", 0)?;
//! let written = run(&moon, &Job::pictures(&gif, folder.path().join("moon.png")))?;
//! assert_eq!(written.frames, moon.frames);
//! assert!(std::fs::read(&gif)?.starts_with(b"GIF89a"));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

pub mod budget;
pub mod check;
pub mod cli;
pub mod compare;
pub mod gif;
pub mod job;
pub mod messages;
pub mod output;
pub mod physics;
pub mod plot;
pub mod progress;
pub mod render;
pub mod run;
pub mod scene;
pub mod stop;
pub mod sweep;
#[doc(hidden)]
pub mod testing;
pub mod trace;
pub(crate) mod work;

pub use job::{Job, OutputKind, RunError, Summary};
pub use run::run;
pub use scene::{BallSpec, Scene};
