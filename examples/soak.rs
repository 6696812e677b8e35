//! The soak run of the stability suite: the billiards preset for many frames in release mode,
//! reporting time, the deepest overlap between two balls, and the range of total kinetic
//! energy (elastic walls and collisions: it must never rise, to rounding).
//!
//! Run: `cargo run --release --example soak -- 10000000` (the frame count; default 10^7).
//! Add `exact` after the count for exact mode (every contact at its moment), which also
//! prints the most events any frame took and the steps that hit the event cap.

use std::time::Instant;

use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::scene::file as scene_file;
use bouncing_ball_lab::accuracy::{deepest_overlap, kinetic_energy};

fn main() {
    let frames: u64 = std::env::args()
        .nth(1)
        .map_or(10_000_000, |n| n.parse().expect("a frame count"));
    let mut scene = scene_file::preset("billiards", 1).expect("the billiards preset");
    if std::env::args().nth(2).as_deref() == Some("exact") {
        scene.motion.collisions = CollisionMode::Exact;
    }
    let mut simulation = scene.simulation();
    let start_energy = kinetic_energy(simulation.balls());
    // Every billiards ball has the same radius.
    let radius = simulation.balls()[0].radius;
    let (mut lowest, mut highest) = (start_energy, start_energy);
    let mut deepest = deepest_overlap(simulation.balls()) / radius;
    let mut non_finite = 0u64;
    let (mut most_events, mut capped) = (0u64, 0u64);
    let started = Instant::now();
    for _ in 0..frames {
        simulation.step();
        let balls = simulation.balls();
        let energy = kinetic_energy(balls);
        lowest = lowest.min(energy);
        highest = highest.max(energy);
        deepest = deepest.max(deepest_overlap(balls) / radius);
        if let Some(counts) = simulation.event_counts() {
            most_events = most_events.max(counts.events);
            capped += counts.capped_steps;
        }
        non_finite += balls
            .iter()
            .filter(|b| ![b.x, b.y, b.vx, b.vy].iter().all(|v| v.is_finite()))
            .count() as u64;
    }
    let seconds = started.elapsed().as_secs_f64();
    println!("billiards soak: {frames} frames of {} balls in {seconds:.1} s ({:.0} frames/s, checks included)", scene.balls.len(), frames as f64 / seconds);
    println!("kinetic energy: start {start_energy:.6}, min {lowest:.6}, max {highest:.6} (max/start − 1 = {:.3e}, min/start − 1 = {:.3e})", highest / start_energy - 1.0, lowest / start_energy - 1.0);
    println!("deepest overlap, spawn and every frame: {deepest:.3e} of the radius");
    println!("non-finite values seen: {non_finite}");
    if simulation.event_counts().is_some() {
        println!("exact mode: at most {most_events} events in a frame, {capped} steps capped");
    }
}
