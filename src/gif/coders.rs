//! Frames coded on every core: a queue of frames waiting for a coder, a coder thread for each
//! core but the caller's, and the caller coding the oldest waiting frame itself whenever more
//! frames wait than the threads need. So one core needs no thread at all, and no core waits
//! while another has frames to code. Frames come back in the order they were coded, each
//! with its number, for the writer to put in order.
//!
//! A frame's coding depends on its pixels alone (`super::cheapest`), so the GIF is the same
//! whichever coder took which frame, on any number of cores.

use std::collections::VecDeque;
use std::num::NonZeroUsize;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::mpsc::{sync_channel, Receiver, SyncSender, TryRecvError};
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::{io, thread};

use super::cheapest::{Coder, Encoding};
use super::delta::Rect;

/// The environment variable that sets how many cores code frames, the caller's included
/// (default: every core). The GIF's bytes do not depend on it.
pub const THREADS_VARIABLE: &str = "BOUNCING_BALL_THREADS";

/// How many frames wait for each coder thread before the caller codes one itself: enough
/// that a thread finds the next frame waiting while the caller codes.
const WAITING_PER_THREAD: usize = 2;

/// One frame on its way through the coders: what to write where, what lies beneath it, and
/// its compressed bytes once coded. Its buffers are kept from frame to frame.
#[derive(Default)]
pub(crate) struct Frame {
    pub rect: Rect,
    pub pixels: Vec<u8>,
    /// What the viewer shows under `rect` before this frame; empty for the first frame.
    pub beneath: Vec<u8>,
    pub lzw: Vec<u8>,
    /// How `lzw` was encoded: what the frame's header must say.
    pub encoding: Encoding,
}

impl Frame {
    /// A frame whose buffers already hold `pixels` pixels, so that it never allocates: a slot
    /// may first be used late in a run, when the coders fall behind. (Memory is only
    /// reserved; the system hands it over when it is first written.)
    pub fn reserved(pixels: usize) -> Frame {
        Frame {
            pixels: Vec::with_capacity(pixels),
            beneath: Vec::with_capacity(pixels),
            lzw: Vec::with_capacity(pixels),
            ..Frame::default()
        }
    }

    /// Compresses the frame in its cheapest encoding, with `coder`'s tools.
    fn code(&mut self, coder: &mut Coder, table_len: usize) {
        let beneath = (!self.beneath.is_empty()).then_some(&self.beneath[..]);
        let width = self.rect.width as usize;
        self.encoding =
            coder.encode_cheapest(&self.pixels, width, beneath, table_len, &mut self.lzw);
    }
}

/// A frame with its number (counted from 0 as frames are queued), so that frames coded out
/// of order find their place.
pub(crate) type Numbered = (usize, Frame);

/// The coders of one GIF: the queue, the threads, and the caller's own coder.
pub(crate) struct Coders {
    waiting: Shared,
    /// The threads' coded frames; `None` from a thread that panicked (a bug), so that the
    /// caller does not wait for a frame that will never come.
    from_threads: Receiver<Option<Numbered>>,
    threads: usize,
    /// The caller's coder, for the frames it codes itself.
    coder: Coder,
    /// How many entries the colour table has, a power of two: the indices free to mean
    /// transparent lie below it.
    table_len: usize,
}

impl Coders {
    /// Starts a coder thread for each of `cores` but the caller's, at most `frames - 1`, for
    /// at most `frames` frames at a time.
    pub fn start(table_len: usize, cores: usize, frames: usize) -> io::Result<Coders> {
        Coders::with_threads(table_len, frames, cores.min(frames).max(1) - 1)
    }

