//! Property tests over random scenes within the allowed ranges: whatever the balls, forces,
//! floors, ball-ball collisions, integrator, substeps, iterations and collision mode, the state stays finite, every ball stays
//! in its box, energy obeys its bound, and two runs give the same bits.

use bouncing_ball::physics::floor::Floor;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::simulation::Simulation;
use bouncing_ball::physics::Integrator;
use bouncing_ball::physics::Vec2;
use bouncing_ball::scene::Named;
use bouncing_ball::{BallSpec, Scene};
use proptest::prelude::*;

fn ball_in(width: f64, height: f64) -> impl Strategy<Value = BallSpec> {
    let max_radius = (width.min(height) / 2.0 - 0.5).max(0.6);
    (
        0.5..max_radius,
        0.0..1.0f64,
        0.0..1.0f64,
        -60.0..60.0f64,
        -60.0..60.0f64,
    )
        .prop_map(move |(radius, fx, fy, vx, vy)| BallSpec {
            x: radius + fx * (width - 2.0 * radius),
            y: radius + fy * (height - 2.0 * radius),
            vx,
            vy,
            radius,
            colour: [255, 200, 60],
            trail_colour: [60, 140, 255],
            trail: 3,
        })
}

fn floor_in(width: f64, height: f64) -> impl Strategy<Value = Floor> {
    (
        0.0..width,
        0.0..height,
        0.0..width,
        0.0..height,
        0.0..=1.0f64,
    )
        .prop_filter("a segment has length", |(x0, y0, x1, y1, _)| {
            (x1 - x0).hypot(y1 - y0) > 1.0
        })
        .prop_map(|(x0, y0, x1, y1, damping)| Floor {
            from: Vec2::new(x0, y0),
            to: Vec2::new(x1, y1),
            damping,
        })
}

fn motion() -> impl Strategy<Value = Motion> {
    (
        proptest::sample::select(Integrator::all()),
        1..=4u32,
        proptest::sample::select(CollisionMode::all()),
        1..=12u32,
    )
        .prop_map(|(integrator, substeps, collisions, iterations)| Motion {
            integrator,
            substeps,
            collisions,
            iterations,
        })
}

/// A random valid scene in a box, with or without ball-ball collisions; `with_floors` adds
/// up to three random segments.
fn scene(with_floors: bool) -> impl Strategy<Value = Scene> {
    (20u32..600, 20u32..600).prop_flat_map(move |(w, h)| {
        let (width, height) = (f64::from(w), f64::from(h));
        (
            proptest::collection::vec(ball_in(width, height), 1..5),
            proptest::option::of((-3.0..3.0f64, -3.0..3.0f64)),
            proptest::option::of(0.0..=1.0f64),
            0.0..=1.0f64,
            proptest::collection::vec(floor_in(width, height), 0..if with_floors { 4 } else { 1 }),
            motion(),
            proptest::option::of(0.0..=1.0f64),
        )
            .prop_map(
                move |(balls, gravity, drag, damping, floors, motion, restitution)| Scene {
                    balls,
                    gravity: gravity.map(|(gx, gy)| Vec2::new(gx, gy)),
                    drag,
                    walls: Some(damping),
                    floors,
                    ball_collisions: restitution,
                    motion,
                    frames: 150,
                    ..Scene::empty(w, h)
                },
            )
    })
}

