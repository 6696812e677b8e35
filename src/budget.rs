//! The resource budget, decided before the first frame: how much memory a scene will need
//! and how long each frame will take, worked out from the scene alone.
//!
//! Memory is refused beyond a budget (2 GiB unless raised with `--memory-budget`); time and
//! GIF size only draw a warning, since a long run is sometimes what is wanted. The figures
//! are estimates: memory errs on the high side (it counts the largest each buffer can grow
//! to), time and GIF size are rough (within a few times, measured on a 2-core VM; see
//! docs/robustness.md).

use std::collections::HashMap;
use std::fmt;
use std::mem::size_of;

use crate::gif::encoder::queue_frames;
use crate::physics::maths;
use crate::physics::{Ball, Trail};
use crate::scene::{BallSpec, Rgb, Scene};

/// The memory a run may be predicted to need unless told otherwise, bytes (2 GiB).
pub const DEFAULT_MEMORY_BUDGET: u64 = 2 << 30;
/// A run predicted to take longer than this draws a warning, seconds.
pub const WARN_SECONDS: f64 = 60.0;
/// A GIF predicted to be bigger than this draws a warning, bytes (1 GB).
pub const WARN_GIF_BYTES: f64 = 1e9;
/// Browsers show a GIF frame delay under this as 100 ms, ms.
pub const WARN_FRAME_MS: u32 = 20;

/// What the program itself takes before any scene: code, stacks, the threads' arenas.
const BASE_BYTES: u64 = 8 << 20;
/// Bytes per pixel of frame buffers outside the GIF queue: the frame being drawn, the frame
/// the GIF shows, and at the end the RGB copy and the PNG being compressed.
const FRAME_BYTES_PER_PIXEL: u64 = 6;
/// Bytes per queued GIF pixel: the cropped indices and their LZW codes (12-bit codes on
/// 8-bit pixels are at most 1.5 bytes each).
const QUEUED_BYTES_PER_PIXEL: f64 = 2.5;
/// Bytes per ball for the broad phase: a 32-byte entry, its cell and up to 12 cell bounds.
const GRID_BYTES_PER_BALL: u64 = 32 + 8 + 12 * 8;
/// The palette indices one ball is drawn with (a colour and a shared table of shades).
const STYLE_BYTES_PER_BALL: u64 = 24;

// Rough costs on the reference machine, ns, for the time prediction.
const NS_PER_BALL_STEP: f64 = 30.0;
const NS_PER_FLOOR_TEST: f64 = 10.0;
const NS_PER_GRID_BALL: f64 = 80.0;
const NS_PER_PAIR_TEST: f64 = 10.0;
const NS_PER_DOT: f64 = 80.0;
const NS_PER_DRAWN_PIXEL: f64 = 2.0;
const NS_PER_CANVAS_PIXEL: f64 = 2.0;
/// Once per run, per canvas pixel: the first (whole) frame and the PNG.
const NS_PER_CANVAS_PIXEL_ONCE: f64 = 20.0;
const NS_PER_CHANGED_PIXEL: f64 = 8.0;
/// LZW bytes per changed pixel of a typical frame (mostly flat background).
const GIF_BYTES_PER_CHANGED_PIXEL: f64 = 0.25;

/// A scene's predicted cost.
#[derive(Clone, Debug, PartialEq)]
pub struct Estimate {
    /// Peak memory, bytes (on the high side).
    pub memory: u64,
    /// Time per frame, ns (rough).
    pub frame_ns: f64,
    /// The whole run, seconds (rough).
    pub seconds: f64,
    /// The GIF's size, bytes (rough).
    pub gif_bytes: f64,
    /// The part that dominates the memory, for the message.
    pub biggest: &'static str,
}

/// A scene predicted to need more memory than the budget.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("the scene needs about {} of memory (mostly {biggest}), over the budget of {}; raise it with --memory-budget <MB> (e.g. --memory-budget {}) or use fewer or smaller balls, trails or frames", megabytes(*needed), megabytes(*budget), needed.div_ceil(1 << 20))]
pub struct OverBudget {
    pub needed: u64,
    pub budget: u64,
    pub biggest: &'static str,
}

fn megabytes(bytes: u64) -> String {
    format!("{} MB", bytes.div_ceil(1 << 20))
}

/// The renderer's shade tables: one per trail colour, as long as its longest trail needs.
fn shade_table_bytes(balls: &[BallSpec]) -> u64 {
    let mut longest: HashMap<Rgb, u64> = HashMap::new();
    for ball in balls {
        let len = longest.entry(ball.trail_colour).or_default();
        *len = (*len).max(ball.trail as u64);
    }
    longest.values().map(|&n| n * (n + 1) / 2).sum()
}

