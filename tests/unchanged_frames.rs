//! Frames that did not change cost nothing: a canvas draws again only what changed, the GIF
//! compares only there, and nothing else changes: the pixels are those of drawing every
//! frame whole, and the GIF's bytes those of comparing every frame whole.

mod common;

use bouncing_ball::gif::GifWriter;
use bouncing_ball::render::{Canvas, Damage, IndexedFrame, Renderer};
use bouncing_ball::scene::file as scene_file;
use bouncing_ball::testing::fill_circle;
use bouncing_ball::testing::work::{self, Work};
use bouncing_ball::testing::Rect;
use bouncing_ball::testing::MOST_BUSY_FRAMES;
use bouncing_ball::{BallSpec, Scene};
use common::decode_gif;

const TRAIL: usize = 5;

/// A coloured ball with a trail, so frames have something that fades and shrinks.
fn ball(x: f64, y: f64, vx: f64, vy: f64, radius: f64) -> BallSpec {
    BallSpec {
        colour: [255, 200, 60],
        trail_colour: [60, 140, 255],
        trail: TRAIL,
        ..common::white_ball(x, y, vx, vy, radius)
    }
}

/// A row of balls that never move (no gravity, no speed) and, unless `mover` is None, one
/// ball moving through them at that velocity (px/frame), bouncing off the walls.
fn still_balls_and(mover: Option<(f64, f64)>, frames: u32) -> Scene {
    let mut balls: Vec<BallSpec> = (0..12)
        .map(|i| ball(20.0 + 25.0 * f64::from(i), 200.0, 0.0, 0.0, 9.0))
        .collect();
    if let Some((vx, vy)) = mover {
        balls.push(ball(40.0, 60.0, vx, vy, 14.0));
    }
    Scene {
        balls,
        walls: Some(1.0),
        frames,
        ..Scene::empty(320, 240)
    }
}

/// What one frame of a run through a canvas cost, and what it said had changed.
struct FrameWork {
    drawn: u64,
    compared: u64,
    damage: Kind,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Unchanged,
    Whole,
    Areas,
}

/// Runs `scene` as the program does (a canvas drawn again where it changed, the GIF told
/// where), counting each frame's pixels drawn and compared; returns them with the GIF.
fn run_through_canvas(scene: &Scene) -> (Vec<FrameWork>, Vec<u8>) {
    let renderer = Renderer::new(scene).unwrap();
    let mut canvas = Canvas::new(&renderer);
    let mut gif = gif_writer(scene, &renderer);
    let mut simulation = scene.simulation();
    let mut costs = Vec::new();
    for _ in 0..scene.frames {
        simulation.step();
        work::reset();
        canvas.redraw(&renderer, simulation.balls());
        gif.write_changes(canvas.frame(), canvas.damage()).unwrap();
        costs.push(FrameWork {
            drawn: work::count(Work::PixelsDrawn),
            compared: work::count(Work::PixelsCompared),
            damage: kind(canvas.damage()),
        });
    }
    (costs, gif.finish().unwrap())
}

/// `scene`'s GIF the plain way: every frame drawn whole and compared whole.
fn gif_of_whole_frames(scene: &Scene) -> Vec<u8> {
    let renderer = Renderer::new(scene).unwrap();
    let mut frame = renderer.new_frame();
    let mut gif = gif_writer(scene, &renderer);
    let mut simulation = scene.simulation();
    for _ in 0..scene.frames {
        simulation.step();
        renderer.draw(simulation.balls(), &mut frame);
        gif.write_frame(&frame).unwrap();
    }
    gif.finish().unwrap()
}

fn gif_writer(scene: &Scene, renderer: &Renderer) -> GifWriter<Vec<u8>> {
    let (width, height) = (scene.width as u16, scene.height as u16);
    GifWriter::new(
        Vec::new(),
        width,
        height,
        renderer.palette(),
        scene.frame_ms,
    )
    .unwrap()
}

fn kind(damage: Damage) -> Kind {
    match damage {
        Damage::Unchanged => Kind::Unchanged,
        Damage::Whole => Kind::Whole,
        Damage::Areas(_) => Kind::Areas,
    }
}

