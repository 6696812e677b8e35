//! Nothing clobbered, nothing left behind, every input bounded: the real binary given odd
//! output paths, signals, huge scenes, overflowing numbers and odd scene files. Every path
//! is inside the test's own temporary folder (FIFOs, sockets and links are made there).

mod common;

use std::io::Read;
use std::path::Path;
use std::time::{Duration, Instant};

use common::decode_gif;
use common::process::{
    args, changes, run_capped, send, snapshot, spawn, Caps, Finished, OddFolder, Request,
};

/// A run that would take days, with budgets raised so that it is not refused for its length
/// (what a test of it looks at is another check, or a signal).
const DAYS: [&str; 6] = [
    "--frames",
    "4000000000",
    "--time-budget",
    "100000000",
    "--gif-budget",
    "100000000",
];

/// A run that ought to be refused before any work: it gets seconds, not minutes.
fn quick() -> Caps {
    Caps {
        time: Duration::from_secs(10),
        ..Caps::default()
    }
}

/// Runs `list` in `dir` and asserts it exits `code` with one line containing `says`, and
/// creates or changes nothing in `dir`.
fn assert_refused(dir: &Path, list: &[&str], code: i32, says: &str) -> Finished {
    let before = snapshot(dir);
    let run = run_capped(dir, &args(list), b"", quick());
    assert_eq!(run.code(), Some(code), "{list:?}: stderr {:?}", run.stderr);
    assert!(
        !run.capped,
        "{list:?} ran until the cap: not refused up front"
    );
    assert_eq!(
        run.stderr.lines().count(),
        1,
        "{list:?}: one line: {:?}",
        run.stderr
    );
    assert!(
        run.stderr.contains(says),
        "{list:?}: {:?} should say {says:?}",
        run.stderr
    );
    let changed = changes(&before, &snapshot(dir));
    assert!(
        changed.is_empty(),
        "{list:?} created or changed {changed:?}"
    );
    run
}

/// Asserts that each `(flag, path, says)` is refused up front with exit 2, changing nothing.
fn assert_outputs_refused(dir: &Path, cases: &[(&str, &str, &str)]) {
    for (flag, path, says) in cases {
        let list = [&[*flag, *path, "-q"][..], &DAYS].concat();
        assert_refused(dir, &list, 2, says);
    }
}

#[test]
fn an_output_that_is_not_a_regular_file_is_refused_before_any_work() {
    let dir = OddFolder::new();
    assert_outputs_refused(
        dir.path(),
        &[
            ("--png", "folder", "is a folder"),
            ("--png", "folder/", "names a folder"),
            ("--png", ".", "names a folder"),
            ("--gif", "-", "only for --trace"),
            ("--png", "-", "only for --trace"),
            ("--trace", "", "a value is required for '--trace <TRACE>'"),
        ],
    );
}

#[test]
fn an_output_named_for_the_other_picture_format_is_refused_before_any_work() {
    let dir = OddFolder::new();
    assert_outputs_refused(
        dir.path(),
        &[
            (
                "--gif",
                "a.png",
                "--gif writes a GIF; give a name ending in .gif",
            ),
            ("--gif", "a.SVG", "give a name ending in .gif"),
            (
                "--png",
                "b.gif",
                "--png writes a PNG; give a name ending in .png",
            ),
        ],
    );
}

#[cfg(unix)]
#[test]
fn an_output_that_is_a_fifo_a_socket_or_a_link_to_one_is_refused_before_any_work() {
    let dir = OddFolder::new();
    assert_outputs_refused(
        dir.path(),
        &[
            ("--gif", "fifo", "is a named pipe (FIFO)"),
            ("--trace", "socket", "is a socket"),
            ("--trace", "link-to-fifo", "is a named pipe (FIFO)"),
            ("--gif", "link-to-folder", "is a folder"),
            ("--png", "link-to-socket", "is a socket"),
            ("--gif", "broken-link", "symbolic link to nothing"),
        ],
    );
}