impl Estimate {
    /// Works out the cost of a validated `scene`.
    pub fn of(scene: &Scene) -> Estimate {
        let n = scene.balls.len() as f64;
        let pixels = u64::from(scene.width) * u64::from(scene.height);
        let canvas = pixels as f64;

        // Memory.
        let per_ball = (size_of::<BallSpec>() + size_of::<Ball>()) as u64 + STYLE_BYTES_PER_BALL;
        let grid = if scene.ball_collisions.is_some() {
            GRID_BYTES_PER_BALL
        } else {
            0
        };
        let balls = scene
            .balls
            .iter()
            .map(|b| per_ball + grid + Trail::heap_bytes(b.trail));
        let balls: u64 = balls.sum();
        let shades = shade_table_bytes(&scene.balls);
        let queued = queue_frames(scene.width, scene.height) as f64 * canvas;
        let frames = pixels * FRAME_BYTES_PER_PIXEL + (queued * QUEUED_BYTES_PER_PIXEL) as u64;
        let parts = [
            (balls, "the balls and their trails"),
            (shades, "the trails' shades"),
            (frames, "the frame buffers"),
        ];
        let biggest = parts.iter().max_by_key(|p| p.0).map_or("", |p| p.1);
        let memory = BASE_BYTES + balls + shades + frames;

        // Time per frame: physics, contacts, drawing, encoding.
        let steps = f64::from(scene.motion.substeps);
        let floors = scene.floors.len() as f64;
        let physics = n * steps * (NS_PER_BALL_STEP + floors * NS_PER_FLOOR_TEST);
        let largest = scene.balls.iter().map(|b| b.radius).fold(0.0, f64::max);
        // Balls within reach of one ball if spread evenly over the canvas.
        let neighbours = (n * std::f64::consts::PI * (2.0 * largest).powi(2) / canvas).min(n);
        let contacts = match scene.ball_collisions {
            Some(_) => n * steps * (NS_PER_GRID_BALL + 2.0 * neighbours * NS_PER_PAIR_TEST),
            None => 0.0,
        };
        let mut dots = 0.0;
        let mut drawn = 0.0;
        let mut moving = 0.0;
        for ball in &scene.balls {
            let area = (std::f64::consts::PI * ball.radius * ball.radius).min(canvas);
            let trail = ball.trail as f64;
            dots += 1.0 + trail;
            // Trail dots shrink with age: on average a third of the ball's area.
            drawn += area * (1.0 + trail / 3.0);
            let speed = maths::hypot(ball.vx, ball.vy).min(canvas);
            moving += (2.0 * ball.radius + 2.0 + speed).powi(2) * 4.0;
        }
        let changed = moving.min(canvas);
        let draw = dots * NS_PER_DOT + drawn * NS_PER_DRAWN_PIXEL;
        let encode = canvas * NS_PER_CANVAS_PIXEL + changed * NS_PER_CHANGED_PIXEL;
        let frame_ns = physics + contacts + draw + encode;
        let frames = f64::from(scene.frames);
        Estimate {
            memory,
            frame_ns,
            seconds: (frame_ns * frames + canvas * NS_PER_CANVAS_PIXEL_ONCE) * 1e-9,
            gif_bytes: canvas + changed * GIF_BYTES_PER_CHANGED_PIXEL * frames,
            biggest,
        }
    }

    /// Refuses a scene predicted to need more than `budget` bytes.
    pub fn check(&self, budget: u64) -> Result<(), OverBudget> {
        if self.memory > budget {
            return Err(OverBudget {
                needed: self.memory,
                budget,
                biggest: self.biggest,
            });
        }
        Ok(())
    }

    /// What about `scene` works but may surprise, one line each.
    pub fn warnings(&self, scene: &Scene) -> Vec<String> {
        let mut warnings = Vec::new();
        if scene.frame_ms < WARN_FRAME_MS {
            warnings.push(format!(
                "--frame-ms {}: browsers show frames shorter than {WARN_FRAME_MS} ms for 100 ms",
                scene.frame_ms
            ));
        }
        if scene.balls.is_empty() {
            warnings.push("the scene has no balls: the animation will be empty".to_string());
        }
        if self.seconds > WARN_SECONDS {
            warnings.push(format!(
                "this run looks to take about {} (Ctrl-C stops it and writes nothing)",
                Duration(self.seconds)
            ));
        }
        if self.gif_bytes > WARN_GIF_BYTES {
            warnings.push(format!(
                "the GIF looks to be about {:.1} GB",
                self.gif_bytes / 1e9
            ));
        }
        warnings
    }
}

/// Seconds as a person reads them.
struct Duration(f64);

impl fmt::Display for Duration {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = self.0;
        if s < 120.0 {
            write!(f, "{s:.0} s")
        } else if s < 7200.0 {
            write!(f, "{:.0} minutes", s / 60.0)
        } else {
            write!(f, "{:.0} hours", s / 3600.0)
        }
    }
}
