//! One whole run: simulate a scene, draw every frame, stream it into the GIF, keep the last
//! frame as the PNG, and optionally trace every state as CSV and plot it.
//!
//! Everything that can be refused is refused before the first frame: the scene's values, its
//! colours, its memory ([`crate::budget`]) and the output paths ([`crate::output::check`]).
//! Every file is then written beside its target and renamed into place only at the end.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::budget::{Budget, Estimate, OverBudget};
use crate::gif::GifWriter;
use crate::output::{self, AtomicFile, Output, OutputError, OutputRefused, StdoutStream};
use crate::physics::Ball;
use crate::plot::Plot;
use crate::progress::Progress;
use crate::render::palette::{IndexedFrame, Palette, TooManyColours};
use crate::render::raster::Renderer;
use crate::render::{write_png, Canvas};
use crate::scene::{InvalidValue, Scene};
use crate::stop::{Signal, Stop};
use crate::trace;

/// Where a run writes, and the limits it runs within.
#[derive(Clone, Debug)]
pub struct Outputs {
    pub gif: PathBuf,
    pub png: PathBuf,
    /// The CSV of every ball's state in every frame, when asked for; `-` is standard output.
    pub trace: Option<PathBuf>,
    /// The plot of height, speed and energy per frame (SVG, or PNG for `.png`), when asked for.
    pub plot: Option<PathBuf>,
    /// Talk on stderr while running: warnings, and a progress bar if the run looks long
    /// (never when stderr is not a terminal). False for `--quiet`.
    pub progress: bool,
    /// The scene file the scene was read from, which no output may replace.
    pub scene_file: Option<PathBuf>,
    /// What a run may be predicted to need (memory, time, GIF size) before it is refused.
    pub budget: Budget,
    /// Set by a signal: the run stops at the next frame and writes nothing.
    pub stop: Stop,
}

impl Outputs {
    /// The GIF and PNG at these paths, no trace, silent, the default budget, never stopped.
    pub fn new(gif: impl Into<PathBuf>, png: impl Into<PathBuf>) -> Outputs {
        Outputs {
            gif: gif.into(),
            png: png.into(),
            trace: None,
            plot: None,
            progress: false,
            scene_file: None,
            budget: Budget::default(),
            stop: Stop::default(),
        }
    }

    /// Every output this run writes, in the order they are renamed into place. A new kind
    /// of output is one more entry here (and one more file in [`Files`]).
    pub fn list(&self) -> Vec<Output<'_>> {
        let mut list = vec![
            Output::picture("--gif", &self.gif, "gif"),
            Output::picture("--png", &self.png, "png"),
        ];
        if let Some(path) = &self.trace {
            list.push(Output::stream("--trace", path));
        }
        if let Some(path) = &self.plot {
            list.push(Output::file("--plot", path));
        }
        list
    }

    /// Whether the trace goes to standard output (then nothing else should).
    pub fn trace_on_stdout(&self) -> bool {
        self.trace.as_deref().is_some_and(output::is_stdout)
    }

    /// The files a stopped or failed run leaves as they were, for its message.
    fn files(&self) -> String {
        let names: Vec<String> = self
            .list()
            .iter()
            .filter(|o| !output::is_stdout(o.path))
            .map(|o| o.path.display().to_string())
            .collect();
        names.join(", ")
    }
}

