//! `Ball::step` is the lesson's loop written out, and every run of the lesson's settings takes
//! it, so a learner who edits it sees the result. The general solver (`Motion::step`, which
//! scenes beyond the lesson take) must give the same numbers on every single-ball scene the
//! lesson could set up, so the two never drift apart.

mod common;

use bouncing_ball::physics::{Ball, Integrator, Motion, Vec2, Walls};
use bouncing_ball::scene::file as scene_file;
use bouncing_ball::testing::work::{self, Work};
use bouncing_ball::{BallSpec, Scene};
use common::lesson_scene;
use proptest::prelude::*;

/// Equal to the last bit, except that −0.0 and +0.0 count as equal: the general solver adds
/// the horizontal gravity 0.0 to `vx`, which turns the −0.0 of a dead-stopped bounce into +0.0
/// (same value, same motion, different sign bit).
fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a == 0.0 && b == 0.0)
}

/// Runs `scene` (one ball, vertical gravity, walls) both ways for `frames` frames and
/// returns the first frame at which they differ, with both balls.
fn first_difference(scene: &Scene, frames: u32) -> Option<(u32, Ball, Ball)> {
    let spec = &scene.balls[0];
    let gravity = scene.gravity.map_or(0.0, |g| g.y);
    let walls = Walls {
        width: f64::from(scene.width),
        height: f64::from(scene.height),
        damping: scene.walls.expect("the lesson's scene has walls"),
    };
    let mut lesson = Ball::new(spec.x, spec.y, spec.vx, spec.vy, spec.radius, spec.trail);
    let mut solver = lesson.clone();
    let effects = scene.effects();
    for frame in 0..frames {
        lesson.step(gravity, &walls);
        scene.motion.advance(&mut solver, &effects);
        solver.record_trail();
        let equal = [
            (lesson.x, solver.x),
            (lesson.y, solver.y),
            (lesson.vx, solver.vx),
            (lesson.vy, solver.vy),
        ]
        .iter()
        .all(|&(a, b)| same(a, b))
            && lesson.trail == solver.trail;
        if !equal {
            return Some((frame, lesson, solver));
        }
    }
    None
}

#[test]
fn the_lessons_step_and_the_general_solver_agree_on_the_lessons_scene() {
    let scene = lesson_scene();
    if let Some((frame, lesson, solver)) = first_difference(&scene, 2000) {
        panic!("frame {frame}: Ball::step gives {lesson:?}, the solver gives {solver:?}");
    }
}

#[test]
fn every_run_of_the_lessons_settings_takes_ball_step() {
    for name in ["lesson", "elastic", "no-gravity", "heavy", "moon", "many"] {
        let scene = scene_file::preset(name, 1).unwrap();
        let mut simulation = scene.simulation();
        assert!(simulation.takes_the_lessons_step(), "preset {name}");
        work::reset();
        for _ in 0..10 {
            simulation.step();
        }
        let steps = 10 * scene.balls.len() as u64;
        assert_eq!(work::count(Work::LessonStep), steps, "preset {name}");
    }
    for name in ["drag", "slope", "billiards", "pile"] {
        let scene = scene_file::preset(name, 1).unwrap();
        let mut simulation = scene.simulation();
        assert!(!simulation.takes_the_lessons_step(), "preset {name}");
        work::reset();
        simulation.step();
        assert_eq!(work::count(Work::LessonStep), 0, "preset {name}");
    }
    let rk4 = Scene {
        motion: Motion {
            integrator: Integrator::Rk4,
            ..Motion::default()
        },
        ..lesson_scene()
    };
    assert!(
        !rk4.simulation().takes_the_lessons_step(),
        "rk4 is beyond the lesson"
    );
}

#[test]
fn a_difference_is_noticed() {
    // The check itself must be able to fail: a different damping is a different run.
    let scene = lesson_scene();
    let mut other = scene.clone();
    other.walls = Some(0.87);
    let spec = &scene.balls[0];
    let mut lesson = Ball::new(spec.x, spec.y, spec.vx, spec.vy, spec.radius, spec.trail);
    let mut general = other.simulation();
    let walls = Walls {
        width: 320.0,
        height: 240.0,
        damping: 0.88,
    };
    let differs = (0..200).any(|_| {
        lesson.step(0.5, &walls);
        general.step();
        !same(lesson.vy, general.balls()[0].vy)
    });
    assert!(differs, "damping 0.87 and 0.88 gave the same run");
}

fn single_ball_scene() -> impl Strategy<Value = Scene> {
    (
        (40u32..800, 40u32..600),
        (0.5..20.0f64, 0.0..1.0f64, 0.0..1.0f64),
        (-30.0..30.0f64, -30.0..30.0f64),
        (-2.0..2.0f64, 0.0..=1.0f64, 0usize..30),
    )
        .prop_map(
            |((width, height), (radius, fx, fy), (vx, vy), (g, damping, trail))| {
                let (w, h) = (f64::from(width), f64::from(height));
                Scene {
                    balls: vec![BallSpec {
                        x: radius + fx * (w - 2.0 * radius),
                        y: radius + fy * (h - 2.0 * radius),
                        vx,
                        vy,
                        radius,
                        colour: [255, 200, 60],
                        trail_colour: [60, 140, 255],
                        trail,
                    }],
                    gravity: Some(Vec2::new(0.0, g)),
                    walls: Some(damping),
                    frames: 500,
                    ..Scene::empty(width, height)
                }
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn the_lessons_step_and_the_general_solver_agree_on_random_single_ball_scenes(
        scene in single_ball_scene()
    ) {
        let difference = first_difference(&scene, scene.frames);
        prop_assert!(
            difference.is_none(),
            "(frame, Ball::step, solver) differ: {:?}",
            difference
        );
    }
}
