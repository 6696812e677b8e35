//! Image files from indexed frames: the animated GIF, streamed frame by frame, and the
//! still PNG. Knows frames and palettes, nothing of balls.

use std::borrow::Cow;
use std::io::{self, Write};

use image::ImageEncoder;

use crate::palette::Palette;
use crate::render::{to_rgb, IndexedFrame};

/// An animated GIF being written: every frame shows `frame_ms`, and the animation loops forever.
pub struct GifWriter<W: Write> {
    encoder: gif::Encoder<W>,
    delay_cs: u16,
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
        let table: Vec<u8> = palette.colours().iter().flatten().copied().collect();
        let mut encoder = gif::Encoder::new(out, width, height, &table).map_err(gif_error)?;
        encoder
            .set_repeat(gif::Repeat::Infinite)
            .map_err(gif_error)?;
        let delay_cs = u16::try_from(frame_ms / 10).map_err(io::Error::other)?;
        Ok(GifWriter { encoder, delay_cs })
    }

    /// Compresses and writes one frame; nothing of it is kept.
    pub fn write_frame(&mut self, frame: &IndexedFrame) -> io::Result<()> {
        let gif_frame = gif::Frame {
            width: frame.width() as u16,
            height: frame.height() as u16,
            delay: self.delay_cs,
            buffer: Cow::Borrowed(frame.as_raw()),
            ..gif::Frame::default()
        };
        self.encoder.write_frame(&gif_frame).map_err(gif_error)
    }

    /// Writes the trailer and hands back the output.
    pub fn finish(self) -> io::Result<W> {
        self.encoder.into_inner().map_err(gif_error)
    }
}

/// Writes `frame` as an RGB PNG.
pub fn write_png(out: impl Write, frame: &IndexedFrame, palette: &Palette) -> io::Result<()> {
    let rgb = to_rgb(frame, palette);
    image::codecs::png::PngEncoder::new(out)
        .write_image(
            rgb.as_raw(),
            rgb.width(),
            rgb.height(),
            image::ExtendedColorType::Rgb8,
        )
        .map_err(io::Error::other)
}
