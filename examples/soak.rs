//! The soak run of the stability suite: the billiards preset for many frames in release mode,
//! reporting time, the deepest overlap between two balls, and the range of total kinetic
//! energy (elastic walls and collisions: it must never rise, to rounding).
//!
//! Run: `cargo run --release --example soak -- 10000000` (the frame count; default 10^7).

use std::time::Instant;

use bouncing_ball::physics::collisions::{deepest_overlap, kinetic_energy};
use bouncing_ball::scene::file as scene_file;

fn main() {
    let frames: u64 = std::env::args()
        .nth(1)
        .map_or(10_000_000, |n| n.parse().expect("a frame count"));
    let scene = scene_file::preset("billiards", 1).expect("the billiards preset");
    let mut simulation = scene.simulation();
    let start_energy = kinetic_energy(simulation.balls());
    let (mut lowest, mut highest, mut deepest) = (start_energy, start_energy, 0.0f64);
    let mut non_finite = 0u64;
    let started = Instant::now();
    for _ in 0..frames {
        simulation.step();
        let balls = simulation.balls();
        let energy = kinetic_energy(balls);
        lowest = lowest.min(energy);
        highest = highest.max(energy);
        // Every billiards ball has the same radius.
        deepest = deepest.max(deepest_overlap(balls) / balls[0].radius);
        non_finite += balls
            .iter()
            .filter(|b| ![b.x, b.y, b.vx, b.vy].iter().all(|v| v.is_finite()))
            .count() as u64;
    }
    let seconds = started.elapsed().as_secs_f64();
    println!("billiards soak: {frames} frames of {} balls in {seconds:.1} s ({:.0} frames/s, checks included)", scene.balls.len(), frames as f64 / seconds);
    println!("kinetic energy: start {start_energy:.6}, min {lowest:.6}, max {highest:.6} (max/start − 1 = {:.3e})", highest / start_energy - 1.0);
    println!(
        "deepest overlap after a frame: {:.4} of the smaller radius",
        deepest
    );
    println!("non-finite values seen: {non_finite}");
}
