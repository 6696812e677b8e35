//! A handed-in GIF read as a viewer shows it, from any encoder: each frame drawn over the
//! last at its offset, its transparent pixels leaving what was there, and each frame's
//! disposal (keep, clear to the background, restore what was before) done before the next.
//!
//! The file is read whole first, its frames kept compressed, so a truncated file, its size
//! and its timing are known before a pixel is decoded; the pictures are then decoded one at
//! a time. The canvas must fit the memory budget before anything is decoded, so a file that
//! claims a 65535 × 65535 canvas costs nothing.

use std::fs::File;
use std::io::BufReader;
use std::num::NonZeroU64;
use std::path::Path;

use gif::DisposalMethod;
use image::{Rgb, RgbImage};

use super::found::Trouble;
use crate::render::dirty::Rect;

/// A GIF's frames as stored, not yet decoded.
pub(crate) struct Animation {
    pub width: u32,
    pub height: u32,
    global: Option<Vec<u8>>,
    background: Rgb<u8>,
    frames: Vec<Stored>,
}

/// One frame as stored: where it goes, how it is drawn and its compressed pixels.
struct Stored {
    left: u32,
    top: u32,
    width: u32,
    height: u32,
    interlaced: bool,
    transparent: Option<u8>,
    dispose: DisposalMethod,
    palette: Option<Vec<u8>>,
    /// The LZW minimum code size, then the codes.
    lzw: Vec<u8>,
    delay_cs: u16,
}

/// The bytes a `width` × `height` canvas takes to composite on: the picture and a copy for
/// frames that restore what was before them.
fn canvas_bytes(width: u32, height: u32) -> u64 {
    u64::from(width) * u64::from(height) * 3 * 2
}

impl Animation {
    /// Reads every frame's header and compressed pixels; refuses a canvas over `memory_budget`
    /// bytes before reading any frame.
    pub(crate) fn read(path: &Path, memory_budget: u64) -> Result<Animation, Trouble> {
        let file = File::open(path).map_err(Trouble::Read)?;
        let mut options = gif::DecodeOptions::new();
        options.skip_frame_decoding(true);
        if let Some(limit) = NonZeroU64::new(memory_budget) {
            options.set_memory_limit(gif::MemoryLimit::Bytes(limit));
        }
        let not_whole = |error: gif::DecodingError| Trouble::NotWhole(error.to_string());
        let mut decoder = options.read_info(BufReader::new(file)).map_err(not_whole)?;
        let (width, height) = (u32::from(decoder.width()), u32::from(decoder.height()));
        Trouble::over_budget(width, height, canvas_bytes(width, height), memory_budget)?;
        let global = decoder.global_palette().map(<[u8]>::to_vec);
        let background = decoder
            .bg_color()
            .and_then(|i| colour(global.as_deref()?, i as u8))
            .unwrap_or(Rgb([0, 0, 0]));
        let mut frames = Vec::new();
        while let Some(frame) = decoder.read_next_frame().map_err(not_whole)? {
            frames.push(Stored {
                left: u32::from(frame.left),
                top: u32::from(frame.top),
                width: u32::from(frame.width),
                height: u32::from(frame.height),
                interlaced: frame.interlaced,
                transparent: frame.transparent,
                dispose: frame.dispose,
                palette: frame.palette.clone(),
                lzw: frame.buffer.to_vec(),
                delay_cs: frame.delay,
            });
        }
        if frames.is_empty() {
            return Err(Trouble::NotWhole("it holds no frame".to_string()));
        }
        Ok(Animation {
            width,
            height,
            global,
            background,
            frames,
        })
    }

    /// How long each stored frame shows, hundredths of a second.
    pub(crate) fn delays(&self) -> impl Iterator<Item = u16> + '_ {
        self.frames.iter().map(|frame| frame.delay_cs)
    }

    /// The stored frames, decoded one at a time and drawn as a viewer draws them.
    pub(crate) fn pictures(&self) -> Pictures<'_> {
        Pictures {
            animation: self,
            next: 0,
            canvas: RgbImage::from_pixel(self.width, self.height, self.background),
            restore: None,
            changed: None,
        }
    }
}

/// The pictures of an [`Animation`], one per stored frame.
pub(crate) struct Pictures<'a> {
    animation: &'a Animation,
    next: usize,
    canvas: RgbImage,
    /// What the last frame's disposal puts back before the next is drawn: the area it covered
    /// and, if it restores what was before, those pixels (else the background).
    restore: Option<(Rect, Option<RgbImage>)>,
    /// Where the canvas may have changed since [`Pictures::take_changed`] was last called.
    changed: Option<Rect>,
}

