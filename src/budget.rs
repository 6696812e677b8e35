//! The resource budget, decided before the first frame: how much memory a scene will need
//! and how long each frame will take, worked out from the scene alone.
//!
//! A run predicted beyond its budget is refused before it starts, naming the knob that raises
//! it: memory (2 GiB unless `--memory-budget`), time (an hour unless `--time-budget`) and the
//! GIF's size (4 GiB unless `--gif-budget`). Below the budget, a run predicted to take over
//! 5 seconds or write over 1 GB draws a warning. Memory errs on the high side (it counts the
//! largest each buffer can grow to); time and GIF size come from a pilot run of the physics
//! and costs fitted to measured runs (within 3 times on the presets and long runs; see
//! `cargo run --release --example budget` and docs/robustness.md).

use std::collections::HashMap;
use std::fmt;
use std::mem::size_of;

use crate::gif::encoder::queue_frames;
use crate::physics::{Ball, Simulation, Trail, Vec2};
use crate::render::Canvas;
use crate::scene::{BallSpec, Rgb, Scene};

/// The memory a run may be predicted to need unless told otherwise, bytes (2 GiB).
pub const DEFAULT_MEMORY_BUDGET: u64 = 2 << 30;
/// The time a run may be predicted to take unless told otherwise, seconds (an hour).
pub const DEFAULT_TIME_BUDGET: f64 = 3600.0;
/// The GIF size a run may be predicted to write unless told otherwise, bytes (4 GiB).
pub const DEFAULT_GIF_BUDGET: u64 = 4 << 30;
/// A run predicted to take longer than this draws a warning with its time and GIF size,
/// seconds.
pub const WARN_SECONDS: f64 = 5.0;
/// A GIF predicted to be bigger than this draws a warning, bytes (1 GB).
pub const WARN_GIF_BYTES: f64 = 1e9;
/// Browsers show a GIF frame delay under this as 100 ms, ms.
pub const WARN_FRAME_MS: u32 = 20;

/// What the program itself takes before any scene: code, stacks, the threads' arenas and
/// their LZW coders (measured: 10 to 17 MB peak for the small presets).
const BASE_BYTES: u64 = 20 << 20;
/// Bytes per pixel of frame buffers outside the GIF queue: the frame being drawn, the
/// background it is cleared to, the frame the GIF shows, and at the end the RGB copy and the
/// PNG being compressed.
const FRAME_BYTES_PER_PIXEL: u64 = 7;
/// Bytes per queued GIF pixel: the cropped indices and their LZW codes (12-bit codes on
/// 8-bit pixels are at most 1.5 bytes each).
const QUEUED_BYTES_PER_PIXEL: f64 = 2.5;
/// Bytes per ball for the broad phase: a 32-byte entry, its cell and up to 12 cell bounds.
const GRID_BYTES_PER_BALL: u64 = 32 + 8 + 12 * 8;
/// Bytes per ball for ball-ball contacts: up to `MAX_PAIRS_PER_BALL` contacts with their
/// warm-start memory and the solver's scratch (measured: 3.3 KB a ball on 20,000 balls piled
/// on one spot, where every ball has its most).
const CONTACT_BYTES_PER_BALL: u64 = 3500;
/// The palette indices one ball is drawn with (a colour and a shared table of shades).
const STYLE_BYTES_PER_BALL: u64 = 24;

