//! The still picture: one indexed frame written as an RGB PNG; or any RGB picture.

use std::io::{self, Write};

use image::{ImageEncoder, RgbImage};

use super::palette::IndexedFrame;
use super::palette::Palette;
use super::raster::to_rgb;

/// Writes `frame` as an RGB PNG.
pub(crate) fn write_png(
    out: impl Write,
    frame: &IndexedFrame,
    palette: &Palette,
) -> io::Result<()> {
    write_rgb_png(out, &to_rgb(frame, palette))
}

/// Writes `rgb` as a PNG.
pub(crate) fn write_rgb_png(out: impl Write, rgb: &RgbImage) -> io::Result<()> {
    image::codecs::png::PngEncoder::new(out)
        .write_image(
            rgb.as_raw(),
            rgb.width(),
            rgb.height(),
            image::ExtendedColorType::Rgb8,
        )
        .map_err(io::Error::other)
}
