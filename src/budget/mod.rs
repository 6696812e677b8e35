//! The resource budget, decided before the first frame: how much memory a scene will need,
//! how long its run will take and how big its GIF will be, and whether that is within what
//! the run may use.
//!
//! A run predicted beyond its budget is refused before it starts, naming the knob that raises
//! it: memory (2 GiB unless `--memory-budget`), time (an hour unless `--time-budget`) and the
//! GIF's size (4 GiB unless `--gif-budget`). Below the budget, a run predicted to take over
//! 5 seconds or write over 1 GB draws a warning. Memory errs on the high side (it counts the
//! largest each buffer can grow to); time and GIF size come from a pilot run of the physics
//! and costs fitted to measured runs (how close they come: `cargo run --release --example
//! budget` and docs/robustness.md).
//!
//! This module holds the policy (the budget, the refusals, the warnings); the models are its
//! submodules:
//! - `memory`: the memory a scene needs at most, from the scene alone;
//! - `pilot`: the pilot run, which measures what a run does (its activity);
//! - `cost`: the costs fitted to measured runs, which turn activity into time and GIF size;
//! - `tiles`: a sweep's panels on one canvas.

mod cost;
pub(crate) mod memory;
mod pilot;
mod tiles;

use std::fmt;

use cost::{physics_ns, time_and_size, Activity};
use memory::memory_of;

use crate::physics::motion::CollisionMode;
use crate::physics::replay::Playback;
use crate::scene::Scene;

/// The memory a run may be predicted to need unless told otherwise, bytes (2 GiB).
pub(crate) const DEFAULT_MEMORY_BUDGET: u64 = 2 << 30;
/// The time a run may be predicted to take unless told otherwise, seconds (an hour).
pub(crate) const DEFAULT_TIME_BUDGET: f64 = 3600.0;
/// The GIF size a run may be predicted to write unless told otherwise, bytes (4 GiB).
pub(crate) const DEFAULT_GIF_BUDGET: u64 = 4 << 30;
/// A run predicted to take longer than this draws a warning with its time and GIF size,
/// seconds.
pub(crate) const WARN_SECONDS: f64 = 5.0;
/// A GIF predicted to be bigger than this draws a warning, bytes (1 GB).
pub(crate) const WARN_GIF_BYTES: f64 = 1e9;
/// Browsers show a GIF frame delay under this as 100 ms, ms.
pub(crate) const WARN_FRAME_MS: u32 = 20;

/// A scene's predicted cost.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Peak memory, bytes (on the high side).
    pub memory: u64,
    /// Time per frame, ns (rough).
    pub frame_ns: f64,
    /// The whole run, seconds (rough).
    pub seconds: f64,
    /// The GIF's size, bytes (rough).
    pub gif_bytes: f64,
    /// The part that dominates the memory, for the message.
    pub biggest: &'static str,
}

/// What a run may be predicted to need before it is refused, not started.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget {
    /// Memory, bytes (`--memory-budget`, MB).
    pub memory: u64,
    /// Time, seconds (`--time-budget`).
    pub seconds: f64,
    /// The GIF's size on disk, bytes (`--gif-budget`, MB).
    pub gif_bytes: u64,
}

impl Default for Budget {
    fn default() -> Budget {
        Budget {
            memory: DEFAULT_MEMORY_BUDGET,
            seconds: DEFAULT_TIME_BUDGET,
            gif_bytes: DEFAULT_GIF_BUDGET,
        }
    }
}

impl Budget {
    /// Refuses `seconds` of predicted time if over the time budget: for a caller that adds up
    /// several runs' estimates (such as `physics_seconds` of each) into one total.
    pub(crate) fn check_seconds(&self, seconds: f64) -> Result<(), OverBudget> {
        if seconds > self.seconds {
            return Err(OverBudget::Time {
                needed: seconds,
                budget: self.seconds,
            });
        }
        Ok(())
    }
}

