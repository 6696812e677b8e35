//! The accuracy options measured against closed-form physics: exact bounces, convergence
//! orders, the lesson's default kept bit for bit, Zeno's bounces ending in rest, and the
//! arithmetic behind the lost apex of clamp-then-reflect.

mod common;

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::tolerances::REST_SPEED;
use bouncing_ball::physics::Integrator;
use bouncing_ball_lab::accuracy::{
    apex_height, bounces, fitted_order, free_flight_error, lesson_effects, FLOOR, GRAVITY, RADIUS,
    WIDTH,
};

/// Released from rest at y 40: 188 px above the floor's contact line.
const DROP: f64 = FLOOR - 40.0;

fn motion(integrator: Integrator, substeps: u32, collisions: CollisionMode) -> Motion {
    Motion {
        integrator,
        substeps,
        collisions,
        ..Motion::default()
    }
}

const CURVED: [Integrator; 2] = [Integrator::VelocityVerlet, Integrator::Rk4];

#[test]
fn exact_bounces_reach_the_closed_form_apex_heights() {
    for integrator in CURVED {
        for e in [0.3, 0.5, 0.8, 0.95] {
            let found = bounces(
                motion(integrator, 1, CollisionMode::Exact),
                e,
                40.0,
                0.0,
                2000,
            );
            // Bounce k rebounds at e^k·√(2gh); the first one slower than REST_SPEED rests.
            let impact = (2.0 * GRAVITY * DROP).sqrt();
            let expected_count = (1..)
                .take_while(|&k| e.powi(k) * impact >= REST_SPEED)
                .count();
            assert_eq!(
                found.len(),
                expected_count,
                "{integrator:?}, e = {e}: expected {expected_count} bounces before rest, got {}",
                found.len()
            );
            for (k, bounce) in (1..).zip(&found) {
                let expected = apex_height(DROP, e, k);
                let relative = (bounce.flight_apex - expected).abs() / expected;
                assert!(
                    relative < 1e-9,
                    "{integrator:?}, e = {e}, bounce {k}: expected apex {expected} px, got {} \
                     (relative error {relative:e})",
                    bounce.flight_apex
                );
            }
        }
    }
}

#[test]
fn fitted_convergence_orders_match_the_textbook() {
    // Free flight with drag 0.01 for 200 frames, substeps 1 to 64; points closer than 1e-10 px
    // to the closed form are rounding, not truncation, and are left out of the fit.
    for (integrator, textbook) in [
        (Integrator::ExplicitEuler, 1.0),
        (Integrator::SemiImplicitEuler, 1.0),
        (Integrator::VelocityVerlet, 2.0),
        (Integrator::Rk4, 4.0),
    ] {
        let points: Vec<(f64, f64)> = [1, 2, 4, 8, 16, 32, 64]
            .iter()
            .map(|&n| {
                let m = motion(integrator, n, CollisionMode::Clamp);
                (1.0 / f64::from(n), free_flight_error(m, 0.01, 200))
            })
            .filter(|&(_, error)| error > 1e-10)
            .collect();
        assert!(
            points.len() >= 3,
            "{integrator:?}: expected at least 3 points above rounding, got {points:?}"
        );
        let order = fitted_order(&points);
        assert!(
            (order - textbook).abs() <= 0.2,
            "{integrator:?}: expected order {textbook} ± 0.2, fitted {order} from {points:?}"
        );
    }
}

#[test]
fn the_lesson_default_still_matches_the_reference_trajectory_bit_for_bit() {
    let scene = common::lesson_scene();
    assert_eq!(
        scene.motion,
        Motion::default(),
        "the lesson's scene uses the default"
    );
    let mut simulation = scene.simulation();
    let reference = include_str!("data/lesson_trajectory.txt");
    for (frame, line) in reference.lines().enumerate() {
        simulation.step();
        let b = &simulation.balls()[0];
        let expected: Vec<f64> = line.split(' ').map(|v| v.parse().unwrap()).collect();
        let ours = [b.x, b.y, b.vx, b.vy];
        let same_bits = ours
            .iter()
            .zip(&expected)
            .all(|(a, b)| a.to_bits() == b.to_bits());
        assert!(
            same_bits,
            "frame {frame}: expected {expected:?}, got {ours:?}"
        );
    }
}

