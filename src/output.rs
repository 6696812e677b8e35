//! Output files that appear whole or not at all, and only where a file belongs.
//!
//! Three steps: [`check`] refuses, before any work, a path no output should take (a folder, a
//! device, a pipe, the scene file, a path another output also names); [`AtomicFile`] writes
//! each output to a temporary file beside its target; [`commit_all`] renames them into place
//! only once every one is written and flushed. `-` means standard output where an output
//! allows it: that stream is written as the run goes, and cannot be taken back.

use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

use tempfile::NamedTempFile;

/// The path that means standard output.
pub(crate) const STDOUT: &str = "-";

/// Whether `path` is `-`, standard output.
pub(crate) fn is_stdout(path: &Path) -> bool {
    path.as_os_str() == STDOUT
}

/// One output a run writes: the flag that names it, the path, whether `-` may stand for
/// standard output (a stream can go there; a GIF or PNG on a terminal would be garbage), and
/// the picture format it writes, if it writes one.
#[derive(Clone, Copy, Debug)]
pub struct Output<'a> {
    pub flag: &'static str,
    pub path: &'a Path,
    pub may_be_stdout: bool,
    pub format: Option<&'static str>,
}

/// The picture formats the program writes, by extension: a path that ends in one of them gets
/// that format, so `--gif a.png` is a mistake (GIF bytes in a file every viewer opens as PNG).
const PICTURE_FORMATS: [&str; 3] = ["gif", "png", "svg"];

impl Output<'_> {
    /// A file output whose format the flag fixes (`--gif`, `--png`): `-` is refused, and so is
    /// a name ending in another picture format's extension.
    pub(crate) fn picture<'a>(
        flag: &'static str,
        path: &'a Path,
        format: &'static str,
    ) -> Output<'a> {
        Output {
            format: Some(format),
            ..Output::file(flag, path)
        }
    }

    /// A file output (`--plot`, whose extension picks its format): `-` is refused.
    pub fn file<'a>(flag: &'static str, path: &'a Path) -> Output<'a> {
        Output {
            flag,
            path,
            may_be_stdout: false,
            format: None,
        }
    }

    /// A stream output (the trace): `-` is standard output.
    pub(crate) fn stream<'a>(flag: &'static str, path: &'a Path) -> Output<'a> {
        Output {
            may_be_stdout: true,
            ..Output::file(flag, path)
        }
    }

    /// Why the path's extension names another picture format than this output writes, if it
    /// does (`--gif a.png`).
    fn wrong_format(&self) -> Option<String> {
        let format = self.format?;
        let extension = self.path.extension()?.to_str()?.to_ascii_lowercase();
        if extension == format || !PICTURE_FORMATS.contains(&extension.as_str()) {
            return None;
        }
        Some(format!(
            "ends in .{extension}, but {} writes a {}; give a name ending in .{format}",
            self.flag,
            format.to_uppercase()
        ))
    }
}

/// A file that cannot be written, and why (exit 1: the input was fine, the disk was not).
#[derive(Debug, thiserror::Error)]
#[error("cannot write {}: {source}", path.display())]
pub struct OutputError {
    pub path: PathBuf,
    #[source]
    pub source: io::Error,
}

impl OutputError {
    /// Ties an I/O failure to the file it was for.
    pub(crate) fn at(path: &Path) -> impl Fn(io::Error) -> OutputError + '_ {
        move |source| OutputError {
            path: path.to_path_buf(),
            source,
        }
    }
}

/// An output path refused before any work (exit 2: the command line asked for something wrong).
#[derive(Debug, thiserror::Error)]
#[error("{flag} {}: {why}", path.display())]
pub struct OutputRefused {
    pub flag: &'static str,
    pub path: PathBuf,
    pub why: String,
}

/// Where a path's bytes would land, to tell two names for one file apart from two files.
#[derive(Debug, PartialEq, Eq)]
enum Identity {
    /// An existing file (links followed), as the system identifies it (device and inode on
    /// Unix, volume and file index on Windows), so hard links match too.
    Existing(same_file::Handle),
    /// A file still to be made: its folder's real path and its name.
    New(PathBuf),
    /// A file in a folder that does not exist; making its temporary file will say so.
    Unknown,
}

