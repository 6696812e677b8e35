//! Scenes: presets, scene files and their errors, flag overrides, seeds, the colour budget,
//! and proof that an effect a scene does not call for never runs.

mod common;

use bouncing_ball::physics::motion::{CollisionMode, Motion, DEFAULT_ITERATIONS};
use bouncing_ball::physics::{Ball, Vec2};
use bouncing_ball::render::Renderer;
use bouncing_ball::scene::file::{self as scene_file, SceneFileError, PRESETS};
use bouncing_ball::scene::TrailFade;
use bouncing_ball::testing::work::{self, Work};
use bouncing_ball::testing::Overrides;
use bouncing_ball::testing::{shade, MAX_COLOURS};
use bouncing_ball::{BallSpec, Scene};
use common::lesson_scene;

#[test]
fn every_preset_parses_and_is_valid() {
    for (name, _) in PRESETS {
        let scene = scene_file::preset(name, 1).unwrap_or_else(|e| panic!("preset {name}: {e}"));
        assert!(!scene.balls.is_empty(), "preset {name} has balls");
    }
}

#[test]
fn the_lesson_preset_is_the_lesson_scene() {
    let preset = scene_file::preset("lesson", 1).unwrap();
    assert_eq!(
        preset,
        lesson_scene(),
        "scenes/lesson.toml must describe exactly the lesson's scene"
    );
}

#[test]
fn the_many_and_billiards_presets_have_fifty_balls() {
    for name in ["many", "billiards"] {
        let scene = scene_file::preset(name, 1).unwrap();
        assert_eq!(scene.balls.len(), 50, "preset {name}");
    }
    assert!(
        scene_file::preset("billiards", 1)
            .unwrap()
            .ball_collisions
            .is_some(),
        "billiards collides"
    );
    assert!(
        scene_file::preset("many", 1)
            .unwrap()
            .ball_collisions
            .is_none(),
        "many does not collide"
    );
}

#[test]
fn the_same_seed_spawns_the_same_balls_and_another_seed_other_balls() {
    let a = scene_file::preset("many", 7).unwrap();
    let b = scene_file::preset("many", 7).unwrap();
    let c = scene_file::preset("many", 8).unwrap();
    assert_eq!(a, b, "same seed, same scene");
    assert_ne!(a.balls, c.balls, "another seed, other balls");
}

#[test]
fn spawned_balls_that_collide_never_overlap_when_they_fit_side_by_side() {
    let scenes = ["billiards", "pile"]
        .into_iter()
        .flat_map(|name| (1..=20).map(move |seed| (name, scene_file::preset(name, seed))));
    for (name, scene) in scenes {
        let balls = scene.expect("a valid scene").balls;
        for (i, a) in balls.iter().enumerate() {
            for b in &balls[i + 1..] {
                let gap = (b.x - a.x).hypot(b.y - a.y) - (a.radius + b.radius);
                assert!(
                    gap > -1e-9 * a.radius,
                    "{name}: balls at ({}, {}) and ({}, {}) overlap by {} px, expected none",
                    a.x,
                    a.y,
                    b.x,
                    b.y,
                    -gap
                );
            }
        }
    }
}

#[test]
fn overrides_replace_only_the_values_given() {
    let mut scene = scene_file::preset("moon", 1).unwrap();
    let moon = scene.clone();
    Overrides {
        damping: Some(1.0),
        vx: Some(-1.5),
        iterations: Some(3),
        ..Overrides::default()
    }
    .apply(&mut scene);
    assert_eq!(scene.walls, Some(1.0), "--damping sets the walls' damping");
    assert_eq!(
        scene.motion.iterations, 3,
        "--iterations sets the iterations"
    );
    assert_eq!(scene.balls[0].vx, -1.5, "--vx sets every ball's vx");
    assert_eq!(
        scene.gravity, moon.gravity,
        "gravity not given, so the moon's is kept"
    );
    assert_eq!(
        scene.balls[0].radius, moon.balls[0].radius,
        "radius not given, so kept"
    );
}

