//! What accuracy costs in time: every integrator × substeps × collision mode, measured against
//! closed-form physics (see `bouncing_ball_lab::accuracy`).
//!
//! `cargo run --release --example accuracy [-- FOLDER]` prints the table and the fitted
//! convergence orders, reproduces the "lost apex" finding, and writes `accuracy.png` (error
//! against time per frame) and `apex.png` (apex height per bounce, clamp vs exact) into
//! FOLDER, `target/accuracy/` if none is given. `-- docs/img` refreshes the pictures the
//! documentation shows (`docs/img/refresh.sh` does that and the rest).

mod apex;

use std::error::Error;
use std::path::{Path, PathBuf};
use std::time::Instant;

use bouncing_ball::output::OutputError;
use bouncing_ball::physics::motion::{CollisionMode, Motion};
use bouncing_ball::physics::Integrator;
use bouncing_ball::plot::{flag_name, save_png};
use bouncing_ball_lab::accuracy::{
    apex_height, bounces, energy_drift, fitted_order, free_flight_error, FLOOR, GRAVITY,
};
use plotters::prelude::*;

const SUBSTEPS: [u32; 7] = [1, 2, 4, 8, 16, 32, 64];
const MODES: [CollisionMode; 2] = [CollisionMode::Clamp, CollisionMode::Exact];
/// Each integrator, its textbook order and its colour in the plots.
const INTEGRATORS: [(Integrator, f64, RGBColor); 4] = [
    (Integrator::ExplicitEuler, 1.0, RGBColor(220, 50, 50)),
    (Integrator::SemiImplicitEuler, 1.0, RGBColor(230, 150, 0)),
    (Integrator::VelocityVerlet, 2.0, RGBColor(40, 150, 60)),
    (Integrator::Rk4, 4.0, RGBColor(40, 90, 220)),
];

/// Free flight: the lesson's ball under gravity and this drag (λ = 0.01005 per frame).
const DRAG: f64 = 0.01;
const FLIGHT_FRAMES: u32 = 200;
/// Bounces: released at rest from y 40 (188 px above the floor) with the lesson's damping.
const DAMPING: f64 = 0.88;
const DROP: f64 = FLOOR - 40.0;
const APEX_BOUNCE: usize = 10;
/// Elastic run, also the timing run.
const ENERGY_FRAMES: u64 = 100_000;
/// Errors closer than this to the closed form are rounding and stay out of the order fit, px.
const ROUNDING: f64 = 1e-10;
/// Errors below this are drawn on the plot's floor.
const PLOT_FLOOR: f64 = 1e-16;

/// One row of the table.
struct Row {
    motion: Motion,
    /// px from the closed form after `FLIGHT_FRAMES` of free flight with drag.
    flight_error: f64,
    /// Relative error of the apex after bounce `APEX_BOUNCE`.
    apex_error: f64,
    /// Relative energy change of an elastic ball over `ENERGY_FRAMES`.
    energy_drift: f64,
    /// Time to advance one ball one frame (all its substeps), ns, best of three.
    ns_per_frame: f64,
}

fn measure(motion: Motion) -> Row {
    let found = bounces(motion, DAMPING, 40.0, 0.0, 2_000);
    let expected = apex_height(DROP, DAMPING, APEX_BOUNCE as i32);
    let apex_error = found
        .get(APEX_BOUNCE - 1)
        .map_or(f64::NAN, |b| (b.flight_apex - expected).abs() / expected);
    let (mut energy, mut best) = (0.0, f64::INFINITY);
    for _ in 0..3 {
        let start = Instant::now();
        energy = energy_drift(motion, ENERGY_FRAMES);
        best = best.min(start.elapsed().as_nanos() as f64 / ENERGY_FRAMES as f64);
    }
    Row {
        motion,
        flight_error: free_flight_error(motion, DRAG, FLIGHT_FRAMES),
        apex_error,
        energy_drift: energy,
        ns_per_frame: best,
    }
}

fn print_table(rows: &[Row]) {
    println!(
        "| integrator | substeps | collisions | free-flight error (px) | apex error, bounce {APEX_BOUNCE} | energy drift, {ENERGY_FRAMES} frames | ns per ball-frame |"
    );
    println!("|---|---:|---|---:|---:|---:|---:|");
    for row in rows {
        let m = row.motion;
        println!(
            "| {} | {} | {} | {:.2e} | {:.2e} | {:+.2e} | {:.0} |",
            flag_name(m.integrator),
            m.substeps,
            flag_name(m.collisions),
            row.flight_error,
            row.apex_error,
            row.energy_drift,
            row.ns_per_frame
        );
    }
}

fn print_orders(rows: &[Row]) {
    println!("\n| integrator | fitted order | textbook |\n|---|---:|---:|");
    for (integrator, textbook, _) in INTEGRATORS {
        let points: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.motion.integrator == integrator)
            .filter(|r| r.motion.collisions == CollisionMode::Clamp)
            .filter(|r| r.flight_error > ROUNDING)
            .map(|r| (1.0 / f64::from(r.motion.substeps), r.flight_error))
            .collect();
        println!(
            "| {} | {:.2} (from {} points) | {textbook} |",
            flag_name(integrator),
            fitted_order(&points),
            points.len()
        );
    }
}

