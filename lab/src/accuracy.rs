//! The accuracy study: closed-form physics, and the experiments that measure a [`Motion`]
//! against it (never against another integrator); measures of piles and gases (height,
//! speed, overlap). Used by the tests, the examples and the benches, never by the program.
//!
//! Every experiment runs in the lesson's box (320 × 240 px, radius 12, gravity 0.5 px/frame²).

pub use bouncing_ball::physics::ball::kinetic_energy;
use bouncing_ball::physics::contacts::Grid;
use bouncing_ball::physics::{maths, Ball, Effects, Motion, Vec2, Walls};

/// The lesson's canvas, px.
pub const WIDTH: f64 = 320.0;
pub const HEIGHT: f64 = 240.0;
/// The lesson's ball radius, px.
pub const RADIUS: f64 = 12.0;
/// The lesson's gravity, px/frame² (downwards: y grows downwards).
pub const GRAVITY: f64 = 0.5;
/// Where the centre is when the ball touches the floor, px.
pub const FLOOR: f64 = HEIGHT - RADIUS;

/// Position and velocity along one axis after `t` frames of free flight from `x0`, `v0`, under
/// gravity `g` and the lesson's per-frame `drag` (`dv/dt = g − k·v`, `k = −ln(1 − drag)`):
/// `v = g/k + (v0 − g/k)·e^(−kt)`, `x = x0 + (g/k)·t + (v0 − g/k)·(1 − e^(−kt))/k`.
pub fn free_flight(x0: f64, v0: f64, g: f64, drag: f64, t: f64) -> (f64, f64) {
    let k = -maths::ln_1p(-drag);
    let terminal = g / k;
    // 1 − e^(−kt), written so that it keeps its digits when kt is small.
    let lost = -maths::exp_m1(-k * t);
    (
        x0 + terminal * t + (v0 - terminal) * lost / k,
        terminal + (v0 - terminal) * (1.0 - lost),
    )
}

/// The apex height above the floor after bounce `k` of a ball released from rest at height `h`
/// with damping `e`: each bounce keeps `e` of the speed, so `e²` of the height.
pub fn apex_height(h: f64, e: f64, k: i32) -> f64 {
    e.powi(2 * k) * h
}

/// The lesson's gravity and a `width` × `height` box with `damping`.
pub fn lesson_effects(damping: f64) -> Effects {
    Effects {
        gravity: Some(Vec2::new(0.0, GRAVITY)),
        walls: Some(Walls {
            width: WIDTH,
            height: HEIGHT,
            damping,
        }),
        ..Effects::default()
    }
}

/// The free-flight experiment: the lesson's ball (from (40, 40) at (5.2, 0) px/frame) under
/// gravity and `drag`, with no walls; the distance, px, between where `motion` puts it after
/// `frames` frames and where the closed form does.
pub fn free_flight_error(motion: Motion, drag: f64, frames: u32) -> f64 {
    let effects = Effects {
        gravity: Some(Vec2::new(0.0, GRAVITY)),
        drag: Some(drag),
        ..Effects::default()
    };
    let (x0, y0, vx0, vy0) = (40.0, 40.0, 5.2, 0.0);
    let mut ball = Ball::new(x0, y0, vx0, vy0, RADIUS, 0);
    for _ in 0..frames {
        motion.advance(&mut ball, &effects);
    }
    let t = f64::from(frames);
    let (x, _) = free_flight(x0, vx0, 0.0, drag, t);
    let (y, _) = free_flight(y0, vy0, GRAVITY, drag, t);
    maths::hypot(ball.x - x, ball.y - y)
}

/// What one bounce looked like, heights in px above the floor's contact line.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bounce {
    /// The frame whose step contained the bounce.
    pub frame: u64,
    /// The apex the ball's state implies in exact flight, `(FLOOR − y) + vy²/2g`, taken at the
    /// end of the bounce's frame: its mechanical energy after the bounce, as a height.
    pub flight_apex: f64,
    /// The highest position drawn in a frame before the next bounce: what a viewer sees.
    pub seen_apex: f64,
}