/// What a run wrote.
#[derive(Clone, Debug)]
pub struct Summary {
    pub frames: u32,
    /// Every file written and its size in bytes, in the order of [`Outputs::list`] (the GIF
    /// first, the PNG second; a trace sent to standard output is not a file).
    pub files: Vec<(PathBuf, u64)>,
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
    OverBudget(#[from] OverBudget),
    #[error(transparent)]
    Refused(#[from] OutputRefused),
    #[error("ball {ball} left the finite numbers at frame {frame} ({state}) from {inputs}; these values are too large to simulate, nothing was written")]
    NonFinite {
        ball: usize,
        frame: u32,
        state: String,
        inputs: String,
    },
    #[error(transparent)]
    Output(#[from] OutputError),
    #[error("stopped by {} at frame {frame} of {frames}: not written: {unwritten} (any earlier files are as they were)", signal.name)]
    Stopped {
        signal: Signal,
        frame: u32,
        frames: u32,
        unwritten: String,
    },
}

impl RunError {
    /// 2 for input the program cannot use, 1 for a file it cannot write, 128 + the signal's
    /// number for a run stopped by one.
    pub fn exit_code(&self) -> u8 {
        match self {
            RunError::Invalid(_)
            | RunError::Colours(_)
            | RunError::OverBudget(_)
            | RunError::Refused(_)
            | RunError::NonFinite { .. } => 2,
            RunError::Output(_) => 1,
            RunError::Stopped { signal, .. } => signal.exit_code(),
        }
    }

    /// `Stopped` at `frame` of `frames` if a signal has come; `unwritten` names the files
    /// left as they were.
    pub(crate) fn if_stopped(
        stop: &Stop,
        frame: u32,
        frames: u32,
        unwritten: impl FnOnce() -> String,
    ) -> Result<(), RunError> {
        match stop.requested() {
            Some(signal) => Err(RunError::Stopped {
                signal,
                frame,
                frames,
                unwritten: unwritten(),
            }),
            None => Ok(()),
        }
    }

    /// `NonFinite` for the first ball that left the finite numbers in `frame`, so no NaN is
    /// traced, measured, drawn or written; `inputs` says what that ball (by index) came from.
    pub(crate) fn if_not_finite(
        balls: &[Ball],
        frame: u32,
        inputs: impl FnOnce(usize) -> String,
    ) -> Result<(), RunError> {
        let Some((i, ball)) = balls.iter().enumerate().find(|(_, b)| !b.is_finite()) else {
            return Ok(());
        };
        Err(RunError::NonFinite {
            ball: i,
            frame,
            state: format!(
                "x {:?}, y {:?}, vx {:?}, vy {:?}",
                ball.x, ball.y, ball.vx, ball.vy
            ),
            inputs: inputs(i),
        })
    }
}

/// Checks that every ball is still a finite number, naming the start of the one that is not.
fn check_finite(scene: &Scene, balls: &[Ball], frame: u32) -> Result<(), RunError> {
    RunError::if_not_finite(balls, frame, |i| {
        let spec = &scene.balls[i];
        let gravity = scene
            .gravity
            .map_or("no gravity".to_string(), |g| format!("gravity {g:?}"));
        format!(
            "x {:?}, y {:?}, vx {:?}, vy {:?}, {gravity}",
            spec.x, spec.y, spec.vx, spec.vy
        )
    })
}

/// Runs `scene` and writes `outputs`; on any error no output file is left half-written and
/// no existing file is changed.
pub fn run(scene: &Scene, outputs: &Outputs) -> Result<Summary, RunError> {
    let started = Instant::now();
    scene.validate()?;
    let estimate = Estimate::within(scene, &outputs.budget)?;
    output::check(&outputs.list(), outputs.scene_file.as_deref())?;
    let renderer = Renderer::new(scene)?;
    let plot = outputs
        .plot
        .as_deref()
        .map(|path| Plot::new(scene, path))
        .transpose()?;
    // Open every output first, so an unwritable folder fails before any work is done.
    let mut files = Files::create(outputs)?;
    // Only once nothing more can be refused, so a refusal stays a single line.
    if outputs.progress {
        for warning in estimate.warnings(scene) {
            eprintln!("warning: {warning}");
        }
    }

    let mut writers = Writers::open(scene, outputs, &renderer, plot, &mut files)?;
    let canvas = animate(scene, outputs, &renderer, &mut writers)?;
    writers.finish(canvas.frame(), renderer.palette())?;

    // The last moment a signal stops the run; from here on the files go into place.
    stop_if_asked(outputs, scene.frames, scene.frames)?;
    let sizes = files.commit()?;
    let written = outputs
        .list()
        .into_iter()
        .filter(|o| !output::is_stdout(o.path));
    Ok(Summary {
        frames: scene.frames,
        files: written.map(|o| o.path.to_path_buf()).zip(sizes).collect(),
        elapsed: started.elapsed(),
    })
}

/// Simulates every frame of `scene`, drawing it and handing it to `writers`; returns the
/// canvas with the last frame drawn, for the still.
fn animate(
    scene: &Scene,
    outputs: &Outputs,
    renderer: &Renderer,
    writers: &mut Writers,
) -> Result<Canvas, RunError> {
    let mut simulation = scene.simulation();
    let mut canvas = Canvas::new(renderer);
    let mut progress = Progress::new(scene.frames, outputs.progress);
    for n in 0..scene.frames {
        stop_if_asked(outputs, n, scene.frames)?;
        simulation.step();
        check_finite(scene, simulation.balls(), n)?;
        writers.record(n, simulation.balls())?;
        // Only what changed is drawn again, and only there does the GIF look for changes.
        canvas.redraw(renderer, simulation.balls());
        writers.write_frame(&canvas)?;
        progress.frames_done(n + 1);
    }
    Ok(canvas)
}

/// Every file a run writes, open from before the first frame until they all go into place
/// together at the end.
struct Files {
    gif: AtomicFile,
    png: AtomicFile,
    /// `None` without a trace, or when it goes to standard output.
    trace: Option<AtomicFile>,
    plot: Option<AtomicFile>,
}

impl Files {
    /// Opens every output file, in the order of [`Outputs::list`].
    fn create(outputs: &Outputs) -> Result<Files, OutputError> {
        Ok(Files {
            gif: AtomicFile::create(&outputs.gif)?,
            png: AtomicFile::create(&outputs.png)?,
            trace: match &outputs.trace {
                Some(path) if !output::is_stdout(path) => Some(AtomicFile::create(path)?),
                _ => None,
            },
            plot: outputs
                .plot
                .as_deref()
                .map(AtomicFile::create)
                .transpose()?,
        })
    }

    /// Puts every file in place; returns their sizes in the same order.
    fn commit(self) -> Result<Vec<u64>, OutputError> {
        let files = [self.gif, self.png]
            .into_iter()
            .chain(self.trace)
            .chain(self.plot);
        output::commit_all(files.collect())
    }
}

/// What a run writes into as it goes, on top of its [`Files`]: the GIF and the trace are
/// streamed frame by frame, the plot is recorded and written at the end, as is the still.
struct Writers<'a> {
    /// Where each goes, for messages.
    outputs: &'a Outputs,
    gif: GifWriter<BufWriter<&'a mut File>>,
    trace: Option<TraceWriter<'a>>,
    plot: Option<Plot>,
    plot_file: Option<&'a mut AtomicFile>,
    png_file: &'a mut AtomicFile,
}

/// The trace's CSV as it is written, and its path for messages.
struct TraceWriter<'a> {
    out: BufWriter<Box<dyn Write + 'a>>,
    path: &'a Path,
}

impl<'a> Writers<'a> {
    /// Starts the GIF (its header and colour table) and the trace (its header) in `files`,
    /// and takes the plot to record into.
    fn open(
        scene: &Scene,
        outputs: &'a Outputs,
        renderer: &Renderer,
        plot: Option<Plot>,
        files: &'a mut Files,
    ) -> Result<Writers<'a>, RunError> {
        let gif = GifWriter::new(
            BufWriter::new(files.gif.file()),
            scene.width as u16,
            scene.height as u16,
            renderer.palette(),
            scene.frame_ms,
        )
        .map_err(OutputError::at(&outputs.gif))?;
        Ok(Writers {
            outputs,
            gif,
            trace: TraceWriter::open(outputs, files.trace.as_mut())?,
            plot,
            plot_file: files.plot.as_mut(),
            png_file: &mut files.png,
        })
    }

