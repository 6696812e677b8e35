//! The real binary, run in a temporary folder: what it writes, what it prints, and how it
//! refuses bad input.

mod common;

use std::path::Path;

use common::{decode_gif, run_in, stderr};

fn temp_dir() -> tempfile::TempDir {
    tempfile::tempdir().expect("a temporary folder")
}

#[test]
fn default_run_writes_a_looping_gif_of_every_frame_and_a_png_of_the_last() {
    let dir = temp_dir();
    let output = run_in(dir.path(), &["--damping", "0.88", "--gravity", "0.5"]);
    assert!(
        output.status.success(),
        "exit {:?}: {}",
        output.status,
        stderr(&output)
    );
    let summary = String::from_utf8_lossy(&output.stdout);
    assert!(
        summary.contains("bouncing_ball.gif") && summary.contains("200 frames"),
        "summary line: {summary}"
    );

    let gif = decode_gif(&dir.path().join("bouncing_ball.gif"));
    assert_eq!((gif.width, gif.height), (320, 240), "GIF size");
    assert_eq!(gif.frames.len(), 200, "GIF frame count");
    assert!(
        gif.delays_cs.iter().all(|&d| d == 3),
        "every delay should be 3 cs (30 ms): {:?}",
        &gif.delays_cs[..5]
    );
    assert_eq!(gif.repeat, gif::Repeat::Infinite, "the GIF loops forever");
    let png = image::open(dir.path().join("bouncing_ball.png"))
        .unwrap()
        .to_rgb8();
    assert!(
        png == gif.frames[199],
        "the PNG must equal the GIF's last frame pixel for pixel"
    );
}

