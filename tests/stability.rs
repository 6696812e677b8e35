//! Hard cases for the integrators, substeps and collision modes, each with an asserted bound:
//! fast balls, corners, resting contact, long elastic runs, extreme magnitudes and drag.
//! Also slopes and ball-ball contacts. (Zeno's bounces ending in rest are in `tests/accuracy.rs`.)

mod common;

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::effects::Effects;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::walls::Walls;
use bouncing_ball::physics::Integrator;
use bouncing_ball::physics::Vec2;
use bouncing_ball_lab::accuracy::{bounces, lesson_effects, FLOOR, GRAVITY, RADIUS};

const INTEGRATORS: [Integrator; 4] = [
    Integrator::ExplicitEuler,
    Integrator::SemiImplicitEuler,
    Integrator::VelocityVerlet,
    Integrator::Rk4,
];
const MODES: [CollisionMode; 2] = [CollisionMode::Clamp, CollisionMode::Exact];

/// Every integrator × collision mode × these substeps.
fn motions(substeps: &[u32]) -> Vec<Motion> {
    let mut all = Vec::new();
    for integrator in INTEGRATORS {
        for collisions in MODES {
            for &substeps in substeps {
                all.push(Motion {
                    integrator,
                    substeps,
                    collisions,
                    ..Motion::default()
                });
            }
        }
    }
    all
}

fn boxed(width: f64, height: f64, damping: f64, gravity: Option<Vec2>) -> Effects {
    Effects {
        gravity,
        walls: Some(Walls {
            width,
            height,
            damping,
        }),
        ..Effects::default()
    }
}

/// Asserts the ball is finite and inside its box to 1e-9 px.
fn assert_inside(ball: &Ball, walls: &Walls, what: &str) {
    let finite = [ball.x, ball.y, ball.vx, ball.vy]
        .iter()
        .all(|v| v.is_finite());
    assert!(finite, "{what}: expected a finite state, got {ball:?}");
    let r = ball.radius - 1e-9;
    let inside =
        ball.x >= r && ball.x <= walls.width - r && ball.y >= r && ball.y <= walls.height - r;
    assert!(
        inside,
        "{what}: expected the centre within [{r}, {}] × [{r}, {}], got ({}, {})",
        walls.width - r,
        walls.height - r,
        ball.x,
        ball.y
    );
}

/// Runs `frames` frames, checking after each that the ball is finite and inside.
fn run_inside(motion: Motion, effects: &Effects, mut ball: Ball, frames: u32, what: &str) -> Ball {
    let walls = effects.walls.expect("a boxed scene");
    for frame in 0..frames {
        motion.advance(&mut ball, effects);
        assert_inside(&ball, &walls, &format!("{what}, {motion:?}, frame {frame}"));
    }
    ball
}

#[test]
fn a_ball_crossing_ten_canvases_a_frame_stays_inside_and_never_speeds_up_beyond_gravity() {
    // Walls only shrink speed (damping ≤ 1) and there is no sideways gravity, so |vx| never
    // grows; |vy| grows by at most g a frame (plus rounding: RK4 adds g in four parts).
    let effects = lesson_effects(0.88);
    let walls = effects.walls.unwrap();
    for motion in motions(&[1, 8]) {
        let mut ball = Ball::new(160.0, 120.0, 3200.0, 2400.0, RADIUS, 0);
        for frame in 0..1000 {
            let (vx, vy) = (ball.vx.abs(), ball.vy.abs());
            motion.advance(&mut ball, &effects);
            let what = format!("{motion:?}, frame {frame}");
            assert_inside(&ball, &walls, &what);
            assert!(
                ball.vx.abs() <= vx,
                "{what}: expected |vx| ≤ {vx}, got {}",
                ball.vx.abs()
            );
            assert!(
                ball.vy.abs() <= vy + GRAVITY + 1e-12,
                "{what}: expected |vy| ≤ {} + 1e-12, got {}",
                vy + GRAVITY,
                ball.vy.abs()
            );
        }
    }
}