fn identity(path: &Path) -> Identity {
    if let Ok(handle) = same_file::Handle::from_path(path) {
        return Identity::Existing(handle);
    }
    let folder = folder_of(path);
    match (fs::canonicalize(folder), path.file_name()) {
        (Ok(real), Some(name)) => Identity::New(real.join(name)),
        _ => Identity::Unknown,
    }
}

/// The folder a path's file sits in (`.` for a bare name).
fn folder_of(path: &Path) -> &Path {
    match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    }
}

/// What is wrong with writing a file at `path` whatever else the run writes, if anything.
fn unusable(path: &Path, may_be_stdout: bool) -> Option<String> {
    if is_stdout(path) {
        return (!may_be_stdout)
            .then(|| "standard output (-) is only for --trace; give a file name".to_string());
    }
    if path.as_os_str().is_empty() {
        return Some("is empty; give a file name".to_string());
    }
    let last = path.as_os_str().as_encoded_bytes().last().copied();
    if last.is_some_and(|byte| std::path::is_separator(char::from(byte)))
        || path.file_name().is_none()
    {
        return Some("names a folder, not a file; give a file name".to_string());
    }
    if cfg!(windows) && path.file_name().is_some_and(is_reserved_on_windows) {
        return Some(
            "is a device name on Windows (CON, PRN, AUX, NUL, COM1-9, LPT1-9, with any \
             extension); an output must be a regular file or a new name"
                .to_string(),
        );
    }
    let Ok(link) = fs::symlink_metadata(path) else {
        return None; // a new file
    };
    let Ok(meta) = fs::metadata(path) else {
        return link
            .file_type()
            .is_symlink()
            .then(|| "is a symbolic link to nothing; remove it or give another name".to_string());
    };
    let kind = meta.file_type();
    let what = if kind.is_file() {
        return None;
    } else if kind.is_dir() {
        "a folder"
    } else {
        special_file(&kind)
    };
    let hint = if may_be_stdout && !kind.is_dir() {
        " (for standard output, give -)"
    } else {
        ""
    };
    Some(format!(
        "is {what}; an output must be a regular file or a new name{hint}"
    ))
}

/// What a file that is neither a regular file nor a folder is, in words.
#[cfg(unix)]
fn special_file(kind: &fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if kind.is_fifo() {
        "a named pipe (FIFO)"
    } else if kind.is_socket() {
        "a socket"
    } else if kind.is_char_device() || kind.is_block_device() {
        "a device"
    } else {
        "not a regular file"
    }
}

/// What a file that is neither a regular file nor a folder is, in words.
#[cfg(not(unix))]
fn special_file(_kind: &fs::FileType) -> &'static str {
    "not a regular file"
}

/// Whether a file name is one Windows keeps for a device in every folder: `CON`, `PRN`, `AUX`,
/// `NUL`, `COM1`-`COM9`, `LPT1`-`LPT9` (and the superscript ¹²³ forms), in any case, with any
/// extension and trailing dots or spaces. Writing `nul.gif` there writes to no file at all.
pub(crate) fn is_reserved_on_windows(name: &std::ffi::OsStr) -> bool {
    let name = name.to_string_lossy();
    let stem = name.split('.').next().unwrap_or_default();
    let stem = stem.trim_end_matches([' ', '.']).to_ascii_uppercase();
    let port = |prefix| {
        stem.strip_prefix(prefix).is_some_and(|digit| {
            matches!(
                digit,
                "1" | "2" | "3" | "4" | "5" | "6" | "7" | "8" | "9" | "¹" | "²" | "³"
            )
        })
    };
    matches!(stem.as_str(), "CON" | "PRN" | "AUX" | "NUL") || port("COM") || port("LPT")
}

