//! Docs that cannot go stale: what `docs/` says the program accepts is checked against the
//! program itself.

use std::path::Path;

mod common;

use bouncing_ball::scene::file as scene_file;

fn doc(name: &str) -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("docs")
            .join(name),
    )
    .unwrap()
}

/// The keys the parser allows in one place of a scene file, read from its own message for an
/// unknown key (`… the keys allowed here are `a`, `b``), so the list is the parser's.
fn allowed_keys(scene: &str) -> Vec<String> {
    let error = scene_file::parse("probe.toml", scene, 1)
        .expect_err("an unknown key is refused")
        .to_string();
    let list = error
        .split("the keys allowed here are ")
        .nth(1)
        .unwrap_or_else(|| panic!("no list of keys in {error:?}"));
    list.split(", ")
        .map(|key| key.trim().trim_matches('`').to_string())
        .collect()
}

#[test]
fn the_scene_file_page_shows_every_key_the_parser_accepts() {
    let page = doc("scene-files.md");
    let size = "width = 320\nheight = 240\n";
    let places = [
        ("the top level", format!("{size}zzz = 1\n")),
        ("[[balls]]", format!("{size}[[balls]]\nzzz = 1\n")),
        ("[spawn]", format!("{size}[spawn]\nzzz = 1\n")),
        ("[[floors]]", format!("{size}[[floors]]\nzzz = 1\n")),
        ("walls", format!("{size}walls = {{ zzz = 1 }}\n")),
        (
            "ball_collisions",
            format!("{size}ball_collisions = {{ zzz = 1 }}\n"),
        ),
    ];
    for (place, scene) in places {
        let keys = allowed_keys(&scene);
        assert!(!keys.is_empty(), "{place}: no keys read");
        for key in keys {
            let shown = [
                format!("{key} = "),
                format!("[{key}]"),
                format!("[[{key}]]"),
            ];
            assert!(
                shown.iter().any(|form| page.contains(form.as_str())),
                "docs/scene-files.md does not show the key `{key}` ({place}); add it to the example"
            );
        }
    }
}

#[test]
fn the_gif_page_quotes_the_size_of_every_preset_gif_as_it_is() {
    let page = doc("gif.md");
    let mut checked = 0;
    for (name, _) in scene_file::PRESETS {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("scenes/{name}.gif"));
        let size = std::fs::metadata(&path).unwrap().len();
        let row = page
            .lines()
            .find(|line| line.starts_with(&format!("| {name} |")))
            .unwrap_or_else(|| panic!("docs/gif.md has no row for the preset {name}"));
        let quoted: u64 = row
            .split('|')
            .nth(2)
            .unwrap()
            .trim()
            .replace(',', "")
            .parse()
            .unwrap();
        assert_eq!(
            quoted, size,
            "docs/gif.md quotes {quoted} B for {name}, scenes/{name}.gif is {size} B: re-run `cargo run --release --example gif_size` and update the table"
        );
        checked += 1;
    }
    assert_eq!(checked, scene_file::PRESETS.len());
}

#[test]
fn the_readme_and_help_save_completions_in_the_same_place() {
    let readme =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    let help = std::process::Command::new(env!("CARGO_BIN_EXE_bouncing_ball"))
        .arg("--help")
        .output()
        .unwrap();
    let help = String::from_utf8_lossy(&help.stdout);
    // The command that saves the bash script, as each of them writes it.
    let saving = |text: &str| -> Option<String> {
        let start = text.find("bouncing_ball completions bash > ")?;
        let rest = &text[start..];
        Some(rest[..rest.find('`')?].to_string())
    };
    let (in_readme, in_help) = (saving(&readme), saving(&help));
    assert!(
        in_readme.is_some(),
        "README.md does not say where to save the bash completions"
    );
    assert_eq!(
        in_readme, in_help,
        "README.md and --help give different places for the completion script"
    );
    assert!(
        readme.contains("cargo install --path .") && help.contains("cargo install --path ."),
        "README.md and --help must both say the completions are for an installed binary"
    );
}

