//! One whole run: simulate a scene, draw every frame, stream it into the GIF, keep the last
//! frame as the PNG, and optionally trace every state as CSV and plot it.

use std::io::{BufWriter, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use crate::gif::GifWriter;
use crate::output::{AtomicFile, OutputError};
use crate::plot::Plot;
use crate::progress::Progress;
use crate::render::palette::TooManyColours;
use crate::render::raster::Renderer;
use crate::render::write_png;
use crate::scene::{InvalidValue, Scene};
use crate::trace;

/// Where a run writes.
#[derive(Clone, Debug)]
pub struct Outputs {
    pub gif: PathBuf,
    pub png: PathBuf,
    /// The CSV of every ball's state in every frame, when asked for.
    pub trace: Option<PathBuf>,
    /// The plot of height, speed and energy per frame (SVG, or PNG for `.png`), when asked for.
    pub plot: Option<PathBuf>,
    /// Show a progress bar on stderr if the run looks long (never when stderr is not a terminal).
    pub progress: bool,
}

/// What a run wrote.
#[derive(Clone, Debug)]
pub struct Summary {
    pub frames: u32,
    pub gif_bytes: u64,
    pub png_bytes: u64,
    pub elapsed: Duration,
}

/// Why a run wrote nothing.
#[derive(Debug, thiserror::Error)]
pub enum RunError {
    #[error(transparent)]
    Invalid(#[from] InvalidValue),
    #[error(transparent)]
    Colours(#[from] TooManyColours),
    #[error(transparent)]
    Output(#[from] OutputError),
}

impl RunError {
    /// 2 for input the program cannot use, 1 for a file it cannot write.
    pub fn exit_code(&self) -> u8 {
        match self {
            RunError::Invalid(_) | RunError::Colours(_) => 2,
            RunError::Output(_) => 1,
        }
    }
}

/// Runs `scene` and writes `outputs`; on any error no output file is left half-written.
pub fn run(scene: &Scene, outputs: &Outputs) -> Result<Summary, RunError> {
    let started = Instant::now();
    scene.validate()?;
    let renderer = Renderer::new(scene)?;
    let mut plot = outputs
        .plot
        .as_deref()
        .map(|path| Plot::new(scene, path))
        .transpose()?;
    // Open every output first, so an unwritable path fails before any work is done.
    let mut gif_file = AtomicFile::create(&outputs.gif)?;
    let mut png_file = AtomicFile::create(&outputs.png)?;
    let mut trace_file = outputs
        .trace
        .as_deref()
        .map(AtomicFile::create)
        .transpose()?;
    let plot_file = outputs
        .plot
        .as_deref()
        .map(AtomicFile::create)
        .transpose()?;

    let gif_error = OutputError::at(&outputs.gif);
    let mut gif = GifWriter::new(
        BufWriter::new(gif_file.file()),
        scene.width as u16,
        scene.height as u16,
        renderer.palette(),
        scene.frame_ms,
    )
    .map_err(&gif_error)?;
    let mut trace_out = trace_file.as_mut().map(|f| BufWriter::new(f.file()));
    let trace_path = outputs.trace.as_deref().unwrap_or(&outputs.gif);
    if let Some(out) = trace_out.as_mut() {
        trace::write_header(out).map_err(OutputError::at(trace_path))?;
    }

    let mut simulation = scene.simulation();
    let mut frame = renderer.new_frame();
    let mut progress = Progress::new(scene.frames, outputs.progress);
    for n in 0..scene.frames {
        simulation.step();
        if let Some(out) = trace_out.as_mut() {
            trace::write_frame(out, n, simulation.balls()).map_err(OutputError::at(trace_path))?;
        }
        if let Some(plot) = plot.as_mut() {
            plot.record(simulation.balls());
        }
        renderer.draw(simulation.balls(), &mut frame);
        gif.write_frame(&frame).map_err(&gif_error)?;
        progress.frames_done(n + 1);
    }
    gif.finish()
        .and_then(|mut out| out.flush())
        .map_err(&gif_error)?;
    if let Some(out) = trace_out.as_mut() {
        out.flush().map_err(OutputError::at(trace_path))?;
    }
    drop(trace_out);
    let mut png_out = BufWriter::new(png_file.file());
    write_png(&mut png_out, &frame, renderer.palette())
        .and_then(|()| png_out.flush())
        .map_err(OutputError::at(&outputs.png))?;
    drop(png_out);
    if let (Some(plot), Some(mut file), Some(path)) = (plot, plot_file, outputs.plot.as_deref()) {
        plot.write(file.file()).map_err(OutputError::at(path))?;
        // First of the renames: a plot path that cannot be replaced (a folder) then fails
        // before any other output is put in place.
        file.commit()?;
    }

    let gif_bytes = gif_file.commit()?;
    let png_bytes = png_file.commit()?;
    if let Some(file) = trace_file {
        file.commit()?;
    }
    Ok(Summary {
        frames: scene.frames,
        gif_bytes,
        png_bytes,
        elapsed: started.elapsed(),
    })
}
