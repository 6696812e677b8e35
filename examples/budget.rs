//! Budget: the memory, time and GIF size the program predicts for a scene before running it,
//! next to what the release binary measures (wall time, and peak RSS from GNU time), for
//! every preset, long runs, exact mode's collisions and crowds. Shows how far the estimates
//! can be trusted; each ratio is predicted over measured. Then the same for `compare`, and how
//! soon a budget below the prediction refuses a run.
//!
//! Run: `cargo build --release && cargo run --release --example budget`. Needs GNU time at
//! /usr/bin/time (skips the measurements without it). Each row is the median of three runs.
//! Writes only to a temporary folder.

use std::path::Path;
use std::process::Command;
use std::time::Instant;

use bouncing_ball::budget::Estimate;
use bouncing_ball::compare::estimate::estimate_seconds;
use bouncing_ball::compare::methods;
use bouncing_ball::physics::motion::CollisionMode;
use bouncing_ball::physics::Integrator;
use bouncing_ball::scene::{file, Scene};

/// Name, scene file text and extra flags: every preset, long runs of some, exact mode's
/// collisions, and crowds. The flags are those `apply` knows.
const SCENES: &[(&str, &str, &[&str])] = &[
    ("lesson", "", &["--preset", "lesson"]),
    ("elastic", "", &["--preset", "elastic"]),
    ("no-gravity", "", &["--preset", "no-gravity"]),
    ("heavy", "", &["--preset", "heavy"]),
    ("moon", "", &["--preset", "moon"]),
    ("many", "", &["--preset", "many"]),
    ("billiards", "", &["--preset", "billiards"]),
    ("slope", "", &["--preset", "slope"]),
    ("drag", "", &["--preset", "drag"]),
    ("pile", "", &["--preset", "pile"]),
    ("pyramid", "", &["--preset", "pyramid"]),
    ("lesson ×20k frames", "", &["--preset", "lesson", "--frames", "20000"]),
    ("elastic ×20k frames", "", &["--preset", "elastic", "--frames", "20000"]),
    ("many ×100k frames", "", &["--preset", "many", "--frames", "100000"]),
    ("pile ×2k frames", "", &["--preset", "pile", "--frames", "2000"]),
    ("pile ×200k frames (asleep)", "", &["--preset", "pile", "--frames", "200000"]),
    ("billiards ×2k frames", "", &["--preset", "billiards", "--frames", "2000"]),
    (
        "lesson ×10M frames (the default scene)",
        "",
        &["--preset", "lesson", "--frames", "10000000"],
    ),
    (
        "pile, exact, rk4, 4 substeps, 100 frames",
        "",
        &[
            "--preset", "pile", "--collisions", "exact", "--integrator", "rk4", "--substeps", "4",
            "--frames", "100",
        ],
    ),
    (
        "pile, exact, velocity-verlet, 100 frames",
        "",
        &[
            "--preset", "pile", "--collisions", "exact", "--integrator", "velocity-verlet",
            "--frames", "100",
        ],
    ),
    (
        "pile, exact, 100 frames",
        "",
        &["--preset", "pile", "--collisions", "exact", "--frames", "100"],
    ),
    ("billiards, exact", "", &["--preset", "billiards", "--collisions", "exact"]),
    (
        "8192² canvas, 3 frames",
        "width = 8192\nheight = 8192\nframes = 3\n[[balls]]\nx = 100.0\ny = 100.0\nradius = 50.0\n",
        &[],
    ),
    (
        "2,000 balls × trail 1,000, 5 frames",
        "width = 640\nheight = 480\nframes = 5\ngravity = [0.0, 0.5]\nwalls = { damping = 0.9 }\n[spawn]\ncount = 2000\nradius = 4.0\nmax_speed = 5.0\ntrail = 1000\ncolours = [[255, 200, 60]]\ntrail_colours = [[60, 140, 255], [255, 90, 90]]\n",
        &[],
    ),
    (
        "20,000 overlapping r=100, collisions, 3 frames",
        "width = 400\nheight = 400\nframes = 3\nwalls = { damping = 0.9 }\nball_collisions = { restitution = 0.9 }\n[spawn]\ncount = 20000\nradius = 100.0\nmax_speed = 1.0\ntrail = 0\ncolours = [[255, 200, 60]]\ntrail_colours = [[60, 140, 255]]\n",
        &[],
    ),
    (
        "300,000 balls × trail 20, 10 frames",
        "width = 1000\nheight = 1000\nframes = 10\nwalls = { damping = 0.9 }\n[spawn]\ncount = 300000\nradius = 2.0\nmax_speed = 3.0\ntrail = 20\ncolours = [[255, 200, 60]]\ntrail_colours = [[60, 140, 255]]\n",
        &[],
    ),
];

