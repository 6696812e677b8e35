//! The time and GIF-size model: costs fitted to measured runs, multiplied by what a run does
//! (its [`Activity`], which the pilot run measures; `super::pilot`).
//!
//! The costs are those of the reference machine (the 2-core VM docs/robustness.md names),
//! fitted to whole runs of the presets, long runs and crowds (`cargo run --release --example
//! budget`). Times are in ns, sizes in bytes.

use crate::physics::Integrator;
use crate::scene::{BallSpec, Scene};

/// Per canvas pixel per frame: clearing the frame and comparing it with the last one.
const NS_PER_CANVAS_PIXEL: f64 = 0.05;
/// Per ball per step, and per ball per step with ball-ball collisions (grid, contacts).
const NS_PER_BALL_STEP: f64 = 30.0;
const NS_PER_COLLIDING_BALL_STEP: f64 = 400.0;
/// Per event of exact mode (a bounce, a contact, a cell crossed), by integrator: the Euler
/// methods fly each ball along a parabola, Verlet and RK4 along curves whose times of
/// contact take longer to find. Measured on `--preset pile --collisions exact` with
/// `cargo run --release --example exact_pile_cost` (the physics alone, steps included, idle
/// machine, medians of 5): semi-implicit Euler 10,704 events, 0.9 µs each (1.0 to 1.9 µs on
/// a loaded one); Verlet 64,416 events, 1.5 µs; RK4 114,120 events, 1.7 µs.
const NS_PER_EULER_EVENT: f64 = 1_300.0;
const NS_PER_CURVED_EVENT: f64 = 1_700.0;
/// Per floor per ball per step.
const NS_PER_FLOOR_TEST: f64 = 10.0;
/// Per ball or trail dot drawn, and per pixel of them (a frame that changed draws every ball;
/// 20,000 overlapping balls of radius 100 draw 0.6 billion pixels a frame in about 0.2 s).
const NS_PER_DOT: f64 = 15.0;
const NS_PER_DRAWN_PIXEL: f64 = 0.5;
/// Per frame, changed or not: checking for a stop, merging an unchanged frame into the last
/// (a still ball, 10 million frames: about 100 ns a frame with the two below).
const NS_PER_FRAME: f64 = 60.0;
/// Per ball per frame in which nothing changed: its trail recorded, the frame found unchanged
/// (a sleeping pile's frames, fitted to `--preset pile -n 200000`).
const NS_PER_QUIET_BALL: f64 = 15.0;
/// Per pixel of a frame's changed rectangle (cut out and coded, in several ways), and per
/// pixel that changed in it (what the codes have to spell out; fitted between the short
/// runs of 10 to 200 moving balls, whose time follows their GIF's size, and the lesson's and
/// elastic's 20,000 frames).
const NS_PER_RECT_PIXEL: f64 = 3.6;
const NS_PER_CHANGED_PIXEL: f64 = 20.0;
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

/// What a run does, summed over its frames: what the costs above are paid for.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Activity {
    /// Frames in which anything changed (expected).
    pub changed_frames: f64,
    /// Frames drawn: those that changed (a run draws no other), or every frame (a sweep's
    /// panels are drawn whole).
    pub drawn_frames: f64,
    /// Balls stepped, summed over the frames (a sleeping ball is not).
    pub awake_ball_frames: f64,
    /// Exact mode's events (bounces, contacts, cells crossed).
    pub events: f64,
    /// Pixels of the frames' changed rectangles (the union of the moving balls and trails).
    pub rect_pixels: f64,
    /// Pixels that changed.
    pub changed_pixels: f64,
}

impl Activity {
    pub(crate) fn add(&mut self, other: Activity) {
        self.changed_frames += other.changed_frames;
        self.drawn_frames += other.drawn_frames;
        self.awake_ball_frames += other.awake_ball_frames;
        self.events += other.events;
        self.rect_pixels += other.rect_pixels;
        self.changed_pixels += other.changed_pixels;
    }
}

