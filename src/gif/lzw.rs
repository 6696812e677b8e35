//! GIF's LZW compression of palette indices: the dictionary coder every GIF uses, written
//! out here because it is the hot loop of the whole program. With its dictionary as one flat
//! table it runs about twice as fast on our frames as the gif crate's coder (weezl), and
//! writes the same bytes (tests/encode.rs checks) until the dictionary fills, where it
//! starts afresh one code later.
//!
//! LZW reads bytes while the string read so far is in its dictionary; at the first byte
//! that makes an unknown string it writes the known string's code, adds the new string as
//! the next code, and starts again from that byte. Codes grow from `min_code_size + 1` bits
//! to 12 as the dictionary fills; once it is full ([`Choices::max_codes`], at most 4096) it
//! writes a clear code and starts afresh. Every decoder rebuilds the same dictionary from
//! the codes.
//!
//! Clearing the dictionary earlier than GIF requires keeps the output valid and can make it
//! smaller: a small dictionary has short codes ([`Choices::max_codes`]). So can keeping a
//! full dictionary to the end instead of clearing it ([`Choices::clear_when_full`]). Codings
//! with other choices write the same bytes as the plain one until their dictionaries part,
//! so they start from there ([`Fork`]).
//!
//! Each pixel's lookup needs the code the last one found, so a coding mostly waits for
//! memory. But most of a frame is runs of one colour, and the strings of two, three, … of
//! one colour are in the dictionary in that order: so a string that starts on a run takes
//! as much of it as the longest of those at once, without a lookup per pixel (`super::runs`).
//! It is the same string, so the same bytes.

use std::ops::Range;

use super::runs::{leading, Runs};

/// GIF codes are at most 12 bits wide.
const MAX_CODE_BITS: u8 = 12;
/// So a dictionary holds at most this many codes.
const MAX_CODES: u16 = 1 << MAX_CODE_BITS;
/// Entries in the dictionary's table: one per code and byte.
const TABLE_LEN: usize = (MAX_CODES as usize) << 8;
/// How many more codes' entries are written out at a time ([`Lzw::rows_written`]).
const CODES_WRITTEN_AT_ONCE: u16 = 512;

/// How the coder chooses, where each choice keeps the output a valid GIF.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Choices {
    /// The dictionary is full once it holds this many codes (at most 4096).
    pub max_codes: u16,
    /// What happens then: a clear code and a fresh dictionary, or (when false) the full
    /// dictionary kept as it is to the end of the image, adding nothing more (a "deferred
    /// clear", which every decoder follows).
    pub clear_when_full: bool,
}

impl Choices {
    /// The plain coder every GIF writer uses: clearing only a full 4096-code dictionary.
    pub const GREEDY: Choices = Choices {
        max_codes: MAX_CODES,
        clear_when_full: true,
    };

    /// A small dictionary, cleared every 512 codes: its codes stay at most 9 bits, which
    /// suits images with few strings (measured in docs/gif.md).
    pub const SMALL: Choices = Choices {
        max_codes: 512,
        clear_when_full: true,
    };

    /// Half the dictionary, cleared every 2048 codes: codes stay at most 11 bits, which suits
    /// big images whose later part repeats few of the earlier part's strings (a canvas empty
    /// above and full below: the first frame of `pyramid`).
    pub const HALF: Choices = Choices {
        max_codes: MAX_CODES / 2,
        clear_when_full: true,
    };

    /// The full dictionary kept once it fills: suits big images whose first part holds the
    /// strings of the rest (gifsicle -O3 does the same).
    pub const KEEP_FULL: Choices = Choices {
        max_codes: MAX_CODES,
        clear_when_full: false,
    };
}

/// Where a greedy coding stood when its dictionary first held as many codes as another
/// choice's is allowed. Up to there the two write the very same bytes, so the other can start
/// from here ([`Lzw::compress_from`]) instead of from the first pixel.
#[derive(Clone, Copy, Debug)]
pub struct Fork {
    state: Coding,
    /// Which coding it forks from (the coder counts its codings).
    coding: u64,
    /// How many bytes were written, and the bits not yet written.
    bytes: usize,
    pending: u64,
    pending_bits: u8,
}

