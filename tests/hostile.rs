//! The hostile-input suite: generated command lines and scene files (valid, mutated and
//! garbage) run through the library and the real binary, each in its own temporary folder
//! holding odd things (a FIFO, a folder, a socket, links, earlier outputs, a scene file),
//! under a memory cap and a time cap. Whatever the input, the run must either
//!
//! - exit 0, having changed only the outputs it named, each of which decodes; or
//! - exit 1 or 2 with one error line (warnings aside), creating or changing nothing; or
//! - reach the time cap, be asked to stop (SIGTERM; Ctrl-Break on Windows), and exit with that
//!   request's code (143; 131) in one line, changing nothing.
//!
//! Never a panic, a crash, or a process that ignores the request.
//!
//! Fast by default (a few seconds). The longer mode sets the number of cases per property:
//! `HOSTILE_CASES=5000 cargo test --release --test hostile -- --nocapture`
//! (docs/robustness.md gives its last figures).

mod common;

use std::cell::{Cell, RefCell};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::time::Duration;

use bouncing_ball::budget::Estimate;
use bouncing_ball::scene::file;
use bouncing_ball::{run, Job, OutputKind};
use common::process::{args, changes, run_capped, snapshot, Caps, Finished, OddFolder, Request};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

/// Cases per property: few by default, `HOSTILE_CASES` for the longer mode.
fn cases(default: u32) -> u32 {
    std::env::var("HOSTILE_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Whether this is the longer mode (a longer time cap lets more runs finish).
fn long_mode() -> bool {
    std::env::var_os("HOSTILE_CASES").is_some()
}

/// A runner with a fixed seed, so every run (and CI) tries the same cases: a failure seen
/// once is seen again. More cases (HOSTILE_CASES) reach further from the same start.
fn runner(default: u32) -> TestRunner {
    let config = Config {
        cases: cases(default),
        // Never write a regressions file beside the sources; a failure prints its input.
        failure_persistence: None,
        ..Config::default()
    };
    TestRunner::new_with_rng(config, TestRng::deterministic_rng(RngAlgorithm::ChaCha))
}

fn caps() -> Caps {
    Caps {
        // Well above the default 2 GiB budget's estimates (which err high), far below the
        // machine: an accepted scene that outgrew its estimate would abort here.
        memory: 3 << 30,
        time: Duration::from_millis(if long_mode() { 4000 } else { 1500 }),
        grace: Duration::from_secs(30),
    }
}

/// Paths the generated command lines use: all relative, none leaving the folder.
const PATHS: &[&str] = &[
    "out.gif",
    "out.png",
    "t.csv",
    "-",
    "fifo",
    "folder",
    "folder/",
    ".",
    "socket",
    "link-to-fifo",
    "link-to-folder",
    "link-to-previous.gif",
    "link-to-my.toml",
    "broken-link",
    "previous.gif",
    "previous.png",
    "my.toml",
    "missing/x.gif",
    "a b.gif",
    "ünï.png",
    "folder/inside.gif",
    "nul.gif",
    "CON",
];

/// Odd values for any flag.
const ODD: &[&str] = &[
    "0",
    "-0",
    "-1",
    "1e308",
    "-1e308",
    "1e-320",
    "NaN",
    "inf",
    "-inf",
    "4294967295",
    "4294967296",
    "18446744073709551616",
    "",
    " ",
    "abc",
    "0x10",
    "1_000",
    "5 ",
    "--",
    "ü",
    "99999999999999999999999",
    "-9223372036854775808",
];

fn number(range: std::ops::Range<f64>) -> BoxedStrategy<String> {
    range.prop_map(|v| format!("{v}")).boxed()
}

fn one_of(values: &'static [&'static str]) -> BoxedStrategy<String> {
    prop::sample::select(values)
        .prop_map(str::to_string)
        .boxed()
}

/// A flag and a value: mostly sensible, sometimes odd.
fn flag_and_value() -> BoxedStrategy<Vec<String>> {
    let sensible: Vec<(&'static str, BoxedStrategy<String>)> = vec![
        ("--width", (20u32..400).prop_map(|v| v.to_string()).boxed()),
        ("--height", (20u32..400).prop_map(|v| v.to_string()).boxed()),
        ("--radius", number(0.5..30.0)),
        ("--x", number(-10.0..400.0)),
        ("--y", number(-10.0..400.0)),
        ("--vx", number(-100.0..100.0)),
        ("--vy", number(-100.0..100.0)),
        ("--gravity", number(-5.0..5.0)),
        ("--damping", number(-0.2..1.2)),
        ("--drag", number(-0.2..1.2)),
        ("--restitution", number(-0.2..1.2)),
        ("--substeps", (0u32..6).prop_map(|v| v.to_string()).boxed()),
        ("--trail", (0usize..60).prop_map(|v| v.to_string()).boxed()),
        ("--frames", (0u32..60).prop_map(|v| v.to_string()).boxed()),
        (
            "--frame-ms",
            (0u32..12).prop_map(|v| (v * 10).to_string()).boxed(),
        ),
        ("--seed", any::<u64>().prop_map(|v| v.to_string()).boxed()),
        ("--memory-budget", one_of(&["1", "20", "100", "2048", "0"])),
        (
            "--integrator",
            one_of(&[
                "explicit-euler",
                "semi-implicit-euler",
                "velocity-verlet",
                "rk4",
                "leapfrog",
            ]),
        ),
        ("--collisions", one_of(&["clamp", "exact", "none"])),
        (
            "--preset",
            one_of(&[
                "lesson",
                "elastic",
                "many",
                "billiards",
                "slope",
                "drag",
                "moon",
                "nope",
            ]),
        ),
        ("--gif", one_of(PATHS)),
        ("--png", one_of(PATHS)),
        ("--trace", one_of(PATHS)),
        (
            "--scene",
            one_of(&[
                "my.toml",
                "link-to-my.toml",
                "fifo",
                "folder",
                "socket",
                "missing.toml",
                "-",
                "previous.gif",
            ]),
        ),
    ];
    let flags: Vec<&'static str> = sensible.iter().map(|(f, _)| *f).collect();
    let pairs = sensible
        .into_iter()
        .map(|(flag, value)| value.prop_map(move |v| vec![flag.to_string(), v]).boxed())
        .collect::<Vec<_>>();
    prop_oneof![
        40 => prop::strategy::Union::new(pairs),
        10 => (prop::sample::select(flags), one_of(ODD)).prop_map(|(f, v)| vec![f.to_string(), v]),
        5 => one_of(&["-q", "--quiet", "-n", "--frames=3", "--bogus", "x", "-", "--vx=-3"]).prop_map(|a| vec![a]),
        // Rarely, a run far longer than the cap (its budgets raised, or it is refused up
        // front): it must stop when asked and write nothing.
        1 => Just(args(&["--frames", "4000000000", "--time-budget", "100000000", "--gif-budget", "100000000"])),
    ]
    .boxed()
}

/// The files a successful run may have written: each output named (or the defaults), with
/// a link replaced through to its target. Paths relative to `dir`.
fn allowed_outputs(dir: &Path, list: &[String]) -> (BTreeSet<PathBuf>, Vec<(String, PathBuf)>) {
    let mut named = vec![("--gif".to_string(), PathBuf::from("bouncing_ball.gif"))];
    // clap takes the last of a repeated flag.
    for pair in list.windows(2) {
        if let ("--gif" | "--png" | "--trace" | "-o", value) = (pair[0].as_str(), &pair[1]) {
            let flag = if pair[0] == "-o" {
                "--gif"
            } else {
                pair[0].as_str()
            };
            named.retain(|(f, _)| f != flag);
            named.push((flag.to_string(), PathBuf::from(value)));
        }
    }
    // Without --png, the still takes the GIF's name with .png.
    if !named.iter().any(|(flag, _)| flag == "--png") {
        let gif = named
            .iter()
            .find(|(flag, _)| flag == "--gif")
            .map(|(_, path)| path);
        let still = gif.map_or(PathBuf::from("bouncing_ball.png"), |gif| {
            gif.with_extension("png")
        });
        named.push(("--png".to_string(), still));
    }
    let real_dir = dir.canonicalize().unwrap();
    let mut allowed = BTreeSet::new();
    for (_, path) in &named {
        allowed.insert(path.clone());
        if let Ok(real) = dir.join(path).canonicalize() {
            if let Ok(inside) = real.strip_prefix(&real_dir) {
                allowed.insert(inside.to_path_buf());
            }
        }
    }
    (allowed, named)
}

/// Checks one finished run against the rules at the top of this file.
fn judge(
    dir: &Path,
    list: &[String],
    before: &common::process::Snapshot,
    run: &Finished,
) -> Result<(), String> {
    let after = snapshot(dir);
    let changed = changes(before, &after);
    let say = |what: &str| {
        Err(format!(
            "{what}\nargs: {list:?}\nexit: {:?}\nstderr: {}\nchanged: {changed:?}",
            run.status, run.stderr
        ))
    };
    let (stop_name, stop_code) = Request::Terminate.expected();
    let stopped_by = format!("stopped by {stop_name}");
    if run.stderr.contains("panicked") {
        return say("panicked");
    }
    if let Some(signal) = run.signal() {
        return say(&format!("died of signal {signal}"));
    }
    if changed
        .iter()
        .any(|p| p.to_string_lossy().ends_with(".tmp"))
    {
        return say("left a temporary file");
    }
    let code = run.code().unwrap_or(-1);
    let errors = run.error_lines();
    match code {
        0 => {
            let (allowed, named) = allowed_outputs(dir, list);
            if let Some(stray) = changed.iter().find(|p| !allowed.contains(*p)) {
                return say(&format!(
                    "changed {stray:?}, which it was not asked to write"
                ));
            }
            for (flag, path) in named {
                if path.as_os_str() == "-" {
                    continue;
                }
                let full = dir.join(&path);
                let decodes = match flag.as_str() {
                    "--gif" => gif::DecodeOptions::new()
                        .read_info(std::fs::File::open(&full).map_err(|e| e.to_string())?)
                        .map(|mut d| while let Ok(Some(_)) = d.read_next_frame() {})
                        .is_ok(),
                    // By content: the name need not end in .png.
                    "--png" => std::fs::read(&full).is_ok_and(|bytes| {
                        image::load_from_memory_with_format(&bytes, image::ImageFormat::Png).is_ok()
                    }),
                    _ => std::fs::read_to_string(&full).is_ok_and(|t| t.starts_with("frame,ball")),
                };
                if !decodes {
                    return say(&format!("{flag} {} does not decode", path.display()));
                }
            }
            Ok(())
        }
        code if code == 1 || code == 2 || code == stop_code => {
            if errors.len() != 1 {
                return say("an error should be one line");
            }
            if code == stop_code && !(run.capped && errors[0].contains(&stopped_by)) {
                return say("a stop's exit code without our request to stop");
            }
            if !changed.is_empty() {
                return say("a failed run created or changed files");
            }
            Ok(())
        }
        _ => say("unexpected exit code"),
    }
}

/// How many runs ended each way: exit code, or "capped" for a stop requested at the time cap.
#[derive(Default)]
struct Tally(RefCell<BTreeMap<String, usize>>);

impl Tally {
    fn note(&self, run: &Finished) {
        let how = match (run.capped, run.code()) {
            (true, _) => "capped".to_string(),
            (false, Some(code)) => format!("exit {code}"),
            (false, None) => "signal".to_string(),
        };
        *self.0.borrow_mut().entry(how).or_default() += 1;
    }
}

impl std::fmt::Display for Tally {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let parts: Vec<String> = self
            .0
            .borrow()
            .iter()
            .map(|(k, n)| format!("{k}: {n}"))
            .collect();
        write!(f, "{}", parts.join(", "))
    }
}

