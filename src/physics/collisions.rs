//! Ball-ball collisions: balls that overlap bounce off each other and are pushed apart.
//!
//! Not the lesson's velocity swap, which is right only for equal balls meeting head-on: each
//! overlapping pair exchanges an impulse along the line through their centres (the contact
//! normal), with masses in proportion to radius² (flat discs of equal density). Run once per
//! frame, after every ball has moved; the walls are someone else's job.
//!
//! Pairs are found by the [`Grid`] broad phase and resolved one after another, in the grid's
//! order, so the same balls always give the same bytes.

use super::ball::Ball;
use super::grid::Grid;
use super::work::{tally, Work};

/// The golden angle, radians: successive multiples of it spread evenly round a circle.
const GOLDEN_ANGLE: f64 = 2.399_963_229_728_653;

/// Resolves the contacts between balls, keeping its broad-phase buffers from frame to frame.
/// A scene without ball-ball collisions never creates one, so never builds a grid.
#[derive(Clone, Debug)]
pub struct Collisions {
    /// Share of the approach speed kept after a bounce: 1.0 elastic, 0.0 the balls stop
    /// relative to each other along the normal (0 to 1; the scene checks it).
    restitution: f64,
    grid: Grid,
}

impl Collisions {
    /// Collisions that keep `restitution` of the approach speed (0 to 1).
    pub fn new(restitution: f64) -> Collisions {
        Collisions {
            restitution,
            grid: Grid::new(),
        }
    }

    /// Bounces and separates every pair of overlapping balls, once, in the grid's fixed
    /// order. The order of `balls` is left as it is.
    pub fn resolve(&mut self, balls: &mut [Ball]) {
        tally(Work::BallCollisions);
        self.grid.rebuild(balls);
        // The grid found the pairs from where the balls were at `rebuild`, so resolving each
        // as it is found gives the same result as listing them all first, without the list.
        let restitution = self.restitution;
        self.grid.for_each_overlapping_pair(|i, j| {
            let (head, tail) = balls.split_at_mut(j);
            collide(&mut head[i], &mut tail[0], restitution, j);
        });
    }
}

/// Resolves one contact between `a` and `b` (`b` is ball number `j`, later than `a`).
///
/// Momentum is conserved because both balls get the same impulse, in opposite directions.
/// Kinetic energy cannot rise because the impulse leaves the motion of the pair's centre of
/// mass alone and turns an approach speed `u` into a parting speed `restitution × u`, no
/// faster (restitution ≤ 1). Pushing the balls apart moves them but leaves their velocities
/// alone, so it adds no energy either.
fn collide(a: &mut Ball, b: &mut Ball, restitution: f64, j: usize) {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let reach = a.radius + b.radius;
    let distance_squared = dx * dx + dy * dy;
    if distance_squared >= reach * reach {
        // An earlier pair this frame already pushed these two apart.
        return;
    }
    let distance = distance_squared.sqrt();
    let (nx, ny) = if distance > 0.0 {
        (dx / distance, dy / distance)
    } else {
        coincident_normal(j)
    };

    // Each ball takes the other's share of the total mass: the lighter one moves more.
    let (mass_a, mass_b) = (a.radius * a.radius, b.radius * b.radius);
    let total = mass_a + mass_b;
    let (share_a, share_b) = (mass_b / total, mass_a / total);

    // Speed of `b` relative to `a` along the normal: negative while they approach. A pair
    // already moving apart gets no impulse: one would pull them back together.
    let approach = (b.vx - a.vx) * nx + (b.vy - a.vy) * ny;
    if approach < 0.0 {
        // Change in relative normal speed that turns `approach` into `-restitution * approach`.
        let change = (1.0 + restitution) * approach;
        a.vx += change * share_a * nx;
        a.vy += change * share_a * ny;
        b.vx -= change * share_b * nx;
        b.vy -= change * share_b * ny;
    }

    // Move both apart along the normal until they just touch.
    let overlap = reach - distance;
    a.x -= overlap * share_a * nx;
    a.y -= overlap * share_a * ny;
    b.x += overlap * share_b * nx;
    b.y += overlap * share_b * ny;
}

/// The normal for two balls at exactly the same centre, where the line between centres has
/// no direction. Any fixed direction would separate a pair, but a heap spawned on one spot
/// would then spread along a single line; so ball `j` leaves at `j` golden angles, which
/// fans successive balls out evenly round the circle, and depends on nothing but `j`.
pub(super) fn coincident_normal(j: usize) -> (f64, f64) {
    let angle = GOLDEN_ANGLE * j as f64;
    (angle.cos(), angle.sin())
}

/// Total kinetic energy, `Σ ½·m·|v|²` with masses ∝ radius² as above: it never rises in a
/// collision with restitution ≤ 1 (the tests and the soak run check it).
pub fn kinetic_energy(balls: &[Ball]) -> f64 {
    balls
        .iter()
        .map(|b| 0.5 * b.radius * b.radius * (b.vx * b.vx + b.vy * b.vy))
        .sum()
}

/// How deep the most overlapping pair overlaps, px (0 if none does), checking every pair:
/// a measure for tests and the soak run, never used to step.
pub fn deepest_overlap(balls: &[Ball]) -> f64 {
    let mut deepest = 0.0f64;
    for (i, a) in balls.iter().enumerate() {
        for b in &balls[i + 1..] {
            deepest = deepest.max(a.radius + b.radius - (b.x - a.x).hypot(b.y - a.y));
        }
    }
    deepest
}
