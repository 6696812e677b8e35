//! The pictures under `docs/img/` are what their commands write today, byte for byte: the
//! `--plot` pictures of four runs, and the accuracy study's `apex.png`. (Its other picture,
//! `accuracy.png`, plots measured times, so it differs from run to run and is not checked.)
//!
//! Refresh them all with `bash docs/img/refresh.sh`; this test alone rewrites the run plots
//! with `UPDATE_GOLDEN=1 cargo test --release --test docs_images`.

#[path = "../examples/accuracy/apex.rs"]
mod apex;

use std::path::{Path, PathBuf};
use std::process::Command;

/// Each run plot: its file under `docs/img/` and the flags that draw it.
const RUN_PLOTS: &[(&str, &[&str])] = &[
    ("plot-default.svg", &[]),
    ("plot-elastic.svg", &["--damping", "1"]),
    (
        "plot-lost-apex.svg",
        &["--damping", "1", "--vy", "0.3", "--frames", "2000"],
    ),
    (
        "plot-exact-verlet.svg",
        &[
            "--damping",
            "1",
            "--collisions",
            "exact",
            "--integrator",
            "velocity-verlet",
        ],
    ),
];

fn docs_img(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs/img")
        .join(name)
}

/// Compares a fresh picture with the committed one, or replaces it under `UPDATE_GOLDEN=1`.
fn check(name: &str, fresh: &Path) {
    let committed = docs_img(name);
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::copy(fresh, &committed).unwrap();
        return;
    }
    let same = std::fs::read(&committed).ok() == Some(std::fs::read(fresh).unwrap());
    assert!(
        same,
        "docs/img/{name} differs from what its command writes now; if the change is \
         intended, refresh it with `bash docs/img/refresh.sh`"
    );
}

#[test]
fn run_plots_in_the_docs_are_what_the_program_draws() {
    let dir = tempfile::tempdir().unwrap();
    for (name, flags) in RUN_PLOTS {
        let output = Command::new(env!("CARGO_BIN_EXE_bouncing_ball"))
            .args(*flags)
            .args(["--plot", name, "-q"])
            .current_dir(dir.path())
            .output()
            .unwrap();
        assert!(
            output.status.success(),
            "{name}: {}",
            String::from_utf8_lossy(&output.stderr)
        );
        check(name, &dir.path().join(name));
    }
}

#[test]
fn apex_plot_in_the_docs_is_what_the_accuracy_study_draws() {
    // The study writes it only when run (`cargo run --release --example accuracy -- docs/img`).
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let fresh = dir.path().join("apex.png");
    apex::plot(&apex::finding(), &fresh).unwrap();
    check("apex.png", &fresh);
}