#[test]
fn once_nothing_moves_a_frame_draws_and_compares_no_pixel() {
    let scene = still_balls_and(None, 40);
    let (costs, _) = run_through_canvas(&scene);
    let canvas = u64::from(scene.width * scene.height);
    // While the trails fill (a ball at rest lays its dots on itself), the frame is drawn
    // again; it is all drawn the first time.
    assert_eq!(costs[0].damage, Kind::Whole, "the first frame");
    assert!(
        costs[0].drawn >= canvas,
        "the first frame clears the canvas"
    );
    for (n, cost) in costs.iter().enumerate().skip(TRAIL) {
        assert_eq!(
            (cost.damage, cost.drawn, cost.compared),
            (Kind::Unchanged, 0, 0),
            "frame {n}: [damage, pixels drawn, pixels compared] once the trails are full"
        );
    }
}

#[test]
fn a_ball_moving_among_still_ones_draws_and_compares_only_around_itself() {
    let scene = still_balls_and(Some((3.0, 1.5)), 120);
    let (costs, _) = run_through_canvas(&scene);
    let canvas = u64::from(scene.width * scene.height);
    // The moving ball (radius 14) and its trail cover well under a quarter of the canvas, so
    // a frame marks at most a few rows of 32 px tiles around it. (While the trails grow, so
    // much changes that a few frames are drawn whole.)
    let settled = TRAIL + 2 * MOST_BUSY_FRAMES as usize;
    for (n, cost) in costs.iter().enumerate().skip(settled) {
        assert_eq!(cost.damage, Kind::Areas, "frame {n}");
        assert!(
            cost.drawn < canvas / 4 && cost.compared < canvas / 4,
            "frame {n}: {} pixels drawn and {} compared, of {canvas}",
            cost.drawn,
            cost.compared
        );
    }
}

/// Draws `scene` both ways, frame by frame, and checks that the canvas's frame is the
/// whole redraw's, and that what it says changed holds every pixel that did. Returns how
/// many frames were of each kind.
fn assert_same_pixels_as_whole_frames(name: &str, scene: &Scene) -> [usize; 3] {
    let renderer = Renderer::new(scene).unwrap();
    let mut canvas = Canvas::new(&renderer);
    let mut whole = renderer.new_frame();
    let mut previous: Option<IndexedFrame> = None;
    let mut kinds = [0; 3];
    let mut simulation = scene.simulation();
    for n in 0..scene.frames {
        simulation.step();
        canvas.redraw(&renderer, simulation.balls());
        renderer.draw(simulation.balls(), &mut whole);
        let differing = whole
            .as_raw()
            .iter()
            .zip(canvas.frame().as_raw())
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(differing, 0, "{name} frame {n}: pixels differ");
        if let Some(previous) = &previous {
            let outside = changed_outside(previous, &whole, canvas.damage());
            assert_eq!(
                outside,
                None,
                "{name} frame {n}: a pixel changed outside {:?}",
                canvas.damage()
            );
        }
        kinds[kind(canvas.damage()) as usize] += 1;
        previous = Some(whole.clone());
    }
    kinds
}

/// The first pixel that differs between `before` and `after` where `damage` says nothing
/// changed.
fn changed_outside(
    before: &IndexedFrame,
    after: &IndexedFrame,
    damage: Damage,
) -> Option<(u32, u32)> {
    let areas: &[Rect] = match damage {
        Damage::Whole => return None,
        Damage::Unchanged => &[],
        Damage::Areas(areas) => areas,
    };
    let inside = |x: u32, y: u32| {
        areas.iter().any(|a| {
            (a.left..a.left + a.width).contains(&x) && (a.top..a.top + a.height).contains(&y)
        })
    };
    before
        .enumerate_pixels()
        .find(|&(x, y, pixel)| pixel != after.get_pixel(x, y) && !inside(x, y))
        .map(|(x, y, _)| (x, y))
}

