//! The runs of one colour an LZW dictionary holds: for each byte, the codes of the strings
//! of two, three, … of it. Most of a frame is runs of one colour, which the coder would
//! otherwise read a pixel and a lookup at a time; with these it takes a run's pixels at once
//! (`super::lzw`). The coder keeps them as it adds codes, and forgets them with its
//! dictionary.

/// The dictionary's runs of one byte, by byte.
pub(crate) struct Runs {
    /// `codes[byte]`: the codes of the strings of two, three, … `byte`s, in that order.
    /// Each list keeps its room from image to image, so it grows only when an image holds a
    /// longer run of its byte than any before: a few times a byte in a whole run. (Room for
    /// every run at once, 8 KB a byte, raised the lesson's peak memory by 1.2 MB.)
    codes: Vec<Vec<u16>>,
    /// `longest[byte]`: the code of the longest run of `byte` (`byte` itself while there is
    /// none longer), checked for every code the dictionary adds.
    longest: [u16; 256],
    /// The bytes with runs, so that forgetting them touches only those.
    bytes: Vec<u8>,
}

impl Default for Runs {
    fn default() -> Self {
        Runs {
            codes: vec![Vec::new(); 256],
            longest: std::array::from_fn(|byte| byte as u16),
            bytes: Vec::with_capacity(256),
        }
    }
}

impl Runs {
    /// Notes `code`, the string `before` followed by `byte`, if it is a run: the longest run
    /// of `byte` so far, one `byte` longer. (A dictionary adds each string one byte longer
    /// than one it holds, so each run comes after the run one byte shorter.)
    #[inline(always)]
    pub fn note(&mut self, before: u16, byte: u8, code: u16) {
        let index = usize::from(byte);
        if before == self.longest[index] {
            if self.codes[index].is_empty() {
                self.bytes.push(byte);
            }
            self.codes[index].push(code);
            self.longest[index] = code;
        }
    }

    /// The codes of the runs of two, three, … `byte`s.
    #[inline(always)]
    pub fn of(&self, byte: u8) -> &[u16] {
        &self.codes[usize::from(byte)]
    }

    /// Forgets every run, with the dictionary.
    pub fn forget(&mut self) {
        for byte in self.bytes.drain(..) {
            self.codes[usize::from(byte)].clear();
            self.longest[usize::from(byte)] = u16::from(byte);
        }
    }
}

/// How many of `bytes` are `byte` before the first that is not: eight compared at a time.
pub(crate) fn leading(bytes: &[u8], byte: u8) -> usize {
    let eight = u64::from_le_bytes([byte; 8]);
    let mut chunks = bytes.chunks_exact(8);
    let mut count = 0;
    for chunk in &mut chunks {
        let chunk = u64::from_le_bytes(chunk.try_into().expect("chunks of eight"));
        let differ = chunk ^ eight;
        if differ != 0 {
            // The lowest byte is the first: the first that differs has the lowest set bit.
            return count + (differ.trailing_zeros() / 8) as usize;
        }
        count += 8;
    }
    count
        + chunks
            .remainder()
            .iter()
            .take_while(|&&next| next == byte)
            .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_code_is_noted_as_a_run_only_when_it_adds_a_byte_to_that_bytes_longest_run() {
        let mut runs = Runs::default();
        runs.note(5, 5, 100); // 5 5
        runs.note(100, 6, 101); // 5 5 6: not a run
        runs.note(100, 5, 102); // 5 5 5
        runs.note(6, 5, 103); // 6 5: not a run
        runs.note(6, 6, 104); // 6 6
        assert_eq!(
            (runs.of(5), runs.of(6), runs.of(7)),
            (&[100, 102][..], &[104][..], &[][..])
        );
        runs.forget();
        assert!(runs.codes.iter().all(Vec::is_empty), "forgotten");
        runs.note(5, 5, 200);
        runs.note(200, 5, 201);
        runs.note(6, 6, 202);
        assert_eq!(
            (runs.of(5), runs.of(6)),
            (&[200, 201][..], &[202][..]),
            "a fresh dictionary's runs start again"
        );
    }

    #[test]
    fn leading_counts_the_bytes_before_the_first_other_one() {
        for len in 0..40 {
            for first_other in 0..=len {
                let mut bytes = vec![9; len];
                if first_other < len {
                    bytes[first_other] = 8;
                }
                assert_eq!(leading(&bytes, 9), first_other, "{len} bytes");
            }
        }
    }
}
