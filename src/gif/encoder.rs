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
//! Frames are coded on every core as they come, the caller's included ([`super::coders`]),
//! and written in order. A bounded set of frame slots travels between the caller and the
//! coders, so memory stays flat however many frames a run has, and their buffers serve the
//! whole run.

use std::borrow::Cow;
use std::collections::VecDeque;
use std::io::{self, Write};
use std::time::{Duration, Instant};

use super::coders::{self, Coders, Frame, Numbered};
use super::delta::{changed_rect, changed_rect_within, crop, paste, Rect};
use crate::render::palette::Palette;
use crate::render::{Damage, IndexedFrame};

/// The most pixels the frame slots hold (unless a single frame is bigger): what bounds memory.
/// Each slot's pixel takes about three bytes: its index, the index beneath it, and its share
/// of the compressed data.
pub const QUEUE_PIXELS: usize = 4 << 20;
/// The most frame slots: enough that the caller seldom waits for a slot while a coder works
/// on a frame that must be written before the ones already coded.
pub const MAX_QUEUED_FRAMES: usize = 32;
/// Frame slots per core, when they fit in [`QUEUE_PIXELS`]: each core's frame being coded,
/// two waiting for each coder thread, and one coded ahead of an older frame still being
/// coded. (Each slot is made at the start with room for a whole frame, so slots that would
/// never be used are not made.)
const SLOTS_PER_CORE: usize = 4;
/// The most frame slots a GIF of `width` × `height` px has, on any number of cores: at least
/// one, at most [`MAX_QUEUED_FRAMES`], and no more than [`QUEUE_PIXELS`] unless one frame
/// alone is.
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
    /// Frames the GIF holds so far: a frame that only repeats the last one lengthens its
    /// time instead of adding one.
    pictures: u32,
    /// Slots free to take the next frame, their buffers kept from earlier frames.
    free: Vec<Frame>,
    /// The frames queued and not yet written, oldest first. The newest is held back until
    /// the next frame comes, since identical frames may still lengthen its time.
    unwritten: VecDeque<Unwritten>,
    coders: Coders,
    timings: EncodeTimings,
}

/// A frame sent to the coders and not yet written: how long it shows, and the frame once
/// it is coded.
struct Unwritten {
    delay_cs: u16,
    coded: Option<Frame>,
}

