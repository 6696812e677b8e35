//! Exact mode for every contact: balls meet at the moment they touch (event-driven), floors
//! are met at the moment of impact, nothing is clamped afterwards.

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::effects::Effects;
use bouncing_ball::physics::floor::Floor;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::tolerances::MAX_EVENTS_PER_BALL;
use bouncing_ball::physics::walls::Walls;
use bouncing_ball::physics::Integrator;
use bouncing_ball::physics::Simulation;
use bouncing_ball::physics::Vec2;
use bouncing_ball::scene::file as scene_file;
use bouncing_ball::scene::random::jittered_lattice;
use bouncing_ball_lab::accuracy::{deepest_overlap, kinetic_energy, lesson_effects, rms_speed};

fn exact(integrator: Integrator) -> Motion {
    Motion {
        integrator,
        collisions: CollisionMode::Exact,
        ..Motion::default()
    }
}

fn ball(x: f64, y: f64, vx: f64, vy: f64, radius: f64) -> Ball {
    Ball::new(x, y, vx, vy, radius, 0)
}

fn relative_error(expected: f64, actual: f64, scale: f64) -> f64 {
    (expected - actual).abs() / scale
}

/// The closed form of an oblique collision: `b` moves at `(v, 0)` towards `a` at rest, offset
/// `aim` px sideways. First contact is when `|Δ + Δv·t| = ra + rb`; the bounce is along the
/// normal at that moment, masses ∝ r², restitution `e`. Returns the outgoing velocities.
fn oblique_closed_form(a: &Ball, b: &Ball, e: f64) -> ([f64; 2], [f64; 2]) {
    let reach = a.radius + b.radius;
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let (vx, vy) = (b.vx - a.vx, b.vy - a.vy);
    // (vx² + vy²)t² + 2(dx·vx + dy·vy)t + dx² + dy² − reach² = 0, smaller root.
    let (qa, qb, qc) = (
        vx * vx + vy * vy,
        2.0 * (dx * vx + dy * vy),
        dx * dx + dy * dy - reach * reach,
    );
    let t = (-qb - (qb * qb - 4.0 * qa * qc).sqrt()) / (2.0 * qa);
    let (nx, ny) = ((dx + vx * t) / reach, (dy + vy * t) / reach);
    let approach = vx * nx + vy * ny;
    let (ma, mb) = (a.radius * a.radius, b.radius * b.radius);
    let j = (1.0 + e) * approach / (ma + mb);
    (
        [a.vx + j * mb * nx, a.vy + j * mb * ny],
        [b.vx - j * ma * nx, b.vy - j * ma * ny],
    )
}

#[test]
fn oblique_collisions_leave_along_the_normal_at_first_contact() {
    for speed in [5.0, 15.0] {
        for e in [1.0, 0.7] {
            let a = ball(100.0, 100.0, 0.0, 0.0, 6.0);
            // 7 px off-centre, touching after 0.6 of the frame.
            let along = (10.0f64 * 10.0 - 7.0 * 7.0).sqrt();
            let b = ball(100.0 - along - 0.6 * speed, 107.0, speed, 0.0, 4.0);
            let (want_a, want_b) = oblique_closed_form(&a, &b, e);
            let mut simulation = Simulation::new(
                vec![a, b],
                Effects::default(),
                exact(Integrator::SemiImplicitEuler),
                Some(e),
            );
            simulation.step();
            let got = simulation.balls();
            for (want, got, name) in [(want_a, &got[0], "a"), (want_b, &got[1], "b")] {
                for (w, g) in want.iter().zip([got.vx, got.vy]) {
                    let error = relative_error(*w, g, speed);
                    assert!(
                        error < 1e-9,
                        "speed {speed}, e {e}, ball {name}: expected velocity {want:?}, \
                         got ({}, {}) (error {error:e} of the speed)",
                        got.vx,
                        got.vy
                    );
                }
            }
        }
    }
}

