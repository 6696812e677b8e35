//! The progress bar: shown on stderr for a run that looks to take more than a second, and
//! only when stderr is a terminal someone is watching. Knows frames and time, nothing else.

use std::io::IsTerminal;
use std::time::{Duration, Instant};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A run projected to finish sooner than this gets no bar: it would only flicker.
pub const WORTH_A_BAR: Duration = Duration::from_secs(1);
/// How long a run goes before its length is projected from its pace so far.
pub const SAMPLE: Duration = Duration::from_millis(100);

/// Whether a run that has done `done` of `total` frames in `elapsed` looks long enough for a bar.
pub fn looks_long(elapsed: Duration, done: u32, total: u32) -> bool {
    if elapsed < SAMPLE || done == 0 {
        return false;
    }
    elapsed.mul_f64(f64::from(total) / f64::from(done)) > WORTH_A_BAR
}

/// A run's progress over its frames: the bar counts from the first frame, so its estimate
/// of the time left is sound, but it is drawn only once the run looks long; it is cleared
/// when this is dropped, so the summary line prints on a clean terminal.
pub struct Progress {
    total: u32,
    started: Instant,
    /// None when asked not to show one (`--quiet`) or nobody would see it.
    bar: Option<ProgressBar>,
    drawn: bool,
}

impl Progress {
    /// Progress over `total` frames; `wanted` false means never show a bar.
    pub fn new(total: u32, wanted: bool) -> Progress {
        let visible = wanted && std::io::stderr().is_terminal();
        let style = ProgressStyle::with_template("{wide_bar} {pos}/{len} frames, {eta} left")
            .unwrap_or_else(|_| ProgressStyle::default_bar());
        let bar = visible.then(|| {
            ProgressBar::with_draw_target(Some(total.into()), ProgressDrawTarget::hidden())
                .with_style(style)
        });
        Progress {
            total,
            started: Instant::now(),
            bar,
            drawn: false,
        }
    }

    /// Notes that `done` frames are finished.
    pub fn frames_done(&mut self, done: u32) {
        let Some(bar) = &self.bar else { return };
        bar.set_position(done.into());
        if !self.drawn && looks_long(self.started.elapsed(), done, self.total) {
            bar.set_draw_target(ProgressDrawTarget::stderr());
            self.drawn = true;
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}
