//! The contact solver (ball-ball collisions in clamp mode): piles come to rest without
//! overlap, a pyramid stands, resting contacts do not bounce, momentum and energy obey their
//! laws. `docs/contacts.md` has the figures these bounds come from.

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::Vec2;
use bouncing_ball::scene::file::preset;
use bouncing_ball::{BallSpec, Scene};
use bouncing_ball_lab::accuracy::{
    deepest_overlap, kinetic_energy, lowest_pile, pile_height, rms_speed,
};
use bouncing_ball_lab::scenes::pile;
use common::white_ball as spec;
use proptest::prelude::*;

mod common;

const FRAMES: u32 = 10_000;
/// The last frames, in which a pile must be at rest.
const SETTLED: u32 = 1_000;

fn all_finite(balls: &[Ball]) -> bool {
    balls
        .iter()
        .all(|b| [b.x, b.y, b.vx, b.vy].iter().all(|v| v.is_finite()))
}

/// Spawns of each pile that the tests drop.
const SEEDS: [u64; 4] = [1, 2, 3, 4];

/// Drops `count` balls of `radius` into the 320 × 240 box (gravity 0.5, walls 0.5,
/// restitution 0.5, default settings), spawned from each of [`SEEDS`], and checks each heap
/// after 10,000 frames.
fn assert_piles_rest(count: usize, radius: f64) {
    for seed in SEEDS {
        assert_pile_rests(count, radius, seed);
    }
}

fn assert_pile_rests(count: usize, radius: f64, seed: u64) {
    let scene = pile(count, radius, seed).unwrap();
    let mut simulation = scene.simulation();
    let (mut deepest, mut fastest) = (0.0f64, 0.0f64);
    for frame in 1..=FRAMES {
        simulation.step();
        let balls = simulation.balls();
        assert!(
            all_finite(balls),
            "seed {seed}, frame {frame}: NaN or infinity"
        );
        if frame > FRAMES - SETTLED {
            deepest = deepest.max(deepest_overlap(balls) / radius);
            fastest = fastest.max(rms_speed(balls));
        }
    }
    eprintln!("{count} balls, seed {seed}: deepest {deepest:.4} r, fastest {fastest:.2e}");
    let height = pile_height(simulation.balls(), f64::from(scene.height));
    let bound = lowest_pile(count, radius, f64::from(scene.width));
    assert!(
        height >= bound,
        "{count} balls, seed {seed}: no heap without overlaps is lower than {bound:.1} px, this one is {height:.1} px"
    );
    assert!(
        deepest <= 0.05,
        "{count} balls, seed {seed}: deepest overlap in the last {SETTLED} frames expected at most 0.05 r, got {deepest:.4} r"
    );
    assert!(
        fastest <= 0.01,
        "{count} balls, seed {seed}: rms speed in the last {SETTLED} frames expected at most 0.01 px/frame, got {fastest:.2e}"
    );
}

#[test]
fn a_pile_of_150_balls_comes_to_rest_without_sinking_into_itself() {
    assert_piles_rest(150, 6.0);
}

#[test]
fn a_pile_of_400_balls_comes_to_rest_without_sinking_into_itself() {
    assert_piles_rest(400, 4.0);
}

#[test]
fn the_pyramid_stands_still_for_10000_frames() {
    let scene = preset("pyramid", 1).unwrap();
    let mut simulation = scene.simulation();
    let start: Vec<Ball> = simulation.balls().to_vec();
    for _ in 0..FRAMES {
        simulation.step();
    }
    for (i, (now, then)) in simulation.balls().iter().zip(&start).enumerate() {
        let moved = (now.x - then.x).hypot(now.y - then.y) / then.radius;
        assert!(
            moved <= 0.05,
            "ball {i}: expected within 0.05 r of its start, moved {moved:.4} r"
        );
    }
}

/// A ball dropped onto a ball resting on the floor, from `drop` px above contact: the gap
/// between them each frame after they first touch, and the top ball's last speed.
fn drop_onto_resting_ball(drop: f64) -> (Vec<f64>, f64) {
    let scene = Scene {
        balls: vec![
            spec(50.0, 190.0, 0.0, 0.0, 10.0),
            spec(50.0, 170.0 - drop, 0.0, 0.0, 10.0),
        ],
        gravity: Some(Vec2::new(0.0, 0.5)),
        walls: Some(0.5),
        ball_collisions: Some(0.9),
        ..Scene::empty(100, 200)
    };
    let mut simulation = scene.simulation();
    let mut gaps = Vec::new();
    for _ in 0..200 {
        simulation.step();
        let [bottom, top] = [&simulation.balls()[0], &simulation.balls()[1]];
        let gap = (top.x - bottom.x).hypot(top.y - bottom.y) - 20.0;
        if gap <= 0.0 || !gaps.is_empty() {
            gaps.push(gap);
        }
    }
    (gaps, simulation.balls()[1].vy)
}

#[test]
fn a_slow_contact_on_a_resting_ball_stays_in_contact_and_rests() {
    // From 2 px up the top ball meets the bottom one at about √(2·0.5·2) ≈ 1.4 px/frame: a
    // rebound of 0.9 × 1.4 = 1.3 px/frame is below the rest speed 1.7, so once touching
    // it must stay touching (a bounce would part them by v²/2g ≈ 1.7 px).
    let (gaps, last_speed) = drop_onto_resting_ball(2.0);
    let parted = gaps.iter().fold(f64::MIN, |m, &g| m.max(g));
    assert!(
        !gaps.is_empty() && parted <= 0.01,
        "a slow contact must not bounce: after touching the balls parted by {parted:.4} px"
    );
    assert!(last_speed.abs() < 1e-6, "and it rests: vy {last_speed:.2e}");
}

