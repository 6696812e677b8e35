//! Ball-ball collisions: the closed-form bounce, conservation laws, no sticking, and the
//! grid broad phase against a brute-force search.

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::collisions::{deepest_overlap, kinetic_energy, Collisions};
use bouncing_ball::physics::grid::Grid;
use bouncing_ball::physics::walls::Walls;
use proptest::prelude::*;

/// Relative tolerance for "equal to rounding".
const ROUNDING: f64 = 1e-12;

fn ball(x: f64, y: f64, vx: f64, vy: f64, radius: f64) -> Ball {
    Ball::new(x, y, vx, vy, radius, 0)
}

/// Mass is radius², as in the collisions module (flat discs of equal density).
fn mass(ball: &Ball) -> f64 {
    ball.radius * ball.radius
}

fn momentum(balls: &[Ball]) -> [f64; 2] {
    balls.iter().fold([0.0, 0.0], |[px, py], b| {
        [px + mass(b) * b.vx, py + mass(b) * b.vy]
    })
}

fn distance(a: &Ball, b: &Ball) -> f64 {
    (b.x - a.x).hypot(b.y - a.y)
}

/// Moves every ball one frame and keeps it in the box; elastic walls keep the kinetic energy.
fn move_in_box(balls: &mut [Ball], walls: &Walls) {
    for b in balls.iter_mut() {
        b.x += b.vx;
        b.y += b.vy;
        b.bounce_off_walls(walls);
    }
}

fn assert_close(what: &str, expected: f64, actual: f64, scale: f64) {
    assert!(
        (expected - actual).abs() <= ROUNDING * scale,
        "{what}: expected {expected}, got {actual}"
    );
}

/// The 1D result for masses `m1`, `m2` meeting at `v1`, `v2` with restitution `e`.
fn one_dimensional_bounce(m1: f64, v1: f64, m2: f64, v2: f64, e: f64) -> (f64, f64) {
    let total = m1 + m2;
    (
        (m1 * v1 + m2 * v2 + m2 * e * (v2 - v1)) / total,
        (m1 * v1 + m2 * v2 + m1 * e * (v1 - v2)) / total,
    )
}

#[test]
fn head_on_collision_of_unequal_balls_matches_the_closed_form() {
    let e = 0.8;
    // Radii 2 and 3, so masses 4 and 9; centres 4.5 apart, overlapping by 0.5.
    let (m1, v1, m2, v2) = (4.0, 3.0, 9.0, -1.0);
    let mut balls = [ball(0.0, 0.0, v1, 0.0, 2.0), ball(4.5, 0.0, v2, 0.0, 3.0)];
    let (expected1, expected2) = one_dimensional_bounce(m1, v1, m2, v2, e);
    Collisions::new(e).resolve(&mut balls);
    assert_close("v1'", expected1, balls[0].vx, 3.0);
    assert_close("v2'", expected2, balls[1].vx, 3.0);
    assert_eq!(
        (0.0, 0.0),
        (balls[0].vy, balls[1].vy),
        "a head-on bounce stays on its line"
    );
    assert_close("momentum", m1 * v1 + m2 * v2, momentum(&balls)[0], 12.0);
}

#[test]
fn oblique_collision_of_unequal_balls_bounces_along_the_normal_and_conserves_momentum() {
    let e = 0.6;
    // Centres 3-4-5 apart: the normal is (0.6, 0.8), the tangent (-0.8, 0.6).
    let mut balls = [
        ball(10.0, 10.0, 2.0, 1.5, 4.0),
        ball(13.0, 14.0, -1.0, -0.5, 1.5),
    ];
    let (normal, tangent) = ([0.6, 0.8], [-0.8, 0.6]);
    let along = |b: &Ball, axis: [f64; 2]| b.vx * axis[0] + b.vy * axis[1];
    let before = momentum(&balls);
    let (n1, n2) = one_dimensional_bounce(
        16.0,
        along(&balls[0], normal),
        2.25,
        along(&balls[1], normal),
        e,
    );
    let (t1, t2) = (along(&balls[0], tangent), along(&balls[1], tangent));

    Collisions::new(e).resolve(&mut balls);

    assert_close("ball 1 normal speed", n1, along(&balls[0], normal), 3.0);
    assert_close("ball 2 normal speed", n2, along(&balls[1], normal), 3.0);
    assert_close(
        "ball 1 tangential speed",
        t1,
        along(&balls[0], tangent),
        3.0,
    );
    assert_close(
        "ball 2 tangential speed",
        t2,
        along(&balls[1], tangent),
        3.0,
    );
    let after = momentum(&balls);
    assert_close("momentum x", before[0], after[0], 40.0);
    assert_close("momentum y", before[1], after[1], 40.0);
}

