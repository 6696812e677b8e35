//! `--plot`: the picture holds the trace's numbers, the PNG decodes, the lesson's energy
//! identity holds at every bounce, and bad plot paths are refused without a file written.

mod common;

use bouncing_ball::testing::Recording;
use common::{lesson_scene, lesson_trace, run_in, stderr, trace_rows};

/// Every `<polyline>` of an SVG: its stroke colour and its points, px.
fn polylines(svg: &str) -> Vec<(String, Vec<(f64, f64)>)> {
    let attribute = |tag: &str, name: &str| -> String {
        let start = tag.find(&format!(" {name}=\"")).expect("attribute present") + name.len() + 3;
        let end = start + tag[start..].find('"').unwrap();
        tag[start..end].to_string()
    };
    svg.split("<polyline")
        .skip(1)
        .map(|rest| {
            let tag = &rest[..rest.find("/>").expect("polyline closes")];
            let points = attribute(tag, "points")
                .split_whitespace()
                .map(|pair| {
                    let (x, y) = pair.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect();
            (attribute(tag, "stroke"), points)
        })
        .collect()
}

/// Every `<polyline>`'s stroke width, px, in drawing order.
fn stroke_widths(svg: &str) -> Vec<f64> {
    svg.split("<polyline")
        .skip(1)
        .map(|rest| {
            let start = rest.find("stroke-width=\"").expect("a stroke width") + 14;
            let end = start + rest[start..].find('"').unwrap();
            rest[start..end].parse().unwrap()
        })
        .collect()
}

/// The polylines with one point per frame: the series (legend samples and bounce marks
/// have two points).
fn series_lines(svg: &str, frames: usize) -> Vec<(String, Vec<(f64, f64)>)> {
    polylines(svg)
        .into_iter()
        .filter(|(_, points)| points.len() == frames)
        .collect()
}

/// The numeric tick labels of the axes, as (value, px) pairs, one list per panel: the
/// vertical axes' labels (`text-anchor="end"`, placed at their value's height) and the
/// frame axes' (`text-anchor="middle"` below the axis, at their frame's x).
fn tick_labels(svg: &str, anchor: &str) -> Vec<Vec<(f64, f64)>> {
    let mut panels: Vec<Vec<(f64, f64)>> = Vec::new();
    for text in svg.split("<text").skip(1) {
        let (tag, rest) = text.split_once('>').unwrap();
        let content = rest[..rest.find("</text>").unwrap()].trim();
        let Ok(value) = content.parse::<f64>() else {
            continue;
        };
        if !tag.contains(&format!("text-anchor=\"{anchor}\"")) {
            continue;
        }
        let at = |name: &str| -> f64 {
            let start = tag.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
            tag[start..start + tag[start..].find('"').unwrap()]
                .parse()
                .unwrap()
        };
        let px = if anchor == "end" { at("y") } else { at("x") };
        match panels.last_mut() {
            Some(panel) if panel.last().is_some_and(|&(last, _)| value > last) => {
                panel.push((value, px))
            }
            _ => panels.push(vec![(value, px)]),
        }
    }
    panels
}

/// The straight line through an axis's tick labels: px = offset + scale · value.
fn axis(ticks: &[(f64, f64)]) -> (f64, f64) {
    let n = ticks.len() as f64;
    let mean_v = ticks.iter().map(|t| t.0).sum::<f64>() / n;
    let mean_p = ticks.iter().map(|t| t.1).sum::<f64>() / n;
    let covariance: f64 = ticks.iter().map(|t| (t.0 - mean_v) * (t.1 - mean_p)).sum();
    let variance: f64 = ticks.iter().map(|t| (t.0 - mean_v).powi(2)).sum();
    let scale = covariance / variance;
    (mean_p - scale * mean_v, scale)
}

/// Checks that `pixels` draw `values` on the axis its tick labels describe. The drawing
/// maps a value to a pixel along a straight line and rounds down to a whole pixel, and so
/// does each label's position: every point must lie within 1.5 px of where the labels put
/// its value. Returns the scale, px per unit, which says how fine the check is.
fn assert_on_axis(what: &str, values: &[f64], pixels: &[f64], ticks: &[(f64, f64)]) -> f64 {
    assert!(ticks.len() >= 3, "{what}: tick labels {ticks:?}");
    let (offset, scale) = axis(ticks);
    for (i, (v, p)) in values.iter().zip(pixels).enumerate() {
        let expected = offset + scale * v;
        assert!(
            (p - expected).abs() <= 1.5,
            "{what}, frame {i}: value {v} is drawn at {p} px, the axis puts it at \
             {expected:.2} px (more than the rounding)"
        );
    }
    scale
}

/// Checks one series polyline of panel `panel`: x is the frame, y is `values`, on the axes
/// the panel's tick labels describe.
fn assert_series(svg: &str, panel: usize, what: &str, points: &[(f64, f64)], values: &[f64]) {
    let frames: Vec<f64> = (0..values.len()).map(|f| f as f64).collect();
    let xs: Vec<f64> = points.iter().map(|p| p.0).collect();
    let ys: Vec<f64> = points.iter().map(|p| p.1).collect();
    let frame_ticks = &tick_labels(svg, "middle")[panel];
    let px_per_frame = assert_on_axis(&format!("{what} (frame)"), &frames, &xs, frame_ticks);
    assert!(
        px_per_frame > 3.0,
        "{what}: frames are {px_per_frame} px apart"
    );
    let value_ticks = &tick_labels(svg, "end")[panel];
    let px_per_unit = assert_on_axis(what, values, &ys, value_ticks);
    let range = values.iter().cloned().fold(f64::MIN, f64::max)
        - values.iter().cloned().fold(f64::MAX, f64::min);
    // Up is smaller y in SVG; the values must span enough pixels for the check to mean much.
    assert!(
        px_per_unit < 0.0 && -px_per_unit * range > 50.0,
        "{what}: {range} units span {} px",
        -px_per_unit * range
    );
}

#[test]
fn one_ball_svg_draws_height_speed_and_energy_of_every_traced_frame() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_in(dir.path(), &["--plot", "run.svg", "--trace", "t.csv", "-q"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let svg = std::fs::read_to_string(dir.path().join("run.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    let rows = trace_rows(&dir.path().join("t.csv"));
    assert_eq!(rows.len(), 200);

    // The lesson's scene: floor where the centre rests, 240 − 12 px; gravity 0.5 px/frame².
    let (floor, g) = (228.0, 0.5);
    let height: Vec<f64> = rows.iter().map(|r| floor - r[3]).collect();
    let speed: Vec<f64> = rows.iter().map(|r| r[4].hypot(r[5])).collect();
    let energy: Vec<f64> = rows
        .iter()
        .map(|r| 0.5 * (r[4] * r[4] + r[5] * r[5]) + g * (floor - r[3]))
        .collect();

    let lines = series_lines(&svg, 200);
    assert_eq!(
        lines.len(),
        3,
        "one polyline per series: height, speed, energy"
    );
    let colours: Vec<&String> = lines.iter().map(|(c, _)| c).collect();
    assert!(
        colours[0] != colours[1] && colours[1] != colours[2],
        "each series has its own colour: {colours:?}"
    );
    assert_series(&svg, 0, "height", &lines[0].1, &height);
    assert_series(&svg, 1, "speed", &lines[1].1, &speed);
    assert_series(&svg, 2, "energy", &lines[2].1, &energy);
    for label in [
        "height above the floor, px",
        "speed, px/frame",
        "px²/frame²",
        "semi-implicit-euler",
        "1 substep",
        "collisions clamp",
        "damping 0.88",
    ] {
        assert!(svg.contains(label), "the plot should say {label:?}");
    }
}

#[test]
fn many_ball_svg_draws_total_energies_and_the_deepest_overlap_of_every_frame() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_in(
        dir.path(),
        &[
            "-p",
            "many",
            "--restitution",
            "0.9",
            "--plot",
            "m.svg",
            "--trace",
            "t.csv",
            "-q",
        ],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    let svg = std::fs::read_to_string(dir.path().join("m.svg")).unwrap();
    let rows = trace_rows(&dir.path().join("t.csv"));
    let frames: Vec<&[[f64; 6]]> = rows.chunks(50).collect();
    assert_eq!(frames.len(), 200);

    // Equal balls (radius 6), so each weighs one average ball; gravity 0.25 px/frame² down,
    // potential measured from where a ball rests on the floor, y = 240 − 6.
    let total = |per_ball: &dyn Fn(&[f64; 6]) -> f64| -> Vec<f64> {
        frames
            .iter()
            .map(|balls| balls.iter().map(per_ball).sum())
            .collect()
    };
    let kinetic = total(&|b| 0.5 * (b[4] * b[4] + b[5] * b[5]));
    let potential = total(&|b| 0.25 * (234.0 - b[3]));
    let sum: Vec<f64> = kinetic.iter().zip(&potential).map(|(k, p)| k + p).collect();
    let overlap: Vec<f64> = frames
        .iter()
        .map(|balls| {
            let mut deepest = 0.0f64;
            for (i, a) in balls.iter().enumerate() {
                for b in &balls[i + 1..] {
                    deepest = deepest.max(12.0 - (b[2] - a[2]).hypot(b[3] - a[3]));
                }
            }
            deepest
        })
        .collect();

    let lines = series_lines(&svg, 200);
    assert_eq!(
        lines.len(),
        4,
        "kinetic, potential, their sum, deepest overlap"
    );
    assert_series(&svg, 0, "total kinetic energy", &lines[0].1, &kinetic);
    assert_series(&svg, 0, "total potential energy", &lines[1].1, &potential);
    assert_series(&svg, 0, "total energy", &lines[2].1, &sum);
    assert_series(&svg, 1, "deepest overlap", &lines[3].1, &overlap);
    assert!(svg.contains("deepest overlap, px") && svg.contains("restitution 0.9"));
}

#[test]
fn a_line_that_coincides_with_an_earlier_one_still_shows_around_it() {
    // Billiards has no gravity: all its energy is kinetic, so the total lies on the kinetic
    // line, frame for frame.
    let dir = tempfile::tempdir().unwrap();
    let output = run_in(dir.path(), &["-p", "billiards", "--plot", "b.svg", "-q"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let svg = std::fs::read_to_string(dir.path().join("b.svg")).unwrap();
    let frames = 200;
    let lines = series_lines(&svg, frames);
    assert_eq!(lines[0].1, lines[2].1, "kinetic and total coincide");
    let widths: Vec<f64> = polylines(&svg)
        .iter()
        .zip(stroke_widths(&svg))
        .filter(|((_, points), _)| points.len() == frames)
        .map(|(_, width)| width)
        .collect();
    assert!(
        widths[0] > widths[2],
        "the kinetic line ({} px) must be wider than the total drawn over it ({} px)",
        widths[0],
        widths[2]
    );
}

#[test]
fn png_plot_decodes_as_an_image_of_the_run() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_in(dir.path(), &["--plot", "run.png", "-q"]);
    assert!(output.status.success(), "{}", stderr(&output));
    let bytes = std::fs::read(dir.path().join("run.png")).unwrap();
    assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "PNG signature");
    let image = image::load_from_memory_with_format(&bytes, image::ImageFormat::Png)
        .expect("the PNG decodes")
        .to_rgb8();
    assert_eq!(image.width(), 960);
    let colours: std::collections::HashSet<_> = image.pixels().collect();
    assert!(
        colours.len() > 10,
        "a drawing, not a blank: {} colours",
        colours.len()
    );
}

/// The lesson: "each bounce removes 12 % of the impact's vertical speed", so the vertical
/// kinetic energy right after a bounce is 0.88² = 0.7744 of that right before.
///
/// Which quantities make this exact for clamp-then-reflect: in the bounce frame `n` the step
/// first adds gravity, `v = vy[n−1] + g`, moves the ball, finds it below the floor, clamps it
/// onto the floor and sets `vy[n] = −0.88·v`. So "right before" is `½·v²` — the previous
/// frame's vertical velocity plus this frame's gravity, the speed the ball hits with, which
/// no frame shows — and "right after" is `½·vy[n]²`, read here from the plotted energy: the
/// ball sits on the floor (height 0, no potential energy), so the energy series minus the
/// horizontal kinetic energy `½·vx[n]²` is the vertical part. (The mechanical energy of the
/// frame before is not the "before": between frames it also falls by g²/2 per frame under
/// semi-implicit Euler, and the clamp lifts the ball back to the floor.)
#[test]
fn every_bounce_keeps_0_7744_of_the_vertical_kinetic_energy_of_the_impact() {
    let scene = lesson_scene();
    let g = scene.gravity.unwrap().y;
    let mut recording = Recording::new(&scene);
    let mut simulation = scene.simulation();
    let mut states = Vec::new();
    for _ in 0..scene.frames {
        simulation.step();
        recording.record(simulation.balls());
        states.push(simulation.balls()[0].clone());
    }
    let energy = &recording.series[2].values;
    assert_eq!(recording.series[2].name, "kinetic + potential");

    // The bounces marked are exactly the frames that end with the ball clamped to the floor.
    let on_floor: Vec<u32> = (0..scene.frames)
        .filter(|&n| states[n as usize].y == 228.0)
        .collect();
    assert_eq!(
        recording.bounces, on_floor,
        "bounce marks vs clamped frames"
    );
    assert!(recording.bounces.len() >= 5, "{:?}", recording.bounces);

    for &n in &recording.bounces {
        let (before, after) = (&states[n as usize - 1], &states[n as usize]);
        let impact = 0.5 * (before.vy + g).powi(2);
        let vertical_after = energy[n as usize] - 0.5 * after.vx * after.vx;
        let expected = 0.7744 * impact;
        println!("frame {n}: before {impact}, after {vertical_after}, 0.7744 × before {expected}");
        assert!(
            (vertical_after - expected).abs() <= 1e-12 * expected,
            "frame {n}: vertical kinetic energy after {vertical_after}, expected 0.7744 × \
             {impact} = {expected}"
        );
    }
}

#[test]
fn a_plot_in_a_missing_folder_exits_1_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let output = run_in(dir.path(), &["--plot", "missing/run.svg"]);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    assert_eq!(stderr(&output).lines().count(), 1, "{}", stderr(&output));
    assert!(stderr(&output).contains("missing/run.svg"));
    let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert!(left.is_empty(), "nothing written: {left:?}");
}

#[test]
fn a_plot_path_that_is_a_folder_is_refused_like_any_output_and_writes_nothing() {
    // Refused before any work, as every output path that is not a regular file is: exit 2.
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("plots")).unwrap();
    let output = run_in(dir.path(), &["--plot", "plots"]);
    assert_eq!(output.status.code(), Some(2), "{}", stderr(&output));
    assert_eq!(stderr(&output).lines().count(), 1, "{}", stderr(&output));
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["plots"], "only the folder, untouched");
    assert!(std::fs::read_dir(dir.path().join("plots"))
        .unwrap()
        .next()
        .is_none());
}

#[test]
fn a_plot_path_with_another_extension_or_too_many_frames_exits_2_and_writes_nothing() {
    let dir = tempfile::tempdir().unwrap();
    for (args, says) in [
        (&["--plot", "run.jpg"][..], "--plot run.jpg is not allowed"),
        (
            &["--plot", "run.svg", "--frames", "100001"][..],
            "--frames 100001 is not allowed",
        ),
    ] {
        let output = run_in(dir.path(), args);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            stderr(&output)
        );
        let message = stderr(&output);
        assert!(
            message.lines().count() == 1 && message.contains(says),
            "{args:?}: {message}"
        );
    }
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none());
}

