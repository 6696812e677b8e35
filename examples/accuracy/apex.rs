//! The lost apex: the lesson's elastic ball, clamp vs exact, its apex bounce by bounce, and
//! `apex.png`, which draws it. Nothing here is timed, so the picture is the same on every
//! run and machine; `tests/docs_images.rs` includes this file to check that
//! `docs/img/apex.png` is what the study would write.

use std::path::Path;

use bouncing_ball::output::OutputError;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::Integrator;
use bouncing_ball::plot::{flag_name, save_png};
use bouncing_ball_lab::accuracy::{bounces, Bounce};
use plotters::prelude::*;

/// One run of the finding: how it is labelled and coloured, and its bounces.
pub struct Finding {
    pub label: String,
    pub colour: RGBColor,
    pub bounces: Vec<Bounce>,
}

/// Frames each run of the finding lasts.
const FRAMES: u64 = 3_000;

/// The finding: the lesson's elastic ball released from y 40, at rest or at vy 0.3, under the
/// lesson's solver (clamp) and under velocity Verlet with exact collisions.
pub fn finding() -> Vec<Finding> {
    let clamp = Motion::default();
    let exact = Motion {
        integrator: Integrator::VelocityVerlet,
        collisions: CollisionMode::Exact,
        ..Motion::default()
    };
    let run = |motion: Motion, vy0: f64, colour: RGBColor, note: &str| {
        let mut found = bounces(motion, 1.0, 40.0, vy0, FRAMES);
        found.pop(); // the last flight is cut off by the end of the run
        let start = if vy0 == 0.0 {
            "from rest".to_string()
        } else {
            format!("vy {vy0}")
        };
        Finding {
            label: format!(
                "{}, {}, {start}{note}",
                flag_name(motion.integrator),
                flag_name(motion.collisions)
            ),
            colour,
            bounces: found,
        }
    };
    vec![
        run(clamp, 0.3, RGBColor(220, 50, 50), ""),
        run(clamp, 0.0, RGBColor(230, 150, 0), ""),
        run(exact, 0.3, RGBColor(40, 90, 220), " (under the green line)"),
        run(exact, 0.0, RGBColor(40, 150, 60), ""),
    ]
}

/// Bounces shown in `apex.png`: the sinking apex reaches the floor at about 52.
const PLOTTED_BOUNCES: usize = 60;

/// Draws the apex height above the floor per bounce (as the frames show it), one line per
/// run of the finding, and writes it as PNG at `path`.
pub fn plot(findings: &[Finding], path: &Path) -> Result<(), OutputError> {
    save_png(path, (900, 520), |root| {
        let mut chart = ChartBuilder::on(root)
            .caption(
                "damping 1: apex per bounce, clamp vs exact",
                ("sans-serif", 22),
            )
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(1..PLOTTED_BOUNCES, 0f64..200.0)?;
        chart
            .configure_mesh()
            .x_desc("bounce")
            .y_desc("apex height above the floor, px")
            .y_label_formatter(&|v| format!("{v:.0}"))
            .draw()?;
        for f in findings {
            let colour = f.colour;
            let points = (1..PLOTTED_BOUNCES)
                .zip(&f.bounces)
                .map(|(k, b)| (k, b.seen_apex));
            chart
                .draw_series(LineSeries::new(points, colour.stroke_width(2)))?
                .label(&f.label)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::MiddleRight)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .label_font(("sans-serif", 14))
            .draw()
    })
}
