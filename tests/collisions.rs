//! Ball-ball collisions in a whole `Simulation` (the contact solver): the closed-form bounce,
//! parting pairs left alone, balls spawned on one spot separating without being set moving,
//! the same bytes twice; and the grid broad phase against a brute-force search.

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::contacts::Grid;
use bouncing_ball::physics::simulation::Simulation;
use bouncing_ball::physics::tolerances::SLOP;
use bouncing_ball::Scene;
use bouncing_ball_lab::accuracy::{deepest_overlap, kinetic_energy};
use common::white_ball as spec;
use proptest::prelude::*;

mod common;

/// Relative tolerance for "equal to rounding".
const ROUNDING: f64 = 1e-12;

fn ball(x: f64, y: f64, vx: f64, vy: f64, radius: f64) -> Ball {
    Ball::new(x, y, vx, vy, radius, 0)
}

/// Mass is radius², as in the contact solver (flat discs of equal density).
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

/// Balls `(x, y, vx, vy, radius)` in a 300 × 200 scene with nothing but ball-ball
/// collisions of restitution `e` (no walls, no gravity), run for `frames` frames.
fn collide(balls: &[(f64, f64, f64, f64, f64)], e: f64, frames: u32) -> Simulation {
    let scene = Scene {
        balls: balls
            .iter()
            .map(|&(x, y, vx, vy, radius)| spec(x, y, vx, vy, radius))
            .collect(),
        ball_collisions: Some(e),
        ..Scene::empty(300, 200)
    };
    let mut simulation = scene.simulation();
    for _ in 0..frames {
        simulation.step();
    }
    simulation
}

#[test]
fn head_on_collision_of_unequal_balls_matches_the_closed_form() {
    let e = 0.8;
    // Radii 2 and 3, so masses 4 and 9, meeting on the line y = 100 within a few frames.
    let (m1, v1, m2, v2) = (4.0, 3.0, 9.0, -1.0);
    let (expected1, expected2) = one_dimensional_bounce(m1, v1, m2, v2, e);
    let simulation = collide(
        &[(100.0, 100.0, v1, 0.0, 2.0), (115.0, 100.0, v2, 0.0, 3.0)],
        e,
        10,
    );
    let balls = simulation.balls();
    assert_close("v1'", expected1, balls[0].vx, 3.0);
    assert_close("v2'", expected2, balls[1].vx, 3.0);
    assert_eq!(
        (0.0, 0.0),
        (balls[0].vy, balls[1].vy),
        "a head-on bounce stays on its line"
    );
    assert_close("momentum", m1 * v1 + m2 * v2, momentum(balls)[0], 12.0);
}

#[test]
fn oblique_collision_of_unequal_balls_bounces_along_the_normal_and_conserves_momentum() {
    let e = 0.6;
    // Centres 3-4-5 apart and already touching: the normal is (0.6, 0.8), the tangent
    // (-0.8, 0.6). The bounce is the first thing the solver does, so along the normal it
    // is the 1D closed form, and across it nothing changes.
    let start = [(10.0, 10.0, 2.0, 1.5, 4.0), (13.0, 14.0, -1.0, -0.5, 1.5)];
    let before: Vec<Ball> = start
        .iter()
        .map(|&(x, y, vx, vy, r)| ball(x, y, vx, vy, r))
        .collect();
    let (normal, tangent) = ([0.6, 0.8], [-0.8, 0.6]);
    let along = |b: &Ball, axis: [f64; 2]| b.vx * axis[0] + b.vy * axis[1];
    let (n1, n2) = one_dimensional_bounce(
        16.0,
        along(&before[0], normal),
        2.25,
        along(&before[1], normal),
        e,
    );
    let (t1, t2) = (along(&before[0], tangent), along(&before[1], tangent));

    let simulation = collide(&start, e, 1);
    let balls = simulation.balls();

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
    let (expected, after) = (momentum(&before), momentum(balls));
    assert_close("momentum x", expected[0], after[0], 40.0);
    assert_close("momentum y", expected[1], after[1], 40.0);
}

