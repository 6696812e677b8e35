//! The real binary run as a hostile user would run it: in a temporary folder, with a cap on
//! its memory (RLIMIT_AS, on Unix) and its time (a polite stop at the cap: SIGTERM on Unix,
//! Ctrl-Break on Windows; killed if that is ignored), and a snapshot of the folder before and
//! after to prove what it created or changed.

use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::time::{Duration, Instant};

/// How a capped run ended.
#[derive(Debug)]
pub struct Finished {
    pub status: ExitStatus,
    pub stdout: Vec<u8>,
    pub stderr: String,
    /// Whether the time cap was reached and [`Request::Terminate`] sent.
    pub capped: bool,
    pub elapsed: Duration,
}

impl Finished {
    pub fn code(&self) -> Option<i32> {
        self.status.code()
    }

    /// The signal that ended the process, if one did (a crash: it handles the ones we send).
    #[cfg(unix)]
    pub fn signal(&self) -> Option<i32> {
        std::os::unix::process::ExitStatusExt::signal(&self.status)
    }

    /// Windows has no signals: a crash is an exit code (an NTSTATUS such as 0xC0000005).
    #[cfg(windows)]
    pub fn signal(&self) -> Option<i32> {
        None
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
    /// After this, [`Request::Terminate`].
    pub time: Duration,
    /// After that, this long to stop before it is killed.
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
    cap_memory(&mut command, memory);
    command.spawn().expect("the binary starts")
}

#[cfg(unix)]
fn cap_memory(command: &mut Command, memory: u64) {
    use std::os::unix::process::CommandExt;
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
}

/// Windows has no per-process address-space limit a test can set before the start (a job
/// object would need the process running); the program's own memory budget still applies.
#[cfg(windows)]
fn cap_memory(_command: &mut Command, _memory: u64) {}

/// The polite ways to ask a run to stop, each with the name the program gives it and the exit
/// code it then ends with.
#[derive(Clone, Copy, Debug)]
pub enum Request {
    /// Ctrl-C: SIGINT, or the console's Ctrl-C event.
    Interrupt,
    /// SIGTERM, or on Windows Ctrl-Break.
    Terminate,
    /// SIGHUP (the terminal went away), or on Windows the console window closed.
    Hangup,
}

impl Request {
    /// The name in the program's message and its exit code.
    #[cfg(unix)]
    pub fn expected(self) -> (&'static str, i32) {
        match self {
            Request::Interrupt => ("SIGINT", 130),
            Request::Terminate => ("SIGTERM", 143),
            Request::Hangup => ("SIGHUP", 129),
        }
    }

    /// The name in the program's message and its exit code.
    #[cfg(windows)]
    pub fn expected(self) -> (&'static str, i32) {
        match self {
            Request::Interrupt => ("Ctrl-C", 130),
            Request::Terminate => ("Ctrl-Break", 131),
            Request::Hangup => ("console close", 129),
        }
    }
}

/// Sends `request` to a child, as the terminal or `kill` would.
#[cfg(unix)]
pub fn send(child: &Child, request: Request) {
    let signal = match request {
        Request::Interrupt => libc::SIGINT,
        Request::Terminate => libc::SIGTERM,
        Request::Hangup => libc::SIGHUP,
    };
    // SAFETY: kill on a pid we own that has not been waited for.
    unsafe {
        libc::kill(child.id() as libc::pid_t, signal);
    }
}

/// Sends `request` to a child as the console does: a new thread in the child that runs
/// kernel32's `CtrlRoutine` with the event, which calls the process's handlers. (The tests
/// run without a console, where `GenerateConsoleCtrlEvent` has nothing to send through;
/// kernel32 sits at the same address in every process of a boot, so its address here is the
/// child's.)
#[cfg(windows)]
pub fn send(child: &Child, request: Request) {
    use std::os::windows::io::AsRawHandle;
    use windows_sys::Win32::Foundation::WAIT_OBJECT_0;
    use windows_sys::Win32::System::LibraryLoader::{GetModuleHandleA, GetProcAddress};
    use windows_sys::Win32::System::Threading::{
        CreateRemoteThread, WaitForSingleObject, LPTHREAD_START_ROUTINE,
    };
    let event: usize = match request {
        Request::Interrupt => 0, // CTRL_C_EVENT
        Request::Terminate => 1, // CTRL_BREAK_EVENT
        Request::Hangup => 2,    // CTRL_CLOSE_EVENT
    };
    // SAFETY: CtrlRoutine has the signature of a thread routine, takes the event as its
    // argument, and the child is ours and has not been waited for.
    unsafe {
        let kernel32 = GetModuleHandleA(c"kernel32.dll".as_ptr().cast());
        let routine = GetProcAddress(kernel32, c"CtrlRoutine".as_ptr().cast());
        assert!(routine.is_some(), "kernel32 has CtrlRoutine");
        let start: LPTHREAD_START_ROUTINE = std::mem::transmute(routine);
        let thread = CreateRemoteThread(
            child.as_raw_handle(),
            std::ptr::null(),
            0,
            start,
            event as *const std::ffi::c_void,
            0,
            std::ptr::null_mut(),
        );
        if thread.is_null() {
            // A child that has ended by itself can no longer take a thread (Wine says access
            // denied); the request is moot then, as `kill` on an ended child is on Unix.
            let error = std::io::Error::last_os_error();
            let ended = WaitForSingleObject(child.as_raw_handle(), 0) == WAIT_OBJECT_0;
            assert!(ended, "{error}");
            return;
        }
        windows_sys::Win32::Foundation::CloseHandle(thread);
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
            send(&child, Request::Terminate);
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
            } else if is_fifo(&kind) {
                Entry::Fifo
            } else if is_socket(&kind) {
                Entry::Socket
            } else {
                Entry::File(std::fs::read(&path).expect("read a file"))
            };
            all.insert(path.strip_prefix(dir).unwrap().to_path_buf(), what);
        }
    }
    all
}

