//! A sweep's runs: every panel stepped and drawn frame by frame, pasted into the tiled canvas
//! and streamed into one GIF, after every check a run makes before its first frame.

use std::io::{BufWriter, Write};
use std::path::PathBuf;
use std::time::Instant;

use crate::budget::{memory_of, Budget, Estimate, OverBudget};
use crate::gif::GifWriter;
use crate::output::{self, AtomicFile, Output, OutputError};
use crate::progress::Progress;
use crate::render::palette::IndexedFrame;
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
    for panel in panels {
        panel.scene.validate().map_err(RunError::from)?;
    }
    let frame_ms = frame_time(panels)?;
    let renderers = panels
        .iter()
        .map(|panel| Renderer::new(&panel.scene))
        .collect::<Result<Vec<_>, _>>()
        .map_err(RunError::from)?;
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
    let frames = panels.iter().map(|p| p.scene.frames).max().unwrap_or(1);
    let estimate = estimate(panels, &tiling, frames, &outputs.budget).map_err(RunError::from)?;
    output::check(&outputs.list(), outputs.scene_file.as_deref()).map_err(RunError::from)?;
    // Open every output first, so an unwritable folder fails before any work is done.
    let mut gif_file = AtomicFile::create(&outputs.gif).map_err(RunError::from)?;
    let mut png_file = outputs.png.as_deref().map(AtomicFile::create);
    let mut png_file = png_file.take().transpose().map_err(RunError::from)?;
    if outputs.progress {
        for warning in estimate.warnings(&panels[0].scene) {
            eprintln!("warning: {warning}");
        }
    }

    let gif_error = OutputError::at(&outputs.gif);
    let (width, height) = tiling.size();
    let mut gif = GifWriter::new(
        BufWriter::new(gif_file.file()),
        width as u16,
        height as u16,
        tiling.palette(),
        frame_ms,
    )
    .map_err(&gif_error)
    .map_err(RunError::from)?;
    let last = animate(panels, &renderers, &tiling, frames, outputs, &mut gif)?;
    gif.send_queued()
        .map_err(&gif_error)
        .map_err(RunError::from)?;
    if let Some(file) = png_file.as_mut() {
        let mut out = BufWriter::new(file.file());
        write_png(&mut out, &last, tiling.palette())
            .and_then(|()| out.flush())
            .map_err(OutputError::at(&outputs.png.clone().unwrap_or_default()))
            .map_err(RunError::from)?;
    }
    gif.finish()
        .and_then(|mut out| out.flush())
        .map_err(&gif_error)
        .map_err(RunError::from)?;

    stop_if_asked(outputs, frames, frames)?;
    let files: Vec<AtomicFile> = std::iter::once(gif_file).chain(png_file).collect();
    let sizes = output::commit_all(files).map_err(RunError::from)?;
    let paths = outputs.list().into_iter().map(|o| o.path.to_path_buf());
    Ok(Summary {
        frames,
        files: paths.zip(sizes).collect(),
        elapsed: started.elapsed(),
    })
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
            if let Some(ball) = simulation.balls().iter().position(|b| !b.is_finite()) {
                let b = &simulation.balls()[ball];
                return Err(RunError::NonFinite {
                    ball,
                    frame: n,
                    state: format!("x {:?}, y {:?}, vx {:?}, vy {:?}", b.x, b.y, b.vx, b.vy),
                    inputs: format!("the panel {}", panel.label),
                });
            }
            renderers[i].draw(simulation.balls(), frame);
            tiling.paste(i, frame, &mut canvas);
        }
        gif.write_frame(&canvas)
            .map_err(OutputError::at(&outputs.gif))?;
        progress.frames_done(n + 1);
    }
    Ok(canvas)
}

/// What the sweep will cost: every panel's run, plus the tiled canvas's frames and GIF.
/// Memory is checked first, from the scenes alone, before any pilot run of their physics.
fn estimate(
    panels: &[Panel],
    tiling: &Tiling,
    frames: u32,
    budget: &Budget,
) -> Result<Estimate, OverBudget> {
    let (width, height) = tiling.size();
    let canvas = Scene {
        frames,
        ..Scene::empty(width, height)
    };
    let scenes = || panels.iter().map(|p| &p.scene).chain([&canvas]);
    let biggest = "the panels' runs and the tiled frames";
    let memory: u64 = scenes().map(|scene| memory_of(scene).0).sum();
    if memory > budget.memory {
        return Err(OverBudget::Memory {
            needed: memory,
            budget: budget.memory,
            biggest,
        });
    }
    let parts: Vec<Estimate> = scenes().map(Estimate::of).collect();
    let total = Estimate {
        memory,
        frame_ns: parts.iter().map(|e| e.frame_ns).sum(),
        seconds: parts.iter().map(|e| e.seconds).sum(),
        gif_bytes: parts.iter().map(|e| e.gif_bytes).sum(),
        biggest,
    };
    total.check_time_and_size(budget)?;
    Ok(total)
}

/// Returns `Stopped` if a signal has come.
fn stop_if_asked(outputs: &SweepOutputs, frame: u32, frames: u32) -> Result<(), RunError> {
    match outputs.stop.requested() {
        Some(signal) => {
            let names: Vec<String> = outputs
                .list()
                .iter()
                .map(|o| o.path.display().to_string())
                .collect();
            Err(RunError::Stopped {
                signal,
                frame,
                frames,
                unwritten: names.join(", "),
            })
        }
        None => Ok(()),
    }
}