#[cfg(windows)]
#[test]
fn an_output_named_for_a_windows_device_or_a_folder_is_refused_before_any_work() {
    let dir = OddFolder::new();
    let device = "is a device name on Windows";
    assert_outputs_refused(
        dir.path(),
        &[
            ("--gif", "NUL", device),
            ("--png", "con.png", device),
            ("--trace", "Aux.csv", device),
            ("--gif", "folder\\lpt1.gif", device),
            ("--png", "COM9 .png", device),
            ("--gif", "folder", "is a folder"),
            ("--png", "folder\\", "names a folder"),
        ],
    );
}

#[test]
fn two_outputs_naming_one_file_or_the_scene_file_are_refused() {
    let dir = OddFolder::new();
    for (list, says) in [
        (
            &["--gif", "out", "--png", "out"][..],
            "same file as --gif out",
        ),
        (&["--gif", "out", "--png", "./out"], "same file as --gif"),
        (
            &["--scene", "my.toml", "--gif", "my.toml"],
            "is the scene file",
        ),
        (
            &["--scene", "my.toml", "--trace", "hard-link.toml"],
            "is the scene file",
        ),
        (
            &["--png", "o.png", "--plot", "o.png"][..],
            "same file as --png o.png",
        ),
        (&["--plot", "folder"], "--plot folder: is a folder"),
    ] {
        let mut list = list.to_vec();
        list.extend(DAYS);
        list.push("-q");
        assert_refused(dir.path(), &list, 2, says);
    }
}

#[cfg(unix)]
#[test]
fn an_output_through_a_link_is_the_file_it_points_to() {
    let dir = OddFolder::new();
    let list = ["--gif", "previous.gif", "--trace", "link-to-previous.gif"];
    assert_refused(
        dir.path(),
        &[&list[..], &DAYS, &["-q"]].concat(),
        2,
        "same file",
    );
}

#[cfg(unix)]
#[test]
fn an_output_through_a_link_replaces_the_file_and_keeps_the_link() {
    let dir = OddFolder::new();
    let run = run_capped(
        dir.path(),
        &args(&[
            "--gif",
            "link-to-previous.gif",
            "--png",
            "p.png",
            "-q",
            "-n",
            "3",
        ]),
        b"",
        quick(),
    );
    assert_eq!(run.code(), Some(0), "{}", run.stderr);
    let link = std::fs::symlink_metadata(dir.path().join("link-to-previous.gif")).unwrap();
    assert!(link.file_type().is_symlink(), "the link is still a link");
    assert_eq!(decode_gif(&dir.path().join("previous.gif")).frames.len(), 3);
}

/// An image viewer on Windows holds the file it shows open without letting others delete it,
/// and a file held so cannot be replaced: the run says so in one line and changes nothing.
#[cfg(windows)]
#[test]
fn an_output_open_in_another_program_fails_in_one_line_leaving_the_old_file() {
    use std::os::windows::fs::OpenOptionsExt;
    let dir = OddFolder::new();
    let viewer = std::fs::OpenOptions::new()
        .read(true)
        .share_mode(windows_sys::Win32::Storage::FileSystem::FILE_SHARE_READ)
        .open(dir.path().join("previous.gif"))
        .unwrap();
    let list = ["--gif", "previous.gif", "--png", "new.png", "-n", "3", "-q"];
    assert_refused(
        dir.path(),
        &list,
        1,
        "previous.gif: it is open in another program",
    );
    drop(viewer);
}