/// A time measured on some machine: `17.2 s`, `0.187 ms`, `60 ns`, `58,000 frames/s`. A table's
/// unit column (`| 30 | ms |`, a setting) is not one: a time is a number and its unit together.
fn quotes_a_timing(text: &str) -> bool {
    let number = |w: &str| {
        let w = w.trim_start_matches(['~', '≈', '<', '>', '(']);
        w.starts_with(|c: char| c.is_ascii_digit())
            && w.chars().all(|c| c.is_ascii_digit() || ".,–-".contains(c))
    };
    let unit = |w: &str| {
        let w = w.trim_end_matches(['.', ',', ';', ':', ')']);
        ["s", "ms", "µs", "us", "ns", "frames/s", "min"].contains(&w)
    };
    let glued = |w: &str| {
        ["ms", "µs", "ns"].iter().any(|u| {
            w.strip_suffix(u).is_some_and(|n| {
                n.starts_with(|c: char| c.is_ascii_digit())
                    && n.chars().all(|c| c.is_ascii_digit() || c == '.')
            })
        })
    };
    text.split('|').any(|cell| {
        let words: Vec<&str> = cell.split_whitespace().collect();
        // `0.187 ms`, `60ns`, or a column of them: `ns per ball-frame`.
        words
            .windows(2)
            .any(|pair| (number(pair[0]) && unit(pair[1])) || (unit(pair[0]) && pair[1] == "per"))
            || words.iter().any(|w| glued(w))
    })
}

#[test]
fn every_timing_in_the_docs_says_where_and_when_it_was_measured() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut pages = vec![root.join("README.md")];
    for entry in std::fs::read_dir(root.join("docs")).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "md") {
            pages.push(path);
        }
    }
    pages.sort();
    let mut unmarked = Vec::new();
    for page in pages {
        let text = std::fs::read_to_string(&page).unwrap();
        // A section runs from one heading to the next; its measurements are marked once in it.
        for section in text.split("\n#") {
            let flat = section.split_whitespace().collect::<Vec<_>>().join(" ");
            let marked = flat.contains("Measured 20") || flat.contains("measured 20");
            if quotes_a_timing(section) && !marked {
                let heading = section.lines().next().unwrap_or("").trim_start_matches('#');
                unmarked.push(format!(
                    "{}: {}",
                    page.file_name().unwrap().to_string_lossy(),
                    heading.trim()
                ));
            }
        }
    }
    assert!(
        unmarked.is_empty(),
        "these sections quote a time without saying when and where it was measured (write \
         \"Measured YYYY-MM-DD on <machine>, load <L>\" in the section):\n{}",
        unmarked.join("\n")
    );
}