#[test]
fn a_zero_gravity_or_drag_override_removes_the_effect() {
    let mut scene = lesson_scene();
    Overrides {
        gravity: Some(0.0),
        drag: Some(0.0),
        ..Overrides::default()
    }
    .apply(&mut scene);
    assert_eq!((scene.gravity, scene.drag), (None, None));
}

/// Steps `scene` for `frames` and returns the counted work.
fn work_done(scene: &Scene, frames: u32) -> [u64; 6] {
    let mut simulation = scene.simulation();
    work::reset();
    for _ in 0..frames {
        simulation.step();
    }
    [
        Work::Gravity,
        Work::Drag,
        Work::Walls,
        Work::Floor,
        Work::BallCollisions,
        Work::Contacts,
    ]
    .map(work::count)
}

#[test]
fn an_effect_the_scene_does_not_call_for_never_runs() {
    // [gravity, drag, walls, floor checks, exact ball-ball event steps, contact-solver steps]
    // over 100 frames.
    let cases = [
        ("lesson", [100, 0, 100, 0, 0, 0]),
        ("no-gravity", [0, 0, 100, 0, 0, 0]),
        ("drag", [100, 100, 100, 0, 0, 0]),
        ("slope", [100, 0, 200, 100, 0, 0]), // the box is checked before and after the floor
        ("many", [5000, 0, 5000, 0, 0, 0]),
        ("billiards", [0, 0, 5000, 0, 0, 100]),
    ];
    for (name, expected) in cases {
        let scene = scene_file::preset(name, 1).unwrap();
        let done = work_done(&scene, 100);
        assert_eq!(
            done, expected,
            "preset {name}: work done [gravity, drag, walls, floor, exact ball-ball, contact solver]"
        );
    }
    // The contact solver checks each ball's walls once per step; a ball that can touch
    // nothing takes the step in one go (gravity once), one that can, one sub-step per
    // iteration (gravity each time).
    let pile = work_done(&scene_file::preset("pile", 1).unwrap(), 100);
    assert_eq!(pile[1..], [0, 15000, 0, 0, 100], "preset pile: work done");
    let most = 15000 * u64::from(DEFAULT_ITERATIONS);
    assert!(
        (15000..=most).contains(&pile[0]),
        "preset pile: gravity expected 15000 to {most} times, got {}",
        pile[0]
    );
    // In exact mode ball-ball collisions are the event-driven step, once per step, and no
    // contact solver.
    let exact = Scene {
        motion: Motion {
            collisions: CollisionMode::Exact,
            ..Motion::default()
        },
        ..scene_file::preset("billiards", 1).unwrap()
    };
    assert_eq!(
        work_done(&exact, 100)[4..],
        [100, 0],
        "billiards in exact mode"
    );
}

#[test]
fn a_scene_whose_balls_keep_no_trail_never_records_a_trail_point() {
    // Drag moves the balls with the general solvers, which record the trails after the step.
    let scene = scene_file::preset("drag", 1).unwrap();
    let frames: u32 = 100;
    let points_recorded = |scene: &Scene| {
        let mut simulation = scene.simulation();
        work::reset();
        for _ in 0..frames {
            simulation.step();
        }
        work::count(Work::TrailPoint)
    };
    let expected = u64::from(frames) * scene.balls.len() as u64;
    assert_eq!(points_recorded(&scene), expected, "drag with its trails");
    let mut without = scene.clone();
    for ball in &mut without.balls {
        ball.trail = 0;
    }
    assert_eq!(
        points_recorded(&without),
        0,
        "drag with no ball keeping a trail"
    );
}

