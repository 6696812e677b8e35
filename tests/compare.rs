//! `bouncing_ball compare`, run as a learner runs it, in a temporary folder: the GIF, the
//! still, the CSV and the plot it writes, decoded and checked against the physics; and how it
//! refuses bad methods.

mod common;

use std::path::Path;
use std::process::{Command, Output};
use std::sync::RwLock;

use common::decode_gif;

/// Every test's runs share this lock; a timed run takes it alone, so that the other tests'
/// runs do not slow it down.
static RUNS: RwLock<()> = RwLock::new(());

fn compare_command(dir: &Path, args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_bouncing_ball"));
    command.arg("compare").args(args).current_dir(dir);
    command
}

fn run_in(dir: &Path, args: &[&str]) -> Output {
    let _shared = RUNS.read().unwrap_or_else(|poisoned| poisoned.into_inner());
    common::output_of(&mut compare_command(dir, args))
}

fn temp_dir() -> tempfile::TempDir {
    tempfile::tempdir().expect("a temporary folder")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Runs `compare` with `args` in `dir` and insists it succeeded; returns what it printed.
fn compare_ok(dir: &Path, args: &[&str]) -> String {
    let output = run_in(dir, args);
    assert!(
        output.status.success(),
        "compare {args:?}: exit {:?}: {}",
        output.status,
        text(&output.stderr)
    );
    text(&output.stdout)
}

/// One CSV row of the table, by column name.
struct Row {
    cells: Vec<(String, String)>,
}

impl Row {
    fn get(&self, column: &str) -> &str {
        let cell = self.cells.iter().find(|(name, _)| name == column);
        cell.unwrap_or_else(|| panic!("no column {column}"))
            .1
            .as_str()
    }

    fn number(&self, column: &str) -> f64 {
        let cell = self.get(column);
        cell.parse()
            .unwrap_or_else(|_| panic!("{column} = {cell:?} is not a number"))
    }
}

/// The CSV's rows, each cell named by the header.
fn table(path: &Path) -> Vec<Row> {
    let csv = std::fs::read_to_string(path).unwrap();
    let mut lines = csv.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(String::from).collect();
    lines
        .map(|line| {
            let cells: Vec<String> = line.split(',').map(String::from).collect();
            assert_eq!(cells.len(), header.len(), "row {line:?}");
            Row {
                cells: header.iter().cloned().zip(cells).collect(),
            }
        })
        .collect()
}

const DEFAULT_METHODS: [&str; 3] = [
    "semi-implicit-euler:1:clamp",
    "velocity-verlet:1:exact",
    "rk4:4:exact",
];

#[test]
fn moon_writes_the_gif_the_table_and_the_plot_with_the_lesson_far_behind_the_best() {
    let dir = temp_dir();
    let printed = compare_ok(
        dir.path(),
        &[
            "--preset", "moon", "-o", "c.gif", "--plot", "c.svg", "--table", "c.csv",
        ],
    );
    let rows = table(&dir.path().join("c.csv"));
    let methods: Vec<&str> = rows.iter().map(|r| r.get("method")).collect();
    assert_eq!(
        methods, DEFAULT_METHODS,
        "one row per default method, in order"
    );
    for row in &rows {
        let (low, median, high) = (
            row.number("ns_per_ball_frame_min"),
            row.number("ns_per_ball_frame"),
            row.number("ns_per_ball_frame_max"),
        );
        assert!(
            0.0 < low && low <= median && median <= high,
            "timing {low} {median} {high}"
        );
    }
    let errors: Vec<f64> = rows
        .iter()
        .map(|r| r.number("max_position_error_px"))
        .collect();
    let best = errors[1..].iter().copied().fold(f64::INFINITY, f64::min);
    assert!(
        errors[0] >= 1000.0 * best,
        "the lesson's error {} px should be at least 1000 times the best method's {best} px",
        errors[0]
    );
    // Under gravity alone RK4 and Verlet fly the exact parabola and exact mode bounces at the
    // exact moment: the reference converges at once, and both agree with it to rounding. It
    // is still refined once past the finest method (rk4:4:exact), to be finer than it.
    assert!(printed.contains("reference: rk4:8:exact") && printed.contains("(converged"));
    assert!(best < 1e-9, "an exact method strays {best} px");
    for method in DEFAULT_METHODS {
        assert!(printed.contains(method), "the printed table names {method}");
    }

    let gif = decode_gif(&dir.path().join("c.gif"));
    assert_eq!(gif.timeline(3).len(), 200, "the moon's 200 frames");
    assert!(gif.height > 240, "a legend strip under the 240 px canvas");
    // The still takes the GIF's name.
    let png = image::open(dir.path().join("c.png")).unwrap().to_rgb8();
    assert!(
        png == *gif.frames.last().unwrap(),
        "the still is the last frame"
    );
    let svg = std::fs::read_to_string(dir.path().join("c.svg")).unwrap();
    assert!(svg.starts_with("<svg"), "an SVG");
}

#[test]
fn the_gif_is_the_same_bytes_from_run_to_run() {
    let dir = temp_dir();
    compare_ok(dir.path(), &["--preset", "moon", "-o", "a.gif", "-q"]);
    compare_ok(dir.path(), &["--preset", "moon", "-o", "b.gif", "-q"]);
    let (a, b) = (
        std::fs::read(dir.path().join("a.gif")).unwrap(),
        std::fs::read(dir.path().join("b.gif")).unwrap(),
    );
    assert!(
        a == b,
        "two runs wrote different GIFs ({} and {} bytes)",
        a.len(),
        b.len()
    );
}

#[test]
fn two_methods_give_two_rows() {
    let dir = temp_dir();
    let methods = "semi-implicit-euler:1:clamp,velocity-verlet:1:exact";
    compare_ok(
        dir.path(),
        &[
            "--preset",
            "lesson",
            "--methods",
            methods,
            "--table",
            "t.csv",
            "-q",
        ],
    );
    let rows = table(&dir.path().join("t.csv"));
    let names: Vec<&str> = rows.iter().map(|r| r.get("method")).collect();
    assert_eq!(names.join(","), methods);
}

/// The pixels of `frame` in `colour`, within rows `rows` and left of column `width`.
fn count(
    frame: &image::RgbImage,
    colour: [u8; 3],
    rows: std::ops::Range<u32>,
    width: u32,
) -> usize {
    frame
        .enumerate_pixels()
        .filter(|(x, y, p)| *x < width && rows.contains(y) && p.0 == colour)
        .count()
}

#[test]
fn every_method_is_drawn_in_its_colour_and_named_in_the_legend_under_the_reference_outline() {
    let dir = temp_dir();
    compare_ok(dir.path(), &["--preset", "moon", "-o", "c.gif", "-q"]);
    let gif = decode_gif(&dir.path().join("c.gif"));
    // The colours of `compare::draw::COLOURS`, then the reference's white outline.
    let colours = [[255, 200, 60], [90, 200, 255], [255, 90, 90]];
    let last = gif.frames.last().unwrap();
    // The 320 × 240 canvas, its bottom edge, then the legend (as wide as its text needs).
    let (canvas, legend) = (0..240, 241..gif.height);
    for colour in colours {
        let named = count(last, colour, legend.clone(), gif.width);
        assert!(named > 20, "{colour:?} in the legend");
    }
    // The lesson's ball is drawn on top. The exact methods lie on the reference, under its
    // outline, one over the other: Verlet, listed before RK4, shows.
    assert!(
        count(last, colours[0], canvas.clone(), 320) > 20,
        "the lesson's ball"
    );
    assert!(
        count(last, colours[1], canvas.clone(), 320) > 20,
        "Verlet's ball"
    );
    let outline = count(last, [255, 255, 255], canvas, 320);
    // A one-pixel ring of radius 12 is about 2π·12 ≈ 75 pixels.
    assert!((60..=110).contains(&outline), "{outline} outline pixels");
}

#[test]
fn the_plot_puts_the_lessons_point_highest_and_rings_it() {
    let dir = temp_dir();
    compare_ok(dir.path(), &["--preset", "moon", "--plot", "p.svg", "-q"]);
    let svg = std::fs::read_to_string(dir.path().join("p.svg")).unwrap();
    // Each method's point: a filled circle of radius 7 in its colour, at (cx, cy).
    let point = |fill: &str| -> (f64, f64) {
        let tag = svg
            .split("<circle")
            .find(|tag| tag.contains("r=\"7\"") && tag.contains(&format!("fill=\"{fill}\"")))
            .unwrap_or_else(|| panic!("no point filled {fill}"));
        let attribute = |name: &str| -> f64 {
            let start = tag.find(&format!(" {name}=\"")).unwrap() + name.len() + 3;
            tag[start..start + tag[start..].find('"').unwrap()]
                .parse()
                .unwrap()
        };
        (attribute("cx"), attribute("cy"))
    };
    let lesson = point("#FFC83C");
    for other in ["#5AC8FF", "#FF5A5A"] {
        assert!(
            lesson.1 < point(other).1,
            "the lesson's error is the largest, so its point is highest"
        );
    }
    let ringed = svg.split("<circle").any(|tag| {
        tag.contains("r=\"13\"")
            && tag.contains(&format!("cx=\"{}\"", lesson.0))
            && tag.contains(&format!("cy=\"{}\"", lesson.1))
    });
    assert!(ringed, "a ring around the lesson's point");

    compare_ok(dir.path(), &["--preset", "moon", "--plot", "p.png", "-q"]);
    let png = image::open(dir.path().join("p.png")).unwrap();
    assert_eq!(
        (png.width(), png.height()),
        (800, 560),
        "the PNG plot decodes"
    );
}

#[test]
fn an_exact_method_keeps_the_energy_of_an_elastic_scene_and_the_lesson_does_not() {
    let dir = temp_dir();
    let printed = compare_ok(dir.path(), &["--preset", "elastic", "--table", "e.csv"]);
    assert!(printed.contains("the scene keeps its energy"), "{printed}");
    let rows = table(&dir.path().join("e.csv"));
    // Damping 1 and gravity alone: ½|v|² + g·h is the same in every frame (closed form).
    let exact = rows[2].number("energy_drift");
    assert!(
        exact.abs() < 1e-9,
        "rk4:4:exact drifts by {exact:e}, expected 0"
    );
    let lesson = rows[0].number("energy_drift");
    assert!(
        lesson.abs() > 1e-3,
        "the lesson's clamp drifts by {lesson:e}, expected > 1e-3"
    );
}

#[test]
fn with_drag_the_reference_takes_doublings_and_fourth_order_beats_second_by_far() {
    let dir = temp_dir();
    let printed = compare_ok(dir.path(), &["--preset", "drag", "--table", "d.csv"]);
    // Drag makes every integrator's flight an approximation: the reference needs more than
    // the one doubling gravity alone needs before two runs agree.
    let reference = printed.lines().next().unwrap();
    let substeps: u32 = reference
        .strip_prefix("reference: rk4:")
        .and_then(|rest| rest.split(':').next())
        .and_then(|n| n.parse().ok())
        .unwrap_or_else(|| panic!("no reference method in {reference:?}"));
    assert!(
        substeps >= 4 && reference.contains("(converged"),
        "{reference}"
    );
    let rows = table(&dir.path().join("d.csv"));
    let (verlet, rk4) = (
        rows[1].number("max_position_error_px"),
        rows[2].number("max_position_error_px"),
    );
    assert!(
        verlet > 1e-3 && rk4 < 1e-6,
        "verlet {verlet} px, rk4 {rk4} px"
    );
}

#[test]
fn colliding_balls_report_when_each_method_parts_from_the_reference() {
    let dir = temp_dir();
    let printed = compare_ok(
        dir.path(),
        &[
            "--preset",
            "billiards",
            "--frames",
            "60",
            "--table",
            "b.csv",
        ],
    );
    assert!(
        printed.contains("first more than a radius off"),
        "{printed}"
    );
    for row in table(&dir.path().join("b.csv")) {
        assert_eq!(
            row.get("max_position_error_px"),
            "",
            "no error for chaotic balls"
        );
        let parted = row.get("parted_at_frame");
        assert!(
            parted.is_empty() || parted.parse::<u32>().is_ok_and(|f| f < 60),
            "parted at {parted:?}"
        );
    }
}

#[test]
fn the_moons_reference_is_trusted_to_the_last_frame_and_the_lesson_is_far_outside_its_uncertainty()
{
    let dir = temp_dir();
    compare_ok(dir.path(), &["--preset", "moon", "--table", "t.csv", "-q"]);
    let rows = table(&dir.path().join("t.csv"));
    for row in &rows {
        assert_eq!(row.get("role"), "method", "{}", row.get("method"));
        let horizon = row.number("reference_horizon_frame");
        assert_eq!(
            horizon, 200.0,
            "the reference converges: trusted in all 200 frames"
        );
    }
    let uncertainty = rows[0].number("reference_uncertainty_px");
    let errors: Vec<f64> = rows
        .iter()
        .map(|r| r.number("max_position_error_px"))
        .collect();
    let best = errors[1..].iter().copied().fold(f64::INFINITY, f64::min);
    let floor = best.max(uncertainty);
    assert!(
        errors[0] >= 1000.0 * floor,
        "the lesson's error {} px should be at least 1000 times {floor} px (the best method's \
         error {best} px, the reference's uncertainty {uncertainty} px)",
        errors[0]
    );
}

#[test]
fn on_billiards_the_reference_is_finer_than_every_method_and_no_method_scores_0() {
    let dir = temp_dir();
    let printed = compare_ok(dir.path(), &["--preset", "billiards", "--table", "t.csv"]);
    // The finest default method is rk4:4:exact: the reference has more substeps.
    assert!(printed.starts_with("reference: rk4:8:exact"), "{printed}");
    let rows = table(&dir.path().join("t.csv"));
    for row in &rows {
        let method = row.get("method");
        assert_eq!(row.get("role"), "method", "{method} is judged");
        let horizon = row.number("reference_horizon_frame");
        assert!(
            (0.0..=200.0).contains(&horizon),
            "{method}: horizon {horizon}"
        );
        let error = row.get("max_position_error_px");
        assert!(
            error.is_empty() || row.number("max_position_error_px") > 0.0,
            "{method}: error {error:?} px"
        );
    }
}

#[test]
fn the_references_own_method_is_named_the_reference_and_not_scored() {
    // On billiards the work limit stops the reference at rk4:128:exact: listed, it cannot
    // be outdone, so its row is the reference's, not a method's with an error of 0.
    let dir = temp_dir();
    let methods = "semi-implicit-euler:1:clamp,rk4:128:exact";
    let printed = compare_ok(
        dir.path(),
        &[
            "--preset",
            "billiards",
            "--methods",
            methods,
            "--table",
            "t.csv",
        ],
    );
    assert!(
        printed.contains("not finer than the finest method"),
        "{printed}"
    );
    let rows = table(&dir.path().join("t.csv"));
    let roles: Vec<&str> = rows.iter().map(|r| r.get("role")).collect();
    assert_eq!(roles, ["method", "reference"]);
    let reference = &rows[1];
    assert_eq!(reference.get("max_position_error_px"), "");
    assert_eq!(reference.get("parted_at_frame"), "");
    assert!(
        !reference.get("energy_drift").is_empty(),
        "the energy drift needs no reference in a scene that keeps its energy"
    );
    let horizon = reference.number("reference_horizon_frame");
    assert!((0.0..=200.0).contains(&horizon), "horizon {horizon}");
}

#[test]
fn a_chaotic_scene_past_the_references_horizon_judges_no_method_there() {
    // 600 frames of billiards: the reference's last two refinements part before the end.
    let dir = temp_dir();
    let printed = compare_ok(
        dir.path(),
        &[
            "--preset",
            "billiards",
            "--frames",
            "600",
            "--table",
            "t.csv",
        ],
    );
    let rows = table(&dir.path().join("t.csv"));
    let horizon = rows[0].number("reference_horizon_frame");
    assert!(horizon < 600.0, "horizon {horizon} of 600 frames");
    assert!(printed.contains("no method is judged there"), "{printed}");
    for row in &rows {
        let parted = row.get("parted_at_frame");
        let said = match parted.parse::<f64>() {
            Ok(frame) => {
                assert!(frame < horizon, "parted at {frame}, horizon {horizon}");
                format!("parted at frame {parted}")
            }
            Err(_) => format!("as far as the reference can tell (frame {horizon})"),
        };
        assert!(printed.contains(&said), "{said:?} in {printed}");
        assert!(
            !row.get("energy_drift").is_empty(),
            "drift past the horizon"
        );
    }
}

#[test]
fn a_comparison_predicted_over_the_time_budget_is_refused_at_once_in_one_line_and_no_file() {
    // The pile in exact mode takes tens of seconds to compare; the estimate says so up front.
    let dir = temp_dir();
    let args = ["--preset", "pile", "--frames", "40", "--time-budget", "0.1"];
    let alone = RUNS
        .write()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    let started = std::time::Instant::now();
    let output = compare_command(dir.path(), &args).output().unwrap();
    let took = started.elapsed().as_secs_f64();
    drop(alone);
    let err = text(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(
        err.contains("--time-budget") && err.contains("over the time budget of 0.1 s"),
        "names the knob and the budget: {err}"
    );
    // Refused before the work, which takes over half a minute. How fast the refusal is (about
    // a second) is measured by `cargo run --release --example budget`, not timed here.
    assert!(
        took < 10.0,
        "refused after {took:.2} s: after the work, not before it"
    );
    let files: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert!(files.is_empty(), "left files behind: {files:?}");
}

#[test]
fn bad_methods_get_one_line_exit_2_and_no_file() {
    for (methods, says) in [
        ("rk5:1:exact", "did you mean rk4?"),
        ("rk4", "INTEGRATOR:SUBSTEPS:COLLISIONS"),
        ("rk4:1", "INTEGRATOR:SUBSTEPS:COLLISIONS"),
        ("rk4:0:exact", "from 1 to 10000"),
        ("rk4:10001:exact", "from 1 to 10000"),
        ("rk4:four:exact", "from 1 to 10000"),
        ("rk4:1:exakt", "did you mean exact?"),
        (
            "leapfrog:1:exact",
            "semi-implicit-euler, velocity-verlet, rk4",
        ),
        ("", "empty"),
        ("rk4:1:exact,rk4:1:exact", "twice"),
        ("rk4:1:exact,", "not a method"),
    ] {
        let dir = temp_dir();
        let output = run_in(dir.path(), &["--methods", methods]);
        let err = text(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{methods:?}: {err}");
        assert_eq!(
            err.trim_end().lines().count(),
            1,
            "{methods:?}: one line: {err}"
        );
        assert!(
            err.contains(says),
            "{methods:?}: should say {says:?}: {err}"
        );
        let files: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert!(files.is_empty(), "{methods:?} left files behind: {files:?}");
    }
    let far = text(&run_in(Path::new("."), &["--methods", "leapfrog:1:exact"]).stderr);
    assert!(
        !far.contains("did you mean"),
        "no suggestion for a far miss: {far}"
    );
}

#[test]
fn refused_outputs_and_settings_each_method_sets_leave_nothing_behind() {
    for args in [
        &["--integrator", "rk4"][..],
        &["--substeps", "2"],
        &["--collisions", "exact"],
        &["--plot", "p.pdf"],
        &["-o", "c.png"],
        &["--table", "same.csv", "--plot", "same.csv"],
        &["--radius", "500"],
    ] {
        let dir = temp_dir();
        let output = run_in(dir.path(), args);
        assert_eq!(
            output.status.code(),
            Some(2),
            "{args:?}: {}",
            text(&output.stderr)
        );
        let files: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert!(files.is_empty(), "{args:?} left files behind: {files:?}");
    }
}

#[test]
fn the_readme_gif_is_what_its_command_draws() {
    // docs/compare.md gives the command; `UPDATE_GOLDEN=1` rewrites the committed GIF.
    let dir = temp_dir();
    compare_ok(
        dir.path(),
        &["--preset", "moon", "-o", "compare-moon.gif", "-q"],
    );
    let fresh = std::fs::read(dir.path().join("compare-moon.gif")).unwrap();
    let committed = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/img/compare-moon.gif");
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::write(&committed, &fresh).unwrap();
        return;
    }
    assert!(
        std::fs::read(&committed).ok() == Some(fresh),
        "docs/img/compare-moon.gif differs from what `compare --preset moon` draws now; if the \
         change is intended, refresh it with \
         `UPDATE_GOLDEN=1 cargo test --release --test compare the_readme_gif`"
    );
}

#[test]
fn a_scene_without_balls_is_refused_in_one_line() {
    let dir = temp_dir();
    std::fs::write(
        dir.path().join("empty.toml"),
        "width = 320\nheight = 240\nframes = 5\n",
    )
    .unwrap();
    let output = run_in(dir.path(), &["--scene", "empty.toml"]);
    let said = text(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{said}");
    assert!(
        said.lines().count() == 1 && said.contains("empty.toml: the scene has no balls"),
        "{said}"
    );
    assert!(!dir.path().join("compare.gif").exists(), "nothing written");
}
