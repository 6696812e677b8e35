//! The methods a comparison runs, as `--methods` spells them: `INTEGRATOR:SUBSTEPS:COLLISIONS`
//! (`rk4:4:exact`), separated by commas. The names are the scene settings' own
//! (`crate::scene::names`), so a method reads as the flags that would run it alone
//! (`--integrator rk4 --substeps 4 --collisions exact`).

use std::fmt;

use crate::physics::{CollisionMode, Integrator, Motion};
use crate::scene::spec::MAX_SUBSTEPS;
use crate::scene::{Named, Scene};

/// The lesson's method first, then the two that fix what it gets wrong: its arcs (Verlet)
/// and its bounces (exact collisions), then both with fourth order.
pub const DEFAULT_METHODS: &str = "semi-implicit-euler:1:clamp,velocity-verlet:1:exact,rk4:4:exact";

/// The lesson's own method: the one a comparison marks.
pub(crate) const LESSON: Method = Method {
    integrator: Integrator::SemiImplicitEuler,
    substeps: 1,
    collisions: CollisionMode::Clamp,
};

/// The most methods one comparison draws: each needs its own colour, and a legend row.
pub(crate) const MAX_METHODS: usize = 8;

/// One way to solve the scene: the three settings that decide how a frame is solved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Method {
    pub integrator: Integrator,
    pub substeps: u32,
    pub collisions: CollisionMode,
}

impl Method {
    /// `scene` solved by this method (its contact-solver iterations kept).
    pub(crate) fn on(self, scene: &Scene) -> Scene {
        Scene {
            motion: Motion {
                integrator: self.integrator,
                substeps: self.substeps,
                collisions: self.collisions,
                ..scene.motion
            },
            ..scene.clone()
        }
    }
}

impl fmt::Display for Method {
    /// As `--methods` spells it: `rk4:4:exact`.
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(
            f,
            "{}:{}:{}",
            self.integrator, self.substeps, self.collisions
        )
    }
}

/// The names of a setting, for a message: `explicit-euler, semi-implicit-euler, …`.
fn names<T: Named>() -> String {
    let names: Vec<&str> = T::NAMED.iter().map(|&(name, _, _)| name).collect();
    names.join(", ")
}

/// The name nearest to `typed`, if one is near enough to be what was meant (clap's own rule
/// for its suggestions: Jaro similarity above 0.7).
fn nearest<T: Named>(typed: &str) -> Option<&'static str> {
    T::NAMED
        .iter()
        .map(|&(name, _, _)| (strsim::jaro(typed, name), name))
        .filter(|&(similarity, _)| similarity > 0.7)
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, name)| name)
}

/// A setting read by name, or why not: what was typed, the names allowed, the nearest.
fn by_name<T: Named>(what: &str, typed: &str, method: &str) -> Result<T, String> {
    T::from_name(typed).ok_or_else(|| {
        let near = nearest::<T>(typed).map_or(String::new(), |n| format!("; did you mean {n}?"));
        format!(
            "unknown {what} `{typed}` in `{method}`; the {what}s are {}{near}",
            names::<T>()
        )
    })
}

/// One method, `INTEGRATOR:SUBSTEPS:COLLISIONS`.
fn method(text: &str) -> Result<Method, String> {
    let parts: Vec<&str> = text.split(':').collect();
    let [integrator, substeps, collisions] = parts[..] else {
        return Err(format!(
            "`{text}` is not a method: write INTEGRATOR:SUBSTEPS:COLLISIONS, e.g. rk4:4:exact"
        ));
    };
    let integrator = by_name("integrator", integrator, text)?;
    let substeps = substeps
        .parse::<u32>()
        .ok()
        .filter(|n| (1..=MAX_SUBSTEPS).contains(n))
        .ok_or_else(|| {
            format!(
                "substeps `{substeps}` in `{text}` must be a whole number from 1 to {MAX_SUBSTEPS}"
            )
        })?;
    let collisions = by_name("collision mode", collisions, text)?;
    Ok(Method {
        integrator,
        substeps,
        collisions,
    })
}

/// The methods of one comparison, as one value of `--methods` reads (a plain `Vec` field would
/// make clap take the flag once per method).
pub(crate) type MethodList = Vec<Method>;

/// `--methods`: a comma-separated list of one to `MAX_METHODS` different methods.
pub fn parse_list(text: &str) -> Result<MethodList, String> {
    if text.trim().is_empty() {
        return Err(format!(
            "the list of methods is empty; give one or more, e.g. {DEFAULT_METHODS}"
        ));
    }
    let methods = text
        .split(',')
        .map(|item| method(item.trim()))
        .collect::<Result<Vec<_>, _>>()?;
    if methods.len() > MAX_METHODS {
        return Err(format!(
            "{} methods is too many: at most {MAX_METHODS}, each drawn in its own colour",
            methods.len()
        ));
    }
    for (k, method) in methods.iter().enumerate() {
        if methods[..k].contains(method) {
            return Err(format!("`{method}` is listed twice; list each method once"));
        }
    }
    Ok(methods)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_list_reads_back_as_it_is_written() {
        let methods = parse_list(DEFAULT_METHODS).unwrap();
        assert_eq!(methods[0], LESSON);
        let written: Vec<String> = methods.iter().map(Method::to_string).collect();
        assert_eq!(written.join(","), DEFAULT_METHODS);
    }

    #[test]
    fn a_near_miss_is_named_and_a_far_one_is_not() {
        let near = parse_list("rk5:1:exact").unwrap_err();
        assert!(near.contains("did you mean rk4?"), "{near}");
        let far = parse_list("leapfrog:1:exact").unwrap_err();
        assert!(!far.contains("did you mean"), "{far}");
        assert!(
            far.contains("semi-implicit-euler, velocity-verlet, rk4"),
            "{far}"
        );
    }

    #[test]
    fn malformed_methods_and_lists_are_refused() {
        for bad in [
            "",
            " ",
            "rk4",
            "rk4:0:exact",
            "rk4:10001:exact",
            "rk4:x:exact",
            "rk4:1:exakt",
            "rk4:1:exact:1",
            "rk4:1:exact,,",
        ] {
            assert!(parse_list(bad).is_err(), "{bad:?} was accepted");
        }
        assert!(parse_list("rk4:1:exact,rk4:1:exact").is_err());
    }
}
