//! The command line's messages, each one line: a refused flag with what is allowed and the
//! nearest name, a value the scene cannot take named as the user typed it, a failed run, and
//! the summary of what a run wrote. The command line ([`crate::cli`]) prints them; nothing
//! here parses or runs.

use std::process::ExitCode;

use clap::error::{ContextKind, ContextValue, ErrorKind};

use crate::job::{RunError, Summary};
use crate::scene::InvalidValue;

/// The flag a scene key came from: `balls[0].frame_ms` → `--frame-ms`.
pub(crate) fn flag(key: &str) -> String {
    let name = key.rsplit('.').next().unwrap_or(key);
    format!("--{}", name.replace('_', "-"))
}

/// What a run wrote, in one line: every file with its size, how many frames the GIF holds
/// (`300 frames, shown as 108 pictures` where repeated frames were merged), the time.
pub(crate) fn summary_line(summary: &Summary) -> String {
    let frames = summary
        .pictures
        .map(|pictures| match pictures == summary.frames {
            true => format!("{} frames, ", summary.frames),
            false if pictures == 1 => format!("{} frames, shown as 1 picture, ", summary.frames),
            false => format!("{} frames, shown as {pictures} pictures, ", summary.frames),
        });
    let files: Vec<String> = summary
        .files
        .iter()
        .enumerate()
        .map(|(k, (path, bytes))| match (k, &frames) {
            (0, Some(frames)) => format!("{} ({frames}{bytes} bytes)", path.display()),
            _ => format!("{} ({bytes} bytes)", path.display()),
        })
        .collect();
    let list = match files.split_last() {
        Some((last, rest)) if !rest.is_empty() => format!("{} and {last}", rest.join(", ")),
        _ => files.join(""),
    };
    let ms = summary.elapsed.as_secs_f64() * 1000.0;
    format!("wrote {list} in {ms:.1} ms")
}

/// What the user is told when a command fails: one line on stderr, and the exit code (2 for
/// input the program cannot use, 1 for a file it cannot write, 128 + a signal's number).
#[derive(Debug)]
pub struct Failure {
    pub line: String,
    pub code: u8,
}

impl Failure {
    /// Prints the line (if any: `check` has said what it found already) and gives the exit
    /// code.
    pub fn report(self) -> ExitCode {
        if !self.line.is_empty() {
            eprintln!("{}", self.line);
        }
        ExitCode::from(self.code)
    }

    /// A run's error; a value the scene cannot take is named as the user knows it (`typed`
    /// says which settings they typed).
    pub(crate) fn of_run(error: &RunError, typed: impl Fn(&str) -> bool) -> Failure {
        let line = match error {
            RunError::Invalid(bad) => format!("error: {}", refuse_value(bad, typed)),
            other => format!("error: {other}"),
        };
        Failure {
            line,
            code: error.exit_code(),
        }
    }

    /// The failure with `hint` added to its line, before where it says which help to read.
    pub(crate) fn hinted(self, hint: &str) -> Failure {
        let line = match self.line.rsplit_once("; see ") {
            Some((what, help)) => format!("{what}; {hint}; see {help}"),
            None => format!("{}; {hint}", self.line),
        };
        Failure { line, ..self }
    }

    /// Input the program cannot use (exit 2).
    pub(crate) fn input(why: impl std::fmt::Display) -> Failure {
        Failure {
            line: format!("error: {why}"),
            code: 2,
        }
    }
}

/// A command-line error in one line (clap spreads it over several): what was wrong, what is
/// allowed, for a near miss the nearest name, and the help to read (`subcommand`'s, if the
/// mistake is in one). (Help and the version are no error: the
/// command line prints them as clap does.)
pub(crate) fn refuse(error: clap::Error, subcommand: Option<&str>) -> Failure {
    let mut line = what_was_wrong(&error);
    if let Some(ContextValue::Strings(allowed)) = error.get(ContextKind::ValidValue) {
        if !allowed.is_empty() {
            line += &format!("; allowed: {}", allowed.join(", "));
        }
    }
    for kind in [
        ContextKind::SuggestedValue,
        ContextKind::SuggestedArg,
        ContextKind::SuggestedSubcommand,
    ] {
        if let Some(near) = context_text(&error, kind) {
            line += &format!("; did you mean {near}?");
        }
    }
    // The help to read is the subcommand's, when the mistake is in one.
    let help = subcommand.map_or("--help".to_string(), |name| {
        format!("bouncing_ball {name} --help")
    });
    Failure {
        line: format!("{line}; see {help}"),
        code: 2,
    }
}

