//! A sweep's runs: every panel stepped and drawn frame by frame, pasted into the tiled canvas
//! and streamed into one GIF, after every check a run makes before its first frame.

use crate::budget::Estimate;
use crate::job::files::Gif;
use crate::job::{Job, RunError, Summary};
use crate::render::palette::IndexedFrame;
use crate::render::raster::Renderer;
use crate::render::tile::{PanelSpec, Tiling};
use crate::scene::Scene;

use super::error::SweepError;
use super::values::Panel;

/// Runs every panel and writes `job`'s outputs (the tiled GIF, and the still if asked for);
/// on any error no output file is left half-written and no existing file is changed.
pub fn run(panels: &[Panel], job: &Job) -> Result<Summary, SweepError> {
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
    Ok(write(panels, &renderers, &tiling, frame_ms, job)?)
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

/// Checks the budget and opens the outputs, then runs the panels into the GIF (and the
/// still) and puts the files in place.
fn write(
    panels: &[Panel],
    renderers: &[Renderer],
    tiling: &Tiling,
    frame_ms: u32,
    job: &Job,
) -> Result<Summary, RunError> {
    let frames = panels.iter().map(|p| p.scene.frames).max().unwrap_or(1);
    let scenes: Vec<&Scene> = panels.iter().map(|p| &p.scene).collect();
    let (width, height) = tiling.size();
    let files = job.open()?;
    let estimate = Estimate::of_tiles(&scenes, width, height, &job.budget)?;
    job.warn(&estimate.warnings(&panels[0].scene));
    let palette = tiling.palette();
    let mut gif = files.start_gif(tiling.size(), palette, frame_ms)?;
    let last = animate(panels, renderers, tiling, frames, job, &mut gif)?;
    files.finish_pictures(gif, &last, palette)?;
    job.commit(files, frames)
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
fn animate(
    panels: &[Panel],
    renderers: &[Renderer],
    tiling: &Tiling,
    frames: u32,
    job: &Job,
    gif: &mut Gif,
) -> Result<IndexedFrame, RunError> {
    let mut runs: Vec<_> = panels
        .iter()
        .zip(renderers)
        .map(|(panel, renderer)| (panel.scene.simulation(), renderer.new_frame()))
        .collect();
    let mut canvas = tiling.new_frame();
    job.progress().add_frames(frames);
    for n in 0..frames {
        job.stop_if_asked(n, frames)?;
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
        gif.write_frame(&canvas)?;
        job.progress().frame_done();
    }
    Ok(canvas)
}
