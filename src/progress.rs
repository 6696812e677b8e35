//! The progress bar: shown on stderr for a job that looks to take more than a second, and
//! only when stderr is a terminal someone is watching. Knows frames and time, nothing else.
//!
//! A job may run its frames in several passes (`compare` runs its reference, then draws every
//! method): each pass adds its frames to the bar's total as it starts.

use std::cell::Cell;
use std::io::IsTerminal;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A run projected to finish sooner than this gets no bar: it would only flicker.
pub const WORTH_A_BAR: Duration = Duration::from_secs(1);
/// How long a run goes before its length is projected from its pace so far.
pub const SAMPLE: Duration = Duration::from_millis(100);

/// Whether a run that has done `done` of `total` frames in `elapsed` looks long enough for a bar.
pub fn looks_long(elapsed: Duration, done: u64, total: u64) -> bool {
    if elapsed < SAMPLE || done == 0 {
        return false;
    }
    elapsed.mul_f64(total as f64 / done as f64) > WORTH_A_BAR
}

/// A job's progress over its frames: the bar counts from the first frame, so its estimate
/// of the time left is sound, but it is drawn only once the job looks long; it is cleared
/// when the job is done or dropped, so the summary line prints on a clean terminal.
#[derive(Debug)]
pub(crate) struct Progress {
    started: Instant,
    /// None when asked not to show one (`--quiet`) or nobody would see it.
    bar: Option<ProgressBar>,
    drawn: Cell<bool>,
}

impl Progress {
    /// Progress over no frames yet; `wanted` false means never show a bar.
    pub(crate) fn new(wanted: bool) -> Progress {
        let visible = wanted && std::io::stderr().is_terminal();
        let style = ProgressStyle::with_template("{wide_bar} {pos}/{len} frames, {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar());
        let bar = visible.then(|| {
            ProgressBar::with_draw_target(Some(0), ProgressDrawTarget::hidden()).with_style(style)
        });
        Progress {
            started: Instant::now(),
            bar,
            drawn: Cell::new(false),
        }
    }

    /// Adds a pass of `frames` frames to the total.
    pub(crate) fn add_frames(&self, frames: u32) {
        if let Some(bar) = &self.bar {
            bar.inc_length(frames.into());
        }
    }

    /// Notes that one more frame is finished.
    pub(crate) fn frame_done(&self) {
        let Some(bar) = &self.bar else { return };
        bar.inc(1);
        let (done, total) = (bar.position(), bar.length().unwrap_or(0));
        if !self.drawn.get() && looks_long(self.started.elapsed(), done, total) {
            bar.set_draw_target(ProgressDrawTarget::stderr());
            self.drawn.set(true);
        }
    }

    /// Clears the bar off the terminal.
    pub(crate) fn clear(&self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        self.clear();
    }
}