/// Where a coding is: the next pixel to read, the code width, the next free code, and the
/// most codes the dictionary has held.
#[derive(Clone, Copy, Debug)]
struct Coding {
    at: usize,
    width: u8,
    free: u16,
    most: u16,
}

impl Coding {
    /// The start of an image: an empty dictionary, whose first free code comes after the
    /// indices, the clear code and the end code.
    fn fresh(min_code_size: u8) -> Coding {
        Coding {
            at: 0,
            width: min_code_size + 1,
            free: (1 << min_code_size) + 2,
            most: 0,
        }
    }
}

/// The last coding's forks: where its dictionary first held [`Choices::SMALL`]'s and
/// [`Choices::HALF`]'s number of codes, and where it was first full.
#[derive(Clone, Copy, Debug, Default)]
pub struct Forks {
    pub small: Option<Fork>,
    pub half: Option<Fork>,
    pub full: Option<Fork>,
}

/// An LZW coder. Its dictionary table is big (2 MB) and built once, then reused for every
/// image it compresses: only the entries an image set are cleared afterwards.
pub struct Lzw {
    /// `next[byte * 4096 + code]`: the code of string `code` followed by `byte`, or 0 while
    /// that string is not in the dictionary (0 is a one-byte string, never a longer one).
    /// Byte-major, so a run of one colour walks neighbouring entries.
    next: Box<[u16; TABLE_LEN]>,
    /// The entries of `next` set since the last clear.
    set: Vec<usize>,
    forks: Forks,
    /// The number of codes at which the greedy coding being written takes its next fork, or
    /// 0 once it has taken them all (and for a coding started from a fork, which takes none).
    next_fork: u16,
    /// How much of the table has been written: the entries of each code below
    /// `codes_written` in each row (one per byte) below `rows_written`. Memory the system
    /// hands over zeroed is mapped to one shared zero page until first written; a coder reads
    /// an entry before it writes it, so each page would fault twice, the second time stopping
    /// the other cores to flush their address caches (a tenth of a default run's time went
    /// there). So the entries a coding can read are written out before it reads them: the
    /// rows its image can use, for the codes its dictionary holds so far. The dictionary of a
    /// small image never holds many codes, so most of the table is never touched at all.
    rows_written: usize,
    codes_written: u16,
    /// How many codings the coder has begun, and the last one's dictionary where it was
    /// first full (`set` then): a coding that keeps it full goes on from there.
    codings: u64,
    full_dictionary: Vec<usize>,
    /// The dictionary's runs of one byte, so that a string takes a run at once.
    runs: Runs,
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
            next: vec![0; TABLE_LEN]
                .into_boxed_slice()
                .try_into()
                .expect("a table of TABLE_LEN entries"),
            rows_written: 0,
            codes_written: 0,
            set: Vec::with_capacity(usize::from(MAX_CODES)),
            forks: Forks::default(),
            next_fork: 0,
            codings: 0,
            full_dictionary: Vec::with_capacity(usize::from(MAX_CODES)),
            runs: Runs::default(),
        }
    }

    /// Compresses `pixels` (each below `2^min_code_size`) into `out`, cleared first, as a GIF
    /// image's data: the `min_code_size` byte, then the codes packed least significant bit
    /// first (sub-block framing is left to the writer). Returns the most codes the dictionary
    /// held at once, or gives up, returning `None`, as soon as `out` reaches `budget` bytes: a
    /// candidate that cannot win need not be finished.
    pub fn compress(
        &mut self,
        min_code_size: u8,
        pixels: &[u8],
        choices: Choices,
        budget: usize,
        out: &mut Vec<u8>,
    ) -> Option<u16> {
        let coding = self.begin(min_code_size, pixels, choices, budget, out);
        self.code(coding)
    }

    /// Starts a greedy or other coding of `pixels` into `out` from the first pixel: the code
    /// size, a clear code, an empty dictionary.
    fn begin<'p, 'o>(
        &mut self,
        min_code_size: u8,
        pixels: &'p [u8],
        choices: Choices,
        budget: usize,
        out: &'o mut Vec<u8>,
    ) -> Stream<'p, 'o> {
        out.clear();
        out.push(min_code_size);
        let mut bits = BitPacker::new(out);
        let start = Coding::fresh(min_code_size);
        bits.put(1 << min_code_size, start.width);
        self.forks = Forks::default();
        self.next_fork = Choices::SMALL.max_codes;
        self.codings += 1;
        self.write_table(1 << min_code_size, start.free);
        Stream::new(start, min_code_size, pixels, choices, budget, bits)
    }

    /// Where the last finished greedy coding could fork into another choice; a fork is
    /// `None` when the dictionary never grew that far (then both codings are the same).
    pub fn forks(&self) -> Forks {
        self.forks
    }

    /// The same as compressing `pixels` again with `choices`, but starting from `fork`, the
    /// fork for `choices` of the greedy coding whose output is `first` (same pixels). A fork
    /// into a dictionary kept full needs that dictionary, which the coder keeps only until its
    /// next [`Lzw::compress`].
    pub fn compress_from(
        &mut self,
        fork: Fork,
        choices: Choices,
        pixels: &[u8],
        first: &[u8],
        budget: usize,
        out: &mut Vec<u8>,
    ) -> Option<u16> {
        // Image data starts with its code size (see `compress`), so the fork's is there.
        let min_code_size = first[0];
        out.clear();
        out.extend_from_slice(&first[..fork.bytes]);
        self.next_fork = 0;
        let mut bits = BitPacker {
            out,
            pending: fork.pending,
            pending_bits: fork.pending_bits,
        };
        // Here the dictionary has just reached `choices`' size: the greedy coding went on
        // (or cleared), this one does what its choices say. (The table is written out far
        // enough: a cleared dictionary starts afresh, and one kept full is this coder's own.)
        let mut state = fork.state;
        if state.free >= choices.max_codes && choices.clear_when_full {
            clear_dictionary(&mut state, min_code_size, &mut bits);
        } else {
            assert_eq!(
                fork.coding, self.codings,
                "a fork into a full dictionary is taken before the next coding"
            );
            self.restore_full_dictionary(Coding::fresh(min_code_size).free);
        }
        let coding = Stream::new(state, min_code_size, pixels, choices, budget, bits);
        self.code(coding)
    }

    /// Fills the dictionary, empty, with the last greedy coding's where it was first full,
    /// its runs included: the strings from `first_code` on.
    fn restore_full_dictionary(&mut self, first_code: u16) {
        let dictionary = std::mem::take(&mut self.full_dictionary);
        for (code, &slot) in (first_code..).zip(&dictionary) {
            self.next[slot] = code;
            let (before, byte) = unslot(slot);
            self.runs.note(before, byte, code);
        }
        self.set.clone_from(&dictionary);
        self.full_dictionary = dictionary;
    }

    /// Codes the rest of `stream`'s pixels: the LZW loop itself.
    fn code(&mut self, mut stream: Stream) -> Option<u16> {
        loop {
            let (code, read) = self.walk(stream.code, stream.unread());
            stream.code = code;
            stream.read += read;
            if stream.unread().is_empty() {
                return stream.finish(self);
            }
            if !stream.extend(self) {
                return None;
            }
        }
    }

    /// Reads on from the string `code` while the longer strings are in the dictionary: the
    /// longest one's code, and how many of `pixels` it took.
    fn walk(&self, mut code: u16, pixels: &[u8]) -> (u16, usize) {
        for (read, &byte) in pixels.iter().enumerate() {
            let longer = self.next[slot(code, byte)];
            if longer == 0 {
                return (code, read);
            }
            code = longer;
        }
        (code, pixels.len())
    }

    /// Writes the table's entries for the bytes below `rows` and the codes below `codes` out,
    /// where not yet done, [`CODES_WRITTEN_AT_ONCE`] codes at a time.
    fn write_table(&mut self, rows: usize, codes: u16) {
        let (old_rows, old_codes) = (self.rows_written, self.codes_written);
        let codes = codes.next_multiple_of(CODES_WRITTEN_AT_ONCE).min(MAX_CODES);
        let (rows, codes) = (rows.max(old_rows), codes.max(old_codes));
        if (rows, codes) == (old_rows, old_codes) {
            return; // the common case: written already
        }
        // The rows written before, for their new codes; then the new rows, for every code.
        let mut write = |these_rows: Range<usize>, these_codes: Range<u16>| {
            for row in these_rows {
                let entries = &mut self.next[row << MAX_CODE_BITS..];
                let entries = &mut entries[these_codes.start.into()..these_codes.end.into()];
                // `black_box` hides that the memory is zero already, so the writes stay.
                std::hint::black_box(entries).fill(0);
            }
        };
        write(0..old_rows, old_codes..codes);
        write(old_rows..rows, 0..codes);
        (self.rows_written, self.codes_written) = (rows, codes);
    }

    /// Keeps where the dictionary first reached the small size, then the half size, then
    /// where it was first full (the greedy coding reaches them in that order, before its first
    /// clear), and waits for the next. Called only when it reaches `next_fork`, so the hot
    /// loop pays one comparison per code.
    fn note_fork(&mut self, state: Coding, bits: &BitPacker) {
        let fork = Some(Fork {
            state,
            coding: self.codings,
            bytes: bits.out.len(),
            pending: bits.pending,
            pending_bits: bits.pending_bits,
        });
        if state.free == Choices::SMALL.max_codes {
            self.forks.small = fork;
            self.next_fork = Choices::HALF.max_codes;
        } else if state.free == Choices::HALF.max_codes {
            self.forks.half = fork;
            self.next_fork = MAX_CODES;
        } else {
            self.forks.full = fork;
            self.full_dictionary.clone_from(&self.set);
            self.next_fork = 0;
        }
    }

    /// Empties the dictionary by undoing only the entries that were set.
    fn forget(&mut self) {
        for slot in self.set.drain(..) {
            self.next[slot] = 0;
        }
        self.runs.forget();
    }
}

