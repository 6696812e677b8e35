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
