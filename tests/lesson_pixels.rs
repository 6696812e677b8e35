//! Our pictures are the lesson's: every frame of the default scene and of elastic, heavy and
//! moon, decoded from our GIF, equals the RGB frame the lesson's script draws with Pillow;
//! and random float circles fill exactly the pixels Pillow fills. The script's side is
//! committed as data (`tests/data/script_frames.txt`, `tests/data/pillow_circles.txt`), so no
//! Python is needed here; `python3 tools/lesson.py bless` regenerates it.

mod common;

use std::collections::BTreeSet;

use bouncing_ball::render::IndexedFrame;
use bouncing_ball::scene::file as scene_file;
use bouncing_ball::testing::fill_circle;
use bouncing_ball::{run, Job, OutputKind};
use common::{decode_gif, lesson_scene, REBLESS};

/// CRC-32 of each of the script's frames for `scene`, in frame order.
fn script_frame_crcs(scene: &str) -> Vec<u32> {
    include_str!("data/script_frames.txt")
        .lines()
        .filter(|line| !line.starts_with('#'))
        .filter_map(|line| {
            let fields: Vec<&str> = line.split(' ').collect();
            (fields[0] == scene).then(|| u32::from_str_radix(fields[2], 16).unwrap())
        })
        .collect()
}

#[test]
fn every_frame_of_our_gifs_equals_the_lesson_scripts_frame() {
    let dir = tempfile::tempdir().unwrap();
    for name in ["lesson", "elastic", "heavy", "moon"] {
        let scene = if name == "lesson" {
            lesson_scene()
        } else {
            scene_file::preset(name, 1).unwrap()
        };
        let outputs = Job::pictures(
            dir.path().join(format!("{name}.gif")),
            dir.path().join(format!("{name}.png")),
        );
        run(&scene, &outputs).unwrap();
        let ours: Vec<u32> = decode_gif(outputs.path(OutputKind::Gif).unwrap())
            .frames
            .iter()
            .map(|frame| crc32fast::hash(frame.as_raw()))
            .collect();
        let script = script_frame_crcs(name);
        assert_eq!(ours.len(), script.len(), "{name}: frame count");
        let differing: Vec<usize> = (0..ours.len()).filter(|&n| ours[n] != script[n]).collect();
        assert!(
            differing.is_empty(),
            "{name}: frames {differing:?} differ from the lesson script's (CRC-32 of the RGB bytes). \
             Write one with `python3 tools/lesson.py frames DIR N --scene scenes/{name}.toml` to look; \
             re-bless only if the script or Pillow changed on purpose: {REBLESS}"
        );
    }
}

/// One circle of the committed table and the pixels Pillow filled for it.
struct PillowCircle {
    x: f64,
    y: f64,
    radius: f64,
    pixels: BTreeSet<(u32, u32)>,
}

fn pillow_circles() -> (u32, Vec<PillowCircle>) {
    let mut side = 0;
    let mut circles: Vec<PillowCircle> = Vec::new();
    for line in include_str!("data/pillow_circles.txt").lines() {
        let fields: Vec<&str> = line.split(' ').collect();
        match fields[0] {
            "#" => {}
            "side" => side = fields[1].parse().unwrap(),
            "circle" => circles.push(PillowCircle {
                x: fields[1].parse().unwrap(),
                y: fields[2].parse().unwrap(),
                radius: fields[3].parse().unwrap(),
                pixels: BTreeSet::new(),
            }),
            _ => {
                let [row, first, last] = [0, 1, 2].map(|i| fields[i].parse::<u32>().unwrap());
                let circle = circles.last_mut().unwrap();
                circle
                    .pixels
                    .extend((first..=last).map(|column| (column, row)));
            }
        }
    }
    (side, circles)
}

#[test]
fn random_float_circles_fill_exactly_the_pixels_pillow_fills() {
    let (side, circles) = pillow_circles();
    assert!(
        circles.len() >= 100,
        "the table holds {} circles",
        circles.len()
    );
    let mut mismatches = Vec::new();
    for c in &circles {
        let mut frame = IndexedFrame::new(side, side);
        fill_circle(&mut frame, c.x, c.y, c.radius, 1);
        let ours: BTreeSet<(u32, u32)> = frame
            .enumerate_pixels()
            .filter(|p| p.2[0] == 1)
            .map(|p| (p.0, p.1))
            .collect();
        if ours != c.pixels {
            mismatches.push(format!(
                "circle x={} y={} r={}: only ours {:?}, only Pillow's {:?}",
                c.x,
                c.y,
                c.radius,
                ours.difference(&c.pixels).collect::<Vec<_>>(),
                c.pixels.difference(&ours).collect::<Vec<_>>()
            ));
        }
    }
    assert!(
        mismatches.is_empty(),
        "{} of {} circles differ from Pillow's:\n{}",
        mismatches.len(),
        circles.len(),
        mismatches.join("\n")
    );
}

#[test]
fn the_circle_table_covers_tiny_radii_half_pixel_centres_and_the_top_left_edge() {
    let (_, circles) = pillow_circles();
    let tiny = circles.iter().filter(|c| c.radius < 1.0).count();
    let half = circles.iter().filter(|c| c.x.fract().abs() == 0.5).count();
    let over_edge = circles.iter().filter(|c| c.x - c.radius < 0.0).count();
    let empty = circles.iter().filter(|c| c.pixels.is_empty()).count();
    assert!(
        tiny >= 20 && half >= 20 && over_edge >= 10 && empty >= 1,
        "tiny {tiny}, centred on .5 {half}, over the left edge {over_edge}, filling nothing {empty}"
    );
}
