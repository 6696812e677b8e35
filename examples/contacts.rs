//! What the contact solver's settings buy and cost: the two test piles (150 balls of radius 6
//! and 400 of radius 4 dropped into the 320 × 240 box, gravity 0.5, walls 0.5, restitution
//! 0.5) for 10,000 frames, for iterations × substeps.
//!
//! `cargo run --release --example contacts` prints one table row per setting:
//! - **deepest overlap**: the most any pair overlaps in the last 1,000 frames, in radii;
//! - **height error**: the heap's height minus the least height it can have without overlaps
//!   (`N·π·r²/(0.9069·W)`), px: negative means the balls sank into each other;
//! - **rest frame**: the first frame after which the rms speed stays at most 0.01 px/frame
//!   (`never` if it does not);
//! - **ns per ball-frame**: time in `Simulation::step` only, per ball and frame (a heap that
//!   sleeps early costs little after that, so this is the cost of the whole run, not of a
//!   frame of falling balls).
//!
//! `cargo run --release --example contacts -- 12 1` runs one setting (iterations, substeps),
//! and `-- 12 1 3` drops the piles at spawn seed 3 instead of 1.
//! Last it prints how far the `pyramid` preset's balls moved in 10,000 frames at the default
//! settings.

use std::time::Instant;

use bouncing_ball::scene::file::preset;
use bouncing_ball_lab::accuracy::{deepest_overlap, lowest_pile, pile_height, rms_speed};
use bouncing_ball_lab::scenes::pile;

const FRAMES: u32 = 10_000;
/// The last frames, in which the heap must be at rest.
const SETTLED: u32 = 1_000;
/// Speed below which a heap counts as at rest, px/frame.
const REST: f64 = 0.01;
const ITERATIONS: [u32; 6] = [1, 2, 4, 8, 12, 16];
const SUBSTEPS: [u32; 3] = [1, 2, 4];
/// The two piles: balls and radius, px.
const PILES: [(usize, f64); 2] = [(150, 6.0), (400, 4.0)];

/// What one run of one pile measured.
struct Outcome {
    deepest_overlap: f64,
    height_error: f64,
    rest_frame: Option<u32>,
    ns_per_ball_frame: f64,
}

fn run(count: usize, radius: f64, iterations: u32, substeps: u32, seed: u64) -> Outcome {
    let mut scene = pile(count, radius, seed).expect("a valid pile");
    scene.motion.iterations = iterations;
    scene.motion.substeps = substeps;
    let mut simulation = scene.simulation();
    let (mut deepest, mut rest_frame, mut stepping) = (0.0f64, None, 0.0);
    for frame in 1..=FRAMES {
        let start = Instant::now();
        simulation.step();
        stepping += start.elapsed().as_secs_f64();
        let balls = simulation.balls();
        if frame > FRAMES - SETTLED {
            deepest = deepest.max(deepest_overlap(balls) / radius);
        }
        match (rms_speed(balls) <= REST, rest_frame) {
            (true, None) => rest_frame = Some(frame),
            (false, _) => rest_frame = None,
            _ => {}
        }
    }
    let (width, floor) = (f64::from(scene.width), f64::from(scene.height));
    Outcome {
        deepest_overlap: deepest,
        height_error: pile_height(simulation.balls(), floor) - lowest_pile(count, radius, width),
        rest_frame,
        ns_per_ball_frame: stepping * 1e9 / (f64::from(FRAMES) * count as f64),
    }
}

/// The farthest any ball of the `pyramid` preset moves from its start in `FRAMES`, in radii.
fn pyramid_drift() -> f64 {
    let mut simulation = preset("pyramid", 1)
        .expect("the pyramid preset")
        .simulation();
    let start = simulation.balls().to_vec();
    for _ in 0..FRAMES {
        simulation.step();
    }
    simulation
        .balls()
        .iter()
        .zip(&start)
        .map(|(now, then)| (now.x - then.x).hypot(now.y - then.y) / then.radius)
        .fold(0.0, f64::max)
}

fn main() {
    let args: Vec<u32> = std::env::args()
        .skip(1)
        .map(|a| {
            a.parse()
                .expect("iterations and substeps are whole numbers")
        })
        .collect();
    let seed = args.get(2).map_or(1, |&seed| u64::from(seed));
    let settings: Vec<(u32, u32)> = match args[..] {
        [iterations, substeps, ..] => vec![(iterations, substeps)],
        _ => SUBSTEPS
            .iter()
            .flat_map(|&s| ITERATIONS.iter().map(move |&i| (i, s)))
            .collect(),
    };
    println!("| balls × radius | iterations | substeps | deepest overlap (r) | height error (px) | rest frame | ns per ball-frame |");
    println!("|---|---:|---:|---:|---:|---:|---:|");
    for (iterations, substeps) in settings {
        for (count, radius) in PILES {
            let o = run(count, radius, iterations, substeps, seed);
            let rest = o.rest_frame.map_or("never".to_string(), |f| f.to_string());
            println!(
                "| {count} × {radius} | {iterations} | {substeps} | {:.3} | {:+.1} | {rest} | {:.0} |",
                o.deepest_overlap, o.height_error, o.ns_per_ball_frame
            );
        }
    }
    println!(
        "pyramid, default settings, {FRAMES} frames: farthest ball moved {:.4} r",
        pyramid_drift()
    );
}
