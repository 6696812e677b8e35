//! `bouncing_ball check`: the real binary grading the fixtures in `tests/data/check/` (made
//! once by the lesson's script, ImageMagick and ffmpeg; see the README there) and files it
//! writes itself, in a temporary folder.

mod common;

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Output;

use common::{decode_gif, run_in, stderr};

/// A fixture in `tests/data/check/`.
fn fixture(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/check")
        .join(name);
    path.to_string_lossy().into_owned()
}

/// `bouncing_ball check ARGS...` in `dir`.
fn check(dir: &Path, args: &[&str]) -> Output {
    let mut all = vec!["check"];
    all.extend_from_slice(args);
    run_in(dir, &all)
}

fn stdout(output: &Output) -> String {
    String::from_utf8_lossy(&output.stdout).into_owned()
}

/// Asserts the exit code and that stdout holds one line per entry of `expected`, each
/// containing its words.
fn assert_says(output: &Output, code: i32, expected: &[&str]) {
    let out = stdout(output);
    let lines: Vec<&str> = out.lines().collect();
    assert_eq!(
        output.status.code(),
        Some(code),
        "expected exit {code}, got {:?}; stdout:\n{out}stderr:\n{}",
        output.status.code(),
        stderr(output)
    );
    assert_eq!(
        lines.len(),
        expected.len(),
        "expected {} lines, got {}:\n{out}",
        expected.len(),
        lines.len()
    );
    for (line, words) in lines.iter().zip(expected) {
        assert!(
            line.contains(words),
            "expected a line with {words:?}, got {line:?}"
        );
    }
}

/// The program's own run with `args`, in `dir`, which must succeed.
fn run_ok(dir: &Path, args: &[&str]) {
    let output = run_in(dir, args);
    assert!(output.status.success(), "{args:?}: {}", stderr(&output));
}

#[test]
fn the_lesson_scripts_own_gif_matches_the_default_scene() {
    let dir = tempfile::tempdir().unwrap();
    let output = check(dir.path(), &["-n", "30", &fixture("pillow.gif")]);
    assert_says(&output, 0, &["pillow.gif: match: 30 frames, 0.90 s"]);
}

#[test]
fn the_lesson_scripts_gif_re_encoded_by_imagemagick_and_ffmpeg_still_matches_exactly() {
    let dir = tempfile::tempdir().unwrap();
    let (magick, ffmpeg) = (fixture("imagemagick.gif"), fixture("ffmpeg.gif"));
    let output = check(dir.path(), &["-n", "30", &magick, &ffmpeg]);
    assert_says(
        &output,
        0,
        &[
            "imagemagick.gif: match: 30 frames",
            "ffmpeg.gif: match: 30 frames",
            "2 files: 2 match, 0 differ, 0 in trouble",
        ],
    );
}

#[test]
fn the_lesson_scripts_trajectory_matches_the_default_scene() {
    let dir = tempfile::tempdir().unwrap();
    let trajectory = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/lesson_trajectory.txt");
    let output = check(dir.path(), &[trajectory.to_str().unwrap()]);
    assert_says(
        &output,
        0,
        &["lesson_trajectory.txt: match: 200 frames, 6.00 s"],
    );
}

#[test]
fn the_programs_own_gif_png_and_trace_match_also_with_still_frames_merged_into_one() {
    let dir = tempfile::tempdir().unwrap();
    // A ball at rest after a few frames: the GIF stores its still frames as one long frame.
    let scene = [
        "-n", "40", "--x", "160", "--y", "228", "--vx", "0", "--vy", "-3",
    ];
    run_ok(
        dir.path(),
        &[&scene[..], &["-q", "--trace", "run.csv"]].concat(),
    );
    let stored = decode_gif(&dir.path().join("bouncing_ball.gif"))
        .frames
        .len();
    assert!(
        stored < 40,
        "expected merged frames, got {stored} stored frames for 40"
    );
    let files = ["bouncing_ball.gif", "bouncing_ball.png", "run.csv"];
    let output = check(dir.path(), &[&scene[..], &files].concat());
    assert_says(
        &output,
        0,
        &[
            "bouncing_ball.gif: match: 40 frames, 1.20 s",
            "bouncing_ball.png: match: the last frame (frame 39)",
            "run.csv: match: 40 frames",
            "3 files: 3 match",
        ],
    );
}

