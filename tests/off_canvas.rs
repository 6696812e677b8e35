//! Drawing costs only what is on the canvas: shapes far off it are dismissed, and floors
//! reaching far beyond it are cut to it, in floating point before any integer conversion.
//! (Unclipped, a floor from -1e30 to 1e30 would walk four billion saturated pixels.)

mod common;

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::floor::Floor;
use bouncing_ball::physics::Vec2;
use bouncing_ball::render::{IndexedFrame, Renderer};
use bouncing_ball::Scene;
use common::lesson_scene;

/// The lesson's canvas and colours with these floors, and a frame drawn with `balls`.
fn draw(floors: Vec<Floor>, balls: &[Ball]) -> (Renderer, IndexedFrame) {
    let scene = Scene {
        floors,
        floor_colour: [200, 200, 200],
        ..lesson_scene()
    };
    let renderer = Renderer::new(&scene).unwrap();
    let mut frame = renderer.new_frame();
    renderer.draw(balls, &mut frame);
    (renderer, frame)
}

/// The pixels that are not background.
fn drawn(frame: &IndexedFrame) -> Vec<(u32, u32)> {
    let background = frame.get_pixel(0, 0)[0].min(frame.get_pixel(319, 0)[0]);
    frame
        .enumerate_pixels()
        .filter(|p| p.2[0] != background)
        .map(|p| (p.0, p.1))
        .collect()
}

fn far_ball(x: f64, y: f64) -> Ball {
    let mut ball = Ball::new(x, y, 0.0, 0.0, 12.0, 20);
    for i in 0..20 {
        ball.trail.push(Vec2::new(x - f64::from(i), y));
    }
    ball
}

#[test]
fn balls_and_trails_far_off_the_canvas_draw_nothing() {
    for (x, y) in [
        (3e9, 100.0),
        (-3e9, 100.0),
        (100.0, 1e300),
        (f64::MAX, f64::MIN),
    ] {
        let (_, frame) = draw(Vec::new(), &[far_ball(x, y)]);
        assert_eq!(drawn(&frame), vec![], "ball at ({x}, {y})");
    }
}

#[test]
fn a_floor_from_minus_1e30_to_1e30_draws_exactly_its_row_across_the_canvas() {
    let floor = Floor {
        from: Vec2::new(-1e30, 120.0),
        to: Vec2::new(1e30, 120.0),
        damping: 1.0,
    };
    let (_, frame) = draw(vec![floor], &[]);
    let expected: Vec<(u32, u32)> = (0..320).map(|x| (x, 120)).collect();
    assert_eq!(drawn(&frame), expected);
}

#[test]
fn a_vertical_floor_from_minus_1e30_to_1e30_draws_exactly_its_column_down_the_canvas() {
    // Steep floors are cut along y, their longer axis (along x there is nothing to cut).
    let floor = Floor {
        from: Vec2::new(100.0, -1e30),
        to: Vec2::new(100.0, 1e30),
        damping: 1.0,
    };
    let (_, frame) = draw(vec![floor], &[]);
    let mut expected: Vec<(u32, u32)> = (0..240).map(|y| (100, y)).collect();
    expected.sort_by_key(|&(x, y)| (y, x));
    assert_eq!(drawn(&frame), expected);
}

#[test]
fn a_diagonal_floor_reaching_1e30_draws_only_its_diagonal_on_the_canvas() {
    let floor = Floor {
        from: Vec2::new(-1e30, -1e30),
        to: Vec2::new(1e30, 1e30),
        damping: 1.0,
    };
    let (_, frame) = draw(vec![floor], &[]);
    let pixels = drawn(&frame);
    let off_diagonal: Vec<_> = pixels.iter().filter(|(x, y)| x != y).collect();
    assert!(
        off_diagonal.is_empty(),
        "off the diagonal: {off_diagonal:?}"
    );
    assert!(
        (239..=240).contains(&pixels.len()),
        "{} pixels on a 240-pixel diagonal",
        pixels.len()
    );
}

#[test]
fn a_floor_wholly_off_the_canvas_draws_nothing() {
    let floor = Floor {
        from: Vec2::new(-1e30, -5.0),
        to: Vec2::new(1e30, -5.0),
        damping: 1.0,
    };
    let (_, frame) = draw(vec![floor], &[]);
    assert_eq!(drawn(&frame), vec![]);
}
