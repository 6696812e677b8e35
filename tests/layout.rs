//! The source tree's layout: one folder per stage, imports flowing one way, no module that
//! imports another which imports it back. Reads `src/` as text, like a reader would.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::Path;

/// The stages in the order data flows; a stage may use only those before it.
const STAGES: [&str; 4] = ["physics", "scene", "render", "gif"];

/// Every module of the library by its path (`physics::ball`), with its source text.
fn modules() -> BTreeMap<String, String> {
    let mut found = BTreeMap::new();
    collect(Path::new("src"), &mut Vec::new(), &mut found);
    found
}

fn collect(dir: &Path, prefix: &mut Vec<String>, found: &mut BTreeMap<String, String>) {
    let mut entries: Vec<_> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    entries.sort();
    for path in entries {
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        if path.is_dir() {
            prefix.push(name);
            collect(&path, prefix, found);
            prefix.pop();
        } else if path.extension().is_some_and(|e| e == "rs") && name != "main" {
            let mut module = prefix.clone();
            if name != "mod" && name != "lib" {
                module.push(name);
            }
            found.insert(module.join("::"), fs::read_to_string(&path).unwrap());
        }
    }
}

/// The code of a file without comments and without its `#[cfg(test)]` unit tests.
fn code(text: &str) -> String {
    let text = text.split("#[cfg(test)]").next().unwrap();
    text.lines()
        .map(|line| line.split("//").next().unwrap())
        .collect::<Vec<_>>()
        .join("\n")
}

/// The paths named in `use` statements, braces expanded: `use super::{a::B, c}` gives
/// `super::a::B` and `super::c`.
fn use_paths(code: &str) -> Vec<String> {
    let mut paths = Vec::new();
    for statement in code.split(';') {
        let statement = statement.trim();
        let Some(tree) = statement
            .strip_prefix("pub use ")
            .or_else(|| statement.strip_prefix("use "))
        else {
            continue;
        };
        expand("", &tree.split_whitespace().collect::<String>(), &mut paths);
    }
    paths
}

fn expand(prefix: &str, tree: &str, out: &mut Vec<String>) {
    match tree.find('{') {
        None => out.push(format!("{prefix}{tree}")),
        Some(open) => {
            let (head, inner) = (&tree[..open], &tree[open + 1..tree.len() - 1]);
            let (mut depth, mut start) = (0, 0);
            for (i, c) in inner.char_indices().chain([(inner.len(), ',')]) {
                match c {
                    '{' => depth += 1,
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        let item = &inner[start..i];
                        if !item.is_empty() {
                            expand(&format!("{prefix}{head}"), item, out);
                        }
                        start = i + 1;
                    }
                    _ => {}
                }
            }
        }
    }
}