#[test]
fn paths_with_spaces_and_non_ascii_names_in_a_subfolder_work_for_every_input_and_output() {
    let dir = tempfile::tempdir().unwrap();
    // Joined with the system's separator: a backslash on Windows.
    let folder = Path::new("mes balles ü");
    std::fs::create_dir(dir.path().join(folder)).unwrap();
    let lesson = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lesson.toml");
    std::fs::copy(lesson, dir.path().join(folder).join("scène 1.toml")).unwrap();
    let named = |name: &str| folder.join(name).to_string_lossy().into_owned();
    let list = [
        "--scene".to_string(),
        named("scène 1.toml"),
        "--gif".to_string(),
        named("balle rebondissante.gif"),
        "--png".to_string(),
        named("dernière image.png"),
        "--trace".to_string(),
        named("trajectoire ü.csv"),
        "-q".to_string(),
    ];
    let run = run_capped(dir.path(), &list, b"", quick());
    assert_eq!(run.code(), Some(0), "{list:?}: {}", run.stderr);
    let written = dir.path().join(folder);
    assert_eq!(
        decode_gif(&written.join("balle rebondissante.gif"))
            .frames
            .len(),
        200
    );
    assert!(written.join("dernière image.png").is_file());
    let trace = std::fs::read_to_string(written.join("trajectoire ü.csv")).unwrap();
    assert_eq!(trace.lines().count(), 201, "header and 200 rows");
}

#[test]
fn trace_dash_streams_the_csv_to_stdout_and_a_closed_pipe_is_no_error() {
    let dir = tempfile::tempdir().unwrap();
    let run = run_capped(dir.path(), &args(&["--trace", "-", "-q"]), b"", quick());
    assert_eq!(run.code(), Some(0), "{}", run.stderr);
    let csv = String::from_utf8(run.stdout).unwrap();
    assert!(
        csv.starts_with("frame,ball,x,y,vx,vy\n0,0,45.2,40.5,5.2,0.5\n"),
        "{csv:.80}"
    );
    assert_eq!(csv.lines().count(), 201, "header and 200 rows");
    assert!(!dir.path().join("-").exists(), "no file named -");

    // `--trace - | head -1`: the reader goes away after one line.
    let mut child = spawn(dir.path(), &args(&["--trace", "-", "-n", "3000"]), 3 << 30);
    drop(child.stdin.take());
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 21];
    stdout.read_exact(&mut first).unwrap();
    drop(stdout);
    let status = child.wait().unwrap();
    let mut stderr = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut stderr)
        .unwrap();
    assert_eq!(&first, b"frame,ball,x,y,vx,vy\n");
    assert_eq!(
        status.code(),
        Some(0),
        "a closed pipe is no error: {stderr}"
    );
    assert!(
        stderr.contains("wrote bouncing_ball.gif"),
        "summary on stderr: {stderr}"
    );
    assert_eq!(
        decode_gif(&dir.path().join("bouncing_ball.gif"))
            .frames
            .len(),
        3000
    );
}

#[test]
fn a_png_path_that_is_a_folder_fails_before_the_work_and_the_old_gif_survives() {
    let dir = OddFolder::new();
    let list = [&["--preset", "elastic", "--gif", "previous.gif"][..], &DAYS].concat();
    let run = assert_refused(
        dir.path(),
        &[&list[..], &["--png", "folder"]].concat(),
        2,
        "is a folder",
    );
    assert!(run.elapsed < Duration::from_secs(10));
}