/// A run's predicted time and GIF size.
pub(crate) struct TimeAndSize {
    /// Time per frame, ns.
    pub frame_ns: f64,
    /// The whole run, seconds.
    pub seconds: f64,
    /// The GIF's size, bytes.
    pub gif_bytes: f64,
}

/// The physics alone of `scene` doing `activity` (stepping the awake balls, exact mode's
/// events), ns: no drawing, no GIF.
pub(crate) fn physics_ns(scene: &Scene, activity: &Activity) -> f64 {
    let steps = f64::from(scene.motion.substeps);
    let per_step = match scene.ball_collisions {
        Some(_) => NS_PER_COLLIDING_BALL_STEP,
        None => NS_PER_BALL_STEP,
    } + scene.floors.len() as f64 * NS_PER_FLOOR_TEST;
    let per_event = match scene.motion.integrator {
        Integrator::ExplicitEuler | Integrator::SemiImplicitEuler => NS_PER_EULER_EVENT,
        Integrator::VelocityVerlet | Integrator::Rk4 => NS_PER_CURVED_EVENT,
    };
    activity.awake_ball_frames * steps * per_step + activity.events * per_event
}

/// The time and GIF size of `scene` when its frames change as `activity` says.
pub(crate) fn time_and_size(scene: &Scene, activity: &Activity) -> TimeAndSize {
    let n = scene.balls.len() as f64;
    let canvas = f64::from(scene.width) * f64::from(scene.height);
    let drawn: f64 = scene.balls.iter().map(|b| drawn_pixels(b, scene)).sum();
    let first_frame_balls: f64 = scene.balls.iter().map(|b| disc_pixels(b, scene)).sum();
    let dots: f64 = scene.balls.iter().map(|b| b.trail.max(1) as f64).sum();
    let frames = f64::from(scene.frames);
    // Every frame records the trails; only frames that changed are drawn and compared,
    // and only awake balls are stepped.
    let every_frame = NS_PER_FRAME + n * NS_PER_QUIET_BALL;
    let drawing = canvas * NS_PER_CANVAS_PIXEL + dots * NS_PER_DOT + drawn * NS_PER_DRAWN_PIXEL;
    let changing = activity.drawn_frames * drawing
        + physics_ns(scene, activity)
        + activity.rect_pixels * NS_PER_RECT_PIXEL
        + activity.changed_pixels * NS_PER_CHANGED_PIXEL
        + activity.changed_frames * NS_PER_CHANGED_FRAME;
    let once = NS_PER_RUN + canvas * NS_PER_CANVAS_PIXEL_ONCE;
    TimeAndSize {
        frame_ns: every_frame + changing / frames,
        seconds: (every_frame * frames + changing + once) * 1e-9,
        gif_bytes: canvas * GIF_BYTES_PER_CANVAS_PIXEL
            + first_frame_balls.min(canvas) * GIF_BYTES_PER_CHANGED_PIXEL
            + activity.rect_pixels * GIF_BYTES_PER_RECT_PIXEL
            + activity.changed_pixels * GIF_BYTES_PER_CHANGED_PIXEL
            + activity.changed_frames * GIF_BYTES_PER_CHANGED_FRAME,
    }
}

/// The pixels a ball covers, without its trail (at most the canvas).
pub(crate) fn disc_pixels(ball: &BallSpec, scene: &Scene) -> f64 {
    let canvas = f64::from(scene.width) * f64::from(scene.height);
    (std::f64::consts::PI * ball.radius * ball.radius).min(canvas)
}

/// The pixels a ball and its trail cover when drawn: the ball, and its dots shrinking into
/// the past (on average a third of its area each; a trail that does not shrink, all of it).
pub(crate) fn drawn_pixels(ball: &BallSpec, scene: &Scene) -> f64 {
    let area = disc_pixels(ball, scene);
    let dots = ball.trail.saturating_sub(1) as f64;
    let dots = if scene.trail_shrink { dots / 3.0 } else { dots };
    area * (1.0 + dots)
}