#[test]
fn a_corner_hit_reflects_each_velocity_component_exactly_once() {
    // From (300, 215) at (10, 15) px/frame with no gravity, the ball reaches x 308 at t = 0.8
    // and y 228 at t = 0.867: both walls in one frame.
    let effects = boxed(320.0, 240.0, 1.0, None);
    for motion in motions(&[1]) {
        let mut ball = Ball::new(300.0, 215.0, 10.0, 15.0, RADIUS, 0);
        motion.advance(&mut ball, &effects);
        assert_eq!(
            (ball.vx, ball.vy),
            (-10.0, -15.0),
            "{motion:?}: expected velocity (-10, -15), got ({}, {})",
            ball.vx,
            ball.vy
        );
        // Clamp puts the ball on both walls; exact flies it back for the rest of the frame.
        let expected = match motion.collisions {
            CollisionMode::Clamp => (308.0, 228.0),
            CollisionMode::Exact => (306.0, 226.0),
        };
        let off = (ball.x - expected.0).hypot(ball.y - expected.1);
        assert!(
            off < 1e-12,
            "{motion:?}: expected position {expected:?}, got ({}, {})",
            ball.x,
            ball.y
        );
    }
}

#[test]
fn a_resting_ball_never_sinks_and_its_clamp_jitter_stays_under_the_derived_bound() {
    // Clamp, semi-implicit Euler: a ball on the floor ending a frame at vy = −a gets
    // vy = g − a, would sink, is clamped and reflected: a' = e·(g − a). The fixed point is
    // a = e·g/(1 + e), so after settling the ball stays on the floor line with |vy| ≤ that.
    let e = 0.88;
    let bound = e * GRAVITY / (1.0 + e);
    let effects = lesson_effects(e);
    for motion in motions(&[1]) {
        let mut ball = Ball::new(160.0, 40.0, 0.0, 0.0, RADIUS, 0);
        for frame in 0..1_000_000 {
            motion.advance(&mut ball, &effects);
            assert!(
                ball.y <= FLOOR,
                "{motion:?}, frame {frame}: expected y ≤ {FLOOR}, got {}",
                ball.y
            );
        }
        match (motion.collisions, motion.integrator) {
            (CollisionMode::Exact, _) => assert!(
                ball.y == FLOOR && ball.vy == 0.0,
                "{motion:?}: expected exact rest at y {FLOOR}, vy 0; got y {}, vy {}",
                ball.y,
                ball.vy
            ),
            (CollisionMode::Clamp, Integrator::SemiImplicitEuler) => assert!(
                ball.y == FLOOR && ball.vy.abs() <= bound + 1e-12,
                "{motion:?}: expected y {FLOOR} and |vy| ≤ {bound}; got y {}, vy {}",
                ball.y,
                ball.vy
            ),
            _ => {}
        }
    }
}

#[test]
fn an_elastic_exact_ball_keeps_its_apex_for_a_million_frames() {
    // Dropped from y 40 at 0.3 px/frame: apex 188 + 0.3²/2g px above the floor, forever.
    let expected = (FLOOR - 40.0) + 0.3 * 0.3 / (2.0 * GRAVITY);
    for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
        let motion = Motion {
            integrator,
            collisions: CollisionMode::Exact,
            ..Motion::default()
        };
        let worst = bounces(motion, 1.0, 40.0, 0.3, 1_000_000)
            .iter()
            .map(|b| (b.flight_apex - expected).abs() / expected)
            .fold(0.0, f64::max);
        assert!(
            worst < 1e-9,
            "{integrator:?}: expected every apex within 1e-9 of {expected}, worst {worst:e}"
        );
    }
}