/// A scene predicted to need more than the budget allows, each with the knob that raises it.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum OverBudget {
    #[error("the scene needs about {} of memory (mostly {biggest}), over the budget of {}; raise it with --memory-budget <MB> (e.g. --memory-budget {}) or use fewer or smaller balls, trails or frames", megabytes(*needed), megabytes(*budget), needed.div_ceil(1 << 20))]
    Memory {
        needed: u64,
        budget: u64,
        biggest: &'static str,
    },
    #[error("this run looks to take about {}, over the time budget of {}; raise it with --time-budget <SECONDS> (e.g. --time-budget {}) or use fewer frames or balls", Duration(*needed), Duration(*budget), suggested_seconds(*needed))]
    Time { needed: f64, budget: f64 },
    #[error("the GIF looks to be about {}, over the budget of {}; raise it with --gif-budget <MB> (e.g. --gif-budget {}) or use fewer frames, balls or a smaller canvas", megabytes(*needed), megabytes(*budget), needed.div_ceil(1 << 20))]
    Gif { needed: u64, budget: u64 },
}

fn megabytes(bytes: u64) -> String {
    format!("{} MB", bytes.div_ceil(1 << 20))
}

/// A time budget that lets a run predicted at `needed` seconds start: whole seconds, or
/// tenths below 10 s (0.43 s suggests 0.5).
fn suggested_seconds(needed: f64) -> f64 {
    if needed < 10.0 {
        (needed * 10.0).ceil() / 10.0
    } else {
        needed.ceil()
    }
}

/// What a pilot run found the physics of a scene doing, to predict whole runs from: of the
/// scene it ran, or of the same scene with its frames cut into other substeps. Those do the
/// same events and step the same balls, only more often: the cost model takes the substeps
/// from the scene it is asked about, so one pilot serves them all.
pub(crate) struct PhysicsPilot(Activity);

impl PhysicsPilot {
    /// Pilots the physics of a validated `scene`.
    pub(crate) fn of(scene: &Scene) -> PhysicsPilot {
        PhysicsPilot(Activity::of(scene))
    }

    /// The predicted seconds of the physics alone of a whole run of `scene` (stepping the
    /// balls, exact mode's events; no drawing, no GIF): the piloted scene, or it with other
    /// substeps.
    pub(crate) fn seconds(&self, scene: &Scene) -> f64 {
        physics_ns(scene, &self.0) * 1e-9
    }
}

impl Estimate {
    /// Works out the cost of a validated `scene`.
    pub fn of(scene: &Scene) -> Estimate {
        let (memory, biggest) = memory_of(scene);
        Estimate::with_memory(scene, memory, biggest, Activity::of(scene))
    }

    /// Works out the cost of a validated `scene` and refuses it if over `budget`. Memory is
    /// checked first, from the scene alone, so a scene too big for it is refused before the
    /// pilot run of its physics allocates anything. The pilot runs only when its answer can
    /// change what happens: if even a run whose every frame changed all over would stay
    /// under the warnings and the budget, that bound is the answer (short runs, where the
    /// pilot would cost as much as the run). Exact mode's events have no such bound, so
    /// with them the pilot always runs.
    pub(crate) fn within(scene: &Scene, budget: &Budget) -> Result<Estimate, OverBudget> {
        Estimate::checked(scene, budget, false).map(|(estimate, _)| estimate)
    }

    /// `within`, and the frames the pilot stepped, for the run to play back instead of
    /// stepping them again (`crate::physics::replay`); `None` where no pilot ran or its
    /// frames did not fit.
    pub(crate) fn within_keeping(
        scene: &Scene,
        budget: &Budget,
    ) -> Result<(Estimate, Option<Playback>), OverBudget> {
        Estimate::checked(scene, budget, true)
    }

    /// `within`, keeping the pilot's frames if `keep`.
    fn checked(
        scene: &Scene,
        budget: &Budget,
        keep: bool,
    ) -> Result<(Estimate, Option<Playback>), OverBudget> {
        let (memory, biggest) = memory_of(scene);
        if memory > budget.memory {
            return Err(OverBudget::Memory {
                needed: memory,
                budget: budget.memory,
                biggest,
            });
        }
        let bound = Estimate::with_memory(scene, memory, biggest, Activity::at_most(scene));
        let has_events =
            scene.ball_collisions.is_some() && scene.motion.collisions == CollisionMode::Exact;
        if !has_events
            && bound.seconds <= WARN_SECONDS.min(budget.seconds)
            && bound.gif_bytes <= WARN_GIF_BYTES.min(budget.gif_bytes as f64)
        {
            return Ok((bound, None));
        }
        let (activity, playback) = if keep {
            Activity::of_keeping(scene)
        } else {
            (Activity::of(scene), None)
        };
        let estimate = Estimate::with_memory(scene, memory, biggest, activity);
        estimate.check_time_and_size(budget)?;
        Ok((estimate, playback))
    }

