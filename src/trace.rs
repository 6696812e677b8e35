//! The `--trace` CSV: every ball's state in every frame, as drawn, for answering the
//! lesson's questions with numbers; and how every CSV of the program writes a number.

use std::io::{self, Write};

use crate::physics::ball::Ball;

/// The CSV's first line.
pub(crate) const HEADER: &str = "frame,ball,x,y,vx,vy";

/// Writes the header.
pub(crate) fn write_header(out: &mut impl Write) -> io::Result<()> {
    writeln!(out, "{HEADER}")
}

/// Writes one row per ball.
pub(crate) fn write_frame(out: &mut impl Write, frame: u32, balls: &[Ball]) -> io::Result<()> {
    for (i, b) in balls.iter().enumerate() {
        let [x, y, vx, vy] = [b.x, b.y, b.vx, b.vy].map(number);
        writeln!(out, "{frame},{i},{x},{y},{vx},{vy}")?;
    }
    Ok(())
}

/// A number as every CSV of the program writes it: the shortest decimal that reads back to
/// the same bits, in plain digits unless they would be long (Python's rule for `repr`: an
/// exponent below 1e-4 and from 1e16 up), so `228.5`, `1.2e-15`, `1e300`.
pub(crate) fn number(value: f64) -> String {
    let size = value.abs();
    if size != 0.0 && size.is_finite() && !(1e-4..1e16).contains(&size) {
        format!("{value:e}")
    } else {
        format!("{value}")
    }
}

#[cfg(test)]
mod tests {
    use super::number;

    #[test]
    fn a_number_reads_back_to_its_bits_with_an_exponent_only_where_digits_would_be_long() {
        for (value, written) in [
            (228.0, "228"),
            (7.916993685943776, "7.916993685943776"),
            (-0.234, "-0.234"),
            (0.0001, "0.0001"),
            (1.2e-15, "1.2e-15"),
            (1e300, "1e300"),
            (-2.5e16, "-2.5e16"),
            (0.0, "0"),
        ] {
            assert_eq!(number(value), written, "{value:?}");
            assert_eq!(
                number(value).parse::<f64>(),
                Ok(value),
                "{written} reads back"
            );
        }
    }
}
