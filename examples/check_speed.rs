//! How long `check` takes to grade the program's own GIF, against the run that wrote it, on
//! every preset: the issue asks for less than twice the run's time. Both go through the
//! library as the binary does (`run` with a GIF and a PNG, `check` of the GIF with the same
//! scene), each the median of RUNS tries.
//!
//! Run: `cargo run --release --example check_speed -- [RUNS]` (default 5). Everything is
//! written to a temporary folder.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use bouncing_ball::check::{self, Grade};
use bouncing_ball::scene::file::{preset, PRESETS};
use bouncing_ball::{run, Job};

/// The median of `runs` timings of `work`.
fn median(runs: usize, mut work: impl FnMut()) -> Duration {
    let mut times: Vec<Duration> = (0..runs)
        .map(|_| {
            let start = Instant::now();
            work();
            start.elapsed()
        })
        .collect();
    times.sort();
    times[runs / 2]
}

fn main() {
    let runs: usize = std::env::args()
        .nth(1)
        .map_or(5, |n| n.parse().expect("RUNS, a number"));
    let dir = tempfile::tempdir().expect("a temporary folder");
    println!("| preset | frames | run ms | check ms | check / run |");
    println!("|---|---:|---:|---:|---:|");
    for (name, _) in PRESETS {
        let scene = preset(name, 1).expect("a bundled preset");
        let gif: PathBuf = dir.path().join(format!("{name}.gif"));
        let job = Job::pictures(&gif, dir.path().join(format!("{name}.png")));
        let run_time = median(runs, || {
            run(&scene, &job).expect("the preset runs");
        });
        let files = [gif.clone()];
        let check_time = median(runs, || {
            let verdicts = check::check(&scene, &files, &check::Options::default(), &Job::new())
                .expect("the check runs");
            assert_eq!(verdicts[0].grade, Grade::Match, "{}", verdicts[0].line());
        });
        let ms = |d: Duration| d.as_secs_f64() * 1000.0;
        println!(
            "| {name} | {} | {:.1} | {:.1} | {:.2} |",
            scene.frames,
            ms(run_time),
            ms(check_time),
            ms(check_time) / ms(run_time)
        );
    }
}
