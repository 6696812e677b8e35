//! A sweep's runs: every panel stepped and drawn frame by frame, pasted into the tiled canvas
//! and streamed into one GIF, after every check a run makes before its first frame.

use std::io::{BufWriter, Write};
use std::path::PathBuf;
use std::time::Instant;

use crate::budget::{Budget, Estimate};
use crate::gif::GifWriter;
use crate::output::{self, AtomicFile, Output, OutputError};
use crate::progress::Progress;
use crate::render::palette::{IndexedFrame, Palette};
use crate::render::raster::Renderer;
use crate::render::tile::{PanelSpec, Tiling};
use crate::render::write_png;
use crate::run::{RunError, Summary};
use crate::scene::Scene;
use crate::stop::Stop;

use super::error::SweepError;
use super::values::Panel;

/// Where a sweep writes, and the limits it runs within.
#[derive(Clone, Debug)]
pub struct SweepOutputs {
    pub gif: PathBuf,
    /// The last tiled frame as a still, when asked for.
    pub png: Option<PathBuf>,
    /// Warnings and a progress bar on stderr (false for `--quiet`).
    pub progress: bool,
    /// The scene file the panels were read from, which no output may replace.
    pub scene_file: Option<PathBuf>,
    pub budget: Budget,
    /// Set by a signal: the sweep stops at the next frame and writes nothing.
    pub stop: Stop,
}

impl SweepOutputs {
    /// Every output, in the order they go into place.
    fn list(&self) -> Vec<Output<'_>> {
        let png = self
            .png
            .as_deref()
            .map(|p| Output::picture("--png", p, "png"));
        let gif = Output::picture("--gif", &self.gif, "gif");
        std::iter::once(gif).chain(png).collect()
    }
}

/// Runs every panel and writes the tiled GIF (and the still, if asked for); on any error no
/// output file is left half-written and no existing file is changed.
pub fn run(panels: &[Panel], outputs: &SweepOutputs) -> Result<Summary, SweepError> {
    let started = Instant::now();
    let renderers = renderers(panels)?;
    let frame_ms = frame_time(panels)?;
    let specs: Vec<PanelSpec> = panels
        .iter()
        .zip(&renderers)
        .map(|(panel, renderer)| PanelSpec {
            label: &panel.label,
            width: panel.scene.width,
            height: panel.scene.height,
            palette: renderer.palette(),
        })
        .collect();
    let tiling = Tiling::new(&specs)?;
    let files = write(panels, &renderers, &tiling, frame_ms, outputs)?;
    Ok(Summary {
        frames: panels.iter().map(|p| p.scene.frames).max().unwrap_or(1),
        files,
        elapsed: started.elapsed(),
    })
}

/// Each panel's renderer, once its scene is checked.
fn renderers(panels: &[Panel]) -> Result<Vec<Renderer>, RunError> {
    panels
        .iter()
        .map(|panel| {
            panel.scene.validate()?;
            Ok(Renderer::new(&panel.scene)?)
        })
        .collect()
}

