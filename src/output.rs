//! Output files that appear whole or not at all: written to a temporary file beside the
//! target, renamed over it only when complete.

use std::fs::File;
use std::io;
use std::path::{Path, PathBuf};

use tempfile::NamedTempFile;

/// A file that cannot be written, and why.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {}: {source}", path.display())]
pub struct OutputError {
    pub path: PathBuf,
    #[source]
    pub source: io::Error,
}

impl OutputError {
    /// Ties an I/O failure to the file it was for.
    pub fn at(path: &Path) -> impl Fn(io::Error) -> OutputError + '_ {
        move |source| OutputError {
            path: path.to_path_buf(),
            source,
        }
    }
}

/// A file being written; dropped without `commit`, it vanishes and the target is untouched.
pub struct AtomicFile {
    temp: NamedTempFile,
    path: PathBuf,
}

impl AtomicFile {
    /// Starts writing `path` (the temporary file sits in the same folder, so the final
    /// rename never crosses file systems).
    pub fn create(path: &Path) -> Result<AtomicFile, OutputError> {
        let folder = match path.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        let name = path.file_name().unwrap_or_default().to_string_lossy();
        let temp = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .suffix(".tmp")
            .tempfile_in(folder)
            .map_err(OutputError::at(path))?;
        Ok(AtomicFile {
            temp,
            path: path.to_path_buf(),
        })
    }

    /// Where the bytes go until `commit`.
    pub fn file(&mut self) -> &mut File {
        self.temp.as_file_mut()
    }

    /// Puts the finished file in place and returns its size in bytes.
    pub fn commit(self) -> Result<u64, OutputError> {
        let at = || OutputError::at(&self.path);
        self.temp.as_file().sync_all().map_err(at())?;
        let bytes = self.temp.as_file().metadata().map_err(at())?.len();
        // Temporary files are private (0600); outputs should read like any file we write.
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let public = std::fs::Permissions::from_mode(0o644);
            self.temp.as_file().set_permissions(public).map_err(at())?;
        }
        self.temp.persist(&self.path).map_err(|e| at()(e.error))?;
        Ok(bytes)
    }
}