#[test]
fn each_pitfall_gif_differs_at_the_frame_the_mistake_first_shows_and_is_named() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("nothing-moves", 0, "nothing moves the ball yet"),
        ("gravity-twice", 0, "adding gravity twice in one step"),
        ("position-first", 1, "moving the ball before adding gravity"),
        (
            "no-clamp",
            26,
            "reflecting the velocity without clamping the position",
        ),
        (
            "gravity-at-bounce",
            27,
            "adding gravity again in the wall response",
        ),
        ("trail-over-ball", 0, "drawing the trail after the ball"),
    ];
    for (pitfall, frame, words) in cases {
        let file = fixture(&format!("pitfall-{pitfall}.gif"));
        let output = check(dir.path(), &["-n", "30", &file]);
        assert_says(&output, 1, &[&format!("differs from frame {frame} (")]);
        assert!(
            stdout(&output).contains(&format!("it looks like {words}")),
            "{pitfall}: expected the pitfall named ({words}), got {}",
            stdout(&output)
        );
    }
}

#[test]
fn a_pitfall_trajectory_says_which_value_differs_first_and_names_the_pitfall() {
    let dir = tempfile::tempdir().unwrap();
    let file = fixture("pitfall-gravity-at-bounce.txt");
    let output = check(dir.path(), &["-n", "30", &file]);
    assert_says(
        &output,
        1,
        &["differs from frame 26 (0.78 s): ball 0 vy: expected -11.88, got -11.38; it looks like adding gravity again in the wall response"],
    );
}

#[test]
fn the_moon_preset_differs_from_the_default_scenes_gif_and_the_diff_shows_three_panels() {
    let dir = tempfile::tempdir().unwrap();
    run_ok(
        dir.path(),
        &["-q", "-n", "1", "-o", "lesson.gif", "--png", "lesson.png"],
    );
    run_ok(
        dir.path(),
        &[
            "-q", "-n", "1", "-p", "moon", "-o", "moon.gif", "--png", "moon.png",
        ],
    );
    let output = check(
        dir.path(),
        &["-p", "moon", "-n", "1", "lesson.gif", "--diff", "d.png"],
    );
    assert_says(&output, 1, &["lesson.gif: differs from frame 0 (0.00 s)"]);
    let open = |name: &str| image::open(dir.path().join(name)).unwrap().to_rgb8();
    let (diff, moon, lesson) = (open("d.png"), open("moon.png"), open("lesson.png"));
    assert_eq!(
        diff.dimensions(),
        (960, 240),
        "expected three 320×240 panels"
    );
    let panel = |k: u32| image::imageops::crop_imm(&diff, 320 * k, 0, 320, 240).to_image();
    assert!(panel(0) == moon, "expected the moon's frame on the left");
    assert!(
        panel(1) == lesson,
        "expected the handed-in frame in the middle"
    );
    let red = panel(2).pixels().filter(|p| p.0 == [255, 0, 0]).count();
    let differing = moon
        .pixels()
        .zip(lesson.pixels())
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(
        red, differing,
        "expected every differing pixel red, and only those"
    );
}

#[test]
fn a_gif_whose_frames_come_at_other_moments_differs_at_the_first_off_beat_frame() {
    let dir = tempfile::tempdir().unwrap();
    run_ok(dir.path(), &["-q", "-n", "10", "--frame-ms", "40"]);
    let output = check(dir.path(), &["-n", "10", "bouncing_ball.gif"]);
    assert_says(
        &output,
        2,
        &["it has 14 frames (0.42 s), but the scene has 10 (0.30 s); differs from frame 1 (0.03 s): stored frame 1 starts at 0.04 s"],
    );
    let output = check(dir.path(), &["-n", "14", "bouncing_ball.gif"]);
    assert_says(
        &output,
        1,
        &["differs from frame 1 (0.03 s): stored frame 1 starts at 0.04 s, between two frames of 30 ms"],
    );
}