/// Total energy: kinetic plus gravitational potential, masses ∝ radius².
fn energy(simulation: &Simulation, gravity: Vec2) -> f64 {
    simulation
        .balls()
        .iter()
        .map(|b| {
            let mass = b.radius * b.radius;
            mass * (0.5 * (b.vx * b.vx + b.vy * b.vy) - (gravity.x * b.x + gravity.y * b.y))
        })
        .sum()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn every_ball_stays_finite_and_inside_its_box(scene in scene(true)) {
        let mut simulation = scene.simulation();
        let (w, h) = (f64::from(scene.width), f64::from(scene.height));
        for frame in 0..scene.frames {
            simulation.step();
            for (i, b) in simulation.balls().iter().enumerate() {
                prop_assert!([b.x, b.y, b.vx, b.vy].iter().all(|v| v.is_finite()), "frame {}: ball {} not finite: {:?}", frame, i, b);
                let tolerance = 1e-9 * w.max(h);
                prop_assert!(
                    b.x >= b.radius - tolerance && b.x <= w - b.radius + tolerance && b.y >= b.radius - tolerance && b.y <= h - b.radius + tolerance,
                    "frame {}: ball {} at ({}, {}) r {} outside the {}×{} box", frame, i, b.x, b.y, b.radius, w, h
                );
            }
        }
    }

    /// Clamp mode can *gain* energy: the clamp lifts a ball that sank by δ against gravity,
    /// worth m·|g|·δ, and δ is at most one frame's travel, (|v| + |g|) px. Reflections with
    /// damping ≤ 1 and drag only take energy away. So per frame:
    /// E(n+1) ≤ E(n) + Σ m·|g|·(|v(n)| + |g|).
    #[test]
    fn energy_never_rises_by_more_than_the_clamp_bound(scene in scene(false)) {
        // Without ball-ball contacts: pushing two overlapping balls apart under gravity can lift
        // one of them, which is the same kind of gain and has its own tests (tests/collisions.rs).
        let scene = Scene { motion: Motion { collisions: CollisionMode::Clamp, ..scene.motion }, ball_collisions: None, ..scene };
        let gravity = scene.gravity.unwrap_or(Vec2::ZERO);
        let g = gravity.x.hypot(gravity.y);
        let mut simulation = scene.simulation();
        let mut before = energy(&simulation, gravity);
        for frame in 0..scene.frames {
            let allowance: f64 = simulation.balls().iter().map(|b| b.radius * b.radius * g * (b.vx.hypot(b.vy) + g)).sum();
            simulation.step();
            let after = energy(&simulation, gravity);
            let bound = before + allowance + 1e-9 * before.abs().max(1.0);
            prop_assert!(after <= bound, "frame {}: energy bound {}, got {}", frame, bound, after);
            before = after;
        }
    }

    /// Exact mode with an integrator that is exact for constant gravity (velocity Verlet,
    /// RK4), damping ≤ 1 and nothing that adds energy (no drag, floors or ball contacts):
    /// bounces happen at the true time of impact, so total energy never rises (to rounding).
    #[test]
    fn energy_never_rises_in_exact_mode(scene in scene(false), rk4 in any::<bool>()) {
        let integrator = if rk4 { Integrator::Rk4 } else { Integrator::VelocityVerlet };
        let motion = Motion { integrator, collisions: CollisionMode::Exact, ..scene.motion };
        let scene = Scene { motion, drag: None, ball_collisions: None, ..scene };
        let gravity = scene.gravity.unwrap_or(Vec2::ZERO);
        let mut simulation = scene.simulation();
        let mut before = energy(&simulation, gravity);
        let scale: f64 = simulation.balls().iter().map(|b| b.radius * b.radius * (b.vx.hypot(b.vy).powi(2) + 1.0 + gravity.x.hypot(gravity.y) * 600.0)).sum();
        for frame in 0..scene.frames {
            simulation.step();
            let after = energy(&simulation, gravity);
            prop_assert!(after <= before + 1e-9 * scale, "frame {}: energy rose from {} to {}", frame, before, after);
            before = after;
        }
    }

    #[test]
    fn the_same_scene_gives_the_same_bits_twice(scene in scene(true)) {
        let (mut a, mut b) = (scene.simulation(), scene.simulation());
        for _ in 0..scene.frames {
            a.step();
            b.step();
        }
        for (x, y) in a.balls().iter().zip(b.balls()) {
            prop_assert_eq!([x.x, x.y, x.vx, x.vy].map(f64::to_bits), [y.x, y.y, y.vx, y.vy].map(f64::to_bits));
        }
    }
}