#[test]
fn without_gravity_an_elastic_ball_keeps_its_speed_to_the_bit() {
    // Reflection only flips signs, and no integrator changes a velocity without a force.
    let effects = boxed(320.0, 240.0, 1.0, None);
    for motion in motions(&[1, 3]) {
        let ball = Ball::new(100.0, 100.0, 7.3, -4.1, RADIUS, 0);
        let ball = run_inside(motion, &effects, ball, 100_000, "no gravity");
        assert_eq!(
            (ball.vx.abs(), ball.vy.abs()),
            (7.3, 4.1),
            "{motion:?}: expected speeds (7.3, 4.1), got ({}, {})",
            ball.vx.abs(),
            ball.vy.abs()
        );
    }
}

#[test]
fn extreme_magnitudes_stay_finite_and_inside() {
    let lesson = |gravity| boxed(320.0, 240.0, 0.88, Some(Vec2::new(0.0, gravity)));
    let cases = [
        (
            "gravity 1e-12",
            lesson(1e-12),
            Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0),
        ),
        (
            "gravity 1e6",
            lesson(1e6),
            Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0),
        ),
        (
            "speed 1e9",
            lesson(0.5),
            Ball::new(40.0, 40.0, 1e9, -1e9, RADIUS, 0),
        ),
        (
            "2·radius just under the width",
            boxed(100.0, 300.0, 0.88, Some(Vec2::new(0.0, 0.5))),
            Ball::new(50.0, 100.0, 3.0, 0.0, 49.999_999, 0),
        ),
        (
            "a 1-px ball in an 8192 canvas",
            boxed(8192.0, 8192.0, 0.88, Some(Vec2::new(0.0, 0.5))),
            Ball::new(4000.0, 100.0, 37.3, -12.9, 0.5, 0),
        ),
    ];
    for (what, effects, ball) in cases {
        for motion in motions(&[1, 4]) {
            run_inside(motion, &effects, ball.clone(), 2000, what);
        }
    }
}

#[test]
fn drag_1_stops_the_ball_within_its_first_frame_and_it_never_moves_again() {
    let effects = Effects {
        drag: Some(1.0),
        ..lesson_effects(0.88)
    };
    for motion in motions(&[1, 4]) {
        let mut ball = Ball::new(100.0, 100.0, 5.2, -3.0, RADIUS, 0);
        motion.advance(&mut ball, &effects);
        assert_eq!(
            (ball.vx, ball.vy),
            (0.0, 0.0),
            "{motion:?}: expected no velocity after one frame, got ({}, {})",
            ball.vx,
            ball.vy
        );
        let stopped = (ball.x, ball.y);
        let ball = run_inside(motion, &effects, ball, 100, "drag 1");
        assert_eq!(
            (ball.x, ball.y),
            stopped,
            "{motion:?}: expected the ball to stay at {stopped:?}"
        );
    }
}

#[test]
fn drag_0_changes_no_bit_of_the_motion() {
    let without = lesson_effects(0.88);
    let with = Effects {
        drag: Some(0.0),
        ..lesson_effects(0.88)
    };
    for motion in motions(&[1, 4]) {
        let (mut a, mut b) = (
            Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0),
            Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0),
        );
        for frame in 0..1000 {
            motion.advance(&mut a, &without);
            motion.advance(&mut b, &with);
            assert_eq!(
                a, b,
                "{motion:?}, frame {frame}: drag 0 must change nothing"
            );
        }
    }
}

#[test]
fn strong_drag_takes_the_same_steps_whether_or_not_the_frame_is_already_split() {
    // Verlet and RK4 treat drag as a force, which overshoots once a step's λ·dt passes 2, so
    // a step never takes more than λ·dt = 1: drag 0.99 (λ = 4.6 a frame) needs 5 steps a
    // frame. 2 sub-steps (λ 2.3 each) become 3 steps each, and 6 sub-steps (λ 0.77) need no
    // more: both are 6 steps of a sixth of a frame, so they move the ball to the same bit.
    let effects = Effects {
        drag: Some(0.99),
        ..lesson_effects(0.88)
    };
    for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
        let split = |substeps| Motion {
            integrator,
            substeps,
            ..Motion::default()
        };
        let (mut two, mut six) = (
            Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0),
            Ball::new(40.0, 40.0, 5.2, 0.0, RADIUS, 0),
        );
        for frame in 0..100 {
            split(2).advance(&mut two, &effects);
            split(6).advance(&mut six, &effects);
            assert_eq!(
                two, six,
                "{integrator:?}, frame {frame}: 2 sub-steps of 3 steps and 6 of 1 differ"
            );
        }
    }
}