#[test]
fn a_folder_of_png_frames_is_read_in_name_order_and_a_threshold_admits_nearby_colours() {
    let dir = tempfile::tempdir().unwrap();
    let frames = decode_gif(Path::new(&fixture("pillow.gif"))).frames;
    let folder = dir.path().join("frames");
    fs::create_dir(&folder).unwrap();
    for (k, frame) in frames.iter().enumerate() {
        // The ball a shade off (255, 200, 60 → 255, 198, 60), as another renderer might draw it.
        let mut frame = frame.clone();
        frame
            .pixels_mut()
            .filter(|p| p.0 == [255, 200, 60])
            .for_each(|p| p.0[1] = 198);
        frame
            .save(folder.join(format!("frame_{k:03}.png")))
            .unwrap();
    }
    let output = check(dir.path(), &["-n", "30", "frames"]);
    assert_says(&output, 1, &["frames: differs from frame 0 (0.00 s): "]);
    let output = check(dir.path(), &["-n", "30", "--threshold", "0.1", "frames"]);
    assert_says(&output, 0, &["frames: match: 30 frames, 0.90 s"]);
}

#[test]
fn many_files_give_a_line_each_then_a_summary_and_exit_1_if_any_differs() {
    let dir = tempfile::tempdir().unwrap();
    let files = [
        fixture("pillow.gif"),
        fixture("ffmpeg.gif"),
        fixture("pitfall-gravity-twice.gif"),
    ];
    let args: Vec<&str> = ["-n", "30"]
        .into_iter()
        .chain(files.iter().map(String::as_str))
        .collect();
    let output = check(dir.path(), &args);
    assert_says(
        &output,
        1,
        &[
            "match",
            "match",
            "differs",
            "3 files: 2 match, 1 differ, 0 in trouble",
        ],
    );
    let json = check(dir.path(), &[&args[..], &["--format", "json"]].concat());
    assert_eq!(json.status.code(), Some(1), "expected exit 1 in JSON too");
    let verdicts: Vec<serde_json::Value> = stdout(&json)
        .lines()
        .map(|line| serde_json::from_str(line).unwrap_or_else(|e| panic!("{e}: {line}")))
        .collect();
    let said: Vec<&str> = verdicts
        .iter()
        .map(|v| v["verdict"].as_str().unwrap())
        .collect();
    assert_eq!(
        said,
        ["match", "match", "differs"],
        "expected three verdicts"
    );
    assert_eq!(verdicts[2]["pitfall"]["name"], "gravity-twice");
    assert_eq!(verdicts[2]["first_difference"], 0);
}

/// A GIF that claims a 65535 × 65535 canvas and frame: a few bytes that would take 25 GB
/// to decode.
fn bomb() -> Vec<u8> {
    let mut gif = b"GIF89a\xff\xff\xff\xff\x00\x00\x00".to_vec();
    gif.extend_from_slice(b",\x00\x00\x00\x00\xff\xff\xff\xff\x00\x08\x02\x4c\x01\x00;");
    gif
}

#[test]
fn every_bad_input_gets_one_line_naming_what_is_wrong_and_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    fs::write(d.join("notes.txt"), "my homework, as words\n").unwrap();
    let pillow = fs::read(fixture("pillow.gif")).unwrap();
    fs::write(d.join("truncated.gif"), &pillow[..pillow.len() / 2]).unwrap();
    fs::write(d.join("bomb.gif"), bomb()).unwrap();
    fs::create_dir(d.join("empty")).unwrap();
    run_ok(
        d,
        &[
            "-q",
            "-n",
            "3",
            "--width",
            "200",
            "-o",
            "small.gif",
            "--png",
            "small.png",
        ],
    );
    let cases: [(&[&str], &str); 8] = [
        (&["notes.txt"], "notes.txt: error: not an image or a trajectory"),
        (&["truncated.gif"], "truncated.gif: error: not a whole GIF"),
        (&["bomb.gif"], "bomb.gif: error: a 65535×65535 picture needs 24575 MB to decode, over the memory budget of 2048 MB"),
        (&["small.gif"], "small.gif: error: the GIF is 200×240 px, but the scene is 320×240 px"),
        (&["small.png"], "small.png: error: the PNG is 200×240 px, but the scene is 320×240 px"),
        (&["empty"], "empty: error: an empty folder: no PNG frames in it"),
        (&["-n", "40", &fixture("pillow.gif")], "it has 30 frames (0.90 s), but the scene has 40 (1.20 s); the 30 shared frames match"),
        (&["missing.gif"], "missing.gif: error: cannot read it"),
    ];
    for (args, words) in cases {
        let output = check(d, args);
        assert_says(&output, 2, &[words]);
        assert!(
            stderr(&output).is_empty(),
            "{args:?}: expected nothing on stderr, got {}",
            stderr(&output)
        );
    }
}