/// A coding under way: where it is, the string it is reading, and the output so far.
struct Stream<'p, 'o> {
    state: Coding,
    min_code_size: u8,
    pixels: &'p [u8],
    /// The string read so far, whose next pixel is `pixels[read]`.
    code: u16,
    read: usize,
    choices: Choices,
    budget: usize,
    bits: BitPacker<'o>,
}

impl<'p, 'o> Stream<'p, 'o> {
    /// A coding of `pixels` whose next string starts at `state.at`, the output so far in
    /// `bits`.
    fn new(
        state: Coding,
        min_code_size: u8,
        pixels: &'p [u8],
        choices: Choices,
        budget: usize,
        bits: BitPacker<'o>,
    ) -> Stream<'p, 'o> {
        // Every single index is a string: the next string starts as its first pixel.
        let (code, read) = match pixels.get(state.at) {
            Some(&byte) => (u16::from(byte), state.at + 1),
            None => (0, state.at),
        };
        Stream {
            state,
            min_code_size,
            pixels,
            code,
            read,
            choices,
            budget,
            bits,
        }
    }

    /// The pixels not yet read.
    fn unread(&self) -> &'p [u8] {
        &self.pixels[self.read..]
    }

    /// Where the string cannot grow by the next pixel: writes its code, adds it followed by
    /// that pixel to `lzw`'s dictionary (or clears a full one), and starts the next string
    /// there. Returns false, giving up, once the output has reached the budget. (Inlined
    /// into the loops: called as a function, it made the coder 7 % slower.)
    #[inline(always)]
    fn extend(&mut self, lzw: &mut Lzw) -> bool {
        let state = &mut self.state;
        self.bits.put(self.code, state.width);
        if self.bits.out.len() >= self.budget {
            lzw.forget();
            return false;
        }
        state.at = self.read;
        if state.free == lzw.next_fork {
            lzw.note_fork(*state, &self.bits);
        }
        let byte = self.pixels[self.read];
        if state.free < self.choices.max_codes.min(MAX_CODES) {
            let slot = slot(self.code, byte);
            lzw.next[slot] = state.free;
            lzw.set.push(slot);
            lzw.runs.note(self.code, byte, state.free);
            state.free += 1;
            if state.free > lzw.codes_written {
                lzw.write_table(lzw.rows_written, state.free);
            }
            // The decoder adds each code one code after we do, and widens once its next
            // free code no longer fits: so we widen once ours is one past that.
            if state.free > 1 << state.width {
                state.width += 1;
            }
        } else if self.choices.clear_when_full {
            clear_dictionary(state, self.min_code_size, &mut self.bits);
            lzw.forget();
        }
        self.code = u16::from(byte);
        self.read += 1;
        self.take_run(byte, lzw.runs.of(byte));
        true
    }

    /// From the string of one `byte`: takes the `byte`s that follow it at once, as far as
    /// `runs` (that byte's runs in the dictionary) reach. The same string as reading them one
    /// by one, without a lookup for each.
    #[inline(always)]
    fn take_run(&mut self, byte: u8, runs: &[u16]) {
        // Most strings do not start on a run: one comparison says so.
        if self.pixels.get(self.read) != Some(&byte) {
            return;
        }
        let ahead = &self.pixels[self.read..];
        let ahead = &ahead[..runs.len().min(ahead.len())];
        let same = leading(ahead, byte);
        if same > 0 {
            self.code = runs[same - 1];
            self.read += same;
        }
    }

    /// With every pixel read: writes the last string's code and the end code. Returns the
    /// most codes the dictionary held, or `None` if the output reached the budget.
    fn finish(mut self, lzw: &mut Lzw) -> Option<u16> {
        let state = &mut self.state;
        if !self.pixels.is_empty() {
            self.bits.put(self.code, state.width);
            // The end code is read once the decoder has caught up with the last code added.
            if state.free == 1 << state.width && state.width < MAX_CODE_BITS {
                state.width += 1;
            }
        }
        let end = (1u16 << self.min_code_size) + 1;
        self.bits.put(end, state.width);
        let written = self.bits.finish();
        lzw.forget();
        (written < self.budget).then_some(state.most.max(state.free))
    }
}