#[cfg(unix)]
fn is_fifo(kind: &std::fs::FileType) -> bool {
    std::os::unix::fs::FileTypeExt::is_fifo(kind)
}

#[cfg(unix)]
fn is_socket(kind: &std::fs::FileType) -> bool {
    std::os::unix::fs::FileTypeExt::is_socket(kind)
}

#[cfg(windows)]
fn is_fifo(_kind: &std::fs::FileType) -> bool {
    false
}

#[cfg(windows)]
fn is_socket(_kind: &std::fs::FileType) -> bool {
    false
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

/// A temporary folder holding things an output must not replace: earlier outputs
/// (`previous.gif`, `previous.png`), a scene file (`my.toml`, and `hard-link.toml` to it), a
/// folder, and on Unix a FIFO, a socket, links to each (`link-to-NAME`) and a broken link.
pub struct OddFolder {
    pub dir: tempfile::TempDir,
    #[cfg(unix)]
    _socket: std::os::unix::net::UnixListener,
}

impl OddFolder {
    pub fn new() -> OddFolder {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path();
        std::fs::write(p.join("previous.gif"), b"previous good gif").unwrap();
        std::fs::write(p.join("previous.png"), b"previous good png").unwrap();
        let lesson = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/lesson.toml");
        std::fs::copy(lesson, p.join("my.toml")).unwrap();
        std::fs::hard_link(p.join("my.toml"), p.join("hard-link.toml")).unwrap();
        std::fs::create_dir(p.join("folder")).unwrap();
        OddFolder {
            #[cfg(unix)]
            _socket: unix_odd_files(p),
            dir,
        }
    }

    pub fn path(&self) -> &Path {
        self.dir.path()
    }
}

/// The FIFO, socket and links of an [`OddFolder`]; the socket lives as long as the listener.
#[cfg(unix)]
fn unix_odd_files(p: &Path) -> std::os::unix::net::UnixListener {
    let fifo = std::ffi::CString::new(p.join("fifo").as_os_str().as_encoded_bytes()).unwrap();
    // SAFETY: a valid C string naming a new path in our temporary folder.
    assert_eq!(unsafe { libc::mkfifo(fifo.as_ptr(), 0o644) }, 0, "mkfifo");
    let socket = std::os::unix::net::UnixListener::bind(p.join("socket")).unwrap();
    for target in ["fifo", "folder", "socket", "previous.gif", "my.toml"] {
        std::os::unix::fs::symlink(target, p.join(format!("link-to-{target}"))).unwrap();
    }
    std::os::unix::fs::symlink("nothing", p.join("broken-link")).unwrap();
    socket
}
