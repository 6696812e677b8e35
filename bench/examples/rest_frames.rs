//! What a frame costs once the pile has come to rest, against a frame of balls falling: a
//! pile of 10,000 balls (radius 4 px, trail 4) dropped on a 1280×720 canvas, its frames drawn
//! on a canvas that draws again only what changed and encoded into a GIF in memory.
//!
//! Three phases, each timed per frame, the physics apart from the drawing and encoding:
//!
//! - **falling**: the first frames, every ball moving;
//! - **settling**: frames run until every ball sleeps (at most a few thousand), untimed;
//! - **at rest**: frames after that, the whole pipeline run as in the program: the physics of
//!   a sleeping pile, and frames that did not change.
//!
//! Drawing and encoding are timed on the caller's thread (drawing, finding the changed
//! rectangles, queueing); the compression on the encoding thread is timed apart, flushed at
//! the end of each phase. Run: `cargo run --release -p bouncing_ball_bench --example
//! rest_frames` (about two minutes); with `-- --whole`, every frame is drawn whole and
//! compared whole instead, as a run did before frames were drawn again only where they
//! changed.

use std::time::{Duration, Instant};

use bouncing_ball::gif::GifWriter;
use bouncing_ball::render::{Canvas, Damage, Renderer};
use bouncing_ball::scene::file as scene_file;

/// Balls in the scene below.
const COUNT: usize = 10_000;

/// The pile preset on a bigger canvas, with more and smaller balls.
const SCENE: &str = r#"
width = 1280
height = 720
background = [0, 0, 0]
frames = 1
frame_ms = 30
gravity = [0.0, 0.5]
walls = { damping = 0.5 }
ball_collisions = { restitution = 0.5 }
iterations = 12

[spawn]
count = 10000
radius = 4.0
max_speed = 4.0
trail = 4
colours = [[255, 200, 60], [255, 90, 90], [120, 230, 120], [200, 120, 255]]
trail_colours = [[60, 140, 255], [255, 150, 60], [60, 200, 200], [230, 90, 200]]
"#;

/// Frames of each timed phase, and the most frames to wait for the pile to sleep.
const PHASE_FRAMES: u32 = 100;
const PATIENCE: u32 = 5_000;

/// One phase's time, summed over its frames, and how its frames were drawn.
#[derive(Default)]
struct Phase {
    physics: Duration,
    draw: Duration,
    queue: Duration,
    compress: Duration,
    /// Frames unchanged, drawn again in areas, drawn whole.
    kinds: [u32; 3],
    /// Drawing and queueing the unchanged frames alone.
    unchanged: Duration,
}

fn main() -> std::io::Result<()> {
    let whole = std::env::args().any(|a| a == "--whole");
    let scene = scene_file::parse("rest_frames", SCENE, 1).map_err(std::io::Error::other)?;
    let renderer = Renderer::new(&scene).map_err(std::io::Error::other)?;
    let mut canvas = Canvas::new(&renderer);
    let mut frame = renderer.new_frame();
    let mut gif = GifWriter::new(Vec::new(), 1280, 720, renderer.palette(), 30)?;
    let mut simulation = scene.simulation();
    let mut phases: Vec<(&str, Phase)> = Vec::new();
    let mut settled = 0;
    // Each phase, and whether it runs until every ball sleeps rather than for its frames.
    for (name, until_asleep) in [("falling", false), ("(settling)", true), ("at rest", false)] {
        let mut phase = Phase::default();
        let lzw_before = gif.timings().lzw;
        let mut frames = 0;
        loop {
            let done = if until_asleep {
                simulation.sleeping_balls() == COUNT || frames == PATIENCE
            } else {
                frames == PHASE_FRAMES
            };
            if done {
                break;
            }
            frames += 1;
            let t = Instant::now();
            simulation.step();
            phase.physics += t.elapsed();
            let started = Instant::now();
            let balls = simulation.balls();
            let (t, kind) = if whole {
                let t = Instant::now();
                renderer.draw(balls, &mut frame);
                phase.draw += t.elapsed();
                let t = Instant::now();
                gif.write_frame(&frame)?;
                (t, 2)
            } else {
                let t = Instant::now();
                canvas.redraw(&renderer, balls);
                phase.draw += t.elapsed();
                let t = Instant::now();
                gif.write_changes(canvas.frame(), canvas.damage())?;
                (t, kind(canvas.damage()))
            };
            phase.queue += t.elapsed();
            phase.kinds[kind] += 1;
            if kind == 0 {
                phase.unchanged += started.elapsed();
            }
        }
        gif.flush()?;
        phase.compress = gif.timings().lzw - lzw_before;
        if until_asleep {
            settled = PHASE_FRAMES + frames;
        }
        phases.push((name, phase));
    }
    let asleep = simulation.sleeping_balls();
    println!("{asleep} of {COUNT} balls asleep from frame {settled}");
    print_table(&phases, whole);
    Ok(())
}

/// Where a frame's kind is counted: unchanged, drawn again in areas, drawn whole.
fn kind(damage: Damage) -> usize {
    match damage {
        Damage::Unchanged => 0,
        Damage::Areas(_) => 1,
        Damage::Whole => 2,
    }
}

fn print_table(phases: &[(&str, Phase)], whole: bool) {
    let ms = |d: Duration| d.as_secs_f64() * 1e3 / f64::from(PHASE_FRAMES);
    let how = if whole {
        "every frame drawn whole and compared whole"
    } else {
        "drawn again only where changed"
    };
    println!("10,000 balls on 1280x720, {how}; per frame (ms), {PHASE_FRAMES} frames a phase");
    println!("| phase | physics | draw | find changes + queue | compress (encoding thread) | drawing + encoding | frames unchanged / in areas / whole |");
    println!("|---|---:|---:|---:|---:|---:|---|");
    for (name, p) in phases.iter().filter(|(name, _)| !name.starts_with('(')) {
        let render = ms(p.draw) + ms(p.queue) + ms(p.compress);
        println!(
            "| {name} | {:.3} | {:.3} | {:.3} | {:.3} | {render:.3} | {} / {} / {} |",
            ms(p.physics),
            ms(p.draw),
            ms(p.queue),
            ms(p.compress),
            p.kinds[0],
            p.kinds[1],
            p.kinds[2]
        );
    }
    let phase = |name: &str| &phases.iter().find(|(n, _)| *n == name).expect("a phase").1;
    let render = |p: &Phase| ms(p.draw) + ms(p.queue) + ms(p.compress);
    let (falling, rest) = (phase("falling"), phase("at rest"));
    println!(
        "\na whole frame at rest (physics, drawing, encoding): {:.2} % of a falling frame's",
        100.0 * (ms(rest.physics) + render(rest)) / (ms(falling.physics) + render(falling))
    );
    println!(
        "drawing + encoding at rest: {:.2} % of a falling frame's",
        100.0 * render(rest) / render(falling)
    );
    if rest.kinds[0] > 0 {
        let each = rest.unchanged.as_secs_f64() * 1e3 / f64::from(rest.kinds[0]);
        println!("an unchanged frame at rest: {each:.4} ms to draw and queue");
    }
}
