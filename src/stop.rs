//! Stopping a run cleanly when asked: Ctrl-C everywhere; SIGTERM and SIGHUP on Unix;
//! Ctrl-Break and closing the console window on Windows.
//!
//! The handler only notes which request came; the run looks at the note once a frame and
//! returns, and returning drops its temporary files. So a stopped run leaves no temporary
//! file and every earlier output as it was.

use std::io;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

/// A request that stopped a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Signal {
    /// The signal's number (Unix) or the console event's (Windows).
    pub number: i32,
    pub name: &'static str,
    /// The process's exit code: the shell's 128 + the signal's number on Unix, and the same
    /// codes for the same requests on Windows (Ctrl-C 130, like SIGINT).
    exit_code: u8,
}

impl Signal {
    /// The exit code of a run stopped by this request.
    pub(crate) fn exit_code(&self) -> u8 {
        self.exit_code
    }
}

/// A note that a run should stop, shared with the handler. The default never fires (for the
/// library and tests, which install no handler).
#[derive(Clone, Debug, Default)]
pub struct Stop {
    /// One more than the index in [`STOPPING`] of the request that came, or 0.
    request: Arc<AtomicUsize>,
}

impl Stop {
    /// Watches for the stop signals (Ctrl-C; on Unix also SIGTERM and SIGHUP): each one
    /// is noted here instead of ending the process at once.
    pub(crate) fn on_signals() -> io::Result<Stop> {
        let stop = Stop::default();
        platform::watch(&stop.request)?;
        Ok(stop)
    }

    /// The request that came, if one did.
    pub(crate) fn requested(&self) -> Option<Signal> {
        let noted = self.request.load(Ordering::Relaxed);
        noted.checked_sub(1).and_then(|k| STOPPING.get(k)).copied()
    }
}

const fn signal(number: i32, name: &'static str, exit_code: u8) -> Signal {
    Signal {
        number,
        name,
        exit_code,
    }
}

/// The requests that stop a run.
#[cfg(unix)]
const STOPPING: [Signal; 3] = [
    signal(signal_hook::consts::SIGINT, "SIGINT", 130),
    signal(signal_hook::consts::SIGTERM, "SIGTERM", 143),
    signal(signal_hook::consts::SIGHUP, "SIGHUP", 129),
];

/// The requests that stop a run: the console's control events.
#[cfg(windows)]
const STOPPING: [Signal; 3] = [
    signal(0, "Ctrl-C", 130),        // CTRL_C_EVENT
    signal(1, "Ctrl-Break", 131),    // CTRL_BREAK_EVENT
    signal(2, "console close", 129), // CTRL_CLOSE_EVENT, like SIGHUP
];

#[cfg(unix)]
mod platform {
    use super::STOPPING;
    use std::io;
    use std::sync::atomic::AtomicUsize;
    use std::sync::Arc;

    /// signal-hook's handler stores the value: the one thing a signal handler may safely do.
    pub(crate) fn watch(request: &Arc<AtomicUsize>) -> io::Result<()> {
        for (k, signal) in STOPPING.iter().enumerate() {
            signal_hook::flag::register_usize(signal.number, Arc::clone(request), k + 1)?;
        }
        Ok(())
    }
}

#[cfg(windows)]
mod platform {
    use super::STOPPING;
    use std::io;
    use std::sync::atomic::{AtomicUsize, Ordering};
    use std::sync::{Arc, OnceLock};
    use windows_sys::core::BOOL;
    use windows_sys::Win32::System::Console::{SetConsoleCtrlHandler, CTRL_CLOSE_EVENT};

    /// Where the handler notes the request: it is a plain function, with no state of its own.
    static REQUEST: OnceLock<Arc<AtomicUsize>> = OnceLock::new();

    /// Windows calls the handler on a thread of its own. For Ctrl-C and Ctrl-Break, returning
    /// TRUE keeps the process alive until the run notices. For a closed console the process
    /// ends as soon as the handler returns, so the handler waits (Windows allows about five
    /// seconds) while the run removes its temporary files and exits.
    unsafe extern "system" fn handler(event: u32) -> BOOL {
        let Some(k) = STOPPING.iter().position(|s| s.number as u32 == event) else {
            return 0; // not ours: the next handler (the default ends the process)
        };
        if let Some(request) = REQUEST.get() {
            request.store(k + 1, Ordering::Relaxed);
        }
        if event == CTRL_CLOSE_EVENT {
            std::thread::sleep(std::time::Duration::from_millis(4500));
        }
        1
    }

    pub(crate) fn watch(request: &Arc<AtomicUsize>) -> io::Result<()> {
        if REQUEST.set(Arc::clone(request)).is_err() {
            return Err(io::Error::other("the Ctrl-C handler is already installed"));
        }
        // SAFETY: `handler` is a valid handler routine for the life of the process.
        if unsafe { SetConsoleCtrlHandler(Some(handler), 1) } == 0 {
            return Err(io::Error::last_os_error());
        }
        Ok(())
    }
}
