//! The pilot run: the scene's physics alone (no drawing) for its first frames, to measure
//! what the run will do ([`Activity`]): how much of the canvas changes, how many balls are
//! stepped, how many events exact mode resolves. The costs (`super::cost`) turn that into
//! time and GIF size.
//!
//! A disc of radius `r` moved by `d` px changes about `4·r·d` pixels (two crescents; at most
//! its area), and each trail dot moves about as far as the ball: so a frame changes
//! `4·d·(r + the dots' radii)` pixels. A circle is drawn from its box of whole pixels, so
//! a frame changes only when a side of some circle's box crosses into another pixel (a
//! slow ball changes a frame now and then; `draws_anew`). Summed over all the run's frames:
//! the pilot's own, then the rest as its last two quarters point (a scene at rest by then
//! stays at rest; one slowing down goes on slowing; see `Span::rest_of`).

use super::cost::{drawn_pixels, physics_ns, Activity};
use crate::physics::replay::{KeptFrames, Playback};
use crate::physics::{maths, Ball, Simulation, Vec2};
use crate::render::palette::{drawn_dots, fade};
use crate::scene::{BallSpec, Scene};

/// The pilot stops once its physics has cost this much by the model, ns (0.25 s): a few
/// million ball-steps, fewer with ball-ball collisions, fewer still where exact mode's events
/// are many.
const PILOT_NS: f64 = 2.5e8;
/// The pilot never runs longer than this many frames: scenes that come to rest do so sooner.
pub(super) const PILOT_FRAMES: u32 = 100_000;