#[test]
fn a_scene_without_ball_collisions_never_builds_the_grid_or_the_contact_solver() {
    // The grid lives inside the contact solver or the event-driven step, which exist only when the
    // scene asks for ball-ball collisions.
    for (name, _) in PRESETS {
        let scene = scene_file::preset(name, 1).unwrap();
        let simulation = scene.simulation();
        assert_eq!(
            simulation.has_ball_collisions(),
            scene.ball_collisions.is_some(),
            "preset {name}"
        );
        assert_eq!(
            simulation.has_contact_solver(),
            scene.ball_collisions.is_some(),
            "preset {name}: clamp mode, so ball-ball collisions mean the contact solver"
        );
    }
}

#[test]
fn without_walls_no_wall_check_runs() {
    let scene = Scene {
        walls: None,
        ..lesson_scene()
    };
    assert_eq!(work_done(&scene, 50)[2], 0, "wall checks without walls");
}

fn parse_error(text: &str) -> String {
    match scene_file::parse("bad.toml", text, 1) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e.to_string(),
    }
}

const GOOD_HEAD: &str = "width = 320\nheight = 240\n";

#[test]
fn an_unknown_key_is_named_with_the_file_and_line() {
    let err = parse_error(&format!("{GOOD_HEAD}gravty = [0.0, 0.5]\n"));
    assert!(
        err.starts_with(
            "bad.toml: line 3: unknown key `gravty`; did you mean `gravity`?; the keys allowed here are `width`"
        ),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "one line: {err}");
}

#[test]
fn a_wrong_type_is_named_with_the_key_and_what_was_expected() {
    let err = parse_error(&format!(
        "{GOOD_HEAD}[[balls]]\nx = 40.0\ny = \"forty\"\nradius = 12.0\n"
    ));
    assert!(
        err.contains("key `balls[0].y`") && err.contains("expected a number"),
        "{err}"
    );
}

#[test]
fn a_missing_value_is_named() {
    let err = parse_error("width = 320\n");
    assert_eq!(err, "bad.toml: missing key `height`");
    let err = parse_error(&format!("{GOOD_HEAD}[[balls]]\nx = 40.0\ny = 40.0\n"));
    assert_eq!(err, "bad.toml: line 3: missing key `radius` in `balls[0]`");
}

#[test]
fn an_unclosed_table_is_named_by_its_header_and_line() {
    let err = parse_error(&format!("{GOOD_HEAD}\n[[balls]\nx = 40.0\n"));
    assert_eq!(err, "bad.toml: line 4: unclosed [[balls]] table");
    let err = parse_error(&format!("{GOOD_HEAD}[walls\ndamping = 1\n"));
    assert_eq!(err, "bad.toml: line 3: unclosed [walls] table");
}

#[test]
fn a_duplicate_key_is_named() {
    let err = parse_error(&format!("{GOOD_HEAD}width = 100\n"));
    assert_eq!(err, "bad.toml: line 3: duplicate key `width`");
}

#[test]
fn an_out_of_range_number_is_named_with_its_allowed_range() {
    for (extra, key, allowed) in [
        ("walls = { damping = 1.5 }\n", "walls.damping = 1.5", "from 0 to 1"),
        ("drag = -0.1\n", "drag = -0.1", "from 0 to 1"),
        ("ball_collisions = { restitution = 2.0 }\n", "ball_collisions.restitution = 2", "from 0 to 1"),
        ("substeps = 0\n", "substeps = 0", "1 to 10000"),
        ("iterations = 0\n", "iterations = 0", "1 to 1000"),
        ("[[floors]]\nfrom = [0.0, 1.0]\nto = [0.0, 1.0]\ndamping = 1.0\n", "floors[0].to", "must differ"),
        ("[[balls]]\nx = 40.0\ny = 40.0\nradius = 200.0\n", "balls[0].radius = 200", "2·radius < width"),
        ("[spawn]\ncount = 5000000\nradius = 1.0\nmax_speed = 1.0\ncolours = []\ntrail_colours = []\n", "spawn.count", "at most"),
    ] {
        let err = parse_error(&format!("{GOOD_HEAD}{extra}"));
        assert!(err.starts_with("bad.toml: ") && err.contains(key) && err.contains(allowed), "{extra:?}: {err}");
    }
}

