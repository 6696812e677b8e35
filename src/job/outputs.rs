//! A job's outputs: what each is ([`OutputKind`], which fixes its flag and what path it may take)
//! and where it goes ([`Target`]).

use std::path::PathBuf;

use crate::output::Output;

/// What an output is, which fixes its flag and what it may be: a picture whose format the
/// flag fixes, a stream that may go to standard output, or a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputKind {
    Gif,
    Png,
    Trace,
    Plot,
    Table,
    /// `check --diff`: expected | theirs | difference.
    Diff,
}

impl OutputKind {
    /// The flag that names this output.
    pub(crate) fn flag(self) -> &'static str {
        match self {
            OutputKind::Gif => "--gif",
            OutputKind::Png => "--png",
            OutputKind::Trace => "--trace",
            OutputKind::Plot => "--plot",
            OutputKind::Table => "--table",
            OutputKind::Diff => "--diff",
        }
    }
}

/// One output of a job: what it is and where it goes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Target {
    pub kind: OutputKind,
    pub path: PathBuf,
}

impl Target {
    /// This output as [`crate::output::check`] judges it.
    pub(crate) fn output(&self) -> Output<'_> {
        let (flag, path) = (self.kind.flag(), self.path.as_path());
        match self.kind {
            OutputKind::Gif => Output::picture(flag, path, "gif"),
            OutputKind::Png | OutputKind::Diff => Output::picture(flag, path, "png"),
            OutputKind::Trace => Output::stream(flag, path),
            OutputKind::Plot | OutputKind::Table => Output::file(flag, path),
        }
    }
}
