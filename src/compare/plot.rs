//! The work-precision diagram (`--plot`): each method's error against its time per
//! ball-frame, both on log scales, one point per method in its GIF colour with its min–max
//! timing as a bar, and the lesson's point ringed; a grey line where the reference stops
//! telling (its uncertainty, or its horizon). Down and to the left is better: cheaper
//! and closer to the reference. SVG, or PNG for a path ending in `.png`, with the `--plot`
//! picture's font and look ([`crate::plot`]).

use std::io::{self, Write};

use plotters::coord::Shift;
use plotters::prelude::*;

use crate::physics::maths;
use crate::plot::{use_embedded_font, write_png, Format};
use crate::scene::Rgb;

use super::draw::COLOURS;
use super::measure::{Outcome, Role, Trust};
use super::methods::LESSON;

/// The picture's size, px.
const SIZE: (u32, u32) = (800, 560);
/// Errors below this are drawn at it, px: a log scale has no zero, and an error this small
/// is rounding (the reference agrees with itself to about 1e-9 px).
const FLOOR_ERROR: f64 = 1e-13;

/// What the vertical axis shows: the largest error, or, for balls that part chaotically,
/// how many frames a method stays within a radius of the reference (at most its `horizon`,
/// past which the reference cannot tell).
fn value(outcome: &Outcome, chaotic: bool, horizon: u32) -> f64 {
    if chaotic {
        f64::from(outcome.stray.parted_at.unwrap_or(horizon).max(1))
    } else {
        outcome.stray.max_error.max(FLOOR_ERROR)
    }
}

/// The outcomes the plot shows, each with its place in `--methods` (for its colour): every
/// method but the reference's own, which is not judged.
fn judged(outcomes: &[Outcome]) -> impl Iterator<Item = (usize, &Outcome)> {
    let judged = |(_, o): &(usize, &Outcome)| o.standing.role() == Role::Method;
    outcomes.iter().enumerate().filter(judged)
}

/// A range around `values` for a log axis: from half the smallest to `above` times the
/// largest, at least a factor of ten wide.
fn log_range(values: impl Iterator<Item = f64>, above: f64) -> std::ops::Range<f64> {
    let (low, high) = values.fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    let (low, high) = (low / 2.0, high * above);
    if low > high {
        // No values (every method is the reference's own): any range will do.
        1.0..10.0
    } else if high < low * 10.0 {
        low / 3.0..high * 3.0
    } else {
        low..high
    }
}

/// A log axis's tick label: only at 1, 2 and 5 times a power of ten (the others are lines
/// without a label, so labels never crowd), as `fmt` writes the value.
fn tick(value: f64, fmt: fn(f64) -> String) -> String {
    let mantissa = value / 10f64.powi(maths::log10(value).floor() as i32);
    let round = mantissa.round();
    if (mantissa - round).abs() < 1e-6 && [1.0, 2.0, 5.0, 10.0].contains(&round) {
        fmt(value)
    } else {
        String::new()
    }
}

/// `5`, `200`, `0.5`: as few digits as a tick needs.
fn plain(value: f64) -> String {
    if value >= 1.0 {
        format!("{value:.0}")
    } else {
        format!("{value}")
    }
}

/// `1e-9`.
fn power(value: f64) -> String {
    format!("{value:.0e}")
}

/// The chart the diagram is drawn in: both axes on log scales.
type LogChart<'a, DB> = ChartContext<'a, DB, Cartesian2d<LogCoord<f64>, LogCoord<f64>>>;