// Costs on the reference machine (the 2-core VM docs/robustness.md names), fitted to whole
// runs of the presets, long runs and crowds (`cargo run --release --example budget`), ns.
/// Per canvas pixel per frame: clearing the frame and comparing it with the last one.
const NS_PER_CANVAS_PIXEL: f64 = 0.05;
/// Per ball per step, and per ball per step with ball-ball collisions (grid, contacts).
const NS_PER_BALL_STEP: f64 = 30.0;
const NS_PER_COLLIDING_BALL_STEP: f64 = 400.0;
/// Per floor per ball per step.
const NS_PER_FLOOR_TEST: f64 = 10.0;
/// Per ball or trail dot drawn, and per pixel of them (a frame that changed draws every ball).
const NS_PER_DOT: f64 = 15.0;
const NS_PER_DRAWN_PIXEL: f64 = 1.0;
/// Per ball per frame in which nothing changed: its trail recorded, the frame found unchanged
/// (a sleeping pile's frames, fitted to `--preset pile -n 200000`).
const NS_PER_QUIET_BALL: f64 = 15.0;
/// Per pixel of a frame's changed rectangle (cut out and coded, in several ways), and per
/// pixel that changed in it (what the codes have to spell out).
const NS_PER_RECT_PIXEL: f64 = 3.6;
const NS_PER_CHANGED_PIXEL: f64 = 10.0;
/// Per frame that changed: its rectangle found, its codings chosen, written.
const NS_PER_CHANGED_FRAME: f64 = 2_000.0;
/// Once per run: starting the process, the first whole frame, the PNG, flushing files.
const NS_PER_RUN: f64 = 5e6;
const NS_PER_CANVAS_PIXEL_ONCE: f64 = 20.0;
/// GIF bytes: the first frame per canvas pixel (mostly one colour) and per pixel of its balls
/// (as changed pixels: a still pyramid is nearly all first frame), then per pixel of a
/// changed rectangle (mostly background, which LZW packs well), per pixel that changed (the
/// edges of moving balls and dots cost the bytes), and per changed frame.
const GIF_BYTES_PER_CANVAS_PIXEL: f64 = 0.002;
const GIF_BYTES_PER_RECT_PIXEL: f64 = 0.0005;
const GIF_BYTES_PER_CHANGED_PIXEL: f64 = 0.19;
const GIF_BYTES_PER_CHANGED_FRAME: f64 = 30.0;
/// The pilot run of the physics stops after this many ball-steps (about 0.1 s), or a fifth of
/// that with ball-ball collisions (each step costs more); the rest of the run is taken to go
/// on as the pilot's last quarter went.
const PILOT_BALL_STEPS: f64 = 4e6;
/// The pilot never runs longer than this many frames: scenes that come to rest do so sooner.
const PILOT_FRAMES: u32 = 100_000;

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

/// What a run may be predicted to need before it is refused, not started.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget {
    /// Memory, bytes (`--memory-budget`, MB).
    pub memory: u64,
    /// Time, seconds (`--time-budget`).
    pub seconds: f64,
    /// The GIF's size on disk, bytes (`--gif-budget`, MB).
    pub gif_bytes: u64,
}

impl Default for Budget {
    fn default() -> Budget {
        Budget {
            memory: DEFAULT_MEMORY_BUDGET,
            seconds: DEFAULT_TIME_BUDGET,
            gif_bytes: DEFAULT_GIF_BUDGET,
        }
    }
}

/// A scene predicted to need more than the budget allows, each with the knob that raises it.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum OverBudget {
    #[error("the scene needs about {} of memory (mostly {biggest}), over the budget of {}; raise it with --memory-budget <MB> (e.g. --memory-budget {}) or use fewer or smaller balls, trails or frames", megabytes(*needed), megabytes(*budget), needed.div_ceil(1 << 20))]
    Memory {
        needed: u64,
        budget: u64,
        biggest: &'static str,
    },
    #[error("this run looks to take about {}, over the time budget of {}; raise it with --time-budget <SECONDS> (e.g. --time-budget {}) or use fewer frames or balls", Duration(*needed), Duration(*budget), needed.ceil())]
    Time { needed: f64, budget: f64 },
    #[error("the GIF looks to be about {}, over the budget of {}; raise it with --gif-budget <MB> (e.g. --gif-budget {}) or use fewer frames, balls or a smaller canvas", megabytes(*needed), megabytes(*budget), needed.div_ceil(1 << 20))]
    Gif { needed: u64, budget: u64 },
}

fn megabytes(bytes: u64) -> String {
    format!("{} MB", bytes.div_ceil(1 << 20))
}