/// Runs `list` in a fresh odd folder, optionally with `scene` as s.toml, and judges it.
fn run_and_judge(
    list: &[String],
    scene: Option<&[u8]>,
    tally: &Tally,
) -> Result<(), TestCaseError> {
    let odd = OddFolder::new();
    let dir = &odd.dir;
    if let Some(text) = scene {
        std::fs::write(dir.path().join("s.toml"), text).unwrap();
    }
    let before = snapshot(dir.path());
    let run = run_capped(dir.path(), list, b"", caps());
    tally.note(&run);
    judge(dir.path(), list, &before, &run).map_err(TestCaseError::fail)
}

#[test]
fn generated_command_lines_succeed_cleanly_or_fail_in_one_line_changing_nothing() {
    let strategy = prop::collection::vec(flag_and_value(), 0..7)
        .prop_map(|pairs| pairs.into_iter().flatten().collect::<Vec<String>>());
    let mut runner = runner(24);
    let tally = Tally::default();
    runner
        .run(&strategy, |list| run_and_judge(&list, None, &tally))
        .unwrap();
    eprintln!("command lines: {} cases, 0 failures ({tally})", cases(24));
}

// ---- Scene files ----

fn colour() -> impl Strategy<Value = String> {
    any::<[u8; 3]>().prop_map(|[r, g, b]| format!("[{r}, {g}, {b}]"))
}

