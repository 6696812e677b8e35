//! The command line. The constants below are the default scene: edit one, run
//! `cargo run --release`, and watch what changes. Each is also a flag (`--help`).

use std::path::PathBuf;
use std::process::ExitCode;

use bouncing_ball::{run, BallSpec, Outputs, RunError, Scene};
use clap::Parser;

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

/// Simulates a bouncing ball and writes an animated GIF and a still PNG of its last frame.
#[derive(Parser, Debug)]
#[command(version, about, allow_negative_numbers = true)]
struct Args {
    /// Canvas width, px
    #[arg(long, default_value_t = WIDTH)]
    width: u32,
    /// Canvas height, px
    #[arg(long, default_value_t = HEIGHT)]
    height: u32,
    /// Ball radius, px
    #[arg(long, default_value_t = RADIUS)]
    radius: f64,
    /// Start position x, px
    #[arg(long, default_value_t = START.0)]
    x: f64,
    /// Start position y, px (y grows downwards)
    #[arg(long, default_value_t = START.1)]
    y: f64,
    /// Start velocity x, px/frame
    #[arg(long, default_value_t = INITIAL_VEL.0)]
    vx: f64,
    /// Start velocity y, px/frame
    #[arg(long, default_value_t = INITIAL_VEL.1)]
    vy: f64,
    /// Gravity, px/frame² (downwards; negative pulls up)
    #[arg(long, default_value_t = GRAVITY)]
    gravity: f64,
    /// Share of speed kept at each bounce, 0 to 1
    #[arg(long, default_value_t = BOUNCE_DAMPING)]
    damping: f64,
    /// Trail length, points (0: no trail)
    #[arg(long, default_value_t = TRAIL_LEN)]
    trail: usize,
    /// Frames to simulate
    #[arg(long, default_value_t = FRAMES)]
    frames: u32,
    /// Time each frame shows, ms (a multiple of 10)
    #[arg(long, default_value_t = FRAME_MS)]
    frame_ms: u32,
    /// Where to write the animated GIF
    #[arg(long, default_value = "bouncing_ball.gif")]
    gif: PathBuf,
    /// Where to write the still PNG (the last frame)
    #[arg(long, default_value = "bouncing_ball.png")]
    png: PathBuf,
    /// Also write every frame's state as CSV (frame,ball,x,y,vx,vy)
    #[arg(long)]
    trace: Option<PathBuf>,
    /// Print nothing on success
    #[arg(long)]
    quiet: bool,
}

impl Args {
    fn scene(&self) -> Scene {
        Scene {
            width: self.width,
            height: self.height,
            background: BACKGROUND,
            balls: vec![BallSpec {
                x: self.x,
                y: self.y,
                vx: self.vx,
                vy: self.vy,
                radius: self.radius,
                colour: BALL_COLOUR,
                trail_colour: TRAIL_COLOUR,
                trail: self.trail,
            }],
            gravity: [0.0, self.gravity],
            damping: self.damping,
            frames: self.frames,
            frame_ms: self.frame_ms,
        }
    }
}

/// The flag a scene key came from: `balls[0].frame_ms` → `--frame-ms`.
fn flag(key: &str) -> String {
    let name = key.rsplit('.').next().unwrap_or(key);
    format!("--{}", name.replace('_', "-"))
}

fn main() -> ExitCode {
    let args = Args::parse();
    let outputs = Outputs {
        gif: args.gif.clone(),
        png: args.png.clone(),
        trace: args.trace.clone(),
    };
    match run(&args.scene(), &outputs) {
        Ok(summary) => {
            if !args.quiet {
                println!(
                    "wrote {} ({} frames, {} bytes) and {} ({} bytes) in {:.1} ms",
                    outputs.gif.display(),
                    summary.frames,
                    summary.gif_bytes,
                    outputs.png.display(),
                    summary.png_bytes,
                    summary.elapsed.as_secs_f64() * 1000.0
                );
            }
            ExitCode::SUCCESS
        }
        Err(error) => {
            match &error {
                RunError::Invalid(bad) => eprintln!(
                    "error: {} {} is not allowed: {}",
                    flag(&bad.key),
                    bad.value,
                    bad.allowed
                ),
                other => eprintln!("error: {other}"),
            }
            ExitCode::from(error.exit_code())
        }
    }
}
