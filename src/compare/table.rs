//! The comparison as a table: aligned on standard output, and as CSV for `--table`, one row
//! per method. Above the table, which reference the errors are measured against, how far it
//! converged and up to which frame it is trusted; below it, what the energy column means for
//! this scene.

use std::io::{self, Write};

use crate::trace::number;

use super::measure::{Outcome, Standing, Trust};

/// The CSV's columns; a value the scene makes meaningless is left empty (the position error
/// of colliding balls, which part chaotically, or of the reference's own method; a parting
/// that never happened). The last three were added later, so older readers still work.
pub(crate) const CSV_HEADER: &str = "method,ns_per_ball_frame,ns_per_ball_frame_min,ns_per_ball_frame_max,max_position_error_px,parted_at_frame,energy_drift,role,reference_uncertainty_px,reference_horizon_frame";

/// What the energy column means, for the line under the table.
fn energy_meaning(conserves: bool) -> &'static str {
    if conserves {
        "energy drift: the change of energy from the first frame to the last, as a share of the \
         first's (the scene keeps its energy, so all of it is the method's error)"
    } else {
        "energy drift: the energy in the last frame minus the reference's, as a share of the \
         first frame's (the scene loses energy; below zero, the method loses more than it should)"
    }
}

/// A number in a few characters: `12.34` from 0.01 to 10,000, else `1.2e-9`.
pub(crate) fn short(value: f64) -> String {
    if value == 0.0 || (0.01..10_000.0).contains(&value.abs()) {
        format!("{value:.2}")
    } else {
        format!("{value:.1e}")
    }
}

/// What the table says of a method against the reference.
fn judgement(standing: Standing, chaotic: bool) -> String {
    match standing {
        Standing::Reference => "the reference (not judged)".to_string(),
        Standing::Parted(frame) => format!("parted at frame {frame}"),
        Standing::AsFarAsKnown(horizon) => {
            format!("agrees with the reference as far as the reference can tell (frame {horizon})")
        }
        Standing::BelowUncertainty(uncertainty) => {
            format!(
                "below the reference's uncertainty ({} px)",
                short(uncertainty)
            )
        }
        Standing::Error(error) if chaotic => format!("within a radius ({} px)", short(error)),
        Standing::Error(error) => short(error),
    }
}

/// One row's cells as the terminal shows them.
fn cells(outcome: &Outcome, chaotic: bool) -> [String; 4] {
    let timing = &outcome.timing;
    [
        outcome.method.to_string(),
        format!("{:.1} ({:.1}–{:.1})", timing.median, timing.min, timing.max),
        judgement(outcome.standing, chaotic),
        outcome
            .energy_drift
            .map_or("–".to_string(), |d| format!("{d:+.1e}")),
    ]
}

/// The table as the terminal shows it, every line ending in a newline: the `reference`'s
/// lines, then a row per method, over `frames` frames.
pub(crate) fn text(
    reference: &[String],
    outcomes: &[Outcome],
    chaotic: bool,
    conserves: bool,
    trust: Trust,
    frames: u32,
) -> String {
    let error_title = match (chaotic, trust.horizon < frames) {
        (true, _) => "first more than a radius off (balls collide: chaotic)".to_string(),
        (false, false) => "largest position error, px".to_string(),
        (false, true) => format!("largest position error before frame {}, px", trust.horizon),
    };
    let head = [
        "method".to_string(),
        "ns per ball-frame (min–max)".to_string(),
        error_title,
        "energy drift".to_string(),
    ];
    let rows: Vec<[String; 4]> = std::iter::once(head)
        .chain(outcomes.iter().map(|o| cells(o, chaotic)))
        .collect();
    let width = |c: usize| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(0);
    let widths = [width(0), width(1), width(2), width(3)];
    let mut out = format!("reference: {}\n", reference.join("\n  "));
    for row in &rows {
        let line = format!(
            "{:<w0$}  {:>w1$}  {:>w2$}  {:>w3$}",
            row[0],
            row[1],
            row[2],
            row[3],
            w0 = widths[0],
            w1 = widths[1],
            w2 = widths[2],
            w3 = widths[3]
        );
        out += line.trim_end();
        out.push('\n');
    }
    out += energy_meaning(conserves);
    if !conserves && trust.horizon < frames {
        out += &format!(
            "; left out here: the reference is trusted only up to frame {}",
            trust.horizon
        );
    }
    out.push('\n');
    out
}

/// The table as CSV: [`CSV_HEADER`], then a row per method.
pub(crate) fn write_csv(
    mut out: impl Write,
    outcomes: &[Outcome],
    chaotic: bool,
    trust: Trust,
) -> io::Result<()> {
    writeln!(out, "{CSV_HEADER}")?;
    for outcome in outcomes {
        let timing = &outcome.timing;
        // No error for the reference's own method, nor where no frame was measured (a
        // reference trusted in none).
        let measured = match outcome.standing {
            Standing::Reference | Standing::AsFarAsKnown(0) => false,
            _ => !chaotic,
        };
        let error = match measured {
            true => number(outcome.stray.max_error),
            false => String::new(),
        };
        let parted = outcome
            .stray
            .parted_at
            .map_or(String::new(), |f| f.to_string());
        let energy = outcome.energy_drift.map_or(String::new(), number);
        writeln!(
            out,
            "{},{:.2},{:.2},{:.2},{error},{parted},{energy},{},{},{}",
            outcome.method,
            timing.median,
            timing.min,
            timing.max,
            outcome.standing.role().name(),
            number(trust.uncertainty),
            trust.horizon
        )?;
    }
    out.flush()
}
