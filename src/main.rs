//! The command line. The constants below are the default scene: edit one, run
//! `cargo run --release`, and watch what changes. Each is also a flag (`--help`).

use std::process::ExitCode;

use bouncing_ball::cli::Cli;
use bouncing_ball::physics::Vec2;
use bouncing_ball::scene::TrailFade;
use bouncing_ball::{BallSpec, Scene};

// --- Canvas ---
/// Canvas width, px.
const WIDTH: u32 = 320;
/// Canvas height, px.
const HEIGHT: u32 = 240;

// --- Ball ---
/// Ball radius, px.
const RADIUS: f64 = 12.0;
/// Where the ball starts (x, y), px from the top-left corner.
const START: (f64, f64) = (40.0, 40.0);
/// The ball's starting velocity (vx, vy), px/frame; y grows downwards.
const INITIAL_VEL: (f64, f64) = (5.2, 0.0);

// --- Physics ---
/// Added to the downward velocity every frame, px/frame².
const GRAVITY: f64 = 0.5;
/// Share of speed a bounce keeps: 1.0 is elastic, 0.0 stops dead.
const BOUNCE_DAMPING: f64 = 0.88;

// --- Animation ---
/// How many past positions the trail shows, points.
const TRAIL_LEN: usize = 20;
/// How trail dots darken into the past: `Linear` (share (i+1)/n of the colour), `None`, or
/// `Power(p)` (that share to the power p).
const TRAIL_FADE: TrailFade = TrailFade::Linear;
/// Whether trail dots shrink into the past along with their fade.
const TRAIL_SHRINK: bool = true;
/// How many frames to simulate, frames.
const FRAMES: u32 = 200;
/// How long each frame shows, ms (GIF counts hundredths, so a multiple of 10).
const FRAME_MS: u32 = 30;

// --- Colours (red, green, blue) ---
/// Canvas colour.
const BACKGROUND: [u8; 3] = [0, 0, 0];
/// Ball colour.
const BALL_COLOUR: [u8; 3] = [255, 200, 60];
/// Trail colour at full brightness; older dots fade towards black.
const TRAIL_COLOUR: [u8; 3] = [60, 140, 255];

// The ball moves in `Ball::step` (src/physics/ball.rs), the lesson's whole loop, and is drawn
// by `Renderer::draw` (src/render/raster.rs): the trail first, then the ball on top.

/// The lesson's scene, from the constants at the top of this file.
fn lesson_scene() -> Scene {
    Scene {
        background: BACKGROUND,
        balls: vec![BallSpec {
            x: START.0,
            y: START.1,
            vx: INITIAL_VEL.0,
            vy: INITIAL_VEL.1,
            radius: RADIUS,
            colour: BALL_COLOUR,
            trail_colour: TRAIL_COLOUR,
            trail: TRAIL_LEN,
        }],
        gravity: Some(Vec2::new(0.0, GRAVITY)),
        walls: Some(BOUNCE_DAMPING),
        frames: FRAMES,
        frame_ms: FRAME_MS,
        trail_fade: TRAIL_FADE,
        trail_shrink: TRAIL_SHRINK,
        ..Scene::empty(WIDTH, HEIGHT)
    }
}

/// Parses the command line, runs what it asks for, and turns a failure into its one line
/// and exit code.
fn main() -> ExitCode {
    match Cli::parse(lesson_scene()).and_then(Cli::execute) {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => failure.report(),
    }
}