#[test]
fn pairs_moving_apart_are_not_pushed_together() {
    // Overlapping by 2 px and parting: no impulse, only their positions are pushed apart.
    let start = [
        (100.0, 100.0, -1.0, 0.5, 5.0),
        (106.0, 100.0, 2.0, 0.5, 3.0),
    ];
    let simulation = collide(&start, 1.0, 5);
    let balls = simulation.balls();
    let velocities = [balls[0].vx, balls[0].vy, balls[1].vx, balls[1].vy];
    assert_eq!(
        [-1.0, 0.5, 2.0, 0.5],
        velocities,
        "velocities of a parting pair"
    );
    let apart = distance(&balls[0], &balls[1]);
    assert!(
        apart > 8.0,
        "expected the pair apart, centres {apart} px apart"
    );
}

#[test]
fn two_balls_spawned_at_the_same_centre_separate_and_stay_apart() {
    // Same velocity, opposite velocities, and one at rest; inelastic and elastic. The
    // position pass pushes them apart over a few frames; afterwards, bouncing off the walls
    // into each other, they overlap by at most 1 % of their reach (a wall and a ball
    // pressing on one ball within a step are solved iteratively, not exactly).
    let allowed = 15.0 * 0.99;
    for ((vx, vy), e) in [((1.0, 0.5), 0.0), ((-1.0, -0.5), 1.0), ((0.0, 0.0), 0.5)] {
        let scene = Scene {
            balls: vec![
                spec(100.0, 100.0, 1.0, 0.5, 10.0),
                spec(100.0, 100.0, vx, vy, 5.0),
            ],
            walls: Some(1.0),
            ball_collisions: Some(e),
            ..Scene::empty(200, 200)
        };
        let mut simulation = scene.simulation();
        for frame in 0..300 {
            simulation.step();
            let [a, b] = [&simulation.balls()[0], &simulation.balls()[1]];
            let apart = distance(a, b);
            assert!(
                frame < 10 || apart >= allowed - 1e-9,
                "frame {frame}, velocity ({vx}, {vy}), e {e}: expected centres at least {allowed} apart, got {apart}"
            );
        }
    }
}

#[test]
fn two_balls_at_one_spot_part_along_the_later_balls_golden_angle() {
    // Two centres at one spot have no line between them. Ball j leaves at j golden angles
    // (π(3 − √5) each), so that a heap spawned on one spot fans out round the circle rather
    // than along one line; here ball 1 leaves at one golden angle, and the pair stays on it.
    let at_rest = (150.0, 100.0, 0.0, 0.0, 5.0);
    let simulation = collide(&[at_rest, at_rest], 0.5, 50);
    let [a, b] = [&simulation.balls()[0], &simulation.balls()[1]];
    let apart = distance(a, b);
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let (cos, sin) = ((b.x - a.x) / apart, (b.y - a.y) / apart);
    let along = cos * golden.cos() + sin * golden.sin();
    assert!(
        along.abs() > 1.0 - ROUNDING,
        "expected the pair apart along ±({}, {}), got ({cos}, {sin})",
        golden.cos(),
        golden.sin()
    );
    assert!(
        apart > 10.0 * (1.0 - SLOP),
        "expected the pair apart, centres {apart} px apart"
    );
}

#[test]
fn an_inelastic_cradles_centre_of_mass_moves_at_its_constant_velocity() {
    // Five balls touching in a row, a sixth arriving at 5 px/frame, restitution 0: the row
    // keeps colliding, so the solver tries touch by touch, gives up and takes sub-steps
    // from where the step began. With no walls or gravity, the centre of mass moves at the
    // total momentum over the total mass whatever the collisions do: x(t) = x(0) + v·t.
    let mut start: Vec<(f64, f64, f64, f64, f64)> = (0..5)
        .map(|k| (100.0 + 20.0 * f64::from(k), 100.0, 0.0, 0.0, 10.0))
        .collect();
    start.push((43.0, 100.0, 5.0, 0.0, 10.0));
    let balls: Vec<Ball> = start
        .iter()
        .map(|&(x, y, vx, vy, r)| ball(x, y, vx, vy, r))
        .collect();
    let total: f64 = balls.iter().map(mass).sum();
    let centre = |balls: &[Ball]| balls.iter().map(|b| mass(b) * b.x).sum::<f64>() / total;
    let (x0, v) = (centre(&balls), momentum(&balls)[0] / total);
    for frames in [1, 5, 30] {
        let simulation = collide(&start, 0.0, frames);
        let expected = x0 + v * f64::from(frames);
        assert_close(
            &format!("centre of mass after {frames} frames"),
            expected,
            centre(simulation.balls()),
            expected,
        );
    }
}