/// Refuses, before any work, outputs that would replace something that is not a regular
/// file, two outputs naming the same file, and an output naming `scene_file`.
pub fn check(outputs: &[Output], scene_file: Option<&Path>) -> Result<(), OutputRefused> {
    let refuse = |output: &Output, why: String| OutputRefused {
        flag: output.flag,
        path: output.path.to_path_buf(),
        why,
    };
    for output in outputs {
        let why = unusable(output.path, output.may_be_stdout).or_else(|| output.wrong_format());
        if let Some(why) = why {
            return Err(refuse(output, why));
        }
    }
    let files: Vec<(&Output, Identity)> = outputs
        .iter()
        .filter(|o| !is_stdout(o.path))
        .map(|o| (o, identity(o.path)))
        .collect();
    let scene = scene_file
        .filter(|p| !is_stdout(p))
        .map(|p| (p, identity(p)));
    for (k, (output, id)) in files.iter().enumerate() {
        if *id == Identity::Unknown {
            continue;
        }
        if let Some((scene_path, _)) = scene.as_ref().filter(|(_, s)| s == id) {
            let why = format!("is the scene file ({}) being read", scene_path.display());
            return Err(refuse(output, why));
        }
        if let Some((first, _)) = files[..k].iter().find(|(_, other)| other == id) {
            let why = format!(
                "is the same file as {} {}",
                first.flag,
                first.path.display()
            );
            return Err(refuse(output, why));
        }
    }
    Ok(())
}

/// A file being written; dropped without being committed, it vanishes and the target is
/// untouched.
pub struct AtomicFile {
    temp: NamedTempFile,
    /// Where the file goes: the path, or the file a symbolic link there points to, so the
    /// link survives and its target is replaced.
    target: PathBuf,
    /// The path as given, for messages.
    path: PathBuf,
    /// The permissions of the file it replaces, if it replaces one.
    mode: Option<fs::Permissions>,
}

impl AtomicFile {
    /// Starts writing `path` (the temporary file sits in the same folder as the target, so
    /// the final rename never crosses file systems).
    pub fn create(path: &Path) -> Result<AtomicFile, OutputError> {
        let is_link = fs::symlink_metadata(path).is_ok_and(|m| m.file_type().is_symlink());
        let target = if is_link {
            fs::canonicalize(path).map_err(OutputError::at(path))?
        } else {
            path.to_path_buf()
        };
        let folder = folder_of(&target);
        if !folder.is_dir() {
            let missing = io::Error::new(
                io::ErrorKind::NotFound,
                format!("there is no folder {}", folder.display()),
            );
            return Err(OutputError::at(path)(missing));
        }
        // A file being replaced keeps its mode; one its owner may not write is left alone.
        let mode = match fs::metadata(&target) {
            Ok(meta) if read_only(&meta) => {
                let why = "it is read-only (make it writable to replace it, or give another name)";
                let denied = io::Error::new(io::ErrorKind::PermissionDenied, why);
                return Err(OutputError::at(path)(denied));
            }
            Ok(meta) => Some(meta.permissions()),
            Err(_) => None,
        };
        let name = target.file_name().unwrap_or_default().to_string_lossy();
        let temp = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .suffix(".tmp")
            .tempfile_in(folder)
            .map_err(|error| OutputError::at(path)(cannot_create_in(folder, error)))?;
        Ok(AtomicFile {
            temp,
            target,
            path: path.to_path_buf(),
            mode,
        })
    }

    /// Where the bytes go until the commit (`&File` writes, as `File` does).
    pub fn file(&self) -> &File {
        self.temp.as_file()
    }

    /// Makes the written bytes durable and readable like any file we write; returns the size.
    fn finish(&self) -> Result<u64, OutputError> {
        let at = || OutputError::at(&self.path);
        let file = self.temp.as_file();
        file.sync_all().map_err(at())?;
        match &self.mode {
            Some(mode) => file.set_permissions(mode.clone()).map_err(at())?,
            None => readable_by_all(file).map_err(at())?,
        }
        Ok(file.metadata().map_err(at())?.len())
    }

    fn rename_into_place(self) -> Result<(), OutputError> {
        let at = OutputError::at(&self.path);
        self.temp
            .persist(&self.target)
            .map_err(|e| at(explain_rename(e.error)))?;
        Ok(())
    }
}

/// Why no file can be made in `folder`, in the user's terms: the system's own error names
/// the hidden temporary file, which the user never asked for.
fn cannot_create_in(folder: &Path, error: io::Error) -> io::Error {
    let text = error.to_string();
    let system = text
        .rsplit_once(" at path ")
        .map_or(text.as_str(), |(said, _)| said);
    let folder = folder.display();
    let why = match error.kind() {
        io::ErrorKind::PermissionDenied => {
            format!("permission denied (this user may not make files in {folder})")
        }
        io::ErrorKind::NotFound => format!("{folder} takes no new files ({system})"),
        _ => system.to_string(),
    };
    io::Error::new(error.kind(), why)
}

