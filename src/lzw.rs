//! GIF's LZW compression of palette indices, into a buffer that is reused frame after frame.
//!
//! The coder is weezl, the one the gif crate itself uses. Calling it directly, rather than
//! through `gif::Frame::make_lzw_pre_encoded` (which allocates a new buffer for every
//! frame), lets the encoder keep its coders and output buffers for the whole run.

use std::io;

use weezl::{encode::Encoder, BitOrder};

/// An LZW coder for the indices of one colour table, reset (not rebuilt) between images.
pub struct Lzw {
    code_size: u8,
    coder: Encoder,
}

impl Lzw {
    /// A coder for indices into a table of `colours` entries.
    pub fn new(colours: usize) -> Lzw {
        let code_size = min_code_size(colours);
        Lzw {
            code_size,
            coder: Encoder::new(BitOrder::Lsb, code_size),
        }
    }

    /// Compresses `pixels` into `out` (cleared first) as a GIF image's data: the code size
    /// byte, then the LZW stream, as `gif::Encoder::write_lzw_pre_encoded_frame` expects.
    /// Fails only on an index outside the colour table.
    pub fn compress(&mut self, pixels: &[u8], out: &mut Vec<u8>) -> io::Result<()> {
        out.clear();
        out.push(self.code_size);
        self.coder.reset();
        let result = self.coder.into_vec(out).encode_all(pixels);
        result.status.map(drop).map_err(io::Error::other)
    }
}

/// A GIF image's smallest code size: bits enough for every index of a table of `colours`,
/// and never under 2 (the format's floor).
pub fn min_code_size(colours: usize) -> u8 {
    let bits = usize::BITS - colours.saturating_sub(1).leading_zeros();
    bits.max(2) as u8
}