/// Parses `x y vx vy` from the reference script or a `frame,ball,x,y,vx,vy` trace row.
fn states(text: &str, skip_columns: usize, separator: char) -> Vec<[f64; 4]> {
    text.lines()
        .map(|line| {
            let v: Vec<f64> = line
                .split(separator)
                .skip(skip_columns)
                .map(|s| s.trim().parse().unwrap())
                .collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

#[test]
fn trace_equals_the_lesson_reference_to_the_last_bit() {
    let dir = temp_dir();
    let output = run_in(dir.path(), &["--trace", "trace.csv", "--quiet"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(output.stdout.is_empty(), "--quiet prints nothing");
    let trace = std::fs::read_to_string(dir.path().join("trace.csv")).unwrap();
    let (header, rows) = trace.split_once('\n').unwrap();
    assert_eq!(header, "frame,ball,x,y,vx,vy");
    let ours = states(rows, 2, ',');

    // The values the lesson's script prints (lesson_reference.py --trajectory).
    assert_eq!((ours[0][0], ours[0][1]), (45.2, 40.5), "frame 0 position");
    assert_eq!(
        (ours[199][0], ours[199][1]),
        (276.1071104000002, 222.10786191360015),
        "frame 199 position"
    );
    let reference = states(include_str!("data/lesson_trajectory.txt"), 0, ' ');
    assert_eq!(ours.len(), reference.len(), "frame count");
    for (frame, (a, b)) in ours.iter().zip(&reference).enumerate() {
        let same_bits = a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits());
        assert!(same_bits, "frame {frame}: ours {a:?}, reference {b:?}");
    }
}

#[test]
fn negative_values_are_read_as_a_learner_types_them() {
    let dir = temp_dir();
    let output = run_in(
        dir.path(),
        &[
            "--vx",
            "-3.5",
            "--gravity",
            "-0.2",
            "--quiet",
            "--trace",
            "t.csv",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let trace = std::fs::read_to_string(dir.path().join("t.csv")).unwrap();
    let first = trace.lines().nth(1).unwrap();
    assert_eq!(first, "0,0,36.5,39.8,-3.5,-0.2", "first traced frame");
}

#[test]
fn help_lists_every_flag_with_its_unit_and_default() {
    let output = run_in(Path::new("."), &["--help"]);
    let help = String::from_utf8_lossy(&output.stdout);
    for (flag, unit, default) in [
        ("--width", "px", "320"),
        ("--height", "px", "240"),
        ("--radius", "px", "12"),
        ("--x", "px", "40"),
        ("--y", "px", "40"),
        ("--vx", "px/frame", "5.2"),
        ("--vy", "px/frame", "0"),
        ("--gravity", "px/frame²", "0.5"),
        ("--damping", "0 to 1", "0.88"),
        ("--trail", "points", "20"),
        ("--frames", "Frames", "200"),
        ("--frame-ms", "ms", "30"),
    ] {
        // The flag's block: its line and the description lines up to the next flag.
        let mut block = help
            .lines()
            .skip_while(|l| !l.contains(&format!("{flag} <")));
        let first = block.next().unwrap_or_default().to_string();
        let line = first
            + &block
                .take_while(|l| !l.trim_start().starts_with('-'))
                .collect::<String>();
        assert!(
            line.contains(unit) && line.contains(&format!("[default: {default}]")),
            "{flag}: expected unit {unit:?} and default {default}, help says {line:?}"
        );
    }
}

#[test]
fn short_and_long_help_agree_and_name_no_code() {
    let short = run_in(Path::new("."), &["-h"]);
    let long = run_in(Path::new("."), &["--help"]);
    assert!(short.status.success() && long.status.success());
    assert_eq!(
        String::from_utf8_lossy(&short.stdout),
        String::from_utf8_lossy(&long.stdout),
        "-h and --help print different text"
    );
    let help = String::from_utf8_lossy(&long.stdout);
    assert!(!help.contains("crate::"), "help refers to code: {help}");
}

#[test]
fn short_flags_work_like_their_long_forms() {
    let dir = temp_dir();
    let output = run_in(dir.path(), &["-q", "-n", "3", "-o", "short.gif"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(output.stdout.is_empty(), "-q printed something");
    assert_eq!(decode_gif(&dir.path().join("short.gif")).frames.len(), 3);
}

#[test]
fn completions_print_a_script_for_each_shell() {
    for shell in ["bash", "zsh", "fish"] {
        let output = run_in(Path::new("."), &["completions", shell]);
        assert!(output.status.success(), "{shell}: {}", stderr(&output));
        let script = String::from_utf8_lossy(&output.stdout);
        assert!(
            script.contains("gravity") && script.contains("preset") && script.contains("elastic"),
            "{shell} completions lack the flags"
        );
    }
}

#[test]
fn a_trail_of_zero_is_allowed() {
    let dir = temp_dir();
    let output = run_in(dir.path(), &["--trail", "0", "--quiet"]);
    assert!(output.status.success(), "{}", stderr(&output));
}

#[test]
fn bad_input_gets_one_line_naming_the_flag_exit_2_and_no_file() {
    for (args, named) in [
        (&["--radius", "NaN"][..], "--radius NaN"),
        (&["--gravity", "inf"], "--gravity inf"),
        (&["--vx=-inf"], "--vx -inf"),
        (&["--radius", "0"], "--radius 0"),
        (&["--radius", "-3"], "--radius -3"),
        (&["--radius", "120"], "--radius 120"),
        (&["--x", "5"], "--x 5"),
        (&["--y", "239"], "--y 239"),
        (&["--frames", "0"], "--frames 0"),
        (&["--damping", "1.5"], "--damping 1.5"),
        (&["--damping", "-0.1"], "--damping -0.1"),
        (&["--width", "9000"], "--width 9000"),
        (&["--height", "0"], "--height 0"),
        (&["--frame-ms", "33"], "--frame-ms 33"),
        (&["--trail", "5000"], "--trail 5000"),
        (&["--iterations", "0"], "--iterations 0"),
        (&["--frames", "ten"], "--frames"),
    ] {
        let dir = temp_dir();
        let output = run_in(dir.path(), args);
        let err = stderr(&output);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?} should exit 2; stderr: {err}"
        );
        assert!(
            err.contains(named),
            "{args:?}: the error should name {named:?}: {err}"
        );
        assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
        let files: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert!(files.is_empty(), "{args:?} left files behind: {files:?}");
    }
}

#[test]
fn spawned_balls_fill_the_canvas_the_flags_give() {
    let dir = temp_dir();
    let args = [
        "--preset", "many", "--width", "1920", "--height", "1080", "-n", "1",
    ];
    let output = run_in(
        dir.path(),
        &[&args[..], &["--trace", "t.csv", "-q"]].concat(),
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let trace = std::fs::read_to_string(dir.path().join("t.csv")).unwrap();
    let rows = trace.split_once('\n').map_or("", |(_header, rows)| rows);
    let at = states(rows, 2, ',');
    let right = at.iter().filter(|s| s[0] > 960.0).count();
    let low = at.iter().filter(|s| s[1] > 540.0).count();
    assert_eq!(at.len(), 50);
    assert!(
        right >= 10 && low >= 10,
        "{right} balls in the right half, {low} in the lower half of 1920x1080"
    );
}

#[test]
fn a_run_predicted_beyond_the_time_budget_is_refused_before_any_work() {
    let dir = temp_dir();
    let started = std::time::Instant::now();
    // 50 balls bouncing for 4.3 billion frames: days. (The lesson's one ball, which comes
    // to roll slower and slower along the floor, takes about 20 minutes for as many frames,
    // within the default hour.)
    let output = run_in(dir.path(), &["-p", "many", "--frames", "4294967295"]);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "one line: {err:?}");
    assert!(
        err.contains("over the time budget") && err.contains("--time-budget"),
        "{err}"
    );
    // Refused up front: a pilot of the physics, not the run (which would take hours).
    assert!(started.elapsed() < std::time::Duration::from_secs(20));
    let files: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert!(files.is_empty(), "left files behind: {files:?}");
}

#[test]
fn the_summary_names_every_file_written() {
    let dir = temp_dir();
    let args = [
        "-n", "3", "--trace", "t.csv", "--plot", "p.svg", "-o", "a.gif", "--png", "b.png",
    ];
    let output = run_in(dir.path(), &args);
    let summary = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{}", stderr(&output));
    for name in ["a.gif (3 frames,", "b.png (", "t.csv (", "p.svg ("] {
        assert!(
            summary.contains(name),
            "the summary should name {name}: {summary}"
        );
    }
}

#[test]
fn a_flag_error_says_what_is_allowed_and_the_nearest_name_in_one_line() {
    for (args, says) in [
        (
            &["--preset", "mon"][..],
            &[
                "--preset mon",
                "allowed: lesson, elastic",
                "did you mean moon?",
            ][..],
        ),
        (
            &["--integrator", "rk5"],
            &[
                "--integrator rk5",
                "allowed: explicit-euler",
                "did you mean rk4?",
            ],
        ),
        (
            &["--collisions", "exakt"],
            &[
                "--collisions exakt",
                "allowed: clamp, exact",
                "did you mean exact?",
            ],
        ),
        (
            &["completions", "tcsh"],
            &[
                "completions tcsh",
                "allowed: bash, elvish, fish, powershell, zsh",
            ],
        ),
        (
            &["--gravty", "0.2"],
            &["'--gravty'", "did you mean --gravity?"],
        ),
        (&["--width", "-320"], &["--width -320", "from 1 to 8192"]),
        (&["--trail", "-1"], &["--trail -1", "from 0 to 1000"]),
        (&["--seed", "-1"], &["--seed -1", "whole number from 0"]),
        (&["--x", "-inf"], &["--x -inf", "finite"]),
        (&["--vy", "-nan"], &["--vy NaN", "finite"]),
        (
            &["--radius", "60", "--width", "1920", "--height", "1080"],
            &[
                "balls[0].x = 40",
                "not typed: set it with --x",
                "60 to 1860 px",
            ],
        ),
    ] {
        let dir = temp_dir();
        let output = run_in(dir.path(), args);
        let err = stderr(&output);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: one line: {err:?}");
        for part in says {
            assert!(err.contains(part), "{args:?} should say {part:?}: {err}");
        }
        let files: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert!(files.is_empty(), "{args:?} left files behind: {files:?}");
    }
}

#[test]
fn the_validation_error_is_a_single_line_saying_what_is_allowed() {
    let output = run_in(&std::env::temp_dir(), &["--damping", "1.5"]);
    let err = stderr(&output);
    assert_eq!(err.lines().count(), 1, "one line: {err:?}");
    assert!(err.contains("from 0 to 1"), "says what is allowed: {err}");
}

#[test]
fn an_unwritable_output_exits_1_and_leaves_no_file_or_clobbered_file() {
    let dir = temp_dir();
    std::fs::write(dir.path().join("bouncing_ball.gif"), b"previous good gif").unwrap();
    let output = run_in(dir.path(), &["--png", "no/such/folder/out.png"]);
    let err = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "exit code; stderr: {err}");
    assert_eq!(err.lines().count(), 1, "one line: {err:?}");
    assert!(
        err.contains("no/such/folder/out.png"),
        "names the path: {err}"
    );
    let previous = std::fs::read(dir.path().join("bouncing_ball.gif")).unwrap();
    assert_eq!(
        previous, b"previous good gif",
        "the previous GIF must not be clobbered"
    );
    let files: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(files.len(), 1, "no temporary file left behind: {files:?}");
}
