//! GIF size against the standard optimiser: every preset rendered by the library, then
//! `gifsicle -O3` (lossless) run on our own GIF, to show what it can still take off, and on
//! the same frames written whole, to show what it makes of them by itself. Also the
//! reference figure each preset must not exceed, and our median wall time per preset.
//!
//! Run: `cargo run --release --example gif_size -- [RUNS]` (RUNS per preset for the time,
//! default 5). Without gifsicle (Debian/Ubuntu: `apt-get install gifsicle`) it prints our
//! sizes only, and says so. Everything is written to a temporary folder.

use std::path::Path;
use std::process::Command;
use std::time::{Duration, Instant};

use bouncing_ball::scene::file::{preset, PRESETS};
use bouncing_ball::{run, Job, OutputKind};

/// `gifsicle -O3` of each preset's GIF as the encoder wrote it before it chose per-frame
/// encodings (one global 256- or 128-entry table, no transparency), measured once with
/// gifsicle 1.93: the size each preset must now reach by itself. These were made from the
/// frames as the earlier rasteriser drew them; circles are now Pillow's, so the frames
/// differ a little, and the column "gifsicle -O3 of the frames" is the like-for-like figure.
const REFERENCE: &[(&str, u64)] = &[
    ("lesson", 119_409),
    ("slope", 109_230),
    ("billiards", 718_667),
    ("many", 906_795),
    ("elastic", 137_328),
    ("no-gravity", 76_981),
    ("heavy", 168_800),
    ("moon", 87_895),
    ("drag", 129_417),
];

/// Runs gifsicle with `args` on `gif`, writing `out`: its size, or `None` when gifsicle
/// cannot run.
fn gifsicle(args: &[&str], gif: &Path, out: &Path) -> Option<u64> {
    let status = Command::new("gifsicle")
        .args(args)
        .arg(gif)
        .arg("-o")
        .arg(out)
        .status()
        .ok()?;
    status
        .success()
        .then(|| std::fs::metadata(out).ok())?
        .map(|m| m.len())
}

/// `gifsicle -O3` of `gif` as it is, and of the same frames written whole first
/// (`--unoptimize`: what gifsicle makes of these frames by itself).
fn gifsicle_o3(gif: &Path) -> Option<(u64, u64)> {
    let (whole, optimised) = (
        gif.with_extension("whole.gif"),
        gif.with_extension("O3.gif"),
    );
    let of_ours = gifsicle(&["-O3"], gif, &optimised)?;
    gifsicle(&["--unoptimize"], gif, &whole)?;
    let of_frames = gifsicle(&["-O3"], &whole, &optimised)?;
    Some((of_ours, of_frames))
}

fn main() {
    let runs: usize = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("RUNS is a whole number"))
        .unwrap_or(5)
        .max(1);
    let dir = tempfile::tempdir().expect("a temporary folder");
    let mut gifsicle_found = true;
    println!("| preset     |  ours (B) | gifsicle -O3 of ours (B) | -O3 takes off | gifsicle -O3 of the frames (B) | reference (B) | ours / reference | median time (ms) |");
    println!("|------------|----------:|-------------------------:|--------------:|-------------------------------:|--------------:|-----------------:|-----------------:|");
    for (name, _) in PRESETS {
        let scene = preset(name, 1).expect("a bundled preset");
        let outputs = Job::pictures(
            dir.path().join(format!("{name}.gif")),
            dir.path().join(format!("{name}.png")),
        );
        let mut times: Vec<Duration> = (0..runs)
            .map(|_| {
                let started = Instant::now();
                run(&scene, &outputs).expect("the preset runs");
                started.elapsed()
            })
            .collect();
        times.sort();
        let median_ms = times[times.len() / 2].as_secs_f64() * 1e3;
        let ours = std::fs::metadata(outputs.path(OutputKind::Gif).unwrap())
            .expect("the GIF")
            .len();
        let optimised = if gifsicle_found {
            gifsicle_o3(outputs.path(OutputKind::Gif).unwrap())
        } else {
            None
        };
        gifsicle_found = optimised.is_some();
        let (o3, takes_off, of_frames) = match optimised {
            Some((o3, of_frames)) => (
                o3.to_string(),
                format!("{:.2} %", 100.0 * (ours as f64 - o3 as f64) / ours as f64),
                of_frames.to_string(),
            ),
            None => ("-".into(), "-".into(), "-".into()),
        };
        let reference = REFERENCE.iter().find(|(n, _)| n == name).map(|r| r.1);
        let (reference, share) = match reference {
            Some(r) => (r.to_string(), format!("{:.4}", ours as f64 / r as f64)),
            None => ("-".into(), "-".into()),
        };
        println!(
            "| {name:<10} | {ours:>9} | {o3:>24} | {takes_off:>13} | {of_frames:>30} | {reference:>13} | {share:>16} | {median_ms:>16.1} |"
        );
    }
    if !gifsicle_found {
        println!("\ngifsicle not found: install it (Debian/Ubuntu: apt-get install gifsicle) for its column.");
    }
    println!("\nA negative figure means gifsicle -O3 made our GIF bigger. Time: one whole run (simulate, draw, encode, write), median of {runs}.");
}