#[test]
fn drag_without_gravity_slows_the_ball_as_the_closed_form_says() {
    // No gravity, no walls: v(n) = v0·(1 − drag)^n along the same line.
    let drag = 0.002;
    let effects = Effects {
        drag: Some(drag),
        ..Effects::default()
    };
    for motion in motions(&[1, 4]) {
        let mut ball = Ball::new(0.0, 0.0, 5.2, -3.0, RADIUS, 0);
        for _ in 0..1000 {
            motion.advance(&mut ball, &effects);
        }
        let keep = (1.0 - drag).powi(1000);
        for (v, v0) in [(ball.vx, 5.2), (ball.vy, -3.0)] {
            let expected = v0 * keep;
            assert!(
                ((v - expected) / expected).abs() < 1e-6,
                "{motion:?}: expected velocity {expected}, got {v}"
            );
        }
    }
}

#[test]
fn a_fast_ball_at_a_steep_slope_does_not_tunnel_and_a_resting_one_does_not_sink() {
    use bouncing_ball::physics::floor::Floor;
    // A 60° slope from the top wall to the bottom wall, so no ball can go around its ends;
    // balls thrown at it at up to 30 diameters per frame.
    let slope = Floor {
        from: Vec2::new(330.0, 0.0),
        to: Vec2::new(100.0, 400.0),
        damping: 0.88,
    };
    let side = |b: &Ball| {
        let (dx, dy) = (slope.to.x - slope.from.x, slope.to.y - slope.from.y);
        ((b.x - slope.from.x) * dy - (b.y - slope.from.y) * dx) / dx.hypot(dy)
    };
    let effects = Effects {
        floors: vec![slope],
        ..boxed(400.0, 400.0, 0.88, Some(Vec2::new(0.0, 0.5)))
    };
    for (vx, vy) in [(300.0, 40.0), (150.0, 150.0), (250.0, -100.0)] {
        let mut ball = Ball::new(60.0, 150.0, vx, vy, 5.0, 0);
        let start_side = side(&ball).signum();
        for frame in 1..=2000 {
            Motion::default().advance(&mut ball, &effects);
            let distance = side(&ball) * start_side;
            // Within the segment's extent the centre keeps at least a radius on its side.
            assert!(
                distance > 0.0,
                "throw ({vx}, {vy}), frame {frame}: crossed the slope, signed distance {distance}"
            );
        }
        assert!(
            side(&ball).abs() >= 5.0 - 1e-9,
            "throw ({vx}, {vy}): sunk into the slope: distance {}",
            side(&ball)
        );
    }
}

mod ball_ball {
    use bouncing_ball::physics::tolerances::SLOP;
    use bouncing_ball::scene::random::Random;
    use bouncing_ball::Scene;
    use bouncing_ball_lab::accuracy::{deepest_overlap, kinetic_energy};

    use crate::common::white_ball as spec;

    /// Two balls closing at 10 diameters per frame: with 20 substeps each substep closes one
    /// diameter, less than the sum of the radii, so the overlap is seen and resolved.
    #[test]
    fn a_head_on_pair_at_ten_diameters_per_frame_bounces_back_with_substeps() {
        let balls = vec![
            spec(100.0, 120.0, 50.0, 0.0, 5.0),
            spec(530.0, 120.0, -50.0, 0.0, 5.0),
        ];
        let scene = Scene {
            balls,
            walls: Some(1.0),
            ball_collisions: Some(1.0),
            motion: bouncing_ball::physics::motion::Motion {
                substeps: 20,
                ..Default::default()
            },
            ..Scene::empty(600, 240)
        };
        let mut simulation = scene.simulation();
        for frame in 1..=6 {
            simulation.step();
            let [a, b] = [&simulation.balls()[0], &simulation.balls()[1]];
            assert!(
                a.x < b.x,
                "frame {frame}: the left ball must stay left of the right one: {} vs {}",
                a.x,
                b.x
            );
        }
        let [a, b] = [&simulation.balls()[0], &simulation.balls()[1]];
        assert!(
            a.vx < 0.0 && b.vx > 0.0,
            "they bounced back: vx = {} and {}",
            a.vx,
            b.vx
        );
    }

