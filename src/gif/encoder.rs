//! The animated GIF from indexed frames. Knows frames and palettes, nothing of balls.
//!
//! The GIF is written for size and speed without losing a pixel. The colour table holds
//! only the scene's colours (padded to a power of two, as GIF requires). After the first
//! frame, each frame is only the rectangle that changed ([`super::delta`]), laid over the
//! last one (disposal Keep), written in whichever of a few encodings is smallest
//! (`super::cheapest`). A frame identical to the one before is not written at all: the one
//! before is shown that much longer (its delay grows), as `gifsicle -O` does. A renderer that
//! knows what it drew again says so ([`crate::render::Damage`]): only there are pixels
//! compared, and a frame it did not draw again is not compared at all.
//!
//! Frames wait in a queue of bounded size. The queue goes to a background thread when it is
//! full, or earlier when that thread is free and there is a frame for each core; the thread
//! encodes it on every core at once (rayon) while the caller draws and queues the next
//! frames, and it comes back to be written in order. Two queues take turns,
//! so memory stays flat however many frames a run has, and their buffers serve the whole run.

use std::borrow::Cow;
use std::io::{self, Write};
use std::mem::take;
use std::sync::mpsc::{sync_channel, Receiver, SyncSender, TryRecvError};
use std::sync::Mutex;
use std::thread;
use std::time::{Duration, Instant};

use rayon::prelude::*;

use super::cheapest::{Coder, Encoding};
use super::delta::{changed_rect, changed_rect_within, crop, paste, Rect};
use crate::render::palette::Palette;
use crate::render::{Damage, IndexedFrame};

/// The most pixels a queue holds (unless a single frame is bigger): what bounds memory.
/// Each queued pixel takes about three bytes: its index, the index beneath it, and its share
/// of the compressed data; two queues take turns (one filling, one being encoded).
pub const QUEUE_PIXELS: usize = 4 << 20;
/// The most frames the queue holds: plenty to keep every core busy.
pub const MAX_QUEUED_FRAMES: usize = 32;

/// How many frames of `width` × `height` px wait to be compressed together: at least one,
/// at most [`MAX_QUEUED_FRAMES`], and no more than [`QUEUE_PIXELS`] unless one frame alone is.
pub fn queue_frames(width: u32, height: u32) -> usize {
    let frame_pixels = (width as usize * height as usize).max(1);
    (QUEUE_PIXELS / frame_pixels).clamp(1, MAX_QUEUED_FRAMES)
}

/// An animated GIF being written: every frame shows `frame_ms`, and the animation loops forever.
pub struct GifWriter<W: Write> {
    encoder: gif::Encoder<W>,
    width: u32,
    height: u32,
    delay_cs: u16,
    /// What a viewer shows after the frames queued so far (None before the first).
    shown: Option<IndexedFrame>,
    /// How long the last frame of the batch being encoded shows, cs: it grows while frames
    /// identical to it come and the next batch is still empty.
    in_flight_last_delay: u16,
    /// The batch being filled; its coders are here while no batch is being encoded.
    filling: Batch,
    /// The other batch's frames and coders while it is being encoded, or back and spare.
    spare: Option<Batch>,
    /// Whether a batch is with the encoding thread now.
    in_flight: bool,
    /// Frames the GIF holds so far: a frame that only repeats the last one lengthens its
    /// time instead of adding one.
    pictures: u32,
    /// How many coders encode a batch at once (one per core).
    cores: usize,
    to_encoder: SyncSender<Batch>,
    from_encoder: Receiver<Batch>,
    timings: EncodeTimings,
}

/// Frames on their way through the encoder, and the coders that encode them (one per core,
/// each kept for the whole run).
#[derive(Default)]
struct Batch {
    frames: Vec<Queued>,
    queued: usize,
    coders: Vec<Coder>,
    /// How many entries the colour table has, a power of two: the indices free to mean
    /// transparent lie below it.
    table_len: usize,
    /// How long encoding it took.
    took: Duration,
}