/// Whether the owner may not write this file: the write bit clear on Unix (root too, who
/// could write it anyway, is refused: the file says it should not change), the read-only
/// attribute on Windows.
#[cfg(unix)]
fn read_only(meta: &fs::Metadata) -> bool {
    use std::os::unix::fs::PermissionsExt;
    meta.permissions().mode() & 0o200 == 0
}

#[cfg(not(unix))]
fn read_only(meta: &fs::Metadata) -> bool {
    meta.permissions().readonly()
}

/// Temporary files are private (0600 on Unix); a new output should read like any file we
/// write.
#[cfg(unix)]
fn readable_by_all(file: &File) -> io::Result<()> {
    use std::os::unix::fs::PermissionsExt;
    file.set_permissions(fs::Permissions::from_mode(0o644))
}

/// On Windows a new file takes its folder's permissions, as any file written there does.
#[cfg(not(unix))]
fn readable_by_all(_file: &File) -> io::Result<()> {
    Ok(())
}

/// On Windows a file another program holds open (an image viewer showing the last GIF) cannot
/// be replaced, and the system only says "access is denied": say what to do about it.
fn explain_rename(error: io::Error) -> io::Error {
    if cfg!(windows) && error.kind() == io::ErrorKind::PermissionDenied {
        let why =
            "it is open in another program (close it and run again); the old file is as it was";
        return io::Error::new(error.kind(), why);
    }
    error
}

/// Puts every finished file in place and returns their sizes, in order. Nothing is renamed
/// until every file is flushed to disk, so a failure up to then leaves every target as it
/// was; only a failing rename itself can leave the earlier ones replaced and the later not.
pub fn commit_all(files: Vec<AtomicFile>) -> Result<Vec<u64>, OutputError> {
    // Flushing a file waits on the disk; flushing them all at once waits about once.
    let sizes = std::thread::scope(|scope| {
        let flushes: Vec<_> = files
            .iter()
            .map(|file| scope.spawn(|| file.finish()))
            .collect();
        flushes
            .into_iter()
            .map(|flush| flush.join().expect("flushing a file does not panic"))
            .collect::<Result<Vec<_>, _>>()
    })?;
    for file in files {
        file.rename_into_place()?;
    }
    Ok(sizes)
}

/// Standard output for a stream such as the trace. Once its reader has gone (`| head`),
/// it falls silent instead of failing, as Unix filters do, and the run carries on.
pub(crate) struct StdoutStream {
    out: io::Stdout,
    closed: bool,
}

impl StdoutStream {
    pub(crate) fn new() -> StdoutStream {
        StdoutStream {
            out: io::stdout(),
            closed: false,
        }
    }

    fn unless_closed(&mut self, result: io::Result<usize>, len: usize) -> io::Result<usize> {
        match result {
            Err(e) if e.kind() == io::ErrorKind::BrokenPipe => {
                self.closed = true;
                Ok(len)
            }
            other => other,
        }
    }
}

impl Default for StdoutStream {
    fn default() -> Self {
        StdoutStream::new()
    }
}

impl Write for StdoutStream {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        if self.closed {
            return Ok(buf.len());
        }
        let result = self.out.write(buf);
        self.unless_closed(result, buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        if self.closed {
            return Ok(());
        }
        let result = self.out.flush().map(|()| 0);
        self.unless_closed(result, 0).map(|_| ())
    }
}

#[cfg(test)]
mod tests {
    use super::is_reserved_on_windows;
    use std::ffi::OsStr;

    #[test]
    fn windows_device_names_are_known_in_any_case_and_with_any_extension() {
        for name in [
            "NUL",
            "con.png",
            "Aux.tar.gz",
            "COM9 .gif",
            "lpt1",
            "com³.gif",
            "prn.",
        ] {
            assert!(is_reserved_on_windows(OsStr::new(name)), "{name}");
        }
        for name in [
            "null.gif",
            "com0.gif",
            "COM10",
            "console.png",
            "éé.gif",
            "ünï.png",
            "Ⅽ",
        ] {
            assert!(!is_reserved_on_windows(OsStr::new(name)), "{name}");
        }
    }
}