/// The modules `module` imports: each `crate::`, `super::` or `self::` path resolved to the
/// longest module it names.
fn imports(module: &str, text: &str, all: &BTreeMap<String, String>) -> BTreeSet<String> {
    let code = code(text);
    let mut named: Vec<String> = use_paths(&code);
    // Paths written inline in code, such as `crate::physics::ball::Ball::new(..)`.
    for (at, _) in code.match_indices("crate::") {
        let rest: String = code[at..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
            .collect();
        named.push(rest);
    }
    let own: Vec<&str> = module.split("::").filter(|s| !s.is_empty()).collect();
    let is_folder = all.keys().any(|m| m.starts_with(&format!("{module}::")));
    let mut found = BTreeSet::new();
    for path in named {
        let mut parts: Vec<&str> = path.split("::").collect();
        let mut base: Vec<&str> = match parts[0] {
            "crate" => Vec::new(),
            // `super` of a folder's mod.rs is the folder's parent; of a file, its folder.
            "super" if is_folder => own[..own.len().saturating_sub(1)].to_vec(),
            "super" => own[..own.len() - 1].to_vec(),
            "self" => own.clone(),
            // A bare path names a child module (`pub use ball::Ball` in a mod.rs) or a crate.
            child if all.contains_key(&[own.as_slice(), &[child]].concat().join("::")) => {
                let mut base = own.clone();
                base.push(child);
                base
            }
            _ => continue,
        };
        parts.remove(0);
        base.extend(parts);
        while !base.is_empty() {
            let candidate = base.join("::");
            if all.contains_key(&candidate) {
                if candidate != module {
                    found.insert(candidate);
                }
                break;
            }
            base.pop();
        }
    }
    found
}

fn graph() -> BTreeMap<String, BTreeSet<String>> {
    let all = modules();
    all.iter()
        .map(|(module, text)| (module.clone(), imports(module, text, &all)))
        .collect()
}

/// A path of imports from `from` back to `to`, if there is one.
fn path_back(
    graph: &BTreeMap<String, BTreeSet<String>>,
    from: &str,
    to: &str,
    seen: &mut BTreeSet<String>,
) -> Option<Vec<String>> {
    if from == to {
        return Some(vec![to.to_string()]);
    }
    if !seen.insert(from.to_string()) {
        return None;
    }
    for next in &graph[from] {
        if let Some(mut rest) = path_back(graph, next, to, seen) {
            rest.insert(0, from.to_string());
            return Some(rest);
        }
    }
    None
}

#[test]
fn no_module_imports_one_that_imports_it_back() {
    let graph = graph();
    assert!(graph.len() > 20, "found only {} modules", graph.len());
    for (module, imported) in &graph {
        // The graph itself, for `cargo test --test layout -- --nocapture`.
        let name = if module.is_empty() { "crate" } else { module };
        println!("{name} -> {}", Vec::from_iter(imported.clone()).join(", "));
        for next in imported {
            let cycle = path_back(&graph, next, module, &mut BTreeSet::new());
            assert!(
                cycle.is_none(),
                "import cycle: {module} -> {}",
                cycle.unwrap_or_default().join(" -> ")
            );
        }
    }
}

#[test]
fn each_stage_uses_only_the_stages_before_it() {
    for (module, imported) in graph() {
        let stage = |m: &str| STAGES.iter().position(|s| m.split("::").next() == Some(s));
        let Some(own) = stage(&module) else { continue };
        for other in imported {
            if let Some(theirs) = stage(&other) {
                assert!(
                    theirs <= own,
                    "{module} (stage {}) imports {other} (stage {}): data flows {}",
                    STAGES[own],
                    STAGES[theirs],
                    STAGES.join(" → ")
                );
            }
        }
    }
}

#[test]
fn every_stage_is_a_folder_whose_mod_rs_says_what_it_owns() {
    let all = modules();
    for stage in STAGES {
        let text = all
            .get(stage)
            .unwrap_or_else(|| panic!("src/{stage}/mod.rs is missing"));
        assert!(text.starts_with("//!"), "src/{stage}/mod.rs has no //! doc");
    }
    for (module, text) in &all {
        assert!(
            text.starts_with("//!"),
            "{module} has no //! doc at the top"
        );
    }
}

/// The lesson's own modules, and the folders of the solvers beyond it.
const LESSON: [&str; 3] = ["physics::ball", "physics::walls", "physics::floor"];
const SOLVERS: [&str; 3] = ["physics::integrate", "physics::contacts", "physics::events"];

#[test]
fn the_lesson_knows_no_solver() {
    let graph = graph();
    for lesson in LESSON {
        for other in &graph[lesson] {
            assert!(
                !SOLVERS.iter().any(|solver| other.starts_with(solver)),
                "{lesson} imports {other}: the lesson's state must not know the solvers beyond it"
            );
        }
    }
}

#[test]
fn each_solver_is_a_folder_that_says_what_it_adds_to_the_lesson_and_when_a_scene_needs_it() {
    let all = modules();
    for solver in SOLVERS {
        let doc: String = all
            .get(solver)
            .unwrap_or_else(|| panic!("{solver} should be a folder with a mod.rs"))
            .lines()
            .take_while(|line| line.starts_with("//!"))
            .collect();
        assert!(
            doc.contains("lesson") && doc.contains("scene needs"),
            "the //! of {solver}/mod.rs should say what it adds to the lesson and when a scene needs it"
        );
    }
}

/// The platform's maths library rounds these differently on each system (see
/// `src/physics/maths.rs`); the program calls them only through that module.
const PLATFORM_MATHS: [&str; 13] = [
    ".sin(", ".cos(", ".tan(", ".hypot(", ".ln(", ".ln_1p(", ".log10(", ".log2(", ".exp(",
    ".exp_m1(", ".powf(", ".atan2(", ".cbrt(",
];

#[test]
fn the_program_computes_transcendental_functions_the_same_on_every_system() {
    let mut found = Vec::new();
    for (module, text) in modules() {
        if module == "physics::maths" {
            continue;
        }
        let code = code(&text);
        for call in PLATFORM_MATHS.iter().filter(|call| code.contains(*call)) {
            found.push(format!("{module} calls f64::{}", &call[1..call.len() - 1]));
        }
    }
    assert!(
        found.is_empty(),
        "use physics::maths instead, so every system computes the same bits: {found:?}"
    );
}

#[test]
fn the_cycle_finder_finds_a_cycle() {
    let mut graph = BTreeMap::new();
    graph.insert("a".to_string(), BTreeSet::from(["b".to_string()]));
    graph.insert("b".to_string(), BTreeSet::from(["a".to_string()]));
    assert_eq!(
        path_back(&graph, "b", "a", &mut BTreeSet::new()),
        Some(vec!["b".to_string(), "a".to_string()])
    );
    let all = BTreeMap::from([
        ("physics".to_string(), String::new()),
        ("physics::ball".to_string(), String::new()),
        ("physics::walls".to_string(), String::new()),
    ]);
    let found = imports(
        "physics::ball",
        "use super::{walls::Walls, ball};\nfn f() { crate::physics::walls::Walls::x(); }",
        &all,
    );
    assert_eq!(found, BTreeSet::from(["physics::walls".to_string()]));
}

/// The commands that run a scene: peers above the job driver, which does what they share.
const COMMANDS: [&str; 4] = ["run", "compare", "sweep", "check"];

#[test]
fn the_commands_are_peers_that_never_import_each_other() {
    let graph = graph();
    let command_of = |m: &str| COMMANDS.iter().find(|c| m.split("::").next() == Some(c));
    for (module, imported) in &graph {
        let Some(own) = command_of(module) else {
            continue;
        };
        for other in imported {
            let theirs = command_of(other);
            assert!(
                theirs.is_none_or(|theirs| theirs == own),
                "{module} imports {other}: run, compare, sweep and check share only what src/job/ does"
            );
        }
    }
}

#[test]
fn the_commands_leave_temporary_files_summaries_and_stop_checks_to_the_job() {
    for (module, text) in modules() {
        if !COMMANDS
            .iter()
            .any(|c| module.split("::").next() == Some(c))
        {
            continue;
        }
        let code = code(&text);
        for own in ["AtomicFile", "commit_all", "requested()", "Summary {"] {
            assert!(
                !code.contains(own),
                "{module} uses {own}: opening, committing, stopping and summing up are the job's"
            );
        }
    }
}

#[test]
fn main_rs_is_the_learners_constants_then_a_short_dispatch() {
    let text = fs::read_to_string("src/main.rs").unwrap();
    let lines = text.lines().count();
    assert!(lines <= 150, "src/main.rs has {lines} lines; at most 150");
    let first_const = text.find("\nconst ").expect("the learner's constants");
    let first_fn = text.find("\nfn ").expect("lesson_scene and main");
    assert!(
        first_const < first_fn,
        "the constants come before any function in src/main.rs"
    );
    assert!(
        !text.contains("#[derive(") && text.matches("ExitCode::").count() <= 2,
        "src/main.rs holds no clap structs and has one exit path"
    );
}

/// Every `.rs` file under `src/` (main.rs too), with its path and text.
fn source_files() -> Vec<(String, String)> {
    fn walk(dir: &Path, out: &mut Vec<(String, String)>) {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = fs::read_to_string(&path).unwrap();
                out.push((path.display().to_string(), text));
            }
        }
    }
    let mut files = Vec::new();
    walk(Path::new("src"), &mut files);
    files.sort();
    files
}