impl Pictures<'_> {
    /// The picture shown now.
    pub(crate) fn canvas(&self) -> &RgbImage {
        &self.canvas
    }

    /// Where the canvas may have changed since the last call (`None`: nowhere).
    pub(crate) fn take_changed(&mut self) -> Option<Rect> {
        self.changed.take()
    }

    /// Notes that `area` of the canvas may change.
    fn mark(&mut self, area: Rect) {
        self.changed = Some(self.changed.map_or(area, |changed| changed.union(area)));
    }

    /// Draws the next stored frame onto the canvas (after the last, does nothing).
    pub(crate) fn advance(&mut self) -> Result<(), Trouble> {
        let Some(frame) = self.animation.frames.get(self.next) else {
            return Ok(());
        };
        let number = self.next;
        self.next += 1;
        self.dispose_of_last();
        let area = self.area_of(frame);
        self.mark(area);
        self.restore = self.disposal(frame, area);
        self.draw(frame, number, area)
    }

    /// Does the last frame's disposal: puts back the background, or what was there before
    /// it, where it was drawn.
    fn dispose_of_last(&mut self) {
        let Some((area, saved)) = self.restore.take() else {
            return;
        };
        self.mark(area);
        for (x, y) in pixels(area) {
            let before = saved.as_ref().map_or(self.animation.background, |saved| {
                *saved.get_pixel(x - area.left, y - area.top)
            });
            self.canvas.put_pixel(x, y, before);
        }
    }

    /// The part of the canvas `frame` covers (a frame may reach beyond the canvas).
    fn area_of(&self, frame: &Stored) -> Rect {
        Rect {
            left: frame.left.min(self.canvas.width()),
            top: frame.top.min(self.canvas.height()),
            width: frame
                .width
                .min(self.canvas.width().saturating_sub(frame.left)),
            height: frame
                .height
                .min(self.canvas.height().saturating_sub(frame.top)),
        }
    }

    /// What `frame`'s disposal will put back over `area` before the next frame: the
    /// background (no pixels), the pixels there now, or nothing.
    fn disposal(&self, frame: &Stored, area: Rect) -> Option<(Rect, Option<RgbImage>)> {
        match frame.dispose {
            DisposalMethod::Background => Some((area, None)),
            DisposalMethod::Previous => {
                let saved = image::imageops::crop_imm(
                    &self.canvas,
                    area.left,
                    area.top,
                    area.width,
                    area.height,
                );
                Some((area, Some(saved.to_image())))
            }
            DisposalMethod::Any | DisposalMethod::Keep => None,
        }
    }

    /// Decodes `frame`, stored frame `number`, and draws its pixels inside `area` over the
    /// canvas, leaving what is there under its transparent ones.
    fn draw(&mut self, frame: &Stored, number: usize, area: Rect) -> Result<(), Trouble> {
        let indices = lzw_indices(&frame.lzw, frame.width, frame.height, frame.interlaced)
            .ok_or_else(|| Trouble::NotWhole(format!("frame {number}'s pixels do not fill it")))?;
        let palette = frame
            .palette
            .as_deref()
            .or(self.animation.global.as_deref());
        let palette = palette.unwrap_or_default();
        let canvas_width = self.canvas.width() as usize;
        for y in area.top..area.top + area.height {
            // Row by row, as slices: this loop is most of what a check costs.
            let from = ((y - frame.top) * frame.width + (area.left - frame.left)) as usize;
            let row = &indices[from..from + area.width as usize];
            let onto = (y as usize * canvas_width + area.left as usize) * 3;
            let onto = &mut (*self.canvas)[onto..onto + area.width as usize * 3];
            for (&index, pixel) in row.iter().zip(onto.chunks_exact_mut(3)) {
                if Some(index) == frame.transparent {
                    continue;
                }
                let at = usize::from(index) * 3;
                let rgb = palette.get(at..at + 3).ok_or_else(|| {
                    Trouble::NotWhole(format!(
                        "frame {number} uses colour {index}, not in its table"
                    ))
                })?;
                pixel.copy_from_slice(rgb);
            }
        }
        Ok(())
    }
}

/// Every pixel of `area`, row by row.
fn pixels(area: Rect) -> impl Iterator<Item = (u32, u32)> {
    let columns = area.left..area.left + area.width;
    (area.top..area.top + area.height).flat_map(move |y| columns.clone().map(move |x| (x, y)))
}

/// Colour `index` of a colour table.
fn colour(palette: &[u8], index: u8) -> Option<Rgb<u8>> {
    let at = usize::from(index) * 3;
    let rgb = palette.get(at..at + 3)?;
    Some(Rgb([rgb[0], rgb[1], rgb[2]]))
}

/// A frame's palette indices in row order from its LZW data (the minimum code size, then
/// the codes), or `None` unless they are exactly `width` × `height`.
///
/// Decoded here with weezl in one piece rather than by the gif crate, whose own pixel
/// decoding rejects valid interlaced frames with rows of a few odd bytes ("image truncated",
/// image-rs/image-gif#232; browsers, Pillow, ffmpeg and ImageMagick read them).
pub fn lzw_indices(lzw: &[u8], width: u32, height: u32, interlaced: bool) -> Option<Vec<u8>> {
    let (&code_size, codes) = lzw.split_first()?;
    let mut decoder = weezl::decode::Decoder::new(weezl::BitOrder::Lsb, code_size.clamp(2, 12));
    let (width, height) = (width as usize, height as usize);
    // One byte more than a frame holds, to notice a frame that holds more.
    let mut stored = vec![0; width * height + 1];
    let (mut codes, mut filled) = (codes, 0);
    loop {
        let step = decoder.decode_bytes(codes, &mut stored[filled..]);
        codes = &codes[step.consumed_in..];
        filled += step.consumed_out;
        // A stream that ends without its end code is read as far as it goes.
        let going = matches!(step.status, Ok(weezl::LzwStatus::Ok));
        if !going || step.consumed_in + step.consumed_out == 0 {
            break;
        }
    }
    if filled != width * height {
        return None;
    }
    stored.truncate(filled);
    if !interlaced {
        return Some(stored);
    }
    let order = [(0, 8), (4, 8), (2, 4), (1, 2)]
        .into_iter()
        .flat_map(|(first, step)| (first..height).step_by(step));
    let mut pixels = vec![0; width * height];
    for (stored_row, row) in order.enumerate() {
        pixels[row * width..(row + 1) * width]
            .copy_from_slice(&stored[stored_row * width..(stored_row + 1) * width]);
    }
    Some(pixels)
}
