//! Scenes: what one run simulates and draws, where it comes from, and the checks it passes.
//!
//! - `spec`: the scene itself (canvas, balls, effects, motion), its limits and validation.
//! - [`file`](mod@file): TOML scene files and the bundled presets.
//! - `overrides`: command-line flags laid over a scene, one table row per setting.
//! - `names`: how flags and files spell the integrators and collision modes.
//! - [`random`]: the seeded generator behind `[spawn]` (same seed, same scene).
//!
//! A scene is a plain description; [`spec::Scene::simulation`] sets it in motion.

pub mod file;
pub(crate) mod names;
pub(crate) mod overrides;
pub mod random;
pub(crate) mod spec;

pub use file::{preset, preset_names, SceneFileError, PRESETS};
pub use names::Named;
pub(crate) use overrides::Overrides;
pub use spec::{BallSpec, InvalidValue, Rgb, Scene, TrailFade};
