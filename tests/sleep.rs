//! Sleep: balls that have come to rest stop being solved and cost nothing, and wake when
//! something could move them (`docs/contacts.md`, "Sleeping islands"). A sleeping ball keeps
//! its position to the bit; the work tally proves no gravity, wall or contact work is spent
//! on it; the lesson's ball never sleeps.

use bouncing_ball::physics::ball::Ball;
use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::physics::simulation::Simulation;
use bouncing_ball::scene::file::{preset, Spawn};
use bouncing_ball::testing::work::{self, Work};
use bouncing_ball_lab::accuracy::deepest_overlap;
use bouncing_ball_lab::scenes::late_drop;

/// The most frames a settling scene may take to fall asleep whole.
const SETTLE_LIMIT: u32 = 2_000;

/// Frames watched once a scene sleeps.
const WATCHED: u32 = 1_000;

/// The deepest overlap allowed between resting balls, as a share of their radius.
const RESTING_OVERLAP: f64 = 0.01;

/// Steps `simulation` until `count` balls sleep; returns the frames that took.
fn until_asleep(simulation: &mut Simulation, count: usize, what: &str) -> u32 {
    for frame in 1..=SETTLE_LIMIT {
        simulation.step();
        if simulation.sleeping_balls() == count {
            return frame;
        }
    }
    panic!(
        "{what}: expected {count} balls asleep within {SETTLE_LIMIT} frames, {} are",
        simulation.sleeping_balls()
    );
}

/// Steps `simulation` [`WATCHED`] frames and checks that no ball moves by a single bit, and
/// that no work of the kinds a moving ball costs is done.
fn assert_nothing_moves(simulation: &mut Simulation, what: &str) {
    let asleep: Vec<Ball> = simulation.balls().to_vec();
    work::reset();
    for frame in 1..=WATCHED {
        simulation.step();
        for (i, (now, then)) in simulation.balls().iter().zip(&asleep).enumerate() {
            assert!(
                (now.x, now.y, now.vx, now.vy) == (then.x, then.y, then.vx, then.vy),
                "{what}, frame {frame} after sleep: ball {i} expected to stay at \
                 ({}, {}) at rest, is at ({}, {}) moving ({}, {})",
                then.x,
                then.y,
                now.x,
                now.y,
                now.vx,
                now.vy
            );
        }
    }
    for kind in [
        Work::Contacts,
        Work::BallCollisions,
        Work::Gravity,
        Work::Walls,
        Work::Floor,
    ] {
        let done = work::count(kind);
        assert_eq!(done, 0, "{what}: {kind:?} work while asleep, expected 0");
    }
}

/// Checks that no two of `balls` overlap by more than `bound` of the first's radius, and
/// returns the deepest overlap, as that share.
fn assert_overlap_at_most(balls: &[Ball], bound: f64, what: &str) -> f64 {
    let deepest = deepest_overlap(balls) / balls[0].radius;
    assert!(
        deepest <= bound,
        "{what}: deepest overlap at rest expected at most {bound} r, got {deepest:.4} r"
    );
    deepest
}

#[test]
fn the_pile_falls_asleep_and_its_balls_do_not_move_once_asleep() {
    let scene = preset("pile", 1).unwrap();
    let mut simulation = scene.simulation();
    let frame = until_asleep(&mut simulation, scene.balls.len(), "pile");
    eprintln!("the pile sleeps from frame {frame}");
    assert_nothing_moves(&mut simulation, "pile");
    assert_overlap_at_most(simulation.balls(), RESTING_OVERLAP, "pile");
}

#[test]
fn the_pile_in_exact_mode_falls_asleep_and_takes_no_step_once_asleep() {
    let mut scene = preset("pile", 1).unwrap();
    scene.motion.collisions = CollisionMode::Exact;
    let mut simulation = scene.simulation();
    let frame = until_asleep(&mut simulation, scene.balls.len(), "exact pile");
    eprintln!("the exact pile sleeps from frame {frame}");
    // The step that found them all asleep may still have resolved an event; the next one
    // resolves none, and from then on no step is taken.
    simulation.step();
    assert_nothing_moves(&mut simulation, "exact pile");
}

#[test]
fn the_pyramid_stands_and_sleeps() {
    let scene = preset("pyramid", 1).unwrap();
    let mut simulation = scene.simulation();
    let start: Vec<Ball> = simulation.balls().to_vec();
    let frame = until_asleep(&mut simulation, scene.balls.len(), "pyramid");
    eprintln!("the pyramid sleeps from frame {frame}");
    assert_nothing_moves(&mut simulation, "pyramid");
    for (i, (now, then)) in simulation.balls().iter().zip(&start).enumerate() {
        // Stacked in place, each ball stays where it was set: within 0.05 r.
        let moved = (now.x - then.x).hypot(now.y - then.y) / then.radius;
        assert!(
            moved <= 0.05,
            "pyramid ball {i}: expected within 0.05 r of its start, moved {moved:.4} r"
        );
    }
}

