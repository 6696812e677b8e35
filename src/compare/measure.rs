//! What a comparison measures of each method: how long its physics takes per ball and frame
//! on this machine, how far its balls stray from the reference's, and what happens to the
//! energy.
//!
//! The errors and energies come from the one run that is drawn, so they are the same on every
//! machine; only the timings depend on the clock, and they go to the table, never to the GIF.

use std::hint::black_box;
use std::time::{Duration, Instant};

use crate::physics::ball::{kinetic_energy, mass};
use crate::physics::{Ball, Vec2};
use crate::plot::record::Recording;
use crate::scene::Scene;

use super::methods::Method;

/// One repetition of the timing runs the physics over and over until it has taken this long,
/// so the clock's resolution and the cost of reading it do not count.
const REPETITION: Duration = Duration::from_millis(5);
/// Repetitions timed per method, at most; fewer once [`TIMING_BUDGET`] per method is spent,
/// but never fewer than `MIN_REPETITIONS`.
const MAX_REPETITIONS: usize = 9;
const MIN_REPETITIONS: usize = 3;
const TIMING_BUDGET: Duration = Duration::from_millis(300);

/// Nanoseconds per ball per frame: the median of the repetitions, and the fastest and slowest.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Timing {
    pub median: f64,
    pub min: f64,
    pub max: f64,
}

/// How long the physics of one whole run of `scene` takes (the simulation is built before
/// the clock starts).
fn one_run(scene: &Scene) -> Duration {
    let mut simulation = scene.simulation();
    let started = Instant::now();
    for _ in 0..scene.frames {
        simulation.step();
    }
    black_box(simulation.balls());
    started.elapsed()
}

/// Times the physics of `scene` (no drawing; give it a scene without trails) solved by each
/// of `methods`, in ns per ball-frame. The methods take turns, repetition by repetition, so a
/// change in the machine's load falls on all of them alike.
pub(crate) fn time_all(scene: &Scene, methods: &[Method]) -> Vec<Timing> {
    let scenes: Vec<Scene> = methods.iter().map(|m| m.on(scene)).collect();
    let ball_frames = scene.balls.len().max(1) as f64 * f64::from(scene.frames);
    // How many runs make one repetition, for each method, from one run; a run that long
    // already is the first repetition.
    let mut samples = vec![Vec::new(); methods.len()];
    let runs: Vec<u32> = scenes
        .iter()
        .zip(&mut samples)
        .map(|(scene, samples)| {
            let first = one_run(scene);
            if first >= REPETITION {
                samples.push(first.as_nanos() as f64 / ball_frames);
                return 1;
            }
            let runs = REPETITION.as_nanos() / first.as_nanos().max(1) + 1;
            runs.min(1 << 20) as u32
        })
        .collect();
    let started = Instant::now();
    let budget = TIMING_BUDGET * methods.len() as u32;
    let enough = |samples: &[Vec<f64>], limit| samples.iter().all(|s| s.len() >= limit);
    while !enough(&samples, MAX_REPETITIONS)
        && (!enough(&samples, MIN_REPETITIONS) || started.elapsed() < budget)
    {
        for ((scene, &runs), samples) in scenes.iter().zip(&runs).zip(&mut samples) {
            let total: Duration = (0..runs).map(|_| one_run(scene)).sum();
            samples.push(total.as_nanos() as f64 / (f64::from(runs) * ball_frames));
        }
    }
    samples
        .into_iter()
        .map(|mut samples| {
            samples.sort_by(f64::total_cmp);
            Timing {
                median: samples[samples.len() / 2],
                min: samples[0],
                max: samples[samples.len() - 1],
            }
        })
        .collect()
}

/// How long [`time_all`] takes when one run of each method takes `runs` seconds: a first run
/// each, then rounds in which every method runs for a repetition (at least `REPETITION`),
/// as many rounds as fit in the timing budget, but at least enough for `MIN_REPETITIONS`
/// and at most `MAX_REPETITIONS`.
pub(crate) fn timing_seconds(runs: &[f64]) -> f64 {
    let repetition = REPETITION.as_secs_f64();
    let round: f64 = runs.iter().map(|&run| run.max(repetition)).sum();
    // A first run as long as a repetition is the first sample.
    let first_counts = runs.iter().all(|&run| run >= repetition);
    let (fewest, most) = match first_counts {
        true => (MIN_REPETITIONS - 1, MAX_REPETITIONS - 1),
        false => (MIN_REPETITIONS, MAX_REPETITIONS),
    };
    let budget = TIMING_BUDGET.as_secs_f64() * runs.len() as f64;
    let fit = (budget / round.max(f64::MIN_POSITIVE)).ceil();
    let rounds = fit.clamp(fewest as f64, most as f64);
    runs.iter().sum::<f64>() + rounds * round
}

/// One method's results.
#[derive(Clone, Debug)]
pub(crate) struct Outcome {
    pub method: Method,
    pub timing: Timing,
    pub stray: Stray,
    /// What can be said of it against the reference.
    pub standing: Standing,
    /// See [`super::table`]'s note under the table; `None` when the scene starts with no energy.
    pub energy_drift: Option<f64>,
}