/// Starts a long run, waits for its temporary files, sends `request`, and checks it stops
/// with the request's exit code, one line, no temporary file, and every earlier file as it was.
fn assert_signal_stops_cleanly(request: Request) {
    let (name, code) = request.expected();
    let dir = OddFolder::new();
    let before = snapshot(dir.path());
    let list = args(
        &[
            &[
                "--preset",
                "elastic",
                "-q",
                "--gif",
                "previous.gif",
                "--png",
                "previous.png",
                "--trace",
                "new.csv",
            ][..],
            &DAYS,
        ]
        .concat(),
    );
    let mut child = spawn(dir.path(), &list, 3 << 30);
    child.stdout = None;
    let started = Instant::now();
    let temp_files = || {
        std::fs::read_dir(dir.path())
            .unwrap()
            .filter(|e| {
                e.as_ref()
                    .unwrap()
                    .file_name()
                    .to_string_lossy()
                    .ends_with(".tmp")
            })
            .count()
    };
    while temp_files() < 3 {
        assert!(
            started.elapsed() < Duration::from_secs(20),
            "no temporary files appeared"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    std::thread::sleep(Duration::from_millis(300)); // some frames into the run
    send(&child, request);
    let output = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(code), "{name}: {stderr}");
    assert_eq!(stderr.lines().count(), 1, "{name}: one line: {stderr}");
    assert!(
        stderr.contains(&format!("stopped by {name}"))
            && stderr.contains("not written: previous.gif, previous.png, new.csv"),
        "{stderr}"
    );
    assert_eq!(temp_files(), 0, "{name} left temporary files");
    let changed = changes(&before, &snapshot(dir.path()));
    assert!(changed.is_empty(), "{name} changed {changed:?}");
}

#[test]
fn ctrl_c_stops_a_long_run_leaving_no_temp_file_and_earlier_outputs_intact() {
    assert_signal_stops_cleanly(Request::Interrupt);
}

#[test]
fn sigterm_or_ctrl_break_stops_a_long_run_leaving_no_temp_file_and_earlier_outputs_intact() {
    assert_signal_stops_cleanly(Request::Terminate);
}

#[test]
fn sighup_or_a_closed_console_stops_a_long_run_leaving_no_temp_file_and_earlier_outputs_intact() {
    assert_signal_stops_cleanly(Request::Hangup);
}

/// A scene file of `count` balls spread over a `side`² box, each of `radius` with a trail of
/// `trail`, in two trail colours.
fn crowd(side: u32, count: usize, radius: f64, trail: usize, extra: &str) -> String {
    format!(
        "width = {side}\nheight = {side}\nframes = 2\nwalls = {{ damping = 0.9 }}\n{extra}\n\
         [spawn]\ncount = {count}\nradius = {radius}\nmax_speed = 2.0\ntrail = {trail}\n\
         colours = [[255, 200, 60]]\ntrail_colours = [[60, 140, 255], [255, 90, 90]]\n"
    )
}

/// A cap well under what the scenes below used to need before the first frame (about 1 GB
/// of trail shades; a 4 GiB list of pairs).
const TIGHT: u64 = 512 << 20;

#[test]
fn two_thousand_balls_with_trails_of_a_thousand_run_within_a_tight_memory_cap() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.toml"), crowd(640, 2000, 3.0, 1000, "")).unwrap();
    let caps = Caps {
        memory: TIGHT,
        ..quick()
    };
    let run = run_capped(dir.path(), &args(&["--scene", "s.toml", "-q"]), b"", caps);
    assert_eq!(run.code(), Some(0), "{}", run.stderr);
}

#[test]
fn twenty_thousand_overlapping_balls_with_collisions_stay_within_a_tight_memory_cap() {
    let dir = tempfile::tempdir().unwrap();
    let extra = "ball_collisions = { restitution = 0.9 }\nframes = 1";
    let scene = crowd(201, 20_000, 100.0, 0, extra).replace("frames = 2\n", "");
    std::fs::write(dir.path().join("s.toml"), scene).unwrap();
    let caps = Caps {
        memory: TIGHT,
        time: Duration::from_secs(60),
        ..Caps::default()
    };
    let run = run_capped(dir.path(), &args(&["--scene", "s.toml", "-q"]), b"", caps);
    assert_eq!(run.code(), Some(0), "{}", run.stderr);
}

#[test]
fn a_million_balls_with_long_trails_are_refused_up_front_naming_the_estimate_and_the_knob() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("s.toml"),
        crowd(2000, 1_000_000, 2.0, 1000, ""),
    )
    .unwrap();
    let run = assert_refused(dir.path(), &["--scene", "s.toml"], 2, "--memory-budget");
    assert!(
        run.stderr.contains("the scene needs about") && run.stderr.contains("MB of memory"),
        "{}",
        run.stderr
    );
}

#[test]
fn a_raised_memory_budget_is_checked_too() {
    let dir = tempfile::tempdir().unwrap();
    assert_refused(
        dir.path(),
        &["--memory-budget", "1", "--width", "4000"],
        2,
        "over the budget of 1 MB",
    );
}

