//! Values typed on the command line that replace a scene's own (`--preset moon --damping 1`).
//!
//! Each setting is one row of the table at the bottom of this file: its help, its short flag
//! if any, its name and type, and where it goes in a [`Scene`]. From that row come its flag
//! (`--frame-ms` for `frame_ms`), its field in [`Overrides`], how [`Overrides::apply`] writes
//! it, and the default `--help` shows, which is the lesson scene's value (so the constants at
//! the top of `src/main.rs` stay the defaults). Adding a setting is adding a row.

use std::ops::RangeInclusive;

use clap::builder::ValueParser;
use clap::parser::ValueSource;
use clap::{Arg, ArgAction, ArgMatches, Command, ValueHint};

use super::spec::{
    Scene, TrailFade, MAX_CANVAS_SIDE, MAX_FRAME_MS, MAX_ITERATIONS, MAX_SUBSTEPS, MAX_TRAIL_LEN,
};
use crate::physics::{CollisionMode, Integrator};

/// `Some(value)` unless it is zero: a zero-strength effect is no effect, and costs nothing.
fn unless_zero(value: f64) -> Option<f64> {
    (value != 0.0).then_some(value)
}

/// How a typed value goes into its place in a scene (`put`), and how that place reads back as
/// the value a flag would have typed (`get`, `None` where the scene has none).
mod fit {
    use super::unless_zero;

    /// The value itself (`--frames 50`).
    pub(crate) mod plain {
        pub(crate) fn put<T>(value: T) -> T {
            value
        }
        pub(crate) fn get<T: Copy>(place: &T) -> Option<T> {
            Some(*place)
        }
    }

    /// Turns an effect on with this value: `--damping` adds walls to a scene without them.
    pub(crate) mod turns_on {
        pub(crate) fn put(value: f64) -> Option<f64> {
            Some(value)
        }
        pub(crate) fn get(place: &Option<f64>) -> Option<f64> {
            *place
        }
    }

    /// An effect's strength; 0 removes the effect (`--drag 0`).
    pub(crate) mod zero_is_off {
        pub(crate) fn put(value: f64) -> Option<f64> {
            super::unless_zero(value)
        }
        pub(crate) use super::turns_on::get;
    }

    /// Downward gravity, px/frame²; 0 removes gravity.
    pub(crate) mod downwards {
        use crate::physics::Vec2;

        pub(crate) fn put(g: f64) -> Option<Vec2> {
            super::unless_zero(g).map(|g| Vec2::new(0.0, g))
        }
        pub(crate) fn get(place: &Option<Vec2>) -> Option<f64> {
            place.map(|g| g.y)
        }
    }
}

/// A parser of whole numbers in `range` that says the range when a value is outside it or no
/// whole number at all (`-320`, `1.5`, `ten`).
fn whole_number_in<T>(
    range: RangeInclusive<i64>,
) -> impl Fn(&str) -> Result<T, String> + Clone + Send + Sync + 'static
where
    T: TryFrom<i64> + Clone + Send + Sync + 'static,
{
    move |text| {
        let (low, high) = (*range.start(), *range.end());
        text.trim()
            .parse::<i64>()
            .ok()
            .filter(|n| range.contains(n))
            .and_then(|n| T::try_from(n).ok())
            .ok_or_else(|| format!("must be a whole number from {low} to {high}"))
    }
}

/// How a setting's flag reads its value.
trait FlagValue {
    fn parser() -> ValueParser;
}

/// A number must be finite, and is refused as typed (`--vx 1e400`, not `inf`).
impl FlagValue for f64 {
    fn parser() -> ValueParser {
        ValueParser::new(|text: &str| match text.trim().parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(value),
            _ => Err("must be a finite number, e.g. 0.5 or -3".to_string()),
        })
    }
}

/// Names and switches read as clap reads them.
macro_rules! read_by_clap {
    ($($ty:ty),*) => {$(
        impl FlagValue for $ty {
            fn parser() -> ValueParser {
                clap::value_parser!($ty).into()
            }
        }
    )*};
}
read_by_clap!(bool, Integrator, CollisionMode, TrailFade);