#[test]
fn a_head_on_pair_closing_at_100_diameters_per_frame_bounces_back() {
    // Radius 5: 100 diameters a frame is 1000 px/frame of closing speed.
    let pair = vec![
        ball(1000.0, 100.0, 500.0, 0.0, 5.0),
        ball(1100.0, 100.0, -500.0, 0.0, 5.0),
    ];
    let mut simulation = Simulation::new(
        pair,
        Effects::default(),
        exact(Integrator::SemiImplicitEuler),
        Some(1.0),
    );
    simulation.step();
    let [a, b] = simulation.balls() else {
        unreachable!()
    };
    assert!(
        a.vx == -500.0 && b.vx == 500.0,
        "expected velocities −500 and 500, got {} and {}",
        a.vx,
        b.vx
    );
    // They touched at t = 0.09 (x 1045 and 1055), then flew apart for 0.91 frames.
    let want = (1045.0 - 455.0, 1055.0 + 455.0);
    assert!(
        (a.x - want.0).abs() < 1e-9 && (b.x - want.1).abs() < 1e-9,
        "expected x {want:?}, got ({}, {})",
        a.x,
        b.x
    );
}

#[test]
fn a_slow_ball_on_a_moving_ball_is_not_put_to_sleep() {
    // In the lesson's box (240 px high), a ball drifting at 0.3 px/frame, slower than the
    // sleep speed (gravity's 0.5 px/frame in one frame), sits exactly on top of one that slides
    // along the floor at 3 px/frame. Only sleeping balls, walls and floors can hold a ball up
    // for good, and the sliding ball is awake: so the top ball must not sleep (which would
    // stop it dead), but keep drifting.
    let balls = vec![
        ball(100.0, 230.0, 3.0, 0.0, 10.0),
        ball(100.0, 210.0, 0.3, 0.0, 10.0),
    ];
    let mut simulation = Simulation::new(
        balls,
        lesson_effects(0.5),
        exact(Integrator::SemiImplicitEuler),
        Some(0.5),
    );
    simulation.step();
    let top = &simulation.balls()[1];
    assert!(
        top.x > 100.0 && top.vx > 0.0,
        "expected the top ball still drifting right from x 100 at 0.3 px/frame, it is at x {} \
         moving at {}",
        top.x,
        top.vx
    );
}

#[test]
fn newtons_cradle_sends_exactly_one_ball_out_at_the_incoming_speed() {
    // Five equal balls touching in a row, a sixth arriving along the line at 5 px/frame.
    let mut balls: Vec<Ball> = (0..5)
        .map(|k| ball(100.0 + 20.0 * f64::from(k), 100.0, 0.0, 0.0, 10.0))
        .collect();
    balls.push(ball(43.0, 100.0, 5.0, 0.0, 10.0));
    let mut simulation = Simulation::new(
        balls,
        Effects::default(),
        exact(Integrator::SemiImplicitEuler),
        Some(1.0),
    );
    let mut collisions = 0;
    for _ in 0..20 {
        simulation.step();
        collisions += simulation
            .event_counts()
            .expect("exact mode counts events")
            .ball_collisions;
    }
    // The impulse runs down the row one pair at a time: six balls, five collisions.
    assert_eq!(collisions, 5, "ball-ball collisions counted over the run");
    let balls = simulation.balls();
    for (k, b) in balls.iter().enumerate() {
        let want = if k == 4 { 5.0 } else { 0.0 };
        assert!(
            (b.vx - want).abs() < 1e-9 * 5.0 && b.vy.abs() < 1e-9 * 5.0,
            "ball {k}: expected velocity ({want}, 0), got ({}, {})",
            b.vx,
            b.vy
        );
    }
    let counts = simulation.event_counts().expect("exact mode counts events");
    assert!(
        counts.capped_steps == 0,
        "no step may hit the cap: {counts:?}"
    );
}

#[test]
fn elastic_billiards_keeps_its_energy_and_never_overlaps_in_exact_mode() {
    let mut scene = scene_file::preset("billiards", 1).expect("the billiards preset");
    scene.motion.collisions = CollisionMode::Exact;
    let mut simulation = scene.simulation();
    let start = kinetic_energy(simulation.balls());
    let radius = simulation.balls()[0].radius;
    let spawned = deepest_overlap(simulation.balls()) / radius;
    assert!(
        spawned < 1e-9,
        "the spawn: expected no overlap, got {spawned:e} r"
    );
    for frame in 0..2000 {
        simulation.step();
        let energy = kinetic_energy(simulation.balls());
        let drift = (energy / start - 1.0).abs();
        assert!(
            drift < 1e-12,
            "frame {frame}: kinetic energy expected {start}, got {energy} (drift {drift:e})"
        );
        let overlap = deepest_overlap(simulation.balls()) / radius;
        assert!(
            overlap < 1e-9,
            "frame {frame}: expected no overlap deeper than 1e-9 r, got {overlap:e} r"
        );
    }
}