#[test]
fn a_trace_of_many_balls_matches_ball_by_ball_and_plain_lines_are_for_one_ball() {
    let dir = tempfile::tempdir().unwrap();
    run_ok(
        dir.path(),
        &["-q", "-p", "many", "-n", "20", "--trace", "many.csv"],
    );
    let output = check(dir.path(), &["-p", "many", "-n", "20", "many.csv"]);
    assert_says(&output, 0, &["many.csv: match: 20 frames, 0.60 s"]);
    let output = check(
        dir.path(),
        &[
            "-p",
            "many",
            "-n",
            "20",
            &fixture("pitfall-gravity-at-bounce.txt"),
        ],
    );
    assert_says(
        &output,
        2,
        &["plain x y vx vy lines hold one ball, but the scene has"],
    );
}

#[test]
fn a_diff_is_written_only_when_a_file_differs_and_nothing_else_is_left() {
    let dir = tempfile::tempdir().unwrap();
    let output = check(
        dir.path(),
        &["-n", "30", &fixture("pillow.gif"), "--diff", "d.png"],
    );
    assert_says(&output, 0, &["match"]);
    let left: Vec<PathBuf> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert!(
        left.is_empty(),
        "expected nothing written on a match, got {left:?}"
    );
}

#[test]
fn a_gif_cut_anywhere_or_with_bytes_changed_is_graded_without_a_crash() {
    let dir = tempfile::tempdir().unwrap();
    let pillow = fs::read(fixture("pillow.gif")).unwrap();
    let mut cases: Vec<Vec<u8>> = (1..pillow.len())
        .step_by(499)
        .map(|n| pillow[..n].to_vec())
        .collect();
    // Bytes changed through the header, the colour table and the frames (a fixed pattern).
    for at in (6..pillow.len()).step_by(631) {
        let mut changed = pillow.clone();
        changed[at] ^= 0x5a;
        cases.push(changed);
    }
    for (n, bytes) in cases.iter().enumerate() {
        fs::write(dir.path().join("their.gif"), bytes).unwrap();
        let output = check(dir.path(), &["-n", "30", "their.gif"]);
        let cut = bytes.len() < pillow.len();
        let allowed: &[i32] = if cut { &[2] } else { &[0, 1, 2] };
        assert!(
            output
                .status
                .code()
                .is_some_and(|code| allowed.contains(&code)),
            "case {n} ({} bytes): expected exit {allowed:?}, got {:?}: {}",
            bytes.len(),
            output.status.code(),
            stderr(&output)
        );
        assert_eq!(
            stdout(&output).lines().count(),
            1,
            "case {n}: expected one line"
        );
    }
}

#[test]
fn a_diff_that_cannot_be_written_gets_one_line_and_exit_2_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let twice = fixture("pitfall-gravity-twice.gif");
    let output = check(
        dir.path(),
        &["-n", "30", &twice, "--diff", "no/such/folder/d.png"],
    );
    assert_eq!(
        output.status.code(),
        Some(2),
        "expected exit 2, got {:?}",
        output.status.code()
    );
    assert!(
        stdout(&output).is_empty(),
        "expected no verdict, got {}",
        stdout(&output)
    );
    let said = stderr(&output);
    assert_eq!(said.lines().count(), 1, "expected one line, got {said}");
    assert!(
        said.contains("no/such/folder/d.png"),
        "expected the path named, got {said}"
    );
    let none: Vec<PathBuf> = fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    assert!(none.is_empty(), "expected nothing written, got {none:?}");
}

#[test]
fn quiet_says_only_what_does_not_match() {
    let dir = tempfile::tempdir().unwrap();
    let (pillow, twice) = (fixture("pillow.gif"), fixture("pitfall-gravity-twice.gif"));
    let output = check(dir.path(), &["-q", "-n", "30", &pillow]);
    assert_says(&output, 0, &[]);
    let output = check(dir.path(), &["-q", "-n", "30", &pillow, &twice]);
    assert_says(
        &output,
        1,
        &["pitfall-gravity-twice.gif: differs from frame 0"],
    );
}

#[test]
fn help_states_the_exit_codes() {
    let dir = tempfile::tempdir().unwrap();
    let output = check(dir.path(), &["--help"]);
    let help = stdout(&output);
    assert!(
        help.contains("0 if every file matches, 1 if any differs, 2 if any is in trouble"),
        "expected the exit codes in --help, got {help}"
    );
}