/// A scene file inside the allowed ranges (or just outside, now and then).
fn valid_scene() -> impl Strategy<Value = String> {
    let head = (
        (10u32..400, 10u32..400),
        1u32..30,
        0u32..10,
        prop::option::of((-3.0..3.0f64, -3.0..3.0f64)),
        prop::option::of(0.0..0.5f64),
        0.0..=1.0f64,
        prop::option::of(0.0..=1.0f64),
        prop::sample::select(
            &[
                "explicit-euler",
                "semi-implicit-euler",
                "velocity-verlet",
                "rk4",
            ][..],
        ),
        1u32..4,
        prop::sample::select(&["clamp", "exact"][..]),
    );
    let floors = prop::collection::vec(
        (
            -500.0..900.0f64,
            -500.0..900.0f64,
            -500.0..900.0f64,
            -500.0..900.0f64,
            0.0..=1.0f64,
        ),
        0..3,
    );
    let balls = prop::collection::vec(
        (
            0.0..1.0f64,
            0.0..1.0f64,
            -40.0..40.0f64,
            -40.0..40.0f64,
            0.5..20.0f64,
            colour(),
            colour(),
            0usize..40,
        ),
        0..5,
    );
    let spawn = prop::option::of((
        0usize..400,
        0.5..10.0f64,
        0.0..10.0f64,
        0usize..30,
        prop::collection::vec(colour(), 0..4),
        prop::collection::vec(colour(), 0..4),
    ));
    (head, floors, balls, spawn).prop_map(|(head, floors, balls, spawn)| {
        let ((w, h), frames, ms, gravity, drag, damping, restitution, integrator, substeps, collisions) = head;
        let mut t = format!("width = {w}\nheight = {h}\nframes = {frames}\nframe_ms = {}\n", ms * 10);
        if let Some((gx, gy)) = gravity {
            t += &format!("gravity = [{gx:?}, {gy:?}]\n");
        }
        if let Some(d) = drag {
            t += &format!("drag = {d:?}\n");
        }
        // Always walls, so that most runs draw something on the canvas.
        t += &format!("walls = {{ damping = {damping:?} }}\n");
        if let Some(r) = restitution {
            t += &format!("ball_collisions = {{ restitution = {r:?} }}\n");
        }
        t += &format!("integrator = \"{integrator}\"\nsubsteps = {substeps}\ncollisions = \"{collisions}\"\n");
        for (x1, y1, x2, y2, d) in floors {
            t += &format!("[[floors]]\nfrom = [{x1:?}, {y1:?}]\nto = [{x2:?}, {y2:?}]\ndamping = {d:?}\n");
        }
        for (fx, fy, vx, vy, r, c, tc, trail) in balls {
            let (x, y) = (r + fx * (f64::from(w) - 2.0 * r), r + fy * (f64::from(h) - 2.0 * r));
            t += &format!("[[balls]]\nx = {x:?}\ny = {y:?}\nvx = {vx:?}\nvy = {vy:?}\nradius = {r:?}\ncolour = {c}\ntrail_colour = {tc}\ntrail = {trail}\n");
        }
        if let Some((count, r, speed, trail, colours, trail_colours)) = spawn {
            t += &format!(
                "[spawn]\ncount = {count}\nradius = {r:?}\nmax_speed = {speed:?}\ntrail = {trail}\ncolours = [{}]\ntrail_colours = [{}]\n",
                colours.join(", "),
                trail_colours.join(", ")
            );
        }
        t
    })
}

