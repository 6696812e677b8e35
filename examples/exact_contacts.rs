//! The accuracy study for contacts other than the box: stepped (clamp mode, substeps) against
//! exact mode, for ball-ball scattering and for a ball on floor segments. Prints two tables.
//!
//! - Scattering: a ball of radius 4 at 5 or 15 px/frame meets a resting ball of radius 6,
//!   7 px off-centre. Error: the outgoing velocity of the moving ball against the closed form
//!   at first contact, as a share of the incoming speed, and the angle between them.
//! - Floors: an elastic ball (radius 10, gravity 0.5) bouncing on a flat floor segment and in a
//!   V valley of two segments, 10,000 frames: the largest relative change of its energy
//!   (kinetic + potential), and ns per ball-frame.
//!
//! Run: `cargo run --release --example exact_contacts`.

use std::time::Instant;

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::effects::Effects;
use bouncing_ball::physics::floor::Floor;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::Integrator;
use bouncing_ball::physics::Simulation;
use bouncing_ball::physics::Vec2;
use bouncing_ball_lab::accuracy::lesson_effects;

const AIM: f64 = 7.0;
const REACH: f64 = 10.0;

/// The moving ball's outgoing velocity from the closed form at first contact (elastic).
fn closed_form(speed: f64) -> [f64; 2] {
    // b (mass 16) hits a (mass 36) at rest; at contact the normal from a to b is
    // (−√(R² − aim²), aim)/R.
    let n = [-(REACH * REACH - AIM * AIM).sqrt() / REACH, AIM / REACH];
    let approach = speed * n[0];
    let j = 2.0 * approach / (36.0 + 16.0);
    [speed - j * 36.0 * n[0], -j * 36.0 * n[1]]
}

fn scattering(speed: f64, motion: Motion) -> (f64, f64) {
    let along = (REACH * REACH - AIM * AIM).sqrt();
    let balls = vec![
        Ball::new(100.0, 100.0, 0.0, 0.0, 6.0, 0),
        Ball::new(100.0 - along - 0.6 * speed, 100.0 + AIM, speed, 0.0, 4.0, 0),
    ];
    let mut simulation = Simulation::new(balls, Effects::default(), motion, Some(1.0));
    for _ in 0..3 {
        simulation.step();
    }
    let b = &simulation.balls()[1];
    let want = closed_form(speed);
    let error = (b.vx - want[0]).hypot(b.vy - want[1]) / speed;
    let angle = (b.vy.atan2(b.vx) - want[1].atan2(want[0]))
        .abs()
        .to_degrees();
    (error, angle)
}

/// The lesson's box and gravity, elastic, with `floors` in it.
fn floors_effects(floors: Vec<Floor>) -> Effects {
    Effects {
        floors,
        ..lesson_effects(1.0)
    }
}

fn energy(ball: &Ball) -> f64 {
    0.5 * (ball.vx * ball.vx + ball.vy * ball.vy) - 0.5 * ball.y
}

fn floor_drift(effects: &Effects, motion: Motion) -> (f64, f64) {
    let mut ball = Ball::new(100.0, 40.0, 1.3, 0.0, 10.0, 0);
    let start = energy(&ball);
    let mut worst = 0.0f64;
    let started = Instant::now();
    for _ in 0..10_000 {
        motion.advance(&mut ball, effects);
        worst = worst.max((energy(&ball) - start).abs() / start.abs());
    }
    (worst, started.elapsed().as_nanos() as f64 / 10_000.0)
}

fn main() {
    let modes = [
        ("clamp, 1 substep", CollisionMode::Clamp, 1),
        ("clamp, 4 substeps", CollisionMode::Clamp, 4),
        ("clamp, 16 substeps", CollisionMode::Clamp, 16),
        ("exact", CollisionMode::Exact, 1),
    ];
    println!("ball-ball scattering (semi-implicit Euler), error of the outgoing velocity");
    println!("{:<20} {:>22} {:>22}", "mode", "5 px/frame", "15 px/frame");
    for (name, collisions, substeps) in modes {
        let motion = Motion {
            integrator: Integrator::SemiImplicitEuler,
            substeps,
            collisions,
            ..Motion::default()
        };
        let cells: Vec<String> = [5.0, 15.0]
            .map(|speed| {
                let (error, angle) = scattering(speed, motion);
                format!("{error:.2e} ({angle:.1}°)")
            })
            .into();
        println!("{name:<20} {:>22} {:>22}", cells[0], cells[1]);
    }
    // A floor with both ends free, and a valley whose sides end on the walls.
    let segment = |from: [f64; 2], to: [f64; 2]| Floor {
        from: Vec2::from(from),
        to: Vec2::from(to),
        damping: 1.0,
    };
    let flat = vec![segment([20.0, 210.0], [300.0, 210.0])];
    let valley = vec![
        segment([0.0, 80.0], [150.0, 230.0]),
        segment([150.0, 230.0], [320.0, 90.0]),
    ];
    println!();
    println!(
        "elastic ball on floors, 10,000 frames: largest relative energy change, ns/ball-frame"
    );
    for (place, floors) in [("flat floor", flat), ("V valley", valley)] {
        let effects = floors_effects(floors);
        for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
            for (name, collisions, substeps) in modes {
                let motion = Motion {
                    integrator,
                    substeps,
                    collisions,
                    ..Motion::default()
                };
                let (drift, ns) = floor_drift(&effects, motion);
                println!(
                    "{place:<11} {:<15} {name:<20} {drift:>10.2e} {ns:>8.0}",
                    format!("{integrator:?}")
                );
            }
        }
    }
}