#[test]
fn a_damped_ball_in_exact_mode_comes_to_rest_before_zenos_time() {
    // Zeno: infinitely many bounces end at t∞ = √(2h/g)·(1+e)/(1−e). The rest rule cuts off
    // bounces slower than REST_SPEED, whose flights add up to less than 2·REST_SPEED/(g(1−e)).
    let e = 0.5;
    let t_infinity = (2.0 * DROP / GRAVITY).sqrt() * (1.0 + e) / (1.0 - e);
    let margin = 2.0 * REST_SPEED / (GRAVITY * (1.0 - e));
    for integrator in [
        Integrator::ExplicitEuler,
        Integrator::SemiImplicitEuler,
        Integrator::VelocityVerlet,
        Integrator::Rk4,
    ] {
        let effects = lesson_effects(e);
        let mut ball = Ball::new(WIDTH / 2.0, 40.0, 0.0, 0.0, RADIUS, 0);
        let m = motion(integrator, 1, CollisionMode::Exact);
        let rested = (1..=1000u32).find(|_| {
            m.advance(&mut ball, &effects);
            ball.y == FLOOR && ball.vy == 0.0
        });
        let rested = rested.map(f64::from);
        assert!(
            rested.is_some_and(|t| t >= t_infinity - margin - 1.0 && t <= t_infinity + 1.0),
            "{integrator:?}: expected rest between frame {} and {}, got {rested:?}",
            t_infinity - margin - 1.0,
            t_infinity + 1.0
        );
        for frame in 0..1000 {
            m.advance(&mut ball, &effects);
            assert!(
                ball.y == FLOOR && ball.vy == 0.0,
                "{integrator:?}: {frame} frames after resting, expected y {FLOOR} and vy 0, \
                 got y {} and vy {}",
                ball.y,
                ball.vy
            );
        }
    }
}

#[test]
fn an_elastic_ball_in_exact_mode_keeps_its_apex_for_100000_frames() {
    for integrator in CURVED {
        let found = bounces(
            motion(integrator, 1, CollisionMode::Exact),
            1.0,
            40.0,
            0.3,
            100_000,
        );
        // From y 40 moving down at 0.3 px/frame: apex 188 + 0.3²/2g above the floor.
        let expected = DROP + 0.3 * 0.3 / (2.0 * GRAVITY);
        assert!(
            found.len() > 1000,
            "expected over 1000 bounces, got {}",
            found.len()
        );
        for (k, bounce) in found.iter().enumerate() {
            let relative = (bounce.flight_apex - expected).abs() / expected;
            assert!(
                relative < 1e-9,
                "{integrator:?}, bounce {k}: expected apex {expected}, got {} (relative {relative:e})",
                bounce.flight_apex
            );
        }
    }
}

#[test]
fn an_elastic_clamp_bounce_with_semi_implicit_euler_loses_exactly_the_gap_to_the_floor() {
    // Semi-implicit Euler's positions under gravity lie on a parabola whose apex is
    // y − (vy + g/2)²/2g. Clamp-then-reflect keeps |vy + g/2| but moves the ball from y down
    // to the floor, so that apex sinks by exactly the gap FLOOR − y at the bounce frame's start.
    let apex = |b: &Ball| b.y - (b.vy + GRAVITY / 2.0).powi(2) / (2.0 * GRAVITY);
    let effects = lesson_effects(1.0);
    let mut ball = Ball::new(WIDTH / 2.0, 40.0, 0.0, 0.3, RADIUS, 0);
    let mut checked = 0;
    for _ in 0..3000 {
        let (before, gap) = (apex(&ball), FLOOR - ball.y);
        let vy_before = ball.vy;
        Motion::default().advance(&mut ball, &effects);
        let expected = if ball.vy < vy_before {
            before + gap
        } else {
            before
        };
        assert!(
            (apex(&ball) - expected).abs() < 1e-9,
            "expected the parabola's apex at y {expected}, got {}",
            apex(&ball)
        );
        checked += usize::from(ball.vy < vy_before);
    }
    assert!(checked > 50, "expected over 50 bounces, got {checked}");
}

#[test]
fn the_lesson_ball_released_at_rest_settles_at_apex_52_5_under_clamp() {
    // The first bounce frame starts 12.5 px above the floor (y 215.5); every later one starts
    // exactly on it, so nothing more is lost.
    let found = bounces(Motion::default(), 1.0, 40.0, 0.0, 1500);
    for bounce in &found[..found.len() - 1] {
        let seen = FLOOR - bounce.seen_apex;
        assert!(
            (seen - 52.5).abs() < 1e-9,
            "bounce at frame {}: expected apex y 52.5, got {seen}",
            bounce.frame
        );
    }
}
