//! The progress bar: only for runs that look long enough to need one.

use std::time::Duration;

use bouncing_ball::progress::{looks_long, SAMPLE, WORTH_A_BAR};

#[test]
fn only_a_run_projected_past_a_second_gets_a_progress_bar() {
    // 150 ms for 10 of 100 frames projects 1.5 s; for 50 of 100, 0.3 s.
    let ms = Duration::from_millis;
    assert!(WORTH_A_BAR == Duration::from_secs(1) && SAMPLE <= ms(150));
    assert!(looks_long(ms(150), 10, 100), "projected 1.5 s");
    assert!(!looks_long(ms(150), 50, 100), "projected 0.3 s");
    assert!(
        !looks_long(SAMPLE / 2, 1, 1_000_000),
        "too early to project anything"
    );
    assert!(!looks_long(ms(500), 0, 100), "nothing done yet");
}

/// `compare` shows the same bar as the main command when a person watches it on a terminal
/// (a pseudo-terminal here), and none when its stderr goes to a file or a pipe. Unix only:
/// Windows has no pseudo-terminal a test can open without the console host, so there the
/// bar's rule is checked by the test above and by hand.
#[cfg(unix)]
#[test]
fn compare_shows_a_progress_bar_on_a_terminal_and_none_in_a_pipe() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    // About 4 s on an idle 2-core machine: long enough for the bar whatever the load.
    let args = ["compare", "-p", "many", "--frames", "5000"];
    let on_terminal = terminal::stderr_of(dir.path(), &args);
    assert!(
        on_terminal.contains("frames,") && on_terminal.contains("left"),
        "a 4-second compare on a terminal should draw the bar, drew: {on_terminal:?}"
    );
    let piped = std::process::Command::new(env!("CARGO_BIN_EXE_bouncing_ball"))
        .args(args)
        .current_dir(dir.path())
        .output()
        .expect("the binary runs");
    let piped = String::from_utf8_lossy(&piped.stderr);
    assert!(
        !piped.contains("frames,"),
        "no bar when stderr is a pipe: {piped:?}"
    );
}

/// A pseudo-terminal to run the binary's stderr on, as a person's terminal would be.
#[cfg(unix)]
mod terminal {
    use std::ffi::CStr;
    use std::fs::File;
    use std::io::Read;
    use std::os::fd::{FromRawFd, OwnedFd};
    use std::path::Path;
    use std::process::{Command, Stdio};

    /// Runs the binary with `args` in `dir`, its stderr on a pseudo-terminal; returns what
    /// it drew there.
    pub fn stderr_of(dir: &Path, args: &[&str]) -> String {
        // SAFETY: plain libc calls on a descriptor this function owns; the name is copied
        // out of libc's buffer before anything else runs.
        let (main, side) = unsafe {
            let main = libc::posix_openpt(libc::O_RDWR | libc::O_NOCTTY);
            assert!(main >= 0, "posix_openpt");
            assert!(libc::grantpt(main) == 0 && libc::unlockpt(main) == 0);
            let name = libc::ptsname(main);
            assert!(!name.is_null(), "ptsname");
            let name = CStr::from_ptr(name).to_string_lossy().into_owned();
            (OwnedFd::from_raw_fd(main), name)
        };
        let side = File::options()
            .write(true)
            .open(side)
            .expect("the terminal's side");
        let mut child = Command::new(env!("CARGO_BIN_EXE_bouncing_ball"))
            .args(args)
            // As a person's terminal says what it is.
            .env("TERM", "xterm")
            .current_dir(dir)
            .stdout(Stdio::null())
            .stderr(side)
            .spawn()
            .expect("the binary runs");
        let mut reader = File::from(main);
        let drawn = std::thread::spawn(move || {
            let mut drawn = Vec::new();
            let mut buffer = [0u8; 4096];
            // Reading ends with an error once the child has exited and closed its side.
            while let Ok(n) = reader.read(&mut buffer) {
                if n == 0 {
                    break;
                }
                drawn.extend_from_slice(&buffer[..n]);
            }
            drawn
        });
        assert!(child.wait().expect("the run ends").success());
        String::from_utf8_lossy(&drawn.join().expect("the reader ends")).into_owned()
    }
}