#[test]
fn drawing_only_what_changed_gives_the_pixels_of_drawing_every_frame_whole() {
    let mut kinds = [0; 3];
    for name in ["lesson", "many", "billiards", "slope", "pile", "pyramid"] {
        let scene = scene_file::preset(name, 1).unwrap();
        let counted = assert_same_pixels_as_whole_frames(name, &scene);
        kinds = [0, 1, 2].map(|k| kinds[k] + counted[k]);
    }
    // Big balls across tile edges and the canvas's, some still, some moving, some leaving.
    let mut scene = still_balls_and(Some((7.0, -3.0)), 150);
    scene.balls.push(ball(-10.0, 120.0, 0.0, 0.0, 40.0));
    scene.balls.push(ball(300.0, 230.0, 2.5, 1.0, 31.5));
    scene.balls.push(ball(160.0, 120.0, -9.0, 0.0, 0.4));
    scene.walls = None;
    let counted = assert_same_pixels_as_whole_frames("mixed", &scene);
    kinds = [0, 1, 2].map(|k| kinds[k] + counted[k]);
    let [unchanged, whole, areas] = kinds;
    assert!(
        unchanged > 50 && whole > 50 && areas > 50,
        "frames unchanged {unchanged}, whole {whole}, in areas {areas}: each kind should be tested"
    );
}

#[test]
fn the_gif_of_changes_is_the_gif_of_whole_frames_byte_for_byte() {
    let mut scenes: Vec<(&str, Scene)> = ["lesson", "many", "pile", "pyramid", "slope"]
        .into_iter()
        .map(|name| (name, scene_file::preset(name, 1).unwrap()))
        .collect();
    scenes.push(("still", still_balls_and(None, 300)));
    scenes.push(("one moving", still_balls_and(Some((3.0, 1.5)), 300)));
    for (name, scene) in scenes {
        let (_, from_changes) = run_through_canvas(&scene);
        assert!(
            from_changes == gif_of_whole_frames(&scene),
            "{name}: the GIFs differ"
        );
    }
}

#[test]
fn a_still_scene_longer_than_a_gif_delay_can_hold_keeps_its_time() {
    // 1 s frames: a GIF delay holds at most 655.35 s, so 700 still frames cannot all merge
    // into one: a one-pixel frame carries the time beyond.
    let scene = Scene {
        frame_ms: 1000,
        ..still_balls_and(None, 700)
    };
    let (_, bytes) = run_through_canvas(&scene);
    assert!(bytes == gif_of_whole_frames(&scene), "the GIFs differ");
    let delays = delays_cs(&bytes);
    let total: u32 = delays.iter().map(|&d| u32::from(d)).sum();
    assert_eq!(total, 700 * 100, "time shown in all, cs: {delays:?}");
    assert!(
        delays.iter().any(|&d| d > 60_000),
        "the still frames merge into long delays: {delays:?}"
    );
}

#[test]
fn frames_shown_for_no_time_are_each_kept_since_a_viewer_times_them_itself() {
    // Delay 0 has no time to add up: a viewer shows each such frame for a time of its own
    // choosing, so merging the still frames would shorten the animation. Each stays a frame
    // (a one-pixel one, since nothing changed).
    let scene = Scene {
        frame_ms: 0,
        ..still_balls_and(None, 12)
    };
    let (_, bytes) = run_through_canvas(&scene);
    assert_eq!(
        delays_cs(&bytes),
        vec![0; 12],
        "one frame of delay 0 per frame drawn"
    );
}

/// Each frame's delay in the GIF `bytes`, cs.
fn delays_cs(bytes: &[u8]) -> Vec<u16> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("still.gif");
    std::fs::write(&path, bytes).unwrap();
    decode_gif(&path).delays_cs
}

#[test]
fn the_pixels_drawn_tally_counts_exactly_the_pixels_a_circle_fills() {
    // The tally behind "a frame where nothing moved draws no pixel" must count pixels, not
    // rows or something near: whole circles, and circles cut by every edge of the canvas.
    for (x, y, radius) in [
        (20.0, 15.0, 7.3),
        (0.5, 14.0, 9.0),
        (40.0, 29.0, 6.0),
        (3.0, 3.0, 12.5),
    ] {
        let mut frame = IndexedFrame::new(40, 30);
        work::reset();
        fill_circle(&mut frame, x, y, radius, 1);
        let filled = frame.pixels().filter(|p| p[0] == 1).count() as u64;
        assert!(filled > 0, "circle ({x}, {y}) r {radius} fills something");
        assert_eq!(
            work::count(Work::PixelsDrawn),
            filled,
            "circle ({x}, {y}) r {radius}: pixels drawn as tallied and as filled"
        );
    }
}
