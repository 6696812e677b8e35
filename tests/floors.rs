//! Floors (sloped segments): clamp along the normal, reflect the normal component with
//! damping, keep the tangential one; no tunnelling; end points bounce like points.

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::effects::Effects;
use bouncing_ball::physics::floor::Floor;
use bouncing_ball::physics::motion::Motion;
use bouncing_ball::physics::Vec2;
use bouncing_ball::Scene;
use common::{lesson_scene, white_ball};

mod common;

fn floor_only(floor: Floor, gravity: Option<Vec2>) -> Effects {
    Effects {
        gravity,
        floors: vec![floor],
        ..Effects::default()
    }
}

/// Signed distance of the ball's centre from the floor's line, positive on the normal's side.
fn height_above(floor: &Floor, ball: &Ball) -> f64 {
    let (dx, dy) = (floor.to.x - floor.from.x, floor.to.y - floor.from.y);
    let length = dx.hypot(dy);
    ((ball.x - floor.from.x) * dy - (ball.y - floor.from.y) * dx) / length
}

#[test]
fn a_ball_ten_diameters_per_frame_does_not_tunnel_through_a_floor() {
    // Horizontal floor at y = 200 (normal points up, towards smaller y... from → to leftwards).
    let floor = Floor {
        from: Vec2::new(300.0, 200.0),
        to: Vec2::new(0.0, 200.0),
        damping: 1.0,
    };
    let mut ball = Ball::new(150.0, 100.0, 0.0, 100.0, 5.0, 0); // 100 px/frame = 10 diameters
    let effects = floor_only(floor, None);
    for frame in 0..20 {
        Motion::default().advance(&mut ball, &effects);
        assert!(
            ball.y <= 200.0 - 5.0 + 1e-9,
            "frame {frame}: the ball must stay above the floor: expected y <= 195, got {}",
            ball.y
        );
    }
    assert!(
        ball.vy < 0.0,
        "after the hit the ball moves up: vy = {}",
        ball.vy
    );
}

#[test]
fn a_bounce_flips_the_normal_speed_with_damping_and_keeps_the_tangential_speed() {
    // A 45° floor; the ball falls straight down onto it.
    let floor = Floor {
        from: Vec2::new(200.0, 0.0),
        to: Vec2::new(0.0, 200.0),
        damping: 0.5,
    };
    let mut ball = Ball::new(100.0, 80.0, 0.0, 20.0, 5.0, 0);
    Motion::default().advance(&mut ball, &floor_only(floor, None));
    // Normal n = (-1, -1)/√2 (up-left), tangent t = (-1, 1)/√2.
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let normal_speed = -(ball.vx + ball.vy) * s;
    let tangential_speed = (-ball.vx + ball.vy) * s;
    let expected_normal = 0.5 * 20.0 * s;
    let expected_tangential = 20.0 * s;
    assert!(
        (normal_speed - expected_normal).abs() < 1e-12,
        "normal speed: expected {expected_normal}, got {normal_speed}"
    );
    assert!(
        (tangential_speed - expected_tangential).abs() < 1e-12,
        "tangential speed: expected {expected_tangential}, got {tangential_speed}"
    );
    let distance = height_above(&floor, &ball).abs();
    assert!(
        (distance - 5.0).abs() < 1e-9,
        "clamped to touch the floor: expected distance 5, got {distance}"
    );
}

#[test]
fn a_ball_resting_on_a_slope_does_not_sink_into_it() {
    let floor = Floor {
        from: Vec2::new(320.0, 240.0),
        to: Vec2::new(0.0, 140.0),
        damping: 0.88,
    };
    let mut ball = Ball::new(160.0, 178.0, 0.0, 0.0, 12.0, 0);
    let effects = floor_only(floor, Some(Vec2::new(0.0, 0.5)));
    let mut lowest = f64::INFINITY;
    for _ in 0..200 {
        Motion::default().advance(&mut ball, &effects);
        if (0.0..320.0).contains(&ball.x) {
            lowest = lowest.min(height_above(&floor, &ball).abs());
        }
    }
    assert!(
        lowest >= 12.0 - 1e-9,
        "the ball's centre must stay a radius (12) from the slope; closest was {lowest}"
    );
}

#[test]
fn a_ball_hitting_an_end_point_bounces_off_it_as_off_a_point() {
    // The segment runs from (0, 100) to (100, 100); the ball comes straight down 4 px past
    // one end, then past the other, and each time bounces off that end, away from it.
    let floor = Floor {
        from: Vec2::new(0.0, 100.0),
        to: Vec2::new(100.0, 100.0),
        damping: 1.0,
    };
    for (end, outwards) in [(floor.to, 1.0), (floor.from, -1.0)] {
        let mut ball = Ball::new(end.x + 4.0 * outwards, 80.0, 0.0, 14.0, 10.0, 0);
        Motion::default().advance(&mut ball, &floor_only(floor, None));
        let distance = (ball.x - end.x).hypot(ball.y - end.y);
        assert!(
            (distance - 10.0).abs() < 1e-9,
            "pushed out to touch the end point {end:?}: expected 10, got {distance}"
        );
        assert!(
            ball.vy < 0.0 && ball.vx * outwards > 0.0,
            "deflected up and away from the point {end:?}: v = ({}, {})",
            ball.vx,
            ball.vy
        );
        let speed = ball.vx.hypot(ball.vy);
        assert!(
            (speed - 14.0).abs() < 1e-9,
            "elastic: speed kept, expected 14, got {speed}"
        );
    }
}