/// The flag of setting `id` (`frame_ms` → `--frame-ms <FRAME_MS>`), as clap's derive makes it.
fn flag(id: &'static str, short: Option<char>, help: &str, parser: ValueParser) -> Arg {
    Arg::new(id)
        .long(id.replace('_', "-"))
        .short(short)
        .value_name(id.to_uppercase())
        .help(help.trim().to_string())
        .value_parser(parser)
        // No setting is a path: a shell completes no file names for it.
        .value_hint(ValueHint::Other)
        // A value may start with a minus sign, `-inf` and `-nan` too (clap's own test for a
        // negative number knows only digits): it then gets the number's own message.
        .allow_hyphen_values(true)
        .action(ArgAction::Set)
}

/// Shows `default` in `arg`'s help (`[default: none]` where the lesson has none: the setting
/// is off unless typed).
fn with_default(arg: Arg, default: Option<String>) -> Arg {
    match default {
        Some(value) => arg.default_value(value),
        None => {
            let help = arg.get_help().map(ToString::to_string).unwrap_or_default();
            arg.help(format!("{help} [default: none]"))
        }
    }
}

/// Whether the user typed flag `id` (a default is not a value to lay over a scene).
fn typed(matches: &ArgMatches, id: &str) -> bool {
    matches.value_source(id) == Some(ValueSource::CommandLine)
}

