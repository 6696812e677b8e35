//! Where exact mode's 150-ball pile stands, seed by seed and integrator by integrator: does it
//! come to rest, and does it stay free of overlaps? Prints one row per seed.
//!
//! The pile: 150 balls of radius 6 in a 320×240 box (walls damping 0.5), restitution 0.5,
//! gravity 0.5 px/frame², dropped from a jittered lattice at up to 2 px/frame along each axis,
//! one step per frame, 400 frames. Columns per integrator: the largest rms speed in frames
//! 300–399 (at rest: at most 0.01 px/frame), the deepest overlap over all frames as a share
//! of the radius, the most events in a frame, and how many frames hit the cap of 64 events
//! per ball (9,600) and dropped the rest of their step.
//!
//! Run: `cargo run --release --example exact_piles` (about 8 s).

use bouncing_ball::physics::effects::Effects;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::walls::Walls;
use bouncing_ball::physics::Integrator;
use bouncing_ball::physics::Simulation;
use bouncing_ball::physics::Vec2;
use bouncing_ball::scene::random::jittered_lattice;
use bouncing_ball_lab::accuracy::{deepest_overlap, rms_speed};

const BALLS: usize = 150;
const RADIUS: f64 = 6.0;
const WIDTH: f64 = 320.0;
const FRAMES: u32 = 400;
/// Frames from which the pile should be at rest.
const SETTLED_FROM: u32 = 300;
const SEEDS: u64 = 12;

/// Runs one pile: (largest rms speed once settled, deepest overlap / r, most events in a
/// frame, capped frames).
fn pile(seed: u64, integrator: Integrator) -> (f64, f64, u64, u64) {
    let effects = Effects {
        gravity: Some(Vec2::new(0.0, 0.5)),
        walls: Some(Walls {
            width: WIDTH,
            height: 240.0,
            damping: 0.5,
        }),
        ..Effects::default()
    };
    let motion = Motion {
        integrator,
        collisions: CollisionMode::Exact,
        ..Motion::default()
    };
    let balls = jittered_lattice(BALLS, RADIUS, WIDTH, 2.0, seed);
    let mut simulation = Simulation::new(balls, effects, motion, Some(0.5));
    let (mut settled_speed, mut deepest, mut most, mut capped) = (0.0f64, 0.0f64, 0, 0);
    for frame in 0..FRAMES {
        simulation.step();
        let balls = simulation.balls();
        if let Some(counts) = simulation.event_counts() {
            most = most.max(counts.events);
            capped += counts.capped_steps;
        }
        deepest = deepest.max(deepest_overlap(balls) / RADIUS);
        if frame >= SETTLED_FROM {
            settled_speed = settled_speed.max(rms_speed(balls));
        }
    }
    (settled_speed, deepest, most, capped)
}

fn main() {
    let integrators = [
        Integrator::SemiImplicitEuler,
        Integrator::VelocityVerlet,
        Integrator::Rk4,
    ];
    print!("| seed |");
    for integrator in integrators {
        print!(" {integrator:?}: rms speed, overlap, events, capped |");
    }
    println!();
    println!("|---:|{}", "---|".repeat(integrators.len()));
    for seed in 1..=SEEDS {
        print!("| {seed} |");
        for integrator in integrators {
            let (speed, overlap, events, capped) = pile(seed, integrator);
            print!(" {speed:.1e}, {overlap:.1e} r, {events}, {capped} |");
        }
        println!();
    }
}
