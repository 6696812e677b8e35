//! Side by side with the lesson's Python script: the release binary and the script (drawing
//! with Pillow) render the same default scene, runs interleaved so both see the same machine,
//! whole process each time. The script is the lesson's reference,
//! `../shared/reference/lesson_reference.py` beside the checkout, where it is there, and the
//! project's own rendition, `tools/lesson.py gif`, otherwise; the table says which ran.
//! Prints the median and fastest wall time of each, the speed ratio, and both GIFs' sizes.
//!
//! Run: `cargo run --release --example bench_vs_python -- [RUNS]` (RUNS defaults to 11; it
//! builds the release binary first). Without Python or Pillow it times our side only and
//! says how to install Pillow (`pip install pillow`).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// What the project aims for: at least this many times faster, and at most this share of the bytes.
const TARGET_SPEEDUP: f64 = 80.0;
const TARGET_SIZE_SHARE: f64 = 0.85;

/// One program to time: how to start it in `dir`, and where its GIF lands there.
struct Contender {
    name: &'static str,
    command: Box<dyn Fn(&Path) -> Command>,
    times: Vec<Duration>,
    gif_bytes: u64,
}

impl Contender {
    /// Runs once in a fresh folder, keeping the wall time (when `timed`) and the GIF size.
    fn run(&mut self, timed: bool) {
        let dir = tempfile::tempdir().expect("a temporary folder");
        let mut command = (self.command)(dir.path());
        let started = Instant::now();
        let status = command.status().expect("the program starts");
        let elapsed = started.elapsed();
        assert!(status.success(), "{} failed: {status}", self.name);
        if timed {
            self.times.push(elapsed);
        }
        self.gif_bytes = std::fs::metadata(dir.path().join("bouncing_ball.gif"))
            .expect("the GIF was written")
            .len();
    }

    fn median(&self) -> Duration {
        let mut times = self.times.clone();
        times.sort();
        times[times.len() / 2]
    }

    fn fastest(&self) -> Duration {
        self.times.iter().copied().min().unwrap_or_default()
    }
}

/// The release binary, built (or found up to date) beside this example, so a fresh clone
/// needs nothing but this command and a stale binary is never timed.
fn our_binary() -> PathBuf {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let status = Command::new(cargo)
        .args(["build", "--release", "--quiet", "--bin", "bouncing_ball"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .status()
        .expect("cargo starts");
    assert!(status.success(), "cargo build --release failed: {status}");
    let exe = std::env::current_exe().expect("the example's own path");
    let release = exe
        .parent()
        .and_then(Path::parent)
        .expect("examples/ sits in the target folder");
    release.join(format!("bouncing_ball{}", std::env::consts::EXE_SUFFIX))
}

/// The script to time, its name in the table and the arguments before the output folder:
/// the lesson's reference script where it is there (it is the faster of the two, drawing
/// without the rendition's scene-file support), the project's rendition otherwise.
fn python_script() -> (PathBuf, &'static str, &'static [&'static str]) {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let reference = manifest.join("../shared/reference/lesson_reference.py");
    if reference.exists() {
        (reference, "Python + Pillow (lesson_reference.py)", &[])
    } else {
        (
            manifest.join("tools/lesson.py"),
            "Python + Pillow (tools/lesson.py)",
            &["gif"],
        )
    }
}

/// Why the Python side cannot run here, if it cannot.
fn python_missing(script: &Path) -> Option<String> {
    if !script.exists() {
        return Some(format!("{} not found", script.display()));
    }
    match Command::new("python3").args(["-c", "import PIL"]).output() {
        Ok(out) if out.status.success() => None,
        Ok(_) => Some("Pillow is not installed; install it with `pip install pillow`".to_string()),
        Err(e) => Some(format!(
            "python3 cannot start ({e}); install Python 3, then `pip install pillow`"
        )),
    }
}

fn ms(d: Duration) -> f64 {
    d.as_secs_f64() * 1000.0
}

fn main() {
    let runs: usize = std::env::args()
        .nth(1)
        .map(|s| s.parse().expect("RUNS is a whole number"))
        .unwrap_or(11);
    let binary = our_binary();
    let (script, name, args) = python_script();

    let mut contenders = vec![Contender {
        name: "Rust (this crate, release)",
        command: Box::new(move |dir| {
            let mut c = Command::new(&binary);
            c.arg("--quiet").current_dir(dir);
            c
        }),
        times: Vec::new(),
        gif_bytes: 0,
    }];
    match python_missing(&script) {
        Some(why) => println!("Skipping the Python side: {why}.\n"),
        None => contenders.push(Contender {
            name,
            command: Box::new(move |dir| {
                let mut c = Command::new("python3");
                c.arg(&script).args(args).arg(dir);
                c
            }),
            times: Vec::new(),
            gif_bytes: 0,
        }),
    }

    // One untimed run each warms the file cache, then the timed runs alternate.
    for contender in &mut contenders {
        contender.run(false);
    }
    for _ in 0..runs {
        for contender in &mut contenders {
            contender.run(true);
        }
    }

    println!("Default scene (320x240, 200 frames), whole process, {runs} runs interleaved:\n");
    println!(
        "| {:<38} | {:>11} | {:>12} | {:>10} |",
        "program", "median (ms)", "fastest (ms)", "GIF bytes"
    );
    println!("|{:-<40}|{:->13}|{:->14}|{:->12}|", "", "", "", "");
    for c in &contenders {
        println!(
            "| {:<38} | {:>11.1} | {:>12.1} | {:>10} |",
            c.name,
            ms(c.median()),
            ms(c.fastest()),
            c.gif_bytes
        );
    }
    if let [ours, python] = &contenders[..] {
        let speedup = python.median().as_secs_f64() / ours.median().as_secs_f64();
        let share = ours.gif_bytes as f64 / python.gif_bytes as f64;
        let verdict = |ok: bool| if ok { "met" } else { "NOT met" };
        println!(
            "\nspeed: {speedup:.0}x faster (median over median; target >= {TARGET_SPEEDUP}x: {})",
            verdict(speedup >= TARGET_SPEEDUP)
        );
        println!(
            "size:  {share:.3}x the Pillow GIF's bytes (target <= {TARGET_SIZE_SHARE}x: {})",
            verdict(share <= TARGET_SIZE_SHARE)
        );
    }
}