/// Checks the budget and the output paths, then runs the panels into the GIF (and the
/// still) and puts the files in place; returns each file written and its size.
fn write(
    panels: &[Panel],
    renderers: &[Renderer],
    tiling: &Tiling,
    frame_ms: u32,
    outputs: &SweepOutputs,
) -> Result<Vec<(PathBuf, u64)>, RunError> {
    let frames = panels.iter().map(|p| p.scene.frames).max().unwrap_or(1);
    let (width, height) = tiling.size();
    let scenes: Vec<&Scene> = panels.iter().map(|p| &p.scene).collect();
    let estimate = Estimate::of_tiles(&scenes, width, height, &outputs.budget)?;
    output::check(&outputs.list(), outputs.scene_file.as_deref())?;
    // Open every output first, so an unwritable folder fails before any work is done.
    let mut gif_file = AtomicFile::create(&outputs.gif)?;
    let mut png_file = outputs.png.as_deref().map(AtomicFile::create).transpose()?;
    if outputs.progress {
        for warning in estimate.warnings(&panels[0].scene) {
            eprintln!("warning: {warning}");
        }
    }

    let gif_error = OutputError::at(&outputs.gif);
    let out = BufWriter::new(gif_file.file());
    let palette = tiling.palette();
    let mut gif =
        GifWriter::new(out, width as u16, height as u16, palette, frame_ms).map_err(&gif_error)?;
    let last = animate(panels, renderers, tiling, frames, outputs, &mut gif)?;
    // The last frames are encoded while the still is written.
    gif.send_queued().map_err(&gif_error)?;
    if let Some(file) = png_file.as_mut() {
        write_still(file, &last, palette)?;
    }
    gif.finish()
        .and_then(|mut out| out.flush())
        .map_err(&gif_error)?;

    // The last moment a signal stops the sweep; from here on the files go into place.
    stop_if_asked(outputs, frames, frames)?;
    let sizes = output::commit_all(std::iter::once(gif_file).chain(png_file).collect())?;
    let paths = outputs.list().into_iter().map(|o| o.path.to_path_buf());
    Ok(paths.zip(sizes).collect())
}

/// Writes the last tiled frame as a PNG into `file`.
fn write_still(
    file: &mut AtomicFile,
    frame: &IndexedFrame,
    palette: &Palette,
) -> Result<(), OutputError> {
    let path = file.path().to_path_buf();
    let mut out = BufWriter::new(file.file());
    write_png(&mut out, frame, palette)
        .and_then(|()| out.flush())
        .map_err(OutputError::at(&path))
}

/// The one frame time every panel shares, ms.
fn frame_time(panels: &[Panel]) -> Result<u32, SweepError> {
    let first = panels.first().map_or(30, |p| p.scene.frame_ms);
    match panels.iter().find(|p| p.scene.frame_ms != first) {
        Some(other) => Err(SweepError::FrameTimes(first, other.scene.frame_ms)),
        None => Ok(first),
    }
}

/// Steps every panel frame by frame, draws it and pastes it into the tiled canvas, which goes
/// to `gif`; returns the last canvas, for the still. A panel with fewer frames than the
/// longest holds its last frame.
fn animate<W: Write>(
    panels: &[Panel],
    renderers: &[Renderer],
    tiling: &Tiling,
    frames: u32,
    outputs: &SweepOutputs,
    gif: &mut GifWriter<W>,
) -> Result<IndexedFrame, RunError> {
    let mut runs: Vec<_> = panels
        .iter()
        .zip(renderers)
        .map(|(panel, renderer)| (panel.scene.simulation(), renderer.new_frame()))
        .collect();
    let mut canvas = tiling.new_frame();
    let mut progress = Progress::new(frames, outputs.progress);
    for n in 0..frames {
        stop_if_asked(outputs, n, frames)?;
        for (i, (panel, (simulation, frame))) in panels.iter().zip(&mut runs).enumerate() {
            if n >= panel.scene.frames {
                continue;
            }
            simulation.step();
            RunError::if_not_finite(simulation.balls(), n, |_| {
                format!("the panel {}", panel.label)
            })?;
            renderers[i].draw(simulation.balls(), frame);
            tiling.paste(i, frame, &mut canvas);
        }
        gif.write_frame(&canvas)
            .map_err(OutputError::at(&outputs.gif))?;
        progress.frames_done(n + 1);
    }
    Ok(canvas)
}

/// Returns `Stopped` if a signal has come.
fn stop_if_asked(outputs: &SweepOutputs, frame: u32, frames: u32) -> Result<(), RunError> {
    RunError::if_stopped(&outputs.stop, frame, frames, || {
        let names: Vec<String> = outputs
            .list()
            .iter()
            .map(|o| o.path.display().to_string())
            .collect();
        names.join(", ")
    })
}
