//! The `--trace` CSV: every ball's state in every frame, as drawn, for answering the
//! lesson's questions with numbers.

use std::io::{self, Write};

use crate::physics::ball::Ball;

/// The CSV's first line.
pub const HEADER: &str = "frame,ball,x,y,vx,vy";

/// Writes the header.
pub fn write_header(out: &mut impl Write) -> io::Result<()> {
    writeln!(out, "{HEADER}")
}

/// Writes one row per ball; Rust's `{}` prints the shortest text that reads back to the same f64.
pub fn write_frame(out: &mut impl Write, frame: u32, balls: &[Ball]) -> io::Result<()> {
    for (i, b) in balls.iter().enumerate() {
        writeln!(out, "{frame},{i},{},{},{},{}", b.x, b.y, b.vx, b.vy)?;
    }
    Ok(())
}
