//! Our side of `tools/scipy_anchors.py`, which sets our methods beside SciPy's `solve_ivp` on
//! the lesson's ball with drag: from (40, 40) at (5.2, 0) px/frame, in the lesson's box
//! (320 × 240, radius 12, gravity 0.5 px/frame²), with the given drag and wall damping. The
//! script measures every method, ours and SciPy's, against one closed-form reference with one
//! error function, so both sides are held to the same measure.
//!
//! `cargo run --release --example anchors -- path DRAG DAMPING FRAMES METHOD...` prints
//! `METHOD FRAME X Y` after every frame, to the last bit (Rust's shortest round-trip form).
//! `cargo run --release --example anchors -- time DRAG DAMPING FRAMES RUNS METHOD...` prints
//! `METHOD NS_PER_RUN`: RUNS whole runs of FRAMES frames timed together, the simulation alone.
//! A method is written `INTEGRATOR:SUBSTEPS:COLLISIONS`, e.g. `rk4:4:exact`.

use std::error::Error;
use std::hint::black_box;
use std::time::Instant;

use bouncing_ball::physics::{Ball, CollisionMode, Effects, Integrator, Motion};
use bouncing_ball::scene::Named;
use bouncing_ball_lab::accuracy::{lesson_effects, RADIUS};

const USAGE: &str = "usage: anchors path DRAG DAMPING FRAMES METHOD... | \
                     anchors time DRAG DAMPING FRAMES RUNS METHOD...";

/// `INTEGRATOR:SUBSTEPS:COLLISIONS` as a [`Motion`].
fn parse_method(text: &str) -> Result<Motion, String> {
    let bad = || format!("method {text:?}: expected INTEGRATOR:SUBSTEPS:COLLISIONS");
    let [integrator, substeps, collisions] = text.split(':').collect::<Vec<_>>()[..] else {
        return Err(bad());
    };
    Ok(Motion {
        integrator: Integrator::from_name(integrator).ok_or_else(bad)?,
        substeps: substeps.parse().ok().filter(|&n| n >= 1).ok_or_else(bad)?,
        collisions: CollisionMode::from_name(collisions).ok_or_else(bad)?,
        ..Motion::default()
    })
}

/// Runs the lesson's ball for `frames` frames, handing it to `each` after every frame.
fn fly(motion: Motion, effects: &Effects, frames: u32, mut each: impl FnMut(u32, &Ball)) -> Ball {
    let mut ball = Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0);
    for frame in 1..=frames {
        motion.advance(&mut ball, effects);
        each(frame, &ball);
    }
    ball
}

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (mode, numbers) = match args.as_slice() {
        [mode, rest @ ..] if mode == "path" && rest.len() >= 3 => (mode, &rest[..3]),
        [mode, rest @ ..] if mode == "time" && rest.len() >= 4 => (mode, &rest[..4]),
        _ => return Err(USAGE.into()),
    };
    let drag: f64 = numbers[0].parse()?;
    let damping: f64 = numbers[1].parse()?;
    let frames: u32 = numbers[2].parse()?;
    let effects = Effects {
        drag: Some(drag),
        ..lesson_effects(damping)
    };
    for name in &args[1 + numbers.len()..] {
        let motion = parse_method(name)?;
        if mode == "path" {
            fly(motion, &effects, frames, |frame, ball| {
                println!("{name} {frame} {} {}", ball.x, ball.y);
            });
        } else {
            let runs: u32 = numbers[3].parse()?;
            let started = Instant::now();
            for _ in 0..runs {
                black_box(fly(motion, black_box(&effects), frames, |_, _| {}));
            }
            let ns = started.elapsed().as_nanos() as f64 / f64::from(runs.max(1));
            println!("{name} {ns}");
        }
    }
    Ok(())
}
