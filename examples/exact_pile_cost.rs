//! What the `pile` preset costs in exact mode, integrator by integrator: 150 balls dropped
//! into a heap, 300 frames of `Simulation::step` (no drawing). Columns: the events over the
//! run, the steps that hit the cap of 64 events per ball, the first frame from which every
//! ball sleeps, and the time, the median of five runs, in all and per event.
//!
//! Run: `cargo run --release --example exact_pile_cost` (a few seconds).

use std::time::Instant;

use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::physics::Integrator;
use bouncing_ball::scene::file::preset;

const FRAMES: u32 = 300;
const RUNS: usize = 5;

/// One run: (events, capped steps, first frame from which every ball sleeps, seconds).
fn run(integrator: Integrator) -> (u64, u64, Option<u32>, f64) {
    let mut scene = preset("pile", 1).expect("the pile preset");
    scene.motion.collisions = CollisionMode::Exact;
    scene.motion.integrator = integrator;
    let mut simulation = scene.simulation();
    let count = simulation.balls().len();
    let (mut events, mut capped, mut asleep_from) = (0, 0, None);
    let start = Instant::now();
    for frame in 0..FRAMES {
        simulation.step();
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
    (events, capped, asleep_from, start.elapsed().as_secs_f64())
}

fn main() {
    println!(
        "| integrator | events | capped steps | all asleep from frame | time | µs per event |"
    );
    println!("|---|---:|---:|---:|---:|---:|");
    for integrator in [
        Integrator::SemiImplicitEuler,
        Integrator::VelocityVerlet,
        Integrator::Rk4,
    ] {
        let mut times = Vec::new();
        let (mut events, mut capped, mut asleep_from) = (0, 0, None);
        for _ in 0..RUNS {
            let seconds;
            (events, capped, asleep_from, seconds) = run(integrator);
            times.push(seconds);
        }
        times.sort_by(f64::total_cmp);
        let time = times[RUNS / 2];
        let asleep = asleep_from.map_or("never".to_string(), |frame| frame.to_string());
        println!(
            "| {integrator:?} | {events} | {capped} | {asleep} | {:.0} ms | {:.2} |",
            time * 1e3,
            time * 1e6 / events.max(1) as f64
        );
    }
}
