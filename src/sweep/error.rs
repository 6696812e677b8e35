//! Why a sweep cannot run, in one line each, and the exit code each gives.

use crate::job::RunError;
use crate::render::tile::TileError;
use crate::scene::SceneFileError;

/// A sweep that cannot run, said in one line.
#[derive(Debug, thiserror::Error)]
pub enum SweepError {
    #[error("{text:?} is not KEY=V1,V2,...: give a setting, `=` and its values separated by commas, e.g. damping=0.5,0.88,1")]
    Malformed { text: String },
    #[error("{key:?} is not a setting a sweep can vary{}; the keys are: {keys}", near.as_ref().map_or(String::new(), |n| format!("; did you mean {n}?")))]
    UnknownKey {
        key: String,
        near: Option<String>,
        keys: String,
    },
    #[error("{key}={list}: a value is empty; give values separated by commas, e.g. {key}=V1,V2")]
    EmptyValue { key: String, list: String },
    #[error("{key} cannot be swept: the panels share one GIF, which shows every frame for the same time")]
    Fixed { key: String },
    #[error("{key} is swept, so {flag} cannot also be given")]
    AlsoTyped { key: String, flag: &'static str },
    /// A value the setting's flag refuses, as clap says it for the flag (`--damping abc`).
    #[error("{}", .0.to_string().lines().next().unwrap_or_default())]
    Flag(clap::Error),
    #[error(transparent)]
    Scene(#[from] SceneFileError),
    #[error("the panels show their frames for {0} ms and {1} ms; one GIF shows every frame for the same time")]
    FrameTimes(u32, u32),
    #[error(transparent)]
    Tiles(#[from] TileError),
    #[error(transparent)]
    Run(#[from] RunError),
}

impl SweepError {
    /// As a run's: 2 for input the program cannot use, 1 for a file it cannot write, 128 +
    /// the signal's number for a sweep stopped by one.
    pub(crate) fn exit_code(&self) -> u8 {
        match self {
            SweepError::Run(error) => error.exit_code(),
            _ => 2,
        }
    }
}