/// Where a GIF writer's time went on the caller's thread, summed over the frames so far.
#[derive(Clone, Copy, Debug, Default)]
pub struct EncodeTimings {
    /// Finding each frame's changed rectangle and copying it out (wall-clock).
    pub changes: Duration,
    /// Choosing each frame's cheapest encoding (several LZW compressions), as far as the
    /// caller did it or waited for it (wall-clock, the caller's thread): what the coder
    /// threads do while the caller draws is not counted.
    pub lzw: Duration,
    /// Handing the compressed frames to the output (wall-clock).
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
        let cores = coders::cores();
        let slots = queue_frames(width.into(), height.into()).min(SLOTS_PER_CORE * cores);
        let pixels = usize::from(width) * usize::from(height);
        let table_len = palette.colours().len().next_power_of_two().max(2);
        let coders = Coders::start(table_len, cores, slots)?;
        Ok(GifWriter {
            encoder,
            width: width.into(),
            height: height.into(),
            delay_cs,
            shown: None,
            pictures: 0,
            free: (0..slots).map(|_| Frame::reserved(pixels)).collect(),
            unwritten: VecDeque::with_capacity(slots),
            coders,
            timings: EncodeTimings::default(),
        })
    }

    /// Queues one frame (the canvas's size) to be coded.
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
        self.timings.changes += started.elapsed();
        if changed == Some(None) && self.show_last_longer() {
            return Ok(());
        }
        let mut slot = self.free_slot()?;
        let started = Instant::now();
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
        self.timings.changes += started.elapsed();
        self.queue(slot)
    }

    /// Hands `slot`, cut from the next frame, to the coders; codes the oldest waiting frame
    /// here if more wait than the coder threads need, and writes what is coded.
    fn queue(&mut self, slot: Frame) -> io::Result<()> {
        self.coders.queue((self.pictures as usize, slot));
        self.unwritten.push_back(Unwritten {
            delay_cs: self.delay_cs,
            coded: None,
        });
        self.pictures += 1;
        let started = Instant::now();
        while let Some(coded) = self.coders.help() {
            self.take_coded(coded);
        }
        self.timings.lzw += started.elapsed();
        // Frames coded meanwhile are written now, so their slots are free for the next.
        while let Some(coded) = self.coders.coded_now()? {
            self.take_coded(coded);
        }
        self.write_coded(1)
    }

    /// Adds one frame's time to the last frame queued, if it is not written yet and its
    /// delay has room (and frames show for some time at all); returns whether it did.
    fn show_last_longer(&mut self) -> bool {
        let Some(last) = self.unwritten.back_mut() else {
            return false;
        };
        match last.delay_cs.checked_add(self.delay_cs) {
            Some(longer) if self.delay_cs > 0 => {
                last.delay_cs = longer;
                true
            }
            _ => false,
        }
    }

    /// A free slot for the next frame; while none is free, the next coded frame is awaited
    /// (or coded here) and written. The next frame is no repeat, so the newest frame's time
    /// is final: it is written too once coded (with a single slot, it holds that slot).
    fn free_slot(&mut self) -> io::Result<Frame> {
        self.write_coded(0)?;
        loop {
            if let Some(slot) = self.free.pop() {
                return Ok(slot);
            }
            self.next_coded()?;
            self.write_coded(0)?;
        }
    }

    /// Takes the next coded frame, coded here or awaited from a coder thread.
    fn next_coded(&mut self) -> io::Result<()> {
        let started = Instant::now();
        let coded = self.coders.next_coded()?;
        self.timings.lzw += started.elapsed();
        self.take_coded(coded);
        Ok(())
    }

    /// Puts a coded frame in its place among the unwritten ones.
    fn take_coded(&mut self, (number, frame): Numbered) {
        let oldest = self.pictures as usize - self.unwritten.len();
        self.unwritten[number - oldest].coded = Some(frame);
    }

    /// Writes the coded frames at the front of the unwritten ones, in order, but leaves the
    /// newest `hold` unwritten; their slots are free again.
    fn write_coded(&mut self, hold: usize) -> io::Result<()> {
        let started = Instant::now();
        while self.unwritten.len() > hold {
            // The oldest frame not yet coded stops the writing: frames go out in order.
            let Some(queued) = self.unwritten[0].coded.take() else {
                break;
            };
            let delay_cs = self.unwritten[0].delay_cs;
            self.unwritten.pop_front();
            let rect = queued.rect;
            let frame = gif::Frame {
                left: rect.left as u16,
                top: rect.top as u16,
                width: rect.width as u16,
                height: rect.height as u16,
                delay: delay_cs,
                dispose: gif::DisposalMethod::Keep,
                transparent: queued.encoding.transparent,
                interlaced: queued.encoding.interlaced,
                buffer: Cow::Borrowed(&queued.lzw),
                ..gif::Frame::default()
            };
            self.encoder
                .write_lzw_pre_encoded_frame(&frame)
                .map_err(gif_error)?;
            self.free.push(queued);
        }
        self.timings.write += started.elapsed();
        Ok(())
    }

    /// Waits for every frame queued so far to be coded, and writes them in order.
    pub fn flush(&mut self) -> io::Result<()> {
        while self.unwritten.iter().any(|frame| frame.coded.is_none()) {
            self.next_coded()?;
        }
        self.write_coded(0)
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_frame_slot_holds_a_whole_frame_from_the_start_so_a_late_first_use_allocates_nothing() {
        let mut palette = Palette::new();
        palette.insert([0, 0, 0]);
        let gif = GifWriter::new(Vec::new(), 64, 48, &palette, 30).unwrap();
        let slots = queue_frames(64, 48).min(SLOTS_PER_CORE * coders::cores());
        assert_eq!(gif.free.len(), slots);
        for slot in &gif.free {
            let held = [&slot.pixels, &slot.beneath, &slot.lzw].map(|buffer| buffer.capacity());
            assert!(held.iter().all(|&bytes| bytes >= 64 * 48), "{held:?} bytes");
        }
    }
}
