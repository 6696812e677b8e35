//! What a pile costs the physics once it has come to rest: the `pile` preset (150 balls
//! heaped under gravity, the contact solver) simulated for 1,000 frames and for 20,000, by
//! `Simulation::step` alone (no drawing, no GIF), and the same in exact mode. It settles
//! within about 300 frames, so without sleep the long run costs about 20 times the short
//! one; with sleeping islands the frames after rest cost next to nothing.
//!
//! Both lengths run in turns, so the host's noise falls on both alike; the table gives the
//! median of the turns. Run: `cargo run --release -p bouncing_ball_bench --example
//! pile_at_rest` (about 20 s).

use std::time::{Duration, Instant};

use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::scene::file::preset;

/// Turns of each length.
const TURNS: usize = 5;
/// The two run lengths, frames.
const SHORT: u32 = 1_000;
const LONG: u32 = 20_000;

/// The time `frames` frames of the pile take to simulate.
fn run(collisions: CollisionMode, frames: u32) -> Duration {
    let mut scene = preset("pile", 1).expect("the pile preset");
    scene.motion.collisions = collisions;
    let mut simulation = scene.simulation();
    let start = Instant::now();
    for _ in 0..frames {
        simulation.step();
    }
    let elapsed = start.elapsed();
    std::hint::black_box(simulation.balls());
    elapsed
}

fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    times[times.len() / 2]
}

fn main() {
    println!("| collisions | {SHORT} frames | {LONG} frames | ratio |");
    println!("|---|---|---|---|");
    for collisions in [CollisionMode::Clamp, CollisionMode::Exact] {
        let (mut short, mut long) = (Vec::new(), Vec::new());
        for _ in 0..TURNS {
            short.push(run(collisions, SHORT));
            long.push(run(collisions, LONG));
        }
        let (short, long) = (median(short), median(long));
        println!(
            "| {collisions:?} | {:.1} ms | {:.1} ms | {:.2} |",
            short.as_secs_f64() * 1e3,
            long.as_secs_f64() * 1e3,
            long.as_secs_f64() / short.as_secs_f64()
        );
    }
}
