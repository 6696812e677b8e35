//! The budget's pilot keeps the frames it stepped, and a run plays them back instead of
//! stepping them again (`physics::replay`): what the run draws must be what stepping
//! would have drawn, every ball and trail to the bit, before, at and after the hand-over.

use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::physics::replay::{KeptFrames, Playback, KEPT_BYTES};
use bouncing_ball::physics::{Ball, Integrator, Simulation};
use bouncing_ball::scene::file::preset;
use bouncing_ball::scene::Scene;

/// Steps `kept` frames of `scene` and keeps them, then plays `frames` frames back and
/// checks each against a simulation stepped frame by frame.
fn assert_played_back_as_stepped(scene: &Scene, kept: usize, frames: usize) {
    let mut recorded = scene.simulation();
    let mut kept_frames = KeptFrames::new(&recorded, kept);
    for _ in 0..kept {
        recorded.step();
        assert!(kept_frames.keep(&recorded), "a small scene's frames fit");
    }
    let mut played = Playback::new(kept_frames, recorded);
    let mut stepped = scene.simulation();
    assert_eq!(played.balls(), stepped.balls(), "before the first frame");
    for frame in 0..frames {
        played.step();
        stepped.step();
        assert_eq!(
            played.balls(),
            stepped.balls(),
            "frame {frame} of {frames} ({kept} of them played back)"
        );
    }
}

#[test]
fn the_lessons_frames_played_back_are_the_frames_stepped() {
    let scene = preset("lesson", 1).expect("the lesson preset");
    assert_played_back_as_stepped(&scene, 30, 60);
}

#[test]
fn an_exact_pile_played_back_then_stepped_on_is_the_pile_stepped_throughout() {
    // Exact mode carries its calendar and clocks from step to step: the simulation handed
    // over must go on from the last kept frame as if it had never stopped.
    let mut scene = preset("pile", 1).expect("the pile preset");
    scene.motion.collisions = CollisionMode::Exact;
    scene.motion.integrator = Integrator::VelocityVerlet;
    assert_played_back_as_stepped(&scene, 40, 80);
}

#[test]
fn no_kept_frames_step_from_the_start() {
    let scene = preset("pile", 1).expect("the pile preset");
    assert_played_back_as_stepped(&scene, 0, 5);
}

#[test]
fn no_more_frames_are_kept_than_their_size_allows() {
    // 65,536 balls keep 2 MiB a frame: four frames fill 8 MiB exactly, a fifth does not fit.
    let balls = (0..65_536)
        .map(|i| Ball::new(f64::from(i % 300), 20.0, 1.0, 0.0, 1.0, 3))
        .collect();
    let simulation = Simulation::new(balls, Default::default(), Default::default(), None);
    let mut kept = KeptFrames::new(&simulation, 5);
    let per_frame = 65_536 * 32;
    let fitting = KEPT_BYTES / per_frame;
    assert_eq!(
        fitting * per_frame,
        KEPT_BYTES,
        "the example must fill the limit exactly"
    );
    for frame in 0..fitting {
        assert!(kept.keep(&simulation), "frame {frame} fits");
    }
    assert!(
        !kept.keep(&simulation),
        "frame {fitting} would pass {KEPT_BYTES} bytes"
    );
}

#[test]
fn a_run_steps_each_frame_once_though_its_pilot_stepped_them_first() {
    // Exact mode's pilot always runs; the run plays its frames back rather than stepping
    // them again, so an exact-mode run of 40 frames takes 40 steps in all.
    use bouncing_ball::job::{Job, OutputKind, Target};
    use bouncing_ball::testing::work::{self, Work};
    let mut scene = preset("pile", 1).expect("the pile preset");
    scene.motion.collisions = CollisionMode::Exact;
    scene.frames = 40;
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut job = Job::new();
    job.outputs = vec![Target {
        kind: OutputKind::Gif,
        path: dir.path().join("pile.gif"),
    }];
    work::reset();
    bouncing_ball::run::run(&scene, &job).expect("the run writes its GIF");
    assert_eq!(
        work::count(Work::BallCollisions),
        40,
        "steps in the pilot and the run"
    );
}