#[test]
fn pairs_moving_apart_are_not_pushed_together() {
    let mut balls = [
        ball(0.0, 0.0, -1.0, 0.5, 5.0),
        ball(6.0, 0.0, 2.0, 0.5, 3.0),
    ];
    let velocities = |balls: &[Ball]| [balls[0].vx, balls[0].vy, balls[1].vx, balls[1].vy];
    let before = velocities(&balls);
    Collisions::new(1.0).resolve(&mut balls);
    assert_eq!(before, velocities(&balls), "velocities of a parting pair");
    assert_close(
        "distance after separation",
        8.0,
        distance(&balls[0], &balls[1]),
        8.0,
    );
}

#[test]
fn two_balls_spawned_at_the_same_centre_separate_and_stay_apart() {
    let walls = Walls {
        width: 200.0,
        height: 200.0,
        damping: 1.0,
    };
    // Same velocity, opposite velocities, and one at rest; inelastic and elastic.
    for (velocity_b, e) in [((1.0, 0.5), 0.0), ((-1.0, -0.5), 1.0), ((0.0, 0.0), 0.5)] {
        let mut balls = [
            ball(100.0, 100.0, 1.0, 0.5, 10.0),
            ball(100.0, 100.0, velocity_b.0, velocity_b.1, 5.0),
        ];
        let mut collisions = Collisions::new(e);
        collisions.resolve(&mut balls);
        for frame in 0..300 {
            let apart = distance(&balls[0], &balls[1]);
            assert!(
                apart >= 15.0 - 1e-9,
                "frame {frame}, velocity {velocity_b:?}, e {e}: expected centres at least 15 apart, got {apart}"
            );
            move_in_box(&mut balls, &walls);
            collisions.resolve(&mut balls);
        }
    }
}

#[test]
fn a_heap_of_balls_spawned_on_one_spot_spreads_out_until_none_overlap() {
    // 60 balls within 1 px of one point, ten of them at exactly that point, all at rest.
    // Each frame removes every overlap it finds but a push can cause a new one, so the heap
    // unpacks over frames: invisibly little overlap is left after 100, none after 400.
    let mut balls: Vec<Ball> = (0..60)
        .map(|i| {
            let offset = if i % 6 == 0 { 0.0 } else { 1.0 / f64::from(i) };
            ball(
                50.0 + offset,
                50.0 - offset / 2.0,
                0.0,
                0.0,
                2.0 + f64::from(i % 4),
            )
        })
        .collect();
    let mut collisions = Collisions::new(0.5);
    for (frames, allowed) in [(100, 0.1), (300, 1e-6)] {
        for _ in 0..frames {
            collisions.resolve(&mut balls);
        }
        let overlap = deepest_overlap(&balls);
        assert!(
            overlap <= allowed,
            "expected at most {allowed} px of overlap, the deepest is {overlap} px"
        );
    }
    assert_eq!(
        kinetic_energy(&balls),
        0.0,
        "pushing balls apart must not set them moving"
    );
}

#[test]
fn the_same_balls_give_the_same_bytes() {
    let heap = || -> Vec<Ball> {
        (0..40)
            .map(|i| ball(20.0, 20.0 + f64::from(i % 3), 0.1 * f64::from(i), -0.2, 3.0))
            .collect()
    };
    let bits = |balls: &[Ball]| -> Vec<u64> {
        balls
            .iter()
            .flat_map(|b| [b.x, b.y, b.vx, b.vy])
            .map(f64::to_bits)
            .collect()
    };
    let (mut first, mut second) = (heap(), heap());
    let (mut a, mut b) = (Collisions::new(0.9), Collisions::new(0.9));
    for _ in 0..20 {
        a.resolve(&mut first);
        b.resolve(&mut second);
    }
    assert_eq!(bits(&first), bits(&second));
}