impl Activity {
    /// The most the model can say for `scene`: every frame changed, all over the canvas, as
    /// much as all its balls and trails can. Exact mode's events are not bounded: this
    /// bound is only taken for runs too short for them to matter.
    pub(crate) fn at_most(scene: &Scene) -> Activity {
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

    /// What a whole run of `scene` does: the pilot's frames, then the rest as the pilot's
    /// last two quarters point (`rest_of`).
    pub(crate) fn of(scene: &Scene) -> Activity {
        Activity::from_pilot(scene, &pilot(scene, false).0)
    }

    /// `of`, and the pilot's frames kept for the run to play back, where they fit.
    pub(crate) fn of_keeping(scene: &Scene) -> (Activity, Option<Playback>) {
        let (frames, playback) = pilot(scene, true);
        (Activity::from_pilot(scene, &frames), playback)
    }

    /// What a whole run of `scene` does, from what each of the pilot's `frames` did.
    fn from_pilot(scene: &Scene, frames: &[Activity]) -> Activity {
        let quarter = frames.len().div_ceil(4);
        let (head, last) = frames.split_at(frames.len() - quarter);
        let before = &head[head.len().saturating_sub(quarter)..];
        let sum = |frames: &[Activity]| {
            let mut sum = Activity::default();
            frames.iter().for_each(|frame| sum.add(*frame));
            sum
        };
        let full_quarters = before.len() == quarter;
        let (mut total, last, before) = (sum(frames), sum(last), sum(before));
        // Each quantity on its own: the balls stepped go on as they were while the pixels
        // that change may die away.
        let span = Span {
            pilot: frames.len() as f64,
            quarter: quarter as f64,
            run: f64::from(scene.frames),
            full_quarters,
        };
        total.add(last.zip(before, |last, before| span.rest_of(last, before)));
        total
    }

    /// A sweep panel's own activity: drawn whole and stepped in every frame, with the events
    /// its `pilot` (`Activity::of`) counted.
    pub(crate) fn every_frame(scene: &Scene, pilot: &Activity) -> Activity {
        let frames = f64::from(scene.frames);
        Activity {
            drawn_frames: frames,
            awake_ball_frames: frames * scene.balls.len() as f64,
            events: pilot.events,
            ..Activity::default()
        }
    }

    /// Each quantity of `self` with the same of `other`, through `f`.
    fn zip(self, other: Activity, f: impl Fn(f64, f64) -> f64) -> Activity {
        Activity {
            changed_frames: f(self.changed_frames, other.changed_frames),
            drawn_frames: f(self.drawn_frames, other.drawn_frames),
            awake_ball_frames: f(self.awake_ball_frames, other.awake_ball_frames),
            events: f(self.events, other.events),
            rect_pixels: f(self.rect_pixels, other.rect_pixels),
            changed_pixels: f(self.changed_pixels, other.changed_pixels),
        }
    }
}

/// Where the pilot stands in the run, frames.
struct Span {
    /// Frames the pilot ran, and a quarter of them (rounded up).
    pilot: f64,
    quarter: f64,
    /// Frames in the whole run.
    run: f64,
    /// Whether the pilot ran two whole quarters, so that its pace can be compared.
    full_quarters: bool,
}

impl Span {
    /// How much of a quantity the frames after the pilot add, from its sum over the pilot's
    /// last quarter (`last`) and the quarter before (`before`). A quantity that kept its
    /// pace, or grew, goes on at the last quarter's pace. One that slowed goes on slowing
    /// as it did, as a power of time: pace ∝ t^−α, with α from the two quarters. A ball
    /// rolling to and fro on the floor, whose speed drops by the wall's damping at each
    /// end, slows as 1/t (α = 1): its changes over a long run grow as the log of its
    /// length, not in proportion to it.
    fn rest_of(&self, last: f64, before: f64) -> f64 {
        let pace = last / self.quarter;
        let rest = self.run - self.pilot;
        if !(self.full_quarters && before > last && last > 0.0) {
            return pace * rest;
        }
        // The quarters' middles, and times as multiples of the last one's.
        let (t_last, t_before) = (
            self.pilot - self.quarter / 2.0,
            self.pilot - self.quarter * 1.5,
        );
        let alpha = maths::ln(before / last) / maths::ln(t_last / t_before);
        let (from, to) = (self.pilot / t_last, self.run / t_last);
        // ∫ pace·(t / t_last)^−α dt from the pilot's end to the run's.
        let integral = if (alpha - 1.0).abs() < 1e-9 {
            maths::ln(to / from)
        } else {
            (maths::powf(to, 1.0 - alpha) - maths::powf(from, 1.0 - alpha)) / (1.0 - alpha)
        };
        pace * t_last * integral
    }
}

/// Runs the physics of `scene` for its first frames (at least one; see `PILOT_NS`) and says
/// what each did; if `keep`, also keeps those frames for the run to play back, where they
/// fit (`crate::physics::replay`).
fn pilot(scene: &Scene, keep: bool) -> (Vec<Activity>, Option<Playback>) {
    let canvas = Vec2::new(f64::from(scene.width), f64::from(scene.height));
    let mut simulation = scene.simulation();
    let most = scene.frames.min(PILOT_FRAMES) as usize;
    let mut kept = keep.then(|| KeptFrames::new(&simulation, most));
    let mut was: Vec<Vec2> = simulation.balls().iter().map(Ball::position).collect();
    let mut frames = Vec::new();
    let mut physics = Activity::default();
    while frames.len() < scene.frames.min(PILOT_FRAMES) as usize
        && physics_ns(scene, &physics) < PILOT_NS
    {
        simulation.step();
        if kept.as_mut().is_some_and(|k| !k.keep(&simulation)) {
            kept = None; // too big to keep: the run steps every frame itself
        }
        let mut rect = CoveringRect::EMPTY;
        let (mut changed, mut redrawn) = (0.0, false);
        for ((ball, spec), was) in simulation.balls().iter().zip(&scene.balls).zip(&mut was) {
            let step = ball.position() - *was;
            if step != Vec2::ZERO {
                let radii = ball.radius * (1.0 + dots_share(spec, scene.trail_shrink));
                changed += (4.0 * step.length() * radii).min(drawn_pixels(spec, scene));
                redrawn = redrawn || draws_anew(ball, *was, spec.trail, scene.trail_shrink);
                rect.add(ball, canvas);
            }
            *was = ball.position();
        }
        let changed = changed.min(canvas.x * canvas.y);
        let chance = if redrawn { 1.0 } else { 0.0 };
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
    let playback = kept.map(|kept| Playback::new(kept, simulation));
    (frames, playback)
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

/// Whether `ball`, which was at `was` a frame ago, draws anything different from what it
/// drew then. The renderer draws a circle from its box of whole pixels
/// (`crate::render::ellipse::PixelBox`), so a circle that moved below a pixel draws the
/// same unless a side of its box crossed into another pixel. Each trail dot is now where
/// the next older one was; the oldest, dropped from the trail, is left out (the smallest
/// dot). A trail still filling up changes its dots' sizes and shades every frame.
fn draws_anew(ball: &Ball, was: Vec2, capacity: usize, shrink: bool) -> bool {
    let n = ball.trail.len();
    if n < capacity {
        return true;
    }
    let sides = |centre: Vec2, r: f64| {
        [
            (centre.x - r) as i32,
            (centre.y - r) as i32,
            (centre.x + r) as i32,
            (centre.y + r) as i32,
        ]
    };
    if sides(ball.position(), ball.radius) != sides(was, ball.radius) {
        return true;
    }
    // Dot `i` (from 1) and where it was, the point before it.
    let moves = ball.trail.iter().zip(ball.trail.iter().skip(1));
    let mut dots = moves.take(drawn_dots(n).end.saturating_sub(1)).enumerate();
    dots.any(|(before, (&was, &now))| {
        let i = before + 1;
        let r = if shrink {
            ball.radius * fade(i, n)
        } else {
            ball.radius
        };
        sides(now, r) != sides(was, r)
    })
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
struct CoveringRect {
    low: Vec2,
    high: Vec2,
}

impl CoveringRect {
    const EMPTY: CoveringRect = CoveringRect {
        low: Vec2::new(f64::INFINITY, f64::INFINITY),
        high: Vec2::new(f64::NEG_INFINITY, f64::NEG_INFINITY),
    };

    /// Grows to cover `ball` and its trail, within the canvas.
    fn add(&mut self, ball: &Ball, canvas: Vec2) {
        let r = Vec2::new(ball.radius, ball.radius);
        let points = ball.trail.iter().copied();
        for point in points.chain([ball.position()]) {
            self.low = Vec2::new(self.low.x.min(point.x - r.x), self.low.y.min(point.y - r.y));
            self.high = Vec2::new(
                self.high.x.max(point.x + r.x),
                self.high.y.max(point.y + r.y),
            );
        }
        self.low = Vec2::new(self.low.x.max(0.0), self.low.y.max(0.0));
        self.high = Vec2::new(self.high.x.min(canvas.x), self.high.y.min(canvas.y));
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A pilot of 400 frames in a run of `run` frames.
    fn span(run: f64) -> Span {
        Span {
            pilot: 400.0,
            quarter: 100.0,
            run,
            full_quarters: true,
        }
    }

    fn assert_close(actual: f64, expected: f64, what: &str) {
        assert!(
            (actual - expected).abs() <= 1e-6 * expected.abs().max(1.0),
            "{what}: expected {expected}, got {actual}"
        );
    }

    #[test]
    fn a_quantity_that_kept_its_pace_goes_on_at_it() {
        // 10 a frame in both quarters: 10 a frame for the 600 frames after the pilot.
        assert_close(span(1000.0).rest_of(1000.0, 1000.0), 6000.0, "steady");
        // Growing: the last quarter's pace, not more.
        assert_close(span(1000.0).rest_of(1000.0, 500.0), 6000.0, "growing");
    }

    #[test]
    fn a_quantity_that_stopped_stays_stopped() {
        assert_close(span(1e7).rest_of(0.0, 1000.0), 0.0, "stopped");
    }

    #[test]
    fn a_quantity_slowing_as_one_over_t_grows_as_the_log_of_the_run() {
        // Pace c/t: the quarters around t = 250 and 350 sum to c·ln(300/200) and c·ln(400/300).
        let c = 1000.0;
        let (before, last) = (c * maths::ln(1.5), c * maths::ln(4.0 / 3.0));
        for run in [1e4, 1e6, 1e8] {
            let expected = c * maths::ln(run / 400.0);
            let actual = span(run).rest_of(last, before);
            // The power is fitted to two quarters' sums (α = 1.02 here), not to c/t itself:
            // within 15 % over a run 250,000 times the pilot's length (a pace kept would be
            // 100 times as much at 1e8 frames as at 1e6).
            assert!(
                (actual / expected - 1.0).abs() < 0.15,
                "{run} frames: expected about {expected:.0}, got {actual:.0}"
            );
        }
    }

    #[test]
    fn a_pilot_that_slowed_over_its_last_two_quarters_goes_on_slowing() {
        // Eight frames whose events halve every two frames, in a run of 10,000 frames: two
        // whole quarters, so the rest goes on slowing, far below the last quarter's pace
        // (one event a frame) kept for the 9,992 frames after the pilot.
        let scene = Scene {
            frames: 10_000,
            ..crate::scene::file::preset("lesson", 1).unwrap()
        };
        let frames = [8.0, 8.0, 4.0, 4.0, 2.0, 2.0, 1.0, 1.0].map(|events| Activity {
            events,
            ..Activity::default()
        });
        let total = Activity::from_pilot(&scene, &frames).events;
        assert!(
            (30.0..100.0).contains(&total),
            "30 events in the pilot, then slowing: got {total}"
        );
    }
}