/// Frames the late ball of [`late_drop`] is watched on its floor while the pile sleeps.
const SLIDING: u32 = 20;

#[test]
fn a_ball_dropped_onto_the_sleeping_pile_wakes_it_and_the_pile_comes_to_rest_again() {
    let scene = late_drop(1).unwrap();
    let mut simulation = scene.simulation();
    let pile = scene.balls.len() - 1;
    let late = |simulation: &Simulation| simulation.balls()[pile].clone();
    let frame = until_asleep(&mut simulation, pile, "pile under a late ball");
    let on_floor = late(&simulation);
    assert!(
        on_floor.x < 200.0 && on_floor.y < 100.0,
        "the late ball should still be on its floor when the pile sleeps (frame {frame}), \
         it is at ({}, {})",
        on_floor.x,
        on_floor.y
    );
    // While it slides, the solver's gravity is one ball's: one kick per iteration.
    work::reset();
    for _ in 0..SLIDING {
        simulation.step();
    }
    let kicks = work::count(Work::Gravity);
    let one_ball = u64::from(SLIDING * scene.motion.iterations);
    assert_eq!(
        kicks, one_ball,
        "gravity kicks while only the late ball is awake: expected {one_ball}, got {kicks}"
    );
    let mut landing = late(&simulation);
    let woken = (1..=SETTLE_LIMIT).find(|_| {
        landing = late(&simulation);
        simulation.step();
        simulation.sleeping_balls() < pile
    });
    let Some(woken) = woken else {
        panic!("the late ball did not wake the pile within {SETTLE_LIMIT} frames");
    };
    assert!(
        landing.y > 120.0 && landing.vy > 1.0,
        "the pile woke {woken} frames later, the late ball coming from ({}, {}) at ({}, {}): \
         expected it falling onto the pile",
        landing.x,
        landing.y,
        landing.vx,
        landing.vy
    );
    let again = until_asleep(&mut simulation, pile + 1, "pile woken by a late ball");
    eprintln!(
        "the pile sleeps from frame {frame}, wakes {woken} frames later, sleeps again {again} \
         frames after that"
    );
    assert_nothing_moves(&mut simulation, "pile woken by a late ball");
    assert_overlap_at_most(
        simulation.balls(),
        RESTING_OVERLAP,
        "pile woken by a late ball",
    );
}

#[test]
fn the_lessons_ball_never_sleeps() {
    for name in ["lesson", "elastic", "heavy", "moon"] {
        let scene = preset(name, 1).unwrap();
        let mut simulation = scene.simulation();
        assert!(simulation.takes_the_lessons_step(), "preset {name}");
        for frame in 1..=10 * WATCHED {
            simulation.step();
            let asleep = simulation.sleeping_balls();
            assert_eq!(asleep, 0, "preset {name}, frame {frame}: {asleep} asleep");
        }
    }
}

#[test]
fn balls_without_gravity_never_sleep() {
    let mut scene = preset("billiards", 1).unwrap();
    scene.ball_collisions = Some(0.5); // they slow down, but nothing presses them together
    let mut simulation = scene.simulation();
    for frame in 1..=WATCHED {
        simulation.step();
        let asleep = simulation.sleeping_balls();
        assert_eq!(asleep, 0, "frame {frame}: {asleep} asleep without gravity");
    }
}

/// The deepest overlap a heap 40 rows deep may keep once asleep, as a share of the radius.
const DEEP_HEAP_OVERLAP: f64 = 0.1;

#[test]
fn a_heap_forty_rows_deep_comes_to_rest_and_falls_asleep() {
    // 1,000 balls of radius 3 in a box 160 px wide: about 26 a row, 40 rows deep. One velocity
    // pass per sub-step lets such a heap sink and be lifted back in every sub-step, and it
    // churns for good; three carry its weight (docs/contacts.md, "Why this one"). A heap this
    // deep keeps some overlap when it sleeps: at spawn seeds 1 to 6, 0.045 to 0.094 r.
    let mut scene = preset("pile", 1).unwrap();
    (scene.width, scene.height) = (160, 400);
    scene.balls = Spawn::new(1_000, 3.0, 4.0).overlapping_balls(160.0, 400.0, 1);
    scene.validate().unwrap();
    let mut simulation = scene.simulation();
    let frame = until_asleep(&mut simulation, scene.balls.len(), "deep heap");
    let deepest = assert_overlap_at_most(simulation.balls(), DEEP_HEAP_OVERLAP, "deep heap");
    eprintln!("the deep heap sleeps from frame {frame}, deepest overlap {deepest:.4} r");
}