/// Kinetic plus potential energy per unit mass (y grows downwards, so height is −y).
fn energy(ball: &Ball, gravity: f64) -> f64 {
    0.5 * (ball.vx * ball.vx + ball.vy * ball.vy) - gravity * ball.y
}

/// The lesson's box and gravity, elastic, with `floors` in it.
fn elastic_box_with(floors: Vec<Floor>) -> Effects {
    Effects {
        floors,
        ..lesson_effects(1.0)
    }
}

#[test]
fn an_elastic_ball_on_a_flat_floor_or_in_a_valley_keeps_its_energy_exactly() {
    let flat = vec![Floor {
        from: Vec2::new(40.0, 200.0),
        to: Vec2::new(280.0, 200.0),
        damping: 1.0,
    }];
    let valley = vec![
        Floor {
            from: Vec2::new(0.0, 100.0),
            to: Vec2::new(160.0, 220.0),
            damping: 1.0,
        },
        Floor {
            from: Vec2::new(160.0, 220.0),
            to: Vec2::new(320.0, 100.0),
            damping: 1.0,
        },
    ];
    for (name, floors) in [("flat floor", flat), ("V valley", valley)] {
        let effects = elastic_box_with(floors);
        for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
            let motion = exact(integrator);
            let mut b = ball(100.0, 40.0, 1.3, 0.0, 10.0);
            let start = energy(&b, 0.5);
            let mut worst = 0.0f64;
            for _ in 0..10_000 {
                motion.advance(&mut b, &effects);
                worst = worst.max((energy(&b, 0.5) - start).abs() / start.abs());
            }
            assert!(
                worst < 1e-9,
                "{name}, {integrator:?}: energy expected {start} throughout, drifted by {worst:e}"
            );
        }
    }
}

#[test]
fn a_ball_dropped_on_a_floor_in_exact_mode_bounces_when_and_where_the_closed_form_says() {
    // A ball of radius 10 falls from rest at y 100 onto a flat elastic floor at y 200, under
    // gravity 0.5 px/frame²: it touches at t₀ = √(2·90/0.5) frames, leaves at −g·t₀, and is
    // back at y 100, at rest, at 2·t₀. Verlet and RK4 follow the parabola exactly.
    let floor = vec![Floor {
        from: Vec2::new(40.0, 200.0),
        to: Vec2::new(280.0, 200.0),
        damping: 1.0,
    }];
    let effects = elastic_box_with(floor);
    let g: f64 = 0.5;
    let touch = (2.0 * 90.0 / g).sqrt();
    let expected = |t: f64| {
        if t < touch {
            (100.0 + 0.5 * g * t * t, g * t)
        } else if t < 2.0 * touch {
            let since = t - touch;
            (
                190.0 - g * touch * since + 0.5 * g * since * since,
                -g * touch + g * since,
            )
        } else {
            let since = t - 2.0 * touch;
            (100.0 + 0.5 * g * since * since, g * since)
        }
    };
    for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
        let motion = exact(integrator);
        let mut b = ball(160.0, 100.0, 0.0, 0.0, 10.0);
        for frame in 1..=40 {
            motion.advance(&mut b, &effects);
            let (y, vy) = expected(f64::from(frame));
            assert!(
                (b.y - y).abs() < 1e-9 && (b.vy - vy).abs() < 1e-9 && b.x == 160.0,
                "{integrator:?}, frame {frame}: expected (160, {y}) moving down at {vy}, got \
                 ({}, {}) at {}",
                b.x,
                b.y,
                b.vy
            );
        }
    }
}

/// The lesson's box under its gravity, with walls that keep half the speed: where piles fall.
fn pile_box() -> Effects {
    Effects {
        gravity: Some(Vec2::new(0.0, 0.5)),
        walls: Some(Walls {
            width: 320.0,
            height: 240.0,
            damping: 0.5,
        }),
        ..Effects::default()
    }
}

/// Seeds of the pile's jittered start: each drops the balls differently.
const PILE_SEEDS: u64 = 12;

