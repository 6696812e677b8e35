//! What a frame of a big pile costs the physics before and after it rests: 10,000 balls of
//! radius 3 dropped into a 1280 × 720 box (the `pile` preset's settings otherwise), stepped
//! by `Simulation::step` until every ball sleeps (at most 5,000 frames), then 1,000 frames
//! more. Prints the median frame time of the first 100 frames (the fall), the frame the
//! pile fell asleep, and the median frame time once asleep.
//!
//! Run: `cargo run --release -p bouncing_ball_bench --example big_pile -- [ITERATIONS [SUBSTEPS]]`
//! (the solver's iterations per step and substeps per frame, default the preset's 12 and 1;
//! up to several minutes). Every 250 frames it says how many balls sleep, how many are still
//! faster than the sleep speed, the fastest one's speed, the deepest overlap, and the mean
//! height of the centres above the floor: a heap that settles sinks or stays, one that the
//! solver feeds energy swells. The velocity passes per sub-step are
//! `physics::tolerances::LOADED_VELOCITY_PASSES`; `docs/contacts.md` has what 1 to 4 did.

use std::time::{Duration, Instant};

use bouncing_ball::physics::tolerances::SLEEP_SPEED;
use bouncing_ball::physics::Simulation;
use bouncing_ball::scene::file::{preset, Spawn};
use bouncing_ball_lab::accuracy::deepest_overlap;

/// Balls, their radius (px) and the canvas, px.
const COUNT: usize = 10_000;
const RADIUS: f64 = 3.0;
const WIDTH: u32 = 1280;
const HEIGHT: u32 = 720;
/// Frames timed during the fall, the most frames to wait for sleep, frames timed after.
const FALL: usize = 100;
const PATIENCE: u32 = 5_000;
const AFTER: usize = 1_000;

fn median(mut times: Vec<Duration>) -> Duration {
    times.sort();
    times[times.len() / 2]
}

fn main() {
    let mut scene = preset("pile", 1).expect("the pile preset");
    (scene.width, scene.height) = (WIDTH, HEIGHT);
    let spawn = Spawn::new(COUNT, RADIUS, 4.0);
    scene.balls = spawn.overlapping_balls(f64::from(WIDTH), f64::from(HEIGHT), 1);
    if let Some(iterations) = std::env::args().nth(1) {
        scene.motion.iterations = iterations.parse().expect("iterations: a whole number");
    }
    if let Some(substeps) = std::env::args().nth(2) {
        scene.motion.substeps = substeps.parse().expect("substeps: a whole number");
    }
    scene.validate().expect("a valid pile");
    let mut simulation = scene.simulation();
    let timed = |simulation: &mut Simulation| {
        let start = Instant::now();
        simulation.step();
        start.elapsed()
    };
    let fall: Vec<Duration> = (0..FALL).map(|_| timed(&mut simulation)).collect();
    let mut frame = FALL as u32;
    while simulation.sleeping_balls() < COUNT && frame < PATIENCE {
        simulation.step();
        frame += 1;
        if frame.is_multiple_of(250) {
            report(&simulation, frame);
        }
    }
    let asleep = simulation.sleeping_balls();
    let after: Vec<Duration> = (0..AFTER).map(|_| timed(&mut simulation)).collect();
    let (fall, after) = (median(fall), median(after));
    println!(
        "{COUNT} balls of radius {RADIUS} px in {WIDTH} x {HEIGHT}, {} iterations:",
        scene.motion.iterations
    );
    println!("  frame during the fall (median of the first {FALL}): {fall:?}");
    println!("  {asleep} of {COUNT} asleep after {frame} frames");
    println!("  frame after that (median of {AFTER}): {after:?}");
    println!(
        "  after / fall: {:.2} %",
        100.0 * after.as_secs_f64() / fall.as_secs_f64()
    );
}

/// How many balls sleep at `frame`, how many move faster than the sleep speed, how deep the
/// deepest overlap is, and how high the centres are on average.
fn report(simulation: &Simulation, frame: u32) {
    let balls = simulation.balls();
    let deepest = deepest_overlap(balls) / RADIUS;
    let height = balls.iter().map(|b| f64::from(HEIGHT) - b.y).sum::<f64>() / COUNT as f64;
    let fast = balls
        .iter()
        .filter(|ball| ball.velocity().length_squared() >= SLEEP_SPEED * SLEEP_SPEED)
        .count();
    let asleep = simulation.sleeping_balls();
    let fastest = balls
        .iter()
        .map(|b| b.velocity().length())
        .fold(0.0, f64::max);
    eprintln!(
        "frame {frame}: {asleep} asleep, {fast} faster than {SLEEP_SPEED} px/frame, the fastest \
         at {fastest:.3} px/frame; deepest overlap {deepest:.3} r, mean height {height:.2} px"
    );
}
