//! GIF's LZW compression of palette indices: the dictionary coder every GIF uses, written
//! out here because it is the hot loop of the whole program. With its dictionary as one flat
//! table it runs about twice as fast on our frames as the gif crate's coder (weezl), and
//! writes the same bytes (tests/encode.rs checks) until the dictionary fills, where it
//! starts afresh one code later.
//!
//! LZW reads bytes while the string read so far is in its dictionary; at the first byte
//! that makes an unknown string it writes the known string's code, adds the new string as
//! the next code, and starts again from that byte. Codes grow from `min_code_size + 1` bits
//! to 12 as the dictionary fills; when all 4096 codes are taken it writes a clear code and
//! starts a fresh dictionary. Every decoder rebuilds the same dictionary from the codes.

/// GIF codes are at most 12 bits wide.
const MAX_CODE_BITS: u8 = 12;
/// So a dictionary holds at most this many codes.
const MAX_CODES: u16 = 1 << MAX_CODE_BITS;

/// An LZW coder. Its dictionary table is big (2 MB) and built once, then reused for every
/// image it compresses: only the entries an image set are cleared afterwards.
pub struct Lzw {
    /// `next[byte * 4096 + code]`: the code of string `code` followed by `byte`, or 0 while
    /// that string is not in the dictionary (0 is a one-byte string, never a longer one).
    /// Byte-major, so a run of one colour walks neighbouring entries.
    next: Vec<u16>,
    /// The entries of `next` set since the last clear.
    set: Vec<usize>,
}

impl Default for Lzw {
    fn default() -> Self {
        Lzw::new()
    }
}

impl Lzw {
    /// A coder with an empty dictionary.
    pub fn new() -> Lzw {
        Lzw {
            next: vec![0; usize::from(MAX_CODES) * 256],
            set: Vec::with_capacity(usize::from(MAX_CODES)),
        }
    }

    /// Compresses `pixels` (each below `2^min_code_size`) into `out`, cleared first, as a GIF
    /// image's data: the `min_code_size` byte, then the codes packed least significant bit
    /// first (sub-block framing is left to the writer).
    pub fn compress(&mut self, min_code_size: u8, pixels: &[u8], out: &mut Vec<u8>) {
        out.clear();
        out.push(min_code_size);
        let clear = 1u16 << min_code_size;
        let end = clear + 1;
        let mut bits = BitPacker::new(out);
        let mut width = min_code_size + 1;
        let mut free = end + 1;
        bits.put(clear, width);
        let mut bytes = pixels.iter().map(|&b| u16::from(b));
        if let Some(first) = bytes.next() {
            let mut string = first;
            for byte in bytes {
                let slot = usize::from(byte) * usize::from(MAX_CODES) + usize::from(string);
                let longer = self.next[slot];
                if longer != 0 {
                    string = longer;
                    continue;
                }
                bits.put(string, width);
                if free < MAX_CODES {
                    self.next[slot] = free;
                    self.set.push(slot);
                    free += 1;
                    // The decoder adds each code one code after we do, and widens once its
                    // next free code no longer fits: so we widen once ours is one past that.
                    if free > 1 << width {
                        width += 1;
                    }
                } else {
                    bits.put(clear, width);
                    self.forget();
                    width = min_code_size + 1;
                    free = end + 1;
                }
                string = byte;
            }
            bits.put(string, width);
            // On reading `string` the decoder catches up with us, so the end code is read
            // at the width our own next free code needs.
            if free == 1 << width && width < MAX_CODE_BITS {
                width += 1;
            }
        }
        bits.put(end, width);
        bits.finish();
        self.forget();
    }

    /// Empties the dictionary by undoing only the entries that were set.
    fn forget(&mut self) {
        for slot in self.set.drain(..) {
            self.next[slot] = 0;
        }
    }
}

/// Packs codes of any width into bytes, least significant bit first, as GIF wants.
struct BitPacker<'a> {
    out: &'a mut Vec<u8>,
    pending: u32,
    pending_bits: u8,
}

impl<'a> BitPacker<'a> {
    fn new(out: &'a mut Vec<u8>) -> Self {
        BitPacker {
            out,
            pending: 0,
            pending_bits: 0,
        }
    }

    fn put(&mut self, code: u16, width: u8) {
        self.pending |= u32::from(code) << self.pending_bits;
        self.pending_bits += width;
        while self.pending_bits >= 8 {
            self.out.push(self.pending as u8);
            self.pending >>= 8;
            self.pending_bits -= 8;
        }
    }

    fn finish(self) {
        if self.pending_bits > 0 {
            self.out.push(self.pending as u8);
        }
    }
}

/// A GIF image's smallest code size: bits enough for every index of a table of `colours`,
/// and never under 2 (the format's floor).
pub fn min_code_size(colours: usize) -> u8 {
    let bits = usize::BITS - colours.saturating_sub(1).leading_zeros();
    bits.max(2) as u8
}
