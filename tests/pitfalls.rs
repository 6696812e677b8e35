//! One test per pitfall in the lesson's "Common pitfalls": each fails if that bug came back.

mod common;

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::walls::Walls;
use bouncing_ball::render::{to_rgb, Renderer};
use common::lesson_scene;

/// The lesson's gravity, px/frame².
const GRAVITY: f64 = 0.5;

fn lesson_walls(damping: f64) -> Walls {
    Walls {
        width: 320.0,
        height: 240.0,
        damping,
    }
}

#[test]
fn position_is_clamped_in_the_same_frame_as_the_reflection() {
    // Falling at 30 px/frame from 10 px above the floor's contact line: the step overshoots by 20.5 px.
    let mut ball = Ball::new(100.0, 218.0, 0.0, 30.0, 12.0, 20);
    ball.step(GRAVITY, &lesson_walls(0.88));
    let expected_y = 240.0 - 12.0;
    let expected_vy = -(30.0 + 0.5) * 0.88;
    assert_eq!(
        ball.y, expected_y,
        "y after the bounce: expected {expected_y} (touching the floor), got {}",
        ball.y
    );
    assert_eq!(
        ball.vy, expected_vy,
        "vy after the bounce: expected {expected_vy}, got {}",
        ball.vy
    );
    // And the next frame moves it up, away from the wall: no second flip, no jitter.
    ball.step(GRAVITY, &lesson_walls(0.88));
    assert!(
        ball.y < expected_y,
        "the frame after a bounce must leave the wall: y = {}",
        ball.y
    );
}

#[test]
fn gravity_is_added_once_per_frame_not_again_at_a_bounce() {
    // Elastic bounce: the rebound speed is exactly the impact speed, which had one frame of gravity.
    let mut ball = Ball::new(100.0, 220.0, 0.0, 10.0, 12.0, 0);
    ball.step(GRAVITY, &lesson_walls(1.0));
    let expected_vy = -(10.0 + 0.5);
    assert_eq!(
        ball.vy, expected_vy,
        "vy after an elastic bounce: expected {expected_vy}, got {}",
        ball.vy
    );
    // In free flight, each frame adds exactly g.
    let mut ball = Ball::new(100.0, 100.0, 0.0, 0.0, 12.0, 0);
    for frame in 1..=10 {
        ball.step(GRAVITY, &lesson_walls(1.0));
        let expected = 0.5 * f64::from(frame);
        assert_eq!(
            ball.vy, expected,
            "vy after {frame} frames: expected {expected}, got {}",
            ball.vy
        );
    }
}

#[test]
fn trail_never_grows_longer_than_trail_len() {
    let mut ball = Ball::new(40.0, 40.0, 5.2, 0.0, 12.0, 20);
    for frame in 1..=1000 {
        ball.step(GRAVITY, &lesson_walls(0.88));
        let expected = frame.min(20);
        assert_eq!(
            ball.trail.len(),
            expected,
            "trail length after {frame} frames: expected {expected}, got {}",
            ball.trail.len()
        );
    }
    let newest = *ball.trail.iter().last().unwrap();
    assert_eq!(
        newest,
        ball.position(),
        "the newest trail point is where the ball is now"
    );
}

#[test]
fn trail_is_drawn_under_the_ball() {
    // A slow ball: its own trail dots overlap its centre in every frame.
    let mut scene = lesson_scene();
    scene.balls[0].vx = 1.0;
    let renderer = Renderer::new(&scene).unwrap();
    let mut simulation = scene.simulation();
    let mut frame = renderer.new_frame();
    for n in 0..60 {
        simulation.step();
        renderer.draw(simulation.balls(), &mut frame);
        let ball = &simulation.balls()[0];
        let centre = to_rgb(&frame, renderer.palette())
            .get_pixel(ball.x.round() as u32, ball.y.round() as u32)
            .0;
        assert_eq!(
            centre,
            [255, 200, 60],
            "frame {n}: the ball's centre pixel should be BALL_COLOUR, got {centre:?}"
        );
    }
}

#[test]
fn sub_pixel_motion_is_kept() {
    // Integer positions would round 0.1 px/frame away and freeze the ball.
    let mut ball = Ball::new(100.0, 100.0, 0.1, 0.0, 12.0, 0);
    for _ in 0..10 {
        ball.step(0.0, &lesson_walls(1.0));
    }
    let moved = ball.x - 100.0;
    assert!(
        (moved - 1.0).abs() < 1e-12,
        "10 frames at 0.1 px/frame: expected 1 px, moved {moved}"
    );
}