/// Starts the lesson's ball mid-box at height `y0` with vertical speed `vy0` (no sideways
/// speed) and `damping`, runs `frames` frames, and records every bounce off the floor: a frame
/// that ends moving up with less vy than it began (in flight, gravity only increases vy).
/// A bounce that ends in rest is not one.
pub fn bounces(motion: Motion, damping: f64, y0: f64, vy0: f64, frames: u64) -> Vec<Bounce> {
    let effects = lesson_effects(damping);
    let mut ball = Ball::new(WIDTH / 2.0, y0, 0.0, vy0, RADIUS, 0);
    let mut found: Vec<Bounce> = Vec::new();
    for frame in 0..frames {
        let vy_before = ball.vy;
        motion.advance(&mut ball, &effects);
        let height = FLOOR - ball.y;
        if ball.vy < vy_before && ball.vy < 0.0 {
            found.push(Bounce {
                frame,
                flight_apex: height + ball.vy * ball.vy / (2.0 * GRAVITY),
                seen_apex: height,
            });
        } else if let Some(last) = found.last_mut() {
            last.seen_apex = last.seen_apex.max(height);
        }
    }
    found
}

/// Mechanical energy per unit mass, px²/frame², with the floor's contact line as zero height.
pub fn energy(ball: &Ball) -> f64 {
    ball.velocity().length_squared() / 2.0 + GRAVITY * (FLOOR - ball.y)
}

/// The elastic experiment: the lesson's ball with damping 1 for `frames` frames; the relative
/// change of its energy from start to end.
pub fn energy_drift(motion: Motion, frames: u64) -> f64 {
    let effects = lesson_effects(1.0);
    let mut ball = Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0);
    let start = energy(&ball);
    for _ in 0..frames {
        motion.advance(&mut ball, &effects);
    }
    (energy(&ball) - start) / start
}

/// The slope of the least-squares line through `(ln x, ln y)`: the order `p` in `y ∝ x^p`.
pub fn fitted_order(points: &[(f64, f64)]) -> f64 {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .map(|&(x, y)| (maths::ln(x), maths::ln(y)))
        .collect();
    let n = logs.len() as f64;
    let (mx, my) = logs
        .iter()
        .fold((0.0, 0.0), |(sx, sy), &(x, y)| (sx + x / n, sy + y / n));
    let (sxy, sxx) = logs.iter().fold((0.0, 0.0), |(sxy, sxx), &(x, y)| {
        (sxy + (x - mx) * (y - my), sxx + (x - mx) * (x - mx))
    });
    sxy / sxx
}

/// Densest packing of equal discs (hexagonal): they cover `π/√12` of the plane.
pub const DENSEST_PACKING: f64 = 0.9069;

/// The least height a heap of `count` balls of `radius` can have on a floor `width` px wide
/// without overlaps: their area, packed as densely as discs can be, spread over the width.
pub fn lowest_pile(count: usize, radius: f64, width: f64) -> f64 {
    count as f64 * std::f64::consts::PI * radius * radius / (DENSEST_PACKING * width)
}

/// How tall the heap of `balls` on a floor at `floor` (y, px) is: up to its highest ball's top.
pub fn pile_height(balls: &[Ball], floor: f64) -> f64 {
    balls
        .iter()
        .map(|b| floor - (b.y - b.radius))
        .fold(0.0, f64::max)
}

/// Root-mean-square speed of `balls`, px/frame: how far a heap is from rest.
pub fn rms_speed(balls: &[Ball]) -> f64 {
    let sum: f64 = balls.iter().map(|b| b.velocity().length_squared()).sum();
    (sum / balls.len().max(1) as f64).sqrt()
}

/// How deep the most overlapping pair overlaps, px (0 if none does): a measure for tests and
/// the soak run, never used to step. The grid finds the overlapping pairs, so a check after
/// every frame of a thousand balls costs about as much as the frame.
pub fn deepest_overlap(balls: &[Ball]) -> f64 {
    let mut grid = Grid::new();
    grid.rebuild(balls);
    grid.deepest_overlap(balls)
}
