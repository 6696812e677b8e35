//! How the command line and scene files spell the settings chosen by name: the integrators
//! (`--integrator rk4`, `integrator = "rk4"`) and the collision modes.
//!
//! The physics layer knows these as plain enums; reading them from text is this layer's
//! business, so `physics/` depends on neither clap nor serde. One table per enum serves
//! `--help`, the flag's parser, shell completions and the scene-file reader.

use std::fmt;
use std::marker::PhantomData;

use clap::builder::{
    PossibleValue, PossibleValuesParser, TryMapValueParser, TypedValueParser, ValueParserFactory,
};
use serde::de::{self, Deserialize, Deserializer, Visitor};

use crate::physics::{CollisionMode, Integrator};

/// A setting whose values are chosen by name.
pub trait Named: Copy + PartialEq + Send + Sync + 'static {
    /// Every value, in the order `--help` lists them: its name, the value, what it does
    /// (shell completions show that line).
    const NAMED: &'static [(&'static str, Self, &'static str)];

    /// Every value, in order.
    fn all() -> Vec<Self> {
        Self::NAMED.iter().map(|&(_, value, _)| value).collect()
    }

    /// How the command line and scene files spell this value.
    fn name(self) -> &'static str {
        let row = Self::NAMED.iter().find(|&&(_, value, _)| value == self);
        row.map_or("", |&(name, _, _)| name)
    }

    /// The value spelt `name`, if any (exactly: `RK4` is not `rk4`).
    fn from_name(name: &str) -> Option<Self> {
        let row = Self::NAMED.iter().find(|&&(n, _, _)| n == name);
        row.map(|&(_, value, _)| value)
    }
}

impl Named for Integrator {
    const NAMED: &'static [(&'static str, Self, &'static str)] = &[
        (
            "explicit-euler",
            Integrator::ExplicitEuler,
            "Position first with the old velocity, then velocity: `x += v·dt`, `v += a·dt`",
        ),
        (
            "semi-implicit-euler",
            Integrator::SemiImplicitEuler,
            "The lesson's: `v += a·dt`, then `x += v·dt`",
        ),
        (
            "velocity-verlet",
            Integrator::VelocityVerlet,
            "`x += v·dt + a·dt²/2`, then `v` by the average of the old and new acceleration",
        ),
        (
            "rk4",
            Integrator::Rk4,
            "The classic fourth-order Runge–Kutta method",
        ),
    ];
}

impl Named for CollisionMode {
    const NAMED: &'static [(&'static str, Self, &'static str)] = &[
        (
            "clamp",
            CollisionMode::Clamp,
            "The lesson's: after the step, clamp the ball back to the wall and reflect its velocity",
        ),
        (
            "exact",
            CollisionMode::Exact,
            "Bounce off walls, floors and (in a `Simulation`) other balls at the moment of impact \
             within the step",
        ),
    ];
}

/// The names as a reader's error lists them: "`a` or `b`", "one of `a`, `b`, `c`".
fn one_of<T: Named>() -> String {
    let names: Vec<String> = T::NAMED.iter().map(|(n, _, _)| format!("`{n}`")).collect();
    match names.as_slice() {
        [one] => one.clone(),
        [a, b] => format!("{a} or {b}"),
        all => format!("one of {}", all.join(", ")),
    }
}

/// Reads `--integrator rk4`: clap checks the word against the names (listed by `--help`,
/// offered by completions), then it becomes the value.
type NameParser<T> = TryMapValueParser<PossibleValuesParser, fn(String) -> Result<T, &'static str>>;

fn parser<T: Named>() -> NameParser<T> {
    let values = T::NAMED
        .iter()
        .map(|&(name, _, help)| PossibleValue::new(name).help(help));
    let read: fn(String) -> Result<T, &'static str> =
        |name| T::from_name(&name).ok_or("not one of the names");
    PossibleValuesParser::new(values).try_map(read)
}

/// `integrator = "rk4"` in a scene file; any other name is refused with the list of names.
fn deserialize<'de, T: Named, D: Deserializer<'de>>(deserializer: D) -> Result<T, D::Error> {
    struct ByName<T>(PhantomData<T>);
    impl<T: Named> Visitor<'_> for ByName<T> {
        type Value = T;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            f.write_str(&one_of::<T>())
        }
        fn visit_str<E: de::Error>(self, name: &str) -> Result<T, E> {
            T::from_name(name).ok_or_else(|| {
                E::custom(format_args!(
                    "unknown variant `{name}`, expected {}",
                    one_of::<T>()
                ))
            })
        }
    }
    deserializer.deserialize_str(ByName(PhantomData))
}

/// Writes the trait impls each named enum needs, all from its [`Named`] table.
macro_rules! named_impls {
    ($($t:ty),*) => {$(
        impl fmt::Display for $t {
            /// The value as its flag spells it (`semi-implicit-euler`).
            fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str(self.name())
            }
        }
        impl ValueParserFactory for $t {
            type Parser = NameParser<$t>;
            fn value_parser() -> Self::Parser {
                parser()
            }
        }
        impl<'de> Deserialize<'de> for $t {
            fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                deserialize(deserializer)
            }
        }
    )*};
}

named_impls!(Integrator, CollisionMode);

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_reads_back_as_its_value() {
        for value in Integrator::all() {
            assert_eq!(Integrator::from_name(value.name()), Some(value));
        }
        for value in CollisionMode::all() {
            assert_eq!(CollisionMode::from_name(value.name()), Some(value));
        }
        assert_eq!(Integrator::from_name("RK4"), None);
    }
}
