//! The preset GIFs shown in the README (`scenes/NAME.gif`) must be what the program renders
//! now, byte for byte, so they cannot go stale. Regenerate on purpose:
//! `UPDATE_GOLDEN=1 cargo test --test presets`.

mod common;

use std::path::Path;

use bouncing_ball::scene::file::{self as scene_file, PRESETS};
use bouncing_ball::{run, Job, OutputKind};
use common::{decode_gif, render_frames};

#[test]
fn every_preset_gif_in_scenes_matches_a_fresh_render_byte_for_byte() {
    let dir = tempfile::tempdir().unwrap();
    let update = std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1");
    let mut stale = Vec::new();
    for (name, _) in PRESETS {
        let scene = scene_file::preset(name, 1).unwrap();
        let outputs = Job::pictures(
            dir.path().join(format!("{name}.gif")),
            dir.path().join(format!("{name}.png")),
        );
        run(&scene, &outputs).unwrap_or_else(|e| panic!("preset {name}: {e}"));
        let fresh = std::fs::read(outputs.path(OutputKind::Gif).unwrap()).unwrap();
        let committed_path =
            Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.gif"));
        if update {
            std::fs::write(&committed_path, &fresh).unwrap();
        } else if std::fs::read(&committed_path).ok().as_deref() != Some(&fresh[..]) {
            stale.push(name);
        }
    }
    assert!(
        stale.is_empty(),
        "these preset GIFs differ from a fresh render: {stale:?}. If the change is intended, regenerate: UPDATE_GOLDEN=1 cargo test --test presets"
    );
}

#[test]
fn every_frame_of_every_committed_preset_gif_shows_what_the_renderer_drew() {
    // While the test above rewrites the GIFs, they are checked on the next plain run.
    if std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1") {
        return;
    }
    for (name, _) in PRESETS {
        let scene = scene_file::preset(name, 1).unwrap();
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.gif"));
        let decoded = decode_gif(&path);
        let rendered = render_frames(&scene);
        let timeline = decoded.timeline((scene.frame_ms / 10) as u16);
        assert_eq!(timeline.len(), rendered.len(), "{name}: frames over time");
        for (n, (shown, drawn)) in timeline.iter().zip(&rendered).enumerate() {
            let wrong = shown.pixels().zip(drawn.pixels()).filter(|(a, b)| a != b);
            assert_eq!(wrong.count(), 0, "{name}, frame {n}: pixels differ");
        }
    }
}

#[test]
fn the_predicted_gif_size_of_every_preset_is_within_three_times_the_real_one() {
    for (name, _) in PRESETS {
        let scene = scene_file::preset(name, 1).unwrap();
        let predicted = bouncing_ball::budget::Estimate::of(&scene).gif_bytes;
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.gif"));
        let real = std::fs::metadata(path).unwrap().len() as f64;
        let ratio = predicted / real;
        assert!(
            (1.0 / 3.0..=3.0).contains(&ratio),
            "{name}: predicted {predicted:.0} B, the GIF is {real} B ({ratio:.2} times)"
        );
    }
}
