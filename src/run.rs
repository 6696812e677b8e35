//! The main command: simulate a scene, draw every frame, stream it into the GIF, keep the
//! last frame as the PNG, and optionally trace every state as CSV and plot it.
//!
//! Everything that can be refused is refused before the first frame: the scene's values, its
//! colours, its budget ([`crate::budget`]) and the output paths. What every command shares,
//! the outputs written beside their targets and renamed into place at the end, the stop
//! check, the progress bar and the summary, is [`crate::job`]'s.

use std::io::Write;

use crate::budget::Estimate;
use crate::job::files::{Gif, Writer};
use crate::job::{Files, Job, OutputKind, RunError, Summary};
use crate::output::OutputError;
use crate::physics::replay::Playback;
use crate::physics::Ball;
use crate::plot::Plot;
use crate::render::palette::{IndexedFrame, Palette};
use crate::render::raster::Renderer;
use crate::render::Canvas;
use crate::scene::Scene;
use crate::trace;

/// Runs `scene` and writes `job`'s outputs (a GIF, a PNG, a trace, a plot); on any error no
/// output file is left half-written and no existing file is changed.
pub fn run(scene: &Scene, job: &Job) -> Result<Summary, RunError> {
    scene.validate()?;
    let files = job.open()?;
    let (estimate, playback) = Estimate::within_keeping(scene, &job.budget)?;
    let renderer = Renderer::new(scene)?;
    let plot = job
        .path(OutputKind::Plot)
        .map(|path| Plot::new(scene, path));
    let plot = plot.transpose()?;
    job.warn(&estimate.warnings(scene));
    let mut writers = Writers::open(scene, &renderer, plot, &files)?;
    let playback = playback.unwrap_or_else(|| Playback::stepping(scene.simulation()));
    let canvas = animate(scene, job, playback, &renderer, &mut writers)?;
    writers.finish(canvas.frame(), renderer.palette())?;
    job.commit(files, scene.frames)
}

/// Checks that every ball is still a finite number, naming the start of the one that is not.
fn check_finite(scene: &Scene, balls: &[Ball], frame: u32) -> Result<(), RunError> {
    RunError::if_not_finite(balls, frame, |i| {
        let spec = &scene.balls[i];
        let gravity = scene.gravity.map_or("no gravity".to_string(), |g| {
            format!("gravity {:?}", g.to_array())
        });
        format!(
            "x {:?}, y {:?}, vx {:?}, vy {:?}, {gravity}",
            spec.x, spec.y, spec.vx, spec.vy
        )
    })
}

/// Simulates every frame of `scene` (the first ones played back where the budget's pilot
/// stepped them already), drawing it and handing it to `writers`; returns the canvas with the
/// last frame drawn, for the still.
fn animate(
    scene: &Scene,
    job: &Job,
    mut simulation: Playback,
    renderer: &Renderer,
    writers: &mut Writers,
) -> Result<Canvas, RunError> {
    let mut canvas = Canvas::new(renderer);
    job.progress().add_frames(scene.frames);
    for n in 0..scene.frames {
        job.stop_if_asked(n, scene.frames)?;
        simulation.step();
        check_finite(scene, simulation.balls(), n)?;
        writers.record(n, simulation.balls())?;
        // Only what changed is drawn again, and only there does the GIF look for changes.
        canvas.redraw(renderer, simulation.balls());
        writers.write_frame(&canvas)?;
        job.progress().frame_done();
    }
    Ok(canvas)
}

/// What a run writes into as it goes: the GIF and the trace are streamed frame by frame, the
/// plot is recorded and written at the end, as is the still.
struct Writers<'a> {
    files: &'a Files,
    gif: Gif,
    trace: Option<Writer>,
    plot: Option<Plot>,
}

impl<'a> Writers<'a> {
    /// Starts the GIF (its header and colour table) and the trace (its header), and takes
    /// the plot to record into.
    fn open(
        scene: &Scene,
        renderer: &Renderer,
        plot: Option<Plot>,
        files: &'a Files,
    ) -> Result<Writers<'a>, OutputError> {
        let size = (scene.width, scene.height);
        let gif = files.start_gif(size, renderer.palette(), scene.frame_ms)?;
        let mut trace = files.writer(OutputKind::Trace)?;
        if let Some(out) = trace.as_mut() {
            trace::write_header(out).map_err(files.error_at(OutputKind::Trace))?;
        }
        Ok(Writers {
            files,
            gif,
            trace,
            plot,
        })
    }

    /// Records frame `n`'s `balls` in the trace and the plot, each if asked for.
    fn record(&mut self, n: u32, balls: &[Ball]) -> Result<(), OutputError> {
        if let Some(out) = self.trace.as_mut() {
            trace::write_frame(out, n, balls).map_err(self.files.error_at(OutputKind::Trace))?;
        }
        if let Some(plot) = self.plot.as_mut() {
            plot.record(balls);
        }
        Ok(())
    }

    /// Queues the canvas's frame for the GIF.
    fn write_frame(&mut self, canvas: &Canvas) -> Result<(), OutputError> {
        self.gif.write_changes(canvas.frame(), canvas.damage())
    }

    /// Writes `last_frame` as the still, then ends the GIF, the trace and the plot: every
    /// byte is written, though no file is in place yet.
    fn finish(self, last_frame: &IndexedFrame, palette: &Palette) -> Result<(), OutputError> {
        let files = self.files;
        files.finish_pictures(self.gif, last_frame, palette)?;
        if let Some(mut out) = self.trace {
            out.flush().map_err(files.error_at(OutputKind::Trace))?;
        }
        if let (Some(plot), Some(mut out)) = (self.plot, files.writer(OutputKind::Plot)?) {
            plot.write(&mut out)
                .and_then(|()| out.flush())
                .map_err(files.error_at(OutputKind::Plot))?;
        }
        Ok(())
    }
}
