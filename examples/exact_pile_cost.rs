//! What the `pile` preset costs in exact mode, integrator by integrator: 150 balls dropped
//! into a heap, 300 frames of `Simulation::step` (no drawing). Columns: the events over the
//! run, the steps that hit the cap of 64 events per ball, the first frame from which every
//! ball sleeps, and the time, the median of five runs, in all and per event; then what a
//! frame costs once every ball sleeps, as a share of a frame before (the mean of each).
//!
//! Run: `cargo run --release --example exact_pile_cost` (a few seconds).

use std::time::Instant;

use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::physics::Integrator;
use bouncing_ball::scene::file::preset;

const FRAMES: u32 = 300;
const RUNS: usize = 5;

/// One run: (events, capped steps, first frame from which every ball sleeps, seconds, and
/// the seconds of each frame).
fn run(integrator: Integrator) -> (u64, u64, Option<u32>, f64, Vec<f64>) {
    let mut scene = preset("pile", 1).expect("the pile preset");
    scene.motion.collisions = CollisionMode::Exact;
    scene.motion.integrator = integrator;
    let mut simulation = scene.simulation();
    let count = simulation.balls().len();
    let (mut events, mut capped, mut asleep_from) = (0, 0, None);
    let mut frame_seconds = Vec::new();
    let start = Instant::now();
    for frame in 0..FRAMES {
        let frame_start = Instant::now();
        simulation.step();
        frame_seconds.push(frame_start.elapsed().as_secs_f64());
        let counts = simulation.event_counts().expect("exact mode counts events");
        events += counts.events;
        capped += counts.capped_steps;
        let all_asleep = simulation.sleeping_balls() == count;
        asleep_from = if all_asleep {
            asleep_from.or(Some(frame))
        } else {
            None
        };
    }
    let seconds = start.elapsed().as_secs_f64();
    (events, capped, asleep_from, seconds, frame_seconds)
}

/// A frame's mean cost once every ball sleeps (from frame `asleep`), as a share of a frame's
/// before.
fn asleep_share(frame_seconds: &[f64], asleep: u32) -> f64 {
    let (falling, resting) = frame_seconds.split_at(asleep as usize);
    let mean = |frames: &[f64]| frames.iter().sum::<f64>() / frames.len().max(1) as f64;
    mean(resting) / mean(falling)
}

fn main() {
    println!(
        "| integrator | events | capped steps | all asleep from frame | time | µs per event | a frame asleep / a frame before |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for integrator in [
        Integrator::SemiImplicitEuler,
        Integrator::VelocityVerlet,
        Integrator::Rk4,
    ] {
        let mut times = Vec::new();
        let (mut events, mut capped, mut asleep_from) = (0, 0, None);
        let mut shares = Vec::new();
        for _ in 0..RUNS {
            let (seconds, frame_seconds);
            (events, capped, asleep_from, seconds, frame_seconds) = run(integrator);
            times.push(seconds);
            shares.extend(asleep_from.map(|frame| asleep_share(&frame_seconds, frame)));
        }
        shares.sort_by(f64::total_cmp);
        let share = shares
            .get(shares.len() / 2)
            .map_or("never asleep".to_string(), |share| {
                format!("{:.4} %", share * 100.0)
            });
        times.sort_by(f64::total_cmp);
        let time = times[RUNS / 2];
        let asleep = asleep_from.map_or("never".to_string(), |frame| frame.to_string());
        println!(
            "| {integrator:?} | {events} | {capped} | {asleep} | {:.0} ms | {:.2} | {share} |",
            time * 1e3,
            time * 1e6 / events.max(1) as f64
        );
    }
}