/// Every overlapping pair `(i, j)`, `i < j`, by testing every pair.
fn brute_force_pairs(balls: &[Ball]) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    for (i, a) in balls.iter().enumerate() {
        for (j, b) in balls.iter().enumerate().skip(i + 1) {
            let (dx, dy) = (b.x - a.x, b.y - a.y);
            let reach = a.radius + b.radius;
            if dx * dx + dy * dy < reach * reach {
                pairs.push((i, j));
            }
        }
    }
    pairs
}

/// Up to `count` balls with centres in a square of side `spread` and radii in `radii`;
/// a few share a centre with the previous ball.
fn random_balls(
    count: usize,
    spread: f64,
    radii: std::ops::Range<f64>,
    speed: f64,
) -> impl Strategy<Value = Vec<Ball>> {
    let one = (
        0.0..spread,
        0.0..spread,
        -speed..=speed,
        -speed..=speed,
        radii,
        0..8u8,
    );
    prop::collection::vec(one, 0..count).prop_map(|specs| {
        let mut balls: Vec<Ball> = Vec::with_capacity(specs.len());
        for (x, y, vx, vy, radius, share) in specs {
            let (x, y) = match balls.last() {
                Some(previous) if share == 0 => (previous.x, previous.y),
                _ => (x, y),
            };
            balls.push(ball(x, y, vx, vy, radius));
        }
        balls
    })
}

#[test]
fn balls_flung_far_away_or_to_infinity_do_not_break_the_grid() {
    // The grid spans the balls' bounding box: a cell one diameter wide here would mean 10²⁴
    // cells, so the grid must widen its cells instead, and still find the overlapping pair.
    let balls = [
        ball(0.0, 0.0, 0.0, 0.0, 1.0),
        ball(1.5, 0.0, 0.0, 0.0, 1.0),
        ball(1e12, 1e12, 0.0, 0.0, 1.0),
        ball(f64::INFINITY, 0.0, 0.0, 0.0, 1.0),
        ball(f64::NAN, f64::NAN, 0.0, 0.0, 1.0),
    ];
    let mut grid = Grid::new();
    grid.rebuild(&balls);
    let mut found = Vec::new();
    grid.overlapping_pairs(&mut found, usize::MAX);
    assert_eq!(vec![(0, 1)], found);
}

proptest! {
    #[test]
    fn the_grid_finds_exactly_the_pairs_a_brute_force_search_finds(
        // From a dense heap to balls spread so thin the grid must widen its cells: the side
        // of the square is 10 to 100,000 px, as likely to be near one end as the other.
        (balls, spread) in (1.0..5.0f64)
            .prop_map(|power| 10f64.powf(power))
            .prop_flat_map(|spread| (random_balls(200, spread, 0.0..20.0, 0.0), Just(spread)))
    ) {
        let mut grid = Grid::new();
        grid.rebuild(&balls);
        let mut found = Vec::new();
        grid.overlapping_pairs(&mut found, usize::MAX);
        found.sort_unstable();
        let expected = brute_force_pairs(&balls);
        prop_assert_eq!(&expected, &found, "{} balls spread over {} px", balls.len(), spread);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn kinetic_energy_never_rises_and_momentum_holds_in_every_collision(
        balls in random_balls(40, 200.0, 3.0..12.0, 4.0),
        e in 0.0..=1.0f64,
    ) {
        let mut balls = balls;
        let walls = Walls { width: 200.0, height: 200.0, damping: 1.0 };
        let mut collisions = Collisions::new(e);
        let scale = kinetic_energy(&balls).max(1.0);
        for frame in 0..300 {
            move_in_box(&mut balls, &walls);
            let (energy, momentum_before) = (kinetic_energy(&balls), momentum(&balls));
            collisions.resolve(&mut balls);
            let after = kinetic_energy(&balls);
            prop_assert!(
                after <= energy + ROUNDING * scale,
                "frame {}: kinetic energy rose from {} to {}", frame, energy, after
            );
            // Momentum is only conserved between walls, so it is checked across collisions alone.
            let momentum_after = momentum(&balls);
            for axis in 0..2 {
                prop_assert!(
                    (momentum_after[axis] - momentum_before[axis]).abs() <= 1e-9 * scale,
                    "frame {}: momentum expected {:?}, got {:?}", frame, momentum_before, momentum_after
                );
            }
        }
    }
}