/// Things to splice into a scene file.
const SPLICES: &[&str] = &[
    "[",
    "]",
    "]]",
    "[[balls]]\n",
    "[spawn]\n",
    "=",
    "\"",
    "'",
    "{",
    "}",
    ",",
    "#",
    "\n",
    "0",
    "-",
    "1e308",
    "-1e308",
    "nan",
    "inf",
    "99999999999999999999",
    "4294967296",
    "1000000",
    "\u{0}",
    "é",
    "true",
    "x = ",
    "radius = 0\n",
    "trail = 1000\n",
    "count = 1000000\n",
    ".5",
    "e",
];

/// A valid scene with a few edits: bytes cut, things spliced in, a line repeated.
fn mutated_scene() -> impl Strategy<Value = Vec<u8>> {
    let edit = (
        0usize..3,
        any::<prop::sample::Index>(),
        any::<prop::sample::Index>(),
        prop::sample::select(SPLICES),
    );
    (valid_scene(), prop::collection::vec(edit, 1..5)).prop_map(|(text, edits)| {
        let mut bytes = text.into_bytes();
        for (kind, at, len, splice) in edits {
            let at = at.index(bytes.len() + 1);
            match kind {
                0 => {
                    let end = (at + len.index(8)).min(bytes.len());
                    bytes.drain(at..end);
                }
                1 => {
                    bytes.splice(at..at, splice.bytes());
                }
                _ => {
                    let line_start = bytes[..at]
                        .iter()
                        .rposition(|&b| b == b'\n')
                        .map_or(0, |p| p + 1);
                    let line_end = bytes[at..]
                        .iter()
                        .position(|&b| b == b'\n')
                        .map_or(bytes.len(), |p| at + p + 1);
                    let line = bytes[line_start..line_end].to_vec();
                    bytes.splice(line_end..line_end, line);
                }
            }
        }
        bytes
    })
}