impl Batch {
    /// Encodes every queued frame, all cores at once: each coder takes the next frame not yet
    /// taken, so a core that drew small frames goes on to help with the rest.
    fn encode(&mut self) {
        let started = Instant::now();
        let table_len = self.table_len;
        let frames = Mutex::new(self.frames[..self.queued].iter_mut());
        let next_frame = || frames.lock().expect("no coder panics").next();
        self.coders.par_iter_mut().for_each(|coder| {
            while let Some(frame) = next_frame() {
                let beneath = (!frame.beneath.is_empty()).then_some(&frame.beneath[..]);
                let width = frame.rect.width as usize;
                frame.encoding =
                    coder.encode_cheapest(&frame.pixels, width, beneath, table_len, &mut frame.lzw);
            }
        });
        self.took = started.elapsed();
    }
}

/// The encoding thread's loop: a batch in, the same batch encoded back out, until the
/// writer is gone.
fn encode_batches(batches: Receiver<Batch>, done: SyncSender<Batch>) {
    for mut batch in batches {
        batch.encode();
        if done.send(batch).is_err() {
            break;
        }
    }
}

/// One frame waiting in the queue: what to write where, what lies beneath it, and its
/// compressed bytes once encoded.
#[derive(Default)]
struct Queued {
    rect: Rect,
    pixels: Vec<u8>,
    /// What the viewer shows under `rect` before this frame; empty for the first frame.
    beneath: Vec<u8>,
    lzw: Vec<u8>,
    /// How `lzw` was encoded: what the frame's header must say.
    encoding: Encoding,
    /// How long the frame shows, cs: longer than a frame's time when identical frames follow.
    delay_cs: u16,
}

impl Queued {
    /// A slot whose buffers already hold a whole frame: batches are cut as the encoder frees
    /// up, so a slot may first be used late in a run, and must not allocate then. (Memory is
    /// only reserved; the system hands it over when it is first written.)
    fn reserved(pixels: usize) -> Queued {
        Queued {
            pixels: Vec::with_capacity(pixels),
            beneath: Vec::with_capacity(pixels),
            lzw: Vec::with_capacity(pixels),
            ..Queued::default()
        }
    }
}

/// Where a GIF writer's time went, summed over the frames so far (wall-clock).
#[derive(Clone, Copy, Debug, Default)]
pub struct EncodeTimings {
    /// Finding each frame's changed rectangle and copying it out.
    pub changes: Duration,
    /// Choosing each frame's cheapest encoding (several LZW compressions), every core at once,
    /// on the encoding thread (mostly while the caller draws the next frames).
    pub lzw: Duration,
    /// Handing the compressed frames to the output.
    pub write: Duration,
}

/// The encoding thread stopped (it panicked): nothing more can be written.
fn encoder_gone() -> io::Error {
    io::Error::other("the GIF encoding thread stopped")
}

fn gif_error(e: gif::EncodingError) -> io::Error {
    match e {
        gif::EncodingError::Io(e) => e,
        other => io::Error::other(other),
    }
}