    #[test]
    fn balls_spawned_at_one_centre_separate_and_never_stick() {
        let balls = (0..20).map(|_| spec(160.0, 120.0, 0.0, 0.0, 6.0)).collect();
        let scene = Scene {
            balls,
            walls: Some(1.0),
            ball_collisions: Some(0.9),
            ..Scene::empty(320, 240)
        };
        let mut simulation = scene.simulation();
        for frame in 1..=500 {
            simulation.step();
            let overlap = deepest_overlap(simulation.balls()) / 6.0;
            assert!(overlap.is_finite(), "frame {frame}: overlap must be finite");
            // The contact solver leaves overlaps up to its slop alone.
            let allowed = SLOP * (1.0 + 1e-9);
            if frame >= 100 {
                assert!(overlap <= allowed, "frame {frame}: separated by frame 100: deepest overlap bound {allowed} r, got {overlap}");
            }
        }
        let energy = kinetic_energy(simulation.balls());
        assert_eq!(
            energy, 0.0,
            "pushing apart sets nothing moving: kinetic energy expected 0, got {energy}"
        );
    }

    /// 1,000 balls covering half the box, restitution 0.9, elastic walls, no gravity.
    ///
    /// Bound on overlap, after every frame: the contact solver stops each pair it finds at
    /// the touching point, and a pair it did not find (a ball struck within the step runs
    /// into a neighbour it was not heading for) is set apart at the end of the step, so
    /// overlap comes only from what its iterations leave unsolved; we assert 0.05 r
    /// (measured in docs/contacts.md).
    #[test]
    fn a_thousand_balls_packed_at_half_the_area_stay_finite_bounded_and_lose_energy() {
        let mut random = Random::new(7);
        let radius = 4.0;
        // 1,000 × π × 4² ≈ 50,265 px² of balls in a 317 × 317 box ≈ half of it.
        let side_px = (1000.0 * std::f64::consts::PI * radius * radius / 0.5f64)
            .sqrt()
            .ceil();
        let per_row = 32;
        let spacing = side_px / per_row as f64;
        let balls = (0..1000)
            .map(|i| {
                let x = ((i % per_row) as f64 + 0.5) * spacing;
                let y = ((i / per_row) as f64 + 0.5) * spacing;
                let (vx, vy) = (random.range(-0.7, 0.7), random.range(-0.7, 0.7));
                spec(x, y, vx, vy, radius)
            })
            .collect();
        let scene = Scene {
            balls,
            walls: Some(1.0),
            ball_collisions: Some(0.9),
            ..Scene::empty(side_px as u32, side_px as u32)
        };
        scene.validate().expect("a valid packed scene");
        let mut simulation = scene.simulation();
        let mut energy = kinetic_energy(simulation.balls());
        let mut worst = 0.0f64;
        for frame in 1..=10_000 {
            simulation.step();
            let balls = simulation.balls();
            assert!(
                balls
                    .iter()
                    .all(|b| [b.x, b.y, b.vx, b.vy].iter().all(|v| v.is_finite())),
                "frame {frame}: NaN or infinity"
            );
            let now = kinetic_energy(balls);
            assert!(
                now <= energy * (1.0 + 1e-12),
                "frame {frame}: kinetic energy rose from {energy} to {now}"
            );
            energy = now;
            worst = worst.max(deepest_overlap(balls) / radius);
        }
        println!("deepest overlap after any frame: {worst:e} r");
        assert!(
            worst <= 0.05,
            "deepest overlap bound 0.05 radius, got {worst}"
        );
    }
}
