//! A handed-in trajectory: the main command's `--trace` CSV (`frame,ball,x,y,vx,vy`), or the
//! `x y vx vy` lines the lesson's loop prints for its one ball, frame by frame.

use super::expected::ExpectedMotion;
use super::found::{Finding, First, Trouble};
use crate::trace::HEADER;

/// Every row of a trajectory, frame by frame and ball by ball within a frame.
pub(crate) struct TrajectoryFile {
    rows: Vec<Row>,
    /// Whether it is the lesson's one-ball lines (no frame or ball numbers).
    plain: bool,
}

/// One ball in one frame; `frame` and `ball` are `None` in the lesson's plain lines.
struct Row {
    line: usize,
    at: Option<(u32, usize)>,
    state: [f64; 4],
}

const NAMES: [&str; 4] = ["x", "y", "vx", "vy"];

impl TrajectoryFile {
    /// The trajectory in `text`; `None` if it looks like neither kind.
    pub fn parse(text: &str) -> Option<Result<TrajectoryFile, Trouble>> {
        let mut lines = text
            .lines()
            .enumerate()
            .filter(|(_, l)| !l.trim().is_empty());
        let (_, first) = lines.clone().next()?;
        let plain = first.trim() != HEADER;
        if plain && numbers(first, ' ').is_none_or(|n| n.len() != 4) {
            return None;
        }
        if !plain {
            lines.next();
        }
        let rows = lines.map(|(n, line)| {
            let bad = || Trouble::Trajectory {
                line: n + 1,
                expected: if plain { "x y vx vy" } else { HEADER },
                got: line.chars().take(60).collect(),
            };
            let values = numbers(line, if plain { ' ' } else { ',' }).ok_or_else(bad)?;
            match (plain, values.as_slice()) {
                (true, &[x, y, vx, vy]) => Ok(Row {
                    line: n + 1,
                    at: None,
                    state: [x, y, vx, vy],
                }),
                (false, &[frame, ball, x, y, vx, vy])
                    if frame.fract() == 0.0 && ball.fract() == 0.0 =>
                {
                    Ok(Row {
                        line: n + 1,
                        at: Some((frame as u32, ball as usize)),
                        state: [x, y, vx, vy],
                    })
                }
                _ => Err(bad()),
            }
        });
        Some(
            rows.collect::<Result<_, _>>()
                .map(|rows| TrajectoryFile { rows, plain }),
        )
    }

    /// This trajectory against `motion` over the scene's `frames`, each value within
    /// `tolerance` (px, px/frame).
    pub(crate) fn compare(
        &self,
        motion: &mut ExpectedMotion,
        frames: u32,
        tolerance: f64,
    ) -> Result<Finding, Trouble> {
        let balls = motion.balls().len();
        if self.plain && balls != 1 {
            return Err(Trouble::PlainLines { balls });
        }
        if !self.rows.len().is_multiple_of(balls) {
            return Err(Trouble::PartFrame {
                rows: self.rows.len(),
                balls,
            });
        }
        let theirs = (self.rows.len() / balls) as u32;
        let mut first = None;
        for (frame, rows) in self.rows.chunks(balls).take(frames as usize).enumerate() {
            let frame = frame as u32;
            motion.step();
            for (ball, (row, expected)) in rows.iter().zip(motion.balls()).enumerate() {
                if row.at.is_some_and(|at| at != (frame, ball)) {
                    return Err(Trouble::OutOfOrder {
                        line: row.line,
                        frame,
                        ball,
                    });
                }
                let ours = [expected.x, expected.y, expected.vx, expected.vy];
                // Not within the tolerance, a NaN included.
                let close = |a: f64, b: f64| (a - b).abs() <= tolerance;
                let far = (0..4).find(|&k| !close(ours[k], row.state[k]));
                if let (None, Some(k)) = (&first, far) {
                    first = Some(First {
                        frame,
                        what: format!(
                            "ball {ball} {}: expected {:.2}, got {:.2}",
                            NAMES[k], ours[k], row.state[k]
                        ),
                        picture: None,
                    });
                }
            }
        }
        Ok(Finding {
            frames: Some(theirs),
            first,
        })
    }
}

/// The numbers of a line split at `separator`, if every part is one.
fn numbers(line: &str, separator: char) -> Option<Vec<f64>> {
    let parts = line.trim().split(separator).filter(|p| !p.is_empty());
    parts.map(|p| p.trim().parse().ok()).collect()
}