/// The memory `scene` needs at most, bytes, and the part that dominates it, for the message.
fn memory_of(scene: &Scene) -> (u64, &'static str) {
    let pixels = u64::from(scene.width) * u64::from(scene.height);
    let per_ball = (size_of::<BallSpec>() + size_of::<Ball>()) as u64 + STYLE_BYTES_PER_BALL;
    let contacts = match scene.ball_collisions {
        Some(_) => GRID_BYTES_PER_BALL + CONTACT_BYTES_PER_BALL,
        None => 0,
    };
    let balls = scene.balls.iter().map(|b| {
        per_ball + contacts + Trail::heap_bytes(b.trail) + Canvas::bytes_per_ball(b.trail)
    });
    let balls: u64 = balls.sum();
    let shades = shade_table_bytes(&scene.balls);
    let queued = queue_frames(scene.width, scene.height) as f64 * pixels as f64;
    let frames = pixels * FRAME_BYTES_PER_PIXEL + (queued * QUEUED_BYTES_PER_PIXEL) as u64;
    let parts = [
        (balls, "the balls and their trails"),
        (shades, "the trails' shades"),
        (frames, "the frame buffers"),
    ];
    let biggest = parts.iter().max_by_key(|p| p.0).map_or("", |p| p.1);
    (BASE_BYTES + balls + shades + frames, biggest)
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
        let (memory, biggest) = memory_of(scene);
        Estimate::with_memory(scene, memory, biggest, Activity::of(scene))
    }

    /// Works out the cost of a validated `scene` and refuses it if over `budget`. Memory is
    /// checked first, from the scene alone, so a scene too big for it is refused before the
    /// pilot run of its physics allocates anything. The pilot runs only when its answer can
    /// change what happens: if even a run whose every frame changed all over would stay
    /// under the warnings and the budget, that bound is the answer (short runs, where the
    /// pilot would cost as much as the run).
    pub fn within(scene: &Scene, budget: &Budget) -> Result<Estimate, OverBudget> {
        let (memory, biggest) = memory_of(scene);
        if memory > budget.memory {
            return Err(OverBudget::Memory {
                needed: memory,
                budget: budget.memory,
                biggest,
            });
        }
        let bound = Estimate::with_memory(scene, memory, biggest, Activity::at_most(scene));
        if bound.seconds <= WARN_SECONDS.min(budget.seconds)
            && bound.gif_bytes <= WARN_GIF_BYTES.min(budget.gif_bytes as f64)
        {
            return Ok(bound);
        }
        let estimate = Estimate::with_memory(scene, memory, biggest, Activity::of(scene));
        estimate.check_time_and_size(budget)?;
        Ok(estimate)
    }

    /// The cost of `panels` run side by side on one `width` × `height` canvas (a sweep), refused
    /// if over `budget`: every panel's physics and drawing, and one GIF of the whole canvas,
    /// whose changed rectangle spans the panels (taken as the whole canvas in every frame some
    /// panel changes). Memory is checked first, from the scenes alone.
    pub fn of_tiles(
        panels: &[&Scene],
        width: u32,
        height: u32,
        budget: &Budget,
    ) -> Result<Estimate, OverBudget> {
        let frames = panels.iter().map(|s| s.frames).max().unwrap_or(1);
        let canvas = Scene {
            frames,
            ..Scene::empty(width, height)
        };
        let biggest = "the panels' runs and the tiled frames";
        // Each panel: its balls, trails and shades, and the one frame it is drawn into; the
        // program itself, the GIF's queue and the still are the canvas's.
        let panel_memory = |scene: &Scene| {
            let frame = u64::from(scene.width) * u64::from(scene.height);
            let bare = memory_of(&Scene::empty(scene.width, scene.height)).0;
            memory_of(scene).0.saturating_sub(bare) + frame
        };
        let memory = memory_of(&canvas).0 + panels.iter().map(|s| panel_memory(s)).sum::<u64>();
        if memory > budget.memory {
            return Err(OverBudget::Memory {
                needed: memory,
                budget: budget.memory,
                biggest,
            });
        }
        // The panels' own changes, coded as the canvas's.
        let mut activity = Activity::default();
        for scene in panels {
            activity.add(Activity::of(scene));
        }
        activity.changed_frames = activity.changed_frames.min(f64::from(frames));
        // The tiled frame is compared whole every frame; the panels' drawing and stepping are
        // counted with each panel, below.
        (activity.drawn_frames, activity.awake_ball_frames) = (f64::from(frames), 0.0);
        activity.rect_pixels = activity.changed_frames * f64::from(width) * f64::from(height);
        let parts = panels
            .iter()
            .map(|scene| (*scene, Activity::every_frame(scene)));
        let parts: Vec<Estimate> = parts
            .chain([(&canvas, activity)])
            .map(|(scene, activity)| Estimate::with_memory(scene, memory, biggest, activity))
            .collect();
        let estimate = Estimate {
            memory,
            frame_ns: parts.iter().map(|e| e.frame_ns).sum(),
            seconds: parts.iter().map(|e| e.seconds).sum(),
            gif_bytes: parts.iter().map(|e| e.gif_bytes).sum(),
            biggest,
        };
        estimate.check_time_and_size(budget)?;
        Ok(estimate)
    }

    /// The time and GIF size of `scene` when its frames change as `activity` says, beside its
    /// memory.
    fn with_memory(
        scene: &Scene,
        memory: u64,
        biggest: &'static str,
        activity: Activity,
    ) -> Estimate {
        let n = scene.balls.len() as f64;
        let canvas = f64::from(scene.width) * f64::from(scene.height);
        // Time and GIF size: what every frame costs, and what the frames that change cost.
        let steps = f64::from(scene.motion.substeps);
        let per_step = match scene.ball_collisions {
            Some(_) => NS_PER_COLLIDING_BALL_STEP,
            None => NS_PER_BALL_STEP,
        } + scene.floors.len() as f64 * NS_PER_FLOOR_TEST;
        let drawn: f64 = scene.balls.iter().map(|b| drawn_pixels(b, scene)).sum();
        let first_frame_balls: f64 = scene.balls.iter().map(|b| disc_pixels(b, scene)).sum();
        let dots: f64 = scene.balls.iter().map(|b| b.trail.max(1) as f64).sum();
        let frames = f64::from(scene.frames);
        // Every frame records the trails; only frames that changed are drawn and compared,
        // and only awake balls are stepped.
        let every_frame = n * NS_PER_QUIET_BALL;
        let drawing = canvas * NS_PER_CANVAS_PIXEL + dots * NS_PER_DOT + drawn * NS_PER_DRAWN_PIXEL;
        let changing = activity.drawn_frames * drawing
            + activity.awake_ball_frames * steps * per_step
            + activity.rect_pixels * NS_PER_RECT_PIXEL
            + activity.changed_pixels * NS_PER_CHANGED_PIXEL
            + activity.changed_frames * NS_PER_CHANGED_FRAME;
        let once = NS_PER_RUN + canvas * NS_PER_CANVAS_PIXEL_ONCE;
        Estimate {
            memory,
            frame_ns: every_frame + changing / frames,
            seconds: (every_frame * frames + changing + once) * 1e-9,
            gif_bytes: canvas * GIF_BYTES_PER_CANVAS_PIXEL
                + first_frame_balls.min(canvas) * GIF_BYTES_PER_CHANGED_PIXEL
                + activity.rect_pixels * GIF_BYTES_PER_RECT_PIXEL
                + activity.changed_pixels * GIF_BYTES_PER_CHANGED_PIXEL
                + activity.changed_frames * GIF_BYTES_PER_CHANGED_FRAME,
            biggest,
        }
    }

    /// Refuses a scene predicted to take more time or GIF bytes than `budget` allows.
    fn check_time_and_size(&self, budget: &Budget) -> Result<(), OverBudget> {
        if self.seconds > budget.seconds {
            return Err(OverBudget::Time {
                needed: self.seconds,
                budget: budget.seconds,
            });
        }
        if self.gif_bytes > budget.gif_bytes as f64 {
            return Err(OverBudget::Gif {
                needed: self.gif_bytes as u64,
                budget: budget.gif_bytes,
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
        if self.seconds > WARN_SECONDS || self.gif_bytes > WARN_GIF_BYTES {
            warnings.push(format!(
                "this run looks to take about {} and write a GIF of about {} (Ctrl-C stops it and writes nothing)",
                Duration(self.seconds),
                megabytes(self.gif_bytes as u64)
            ));
        }
        warnings
    }
}

/// The pixels a ball covers, without its trail (at most the canvas).
fn disc_pixels(ball: &BallSpec, scene: &Scene) -> f64 {
    let canvas = f64::from(scene.width) * f64::from(scene.height);
    (std::f64::consts::PI * ball.radius * ball.radius).min(canvas)
}

/// The pixels a ball and its trail cover when drawn: the ball, and its dots shrinking into
/// the past (on average a third of its area each; a trail that does not shrink, all of it).
fn drawn_pixels(ball: &BallSpec, scene: &Scene) -> f64 {
    let area = disc_pixels(ball, scene);
    let dots = ball.trail.saturating_sub(1) as f64;
    let dots = if scene.trail_shrink { dots / 3.0 } else { dots };
    area * (1.0 + dots)
}

/// How much of the canvas changes over a run, from a pilot run of the physics alone (no
/// drawing). A disc of radius `r` moved by `d` px changes about `4·r·d` pixels (two
/// crescents; at most its area), and each trail dot moves about as far as the ball: so a
/// frame changes `4·d·(r + the dots' radii)` pixels, and below one pixel it changes with that
/// probability (a slow ball changes a frame now and then). Summed over all the run's frames:
/// the pilot's own, then its last quarter's pace for the rest (a scene at rest by then stays
/// at rest).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Activity {
    /// Frames in which anything changed (expected).
    changed_frames: f64,
    /// Frames drawn: those that changed (a run draws no other), or every frame (a sweep's
    /// panels are drawn whole).
    drawn_frames: f64,
    /// Balls stepped, summed over the frames (a sleeping ball is not).
    awake_ball_frames: f64,
    /// Pixels of the frames' changed rectangles (the union of the moving balls and trails).
    rect_pixels: f64,
    /// Pixels that changed.
    changed_pixels: f64,
}

impl Activity {
    /// The most the model can say for `scene`: every frame changed, all over the canvas, as
    /// much as all its balls and trails can.
    fn at_most(scene: &Scene) -> Activity {
        let frames = f64::from(scene.frames);
        let canvas = f64::from(scene.width) * f64::from(scene.height);
        let drawn: f64 = scene.balls.iter().map(|b| drawn_pixels(b, scene)).sum();
        Activity {
            changed_frames: frames,
            drawn_frames: frames,
            awake_ball_frames: frames * scene.balls.len() as f64,
            rect_pixels: frames * canvas,
            changed_pixels: frames * drawn.min(canvas),
        }
    }

    fn of(scene: &Scene) -> Activity {
        let n = scene.balls.len().max(1) as f64;
        let budget = match scene.ball_collisions {
            Some(_) => PILOT_BALL_STEPS / 5.0,
            None => PILOT_BALL_STEPS,
        };
        let steps = n * f64::from(scene.motion.substeps);
        let pilot = (budget / steps).clamp(1.0, f64::from(scene.frames.min(PILOT_FRAMES))) as u32;
        let canvas = [f64::from(scene.width), f64::from(scene.height)];
        let mut simulation = scene.simulation();
        let mut was: Vec<Vec2> = simulation.balls().iter().map(Ball::position).collect();
        let (mut total, mut tail) = (Activity::default(), Activity::default());
        for frame in 0..pilot {
            simulation.step();
            let mut rect = Bounds::EMPTY;
            let mut changed = 0.0;
            for ((ball, spec), was) in simulation.balls().iter().zip(&scene.balls).zip(&mut was) {
                let moved = (ball.position() - *was).length();
                *was = ball.position();
                if moved > 0.0 {
                    let radii = ball.radius * (1.0 + dots_share(spec, scene.trail_shrink));
                    changed += (4.0 * moved * radii).min(drawn_pixels(spec, scene));
                    rect.add(ball, canvas);
                }
            }
            let changed = changed.min(canvas[0] * canvas[1]);
            let chance = changed.min(1.0);
            let this = Activity {
                changed_frames: chance,
                drawn_frames: chance,
                awake_ball_frames: awake(&simulation),
                rect_pixels: chance * rect.area(),
                changed_pixels: changed,
            };
            total.add(this);
            if frame >= pilot - pilot.div_ceil(4) {
                tail.add(this);
            }
        }
        // The rest of the run at the pace of the pilot's last quarter.
        let rest = f64::from(scene.frames - pilot) / f64::from(pilot.div_ceil(4));
        total.changed_frames += tail.changed_frames * rest;
        total.drawn_frames += tail.drawn_frames * rest;
        total.awake_ball_frames += tail.awake_ball_frames * rest;
        total.rect_pixels += tail.rect_pixels * rest;
        total.changed_pixels += tail.changed_pixels * rest;
        total
    }

    /// A sweep panel's own activity: drawn whole and stepped in every frame.
    fn every_frame(scene: &Scene) -> Activity {
        let frames = f64::from(scene.frames);
        Activity {
            drawn_frames: frames,
            awake_ball_frames: frames * scene.balls.len() as f64,
            ..Activity::default()
        }
    }

    fn add(&mut self, other: Activity) {
        self.changed_frames += other.changed_frames;
        self.drawn_frames += other.drawn_frames;
        self.awake_ball_frames += other.awake_ball_frames;
        self.rect_pixels += other.rect_pixels;
        self.changed_pixels += other.changed_pixels;
    }
}

/// How many balls the solver steps now: all but the sleeping ones, and none once every ball
/// sleeps (exact mode steps every ball while any is awake).
fn awake(simulation: &Simulation) -> f64 {
    let (n, sleeping) = (simulation.balls().len(), simulation.sleeping_balls());
    match (sleeping == n, simulation.has_contact_solver()) {
        (true, _) => 0.0,
        (false, true) => (n - sleeping) as f64,
        (false, false) => n as f64,
    }
}

/// The trail dots' radii added up, as a share of the ball's: half the trail's length when
/// the dots shrink (from nothing to the ball's size), all of it when they do not.
fn dots_share(ball: &BallSpec, shrink: bool) -> f64 {
    let dots = ball.trail.saturating_sub(1) as f64;
    if shrink {
        dots / 2.0
    } else {
        dots
    }
}

/// A rectangle on the canvas grown to cover balls and their trails.
struct Bounds {
    low: Vec2,
    high: Vec2,
}

impl Bounds {
    const EMPTY: Bounds = Bounds {
        low: Vec2::new(f64::INFINITY, f64::INFINITY),
        high: Vec2::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
    };

    /// Grows to cover `ball` and its trail, within the canvas.
    fn add(&mut self, ball: &Ball, canvas: [f64; 2]) {
        let r = Vec2::new(ball.radius, ball.radius);
        let points = ball.trail.iter().map(|&(x, y)| Vec2::new(x, y));
        for point in points.chain([ball.position()]) {
            self.low = Vec2::new(self.low.x.min(point.x - r.x), self.low.y.min(point.y - r.y));
            self.high = Vec2::new(
                self.high.x.max(point.x + r.x),
                self.high.y.max(point.y + r.y),
            );
        }
        self.low = Vec2::new(self.low.x.max(0.0), self.low.y.max(0.0));
        self.high = Vec2::new(self.high.x.min(canvas[0]), self.high.y.min(canvas[1]));
    }

    fn is_empty(&self) -> bool {
        !(self.low.x < self.high.x && self.low.y < self.high.y)
    }

    fn area(&self) -> f64 {
        if self.is_empty() {
            return 0.0;
        }
        (self.high.x - self.low.x) * (self.high.y - self.low.y)
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