#[test]
fn a_heap_of_balls_spawned_on_one_spot_spreads_out_without_being_set_moving() {
    // 60 balls at rest within 1 px of one point, ten of them at exactly that point. The
    // position pass unpacks the heap over frames, moving positions only.
    let start: Vec<(f64, f64, f64, f64, f64)> = (0..60)
        .map(|i| {
            let offset = if i % 6 == 0 { 0.0 } else { 1.0 / f64::from(i) };
            (
                150.0 + offset,
                100.0 - offset / 2.0,
                0.0,
                0.0,
                2.0 + f64::from(i % 4),
            )
        })
        .collect();
    let simulation = collide(&start, 0.5, 400);
    let balls = simulation.balls();
    let overlap = deepest_overlap(balls);
    let allowed = SLOP * 5.0 + 1e-9;
    assert!(
        overlap <= allowed,
        "expected at most {allowed} px of overlap (the slop), the deepest is {overlap} px"
    );
    assert_eq!(
        kinetic_energy(balls),
        0.0,
        "pushing balls apart must not set them moving"
    );
}

#[test]
fn the_same_balls_give_the_same_bytes() {
    let heap: Vec<(f64, f64, f64, f64, f64)> = (0..40)
        .map(|i| (20.0, 20.0 + f64::from(i % 3), 0.1 * f64::from(i), -0.2, 3.0))
        .collect();
    let bits = |simulation: &Simulation| -> Vec<u64> {
        simulation
            .balls()
            .iter()
            .flat_map(|b| [b.x, b.y, b.vx, b.vy])
            .map(f64::to_bits)
            .collect()
    };
    assert_eq!(
        bits(&collide(&heap, 0.9, 20)),
        bits(&collide(&heap, 0.9, 20))
    );
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
    grid.for_each_overlapping_pair(|i, j| found.push((i, j)));
    assert_eq!(vec![(0, 1)], found);
}

#[test]
fn a_ball_that_rounding_puts_one_column_past_the_grid_is_still_paired_and_measured() {
    // Balls of radius 1.1 make cells 2.2 px wide. From x = 0 to x = 24.2 the grid has
    // floor(24.2 / 2.2) + 1 = 11 columns (24.2 / 2.2 rounds to 10.999…), but it finds a ball's
    // column by multiplying by 1 / 2.2, and 24.2 × (1 / 2.2) rounds to 11.0: one column past
    // the last, where the ball must be kept in the last column, or it is in no cell at all.
    let per_cell: f64 = 1.0 / 2.2;
    assert!(
        24.2 / 2.2 < 11.0 && 24.2 * per_cell == 11.0,
        "the rounding this test relies on"
    );
    let balls = [
        ball(0.0, 0.0, 0.0, 0.0, 1.1),
        ball(23.0, 0.0, 0.0, 0.0, 1.1),
        ball(24.2, 0.0, 0.0, 0.0, 1.1),
    ];
    let mut grid = Grid::new();
    grid.rebuild(&balls);
    let mut found = Vec::new();
    grid.for_each_overlapping_pair(|i, j| found.push((i, j)));
    assert_eq!(vec![(1, 2)], found);
    // The pair overlaps by the sum of the radii less the distance between the centres.
    let expected = 2.2 - (24.2 - 23.0);
    let measured = grid.deepest_overlap(&balls);
    assert!(
        (measured - expected).abs() < ROUNDING,
        "deepest overlap {measured} px, expected {expected} px"
    );
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
        grid.for_each_overlapping_pair(|i, j| found.push((i, j)));
        found.sort_unstable();
        let expected = brute_force_pairs(&balls);
        prop_assert_eq!(&expected, &found, "{} balls spread over {} px", balls.len(), spread);
    }
}
