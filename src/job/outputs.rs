//! A job's outputs: what each is ([`Role`], which fixes its flag and what path it may take)
//! and where it goes ([`Target`]).

use std::path::PathBuf;

use crate::output::Output;

/// What an output is, which fixes its flag and what it may be: a picture whose format the
/// flag fixes, a stream that may go to standard output, or a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    Gif,
    Png,
    Trace,
    Plot,
    Table,
    /// `check --diff`: expected | theirs | difference.
    Diff,
}

impl Role {
    /// The flag that names this output.
    pub fn flag(self) -> &'static str {
        match self {
            Role::Gif => "--gif",
            Role::Png => "--png",
            Role::Trace => "--trace",
            Role::Plot => "--plot",
            Role::Table => "--table",
            Role::Diff => "--diff",
        }
    }
}

/// One output of a job: what it is and where it goes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Target {
    pub role: Role,
    pub path: PathBuf,
}

impl Target {
    /// This output as [`crate::output::check`] judges it.
    pub fn output(&self) -> Output<'_> {
        let (flag, path) = (self.role.flag(), self.path.as_path());
        match self.role {
            Role::Gif => Output::picture(flag, path, "gif"),
            Role::Png | Role::Diff => Output::picture(flag, path, "png"),
            Role::Trace => Output::stream(flag, path),
            Role::Plot | Role::Table => Output::file(flag, path),
        }
    }
}
