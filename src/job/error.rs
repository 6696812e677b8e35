//! Why a job wrote nothing, in one line each, and the exit code each gives.

use crate::budget::OverBudget;
use crate::output::{OutputError, OutputRefused};
use crate::physics::Ball;
use crate::render::palette::TooManyColours;
use crate::scene::InvalidValue;
use crate::stop::Signal;

/// Why a job wrote nothing.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    #[error(transparent)]
    Invalid(#[from] InvalidValue),
    #[error(transparent)]
    Colours(#[from] TooManyColours),
    #[error(transparent)]
    OverBudget(#[from] OverBudget),
    #[error(transparent)]
    Refused(#[from] OutputRefused),
    #[error("ball {ball} left the finite numbers at frame {frame} ({state}) from {inputs}; these values are too large to simulate, nothing was written")]
    NonFinite {
        ball: usize,
        frame: u32,
        state: String,
        inputs: String,
    },
    #[error(transparent)]
    Output(#[from] OutputError),
    #[error("stopped by {} at frame {frame} of {frames}: not written: {unwritten} (any earlier files are as they were)", signal.name)]
    Stopped {
        signal: Signal,
        frame: u32,
        frames: u32,
        unwritten: String,
    },
}

impl RunError {
    /// 2 for input the program cannot use, 1 for a file it cannot write, 128 + the signal's
    /// number for a job stopped by one.
    pub(crate) fn exit_code(&self) -> u8 {
        match self {
            RunError::Invalid(_)
            | RunError::Colours(_)
            | RunError::OverBudget(_)
            | RunError::Refused(_)
            | RunError::NonFinite { .. } => 2,
            RunError::Output(_) => 1,
            RunError::Stopped { signal, .. } => signal.exit_code(),
        }
    }

    /// `NonFinite` for the first ball that left the finite numbers in `frame`, so no NaN is
    /// traced, measured, drawn or written; `inputs` says what that ball (by index) came from.
    pub(crate) fn if_not_finite(
        balls: &[Ball],
        frame: u32,
        inputs: impl FnOnce(usize) -> String,
    ) -> Result<(), RunError> {
        let Some((i, ball)) = balls.iter().enumerate().find(|(_, b)| !b.is_finite()) else {
            return Ok(());
        };
        Err(RunError::NonFinite {
            ball: i,
            frame,
            state: format!(
                "x {:?}, y {:?}, vx {:?}, vy {:?}",
                ball.x, ball.y, ball.vx, ball.vy
            ),
            inputs: inputs(i),
        })
    }
}