    fn with_threads(table_len: usize, frames: usize, threads: usize) -> io::Result<Coders> {
        // Held as `Shared` from the start, so that the threads started stop if a later one
        // cannot be.
        let waiting = Shared(Arc::new(Waiting::for_frames(frames)));
        // Room for every frame at once, so a thread never waits to hand one back, and the
        // channel's memory is made here once.
        let (to_caller, from_threads) = sync_channel(frames);
        for n in 1..=threads {
            let (waiting, to_caller) = (Arc::clone(&waiting.0), to_caller.clone());
            thread::Builder::new()
                .name(format!("gif coder {n}"))
                .spawn(move || {
                    let mut coder = Coder::default();
                    code_frames(&waiting, &to_caller, |frame| {
                        frame.code(&mut coder, table_len)
                    });
                })?;
        }
        Ok(Coders {
            waiting,
            from_threads,
            threads,
            coder: Coder::default(),
            table_len,
        })
    }

    /// Queues `frame` for the next free coder.
    pub fn queue(&self, frame: Numbered) {
        self.waiting.0.push(frame);
    }

    /// The oldest waiting frame coded here, when more frames wait than the threads need;
    /// `None` when they do not.
    pub fn help(&mut self) -> Option<Numbered> {
        if self.waiting.0.len() <= WAITING_PER_THREAD * self.threads {
            return None;
        }
        let oldest = self.waiting.0.take()?;
        Some(self.code_here(oldest))
    }

    /// A frame the threads have coded, if one is ready now.
    pub fn coded_now(&mut self) -> io::Result<Option<Numbered>> {
        if self.threads == 0 {
            return Ok(None);
        }
        match self.from_threads.try_recv() {
            Ok(Some(frame)) => Ok(Some(frame)),
            Ok(None) | Err(TryRecvError::Disconnected) => Err(coder_gone()),
            Err(TryRecvError::Empty) => Ok(None),
        }
    }

    /// The next coded frame: the oldest waiting frame coded here, or, when the threads have
    /// taken them all, the next they finish.
    pub fn next_coded(&mut self) -> io::Result<Numbered> {
        if let Some(oldest) = self.waiting.0.take() {
            return Ok(self.code_here(oldest));
        }
        match self.from_threads.recv() {
            Ok(Some(frame)) => Ok(frame),
            Ok(None) | Err(_) => Err(coder_gone()),
        }
    }

    fn code_here(&mut self, (number, mut frame): Numbered) -> Numbered {
        frame.code(&mut self.coder, self.table_len);
        (number, frame)
    }
}

/// A coder thread stopped (it panicked): nothing more can be written.
fn coder_gone() -> io::Error {
    io::Error::other("a GIF coding thread stopped")
}

/// How many cores code frames: [`THREADS_VARIABLE`] if set to a whole number above zero,
/// else every core.
pub fn cores() -> usize {
    let set = std::env::var(THREADS_VARIABLE).ok();
    match set.and_then(|n| n.trim().parse::<NonZeroUsize>().ok()) {
        Some(cores) => cores.get(),
        None => thread::available_parallelism().map_or(1, NonZeroUsize::get),
    }
}

/// A coder thread's loop: the oldest frame not yet taken, coded by `code` and sent back,
/// until the writer is gone or a coding panicked (a bug: the thread says so with `None` and
/// stops).
fn code_frames(
    waiting: &Waiting,
    to_caller: &SyncSender<Option<Numbered>>,
    mut code: impl FnMut(&mut Frame),
) {
    while let Some((number, mut frame)) = waiting.wait_for_frame() {
        let coded = catch_unwind(AssertUnwindSafe(|| code(&mut frame)));
        let message = coded.ok().map(|()| (number, frame));
        let panicked = message.is_none();
        if to_caller.send(message).is_err() || panicked {
            return;
        }
    }
}

/// The frames waiting for a coder, oldest first, shared by the caller and the threads.
struct Waiting {
    frames: Mutex<WaitingFrames>,
    /// Signalled when a frame comes or the writer goes.
    changed: Condvar,
}

struct WaitingFrames {
    queue: VecDeque<Numbered>,
    /// The writer is gone: the threads stop.
    closed: bool,
}

/// The caller's hold on the waiting frames: when the caller drops it, the threads stop.
struct Shared(Arc<Waiting>);

