//! The real binary run as a hostile user would run it: in a temporary folder, with a cap on
//! its memory (RLIMIT_AS) and its time (SIGTERM at the cap, SIGKILL if that is ignored), and
//! a snapshot of the folder before and after to prove what it created or changed.

use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::os::unix::fs::FileTypeExt;
use std::os::unix::process::{CommandExt, ExitStatusExt};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// How a capped run ended.
#[derive(Debug)]
pub struct Finished {
    pub status: ExitStatus,
    pub stdout: Vec<u8>,
    pub stderr: String,
    /// Whether the time cap was reached and SIGTERM sent.
    pub capped: bool,
    pub elapsed: Duration,
}

impl Finished {
    pub fn code(&self) -> Option<i32> {
        self.status.code()
    }

    /// The signal that ended the process, if one did (a crash: it handles the ones we send).
    pub fn signal(&self) -> Option<i32> {
        self.status.signal()
    }

    /// The lines on stderr that are not warnings.
    pub fn error_lines(&self) -> Vec<&str> {
        self.stderr
            .lines()
            .filter(|l| !l.starts_with("warning: "))
            .collect()
    }
}

/// The limits a run is held to.
#[derive(Clone, Copy, Debug)]
pub struct Caps {
    /// Address space, bytes.
    pub memory: u64,
    /// After this, SIGTERM.
    pub time: Duration,
    /// After SIGTERM, this long to stop before SIGKILL.
    pub grace: Duration,
}

impl Default for Caps {
    fn default() -> Self {
        Caps {
            memory: 3 << 30,
            time: Duration::from_secs(20),
            grace: Duration::from_secs(20),
        }
    }
}

/// Starts the binary in `dir` with `args`, standard input from `stdin`, under `caps.memory`.
pub fn spawn(dir: &Path, args: &[String], memory: u64) -> Child {
    let mut command = Command::new(env!("CARGO_BIN_EXE_bouncing_ball"));
    command
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // SAFETY: only async-signal-safe setrlimit between fork and exec.
    unsafe {
        command.pre_exec(move || {
            let limit = libc::rlimit {
                rlim_cur: memory,
                rlim_max: memory,
            };
            if libc::setrlimit(libc::RLIMIT_AS, &limit) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            Ok(())
        });
    }
    command.spawn().expect("the binary starts")
}

/// Sends `signal` to a child.
pub fn send(child: &Child, signal: i32) {
    // SAFETY: kill on a pid we own that has not been waited for.
    unsafe {
        libc::kill(child.id() as libc::pid_t, signal);
    }
}

/// Runs the binary to the end or the cap, feeding it `stdin`.
pub fn run_capped(dir: &Path, args: &[String], stdin: &[u8], caps: Caps) -> Finished {
    let started = Instant::now();
    let mut child = spawn(dir, args, caps.memory);
    let mut input = child.stdin.take().expect("stdin");
    let stdin = stdin.to_vec();
    let feeder = std::thread::spawn(move || {
        let _ = input.write_all(&stdin); // it may not read it all
    });
    let mut out = child.stdout.take().expect("stdout");
    let mut err = child.stderr.take().expect("stderr");
    let stdout = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        let _ = out.read_to_end(&mut bytes);
        bytes
    });
    let stderr = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        let _ = err.read_to_end(&mut bytes);
        bytes
    });
    let mut capped = false;
    let status = loop {
        if let Some(status) = child.try_wait().expect("wait") {
            break status;
        }
        let elapsed = started.elapsed();
        if !capped && elapsed > caps.time {
            send(&child, libc::SIGTERM);
            capped = true;
        }
        if elapsed > caps.time + caps.grace {
            let _ = child.kill();
            break child.wait().expect("wait");
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let _ = feeder.join();
    Finished {
        status,
        stdout: stdout.join().unwrap_or_default(),
        stderr: String::from_utf8_lossy(&stderr.join().unwrap_or_default()).into_owned(),
        capped,
        elapsed: started.elapsed(),
    }
}

/// Strings from `&str`s, for argument lists.
pub fn args(list: &[&str]) -> Vec<String> {
    list.iter().map(|s| s.to_string()).collect()
}

/// A folder's contents by relative path.
pub type Snapshot = BTreeMap<PathBuf, Entry>;

/// What sits at a path, compared before and after a run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Entry {
    File(Vec<u8>),
    Folder,
    Link(PathBuf),
    Fifo,
    Socket,
}

/// Everything under `dir`, by path relative to it (links are not followed).
pub fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Entry> {
    let mut all = BTreeMap::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(folder) = todo.pop() {
        for entry in std::fs::read_dir(&folder).expect("read the folder") {
            let path = entry.expect("an entry").path();
            let kind = std::fs::symlink_metadata(&path)
                .expect("metadata")
                .file_type();
            let what = if kind.is_symlink() {
                Entry::Link(std::fs::read_link(&path).expect("a link"))
            } else if kind.is_dir() {
                todo.push(path.clone());
                Entry::Folder
            } else if kind.is_fifo() {
                Entry::Fifo
            } else if kind.is_socket() {
                Entry::Socket
            } else {
                Entry::File(std::fs::read(&path).expect("read a file"))
            };
            all.insert(path.strip_prefix(dir).unwrap().to_path_buf(), what);
        }
    }
    all
}

/// The paths that differ between two snapshots (created, removed or changed).
pub fn changes(
    before: &BTreeMap<PathBuf, Entry>,
    after: &BTreeMap<PathBuf, Entry>,
) -> Vec<PathBuf> {
    let mut changed: Vec<PathBuf> = after
        .iter()
        .filter(|(path, entry)| before.get(*path) != Some(entry))
        .map(|(path, _)| path.clone())
        .collect();
    changed.extend(before.keys().filter(|p| !after.contains_key(*p)).cloned());
    changed
}