/// Draws the diagram on `root`.
fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    outcomes: &[Outcome],
    chaotic: bool,
    trust: Trust,
    title: &str,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    root.fill(&WHITE)?;
    let horizon = trust.horizon;
    let limit = reference_limit(chaotic, trust);
    let x_range = log_range(
        outcomes.iter().flat_map(|o| [o.timing.min, o.timing.max]),
        2.0,
    );
    // Room above for the lesson's ring, drawn 13 px around its point.
    let values = judged(outcomes).map(|(_, o)| value(o, chaotic, horizon));
    let y_range = log_range(values.chain(limit.map(|(y, _)| y)), 4.0);
    let mut chart = ChartBuilder::on(root)
        .margin(16)
        .caption(title, ("sans-serif", 17))
        .x_label_area_size(44)
        .y_label_area_size(80)
        .build_cartesian_2d(x_range.clone().log_scale(), y_range.log_scale())?;
    draw_axes(&mut chart, chaotic)?;
    if let Some((y, name)) = limit {
        let grey = RGBColor(150, 150, 150);
        let across = vec![(x_range.start, y), (x_range.end, y)];
        chart
            .draw_series([PathElement::new(across, grey.stroke_width(2))])?
            .label(name)
            .legend(move |(x, y)| PathElement::new(vec![(x - 6, y), (x + 6, y)], grey));
    }
    for (k, outcome) in judged(outcomes) {
        draw_method(
            &mut chart,
            COLOURS[k],
            outcome,
            value(outcome, chaotic, horizon),
        )?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .label_font(("sans-serif", 13))
        .background_style(WHITE.mix(0.9))
        .border_style(RGBColor(200, 200, 200))
        .draw()?;
    root.present()
}

/// The line past which the reference tells no more, and its name: its uncertainty, under
/// which errors are not resolved, or for colliding balls its horizon, which no method can
/// pass. `None` where it is not finite (a reference of one run).
fn reference_limit(chaotic: bool, trust: Trust) -> Option<(f64, &'static str)> {
    let limit = if chaotic {
        (f64::from(trust.horizon.max(1)), "the reference's horizon")
    } else {
        let uncertainty = trust.uncertainty.max(FLOOR_ERROR);
        (uncertainty, "the reference's uncertainty")
    };
    Some(limit).filter(|(y, _)| y.is_finite())
}

/// The grid and the axes' labels: time along the bottom, error (or, for colliding balls,
/// frames kept close) up the side.
fn draw_axes<DB: DrawingBackend>(
    chart: &mut LogChart<DB>,
    chaotic: bool,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let y_desc = if chaotic {
        "frames before a ball is more than a radius off (higher is better)"
    } else {
        "largest position error against the reference, px"
    };
    chart
        .configure_mesh()
        .x_desc("ns per ball-frame on this machine (median; bar: fastest to slowest)")
        .y_desc(y_desc)
        .x_labels(30)
        .y_labels(30)
        .x_label_formatter(&|v| tick(*v, plain))
        .y_label_formatter(&|v| tick(*v, if chaotic { plain } else { power }))
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 14))
        .max_light_lines(0)
        .bold_line_style(RGBColor(230, 230, 230))
        .draw()
}

/// One method at height `y` in its GIF colour `[r, g, b]`: its min–max timing as a bar, its
/// median as a point (ringed if it is the lesson's), and its entry in the legend.
fn draw_method<DB: DrawingBackend>(
    chart: &mut LogChart<DB>,
    [r, g, b]: Rgb,
    outcome: &Outcome,
    y: f64,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let colour = RGBColor(r, g, b);
    let (x, timing) = (outcome.timing.median, &outcome.timing);
    chart.draw_series([PathElement::new(
        vec![(timing.min, y), (timing.max, y)],
        colour.stroke_width(3),
    )])?;
    let lesson = outcome.method == LESSON;
    if lesson {
        chart.draw_series([Circle::new((x, y), 13, BLACK.stroke_width(2))])?;
    }
    let name = match lesson {
        true => format!("{}  (the lesson's, ringed)", outcome.method),
        false => outcome.method.to_string(),
    };
    chart
        .draw_series([
            Circle::new((x, y), 7, colour.filled()),
            Circle::new((x, y), 7, BLACK.stroke_width(1)),
        ])?
        .label(name)
        .legend(move |(x, y)| Circle::new((x, y), 6, colour.filled()));
    Ok(())
}

/// Writes the diagram to `out` as `format`.
pub(crate) fn write(
    out: impl Write,
    format: Format,
    outcomes: &[Outcome],
    chaotic: bool,
    trust: Trust,
    title: &str,
) -> io::Result<()> {
    use_embedded_font()?;
    match format {
        Format::Svg => {
            let mut text = String::new();
            {
                let root = SVGBackend::with_string(&mut text, SIZE).into_drawing_area();
                draw(&root, outcomes, chaotic, trust, title).map_err(io::Error::other)?;
            }
            let mut out = out;
            out.write_all(text.as_bytes())
        }
        Format::Png => write_png(out, SIZE, |root| {
            draw(root, outcomes, chaotic, trust, title)
        }),
    }
}