/// A scene's mechanical energy: kinetic `Σ ½·m·|v|²` plus potential `Σ m·g·h`, with the
/// masses of collisions (m ∝ r²) and the plot's heights (how far each ball could still fall).
pub(crate) struct Energy {
    heights: Recording,
}

impl Energy {
    pub(crate) fn new(scene: &Scene) -> Energy {
        Energy {
            heights: Recording::new(scene),
        }
    }

    /// The energy of `balls`, px⁴/frame² (mass in px²).
    pub(crate) fn of(&self, balls: &[Ball]) -> f64 {
        let potential: f64 = balls
            .iter()
            .map(|b| mass(b.radius) * self.heights.potential(b))
            .sum();
        kinetic_energy(balls) + potential
    }
}

/// Whether `scene` keeps its energy, so a method's drift is its own error: no drag, and every
/// wall, floor and ball-ball collision elastic.
pub(crate) fn conserves_energy(scene: &Scene) -> bool {
    scene.drag.is_none()
        && scene.walls.is_none_or(|damping| damping == 1.0)
        && scene.floors.iter().all(|floor| floor.damping == 1.0)
        && scene
            .ball_collisions
            .is_none_or(|restitution| restitution == 1.0)
}

/// How far one method has strayed from the reference, frame by frame, in the frames before
/// the reference's horizon (past it the reference no longer says where the balls are).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Stray {
    /// The largest distance of any ball from its reference so far, px.
    pub max_error: f64,
    /// The first frame in which some ball was more than its radius from its reference.
    pub parted_at: Option<u32>,
    /// The reference's horizon: frames from here on are not measured.
    horizon: u32,
}

impl Stray {
    /// Nothing strayed yet, measured against a reference trusted up to `horizon`.
    pub(crate) fn until(horizon: u32) -> Stray {
        Stray {
            max_error: 0.0,
            parted_at: None,
            horizon,
        }
    }

    /// Takes in frame `n`: the method's `balls` and the reference's `centres`.
    pub(crate) fn frame(&mut self, n: u32, balls: &[Ball], centres: &[Vec2]) {
        if n >= self.horizon {
            return;
        }
        for (ball, &centre) in balls.iter().zip(centres) {
            let error = (ball.position() - centre).length();
            self.max_error = self.max_error.max(error);
            if error > ball.radius && self.parted_at.is_none() {
                self.parted_at = Some(n);
            }
        }
    }
}

/// How far the reference can be trusted: what every method is judged by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Trust {
    /// The largest uncertainty before the horizon, px: a smaller error says nothing.
    pub uncertainty: f64,
    /// The first frame the reference does not say where the balls are.
    pub horizon: u32,
}

impl Trust {
    /// Whether the reference can tell how far a method is off over the first `seen` frames:
    /// not at all when it is trusted in no frame, and for colliding balls (`chaotic`) not
    /// past its horizon, where any error is as likely as any other.
    pub(crate) fn tells(self, chaotic: bool, seen: u32) -> bool {
        self.horizon > 0 && !(chaotic && self.horizon < seen)
    }
}

/// What a row of the table is: a method judged against the reference, or the reference's
/// own method, shown but not judged (it would agree with itself exactly).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Role {
    Method,
    Reference,
}

impl Role {
    /// As the CSV writes it.
    pub(crate) fn name(self) -> &'static str {
        match self {
            Role::Method => "method",
            Role::Reference => "reference",
        }
    }
}

/// What can be said of a method against the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Standing {
    /// It is the reference's own method: shown, not judged.
    Reference,
    /// Some ball was more than its radius off in this frame, before the horizon (colliding
    /// balls: from then on the runs are different games).
    Parted(u32),
    /// It stayed within a radius up to the horizon, and the reference can tell no further
    /// (colliding balls, or a reference not even checked).
    AsFarAsKnown(u32),
    /// Its largest error is smaller than the reference's uncertainty (that, px), so the
    /// reference cannot tell how small it is.
    BelowUncertainty(f64),
    /// Its largest error before the horizon, px.
    Error(f64),
}

impl Standing {
    /// The standing of a method of `role` that strayed as `stray`, after `seen` frames of a
    /// scene (`chaotic` when its balls collide), against a reference trusted as `trust`.
    pub(crate) fn of(
        role: Role,
        stray: &Stray,
        trust: Trust,
        chaotic: bool,
        seen: u32,
    ) -> Standing {
        if role == Role::Reference {
            return Standing::Reference;
        }
        if let (true, Some(frame)) = (chaotic, stray.parted_at) {
            return Standing::Parted(frame);
        }
        if !trust.tells(chaotic, seen) {
            return Standing::AsFarAsKnown(trust.horizon);
        }
        if stray.max_error < trust.uncertainty {
            return Standing::BelowUncertainty(trust.uncertainty);
        }
        Standing::Error(stray.max_error)
    }

    /// Whether it is the reference's own method or a method judged against it.
    pub(crate) fn role(self) -> Role {
        match self {
            Standing::Reference => Role::Reference,
            _ => Role::Method,
        }
    }
}
