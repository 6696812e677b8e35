//! The driver under every command that runs a scene (the main command, `compare`, `sweep`,
//! `check`): what they share, written once. A [`Job`] is built once from the command line
//! and holds where the scene came from, the budget, the stop flag, whether to talk on stderr (warnings
//! and a progress bar) and the list of outputs. A command uses it in this order:
//!
//! 1. [`Job::check`] before any work, then `Job::open`: every output path is checked, each
//!    file is opened beside its target, and the warnings are printed;
//! 2. `Job::stop_if_asked` once a frame, and a `Job::progress` bar over the frames;
//! 3. `Files::finish_pictures`: the GIF's last frames, the still PNG, the GIF's end;
//! 4. `Job::commit`: every file into place together, and the [`Summary`] of what was
//!    written.
//!
//! The commands are peers above it: none imports another.
//!
//! - `outputs`: what each output is ([`OutputKind`]) and where it goes ([`Target`]).
//! - `files`: the open outputs, written beside their targets and committed together.
//! - `error`: why a job wrote nothing ([`RunError`]), with its exit code.

pub(crate) mod error;
pub(crate) mod files;
pub(crate) mod outputs;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::budget::Budget;
use crate::output;
use crate::progress::Progress;
use crate::stop::Stop;

pub use error::RunError;
pub(crate) use files::Files;
pub use outputs::{OutputKind, Target};

/// One command's run: its outputs and the limits it runs within.
pub struct Job {
    /// Every output, in the order they are renamed into place (the GIF first).
    pub outputs: Vec<Target>,
    /// The scene file the scene was read from, which no output may replace.
    pub scene_file: Option<PathBuf>,
    /// What a run may be predicted to need (memory, time, GIF size) before it is refused.
    pub budget: Budget,
    /// Set by a signal: the job stops at the next frame and writes nothing.
    pub stop: Stop,
    /// Talk on stderr while running: warnings, and a progress bar if the job looks long
    /// (never when stderr is not a terminal). See [`Job::talking`].
    talk: bool,
    progress: Progress,
    started: Instant,
}

/// What a job wrote.
#[derive(Clone, Debug)]
pub struct Summary {
    pub frames: u32,
    /// How many frames the GIF holds (it merges a frame that repeats the last into it), if
    /// the job wrote one; then the GIF is the first of `files`.
    pub pictures: Option<u32>,
    /// Every file written and its size in bytes, in the order of [`Job::outputs`] (a trace
    /// sent to standard output is not a file).
    pub files: Vec<(PathBuf, u64)>,
    pub elapsed: Duration,
}

impl Default for Job {
    fn default() -> Job {
        Job::new()
    }
}

impl Job {
    /// A job with no outputs yet, silent, within the default budget, never stopped.
    pub fn new() -> Job {
        Job {
            outputs: Vec::new(),
            scene_file: None,
            budget: Budget::default(),
            stop: Stop::default(),
            talk: false,
            progress: Progress::new(false),
            started: Instant::now(),
        }
    }

    /// The job, talking on stderr: warnings, and a progress bar once it looks long.
    pub(crate) fn talking(self) -> Job {
        Job {
            talk: true,
            progress: Progress::new(true),
            ..self
        }
    }

    /// A job that writes a GIF and its still: what the main command writes by default.
    pub fn pictures(gif: impl Into<PathBuf>, png: impl Into<PathBuf>) -> Job {
        Job::new()
            .with(OutputKind::Gif, gif)
            .with(OutputKind::Png, png)
    }

    /// The job with one more output.
    pub(crate) fn with(mut self, kind: OutputKind, path: impl Into<PathBuf>) -> Job {
        self.outputs.push(Target {
            kind,
            path: path.into(),
        });
        self
    }

    /// The job with one more output if `path` is given (a flag the user may leave out).
    pub(crate) fn with_optional(self, kind: OutputKind, path: Option<&PathBuf>) -> Job {
        match path {
            Some(path) => self.with(kind, path),
            None => self,
        }
    }

    /// Where the output of this kind goes, if the job writes one.
    pub fn path(&self, kind: OutputKind) -> Option<&Path> {
        let target = self.outputs.iter().find(|t| t.kind == kind);
        target.map(|t| t.path.as_path())
    }

    /// Whether some output goes to standard output (then the summary goes to stderr).
    pub(crate) fn writes_to_stdout(&self) -> bool {
        self.outputs.iter().any(|t| output::is_stdout(&t.path))
    }

    /// Refuses an output path no output should take: a folder, a device, the scene file, a
    /// path another output names too. `Job::open` checks first too; a command calls this
    /// before any work of its own, so a wrong path is the first thing it says.
    pub fn check(&self) -> Result<(), RunError> {
        let list: Vec<_> = self.outputs.iter().map(Target::output).collect();
        Ok(output::check(&list, self.scene_file.as_deref())?)
    }

    /// Checks every output path and opens each output beside its target: before any work,
    /// so that an output that cannot be written is refused at once.
    pub(crate) fn open(&self) -> Result<Files, RunError> {
        self.check()?;
        Ok(Files::create(&self.outputs)?)
    }

    /// Prints `warnings` (unless silent): once nothing more can be refused, so that a
    /// refusal stays a single line.
    pub(crate) fn warn(&self, warnings: &[String]) {
        if self.talk {
            for warning in warnings {
                eprintln!("warning: {warning}");
            }
        }
    }

    /// `Stopped` at `frame` of `frames` if a signal has come.
    pub(crate) fn stop_if_asked(&self, frame: u32, frames: u32) -> Result<(), RunError> {
        match self.stop.requested() {
            Some(signal) => Err(RunError::Stopped {
                signal,
                frame,
                frames,
                unwritten: self.files_named(),
            }),
            None => Ok(()),
        }
    }

    /// The progress bar over the job's frames (shown only if the job talks and looks long).
    pub(crate) fn progress(&self) -> &Progress {
        &self.progress
    }

    /// Puts every file in place once a last look finds no signal, and says what was written:
    /// `frames` frames, and every file with its size.
    pub(crate) fn commit(&self, files: Files, frames: u32) -> Result<Summary, RunError> {
        // The last moment a signal stops the job; from here on the files go into place.
        self.stop_if_asked(frames, frames)?;
        let pictures = files.pictures();
        let files = files.commit()?;
        self.progress.clear();
        Ok(Summary {
            frames,
            pictures,
            files,
            elapsed: self.started.elapsed(),
        })
    }

    /// The files a stopped or failed job leaves as they were, for its message.
    fn files_named(&self) -> String {
        let names: Vec<String> = self
            .outputs
            .iter()
            .filter(|t| !output::is_stdout(&t.path))
            .map(|t| t.path.display().to_string())
            .collect();
        names.join(", ")
    }
}