fn print_finding(findings: &[apex::Finding]) {
    println!("\nThe lost apex (damping 1, apex as y, px; the release is at y 40):");
    for f in findings {
        let seen: Vec<String> = f
            .bounces
            .iter()
            .take(6)
            .map(|b| format!("{:.2}", FLOOR - b.seen_apex))
            .collect();
        let grounded = f.bounces.iter().position(|b| b.seen_apex < 1.0);
        println!(
            "  {}: first apexes {} …; apex within 1 px of the floor at bounce {}",
            f.label,
            seen.join(", "),
            grounded.map_or("never".to_string(), |k| (k + 1).to_string())
        );
    }
    println!("\nExact mode, elastic, {ENERGY_FRAMES} frames: largest relative deviation of the flight apex");
    for (integrator, _, _) in INTEGRATORS {
        for vy0 in [0.3, 0.0] {
            let motion = Motion {
                integrator,
                collisions: CollisionMode::Exact,
                ..Motion::default()
            };
            let expected = DROP + vy0 * vy0 / (2.0 * GRAVITY);
            let worst = bounces(motion, 1.0, 40.0, vy0, ENERGY_FRAMES)
                .iter()
                .map(|b| (b.flight_apex - expected).abs() / expected)
                .fold(0.0, f64::max);
            println!("  {}, vy {vy0}: {worst:.2e}", flag_name(integrator));
        }
    }
}

/// One panel of `accuracy.png`: its title, the error it shows, the collision modes drawn
/// (free flight has no walls, so only clamp's timing means anything there) and where the
/// legend goes.
struct Panel {
    title: &'static str,
    error: fn(&Row) -> f64,
    modes: &'static [CollisionMode],
    legend: SeriesLabelPosition,
}

/// Error against cost, log-log: one line per integrator and mode (exact with dots), its
/// points substeps 1 to 64 from left to right.
fn plot_cost(rows: &[Row], path: &Path) -> Result<(), OutputError> {
    let panels = [
        Panel {
            title: "free flight with drag: position error, px",
            error: |r| r.flight_error,
            modes: &[CollisionMode::Clamp],
            legend: SeriesLabelPosition::UpperRight,
        },
        Panel {
            title: "bounce 10: relative apex error",
            error: |r| r.apex_error,
            modes: &MODES,
            legend: SeriesLabelPosition::MiddleRight,
        },
    ];
    save_png(path, (1400, 600), |root| {
        for (area, panel) in root.split_evenly((1, 2)).iter().zip(panels) {
            let mut chart = ChartBuilder::on(area)
                .caption(panel.title, ("sans-serif", 22))
                .margin(12)
                .x_label_area_size(45)
                .y_label_area_size(70)
                .build_cartesian_2d((3f64..30_000.0).log_scale(), (PLOT_FLOOR..1e3).log_scale())?;
            chart
                .configure_mesh()
                .x_desc("time per ball-frame, ns (substeps 1 → 64)")
                .y_desc("error")
                .x_label_formatter(&|v| format!("{v:.0}"))
                .y_label_formatter(&|v| format!("{v:.0e}"))
                .draw()?;
            for (integrator, _, colour) in INTEGRATORS {
                for &mode in panel.modes {
                    let points: Vec<(f64, f64)> = rows
                        .iter()
                        .filter(|r| {
                            r.motion.integrator == integrator && r.motion.collisions == mode
                        })
                        .map(|r| (r.ns_per_frame, (panel.error)(r).max(PLOT_FLOOR)))
                        .collect();
                    let dots = if mode == CollisionMode::Exact { 4 } else { 0 };
                    let style = colour.stroke_width(2);
                    chart
                        .draw_series(LineSeries::new(points, style).point_size(dots))?
                        .label(format!("{}, {}", flag_name(integrator), flag_name(mode)))
                        .legend(move |(x, y)| {
                            EmptyElement::at((x, y))
                                + PathElement::new(vec![(0, 0), (20, 0)], style)
                                + Circle::new((10, 0), dots, style)
                        });
                }
            }
            chart
                .configure_series_labels()
                .position(panel.legend)
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .label_font(("sans-serif", 14))
                .draw()?;
        }
        Ok(())
    })
}

fn main() -> Result<(), Box<dyn Error>> {
    let folder = match std::env::args_os().nth(1) {
        Some(folder) => PathBuf::from(folder),
        // Beside this example's binary, in whatever target folder cargo uses
        // (`CARGO_TARGET_DIR` included): TARGET/release/examples/accuracy → TARGET/accuracy.
        None => std::env::current_exe()?
            .ancestors()
            .nth(3)
            .ok_or("the example runs from the target folder")?
            .join("accuracy"),
    };
    std::fs::create_dir_all(&folder)?;
    let started = Instant::now();
    let mut rows = Vec::new();
    for (integrator, _, _) in INTEGRATORS {
        for substeps in SUBSTEPS {
            for collisions in MODES {
                rows.push(measure(Motion {
                    integrator,
                    substeps,
                    collisions,
                    ..Motion::default()
                }));
            }
        }
    }
    print_table(&rows);
    print_orders(&rows);
    let findings = apex::finding();
    print_finding(&findings);
    plot_cost(&rows, &folder.join("accuracy.png"))?;
    apex::plot(&findings, &folder.join("apex.png"))?;
    println!("\nwrote accuracy.png and apex.png in {}", folder.display());
    println!("study took {:.1} s", started.elapsed().as_secs_f64());
    Ok(())
}