/// Garbage: random bytes, or random TOML-ish text.
fn garbage_scene() -> impl Strategy<Value = Vec<u8>> {
    prop_oneof![
        prop::collection::vec(any::<u8>(), 0..400),
        prop::collection::vec(prop::sample::select(SPLICES), 0..60)
            .prop_map(|parts| parts.concat().into_bytes()),
    ]
}

fn any_scene() -> impl Strategy<Value = Vec<u8>> {
    prop_oneof![
        2 => valid_scene().prop_map(String::into_bytes),
        3 => mutated_scene(),
        1 => garbage_scene(),
    ]
}

#[test]
fn generated_scene_files_succeed_cleanly_or_fail_in_one_line_changing_nothing() {
    let strategy = (any_scene(), prop::collection::vec(flag_and_value(), 0..3));
    let mut runner = runner(24);
    let tally = Tally::default();
    runner
        .run(&strategy, |(text, flags)| {
            // The library first: parsing never panics, and an error is one line.
            let parsed = file::parse("s.toml", &String::from_utf8_lossy(&text), 1);
            if let Err(e) = &parsed {
                prop_assert_eq!(e.to_string().lines().count(), 1, "{}", e);
            }
            let mut list = args(&["--scene", "s.toml"]);
            list.extend(flags.into_iter().flatten().filter(|a| a != "--scene"));
            run_and_judge(&list, Some(&text), &tally)
        })
        .unwrap();
    eprintln!("scene files: {} cases, 0 failures ({tally})", cases(24));
}

#[test]
fn generated_scenes_run_through_the_library_write_decodable_files_or_nothing() {
    let mut runner = runner(24);
    let ran = Cell::new(0);
    runner
        .run(&any_scene(), |text| {
            let Ok(scene) = file::parse("s.toml", &String::from_utf8_lossy(&text), 1) else {
                return Ok(());
            };
            // The library has no time cap of its own: only scenes predicted to be quick.
            if Estimate::of(&scene).seconds > 0.5 {
                return Ok(());
            }
            ran.set(ran.get() + 1);
            let dir = tempfile::tempdir().unwrap();
            let outputs = Job::pictures(dir.path().join("a.gif"), dir.path().join("a.png"));
            match run(&scene, &outputs) {
                Ok(summary) => {
                    let gif = common::decode_gif(outputs.path(OutputKind::Gif).unwrap());
                    let frame_cs = (scene.frame_ms / 10) as u16;
                    prop_assert_eq!(gif.timeline(frame_cs).len() as u32, summary.frames);
                    prop_assert!(image::open(outputs.path(OutputKind::Png).unwrap()).is_ok());
                }
                Err(e) => {
                    prop_assert_eq!(e.to_string().lines().count(), 1, "{}", e);
                    let left = std::fs::read_dir(dir.path()).unwrap().count();
                    prop_assert_eq!(left, 0, "{} left files", e);
                }
            }
            Ok(())
        })
        .unwrap();
    eprintln!(
        "library: {} cases, {} run, 0 failures",
        cases(24),
        ran.get()
    );
}
