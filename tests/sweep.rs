//! `bouncing_ball sweep`, run as a user runs it in a temporary folder: the tiled GIF it
//! writes, decoded, panel by panel against the plain runs; and how it refuses bad sweeps.

mod common;

use std::path::Path;

use bouncing_ball::testing::{GAP, LABEL_STRIP};
use common::{decode_gif, run_in};
use image::RgbImage;

fn succeeds(dir: &Path, args: &[&str]) {
    let output = run_in(dir, args);
    assert!(
        output.status.success(),
        "{args:?}: exit {:?}: {}",
        output.status,
        String::from_utf8_lossy(&output.stderr)
    );
}

/// Every frame as a viewer shows it, one per 30 ms (frames that repeat are stored once).
fn frames(path: &Path) -> Vec<RgbImage> {
    let gif = decode_gif(path);
    gif.timeline(3).into_iter().cloned().collect()
}

/// Where panel `i` lies in a tiled frame `width` px wide of cells of `cell` (width, height) px
/// (docs/sweep.md: a label strip above each panel, gaps around every cell).
fn origin(i: u32, width: u32, cell: (u32, u32)) -> (u32, u32) {
    let columns = (width - GAP) / (cell.0 + GAP);
    let (column, row) = (i % columns, i / columns);
    let x = GAP + column * (cell.0 + GAP);
    let y = GAP + row * (LABEL_STRIP + cell.1 + GAP) + LABEL_STRIP;
    (x, y)
}

/// The part of `frame` at `at`, `size` px.
fn region(frame: &RgbImage, at: (u32, u32), size: (u32, u32)) -> RgbImage {
    image::imageops::crop_imm(frame, at.0, at.1, size.0, size.1).to_image()
}

/// Asserts that panel `i` of the sweep shows, frame for frame, what the plain run shows.
fn assert_panel_is_the_plain_run(sweep: &[RgbImage], plain: &[RgbImage], at: (u32, u32)) {
    assert_eq!(sweep.len(), plain.len(), "frame count");
    let size = plain[0].dimensions();
    for (n, (tiled, alone)) in sweep.iter().zip(plain).enumerate() {
        assert!(
            region(tiled, at, size) == *alone,
            "frame {n}: the panel at {at:?} differs from the plain run"
        );
    }
}

#[test]
fn four_damping_values_make_one_gif_of_four_labelled_panels_each_the_plain_run() {
    let dir = tempfile::tempdir().unwrap();
    let sweep = "damping=0.5,0.7,0.88,1.0";
    succeeds(
        dir.path(),
        &["sweep", sweep, "-o", "s.gif", "--png", "s.png"],
    );
    let tiled = frames(&dir.path().join("s.gif"));
    assert_eq!(tiled.len(), 200, "every frame of the scene");
    let (width, height) = tiled[0].dimensions();
    assert!(
        width >= 2 * 320 && height >= 2 * 240,
        "{width} x {height} cannot hold four 320 x 240 panels"
    );
    let still = image::open(dir.path().join("s.png")).unwrap().to_rgb8();
    assert!(still == tiled[199], "the PNG is the last tiled frame");

    for (i, damping) in ["0.5", "0.7", "0.88", "1.0"].into_iter().enumerate() {
        let at = origin(i as u32, width, (320, 240));
        // The label strip above the panel holds light text.
        let label = region(&tiled[0], (at.0, at.1 - LABEL_STRIP), (320, LABEL_STRIP));
        let lit = label.pixels().filter(|p| p.0[0] > 200).count();
        assert!(lit > 50, "panel {i}'s label lights only {lit} pixels");
        if damping == "0.5" || damping == "1.0" {
            let name = format!("plain-{damping}.gif");
            succeeds(dir.path(), &["--damping", damping, "-o", &name, "-q"]);
            assert_panel_is_the_plain_run(&tiled, &frames(&dir.path().join(name)), at);
        }
    }
}