impl<W: Write> GifWriter<W> {
    /// Writes the header and the scene's one colour table.
    pub fn new(
        out: W,
        width: u16,
        height: u16,
        palette: &Palette,
        frame_ms: u32,
    ) -> io::Result<Self> {
        if width == 0 || height == 0 {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                "a GIF needs at least one pixel",
            ));
        }
        let table: Vec<u8> = palette.colours().iter().flatten().copied().collect();
        let mut encoder = gif::Encoder::new(out, width, height, &table).map_err(gif_error)?;
        encoder
            .set_repeat(gif::Repeat::Infinite)
            .map_err(gif_error)?;
        let delay_cs = u16::try_from(frame_ms / 10).map_err(io::Error::other)?;
        let frames = queue_frames(width.into(), height.into());
        let pixels = usize::from(width) * usize::from(height);
        let batch = |coders| Batch {
            frames: (0..frames).map(|_| Queued::reserved(pixels)).collect(),
            coders,
            table_len: palette.colours().len().next_power_of_two().max(2),
            ..Batch::default()
        };
        let cores = rayon::current_num_threads().min(frames);
        let coders = (0..cores).map(|_| Coder::default()).collect();
        let (to_encoder, batches) = sync_channel(1);
        let (done, from_encoder) = sync_channel(1);
        thread::Builder::new()
            .name("gif encoder".into())
            .spawn(move || encode_batches(batches, done))?;
        Ok(GifWriter {
            encoder,
            width: width.into(),
            height: height.into(),
            delay_cs,
            shown: None,
            in_flight_last_delay: 0,
            filling: batch(coders),
            spare: Some(batch(Vec::new())),
            in_flight: false,
            pictures: 0,
            cores,
            to_encoder,
            from_encoder,
            timings: EncodeTimings::default(),
        })
    }

    /// Queues one frame (the canvas's size), sending the queue to be encoded when it is full
    /// or the encoder is free.
    pub fn write_frame(&mut self, frame: &IndexedFrame) -> io::Result<()> {
        self.write_changes(frame, Damage::Whole)
    }

    /// Queues one frame that differs from the last one queued only as `damage` says (a
    /// [`crate::render::Canvas`] says so): only there is it compared with the last frame,
    /// and not at all when unchanged. The GIF is the same as [`GifWriter::write_frame`]'s.
    pub fn write_changes(&mut self, frame: &IndexedFrame, damage: Damage) -> io::Result<()> {
        if frame.dimensions() != (self.width, self.height) {
            return Err(io::Error::new(
                io::ErrorKind::InvalidInput,
                format!(
                    "a {}x{} frame does not fit a {}x{} GIF",
                    frame.width(),
                    frame.height(),
                    self.width,
                    self.height
                ),
            ));
        }
        let started = Instant::now();
        let changed = self.shown.as_ref().map(|shown| match damage {
            Damage::Unchanged => None,
            Damage::Whole => changed_rect(shown, frame),
            Damage::Areas(areas) => areas
                .iter()
                .filter_map(|&area| changed_rect_within(shown, frame, area))
                .reduce(Rect::union),
        });
        if changed == Some(None) && self.show_last_longer() {
            self.timings.changes += started.elapsed();
            return Ok(());
        }
        let slot = &mut self.filling.frames[self.filling.queued];
        slot.delay_cs = self.delay_cs;
        match (&mut self.shown, changed) {
            (Some(shown), Some(changed)) => {
                // An unchanged frame whose time cannot be added to the last one's is written
                // as one pixel, so it keeps its time.
                slot.rect = changed.unwrap_or(Rect::corner());
                crop(shown, slot.rect, &mut slot.beneath);
                if let Some(changed) = changed {
                    paste(frame, changed, shown);
                }
            }
            _ => {
                slot.rect = Rect::whole(frame);
                slot.beneath.clear();
                self.shown = Some(frame.clone());
            }
        }
        crop(frame, slot.rect, &mut slot.pixels);
        self.filling.queued += 1;
        self.pictures += 1;
        self.timings.changes += started.elapsed();
        // A batch goes as soon as it is full, or as soon as the encoder is free and there is
        // a frame for each core: no core waits for a batch to fill.
        let full = self.filling.queued == self.filling.frames.len();
        if full || (self.filling.queued >= self.cores && self.encoder_free()?) {
            self.hand_over()?;
        }
        Ok(())
    }

    /// Whether no batch is being encoded now (writing the one that just came back, if any).
    fn encoder_free(&mut self) -> io::Result<bool> {
        if !self.in_flight {
            return Ok(true);
        }
        match self.from_encoder.try_recv() {
            Ok(batch) => {
                self.write_batch(batch)?;
                Ok(true)
            }
            Err(TryRecvError::Empty) => Ok(false),
            Err(TryRecvError::Disconnected) => Err(encoder_gone()),
        }
    }

    /// Adds one frame's time to the last frame queued, if its delay has room (and frames
    /// show for some time at all); returns whether it did.
    fn show_last_longer(&mut self) -> bool {
        let delay = match self.filling.queued.checked_sub(1) {
            Some(last) => &mut self.filling.frames[last].delay_cs,
            None if self.in_flight => &mut self.in_flight_last_delay,
            None => return false,
        };
        match delay.checked_add(self.delay_cs) {
            Some(longer) if self.delay_cs > 0 => {
                *delay = longer;
                true
            }
            _ => false,
        }
    }

    /// Sends the full batch to the encoding thread and goes on with the other one (after
    /// writing it, if it was out being encoded).
    fn hand_over(&mut self) -> io::Result<()> {
        self.collect()?;
        // The coders go with the full batch, and come back with it.
        let next = self
            .spare
            .take()
            .expect("the spare batch is back after collect");
        let full = std::mem::replace(&mut self.filling, next);
        self.in_flight_last_delay = full.frames[full.queued - 1].delay_cs;
        self.to_encoder.send(full).map_err(|_| encoder_gone())?;
        self.in_flight = true;
        Ok(())
    }

    /// Waits for the batch being encoded, if any, and writes it.
    fn collect(&mut self) -> io::Result<()> {
        if !self.in_flight {
            return Ok(());
        }
        let batch = self.from_encoder.recv().map_err(|_| encoder_gone())?;
        self.write_batch(batch)
    }

    /// Writes an encoded batch's frames in order, and keeps its frames as the spare batch and
    /// its coders for the next.
    fn write_batch(&mut self, mut batch: Batch) -> io::Result<()> {
        self.in_flight = false;
        let started = Instant::now();
        let last = batch.queued - 1;
        for (n, queued) in batch.frames[..batch.queued].iter().enumerate() {
            let rect = queued.rect;
            let delay = if n == last {
                self.in_flight_last_delay
            } else {
                queued.delay_cs
            };
            let frame = gif::Frame {
                left: rect.left as u16,
                top: rect.top as u16,
                width: rect.width as u16,
                height: rect.height as u16,
                delay,
                dispose: gif::DisposalMethod::Keep,
                transparent: queued.encoding.transparent,
                interlaced: queued.encoding.interlaced,
                buffer: Cow::Borrowed(&queued.lzw),
                ..gif::Frame::default()
            };
            self.encoder
                .write_lzw_pre_encoded_frame(&frame)
                .map_err(gif_error)?;
        }
        self.timings.lzw += batch.took;
        self.timings.write += started.elapsed();
        self.filling.coders = take(&mut batch.coders);
        batch.queued = 0;
        self.spare = Some(batch);
        Ok(())
    }

    /// Sends every frame queued so far to be encoded, without waiting for it (only for the
    /// batch before it, if any), so the caller can do other work in the meantime.
    pub(crate) fn send_queued(&mut self) -> io::Result<()> {
        if self.filling.queued > 0 {
            self.hand_over()?;
        }
        Ok(())
    }

    /// Encodes every frame queued so far and writes them in order.
    pub fn flush(&mut self) -> io::Result<()> {
        self.send_queued()?;
        self.collect()
    }

    /// How many frames the GIF holds so far (repeats are merged into the frame before them).
    pub(crate) fn pictures(&self) -> u32 {
        self.pictures
    }

    /// Where the time went so far.
    pub fn timings(&self) -> EncodeTimings {
        self.timings
    }

    /// Writes what is still queued and the trailer, and hands back the output.
    pub fn finish(mut self) -> io::Result<W> {
        self.flush()?;
        self.encoder.into_inner().map_err(gif_error)
    }
}