fn main() {
    let bin = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/release/bouncing_ball");
    let time = Path::new("/usr/bin/time");
    let measured = bin.exists() && time.exists();
    if !measured {
        eprintln!("(no release binary or no /usr/bin/time: predictions only)");
    }
    let dir = tempfile::tempdir().expect("a temporary folder");
    println!("| scene | memory predicted | peak RSS | time predicted | wall time | ratio | GIF predicted | GIF | ratio |");
    println!("|---|--:|--:|--:|--:|--:|--:|--:|--:|");
    for (name, text, flags) in SCENES {
        let scene_path = dir.path().join("scene.toml");
        let mut args: Vec<String> = flags.iter().map(|s| s.to_string()).collect();
        let mut scene = if text.is_empty() {
            file::preset(flags[1], 1).expect("a preset")
        } else {
            std::fs::write(&scene_path, text).expect("write the scene");
            args.extend(["--scene".into(), scene_path.display().to_string()]);
            file::parse("scene.toml", text, 1).expect("a valid scene")
        };
        apply(&mut scene, flags);
        let estimate = Estimate::of(&scene);
        let gif = dir.path().join("out.gif");
        let (mut rss, mut wall, mut gif_bytes) = ("-".to_string(), "-".to_string(), "-".into());
        let (mut time_ratio, mut gif_ratio) = ("-".to_string(), "-".to_string());
        if measured {
            // The median of three runs: other work on the machine makes any one of them slow.
            let mut runs: Vec<(f64, f64)> = (0..3)
                .map(|_| measure(time, &bin, &args, dir.path()))
                .collect();
            runs.sort_by(|a, b| a.0.total_cmp(&b.0));
            let (seconds, kb) = runs[1];
            rss = format!("{:.0} MB", kb / 1024.0);
            wall = format!("{seconds:.3} s");
            time_ratio = format!("{:.2}", estimate.seconds / seconds);
            if let Ok(meta) = std::fs::metadata(&gif) {
                gif_bytes = mb(meta.len() as f64);
                gif_ratio = format!("{:.2}", estimate.gif_bytes / meta.len() as f64);
            }
        }
        println!(
            "| {name} | {} | {rss} | {:.3} s | {wall} | {time_ratio} | {} | {gif_bytes} | {gif_ratio} |",
            mb(estimate.memory as f64),
            estimate.seconds,
            mb(estimate.gif_bytes),
        );
    }
    if measured {
        comparisons(&bin, dir.path());
    }
}

/// Comparisons (`compare`): the time predicted before any work against the run's, and how
/// soon a budget below the prediction refuses it.
const COMPARISONS: &[&[&str]] = &[
    &["--preset", "moon"],
    &["--preset", "billiards"],
    &["--preset", "pile", "--frames", "40"],
];

/// Runs that a budget of 0.1 s refuses up front: how long the refusal takes.
const REFUSED: &[&[&str]] = &[
    &["compare", "--preset", "pile", "--frames", "40"],
    &[
        "--preset",
        "pile",
        "--collisions",
        "exact",
        "--integrator",
        "rk4",
        "--substeps",
        "4",
        "--frames",
        "100",
    ],
    &["--frames", "10000000"],
];

/// The comparisons' table, and the refusals'.
fn comparisons(bin: &Path, dir: &Path) {
    println!();
    println!("| comparison | time predicted | wall time | ratio |");
    println!("|---|--:|--:|--:|");
    for flags in COMPARISONS {
        let mut scene = file::preset(flags[1], 1).expect("a preset");
        apply(&mut scene, flags);
        let methods = methods::parse_list(methods::DEFAULT_METHODS).expect("the default methods");
        let predicted = estimate_seconds(&scene, &methods);
        let args: Vec<String> = ["compare", "-q"]
            .iter()
            .chain(*flags)
            .map(|s| s.to_string())
            .collect();
        let started = Instant::now();
        let status = Command::new(bin)
            .args(&args)
            .current_dir(dir)
            .status()
            .expect("compare runs");
        assert!(status.success(), "compare {flags:?}");
        let seconds = started.elapsed().as_secs_f64();
        let ratio = predicted / seconds;
        println!(
            "| compare {} | {predicted:.2} s | {seconds:.2} s | {ratio:.2} |",
            flags.join(" ")
        );
    }
    println!();
    println!("| refused under --time-budget 0.1 | exit | refused after |");
    println!("|---|--:|--:|");
    for flags in REFUSED {
        let started = Instant::now();
        let output = Command::new(bin)
            .args(*flags)
            .args(["--time-budget", "0.1"])
            .current_dir(dir)
            .output()
            .expect("the binary runs");
        let seconds = started.elapsed().as_secs_f64();
        let exit = output.status.code().unwrap_or(-1);
        println!("| {} | {exit} | {seconds:.2} s |", flags.join(" "));
    }
}

fn mb(bytes: f64) -> String {
    format!("{:.1} MB", bytes / 1048576.0)
}

/// Lays the flags of a row over its scene, as the program does with them.
fn apply(scene: &mut Scene, flags: &[&str]) {
    for pair in flags.chunks(2) {
        match pair {
            ["--preset", _] => {}
            ["--frames", n] => scene.frames = n.parse().expect("frames"),
            ["--substeps", n] => scene.motion.substeps = n.parse().expect("substeps"),
            ["--collisions", "exact"] => scene.motion.collisions = CollisionMode::Exact,
            ["--integrator", "rk4"] => scene.motion.integrator = Integrator::Rk4,
            ["--integrator", "velocity-verlet"] => {
                scene.motion.integrator = Integrator::VelocityVerlet
            }
            other => panic!("the example does not know the flags {other:?}"),
        }
    }
}

/// Runs the binary with `args` under GNU time, writing into `dir`: wall time, seconds (timed
/// here: GNU time's %e counts hundredths of a second), and peak RSS, KB.
fn measure(time: &Path, bin: &Path, args: &[String], dir: &Path) -> (f64, f64) {
    let started = Instant::now();
    let output = Command::new(time)
        .args(["-f", "%M"])
        .arg(bin)
        .args(args)
        .args(["-q", "--memory-budget", "100000", "--gif"])
        .arg(dir.join("out.gif"))
        .arg("--png")
        .arg(dir.join("out.png"))
        .output()
        .expect("GNU time runs");
    let seconds = started.elapsed().as_secs_f64();
    let stderr = String::from_utf8_lossy(&output.stderr);
    let kb = stderr
        .lines()
        .last()
        .unwrap_or("")
        .trim()
        .parse()
        .unwrap_or(0.0);
    (seconds, kb)
}