#[test]
fn a_seed_sweep_shows_each_seeds_run_in_its_panel() {
    let dir = tempfile::tempdir().unwrap();
    let scene = ["-p", "many", "-n", "5"];
    succeeds(
        dir.path(),
        &[&["sweep", "seed=1,7", "-o", "s.gif"][..], &scene].concat(),
    );
    let tiled = frames(&dir.path().join("s.gif"));
    let width = tiled[0].width();
    for (i, seed) in ["1", "7"].into_iter().enumerate() {
        let name = format!("plain-{seed}.gif");
        succeeds(
            dir.path(),
            &[&["--seed", seed, "-o", &name, "-q"][..], &scene].concat(),
        );
        let plain = frames(&dir.path().join(name));
        let at = origin(i as u32, width, plain[0].dimensions());
        assert_panel_is_the_plain_run(&tiled, &plain, at);
    }
}

#[test]
fn a_preset_sweep_tiles_the_lessons_exercises_and_writes_the_same_bytes_twice() {
    let dir = tempfile::tempdir().unwrap();
    let sweep = "preset=elastic,no-gravity,heavy,moon";
    succeeds(dir.path(), &["sweep", sweep, "-o", "a.gif", "-q"]);
    succeeds(dir.path(), &["sweep", sweep, "-o", "b.gif", "-q"]);
    let a = std::fs::read(dir.path().join("a.gif")).unwrap();
    assert!(a == std::fs::read(dir.path().join("b.gif")).unwrap());
    let tiled = frames(&dir.path().join("a.gif"));
    assert_eq!(tiled.len(), 200);
    succeeds(dir.path(), &["--preset", "moon", "-o", "moon.gif", "-q"]);
    let moon = frames(&dir.path().join("moon.gif"));
    let width = tiled[0].width();
    assert_panel_is_the_plain_run(&tiled, &moon, origin(3, width, (320, 240)));
}

#[test]
fn panels_of_different_sizes_sit_in_cells_of_the_largest_each_still_the_plain_run() {
    let dir = tempfile::tempdir().unwrap();
    // `many` spawns its balls over whatever canvas it is given, so the width is laid over
    // the preset before its balls are placed, as `--width` is.
    let sweep = ["sweep", "width=200,320", "--preset", "many", "-n", "40"];
    succeeds(dir.path(), &[&sweep[..], &["-o", "w.gif", "-q"]].concat());
    let tiled = frames(&dir.path().join("w.gif"));
    for (i, width) in ["200", "320"].into_iter().enumerate() {
        let name = format!("many-{width}.gif");
        let plain = ["--preset", "many", "-n", "40", "--width", width];
        succeeds(dir.path(), &[&plain[..], &["-o", &name, "-q"]].concat());
        let at = origin(i as u32, tiled[0].width(), (320, 240));
        assert_panel_is_the_plain_run(&tiled, &frames(&dir.path().join(name)), at);
    }
    // The narrower panel's cell is filled beyond it with the tiling's background.
    let (x, y) = origin(0, tiled[0].width(), (320, 240));
    let beyond = tiled[0].get_pixel(x + 250, y + 100);
    assert_eq!(beyond.0, [48, 48, 48]);
}