    /// Records frame `n`'s `balls` in the trace and the plot, each if asked for.
    fn record(&mut self, n: u32, balls: &[Ball]) -> Result<(), OutputError> {
        if let Some(trace) = self.trace.as_mut() {
            trace::write_frame(&mut trace.out, n, balls).map_err(OutputError::at(trace.path))?;
        }
        if let Some(plot) = self.plot.as_mut() {
            plot.record(balls);
        }
        Ok(())
    }

    /// Queues the canvas's frame for the GIF.
    fn write_frame(&mut self, canvas: &Canvas) -> Result<(), OutputError> {
        self.gif
            .write_changes(canvas.frame(), canvas.damage())
            .map_err(OutputError::at(&self.outputs.gif))
    }

    /// Writes `last_frame` as the still, then ends the GIF, the trace and the plot: every
    /// byte is written, though no file is in place yet.
    fn finish(mut self, last_frame: &IndexedFrame, palette: &Palette) -> Result<(), OutputError> {
        let gif_error = OutputError::at(&self.outputs.gif);
        // The last frames are encoded while the still is written.
        self.gif.send_queued().map_err(&gif_error)?;
        let mut png_out = BufWriter::new(self.png_file.file());
        write_png(&mut png_out, last_frame, palette)
            .and_then(|()| png_out.flush())
            .map_err(OutputError::at(&self.outputs.png))?;
        drop(png_out);
        self.gif
            .finish()
            .and_then(|mut out| out.flush())
            .map_err(&gif_error)?;
        if let Some(mut trace) = self.trace {
            trace.out.flush().map_err(OutputError::at(trace.path))?;
        }
        if let (Some(plot), Some(file)) = (self.plot, self.plot_file) {
            plot.write(file.file())
                .map_err(OutputError::at(file.path()))?;
        }
        Ok(())
    }
}

impl<'a> TraceWriter<'a> {
    /// Starts the trace, into `file` or standard output, with its header; `None` when no
    /// trace was asked for.
    fn open(
        outputs: &'a Outputs,
        file: Option<&'a mut AtomicFile>,
    ) -> Result<Option<TraceWriter<'a>>, OutputError> {
        let Some(path) = outputs.trace.as_deref() else {
            return Ok(None);
        };
        // A trace without a file is one on standard output (see `Files::create`).
        let out: Box<dyn Write + 'a> = match file {
            Some(file) => Box::new(file.file()),
            None => Box::new(StdoutStream::new()),
        };
        let mut out = BufWriter::new(out);
        trace::write_header(&mut out).map_err(OutputError::at(path))?;
        Ok(Some(TraceWriter { out, path }))
    }
}

/// Returns `Stopped` if a signal has come.
fn stop_if_asked(outputs: &Outputs, frame: u32, frames: u32) -> Result<(), RunError> {
    RunError::if_stopped(&outputs.stop, frame, frames, || outputs.files())
}
