//! A job's open outputs: each written to a temporary file beside its target (or to standard
//! output, for a stream given as `-`), and renamed into place together only once every one
//! is whole ([`crate::output`] does the renaming).

use std::cell::Cell;
use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

use crate::gif::GifWriter;
use crate::output::{self, AtomicFile, OutputError, StdoutStream};
use crate::render::palette::{IndexedFrame, Palette};
use crate::render::write_png;
use crate::render::Damage;

use super::outputs::{OutputKind, Target};

/// Where an output's bytes go while the job runs.
pub(crate) type Writer = BufWriter<Box<dyn Write>>;

/// Every output of a job, open from before the first frame until they go into place.
pub(crate) struct Files {
    open: Vec<Open>,
    /// How many frames the finished GIF holds, once it is finished.
    pictures: Cell<Option<u32>>,
}

/// One open output.
struct Open {
    kind: OutputKind,
    path: PathBuf,
    /// `None` for standard output, which is written as the job goes.
    file: Option<AtomicFile>,
}

impl Files {
    /// Opens every target, in order; a file that cannot be made fails before any work.
    pub(super) fn create(targets: &[Target]) -> Result<Files, OutputError> {
        let open = targets.iter().map(|target| {
            let file = match output::is_stdout(&target.path) {
                true => None,
                false => Some(AtomicFile::create(&target.path)?),
            };
            Ok(Open {
                kind: target.kind,
                path: target.path.clone(),
                file,
            })
        });
        Ok(Files {
            open: open.collect::<Result<_, OutputError>>()?,
            pictures: Cell::new(None),
        })
    }

    /// A writer onto the output of `kind`, if the job has one: a second handle on its
    /// temporary file (so writing it borrows nothing), or standard output.
    pub(crate) fn writer(&self, kind: OutputKind) -> Result<Option<Writer>, OutputError> {
        let Some(open) = self.open.iter().find(|o| o.kind == kind) else {
            return Ok(None);
        };
        let out: Box<dyn Write> = match &open.file {
            Some(file) => Box::new(handle(file).map_err(OutputError::at(&open.path))?),
            None => Box::new(StdoutStream::new()),
        };
        Ok(Some(BufWriter::new(out)))
    }

    /// Ties an I/O failure to the output of `kind`.
    pub(crate) fn error_at(&self, kind: OutputKind) -> impl Fn(io::Error) -> OutputError + '_ {
        OutputError::at(self.path(kind))
    }

    /// Where the output of `kind` goes (its flag, for one the job does not write).
    fn path(&self, kind: OutputKind) -> &Path {
        let open = self.open.iter().find(|o| o.kind == kind);
        open.map_or(Path::new(kind.flag()), |o| &o.path)
    }

    /// Starts the GIF (its header and colour table), `width` × `height` px, each frame shown
    /// for `frame_ms`.
    pub(crate) fn start_gif(
        &self,
        (width, height): (u32, u32),
        palette: &Palette,
        frame_ms: u32,
    ) -> Result<Gif, OutputError> {
        let error = self.error_at(OutputKind::Gif);
        let writer = match self.writer(OutputKind::Gif)? {
            Some(out) => Some(
                GifWriter::new(out, width as u16, height as u16, palette, frame_ms)
                    .map_err(&error)?,
            ),
            None => None,
        };
        let path = self.path(OutputKind::Gif).to_path_buf();
        Ok(Gif { writer, path })
    }

    /// Ends the pictures: the GIF's last frames are encoded while `still` is written as the
    /// PNG (if the job writes one), then the GIF is ended. Every byte is written, though no
    /// file is in place yet.
    pub(crate) fn finish_pictures(
        &self,
        gif: Gif,
        still: &IndexedFrame,
        palette: &Palette,
    ) -> Result<(), OutputError> {
        let gif_error = OutputError::at(&gif.path);
        if let Some(mut png) = self.writer(OutputKind::Png)? {
            write_png(&mut png, still, palette)
                .and_then(|()| png.flush())
                .map_err(self.error_at(OutputKind::Png))?;
        }
        if let Some(writer) = gif.writer {
            self.pictures.set(Some(writer.pictures()));
            writer
                .finish()
                .and_then(|mut out| out.flush())
                .map_err(&gif_error)?;
        }
        Ok(())
    }

    /// How many frames the GIF holds, once [`Files::finish_pictures`] has ended it.
    pub(super) fn pictures(&self) -> Option<u32> {
        self.pictures.get()
    }

    /// Puts every file in place; returns each file written and its size, in order (an
    /// output on standard output is no file).
    pub(super) fn commit(self) -> Result<Vec<(PathBuf, u64)>, OutputError> {
        let (paths, files): (Vec<PathBuf>, Vec<AtomicFile>) = self
            .open
            .into_iter()
            .filter_map(|o| o.file.map(|file| (o.path, file)))
            .unzip();
        let sizes = output::commit_all(files)?;
        Ok(paths.into_iter().zip(sizes).collect())
    }
}

/// The GIF as it is streamed, frame by frame; a job that writes no GIF takes its frames and
/// does nothing with them.
pub(crate) struct Gif {
    writer: Option<GifWriter<Writer>>,
    /// Where it goes, for messages.
    path: PathBuf,
}

impl Gif {
    /// Queues one whole frame.
    pub(crate) fn write_frame(&mut self, frame: &IndexedFrame) -> Result<(), OutputError> {
        self.write_changes(frame, Damage::Whole)
    }

    /// Queues one frame that differs from the last only as `damage` says.
    pub(crate) fn write_changes(
        &mut self,
        frame: &IndexedFrame,
        damage: Damage,
    ) -> Result<(), OutputError> {
        let Some(writer) = self.writer.as_mut() else {
            return Ok(());
        };
        writer
            .write_changes(frame, damage)
            .map_err(OutputError::at(&self.path))
    }
}

/// A second handle on `file`'s temporary file, writing where the first would.
fn handle(file: &AtomicFile) -> io::Result<File> {
    file.file().try_clone()
}