/// `text` with comments, strings and character literals blanked to spaces, lines kept, so
/// that braces can be counted.
fn braces_only(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < chars.len() {
        let (c, next) = (chars[i], chars.get(i + 1).copied());
        let end = match (c, next) {
            ('/', Some('/')) => (i..chars.len())
                .find(|&j| chars[j] == '\n')
                .unwrap_or(chars.len()),
            ('"', _) => {
                let mut j = i + 1;
                while chars[j] != '"' {
                    j += if chars[j] == '\\' { 2 } else { 1 };
                }
                j + 1
            }
            // A character literal ('{', '\n'), not a lifetime ('a).
            ('\'', Some('\\')) => (i + 2..chars.len()).find(|&j| chars[j] == '\'').unwrap() + 1,
            ('\'', Some(_)) if chars.get(i + 2) == Some(&'\'') => i + 3,
            _ => {
                out.push(c);
                i += 1;
                continue;
            }
        };
        out.extend(
            chars[i..end]
                .iter()
                .map(|&c| if c == '\n' { '\n' } else { ' ' }),
        );
        i = end;
    }
    out
}

/// Each function with a body in `text`: its name and its length in lines, from the `fn`
/// line to the line of its closing brace.
fn function_lengths(text: &str) -> Vec<(String, usize)> {
    let code = braces_only(text);
    let lines: Vec<&str> = code.lines().collect();
    let mut found = Vec::new();
    for (start, line) in lines.iter().enumerate() {
        let Some(at) = line.find("fn ").filter(|&at| {
            at == 0
                || !line.as_bytes()[at - 1].is_ascii_alphanumeric()
                    && line.as_bytes()[at - 1] != b'_'
        }) else {
            continue;
        };
        let name: String = line[at + 3..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        if name.is_empty() {
            continue; // `fn(` in a type
        }
        // The body opens at the first `{` before any `;` (a declaration without a body).
        let (mut depth, mut opened) = (0usize, false);
        'lines: for (end, line) in lines.iter().enumerate().skip(start) {
            let from = if end == start { at } else { 0 };
            for c in line[from..].chars() {
                match c {
                    ';' if !opened => break 'lines,
                    '{' => (depth, opened) = (depth + 1, true),
                    '}' => depth -= 1,
                    _ => continue,
                }
                if opened && depth == 0 {
                    found.push((name, end - start + 1));
                    break 'lines;
                }
            }
        }
    }
    found
}