#[test]
fn a_failed_run_leaves_the_previous_plot_untouched() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("run.svg"), "the previous plot").unwrap();
    let output = run_in(dir.path(), &["--plot", "run.svg", "--png", "missing/x.png"]);
    assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
    let kept = std::fs::read_to_string(dir.path().join("run.svg")).unwrap();
    assert_eq!(kept, "the previous plot");
}

#[test]
fn a_scene_file_can_ask_for_a_plot_and_the_flag_overrides_it() {
    let dir = tempfile::tempdir().unwrap();
    // A top-level key, so before the file's first table.
    let scene = "plot = \"scene.svg\"\n".to_string() + bouncing_ball::scene::PRESETS[0].1;
    std::fs::write(dir.path().join("scene.toml"), scene).unwrap();
    let output = run_in(dir.path(), &["--scene", "scene.toml", "-q"]);
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(dir.path().join("scene.svg").is_file());
    let output = run_in(
        dir.path(),
        &["--scene", "scene.toml", "--plot", "flag.png", "-q"],
    );
    assert!(output.status.success(), "{}", stderr(&output));
    assert!(dir.path().join("flag.png").is_file());
}

/// Energy per unit mass of the default scene's ball: kinetic plus g times its height above
/// the floor (the floor the 12-px ball rests on is y = 228), px²/frame².
fn lesson_energy(row: &[f64; 6]) -> f64 {
    0.5 * (row[4] * row[4] + row[5] * row[5]) + 0.5 * (228.0 - row[3])
}

