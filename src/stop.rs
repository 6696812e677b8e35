//! Stopping a run cleanly on SIGINT (Ctrl-C), SIGTERM or SIGHUP.
//!
//! The signal handler only notes which signal came (signal-hook does that safely); the run
//! looks at the note once a frame and returns, and returning drops its temporary files. So a
//! stopped run leaves no temporary file and every earlier output as it was.

use std::io;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};

/// The signals that stop a run, with their names.
const STOPPING: [(i32, &str); 3] = [(SIGINT, "SIGINT"), (SIGTERM, "SIGTERM"), (SIGHUP, "SIGHUP")];

/// A note that a run should stop, shared with the signal handlers. The default never fires
/// (for the library and tests, which install no handlers).
#[derive(Clone, Debug, Default)]
pub struct Stop {
    /// The signal number that came, or 0.
    signal: Arc<AtomicUsize>,
}

/// A signal that stopped a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Signal {
    pub number: i32,
    pub name: &'static str,
}

impl Signal {
    /// The shell's convention for a process ended by a signal: 128 + its number.
    pub fn exit_code(&self) -> u8 {
        (128 + self.number) as u8
    }
}

impl Stop {
    /// A note that SIGINT, SIGTERM and SIGHUP set, instead of ending the process at once.
    pub fn on_signals() -> io::Result<Stop> {
        let stop = Stop::default();
        for (number, _) in STOPPING {
            signal_hook::flag::register_usize(number, Arc::clone(&stop.signal), number as usize)?;
        }
        Ok(stop)
    }

    /// The signal that came, if one did.
    pub fn requested(&self) -> Option<Signal> {
        let number = self.signal.load(Ordering::Relaxed);
        STOPPING
            .iter()
            .find(|(n, _)| *n as usize == number)
            .map(|&(number, name)| Signal { number, name })
    }
}
