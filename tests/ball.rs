//! The lesson's `Ball` at the edges of its rules: where touching a wall is not yet crossing
//! it, and what a trail holds before its first point and when it keeps none.

use bouncing_ball::physics::ball::{Ball, Trail};
use bouncing_ball::physics::walls::Walls;
use bouncing_ball::physics::Vec2;

const WALLS: Walls = Walls {
    width: 320.0,
    height: 240.0,
    damping: 0.88,
};

#[test]
fn a_ball_that_ends_a_frame_exactly_touching_a_wall_is_not_reflected_until_it_crosses() {
    // The lesson reflects when `x - r < 0` (and so on): a ball whose edge lands exactly on a
    // wall is still inside and keeps its velocity; the next frame takes it through, and only
    // then is it clamped and reflected. Radius 10, 3 px/frame, no gravity: exact in binary.
    let r = 10.0;
    let cases = [
        ("left", Ball::new(r + 3.0, 120.0, -3.0, 0.0, r, 0)),
        ("right", Ball::new(320.0 - r - 3.0, 120.0, 3.0, 0.0, r, 0)),
        ("top", Ball::new(160.0, r + 3.0, 0.0, -3.0, r, 0)),
        ("bottom", Ball::new(160.0, 240.0 - r - 3.0, 0.0, 3.0, r, 0)),
    ];
    for (wall, mut ball) in cases {
        let moving = ball.velocity();
        ball.step(0.0, &WALLS);
        assert_eq!(
            ball.velocity(),
            moving,
            "{wall} wall: a ball touching it after the frame must keep its velocity {moving:?}, got {:?}",
            ball.velocity()
        );
        let touching = ball.position();
        ball.step(0.0, &WALLS);
        let reflected = moving * -WALLS.damping;
        assert_eq!(
            (ball.position(), ball.velocity()),
            (touching, reflected),
            "{wall} wall: the frame that crosses it clamps the ball back to touching and reflects it"
        );
    }
}

#[test]
fn a_trail_is_empty_until_its_first_point_and_one_that_keeps_none_stays_empty() {
    let mut trail = Trail::new(3);
    assert!(trail.is_empty(), "a new trail holds no point");
    trail.push(Vec2::new(1.0, 2.0));
    assert!(!trail.is_empty(), "a trail with one point is not empty");
    let mut none = Trail::new(0);
    none.push(Vec2::new(1.0, 2.0));
    assert!(
        none.is_empty(),
        "a trail that keeps no point stays empty after a push"
    );
    assert_eq!(none.len(), 0);
}