#[test]
fn the_plot_page_quotes_each_of_its_runs_as_the_program_runs_it() {
    let page =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/plots.md")).unwrap();
    // Where the lines break does not matter.
    let page = page.split_whitespace().collect::<Vec<_>>().join(" ");
    let quoted = |figure: String| {
        assert!(
            page.contains(&figure),
            "docs/plots.md should say `{figure}`, which is what the run gives now"
        );
    };

    // The default scene: the frames where the ball leaves the floor going up.
    let rows = lesson_trace(&[]);
    let bounces: Vec<String> = rows
        .windows(2)
        .filter(|w| w[0][5] > 0.0 && w[1][5] < 0.0 && w[1][3] == 228.0)
        .map(|w| format!("{}", w[1][0]))
        .collect();
    let (last, rest) = bounces.split_last().unwrap();
    quoted(format!("bounces at frames {} and {last}", rest.join(", ")));

    // The elastic goal: every apex after the first bounce at the same height.
    let rows = lesson_trace(&["--damping", "1"]);
    let first_bounce = rows.iter().position(|r| r[5] < 0.0).unwrap();
    let apexes: Vec<f64> = rows[first_bounce..]
        .windows(2)
        .filter(|w| w[0][5] < 0.0 && w[1][5] >= 0.0)
        .map(|w| w[0][3].min(w[1][3]))
        .collect();
    assert!(
        apexes.len() >= 2,
        "the elastic ball bounced only {} times",
        apexes.len()
    );
    assert!(
        apexes.iter().all(|&y| y == apexes[0]),
        "the elastic apexes differ: {apexes:?}"
    );
    quoted(format!(
        "every apex is {} px above the floor (y {})",
        228.0 - apexes[0],
        apexes[0]
    ));

    // The lost apex: the energy left once the ball runs along the floor.
    let rows = lesson_trace(&["--damping", "1", "--vy", "0.3", "--frames", "2000"]);
    let late: Vec<f64> = rows[1600..].iter().map(lesson_energy).collect();
    let (low, high) = late
        .iter()
        .fold((f64::MAX, f64::MIN), |(lo, hi), &e| (lo.min(e), hi.max(e)));
    quoted(format!(
        "swings between {low:.3} and {high:.3} px²/frame² from frame 1600 on"
    ));

    // Exact collisions with velocity Verlet: the energy, and how far it strays (rounding).
    let rows = lesson_trace(&[
        "--damping",
        "1",
        "--collisions",
        "exact",
        "--integrator",
        "velocity-verlet",
    ]);
    let start = lesson_energy(&rows[0]);
    let drift = rows
        .iter()
        .map(|r| ((lesson_energy(r) - start) / start).abs())
        .fold(0.0, f64::max);
    quoted(format!(
        "{start:.2} px²/frame² in every frame, to {drift:.1e} relative"
    ));
}
