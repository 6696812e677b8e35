//! Drawing a recording with plotters: one panel per quantity stacked top to bottom, frames
//! along the bottom, bounces as thin grey lines, the run's settings in the title.
//!
//! Generic over plotters' backends, so the SVG and the PNG are the same drawing.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::record::{PlotPanel, Recording, Series};

use crate::physics::maths;

/// The picture's width, of the legend strip right of each panel, and the height of a title
/// line and of each panel, px.
const WIDTH: u32 = 960;
const LEGEND_WIDTH: u32 = 190;
const TITLE_LINE_HEIGHT: u32 = 24;
const PANEL_HEIGHT: u32 = 250;
/// The longest title line, characters (it fits the width at the title's font size).
const TITLE_LINE_CHARS: usize = 100;

/// Series colours, in the order the recording lists its series.
const COLOURS: [RGBColor; 4] = [
    RGBColor(40, 90, 220),
    RGBColor(230, 120, 0),
    RGBColor(40, 150, 60),
    RGBColor(150, 60, 190),
];
const BOUNCE: RGBColor = RGBColor(170, 170, 170);

/// The panels the recording has, top to bottom.
fn panels(recording: &Recording) -> Vec<PlotPanel> {
    let mut panels: Vec<PlotPanel> = recording.series.iter().map(|s| s.panel).collect();
    panels.sort();
    panels.dedup();
    panels
}

/// The title's parts joined with ` · ` into lines that fit the width.
fn title_lines(parts: &[String]) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for part in parts {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 3 + part.chars().count() <= TITLE_LINE_CHARS => {
                line.push_str(" · ");
                line.push_str(part);
            }
            _ => lines.push(part.clone()),
        }
    }
    lines
}

/// The picture's size for `recording` under a title made of `title` parts, px.
pub(crate) fn size(recording: &Recording, title: &[String]) -> (u32, u32) {
    let panels = panels(recording).len() as u32;
    let title_lines = title_lines(title).len() as u32;
    (
        WIDTH,
        TITLE_LINE_HEIGHT * (title_lines + 1) + panels * PANEL_HEIGHT,
    )
}

/// Draws `recording` on `root`, under a title made of `title` parts.
pub(crate) fn draw<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    recording: &Recording,
    title: &[String],
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    root.fill(&WHITE)?;
    let lines = title_lines(title);
    let (head, body) = root.split_vertically(TITLE_LINE_HEIGHT * (lines.len() as u32 + 1));
    let centred = ("sans-serif", 17)
        .into_text_style(root)
        .pos(Pos::new(HPos::Center, VPos::Top));
    for (i, line) in lines.iter().enumerate() {
        let y = (TITLE_LINE_HEIGHT / 2 + TITLE_LINE_HEIGHT * i as u32) as i32;
        head.draw_text(line, &centred, (WIDTH as i32 / 2, y))?;
    }
    let panels = panels(recording);
    for (area, panel) in body.split_evenly((panels.len(), 1)).iter().zip(panels) {
        draw_panel(area, recording, panel)?;
    }
    root.present()
}

/// The vertical range a panel shows: from zero (so a change reads against the whole) to the
/// largest value, or from the smallest if it is below zero, with a little room above.
fn value_range<'a>(values: impl Iterator<Item = &'a f64>) -> (f64, f64) {
    let (low, high) = values
        .filter(|v| v.is_finite())
        .fold((0.0f64, 0.0f64), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    let room = 0.05 * if high > low { high - low } else { 1.0 };
    (if low < 0.0 { low - room } else { 0.0 }, high + room)
}

/// Tick labels with as many decimals as the span needs and no more.
fn tick_label(span: f64) -> impl Fn(&f64) -> String {
    let decimals = (2.0 - maths::log10(span).floor()).clamp(0.0, 6.0) as usize;
    move |v| format!("{v:.decimals$}")
}

/// One panel: its chart on the left, its legend in a strip on the right, so the legend never
/// hides a line.
fn draw_panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    recording: &Recording,
    panel: PlotPanel,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let (chart_area, legend_area) = area.split_horizontally(WIDTH - LEGEND_WIDTH);
    let in_panel: Vec<(usize, &Series)> = recording
        .series
        .iter()
        .enumerate()
        .filter(|(_, s)| s.panel == panel)
        .collect();
    let (low, high) = value_range(in_panel.iter().flat_map(|(_, s)| &s.values));
    let last_frame = f64::from(recording.frames().saturating_sub(1).max(1));
    let mut chart = ChartBuilder::on(&chart_area)
        .margin(10)
        .x_label_area_size(36)
        .y_label_area_size(72)
        .build_cartesian_2d(0.0..last_frame, low..high)?;
    let y_label = tick_label(high - low);
    chart
        .configure_mesh()
        .x_desc("frame")
        .y_desc(panel.axis())
        .x_label_formatter(&|v| format!("{v:.0}"))
        .y_label_formatter(&y_label)
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 14))
        .max_light_lines(0)
        .bold_line_style(RGBColor(230, 230, 230))
        .draw()?;

    // Bounce marks first, so the lines are drawn over them.
    let marks = recording.bounces.iter().map(|&frame| {
        let x = f64::from(frame);
        PathElement::new(vec![(x, low), (x, high)], BOUNCE.stroke_width(1))
    });
    chart.draw_series(marks)?;
    let mut legend: Vec<(&str, ShapeStyle, bool)> = Vec::new();
    // Each line is drawn narrower than the one before it, so a line that coincides with an
    // earlier one (billiards' kinetic energy under its total, with no gravity) still shows
    // as a border around it.
    let count = in_panel.len() as u32;
    for (j, (i, series)) in (0u32..).zip(in_panel) {
        let style = COLOURS[i % COLOURS.len()].stroke_width(2 + 2 * (count - 1 - j));
        let points = series
            .values
            .iter()
            .enumerate()
            .map(|(frame, &v)| (frame as f64, v));
        chart.draw_series(LineSeries::new(points, style))?;
        legend.push((series.name, style, false));
    }
    if !recording.bounces.is_empty() {
        legend.push(("bounce (moving up again)", BOUNCE.stroke_width(1), true));
    }
    draw_legend(&legend_area, legend)
}

/// A panel's legend strip: each entry's name beside a sample of its line, upright for an
/// entry drawn upright in the chart (the bounce marks).
fn draw_legend<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    legend: Vec<(&str, ShapeStyle, bool)>,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let text = ("sans-serif", 13).into_text_style(area);
    for (row, (name, style, upright)) in legend.into_iter().enumerate() {
        let y = 30 + 22 * row as i32;
        let sample = if upright {
            vec![(12, y - 8), (12, y + 8)]
        } else {
            vec![(0, y), (24, y)]
        };
        area.draw(&PathElement::new(sample, style))?;
        area.draw_text(name, &text.pos(Pos::new(HPos::Left, VPos::Center)), (32, y))?;
    }
    Ok(())
}
