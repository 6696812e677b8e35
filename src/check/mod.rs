//! `check`: grades a learner's work against the scene it should show. The scene is
//! simulated and drawn in memory, frame by frame, and each handed-in file compared with it:
//! an animated GIF from any encoder or a folder of PNG frames (on the timeline, pixel by
//! pixel), a PNG (the last frame), or a trajectory (value by value). When the work differs,
//! each of the lesson's named mistakes is simulated too, and the one it matches is named.
//!
//! - `animation`: a GIF read as a viewer shows it, within the memory budget.
//! - `pictures`: the handed-in pictures frame by frame, against the expected ones.
//! - `pixels`: whether two pictures match, within a tolerance; the picture of a difference.
//! - `trajectory`: a `--trace` CSV or the lesson's `x y vx vy` lines, value by value.
//! - `expected`: the scene's frames, or the scene with a mistake in it.
//! - [`pitfalls`]: the lesson's mistakes, shared with the starter example.
//! - `found`: where a file first differs, or why it cannot be graded.
//! - `verdict`: what is said about each file, as a line or as JSON.

pub(crate) mod animation;
pub(crate) mod expected;
pub(crate) mod found;
pub(crate) mod pictures;
pub mod pitfalls;
pub(crate) mod pixels;
pub(crate) mod trajectory;
pub(crate) mod verdict;

use std::io::Write;
use std::path::{Path, PathBuf};

use image::RgbImage;

use crate::budget::Estimate;
use crate::job::{Job, OutputKind, RunError};
use crate::render::raster::Renderer;
use crate::render::write_rgb_png;
use crate::scene::Scene;

use expected::ExpectedMotion;
pub(crate) use found::{Finding, Trouble};
use pictures::Theirs;
use pitfalls::Pitfall;
use pixels::Tolerance;
pub use verdict::{Grade, Verdict};

/// How close a learner's work must be to match.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options {
    pub pixels: Tolerance,
    /// How far a trajectory's positions (px) and velocities (px/frame) may be off.
    pub tolerance: f64,
    /// The most bytes a handed-in picture may need to decode: [`check`] sets it to the job's
    /// memory budget.
    pub memory_budget: u64,
}

/// Grades every file in `theirs` against `scene`; `job` holds the budget and the `--diff`
/// picture (the first differing frame of the first file that differs), if asked for.
pub fn check(
    scene: &Scene,
    theirs: &[PathBuf],
    options: &Options,
    job: &Job,
) -> Result<Vec<Verdict>, RunError> {
    scene.validate()?;
    Estimate::within(scene, &job.budget)?;
    let renderer = Renderer::new(scene)?;
    let options = &Options {
        memory_budget: job.budget.memory,
        ..*options
    };
    // Opened before any work, so a --diff that cannot be written is said first.
    let files = job.open()?;
    let mut picture = None;
    let mut verdicts = Vec::new();
    for path in theirs {
        let want_picture = job.path(OutputKind::Diff).is_some() && picture.is_none();
        let (verdict, first) = grade(scene, &renderer, path, options, want_picture);
        picture = picture.or(first);
        verdicts.push(verdict);
    }
    if let (Some(picture), Some(mut out)) = (picture, files.writer(OutputKind::Diff)?) {
        write_rgb_png(&mut out, &picture)
            .and_then(|()| out.flush())
            .map_err(files.error_at(OutputKind::Diff))?;
        job.commit(files, 1)?;
    }
    Ok(verdicts)
}

/// One file's verdict, and its first differing frame's picture if `want_picture`.
fn grade(
    scene: &Scene,
    renderer: &Renderer,
    path: &Path,
    options: &Options,
    want_picture: bool,
) -> (Verdict, Option<RgbImage>) {
    let compared = Theirs::load(path, scene, options.memory_budget).and_then(|theirs| {
        let mut finding = compare(&theirs, scene, renderer, None, options, want_picture)?
            .expect("the scene's own motion always applies");
        let picture = finding.first.as_mut().and_then(|f| f.picture.take());
        let pitfall = if finding.first.is_some() {
            diagnose(&theirs, scene, renderer, options)
        } else {
            None
        };
        Ok((finding, pitfall, picture))
    });
    match compared {
        Ok((finding, pitfall, picture)) => (Verdict::of(path, scene, &finding, pitfall), picture),
        Err(trouble) => (Verdict::trouble(path, &trouble), None),
    }
}

/// `theirs` against `scene` with `pitfall` in it (`None`: as the program runs it); `None`
/// if the scene cannot have that mistake.
fn compare(
    theirs: &Theirs,
    scene: &Scene,
    renderer: &Renderer,
    pitfall: Option<Pitfall>,
    options: &Options,
    want_picture: bool,
) -> Result<Option<Finding>, Trouble> {
    match theirs {
        Theirs::Trajectory(trajectory) => match ExpectedMotion::new(scene, pitfall) {
            Some(mut motion) => trajectory
                .compare(&mut motion, scene.frames, options.tolerance)
                .map(Some),
            None => Ok(None),
        },
        Theirs::Images(images) => match expected::Frames::new(scene, renderer, pitfall) {
            Some(mut frames) => images
                .compare(
                    scene,
                    options.memory_budget,
                    &mut frames,
                    &options.pixels,
                    want_picture,
                )
                .map(Some),
            None => Ok(None),
        },
    }
}

/// The lesson's mistake that `theirs` matches (within the same tolerances) where it has the
/// scene's frames, if any.
fn diagnose(
    theirs: &Theirs,
    scene: &Scene,
    renderer: &Renderer,
    options: &Options,
) -> Option<Pitfall> {
    let is_trajectory = matches!(theirs, Theirs::Trajectory(_));
    Pitfall::ALL
        .into_iter()
        .filter(|pitfall| pitfall.shows_in_trajectory() || !is_trajectory)
        .find(|&pitfall| {
            let compared = compare(theirs, scene, renderer, Some(pitfall), options, false);
            compared.is_ok_and(|c| c.is_some_and(|c| c.first.is_none()))
        })
}