#[test]
fn no_source_file_is_over_700_lines_and_no_function_over_60() {
    let mut long = Vec::new();
    for (path, text) in source_files() {
        let lines = text.lines().count();
        if lines > 700 {
            long.push(format!("{path}: {lines} lines (at most 700)"));
        }
        for (name, length) in function_lengths(&text) {
            if length > 60 {
                long.push(format!("{path}: fn {name} is {length} lines (at most 60)"));
            }
        }
    }
    assert!(
        long.is_empty(),
        "split these by what they do:\n{}",
        long.join("\n")
    );
}

#[test]
fn the_function_counter_counts_from_the_fn_line_to_its_closing_brace() {
    let text =
        "fn a() {\n    let s = \"}\";\n    if x { '{' }\n}\nfn b();\nfn c<'a>(x: &'a str) { x }\n";
    assert_eq!(
        function_lengths(text),
        [("a".to_string(), 4), ("c".to_string(), 1)]
    );
}

#[test]
fn no_two_types_in_the_program_share_a_name() {
    let mut seen: BTreeMap<String, String> = BTreeMap::new();
    let mut twice = Vec::new();
    for (path, text) in source_files() {
        for line in code(&text).lines() {
            // Associated types (`type Output = ..` inside an impl) are indented; they name a
            // trait's slot, not a new idea.
            let item = line.trim_start();
            let words: Vec<&str> = item.split_whitespace().collect();
            let Some(at) = words
                .iter()
                .position(|w| ["struct", "enum", "trait", "type"].contains(w))
            else {
                continue;
            };
            let visibility_only = words[..at].iter().all(|w| w.starts_with("pub"));
            if !visibility_only || (words[at] == "type" && line.starts_with(' ')) {
                continue;
            }
            let Some(name) = words.get(at + 1).map(|w| {
                w.chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect::<String>()
            }) else {
                continue;
            };
            if let Some(first) = seen.insert(name.clone(), path.clone()) {
                twice.push(format!("{name}: {first} and {path}"));
            }
        }
    }
    assert!(
        twice.is_empty(),
        "one name per idea; these are defined twice:\n{}",
        twice.join("\n")
    );
}