#[test]
fn a_ball_struck_through_a_floor_within_one_step_is_put_back_on_its_side_and_bounces() {
    // A level floor at y = 100; a ball of radius 4 whose centre went from y 90 to y 105 in
    // one step (another ball struck it harder than its own floor contact foresaw).
    let floor = Floor {
        from: Vec2::new(0.0, 100.0),
        to: Vec2::new(200.0, 100.0),
        damping: 0.5,
    };
    let mut ball = Ball::new(50.0, 105.0, 1.0, 10.0, 4.0, 0);
    floor.undo_crossing(&mut ball, Vec2::new(49.0, 90.0));
    // Back above, touching the face: y = 100 − r; the normal speed reflected with damping.
    assert_eq!(
        (ball.x, ball.y),
        (50.0, 96.0),
        "put back touching the floor"
    );
    assert_eq!((ball.vx, ball.vy), (1.0, -5.0), "expected (1, -0.5 × 10)");
    // A ball that only overlaps the face (a resting contact) is the contacts' business.
    let mut resting = Ball::new(50.0, 97.0, 0.0, 0.1, 4.0, 0);
    floor.undo_crossing(&mut resting, Vec2::new(50.0, 96.9));
    assert_eq!((resting.y, resting.vy), (97.0, 0.1), "left alone");
}

/// One ball of radius 10 starting at `(x, y)` above a level floor from x 100 to 200 at y 150
/// (its normal points up), under `gravity`, with ball-ball collisions on, so the contact
/// solver carries the floor contact; the ball after `frames` frames.
fn on_a_floor_with_the_contact_solver(x: f64, y: f64, gravity: f64, frames: u32) -> Ball {
    let scene = Scene {
        balls: vec![white_ball(x, y, 0.0, 0.0, 10.0)],
        gravity: Some(Vec2::new(0.0, gravity)),
        walls: Some(0.5),
        floors: vec![Floor {
            from: Vec2::new(100.0, 150.0),
            to: Vec2::new(200.0, 150.0),
            damping: 0.5,
        }],
        ball_collisions: Some(0.5),
        ..lesson_scene()
    };
    let mut simulation = scene.simulation();
    assert!(simulation.has_contact_solver(), "the contact solver runs");
    for _ in 0..frames {
        simulation.step();
    }
    simulation.balls()[0].clone()
}

#[test]
fn a_ball_dropped_on_a_floor_in_the_contact_solver_comes_to_rest_touching_it() {
    let ball = on_a_floor_with_the_contact_solver(150.0, 50.0, 0.5, 600);
    // At rest on the face: the centre one radius above the floor, within the solver's
    // allowed overlap (0.01 r), and still.
    let expected = 150.0 - 10.0;
    assert!(
        (ball.y - expected).abs() <= 0.1,
        "resting on the floor: expected y {expected} ± 0.1, got {}",
        ball.y
    );
    assert!(
        ball.vx.hypot(ball.vy) < 1e-3 && ball.x == 150.0,
        "at rest where it fell: x {}, v ({}, {})",
        ball.x,
        ball.vx,
        ball.vy
    );
}

#[test]
fn a_ball_landing_on_a_floors_end_point_in_the_contact_solver_rolls_off_it() {
    // Dropped 5 px past the right end: the end point pushes it outwards, away from its centre,
    // so it slides off the corner and falls to the bottom of the box (y 240 − r).
    let ball = on_a_floor_with_the_contact_solver(205.0, 50.0, 0.5, 600);
    let bottom = 240.0 - 10.0;
    assert!(
        (ball.y - bottom).abs() <= 0.1,
        "fallen past the end to the bottom: expected y {bottom} ± 0.1, got ({}, {})",
        ball.x,
        ball.y
    );
}

#[test]
fn a_ball_centred_exactly_on_a_floor_in_the_contact_solver_is_pushed_out_along_its_normal() {
    // No direction from the floor to the centre: the face's normal (up here) is the way out.
    let ball = on_a_floor_with_the_contact_solver(150.0, 150.0, 0.0, 60);
    assert!(
        ball.y <= 140.0 + 0.1,
        "pushed up out of the floor: expected y <= 140.1, got {}",
        ball.y
    );
}

#[test]
fn a_ball_starting_a_step_centred_on_a_floors_line_is_pushed_out_on_the_side_it_moves_to() {
    // Its centre starts on the line of a level floor at y = 100 and moves 2 px up: it came
    // from no side, so the side it moves to is its side, and it ends touching the face there
    // (y = 100 − r), still moving away.
    let floor = Floor {
        from: Vec2::new(0.0, 100.0),
        to: Vec2::new(200.0, 100.0),
        damping: 0.5,
    };
    let mut ball = Ball::new(50.0, 100.0, 0.0, -2.0, 5.0, 0);
    Motion::default().advance(&mut ball, &floor_only(floor, None));
    assert_eq!(
        (ball.y, ball.vy),
        (95.0, -2.0),
        "expected touching the face above (y 95), still moving up at 2 px/frame"
    );
}