#[test]
fn the_readme_answers_the_reflection_questions_with_the_programs_numbers() {
    let readme =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md")).unwrap();
    let readme = readme.split_whitespace().collect::<Vec<_>>().join(" ");
    let quoted = |figure: String| {
        assert!(
            readme.contains(&figure),
            "README.md should say `{figure}`, which is what the run gives now"
        );
    };
    let list = |items: Vec<String>| items.join(", ");
    // The frames where the ball leaves the floor (y 228) going up, and its speed then.
    let bounces = |rows: &[[f64; 6]]| -> Vec<[f64; 6]> {
        rows.windows(2)
            .filter(|w| w[0][5] > 0.0 && w[1][5] < 0.0 && w[1][3] == 228.0)
            .map(|w| w[1])
            .collect()
    };

    // 1. The default scene's bounces, and where a long run settles.
    let rows = common::lesson_trace(&[]);
    let first = bounces(&rows);
    quoted(
        format!(
            "the floor only {} times (frames {}) and leaves with vy = {} px/frame",
            first.len(),
            list(first.iter().map(|r| r[0].to_string()).collect()),
            list(first.iter().map(|r| format!("{:.2}", r[5])).collect()),
        )
        .replace('-', "−"),
    );
    let long = common::lesson_trace(&["--frames", "2000"]);
    let last_100 = &long[long.len() - 100..];
    assert!(
        last_100.iter().all(|r| r[3] == 228.0),
        "README.md says y is 228 in every one of the last 100 frames of --frames 2000"
    );
    let settled = last_100.iter().map(|r| r[5]).fold(0.0, f64::min);
    quoted(format!("vy settles at −e·g/(1 + e) = {:.3} px/frame", settled).replace('-', "−"));

    // 2. A straight drop.
    let drop = common::lesson_trace(&["--vx", "0", "--vy", "5.2"]);
    assert!(
        drop.iter().all(|r| r[2] == 40.0),
        "x must stay 40 in a straight drop"
    );
    let hit = bounces(&drop)[0];
    quoted(
        format!(
            "first hits the floor in frame {} (vy {:.2})",
            hit[0], hit[5]
        )
        .replace('-', "−"),
    );

    // 3. How far the ball moves in a frame: the gap a trail one step behind would show.
    let step = |w: &[[f64; 6]]| (w[1][2] - w[0][2]).hypot(w[1][3] - w[0][3]);
    let mut steps: Vec<f64> = rows.windows(2).map(step).collect();
    let longest = rows
        .windows(2)
        .max_by(|a, b| step(a).total_cmp(&step(b)))
        .unwrap();
    let landing = rows[longest[1][0] as usize + 1];
    assert_eq!(landing[3], 228.0, "the longest step leads into a bounce");
    steps.sort_by(f64::total_cmp);
    quoted(format!(
        "{:.1} px on the median frame of the default scene and up to {:.0} px on the step into a bounce (frames {} → {}, before the ball reaches the floor in frame {})",
        steps[steps.len() / 2],
        steps[steps.len() - 1],
        longest[0][0],
        longest[1][0],
        landing[0]
    ));
}

/// The TOML example of the scene-file page, as written.
fn scene_file_example() -> String {
    let page = doc("scene-files.md");
    let start = page.find("```toml\n").expect("a TOML example") + "```toml\n".len();
    let end = start + page[start..].find("```").expect("the example's end");
    page[start..end].to_string()
}

#[test]
fn the_scene_file_example_keeps_every_ball_above_its_slope_from_first_frame_to_last() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("example.toml"), scene_file_example()).unwrap();
    let output = common::run_in(
        dir.path(),
        &["--scene", "example.toml", "--trace", "t.csv", "-q"],
    );
    assert!(output.status.success(), "{}", common::stderr(&output));
    let scene = scene_file::load(&dir.path().join("example.toml"), 1).unwrap();
    let slope = scene.floors[0];
    let surface = |x: f64| {
        slope.from.y
            + (slope.to.y - slope.from.y) * (x - slope.from.x) / (slope.to.x - slope.from.x)
    };
    let rows = common::trace_rows(&dir.path().join("t.csv"));
    assert_eq!(rows.len(), scene.balls.len() * scene.frames as usize);
    for (k, row) in rows.iter().enumerate() {
        let [frame, i, x, y, _, _] = *row;
        let radius = scene.balls[k % scene.balls.len()].radius;
        // Spawned clear of the slope; afterwards never through it (resting contacts may
        // overlap it by a hair, so the centre is what must stay above).
        let lowest = if frame == 0.0 {
            surface(x) - radius
        } else {
            surface(x)
        };
        assert!(
            y <= lowest,
            "frame {frame}: ball {i} at y {y} (radius {radius}) is below the slope's surface at y {}",
            surface(x)
        );
    }
}

#[test]
fn a_spawn_the_floors_leave_no_room_for_is_refused() {
    let text = "width = 200\nheight = 200\nball_collisions = { restitution = 1.0 }\n\
                [[floors]]\nfrom = [0.0, 5.0]\nto = [200.0, 5.0]\ndamping = 1.0\n\
                [spawn]\ncount = 10\nradius = 4.0\nmax_speed = 1.0\n";
    let error = scene_file::parse("full.toml", text, 1)
        .unwrap_err()
        .to_string();
    assert!(
        error.contains("no room for that many balls of radius 4 above the floors"),
        "{error}"
    );
}