    /// The time and GIF size of `scene` when it does what `activity` says, beside its memory.
    fn with_memory(
        scene: &Scene,
        memory: u64,
        biggest: &'static str,
        activity: Activity,
    ) -> Estimate {
        let cost = time_and_size(scene, &activity);
        Estimate {
            memory,
            frame_ns: cost.frame_ns,
            seconds: cost.seconds,
            gif_bytes: cost.gif_bytes,
            biggest,
        }
    }

    /// Refuses a scene predicted to take more time or GIF bytes than `budget` allows.
    fn check_time_and_size(&self, budget: &Budget) -> Result<(), OverBudget> {
        budget.check_seconds(self.seconds)?;
        if self.gif_bytes > budget.gif_bytes as f64 {
            return Err(OverBudget::Gif {
                needed: self.gif_bytes as u64,
                budget: budget.gif_bytes,
            });
        }
        Ok(())
    }

    /// What about `scene` works but may surprise, one line each.
    pub(crate) fn warnings(&self, scene: &Scene) -> Vec<String> {
        let long = (self.seconds > WARN_SECONDS || self.gif_bytes > WARN_GIF_BYTES).then(|| {
            format!(
                "this run looks to take about {} and write a GIF of about {} (Ctrl-C stops it and writes nothing)",
                Duration(self.seconds),
                megabytes(self.gif_bytes as u64)
            )
        });
        frame_ms_warning(scene).into_iter().chain(long).collect()
    }
}

/// The warning for frames shown shorter than browsers show them, if `scene`'s are.
pub(crate) fn frame_ms_warning(scene: &Scene) -> Option<String> {
    (scene.frame_ms < WARN_FRAME_MS).then(|| {
        format!(
            "--frame-ms {}: browsers show frames shorter than {WARN_FRAME_MS} ms for 100 ms",
            scene.frame_ms
        )
    })
}

/// The warning for work predicted to take `seconds`, if that is long (a comparison, whose
/// GIF size is each method's business).
pub(crate) fn long_work_warning(seconds: f64) -> Option<String> {
    (seconds > WARN_SECONDS).then(|| {
        format!(
            "this looks to take about {} (Ctrl-C stops it and writes nothing)",
            Duration(seconds)
        )
    })
}

/// Seconds as a person reads them: two significant figures below 10 s (0.4 s, 0.12 s,
/// 2.5 s), whole seconds up to two minutes, then minutes, then hours.
struct Duration(f64);

impl fmt::Display for Duration {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = self.0;
        if s < 10.0 {
            let decimals = match s {
                1.0.. => 1,
                0.1.. => 2,
                _ => 3,
            };
            let text = format!("{s:.decimals$}");
            let text = match text.contains('.') {
                true => text.trim_end_matches('0').trim_end_matches('.'),
                false => &text,
            };
            write!(f, "{text} s")
        } else if s < 120.0 {
            write!(f, "{s:.0} s")
        } else if s < 7200.0 {
            write!(f, "{:.0} minutes", s / 60.0)
        } else {
            write!(f, "{:.0} hours", s / 3600.0)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fraction_of_a_second_reads_as_one() {
        for (seconds, expected) in [
            (0.4, "0.4 s"),
            (0.123, "0.12 s"),
            (0.1, "0.1 s"),
            (0.0004, "0 s"),
            (2.5, "2.5 s"),
            (9.96, "10 s"),
            (42.0, "42 s"),
            (1176.0, "20 minutes"),
            (50419.0, "14 hours"),
        ] {
            let actual = Duration(seconds).to_string();
            assert_eq!(
                actual, expected,
                "{seconds} s: expected {expected:?}, got {actual:?}"
            );
        }
    }

    #[test]
    fn a_sub_second_refusal_names_both_times_and_a_budget_that_would_do() {
        let budget = Budget {
            seconds: 0.1,
            ..Budget::default()
        };
        let refusal = budget.check_seconds(0.43).unwrap_err().to_string();
        for part in ["about 0.43 s", "time budget of 0.1 s", "--time-budget 0.5"] {
            assert!(refusal.contains(part), "expected {part:?} in: {refusal}");
        }
    }

    #[test]
    fn check_seconds_lets_a_total_within_the_budget_through() {
        let budget = Budget::default();
        assert_eq!(budget.check_seconds(DEFAULT_TIME_BUDGET), Ok(()));
        assert!(budget.check_seconds(DEFAULT_TIME_BUDGET + 1.0).is_err());
    }
}