/// Asserts that `list` is refused for its time in one line naming the estimate, within
/// `seconds` of wall time (the pilot run of its physics is all it may do), writing nothing.
fn assert_refused_for_time_within(list: &[&str], seconds: f64) {
    let dir = tempfile::tempdir().unwrap();
    let run = assert_refused(dir.path(), list, 2, "over the time budget of 0.1 s");
    assert!(
        run.stderr.contains("this run looks to take about"),
        "{list:?}: names the estimate: {}",
        run.stderr
    );
    let elapsed = run.elapsed.as_secs_f64();
    assert!(
        elapsed < seconds,
        "{list:?}: expected a refusal within {seconds} s, took {elapsed:.2} s"
    );
}

#[test]
fn exact_collisions_with_rk4_and_substeps_are_refused_up_front_for_their_events() {
    // Several seconds of collision events (about 3 µs each with RK4): the budget counts them.
    let list = [
        "-p",
        "pile",
        "--collisions",
        "exact",
        "--integrator",
        "rk4",
        "--substeps",
        "4",
        "--frames",
        "100",
        "--time-budget",
        "0.1",
    ];
    assert_refused_for_time_within(&list, 2.0);
}

#[test]
fn ten_million_frames_of_the_lesson_are_refused_up_front_for_their_length() {
    assert_refused_for_time_within(&["--frames", "10000000", "--time-budget", "0.1"], 2.0);
}

#[test]
fn finite_inputs_that_overflow_stop_with_exit_2_naming_ball_frame_and_inputs() {
    let dir = tempfile::tempdir().unwrap();
    let list = [
        "--vy",
        "1e308",
        "--gravity",
        "1e308",
        "--damping",
        "0",
        "--trace",
        "t.csv",
    ];
    let run = assert_refused(
        dir.path(),
        &list,
        2,
        "ball 0 left the finite numbers at frame 0",
    );
    assert!(
        run.stderr.contains("vy 1e308") && run.stderr.contains("gravity [0.0, 1e308]"),
        "names the inputs: {}",
        run.stderr
    );
}

#[test]
fn a_scene_that_is_not_a_regular_file_or_is_too_long_is_refused() {
    let dir = OddFolder::new();
    let odd: &[&str] = if cfg!(unix) {
        &["fifo", "folder", "link-to-fifo", "socket"]
    } else {
        &["folder"]
    };
    for path in odd {
        assert_refused(dir.path(), &["--scene", path], 2, "not a regular file");
    }
    let long = format!(
        "width = 320\nheight = 240\n{}",
        "# padding\n".repeat(120_000)
    );
    std::fs::write(dir.path().join("long.toml"), &long).unwrap();
    assert_refused(
        dir.path(),
        &["--scene", "long.toml"],
        2,
        "longer than 1024 KiB",
    );
    let before = snapshot(dir.path());
    let run = run_capped(
        dir.path(),
        &args(&["--scene", "-"]),
        long.as_bytes(),
        quick(),
    );
    assert_eq!(run.code(), Some(2), "{}", run.stderr);
    assert!(
        run.stderr
            .contains("standard input: cannot read: longer than"),
        "{}",
        run.stderr
    );
    assert!(changes(&before, &snapshot(dir.path())).is_empty());
}

#[test]
fn shapes_far_off_the_canvas_cost_nothing_to_draw() {
    // A ball thrown 3e9 px a frame with no walls, a ball pulled sideways for 100,000 frames,
    // and a floor from −1e30 to 1e30: once each hung the renderer in integer arithmetic.
    for scene in [
        "width = 320\nheight = 240\nframes = 3\n[[balls]]\nx = 40.0\ny = 40.0\nvx = 3e9\nradius = 12.0\n",
        "width = 32\nheight = 24\nframes = 100000\ngravity = [0.5, 0.0]\n[[balls]]\nx = 4.0\ny = 4.0\nradius = 2.0\ntrail = 0\n",
        "width = 320\nheight = 240\nframes = 3\nwalls = { damping = 1.0 }\n[[floors]]\nfrom = [-1e30, 120.0]\nto = [1e30, 120.0]\ndamping = 1.0\n[[balls]]\nx = 40.0\ny = 40.0\nradius = 12.0\n",
    ] {
        let dir = tempfile::tempdir().unwrap();
        let run = run_capped(
            dir.path(),
            &args(&["--scene", "-", "-q"]),
            scene.as_bytes(),
            quick(),
        );
        assert!(!run.capped, "still drawing after the cap: {scene}");
        assert_eq!(run.code(), Some(0), "{scene}: {}", run.stderr);
    }
}