/// Writes a clear code and starts the codes afresh (the caller empties the dictionary).
fn clear_dictionary(state: &mut Coding, min_code_size: u8, bits: &mut BitPacker) {
    // The decoder has caught up when it reads the clear code, so it reads it at the width
    // its own next free code needs.
    if state.free == 1 << state.width && state.width < MAX_CODE_BITS {
        state.width += 1;
    }
    bits.put(1 << min_code_size, state.width);
    *state = Coding {
        at: state.at,
        most: state.most.max(state.free),
        ..Coding::fresh(min_code_size)
    };
}

/// Where `Lzw::next` keeps the code of string `code` followed by `byte`.
fn slot(code: u16, byte: u8) -> usize {
    // Codes are below 4096, so this is always inside the table, and the compiler can see it
    // (no bounds check in the hot loop).
    usize::from(byte) << MAX_CODE_BITS | usize::from(code & (MAX_CODES - 1))
}

/// The string and the byte whose entry [`slot`] gives.
fn unslot(slot: usize) -> (u16, u8) {
    (
        (slot & usize::from(MAX_CODES - 1)) as u16,
        (slot >> MAX_CODE_BITS) as u8,
    )
}

/// Packs codes of any width into bytes, least significant bit first, as GIF wants.
struct BitPacker<'a> {
    out: &'a mut Vec<u8>,
    /// Bits not yet written, lowest first: written four bytes at a time.
    pending: u64,
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
        self.pending |= u64::from(code) << self.pending_bits;
        self.pending_bits += width;
        if self.pending_bits >= 32 {
            self.out
                .extend_from_slice(&(self.pending as u32).to_le_bytes());
            self.pending >>= 32;
            self.pending_bits -= 32;
        }
    }

    /// Writes the last bits out; returns how many bytes were written in all.
    fn finish(self) -> usize {
        let bytes = self.pending.to_le_bytes();
        self.out
            .extend_from_slice(&bytes[..usize::from(self.pending_bits.div_ceil(8))]);
        self.out.len()
    }
}