#[test]
fn the_150_ball_pile_comes_to_rest_without_overlap_and_every_frame_finishes() {
    let effects = pile_box();
    let cap = MAX_EVENTS_PER_BALL * 150;
    for seed in 1..=PILE_SEEDS {
        let balls = jittered_lattice(150, 6.0, 320.0, 2.0, seed);
        let mut simulation = Simulation::new(
            balls,
            effects.clone(),
            exact(Integrator::SemiImplicitEuler),
            Some(0.5),
        );
        let (mut deepest, mut most, mut capped, mut late_speed) = (0.0f64, 0, 0, 0.0f64);
        for frame in 0..400 {
            simulation.step();
            let counts = simulation.event_counts().expect("exact mode counts events");
            assert!(
                counts.events <= cap,
                "seed {seed}, frame {frame}: {counts:?} beyond the cap {cap}"
            );
            most = most.max(counts.events);
            capped += counts.capped_steps;
            deepest = deepest.max(deepest_overlap(simulation.balls()) / 6.0);
            if frame >= 300 {
                late_speed = late_speed.max(rms_speed(simulation.balls()));
            }
        }
        println!(
            "seed {seed}: most events in a frame {most} (cap {cap}), capped steps {capped}, \
             deepest overlap {deepest:e} r, largest rms speed in frames 300-399 \
             {late_speed:e} px/frame"
        );
        assert!(
            deepest < 1e-6,
            "seed {seed}: expected no overlap deeper than 1e-6 r, got {deepest:e} r"
        );
        assert!(
            late_speed <= 0.01,
            "seed {seed}: expected the pile at rest in frames 300-399 (rms speed at most \
             0.01 px/frame), got {late_speed:e} px/frame"
        );
    }
}

#[test]
fn the_pile_preset_in_exact_mode_falls_asleep_and_then_costs_no_events() {
    // Before the held ball stopped pressing into the ball resting on it, velocity Verlet
    // needed 385,736 events over these 300 frames (29 steps capped), RK4 374,095.
    const MOST_EVENTS: u64 = 150_000;
    const ASLEEP_BY: u32 = 150;
    for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
        let mut scene = scene_file::preset("pile", 1).expect("the pile preset");
        scene.motion.collisions = CollisionMode::Exact;
        scene.motion.integrator = integrator;
        let mut simulation = scene.simulation();
        let count = simulation.balls().len();
        let mut total = 0;
        for frame in 0..300 {
            let before = simulation.balls().to_vec();
            simulation.step();
            let events = simulation
                .event_counts()
                .expect("exact mode counts events")
                .events;
            total += events;
            if frame >= ASLEEP_BY {
                let asleep = simulation.sleeping_balls();
                assert!(
                    asleep == count && events == 0 && simulation.balls() == &before[..],
                    "{integrator:?}, frame {frame}: expected all {count} balls asleep, \
                     unmoved, with 0 events; got {asleep} asleep and {events} events"
                );
            }
        }
        assert!(
            total <= MOST_EVENTS,
            "{integrator:?}: expected the pile to settle within {MOST_EVENTS} events, took \
             {total}"
        );
    }
}

#[test]
fn a_ball_falling_onto_a_sleeping_ball_meets_it_on_its_parabola() {
    // Ball A rests on the floor of the box and sleeps: its flight is a straight one, gravity
    // taken away. Ball B falls from rest 110 px above touching it, under gravity 0.5
    // px/frame²: on its parabola it touches A at √(2·110/0.5) ≈ 20.98 frames. Taken as a
    // straight line from the step's start (10 px/frame from 10 px away), the touch would
    // come at frame 21, with B a quarter of a pixel inside A.
    for integrator in [Integrator::VelocityVerlet, Integrator::Rk4] {
        let pair = vec![
            ball(160.0, 230.0, 0.0, 0.0, 10.0),
            ball(160.0, 100.0, 0.0, 0.0, 10.0),
        ];
        let effects = pile_box();
        let mut simulation = Simulation::new(pair, effects, exact(integrator), Some(1.0));
        let mut collided = false;
        for frame in 1..=22 {
            simulation.step();
            collided |= simulation
                .event_counts()
                .is_some_and(|c| c.ball_collisions > 0);
            let overlap = deepest_overlap(simulation.balls()) / 10.0;
            assert!(
                overlap < 1e-6,
                "{integrator:?}, frame {frame}: the balls overlap by {overlap} r"
            );
        }
        assert!(
            collided,
            "{integrator:?}: expected B to strike A by frame 22"
        );
    }
}