impl Drop for Shared {
    fn drop(&mut self) {
        self.0.lock().closed = true;
        self.0.changed.notify_all();
    }
}

impl Waiting {
    /// A queue with room for `frames` frames, made once.
    fn for_frames(frames: usize) -> Waiting {
        let frames = WaitingFrames {
            queue: VecDeque::with_capacity(frames),
            closed: false,
        };
        Waiting {
            frames: Mutex::new(frames),
            changed: Condvar::new(),
        }
    }

    fn lock(&self) -> MutexGuard<'_, WaitingFrames> {
        // The lock is held only to push or take a frame, which cannot panic.
        self.frames
            .lock()
            .expect("no thread panics holding the queue")
    }

    fn push(&self, frame: Numbered) {
        self.lock().queue.push_back(frame);
        self.changed.notify_one();
    }

    fn len(&self) -> usize {
        self.lock().queue.len()
    }

    /// The oldest waiting frame, if any, without waiting for one.
    fn take(&self) -> Option<Numbered> {
        self.lock().queue.pop_front()
    }

    /// The oldest waiting frame, waiting for one to come; `None` once the caller is gone.
    fn wait_for_frame(&self) -> Option<Numbered> {
        let mut frames = self.lock();
        loop {
            if frames.closed {
                return None;
            }
            if let Some(frame) = frames.queue.pop_front() {
                return Some(frame);
            }
            frames = self
                .changed
                .wait(frames)
                .expect("no thread panics holding the queue");
        }
    }
}

#[cfg(test)]
mod tests {
    use std::time::{Duration, Instant};

    use super::*;

    /// Waits up to ten seconds for `done` (it takes microseconds), checking every millisecond.
    fn eventually(done: impl Fn() -> bool) -> bool {
        let started = Instant::now();
        while !done() {
            if started.elapsed() > Duration::from_secs(10) {
                return false;
            }
            thread::sleep(Duration::from_millis(1));
        }
        true
    }

    #[test]
    fn the_coder_threads_stop_when_their_writer_goes() {
        let coders = Coders::with_threads(16, 8, 3).unwrap();
        let waiting = Arc::clone(&coders.waiting.0);
        assert_eq!(
            Arc::strong_count(&waiting),
            5,
            "the caller, three threads and this test"
        );
        drop(coders);
        assert!(
            eventually(|| Arc::strong_count(&waiting) == 1),
            "{} holders of the queue left ten seconds after the writer went",
            Arc::strong_count(&waiting)
        );
    }

    #[test]
    fn a_coder_thread_codes_frame_after_frame_while_the_caller_only_queues() {
        let coders = Coders::with_threads(16, 8, 1).unwrap();
        for number in 0..6 {
            coders.queue((number, Frame::default()));
        }
        assert!(
            eventually(|| coders.waiting.0.len() == 0),
            "{} of 6 frames still wait for the thread",
            coders.waiting.0.len()
        );
    }

    #[test]
    fn a_coder_thread_that_panics_is_an_error_for_the_writer_not_a_hang() {
        let waiting = Arc::new(Waiting::for_frames(8));
        let (to_caller, from_threads) = sync_channel(8);
        let thread_waiting = Arc::clone(&waiting);
        thread::spawn(move || {
            code_frames(&thread_waiting, &to_caller, |_| {
                panic!("a coder's bug, on purpose")
            })
        });
        let mut coders = Coders {
            waiting: Shared(waiting),
            from_threads,
            threads: 1,
            coder: Coder::default(),
            table_len: 16,
        };
        coders.queue((0, Frame::default()));
        // Once the thread has taken the frame, the writer can only wait for the thread.
        assert!(
            eventually(|| coders.waiting.0.len() == 0),
            "the thread took the frame"
        );
        let error = coders.next_coded().err().expect("an error, not a frame");
        assert_eq!(error.to_string(), "a GIF coding thread stopped");
        assert!(
            eventually(|| Arc::strong_count(&coders.waiting.0) == 1),
            "the thread went on after its panic"
        );
    }
}