#[test]
fn a_scene_on_standard_input_runs() {
    let dir = tempfile::tempdir().unwrap();
    let scene =
        std::fs::read(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/many.toml")).unwrap();
    let run = run_capped(
        dir.path(),
        &args(&["--scene", "-", "-q", "-n", "4"]),
        &scene,
        quick(),
    );
    assert_eq!(run.code(), Some(0), "{}", run.stderr);
    assert_eq!(
        decode_gif(&dir.path().join("bouncing_ball.gif"))
            .frames
            .len(),
        4
    );
}

#[test]
fn a_bad_scene_file_or_value_is_named_in_one_line() {
    let dir = OddFolder::new();
    std::fs::write(dir.path().join("no-height.toml"), "width = 320\n").unwrap();
    std::fs::write(
        dir.path().join("unclosed.toml"),
        "width = 320\nheight = 240\n[[balls\nx = 1\n",
    )
    .unwrap();
    assert_refused(
        dir.path(),
        &["--png", "folder/"],
        2,
        "--png folder/: names a folder, not a file",
    );
    assert_refused(
        dir.path(),
        &["--png", "."],
        2,
        "--png .: names a folder, not a file",
    );
    assert_refused(
        dir.path(),
        &["--scene", "no-height.toml"],
        2,
        "no-height.toml: missing key `height`",
    );
    assert_refused(
        dir.path(),
        &["--scene", "unclosed.toml"],
        2,
        "unclosed.toml: line 3: unclosed [[balls]] table",
    );
    assert_refused(
        dir.path(),
        &["--frames", "ten"],
        2,
        "--frames ten is not allowed: must be a whole number from 1",
    );
    assert_refused(
        dir.path(),
        &["--png", "no/such/folder/x.png"],
        1,
        "there is no folder no/such/folder",
    );
}

#[test]
fn a_short_frame_delay_and_a_long_run_draw_warnings_not_errors() {
    let dir = tempfile::tempdir().unwrap();
    for (list, warns) in [
        (
            &["--frame-ms", "0", "-n", "2"][..],
            "warning: --frame-ms 0: browsers show frames shorter than 20 ms",
        ),
        (&["--frame-ms", "10", "-n", "2"], "warning: --frame-ms 10"),
        // 100 million frames of the lesson: about half a minute (3 million take about 2 s,
        // under the 5 s that draws the warning).
        (
            &["-n", "100000000"],
            "warning: this run looks to take about",
        ),
    ] {
        let mut child = spawn(dir.path(), &args(list), 3 << 30);
        let mut line = String::new();
        let mut stderr = child.stderr.take().unwrap();
        let mut byte = [0u8];
        while stderr.read(&mut byte).unwrap() == 1 && byte[0] != b'\n' {
            line.push(byte[0] as char);
        }
        assert!(
            line.starts_with(warns),
            "{list:?}: first stderr line {line:?}"
        );
        send(&child, Request::Interrupt); // the long one need not finish
        let status = child.wait().unwrap();
        assert!(
            matches!(status.code(), Some(0 | 130)),
            "{list:?}: {status:?}"
        );
    }
    let quiet = run_capped(
        dir.path(),
        &args(&["--frame-ms", "0", "-n", "2", "-q"]),
        b"",
        quick(),
    );
    assert!(
        quiet.stderr.is_empty(),
        "--quiet silences warnings: {}",
        quiet.stderr
    );
}