/// A level floor from x 0 to 200 at y 100 (its normal points up), damping 0.5.
fn level_floor() -> Floor {
    Floor {
        from: Vec2::new(0.0, 100.0),
        to: Vec2::new(200.0, 100.0),
        damping: 0.5,
    }
}

#[test]
fn a_ball_that_ends_a_step_exactly_touching_a_floor_is_not_reflected_until_it_overlaps() {
    // As at the walls: touching is not yet a contact. 3 px/frame down from 8 px above the
    // face's contact line (radius 5): exact in binary.
    let mut ball = Ball::new(50.0, 92.0, 0.0, 3.0, 5.0, 0);
    Motion::default().advance(&mut ball, &floor_only(level_floor(), None));
    assert_eq!(
        (ball.y, ball.vy),
        (95.0, 3.0),
        "expected touching the face (y 95) and still falling at 3 px/frame"
    );
}

#[test]
fn a_ball_touching_a_floors_face_that_slides_past_its_end_leaves_the_face() {
    // It starts the step touching the face near the right end and ends with its centre past
    // the end, exactly one radius from the end point (a 3-4-5 triangle): no contact with the
    // face, which its centre no longer faces, nor with the end point, which it only touches.
    let mut ball = Ball::new(199.0, 95.0, 4.0, 1.0, 5.0, 0);
    Motion::default().advance(&mut ball, &floor_only(level_floor(), None));
    assert_eq!(
        (ball.position(), ball.velocity()),
        (Vec2::new(203.0, 96.0), Vec2::new(4.0, 1.0)),
        "expected to move on untouched"
    );
}

#[test]
fn a_ball_struck_exactly_onto_a_floors_line_is_put_back_on_the_side_it_came_from() {
    // Its centre went from (10, 90) to (30, 100): it ends on the line, not across it, but
    // overlapping by a whole radius, so it goes back up, touching, its normal speed reflected.
    let mut ball = Ball::new(30.0, 100.0, 2.0, 10.0, 4.0, 0);
    level_floor().undo_crossing(&mut ball, Vec2::new(10.0, 90.0));
    assert_eq!(
        (ball.position(), ball.velocity()),
        (Vec2::new(30.0, 96.0), Vec2::new(2.0, -5.0)),
        "expected touching the face (y 96) with vy −0.5 × 10"
    );
}

#[test]
fn a_ball_struck_across_a_floor_is_put_back_only_where_its_path_met_the_segment() {
    // From (90, 90) to (150, 105): the path meets the line at 10 / 15 of the way, x 130, on
    // the segment, so the ball goes back up (y 100 − 4), its normal speed reflected. Through
    // the same line past the end (the segment cut to x 120), the ball passed beside the floor
    // and is left where it is.
    let mut ball = Ball::new(150.0, 105.0, 60.0, 15.0, 4.0, 0);
    level_floor().undo_crossing(&mut ball, Vec2::new(90.0, 90.0));
    assert_eq!(
        (ball.position(), ball.velocity()),
        (Vec2::new(150.0, 96.0), Vec2::new(60.0, -7.5)),
        "crossed at x 130: expected put back at y 96 with vy −0.5 × 15"
    );
    let short = Floor {
        to: Vec2::new(120.0, 100.0),
        ..level_floor()
    };
    let mut beside = Ball::new(150.0, 105.0, 60.0, 15.0, 4.0, 0);
    short.undo_crossing(&mut beside, Vec2::new(90.0, 90.0));
    assert_eq!(
        (beside.position(), beside.velocity()),
        (Vec2::new(150.0, 105.0), Vec2::new(60.0, 15.0)),
        "crossed the line at x 130, past the end at 120: expected left alone"
    );
}

#[test]
fn a_ball_ending_exactly_between_the_ends_of_a_short_floor_bounces_off_the_far_end() {
    // A floor 10 px long, a ball of radius 10 coming down from the left at (30, 15) px/frame:
    // its path meets the floor's line before the floor begins, and its centre ends at (5, 95),
    // exactly above the middle, overlapping both ends alike. The tie goes to `to`, so the
    // ball is pushed away from it, left and up (one rule, so one run always gives one result).
    let floor = Floor {
        from: Vec2::new(0.0, 100.0),
        to: Vec2::new(10.0, 100.0),
        damping: 1.0,
    };
    let mut ball = Ball::new(-25.0, 80.0, 30.0, 15.0, 10.0, 0);
    Motion::default().advance(&mut ball, &floor_only(floor, None));
    let distance = (ball.x - 10.0).hypot(ball.y - 100.0);
    assert!(
        (distance - 10.0).abs() < 1e-9 && ball.x < 5.0 && ball.y < 95.0,
        "pushed left and up off the end (10, 100) to touch it: got ({}, {}), {distance} from it",
        ball.x,
        ball.y
    );
}
