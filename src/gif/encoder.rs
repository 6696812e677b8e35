//! The animated GIF from indexed frames. Knows frames and palettes, nothing of balls.
//!
//! The GIF is written for size and speed without losing a pixel. The colour table holds
//! only the scene's colours (padded to a power of two, as GIF requires). After the first
//! frame, each frame is only the rectangle that changed ([`super::delta`]), laid over the
//! last one (disposal Keep), written in whichever of a few encodings is smallest
//! ([`super::cheapest`]). Frames wait in a queue of bounded size; a full queue is encoded on
//! every core at once (rayon) and written in order, so memory stays flat however many
//! frames a run has, and the queue's buffers serve the whole run.

use std::borrow::Cow;
use std::io::{self, Write};
use std::time::{Duration, Instant};

use rayon::prelude::*;

use super::cheapest::{Coder, Encoding};
use super::delta::{changed_rect, crop, paste, Rect};
use crate::render::palette::Palette;
use crate::render::IndexedFrame;

/// The most pixels the queue holds (unless a single frame is bigger): what bounds memory.
/// Each queued pixel takes about three bytes: its index, the index beneath it, and its share
/// of the compressed data.
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
    /// How many entries the colour table has, a power of two: the indices free to mean
    /// transparent lie below it.
    table_len: usize,
    /// One coder per thread that compresses, each kept for the whole run.
    coders: Vec<Coder>,
    /// What a viewer shows after the frames written so far (None before the first).
    shown: Option<IndexedFrame>,
    queue: Vec<Queued>,
    queued: usize,
    timings: EncodeTimings,
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
}

/// Where a GIF writer's time went, summed over the frames so far (wall-clock).
#[derive(Clone, Copy, Debug, Default)]
pub struct EncodeTimings {
    /// Finding each frame's changed rectangle and copying it out.
    pub changes: Duration,
    /// Choosing each frame's cheapest encoding (several LZW compressions), every core at once.
    pub lzw: Duration,
    /// Handing the compressed frames to the output.
    pub write: Duration,
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
        let queue: Vec<Queued> = (0..queue_frames(width.into(), height.into()))
            .map(|_| Queued::default())
            .collect();
        let coders = (0..rayon::current_num_threads().min(queue.len()))
            .map(|_| Coder::default())
            .collect();
        Ok(GifWriter {
            encoder,
            width: width.into(),
            height: height.into(),
            delay_cs,
            table_len: palette.colours().len().next_power_of_two().max(2),
            coders,
            shown: None,
            queue,
            queued: 0,
            timings: EncodeTimings::default(),
        })
    }

    /// Queues one frame (the canvas's size), writing the queue when it is full.
    pub fn write_frame(&mut self, frame: &IndexedFrame) -> io::Result<()> {
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
        let slot = &mut self.queue[self.queued];
        match &mut self.shown {
            None => {
                slot.rect = Rect::whole(frame);
                slot.beneath.clear();
                self.shown = Some(frame.clone());
            }
            Some(shown) => {
                let changed = changed_rect(shown, frame);
                // An unchanged frame is still written, as one pixel, so it keeps its time.
                slot.rect = changed.unwrap_or(Rect::corner());
                crop(shown, slot.rect, &mut slot.beneath);
                if let Some(changed) = changed {
                    paste(frame, changed, shown);
                }
            }
        }
        crop(frame, slot.rect, &mut slot.pixels);
        self.queued += 1;
        self.timings.changes += started.elapsed();
        if self.queued == self.queue.len() {
            self.flush()?;
        }
        Ok(())
    }

    /// Encodes every queued frame, all cores at once, and writes them in order.
    pub fn flush(&mut self) -> io::Result<()> {
        let queue = &mut self.queue[..self.queued];
        let started = Instant::now();
        let table_len = self.table_len;
        // Each coder takes an equal run of the queue, so each keeps its table hot.
        let per_coder = queue.len().div_ceil(self.coders.len()).max(1);
        queue
            .par_chunks_mut(per_coder)
            .zip(self.coders.par_iter_mut())
            .for_each(|(frames, coder)| {
                for frame in frames {
                    let beneath = (!frame.beneath.is_empty()).then_some(&frame.beneath[..]);
                    let width = frame.rect.width as usize;
                    frame.encoding = coder.encode_cheapest(
                        &frame.pixels,
                        width,
                        beneath,
                        table_len,
                        &mut frame.lzw,
                    );
                }
            });
        let compressed = Instant::now();
        for queued in queue.iter() {
            let rect = queued.rect;
            let frame = gif::Frame {
                left: rect.left as u16,
                top: rect.top as u16,
                width: rect.width as u16,
                height: rect.height as u16,
                delay: self.delay_cs,
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
        self.queued = 0;
        self.timings.lzw += compressed - started;
        self.timings.write += compressed.elapsed();
        Ok(())
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