/// The `kind` of context clap gave `error`, as text: several values joined by "or".
fn context_text(error: &clap::Error, kind: ContextKind) -> Option<String> {
    match error.get(kind) {
        Some(ContextValue::String(text)) => Some(text.clone()),
        Some(ContextValue::Strings(texts)) if !texts.is_empty() => Some(texts.join(" or ")),
        _ => None,
    }
}

/// The start of a refusal's line, `error: ...`: a refused value as the user typed it and
/// why, what is missing, or else clap's own first line.
fn what_was_wrong(error: &clap::Error) -> String {
    let text = |kind| context_text(error, kind);
    match (
        text(ContextKind::InvalidArg),
        text(ContextKind::InvalidValue),
    ) {
        // `--width <WIDTH>` and `9000`: said as the user typed it, then why.
        (Some(arg), Some(value)) if !value.is_empty() => {
            // A flag is named by its long form; the one value without a flag is the shell.
            let flag = match arg.split(' ').next().unwrap_or(&arg) {
                "<SHELL>" => "completions",
                flag => flag,
            };
            let why =
                std::error::Error::source(error).map_or(String::new(), |why| format!(": {why}"));
            format!(
                "error: {flag} {value} is not allowed{why}{}",
                decimal_comma(&value)
            )
        }
        // clap lists what is missing on the lines below its first.
        (Some(missing), None) if error.kind() == ErrorKind::MissingRequiredArgument => {
            let missing = match error.get(ContextKind::InvalidArg) {
                Some(ContextValue::Strings(all)) => all.join(", "),
                _ => missing,
            };
            format!("error: missing {missing}")
        }
        _ => error
            .to_string()
            .lines()
            .next()
            .unwrap_or("error")
            .trim_end()
            .to_string(),
    }
}

/// A hint for a number written with a decimal comma (`0,5`), which a flag reads as no number.
fn decimal_comma(value: &str) -> String {
    let pointed = value.replace(',', ".");
    match value.contains(',') && pointed.parse::<f64>().is_ok() {
        true => format!(" (decimals take a point: {pointed})"),
        false => String::new(),
    }
}

/// A value the scene cannot take, named as the user knows it: the flag they typed, or the
/// scene's own value that what they typed no longer fits (`--radius 60` with the default x).
pub(crate) fn refuse_value(bad: &InvalidValue, typed: impl Fn(&str) -> bool) -> String {
    let name = bad.key.rsplit('.').next().unwrap_or(&bad.key);
    if typed(name) {
        return format!(
            "{} {} is not allowed: {}",
            flag(&bad.key),
            bad.value,
            bad.allowed
        );
    }
    format!(
        "the scene's {} = {} (not typed: set it with {}) does not fit what was typed: {}",
        bad.key,
        bad.value,
        flag(&bad.key),
        bad.allowed
    )
}

/// A whole number from 0 up, said so when it is not (`--seed -1`).
pub(crate) fn whole_number(text: &str) -> Result<u64, String> {
    text.parse()
        .map_err(|_| format!("must be a whole number from 0 to {}", u64::MAX))
}

/// A finite number from `low` to `high`, or `allowed` (what the flag takes) when it is not.
fn number_in(text: &str, low: f64, high: f64, allowed: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(value) if value.is_finite() && (low..=high).contains(&value) => Ok(value),
        _ => Err(allowed.to_string()),
    }
}

/// A number of seconds from 0 up, fractions allowed (`--time-budget 0.5`).
pub(crate) fn seconds(text: &str) -> Result<f64, String> {
    let allowed = "must be a number of seconds from 0 up, e.g. 0.5 or 3600";
    number_in(text, 0.0, f64::MAX, allowed)
}

/// A distance from 0 up, fractions allowed (`--tolerance 0.5`).
pub(crate) fn distance(text: &str) -> Result<f64, String> {
    number_in(text, 0.0, f64::MAX, "must be a number from 0 up, e.g. 0.5")
}

/// A share from 0 to 1 (`--threshold 0.1`).
pub(crate) fn share(text: &str) -> Result<f64, String> {
    number_in(text, 0.0, 1.0, "must be a number from 0 to 1, e.g. 0.1")
}