#[test]
fn an_unknown_preset_lists_the_presets() {
    let err = scene_file::preset("mars", 1).unwrap_err();
    assert!(matches!(err, SceneFileError::UnknownPreset { .. }));
    assert!(err.to_string().contains("moon"), "{err}");
}

#[test]
fn the_bad_scene_file_exits_2_with_one_line_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("bad.toml"),
        format!("{GOOD_HEAD}walls = {{ damping = 7.0 }}\n"),
    )
    .unwrap();
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_bouncing_ball"))
        .args(["--scene", "bad.toml"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("bad.toml")
            && err.contains("walls.damping = 7")
            && err.contains("from 0 to 1"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "only the scene file remains"
    );
}

fn ball(trail_colour: [u8; 3], trail: usize) -> BallSpec {
    BallSpec {
        trail_colour,
        trail,
        ..lesson_scene().balls[0].clone()
    }
}

#[test]
fn trails_beyond_the_gif_colour_budget_fade_in_fewer_evenly_spaced_shades() {
    // Two 300-point trails in two colours need thousands of exact shades.
    let scene = Scene {
        balls: vec![ball([60, 140, 255], 300), ball([255, 90, 90], 300)],
        ..lesson_scene()
    };
    let renderer = Renderer::new(&scene).unwrap();
    let colours = renderer.palette().colours();
    assert!(
        colours.len() <= MAX_COLOURS,
        "palette holds {} colours",
        colours.len()
    );
    // The rule: (256 − 2 solid colours) / 2 trail colours = 127 levels, fade k/127 for k = 1..=127.
    let levels = 127;
    let allowed: Vec<[u8; 3]> = [[0, 0, 0], [255, 200, 60]]
        .into_iter()
        .chain(
            [[60, 140, 255], [255, 90, 90]]
                .iter()
                .flat_map(|&c| (1..=levels).map(move |k| shade(c, k as f64 / levels as f64))),
        )
        .collect();
    for colour in colours {
        assert!(
            allowed.contains(colour),
            "{colour:?} is not background, ball, or a trail shade at k/{levels}"
        );
    }
    assert!(
        colours.len() > 200,
        "the budget is used, not collapsed: {} colours",
        colours.len()
    );
}

#[test]
fn the_lesson_trail_fits_with_every_exact_shade() {
    let renderer = Renderer::new(&lesson_scene()).unwrap();
    let n = renderer.palette().colours().len();
    assert!(
        n < MAX_COLOURS,
        "the lesson's palette fits exactly: {n} colours"
    );
    // Dot 0 of 20 shines at 1/20: int(60/20, 140/20, 255/20) = (3, 7, 12).
    assert!(
        renderer.palette().colours().contains(&[3, 7, 12]),
        "the faintest exact lesson shade is present"
    );
}

#[test]
fn the_lesson_palette_leaves_out_the_trail_shade_the_ball_always_covers() {
    // A trail's newest dot is the ball's own circle at fade 1, drawn over by the ball: its
    // shade, the full trail colour, is never seen. The rest fit 128 entries (7-bit codes).
    let renderer = Renderer::new(&lesson_scene()).unwrap();
    let colours = renderer.palette().colours();
    assert!(
        !colours.contains(&[60, 140, 255]),
        "the full trail colour is never visible"
    );
    assert_eq!(colours.len(), 128, "background, ball and 126 trail shades");
}

#[test]
fn once_the_lesson_trail_has_grown_every_frame_uses_only_indices_below_32() {
    // Background, ball and the 19 shades a full 20-point trail draws come first in the
    // table, so those frames are coded with 5-bit indices.
    let scene = lesson_scene();
    let renderer = Renderer::new(&scene).unwrap();
    let mut simulation = scene.simulation();
    let mut frame = renderer.new_frame();
    for n in 0..scene.frames {
        simulation.step();
        renderer.draw(simulation.balls(), &mut frame);
        let largest = frame.as_raw().iter().copied().max().unwrap();
        if n >= 19 {
            assert!(largest < 32, "frame {n} uses index {largest}");
        }
    }
}

#[test]
fn the_iterations_key_sets_the_contact_solver_iterations_and_defaults_to_the_constant() {
    let given = scene_file::parse("it.toml", &format!("{GOOD_HEAD}iterations = 3\n"), 1).unwrap();
    assert_eq!(given.motion.iterations, 3, "iterations = 3");
    let default = scene_file::parse("it.toml", GOOD_HEAD, 1).unwrap();
    assert_eq!(
        default.motion.iterations, DEFAULT_ITERATIONS,
        "no key: the default"
    );
}

#[test]
fn a_scene_file_saved_by_a_windows_editor_with_crlf_and_a_byte_order_mark_reads_the_same() {
    let dir = tempfile::tempdir().unwrap();
    for (name, text) in PRESETS {
        let plain = dir.path().join("plain.toml");
        let windows = dir.path().join("windows.toml");
        std::fs::write(&plain, text).unwrap();
        std::fs::write(&windows, format!("\u{feff}{}", text.replace('\n', "\r\n"))).unwrap();
        let read = |path: &std::path::Path| format!("{:?}", scene_file::load(path, 7).unwrap());
        assert_eq!(
            read(&windows),
            read(&plain),
            "preset {name} with CRLF and a BOM"
        );
    }
}

#[test]
fn the_trail_fade_sets_the_shades_and_a_trail_that_does_not_fade_uses_one() {
    let with = |fade| Scene {
        trail_fade: fade,
        ..lesson_scene()
    };
    let trail = lesson_scene().balls[0].trail_colour;
    let none = Renderer::new(&with(TrailFade::None)).unwrap();
    let shades: Vec<_> = none
        .palette()
        .colours()
        .iter()
        .filter(|&&c| c != [0, 0, 0])
        .collect();
    assert_eq!(
        shades.len(),
        2,
        "the ball's colour and the one trail colour: {shades:?}"
    );
    assert!(shades.contains(&&trail), "{shades:?}");
    // A power darkens each dot to (share)^p of the colour: the oldest dot of a full trail of
    // 20 at power 2 is (1/20)² of it.
    let squared = Renderer::new(&with(TrailFade::Power(2.0))).unwrap();
    let oldest = shade(trail, (1.0f64 / 20.0).powi(2));
    assert!(
        squared.palette().colours().contains(&oldest),
        "missing {oldest:?}"
    );
    assert!(!squared
        .palette()
        .colours()
        .contains(&shade(trail, 1.0 / 20.0)));
}

#[test]
fn a_trail_that_does_not_shrink_draws_its_dots_at_the_balls_radius() {
    let drawn_trail_pixels = |shrink: bool| {
        let scene = Scene {
            trail_fade: TrailFade::None,
            trail_shrink: shrink,
            ..lesson_scene()
        };
        let renderer = Renderer::new(&scene).unwrap();
        // Two trail points far apart: the older is drawn (at half the radius if it shrinks),
        // the newer lies under the ball.
        let mut ball = Ball::new(200.0, 120.0, 0.0, 0.0, 12.0, 2);
        ball.trail.push(Vec2::new(60.0, 120.0));
        ball.trail.push(Vec2::new(200.0, 120.0));
        let mut frame = renderer.new_frame();
        renderer.draw(&[ball], &mut frame);
        let trail = scene.balls[0].trail_colour;
        frame
            .pixels()
            .filter(|p| renderer.palette().rgb(p.0[0]) == trail)
            .count()
    };
    let (full, shrunk) = (drawn_trail_pixels(false), drawn_trail_pixels(true));
    // π·12² ≈ 452 px against π·6² ≈ 113 px.
    assert!(
        (400..=500).contains(&full),
        "a dot at the ball's radius: {full} px"
    );
    assert!(
        (90..=140).contains(&shrunk),
        "a dot at half the radius: {shrunk} px"
    );
}