/// Drops a ball from `drop` px above contact onto an equal ball resting on the floor, with
/// elastic balls and floor damping `floor`: the top ball's fastest fall before the impact
/// and fastest rise after it, px/frame.
fn fall_and_rebound(drop: f64, floor: f64) -> (f64, f64) {
    let scene = Scene {
        balls: vec![
            spec(50.0, 190.0, 0.0, 0.0, 10.0),
            spec(50.0, 170.0 - drop, 0.0, 0.0, 10.0),
        ],
        gravity: Some(Vec2::new(0.0, 0.5)),
        walls: Some(floor),
        ball_collisions: Some(1.0),
        ..Scene::empty(100, 200)
    };
    let mut simulation = scene.simulation();
    let (mut fall, mut rise) = (0.0f64, 0.0f64);
    for _ in 0..60 {
        simulation.step();
        let top = &simulation.balls()[1];
        if rise == 0.0 && top.vy >= 0.0 {
            fall = fall.max(top.vy);
        } else {
            rise = rise.max(-top.vy);
        }
    }
    (fall, rise)
}

#[test]
fn a_fast_ball_dropped_on_a_resting_one_bounces_back_up() {
    // Equal balls, elastic: the blow passes to the bottom ball, the floor sends it back up
    // at `f` times its speed, and it passes that to the top ball. So the top ball leaves at
    // `f` times the speed it came in with, less at most one frame of gravity (0.5).
    for floor in [1.0, 0.5] {
        let (fall, rise) = fall_and_rebound(100.0, floor);
        let expected = floor * fall;
        assert!(
            (rise - expected).abs() <= 0.5,
            "floor {floor}: fell at {fall:.3} px/frame, expected to rise at {expected:.3}, rose at {rise:.3}"
        );
    }
}

#[test]
fn a_fast_ball_beside_a_resting_one_bounces_off_the_floor() {
    // Dropped from 100 px onto the floor (walls damping 0.5) beside a resting ball: it meets
    // the floor at about √(2·0.5·100) = 10 px/frame and leaves at about 5, rising about
    // 5²/(2·0.5) = 25 px; more than 10 px.
    let scene = Scene {
        balls: vec![
            spec(20.0, 190.0, 0.0, 0.0, 10.0),
            spec(70.0, 90.0, 0.0, 0.0, 10.0),
        ],
        gravity: Some(Vec2::new(0.0, 0.5)),
        walls: Some(0.5),
        ball_collisions: Some(0.9),
        ..Scene::empty(100, 200)
    };
    let mut simulation = scene.simulation();
    let mut lowest_after_rising = f64::MAX;
    let mut rising = false;
    for _ in 0..60 {
        simulation.step();
        let ball = &simulation.balls()[1];
        rising |= ball.vy < 0.0;
        if rising {
            lowest_after_rising = lowest_after_rising.min(ball.y);
        }
    }
    let rise = 190.0 - lowest_after_rising;
    assert!(
        rise > 10.0,
        "the ball must bounce off the floor: it rose {rise:.2} px"
    );
}

#[test]
fn a_free_pair_keeps_its_momentum_to_1e_12() {
    // No walls, no gravity: only the two balls push on each other, head-on and glancing.
    for (restitution, vy) in [(1.0, 0.0), (0.5, 0.7), (0.0, -1.3)] {
        let scene = Scene {
            balls: vec![
                spec(100.0, 100.0, 3.0, vy, 6.0),
                spec(140.0, 103.0, -2.0, 0.0, 9.0),
            ],
            ball_collisions: Some(restitution),
            ..Scene::empty(300, 200)
        };
        let momentum = |balls: &[Ball]| {
            balls.iter().fold([0.0, 0.0], |[px, py], b| {
                let mass = b.radius * b.radius;
                [px + mass * b.vx, py + mass * b.vy]
            })
        };
        let mut simulation = scene.simulation();
        let before = momentum(simulation.balls());
        let scale = before[0].abs() + before[1].abs();
        for frame in 1..=30 {
            simulation.step();
            let after = momentum(simulation.balls());
            for axis in 0..2 {
                assert!(
                    (after[axis] - before[axis]).abs() <= 1e-12 * scale,
                    "e {restitution}, frame {frame}: momentum expected {before:?}, got {after:?}"
                );
            }
        }
        let [a, b] = [&simulation.balls()[0], &simulation.balls()[1]];
        assert!(
            a.vx < 3.0 && b.vx > -2.0,
            "e {restitution}: the pair collided: vx {} and {}",
            a.vx,
            b.vx
        );
    }
}

/// Up to 30 balls at random places (overlaps allowed) in a 200 × 200 box.
fn random_balls() -> impl Strategy<Value = Vec<BallSpec>> {
    let one = (
        5.0..195.0f64,
        5.0..195.0f64,
        -4.0..4.0f64,
        -4.0..4.0f64,
        2.0..5.0f64,
    );
    proptest::collection::vec(one, 2..30).prop_map(|specs| {
        specs
            .into_iter()
            .map(|(x, y, vx, vy, r)| spec(x, y, vx, vy, r))
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn kinetic_energy_of_an_elastic_scene_never_rises(balls in random_balls(), iterations in 1..=12u32) {
        let mut scene = Scene {
            balls,
            walls: Some(1.0),
            ball_collisions: Some(1.0),
            ..Scene::empty(200, 200)
        };
        scene.motion.iterations = iterations;
        let mut simulation = scene.simulation();
        let mut energy = kinetic_energy(simulation.balls());
        for frame in 1..=300 {
            simulation.step();
            let now = kinetic_energy(simulation.balls());
            prop_assert!(
                now <= energy * (1.0 + 1e-12),
                "frame {}: kinetic energy rose from {} to {}", frame, energy, now
            );
            energy = now;
        }
    }
}
