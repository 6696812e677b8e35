//! What the benchmarks share: the scenes they time.

use std::f64::consts::PI;

use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::scene::random::Random;
use bouncing_ball::{BallSpec, Scene};

/// The exact-mode gas's balls: radius, px.
pub const EXACT_GAS_RADIUS: f64 = 3.0;
/// The exact-mode gas's packing and starting speed (px/frame, along each axis at most).
const EXACT_GAS_PACKING: f64 = 0.3;
const EXACT_GAS_SPEED: f64 = 2.0;
/// Frames to run the exact-mode gas before timing it, so the lattice has melted into a gas.
pub const EXACT_GAS_STIR: u32 = 20;

/// An elastic gas: balls of the given `radii` in a square box sized so that they cover
/// `packing` of it (0.3: 30 %), elastic walls and ball-ball collisions, no gravity (with
/// gravity the balls pile up within ~100 frames, and each size would be measured at another
/// density). Ball `i` starts near the middle of its own square of a lattice, jittered by
/// `random` so that none overlap, moving at up to `max_speed` px/frame along each axis.
pub fn lattice_gas(radii: &[f64], packing: f64, max_speed: f64, random: &mut Random) -> Scene {
    let area: f64 = radii.iter().map(|r| PI * r * r).sum();
    let side = (area / packing).sqrt().ceil();
    let per_row = (radii.len() as f64).sqrt().ceil() as usize;
    let spacing = side / per_row as f64;
    let largest = radii.iter().copied().fold(0.0, f64::max);
    assert!(
        spacing > 2.0 * largest,
        "the lattice is too tight to start without overlaps"
    );
    let balls = radii
        .iter()
        .enumerate()
        .map(|(i, &radius)| {
            let slack = spacing / 2.0 - radius;
            BallSpec {
                x: ((i % per_row) as f64 + 0.5) * spacing + random.range(-slack, slack),
                y: ((i / per_row) as f64 + 0.5) * spacing + random.range(-slack, slack),
                vx: random.range(-max_speed, max_speed),
                vy: random.range(-max_speed, max_speed),
                radius,
                colour: [255, 255, 255],
                trail_colour: [255, 255, 255],
                trail: 0,
            }
        })
        .collect();
    Scene {
        balls,
        walls: Some(1.0),
        ball_collisions: Some(1.0),
        ..Scene::empty(side as u32, side as u32)
    }
}

/// The gas exact mode is timed on: `count` equal balls of radius 3 covering 30 % of the box,
/// moving at up to 2 px/frame along each axis, in exact mode (seeded by `count`).
pub fn exact_gas(count: usize) -> Scene {
    let mut scene = lattice_gas(
        &vec![EXACT_GAS_RADIUS; count],
        EXACT_GAS_PACKING,
        EXACT_GAS_SPEED,
        &mut Random::new(count as u64),
    );
    scene.motion.collisions = CollisionMode::Exact;
    scene
}
