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
fn an_output_that_cannot_be_written_is_refused_before_the_budget_runs_its_pilot() {
    // Exact mode's budget runs a pilot of the physics; this one would end in a refusal for
    // time. A missing folder is found first, in one line, for each command that writes.
    let dir = temp_dir();
    let exact = ["-p", "pile", "--collisions", "exact"];
    // (compare's methods set the collisions themselves; its reference is exact.)
    let commands = [
        &exact[..],
        &["compare", "-p", "pile"],
        &["sweep", "damping=0.5,0.9"],
    ];
    for command in commands {
        let mut list = command.to_vec();
        if command[0] == "sweep" {
            list.extend_from_slice(&exact);
        }
        list.extend_from_slice(&["--time-budget", "0.001", "-o", "no/such/folder/x.gif"]);
        let output = run_in(dir.path(), &list);
        let err = stderr(&output);
        assert_eq!(output.status.code(), Some(1), "{list:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{list:?}: one line: {err:?}");
        assert!(
            err.contains("there is no folder no/such/folder"),
            "{list:?}: {err}"
        );
    }
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
        // Echoed as typed, not as the number it would have become.
        (&["--vy", "-nan"], &["--vy -nan", "finite"]),
        (&["--vx", "1e400"], &["--vx 1e400", "finite"]),
        (
            &["--damping", "0,5"],
            &["--damping 0,5", "decimals take a point: 0.5"],
        ),
        (&["-damping", "0.5"], &["-damping", "two dashes: --damping"]),
        (&["swep", "damping=1"], &["'swep'", "did you mean sweep?"]),
        (
            &["sweep", "damping=0.5", "1.0"],
            &[
                "separated by commas without spaces",
                "see bouncing_ball sweep --help",
            ],
        ),
        (
            &["sweep"],
            &["missing <KEY=V1,V2,...>", "bouncing_ball sweep --help"],
        ),
        (
            &["completions"],
            &["missing <SHELL>", "bouncing_ball completions --help"],
        ),
        (
            &["--time-budget", "0,5"],
            &["--time-budget 0,5", "from 0 up"],
        ),
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

#[test]
fn the_shared_flags_may_come_before_a_subcommand_and_the_main_commands_may_not() {
    let dir = temp_dir();
    let before = run_in(
        dir.path(),
        &["-q", "--time-budget", "600", "compare", "-n", "5"],
    );
    assert!(
        before.status.success(),
        "-q before compare: {}",
        stderr(&before)
    );
    assert!(before.stdout.is_empty(), "-q keeps compare silent");
    assert!(dir.path().join("compare.gif").exists());
    let main_flag = run_in(dir.path(), &["-p", "moon", "compare", "-n", "5"]);
    let said = stderr(&main_flag);
    assert_eq!(main_flag.status.code(), Some(2), "{said}");
    assert!(
        said.lines().count() == 1
            && said.contains("--preset cannot come before the subcommand compare"),
        "one line naming the flag: {said}"
    );
}

#[test]
fn the_time_budget_takes_fractions_of_a_second_and_says_what_it_allows() {
    let dir = temp_dir();
    let fraction = run_in(dir.path(), &["--time-budget", "0.5", "-n", "5", "-q"]);
    assert!(fraction.status.success(), "{}", stderr(&fraction));
    for bad in ["-1", "abc", "inf"] {
        let refused = run_in(dir.path(), &["--time-budget", bad]);
        let said = stderr(&refused);
        assert_eq!(refused.status.code(), Some(2), "{bad}: {said}");
        assert!(
            said.contains(&format!("--time-budget {bad} is not allowed"))
                && said.contains("number of seconds from 0 up"),
            "{bad}: {said}"
        );
    }
}

#[test]
fn the_still_takes_the_gifs_name_for_the_main_command_compare_and_a_sweep_asked_for_one() {
    let dir = temp_dir();
    for (args, written) in [
        (&["-o", "x.gif", "-n", "5"][..], ["x.gif", "x.png"]),
        (&["compare", "-o", "c.gif", "-n", "5"], ["c.gif", "c.png"]),
        (
            &["sweep", "damping=1,0.5", "-o", "s.gif", "--png", "-n", "5"],
            ["s.gif", "s.png"],
        ),
    ] {
        let output = run_in(dir.path(), args);
        assert!(output.status.success(), "{args:?}: {}", stderr(&output));
        for name in written {
            assert!(
                dir.path().join(name).is_file(),
                "{args:?} should write {name}"
            );
        }
    }
    assert!(
        !dir.path().join("bouncing_ball.png").exists() && !dir.path().join("compare.png").exists(),
        "no still under the default name when the GIF has another"
    );
}

#[test]
fn no_gif_and_no_png_leave_those_out_and_together_alone_are_refused() {
    let dir = temp_dir();
    let output = run_in(dir.path(), &["--no-gif", "--trace", "t.csv", "-n", "5"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let names = |dir: &Path| {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    };
    assert_eq!(names(dir.path()), ["bouncing_ball.png", "t.csv"]);
    let empty = temp_dir();
    let refused = run_in(empty.path(), &["--no-gif", "--no-png"]);
    let said = stderr(&refused);
    assert_eq!(refused.status.code(), Some(2), "{said}");
    assert!(
        said.lines().count() == 1 && said.contains("nothing to write"),
        "{said}"
    );
    assert!(names(empty.path()).is_empty(), "nothing written");
}

#[test]
fn the_summary_counts_the_frames_the_gif_holds_once_repeats_are_merged() {
    let dir = temp_dir();
    let output = run_in(dir.path(), &["-p", "pile"]);
    let said = String::from_utf8_lossy(&output.stdout);
    let gif = decode_gif(&dir.path().join("bouncing_ball.gif"));
    let expected = format!("300 frames, shown as {} pictures", gif.frames.len());
    assert!(gif.frames.len() < 300, "the resting pile merges frames");
    assert!(
        said.contains(&expected),
        "expected {expected:?} in {said:?}"
    );
}

#[test]
fn a_read_only_output_is_refused_and_left_as_it_was() {
    let dir = temp_dir();
    let png = dir.path().join("bouncing_ball.png");
    std::fs::write(&png, b"an older still").unwrap();
    let mut permissions = std::fs::metadata(&png).unwrap().permissions();
    permissions.set_readonly(true);
    std::fs::set_permissions(&png, permissions).unwrap();
    let output = run_in(dir.path(), &["-n", "5"]);
    let said = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "{said}");
    assert!(
        said.lines().count() == 1
            && said.contains("cannot write bouncing_ball.png: it is read-only"),
        "{said}"
    );
    assert_eq!(std::fs::read(&png).unwrap(), b"an older still");
    assert!(
        !dir.path().join("bouncing_ball.gif").exists(),
        "nothing written"
    );
}

#[cfg(unix)]
#[test]
fn a_replaced_output_keeps_its_mode() {
    use std::os::unix::fs::PermissionsExt;
    let dir = temp_dir();
    assert!(run_in(dir.path(), &["-n", "5", "-q"]).status.success());
    let gif = dir.path().join("bouncing_ball.gif");
    std::fs::set_permissions(&gif, std::fs::Permissions::from_mode(0o600)).unwrap();
    let output = run_in(dir.path(), &["-n", "6", "-q"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let mode = std::fs::metadata(&gif).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600, "expected 0600, got {mode:o}");
    let png = dir.path().join("bouncing_ball.png");
    let mode = std::fs::metadata(&png).unwrap().permissions().mode() & 0o777;
    assert_eq!(
        mode, 0o644,
        "a new file reads like any other: expected 0644, got {mode:o}"
    );
}

/// A folder the user may not write into: the message names the user's own path, not the
/// hidden temporary file. Root may write anywhere, so the run drops to `nobody` (setpriv).
#[cfg(unix)]
#[test]
fn a_permission_error_names_the_users_path() {
    use std::os::unix::fs::PermissionsExt;
    let dir = temp_dir();
    std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o755)).unwrap();
    let locked = dir.path().join("locked");
    std::fs::create_dir(&locked).unwrap();
    std::fs::set_permissions(&locked, std::fs::Permissions::from_mode(0o555)).unwrap();
    let bin = env!("CARGO_BIN_EXE_bouncing_ball");
    let mut command = if unsafe { libc::geteuid() } == 0 {
        let mut setpriv = std::process::Command::new("setpriv");
        setpriv.args(["--reuid=65534", "--regid=65534", "--clear-groups", bin]);
        setpriv
    } else {
        std::process::Command::new(bin)
    };
    let output = command
        .args(["-o", "locked/x.gif", "-n", "5"])
        .current_dir(dir.path())
        .output()
        .expect("setpriv (util-linux) runs the binary as nobody");
    let said = stderr(&output);
    assert_eq!(output.status.code(), Some(1), "{said}");
    assert!(
        said.contains("cannot write locked/x.gif: permission denied") && !said.contains(".tmp"),
        "{said}"
    );
}

#[test]
fn help_is_there_for_every_subcommand_as_a_flag_and_as_help_name() {
    let dir = temp_dir();
    for args in [
        &["completions", "--help"][..],
        &["completions", "-h"],
        &["help", "compare"],
        &["help", "sweep"],
        &["compare", "-h"],
    ] {
        let output = run_in(dir.path(), args);
        let said = String::from_utf8_lossy(&output.stdout);
        assert!(output.status.success(), "{args:?}: {}", stderr(&output));
        assert!(said.contains("Usage: bouncing_ball"), "{args:?}: {said}");
    }
    let compare = run_in(dir.path(), &["compare", "--help"]);
    let said = String::from_utf8_lossy(&compare.stdout);
    for hidden in ["--integrator <", "--substeps <", "--collisions <"] {
        assert!(
            !said.contains(hidden),
            "compare sets {hidden} per method: {said}"
        );
    }
}

#[test]
fn a_scene_file_key_gets_the_nearest_name_and_a_whole_number_its_real_range() {
    let dir = temp_dir();
    for (text, says) in [
        (
            "width = 320\nheight = 240\ngravty = [0.0, 0.5]\n[[balls]]\nx = 10.0\ny = 10.0\nradius = 3.0\n",
            "unknown key `gravty`; did you mean `gravity`?",
        ),
        (
            "width = 400.0\nheight = 240\n[[balls]]\nx = 10.0\ny = 10.0\nradius = 3.0\n",
            "expected a whole number from 1 to 8192",
        ),
    ] {
        std::fs::write(dir.path().join("s.toml"), text).unwrap();
        let output = run_in(dir.path(), &["--scene", "s.toml"]);
        let said = stderr(&output);
        assert_eq!(output.status.code(), Some(2), "{said}");
        assert!(said.lines().count() == 1 && said.contains(says), "{says}: {said}");
    }
}

#[test]
fn a_spawn_without_colours_takes_the_lessons() {
    let dir = temp_dir();
    let text = "width = 200\nheight = 120\nframes = 1\n[spawn]\ncount = 3\nradius = 6.0\nmax_speed = 0.0\ntrail = 0\n";
    std::fs::write(dir.path().join("s.toml"), text).unwrap();
    let output = run_in(dir.path(), &["--scene", "s.toml", "-q"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let png = image::open(dir.path().join("bouncing_ball.png"))
        .unwrap()
        .to_rgb8();
    let lesson_ball = png.pixels().filter(|p| p.0 == [255, 200, 60]).count();
    assert!(
        lesson_ball > 3 * 90,
        "three balls in the lesson's yellow: {lesson_ball} px"
    );
}

#[test]
fn the_trace_writes_the_shortest_number_that_reads_back_with_an_exponent_only_when_long() {
    let dir = temp_dir();
    let output = run_in(
        dir.path(),
        &["--vx", "1e-20", "--y", "100.5", "-n", "1", "--trace", "-"],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let trace = String::from_utf8_lossy(&output.stdout);
    let row = trace.lines().nth(1).expect("a row after the header");
    // x moves by 1e-20 from 40 (lost to rounding), vx stays tiny, y and vy are plain.
    assert_eq!(row, "0,0,40,101,1e-20,0.5", "the trace row");
}

/// A file name need not be Unicode on Unix: the command line reads it as the system gives it.
#[cfg(unix)]
#[test]
fn an_output_name_that_is_not_unicode_is_written_as_given() {
    use std::os::unix::ffi::OsStrExt;
    let dir = temp_dir();
    let name = std::ffi::OsStr::from_bytes(b"odd\xff.gif");
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_bouncing_ball"))
        .arg("-o")
        .arg(name)
        .args(["-n", "3", "-q"])
        .current_dir(dir.path())
        .output()
        .expect("the binary runs");
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(
        dir.path().join(name).is_file(),
        "the GIF under its own name"
    );
    let still = std::ffi::OsStr::from_bytes(b"odd\xff.png");
    assert!(dir.path().join(still).is_file(), "and the still beside it");
}
