//! The pilot run: the scene's physics alone (no drawing) for its first frames, to measure
//! what the run will do ([`Activity`]): how much of the canvas changes, how many balls are
//! stepped, how many events exact mode resolves. The costs (`super::cost`) turn that into
//! time and GIF size.
//!
//! A disc of radius `r` moved by `d` px changes about `4·r·d` pixels (two crescents; at most
//! its area), and each trail dot moves about as far as the ball: so a frame changes
//! `4·d·(r + the dots' radii)` pixels, and below one pixel it changes with that probability
//! (a slow ball changes a frame now and then). Summed over all the run's frames: the pilot's
//! own, then its last quarter's pace for the rest (a scene at rest by then stays at rest).

use super::cost::{drawn_pixels, physics_ns, Activity};
use crate::physics::{Ball, Simulation, Vec2};
use crate::scene::{BallSpec, Scene};

/// The pilot stops once its physics has cost this much by the model, ns (0.15 s): a few
/// million ball-steps, fewer with ball-ball collisions, fewer still where exact mode's events
/// are many.
const PILOT_NS: f64 = 1.5e8;
/// The pilot never runs longer than this many frames: scenes that come to rest do so sooner.
const PILOT_FRAMES: u32 = 100_000;

impl Activity {
    /// The most the model can say for `scene`: every frame changed, all over the canvas, as
    /// much as all its balls and trails can. Exact mode's events are not bounded: this
    /// bound is only taken for runs too short for them to matter.
    pub fn at_most(scene: &Scene) -> Activity {
        let frames = f64::from(scene.frames);
        let canvas = f64::from(scene.width) * f64::from(scene.height);
        let drawn: f64 = scene.balls.iter().map(|b| drawn_pixels(b, scene)).sum();
        Activity {
            changed_frames: frames,
            drawn_frames: frames,
            awake_ball_frames: frames * scene.balls.len() as f64,
            events: 0.0,
            rect_pixels: frames * canvas,
            changed_pixels: frames * drawn.min(canvas),
        }
    }

    /// What a whole run of `scene` does: the pilot's frames, then the rest at the pace of
    /// the pilot's last quarter.
    pub fn of(scene: &Scene) -> Activity {
        let frames = pilot(scene);
        let pilot = frames.len();
        let mut total = Activity::default();
        let mut tail = Activity::default();
        for (frame, this) in frames.into_iter().enumerate() {
            total.add(this);
            if frame >= pilot - pilot.div_ceil(4) {
                tail.add(this);
            }
        }
        let rest = (f64::from(scene.frames) - pilot as f64) / pilot.div_ceil(4) as f64;
        total.add(tail.times(rest));
        total
    }

    /// A sweep panel's own activity: drawn whole and stepped in every frame, with the events
    /// its `pilot` (`Activity::of`) counted.
    pub fn every_frame(scene: &Scene, pilot: &Activity) -> Activity {
        let frames = f64::from(scene.frames);
        Activity {
            drawn_frames: frames,
            awake_ball_frames: frames * scene.balls.len() as f64,
            events: pilot.events,
            ..Activity::default()
        }
    }

    fn times(self, k: f64) -> Activity {
        Activity {
            changed_frames: self.changed_frames * k,
            drawn_frames: self.drawn_frames * k,
            awake_ball_frames: self.awake_ball_frames * k,
            events: self.events * k,
            rect_pixels: self.rect_pixels * k,
            changed_pixels: self.changed_pixels * k,
        }
    }
}

/// Runs the physics of `scene` for its first frames (at least one; see `PILOT_NS`) and says
/// what each did.
fn pilot(scene: &Scene) -> Vec<Activity> {
    let canvas = [f64::from(scene.width), f64::from(scene.height)];
    let mut simulation = scene.simulation();
    let mut was: Vec<Vec2> = simulation.balls().iter().map(Ball::position).collect();
    let mut frames = Vec::new();
    let mut physics = Activity::default();
    while frames.len() < scene.frames.min(PILOT_FRAMES) as usize
        && physics_ns(scene, &physics) < PILOT_NS
    {
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
            events: simulation.event_counts().map_or(0.0, |c| c.events as f64),
            rect_pixels: chance * rect.area(),
            changed_pixels: changed,
        };
        physics.add(this);
        frames.push(this);
    }
    frames
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
