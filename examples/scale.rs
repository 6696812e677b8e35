//! Scale: a 1920x1080 scene with 1,000 balls for 600 frames, simulated, rendered and
//! encoded to a GIF file, with frames per second and where the time went (physics, raster,
//! finding changes, LZW, write). Seeded, so every run draws the same frames.
//!
//! Run: `cargo run --release --example scale` (balls pass through each other), or
//! `cargo run --release --example scale -- --collisions` (billiards: elastic ball-ball
//! collisions). The GIF goes to the system's temporary folder.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::time::{Duration, Instant};

use bouncing_ball::gif::GifWriter;
use bouncing_ball::render::Renderer;
use bouncing_ball::scene::random::Random;
use bouncing_ball::{BallSpec, Scene};

const WIDTH: u32 = 1920;
const HEIGHT: u32 = 1080;
const BALLS: usize = 1000;
const FRAMES: u32 = 600;
/// Radii are spread over this range, px.
const RADII: (f64, f64) = (5.0, 9.0);
/// Starting speeds are up to this much along each axis, px/frame.
const MAX_SPEED: f64 = 4.0;
const TRAIL: usize = 8;
const COLOURS: [[u8; 3]; 4] = [
    [255, 200, 60],
    [255, 90, 90],
    [120, 230, 120],
    [200, 120, 255],
];
const TRAIL_COLOURS: [[u8; 3]; 4] = [
    [60, 140, 255],
    [255, 150, 60],
    [60, 200, 200],
    [230, 90, 200],
];

/// 1,000 balls, each jittered about the centre of its own cell of a lattice (so none
/// overlap at the start), in an elastic box without gravity.
fn scene(collisions: bool) -> Scene {
    let mut random = Random::new(2024);
    let columns = ((BALLS as f64) * f64::from(WIDTH) / f64::from(HEIGHT))
        .sqrt()
        .ceil() as usize;
    let rows = BALLS.div_ceil(columns);
    let cell = (f64::from(WIDTH) / columns as f64).min(f64::from(HEIGHT) / rows as f64);
    let balls = (0..BALLS)
        .map(|i| {
            let radius = random.range(RADII.0, RADII.1);
            let slack = cell / 2.0 - radius;
            BallSpec {
                x: ((i % columns) as f64 + 0.5) * cell + random.range(-slack, slack),
                y: ((i / columns) as f64 + 0.5) * cell + random.range(-slack, slack),
                vx: random.range(-MAX_SPEED, MAX_SPEED),
                vy: random.range(-MAX_SPEED, MAX_SPEED),
                radius,
                colour: COLOURS[i % COLOURS.len()],
                trail_colour: TRAIL_COLOURS[i % TRAIL_COLOURS.len()],
                trail: TRAIL,
            }
        })
        .collect();
    Scene {
        balls,
        walls: Some(1.0),
        ball_collisions: collisions.then_some(1.0),
        frames: FRAMES,
        ..Scene::empty(WIDTH, HEIGHT)
    }
}

fn main() -> std::io::Result<()> {
    let collisions = std::env::args().any(|a| a == "--collisions");
    let scene = scene(collisions);
    scene.validate().map_err(std::io::Error::other)?;
    let renderer = Renderer::new(&scene).map_err(std::io::Error::other)?;
    let path = std::env::temp_dir().join("bouncing_ball_scale.gif");

    let started = Instant::now();
    let out = BufWriter::new(File::create(&path)?);
    let mut gif = GifWriter::new(
        out,
        WIDTH as u16,
        HEIGHT as u16,
        renderer.palette(),
        scene.frame_ms,
    )?;
    let mut simulation = scene.simulation();
    let mut frame = renderer.new_frame();
    let (mut physics, mut raster) = (Duration::ZERO, Duration::ZERO);
    for _ in 0..scene.frames {
        let t = Instant::now();
        simulation.step();
        physics += t.elapsed();
        let t = Instant::now();
        renderer.draw(simulation.balls(), &mut frame);
        raster += t.elapsed();
        gif.write_frame(&frame)?;
    }
    gif.flush()?;
    let encoder = gif.timings();
    let t = Instant::now();
    gif.finish()?.flush()?;
    let write = encoder.write + t.elapsed();
    let total = started.elapsed();

    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    println!(
        "{WIDTH}x{HEIGHT}, {BALLS} balls, {FRAMES} frames, trail {TRAIL}, {}; {cores} cores",
        if collisions {
            "elastic ball-ball collisions (billiards)"
        } else {
            "no ball-ball collisions"
        }
    );
    println!(
        "{:.1} frames/s ({:.2} s in all); GIF {} bytes at {}\n",
        f64::from(FRAMES) / total.as_secs_f64(),
        total.as_secs_f64(),
        std::fs::metadata(&path)?.len(),
        path.display()
    );
    println!("| stage                        | total (ms) | per frame (ms) | share |");
    println!("|------------------------------|-----------:|---------------:|------:|");
    let rest = total.saturating_sub(physics + raster + encoder.changes + encoder.lzw + write);
    for (stage, time) in [
        ("physics (Simulation::step)", physics),
        ("raster (Renderer::draw)", raster),
        ("changed rectangle + copy", encoder.changes),
        ("LZW (not hidden by threads)", encoder.lzw),
        ("write (to the file)", write),
        ("everything else", rest),
    ] {
        println!(
            "| {stage:<28} | {:>10.1} | {:>14.3} | {:>4.0}% |",
            time.as_secs_f64() * 1000.0,
            time.as_secs_f64() * 1000.0 / f64::from(FRAMES),
            100.0 * time.as_secs_f64() / total.as_secs_f64()
        );
    }
    Ok(())
}