#[test]
fn bad_sweeps_exit_2_with_one_line_saying_what_is_allowed_and_create_nothing() {
    let cases: &[(&[&str], &str)] = &[
        (&["dampign=0.5,1"], "did you mean damping?"),
        (
            &["damping=0.5,2"],
            "--damping 2 is not allowed: must be from 0 to 1",
        ),
        (&["damping=0.5,abc"], "--damping abc is not allowed"),
        (&["width=320,9000"], "must be a whole number from 1 to 8192"),
        (&["integrator=rk4,rk5"], "did you mean rk4?"),
        (&["preset=elastic,mon"], "did you mean moon?"),
        (&["damping="], "is not KEY=V1,V2,..."),
        (&["damping"], "is not KEY=V1,V2,..."),
        (&["=0.5,1"], "is not KEY=V1,V2,..."),
        (&["damping=0.5,,1"], "a value is empty"),
        (&["frame-ms=30,60"], "cannot be swept"),
        (
            &["damping=0.5,1", "--damping", "0.7"],
            "cannot also be given",
        ),
        (
            &["preset=moon,heavy", "--preset", "lesson"],
            "cannot also be given",
        ),
        (
            &["damping=0.5,1", "--width", "8000", "--height", "8000"],
            "over the 8192 px a side",
        ),
        (&["trail=100,300,1000"], "a GIF holds 256"),
        (
            &["damping=0.5,1", "--memory-budget", "10"],
            "--memory-budget",
        ),
        (
            &["damping=0.5,0.7,0.88,1", "-n", "2000", "--time-budget", "1"],
            "--time-budget",
        ),
        (
            &["damping=0.5,1", "-o", "s.png"],
            "give a name ending in .gif",
        ),
        (
            &["damping=0.5,1", "--png", "s.gif"],
            "give a name ending in .png",
        ),
    ];
    for (args, expected) in cases {
        let dir = tempfile::tempdir().unwrap();
        let output = run_in(dir.path(), &[&["sweep"], *args].concat());
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: one line: {stderr}");
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
        let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert!(left.is_empty(), "{args:?} left {left:?}");
    }
}

/// The README's sweep GIF and the flags that make it (docs/sweep.md says how to refresh it).
const README_SWEEP: (&str, &[&str]) = (
    "sweep-exercises.gif",
    &[
        "sweep",
        "preset=elastic,no-gravity,heavy,moon",
        "--frames",
        "100",
    ],
);

#[test]
fn the_readmes_sweep_gif_is_what_its_command_writes() {
    let (name, args) = README_SWEEP;
    let dir = tempfile::tempdir().unwrap();
    succeeds(dir.path(), &[args, &["-o", name, "-q"]].concat());
    let fresh = std::fs::read(dir.path().join(name)).unwrap();
    let committed = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs/img")
        .join(name);
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::write(&committed, &fresh).unwrap();
        return;
    }
    assert!(
        std::fs::read(&committed).ok() == Some(fresh),
        "docs/img/{name} differs from what `bouncing_ball {}` writes now; if intended, refresh it \
         with `UPDATE_GOLDEN=1 cargo test --release --test sweep`",
        args.join(" ")
    );
}

#[test]
fn ctrl_c_stops_a_long_sweep_leaving_no_temp_file_and_an_earlier_gif_as_it_was() {
    use common::process::{args, send, spawn, Request};
    use std::time::{Duration, Instant};
    let (name, code) = Request::Interrupt.expected();
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.gif"), b"an earlier GIF").unwrap();
    let list = [
        "sweep",
        "damping=0.5,1",
        "-n",
        "100000",
        "-o",
        "s.gif",
        "--png",
        "s.png",
    ];
    let mut child = spawn(dir.path(), &args(&[&list[..], &["-q"]].concat()), 3 << 30);
    child.stdout = None;
    let entries = || -> Vec<String> {
        let names = std::fs::read_dir(dir.path()).unwrap();
        let names = names.map(|e| e.unwrap().file_name().to_string_lossy().into_owned());
        names.collect()
    };
    let started = Instant::now();
    while entries().iter().filter(|n| n.ends_with(".tmp")).count() < 2 {
        assert!(
            started.elapsed() < Duration::from_secs(20),
            "no temporary files appeared"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    std::thread::sleep(Duration::from_millis(300)); // some frames into the sweep
    send(&child, Request::Interrupt);
    let output = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(code), "{name}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "one line: {stderr}");
    assert!(
        stderr.contains(&format!("stopped by {name}")) && stderr.contains("s.gif, s.png"),
        "{stderr}"
    );
    assert_eq!(entries(), ["s.gif"], "only the earlier GIF is left");
    let earlier = std::fs::read(dir.path().join("s.gif")).unwrap();
    assert_eq!(earlier, b"an earlier GIF");
}