/// Writes the settings' struct, its `apply`, its flags and its defaults from the table below.
/// A row: help (doc comment), `-'c'` for a short flag, `name: Type`, then where it goes:
/// `scene.field…` or `ball.field` (every ball; the first ball's is the default), and after a
/// comma how it fits there (a module of [`fit`]; `plain` if none).
macro_rules! settings {
    ($(
        #[doc = $help:literal]
        $(-$short:literal)? $name:ident: $ty:ty $([$range:expr])? = $at:ident.$($field:ident).+ $(, $fit:ident)?;
    )*) => {
        /// Each `Some` replaces the scene's value; ball values apply to every ball.
        #[derive(Clone, Debug, Default, PartialEq)]
        pub struct Overrides {
            $(#[doc = $help] pub $name: Option<$ty>,)*
        }

        impl Overrides {
            /// Writes every given value into `scene`.
            pub fn apply(&self, scene: &mut Scene) {
                $(if let Some(value) = self.$name {
                    settings!(@put scene, $at ($($field).+) [$($fit)?] value);
                })*
            }

            /// These values, and `other`'s where these have none (a sweep's value over the
            /// typed flags).
            pub(crate) fn or(&self, other: &Overrides) -> Overrides {
                Overrides {$($name: self.$name.or(other.$name),)*}
            }

            /// The whole numbers the setting `name` (`width`) allows, if it is a whole number.
            pub(crate) fn whole_range(name: &str) -> Option<RangeInclusive<i64>> {
                match name {
                    $(stringify!($name) => settings!(@range $($range)?),)*
                    _ => None,
                }
            }

            /// Whether the setting `name` (`frame_ms`) was typed.
            pub(crate) fn is_typed(&self, name: &str) -> bool {
                match name {
                    $(stringify!($name) => self.$name.is_some(),)*
                    _ => false,
                }
            }

            /// `command` with each setting's flag showing `scene`'s value as its default.
            pub(crate) fn defaults_from(scene: &Scene, command: Command) -> Command {
                let defaults = [$((
                    stringify!($name),
                    settings!(@get scene, $at ($($field).+) [$($fit)?])
                        .map(|value: $ty| value.to_string()),
                )),*];
                // `mut_args`, not `mut_arg`: that one moves the flag to the end of the list,
                // which is the order completion scripts give.
                command.mut_args(|arg| {
                    match defaults.iter().find(|(id, _)| arg.get_id() == *id) {
                        Some((_, default)) => with_default(arg, default.clone()),
                        None => arg,
                    }
                })
            }
        }

        /// The flags, in the table's order (which is `--help`'s).
        impl clap::Args for Overrides {
            fn augment_args(command: Command) -> Command {
                command.args([$(flag(
                    stringify!($name),
                    settings!(@short $($short)?),
                    $help,
                    settings!(@parser $ty $(, $range)?),
                )),*])
            }
            fn augment_args_for_update(command: Command) -> Command {
                Self::augment_args(command)
            }
        }

        /// The flags the user typed; the rest stay `None`.
        impl clap::FromArgMatches for Overrides {
            fn from_arg_matches(matches: &ArgMatches) -> Result<Self, clap::Error> {
                Ok(Overrides {$(
                    $name: typed(matches, stringify!($name))
                        .then(|| matches.get_one::<$ty>(stringify!($name)).copied())
                        .flatten(),
                )*})
            }
            fn update_from_arg_matches(&mut self, matches: &ArgMatches) -> Result<(), clap::Error> {
                *self = Self::from_arg_matches(matches)?;
                Ok(())
            }
        }
    };

    (@range) => { None };
    (@range $range:expr) => { Some($range) };

    (@short) => { None };
    (@short $short:literal) => { Some($short) };

    // A whole number is read as any integer and held to its real range, so `--width -320`
    // says `-320 is not in 1..=8192`, not that a minus sign is an invalid digit.
    (@parser $ty:ty) => { <$ty as FlagValue>::parser() };
    (@parser $ty:ty, $range:expr) => { ValueParser::new(whole_number_in::<$ty>($range)) };

    (@put $scene:ident, scene ($($field:ident).+) [] $value:ident) => {
        $scene.$($field).+ = fit::plain::put($value)
    };
    (@put $scene:ident, scene ($($field:ident).+) [$fit:ident] $value:ident) => {
        $scene.$($field).+ = fit::$fit::put($value)
    };
    (@put $scene:ident, ball ($field:ident) [] $value:ident) => {
        for ball in &mut $scene.balls {
            ball.$field = fit::plain::put($value);
        }
    };

    (@get $scene:ident, scene ($($field:ident).+) []) => {
        fit::plain::get(&$scene.$($field).+)
    };
    (@get $scene:ident, scene ($($field:ident).+) [$fit:ident]) => {
        fit::$fit::get(&$scene.$($field).+)
    };
    (@get $scene:ident, ball ($field:ident) []) => {
        $scene.balls.first().and_then(|ball| fit::plain::get(&ball.$field))
    };
}

settings! {
    /// Canvas width, px
    width: u32 [1..=i64::from(MAX_CANVAS_SIDE)] = scene.width;
    /// Canvas height, px
    height: u32 [1..=i64::from(MAX_CANVAS_SIDE)] = scene.height;
    /// Ball radius, px
    radius: f64 = ball.radius;
    /// Start position x, px
    x: f64 = ball.x;
    /// Start position y, px (y grows downwards)
    y: f64 = ball.y;
    /// Start velocity x, px/frame
    vx: f64 = ball.vx;
    /// Start velocity y, px/frame
    vy: f64 = ball.vy;
    /// Gravity, px/frame² (downwards; negative pulls up)
    -'g' gravity: f64 = scene.gravity, downwards;
    /// Share of speed kept at each bounce, 0 to 1
    -'d' damping: f64 = scene.walls, turns_on;
    /// Air drag: share of speed lost per frame, 0 to 1 (the lesson's 0.998 is 0.002)
    drag: f64 = scene.drag, zero_is_off;
    /// Ball-ball collisions with this restitution, 0 to 1
    restitution: f64 = scene.ball_collisions, turns_on;
    /// How each step turns forces into motion
    integrator: Integrator = scene.motion.integrator;
    /// Steps per frame (each frame split into equal steps)
    substeps: u32 [1..=i64::from(MAX_SUBSTEPS)] = scene.motion.substeps;
    /// How wall and floor contacts are resolved
    collisions: CollisionMode = scene.motion.collisions;
    /// Contact-solver iterations per step (ball-ball collisions in clamp mode)
    iterations: u32 [1..=i64::from(MAX_ITERATIONS)] = scene.motion.iterations;
    /// Trail length, points (0: no trail)
    trail: usize [0..=MAX_TRAIL_LEN as i64] = ball.trail;
    /// How trail dots darken into the past: linear (the lesson's), none, or a power (2: sooner)
    trail_fade: TrailFade = scene.trail_fade;
    /// Whether trail dots shrink into the past (the lesson's: true)
    trail_shrink: bool = scene.trail_shrink;
    /// Frames to simulate
    -'n' frames: u32 [1..=i64::from(u32::MAX)] = scene.frames;
    /// Time each frame shows, ms (a multiple of 10)
    frame_ms: u32 [0..=i64::from(MAX_FRAME_MS)] = scene.frame_ms;
}
