//! The named hard cases of the stability suite (clamp mode, the lesson's physics). Each test
//! asserts a bound and prints the bound and the value seen; "it did not panic" is not enough.

use bouncing_ball::ball::Ball;
use bouncing_ball::effects::Effects;
use bouncing_ball::motion::Motion;
use bouncing_ball::walls::Walls;

fn boxed(width: f64, height: f64, damping: f64, gravity: Option<[f64; 2]>) -> Effects {
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

fn with_substeps(substeps: u32) -> Motion {
    Motion {
        substeps,
        ..Motion::default()
    }
}

/// Fails unless the ball is finite and inside the `width` × `height` box (to 1e-9).
fn assert_inside(ball: &Ball, width: f64, height: f64, context: &str) {
    let finite = [ball.x, ball.y, ball.vx, ball.vy]
        .iter()
        .all(|v| v.is_finite());
    assert!(finite, "{context}: state must be finite: {ball:?}");
    let r = ball.radius;
    let tolerance = 1e-9 * width.max(height);
    let inside = ball.x >= r - tolerance
        && ball.x <= width - r + tolerance
        && ball.y >= r - tolerance
        && ball.y <= height - r + tolerance;
    assert!(
        inside,
        "{context}: centre must be within [{r}, {}] × [{r}, {}], got ({}, {})",
        width - r,
        height - r,
        ball.x,
        ball.y
    );
}

#[test]
fn case_1_a_ball_ten_canvases_per_frame_stays_inside_and_never_gains_speed() {
    for substeps in [1, 10] {
        let effects = boxed(320.0, 240.0, 0.88, Some([0.0, 0.5]));
        let mut ball = Ball::new(160.0, 120.0, 3200.0, -2400.0, 12.0, 0);
        let (vx0, vy0) = (ball.vx.abs(), ball.vy.abs());
        for frame in 1..=1000u32 {
            ball.step(&effects, &with_substeps(substeps));
            assert_inside(
                &ball,
                320.0,
                240.0,
                &format!("substeps {substeps}, frame {frame}"),
            );
            // Reflection only scales a component by damping ≤ 1; gravity adds at most g per frame.
            let vy_bound = vy0 + 0.5 * f64::from(frame);
            assert!(
                ball.vx.abs() <= vx0,
                "frame {frame}: |vx| bound {vx0}, got {}",
                ball.vx.abs()
            );
            assert!(
                ball.vy.abs() <= vy_bound,
                "frame {frame}: |vy| bound {vy_bound}, got {}",
                ball.vy.abs()
            );
        }
    }
}

#[test]
fn case_2_a_corner_hit_reflects_each_velocity_component_exactly_once() {
    let effects = boxed(320.0, 240.0, 0.8, Some([0.0, 0.5]));
    // Heading into the bottom-right corner, crossing both walls in this one frame.
    let mut ball = Ball::new(300.0, 220.0, 15.0, 15.0, 12.0, 0);
    ball.step(&effects, &Motion::default());
    let (expected_vx, expected_vy) = (-15.0 * 0.8, -(15.0 + 0.5) * 0.8);
    assert_eq!(
        ball.vx, expected_vx,
        "vx: expected {expected_vx}, got {}",
        ball.vx
    );
    assert_eq!(
        ball.vy, expected_vy,
        "vy: expected {expected_vy}, got {}",
        ball.vy
    );
    assert_eq!((ball.x, ball.y), (308.0, 228.0), "clamped into the corner");
}

#[test]
fn case_3_resting_contact_in_clamp_mode_never_sinks_and_its_residual_bounce_stays_bounded() {
    // At rest on the floor, each frame adds g, the step sinks by that much, the clamp lifts it
    // back and the reflection leaves vy = -e·(v + g). The fixed point is v* = -e·g/(1 + e):
    // the ball ends every frame exactly touching the floor, with |vy| ≤ e·g/(1 + e).
    let (e, g) = (0.88, 0.5);
    let effects = boxed(320.0, 240.0, e, Some([0.0, g]));
    let mut ball = Ball::new(160.0, 40.0, 0.0, 0.0, 12.0, 0);
    let floor = 240.0 - 12.0;
    let bound = e * g / (1.0 + e);
    let mut worst = 0.0f64;
    for frame in 1..=1_000_000u32 {
        ball.step(&effects, &Motion::default());
        assert!(
            ball.y <= floor,
            "frame {frame}: never below the floor: y ≤ {floor}, got {}",
            ball.y
        );
        if frame > 2000 {
            worst = worst.max(ball.vy.abs());
            assert_eq!(
                ball.y, floor,
                "frame {frame}: settled, the ball ends each frame touching the floor"
            );
        }
    }
    assert!(
        worst <= bound + 1e-12,
        "residual |vy| bound e·g/(1+e) = {bound}, worst seen {worst}"
    );
}

#[test]
fn case_6_extreme_magnitudes_stay_finite_and_inside() {
    struct Case {
        name: &'static str,
        size: (f64, f64),
        ball: Ball,
        gravity: f64,
    }
    let cases = [
        Case {
            name: "gravity 1e-12",
            size: (320.0, 240.0),
            ball: Ball::new(40.0, 40.0, 5.2, 0.0, 12.0, 0),
            gravity: 1e-12,
        },
        Case {
            name: "gravity 1e6",
            size: (320.0, 240.0),
            ball: Ball::new(40.0, 40.0, 5.2, 0.0, 12.0, 0),
            gravity: 1e6,
        },
        Case {
            name: "velocity 1e9",
            size: (320.0, 240.0),
            ball: Ball::new(40.0, 40.0, 1e9, -1e9, 12.0, 0),
            gravity: 0.5,
        },
        Case {
            name: "2·radius just under the width",
            size: (320.0, 400.0),
            ball: Ball::new(160.0, 200.0, 3.0, 1.0, 159.999, 0),
            gravity: 0.5,
        },
        Case {
            name: "1 px ball in an 8192 canvas",
            size: (8192.0, 8192.0),
            ball: Ball::new(4000.0, 10.0, 37.0, 0.0, 1.0, 0),
            gravity: 0.5,
        },
    ];
    for case in cases {
        let (w, h) = case.size;
        let effects = boxed(w, h, 0.88, Some([0.0, case.gravity]));
        let mut ball = case.ball;
        for frame in 1..=10_000 {
            ball.step(&effects, &Motion::default());
            assert_inside(&ball, w, h, &format!("{}, frame {frame}", case.name));
        }
    }
}

#[test]
fn case_9_drag_of_one_stops_the_ball_at_once() {
    let effects = Effects {
        drag: Some(1.0),
        ..boxed(320.0, 240.0, 0.88, Some([0.0, 0.5]))
    };
    let mut ball = Ball::new(100.0, 100.0, 7.0, -3.0, 12.0, 0);
    ball.step(&effects, &Motion::default());
    assert_eq!(
        (ball.vx, ball.vy),
        (0.0, 0.0),
        "velocity after one frame of drag 1"
    );
    assert_eq!((ball.x, ball.y), (100.0, 100.0), "the ball does not move");
}

#[test]
fn case_9_drag_of_zero_changes_nothing() {
    let plain = boxed(320.0, 240.0, 0.88, Some([0.0, 0.5]));
    let zero_drag = Effects {
        drag: Some(0.0),
        ..plain.clone()
    };
    let (mut a, mut b) = (
        Ball::new(40.0, 40.0, 5.2, 0.0, 12.0, 5),
        Ball::new(40.0, 40.0, 5.2, 0.0, 12.0, 5),
    );
    for _ in 0..1000 {
        a.step(&plain, &Motion::default());
        b.step(&zero_drag, &Motion::default());
    }
    assert_eq!(a, b, "drag 0 must give the same state, bit for bit");
}

#[test]
fn case_9_drag_without_gravity_decays_speed_geometrically() {
    // No gravity, no walls in reach: |v_n| = |v_0| · (1 − k)^n.
    let k = 0.002;
    let effects = Effects {
        drag: Some(k),
        ..Effects::default()
    };
    let mut ball = Ball::new(0.0, 0.0, 3.0, 4.0, 1.0, 0);
    for n in 1..=1000 {
        ball.step(&effects, &Motion::default());
        let expected = 5.0 * (1.0 - k).powi(n);
        let speed = ball.vx.hypot(ball.vy);
        assert!(
            (speed - expected).abs() <= 1e-12 * expected,
            "frame {n}: expected speed {expected}, got {speed}"
        );
    }
}

#[test]
fn case_8_a_fast_ball_at_a_steep_slope_does_not_tunnel_and_a_resting_one_does_not_sink() {
    use bouncing_ball::floor::Floor;
    // A 60° slope from the top wall to the bottom wall, so no ball can go around its ends;
    // balls thrown at it at up to 30 diameters per frame.
    let slope = Floor {
        from: [330.0, 0.0],
        to: [100.0, 400.0],
        damping: 0.88,
    };
    let side = |b: &Ball| {
        let (dx, dy) = (slope.to[0] - slope.from[0], slope.to[1] - slope.from[1]);
        ((b.x - slope.from[0]) * dy - (b.y - slope.from[1]) * dx) / dx.hypot(dy)
    };
    let effects = Effects {
        floors: vec![slope],
        ..boxed(400.0, 400.0, 0.88, Some([0.0, 0.5]))
    };
    for (vx, vy) in [(300.0, 40.0), (150.0, 150.0), (250.0, -100.0)] {
        let mut ball = Ball::new(60.0, 150.0, vx, vy, 5.0, 0);
        let start_side = side(&ball).signum();
        for frame in 1..=2000 {
            ball.step(&effects, &Motion::default());
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
    use bouncing_ball::ball::Ball;
    use bouncing_ball::random::Random;
    use bouncing_ball::simulation::Simulation;
    use bouncing_ball::{BallSpec, Scene};

    fn spec(x: f64, y: f64, vx: f64, vy: f64, radius: f64) -> BallSpec {
        BallSpec {
            x,
            y,
            vx,
            vy,
            radius,
            colour: [255, 255, 255],
            trail_colour: [255, 255, 255],
            trail: 0,
        }
    }

    fn kinetic_energy(balls: &[Ball]) -> f64 {
        balls
            .iter()
            .map(|b| 0.5 * b.radius * b.radius * (b.vx * b.vx + b.vy * b.vy))
            .sum()
    }

    /// The deepest overlap of any pair, as a share of the smaller radius (brute force).
    fn deepest_overlap(balls: &[Ball]) -> f64 {
        let mut deepest = 0.0f64;
        for (i, a) in balls.iter().enumerate() {
            for b in &balls[i + 1..] {
                let overlap = a.radius + b.radius - (a.x - b.x).hypot(a.y - b.y);
                deepest = deepest.max(overlap / a.radius.min(b.radius));
            }
        }
        deepest
    }

    #[test]
    fn case_7_balls_spawned_at_one_centre_separate_and_never_stick() {
        let balls = (0..20).map(|_| spec(160.0, 120.0, 0.0, 0.0, 6.0)).collect();
        let scene = Scene {
            balls,
            walls: Some(1.0),
            ball_collisions: Some(0.9),
            ..Scene::empty(320, 240)
        };
        let mut simulation = Simulation::new(&scene);
        for frame in 1..=500 {
            simulation.step();
            let overlap = deepest_overlap(simulation.balls());
            assert!(overlap.is_finite(), "frame {frame}: overlap must be finite");
            if frame >= 100 {
                assert!(overlap < 1e-6, "frame {frame}: separated by frame 100: deepest overlap bound 1e-6 r, got {overlap}");
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
    /// Bound on overlap: contacts are resolved once per frame, pair by pair, so a ball pushed
    /// out of one overlap can be pushed into another and keep that depth until the next frame.
    /// The depth of a new overlap is at most the pair's approach in one frame, 2 × max speed
    /// (here 2 × 1 px = 2 px = half a radius); we assert half a radius.
    #[test]
    fn case_7_a_thousand_balls_packed_at_half_the_area_stay_finite_bounded_and_lose_energy() {
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
        let mut simulation = Simulation::new(&scene);
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
            if frame % 50 == 0 {
                worst = worst.max(deepest_overlap(balls));
            }
        }
        assert!(
            worst <= 0.5,
            "deepest overlap bound 0.5 radius, got {worst}"
        );
    }
}