/// A GIF image's smallest code size: bits enough for every index of a table of `colours`,
/// and never under 2 (the format's floor).
pub fn min_code_size(colours: usize) -> u8 {
    let bits = usize::BITS - colours.saturating_sub(1).leading_zeros();
    bits.max(2) as u8
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::random::Random;

    /// `count` pixels of random indices below `colours`, and their greedy coding by `lzw`:
    /// the most codes its dictionary held.
    fn code_noise(lzw: &mut Lzw, count: usize, colours: u64) -> u16 {
        let mut random = Random::new(7);
        let pixels: Vec<u8> = (0..count)
            .map(|_| (random.next_u64() % colours) as u8)
            .collect();
        let code_size = min_code_size(colours as usize);
        let mut out = Vec::new();
        lzw.compress(code_size, &pixels, Choices::GREEDY, usize::MAX, &mut out)
            .expect("no budget to give up at")
    }

    /// The runs of `byte` that `lzw`'s table holds, found by walking it from `byte` along
    /// `byte`s: the codes of two, three, … `byte`s.
    fn runs_in_table(lzw: &Lzw, byte: u8) -> Vec<u16> {
        let mut runs = Vec::new();
        let mut code = u16::from(byte);
        while lzw.next[slot(code, byte)] != 0 {
            code = lzw.next[slot(code, byte)];
            runs.push(code);
        }
        runs
    }

    #[test]
    fn a_string_that_starts_on_a_run_takes_as_much_of_it_as_the_dictionary_holds() {
        let pixels = [5, 5, 5, 5, 5, 5, 7, 5];
        // (runs of 5 in the dictionary, where the string starts) → (its code, pixels read)
        let cases: [(&[u16], usize, u16, usize); 5] = [
            (&[], 0, 5, 1),                               // no run of two yet
            (&[100, 101, 102], 0, 102, 4),                // the longest run held
            (&[100, 101, 102, 103, 104, 105], 0, 104, 6), // the image's whole run
            (&[100], 6, 7, 7),                            // no run of 7 follows
            (&[100, 101], 7, 5, 8),                       // no pixel left
        ];
        for (runs, at, code, read) in cases {
            let mut out = Vec::new();
            let state = Coding {
                at,
                ..Coding::fresh(3)
            };
            let choices = Choices::GREEDY;
            let bits = BitPacker::new(&mut out);
            let mut stream = Stream::new(state, 3, &pixels, choices, usize::MAX, bits);
            stream.take_run(pixels[at], runs);
            assert_eq!(
                (stream.code, stream.read),
                (code, read),
                "{runs:?} from {at}"
            );
        }
    }

    #[test]
    fn the_full_dictionary_restored_holds_its_runs() {
        let mut lzw = Lzw::new();
        // Runs of 1 to 12 of four bytes fill the dictionary, runs of each byte among them.
        let mut random = Random::new(3);
        let mut pixels = Vec::new();
        while pixels.len() < 60_000 {
            let (byte, run) = (random.next_u64() % 4, 1 + random.next_u64() % 12);
            pixels.extend(std::iter::repeat_n(byte as u8, run as usize));
        }
        let mut out = Vec::new();
        lzw.compress(2, &pixels, Choices::GREEDY, usize::MAX, &mut out);
        assert!(lzw.forks.full.is_some(), "the dictionary filled");
        lzw.restore_full_dictionary(Coding::fresh(2).free);
        for byte in 0..4 {
            let runs = runs_in_table(&lzw, byte);
            assert!(runs.len() >= 8, "{} runs of {byte}", runs.len());
            assert_eq!(lzw.runs.of(byte), runs, "runs of {byte}");
        }
    }

    #[test]
    fn a_small_image_writes_out_only_the_start_of_its_rows() {
        let mut lzw = Lzw::new();
        let most = code_noise(&mut lzw, 300, 4);
        assert!(most < CODES_WRITTEN_AT_ONCE, "{most} codes held");
        assert_eq!(
            (lzw.rows_written, lzw.codes_written),
            (4, CODES_WRITTEN_AT_ONCE),
            "rows and codes written out, where the dictionary held {most} codes"
        );
    }

    #[test]
    fn the_table_is_written_out_ahead_of_every_code_the_dictionary_holds() {
        let mut lzw = Lzw::new();
        let most = code_noise(&mut lzw, 3000, 16);
        assert!(most > 2 * CODES_WRITTEN_AT_ONCE, "{most} codes held");
        assert!(lzw.codes_written >= most, "{} < {most}", lzw.codes_written);
        assert!(lzw.codes_written - most < CODES_WRITTEN_AT_ONCE);
        // A later image with more indices adds its rows, as long as the others.
        let written = lzw.codes_written;
        code_noise(&mut lzw, 10, 64);
        assert_eq!((lzw.rows_written, lzw.codes_written), (64, written));
    }
}
