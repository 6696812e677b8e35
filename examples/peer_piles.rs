//! The two piles that `../shared/peers/rapier2d` simulates with rapier2d (150 balls of radius
//! 6 and 400 of radius 4, dropped into a 320 × 240 box; gravity 0.5, walls and balls keeping
//! half their speed), here in clamp mode: 10^4 frames of `Simulation::step` alone, timed as
//! the peer times its `world.step()` loop. Prints, per pile: the median of five runs, the
//! first frame from which every ball sleeps, and the deepest overlap at the end, as a share
//! of the radius. Run the peer beside it for its figures:
//! `rapier2d_peer pile 150 6 10000` and `rapier2d_peer pile 400 4 10000`.
//!
//! Run: `cargo run --release --example peer_piles` (a few seconds).

use std::time::Instant;

use bouncing_ball::scene::file::parse;
use bouncing_ball_lab::accuracy::deepest_overlap;

const FRAMES: u32 = 10_000;
const RUNS: usize = 5;

/// The pile as a scene file.
fn pile(count: usize, radius: f64) -> String {
    format!(
        "width = 320\nheight = 240\nframes = {FRAMES}\ngravity = [0.0, 0.5]\n\
         walls = {{ damping = 0.5 }}\nball_collisions = {{ restitution = 0.5 }}\n\
         [spawn]\ncount = {count}\nradius = {radius}\nmax_speed = 2.0\ntrail = 0\n"
    )
}

/// One run: (seconds, first frame from which every ball sleeps, deepest overlap at the end,
/// px).
fn run(count: usize, radius: f64) -> (f64, Option<u32>, f64) {
    let scene = parse("pile.toml", &pile(count, radius), 1).expect("a valid pile");
    let mut simulation = scene.simulation();
    let mut asleep_from = None;
    let mut seconds = 0.0;
    for frame in 0..FRAMES {
        let start = Instant::now();
        simulation.step();
        seconds += start.elapsed().as_secs_f64();
        let asleep = simulation.sleeping_balls() == count;
        asleep_from = if asleep {
            asleep_from.or(Some(frame))
        } else {
            None
        };
    }
    (seconds, asleep_from, deepest_overlap(simulation.balls()))
}

fn main() {
    println!("| pile | 10^4 frames, median of {RUNS} | all asleep from frame | deepest overlap at the end |");
    println!("|---|---:|---:|---:|");
    for (count, radius) in [(150, 6.0), (400, 4.0)] {
        let mut times = Vec::new();
        let (mut asleep_from, mut deepest) = (None, 0.0);
        for _ in 0..RUNS {
            let seconds;
            (seconds, asleep_from, deepest) = run(count, radius);
            times.push(seconds);
        }
        times.sort_by(f64::total_cmp);
        let asleep = asleep_from.map_or("never".to_string(), |frame| frame.to_string());
        println!(
            "| {count} × r {radius} | {:.1} ms | {asleep} | {:.4} r |",
            times[RUNS / 2] * 1e3,
            deepest / radius
        );
    }
}
