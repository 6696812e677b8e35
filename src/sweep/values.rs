//! `KEY=V1,V2,...`: which setting a sweep varies and the values it takes, each read by the
//! setting's own flag parser, so a value is allowed or refused exactly as `--KEY V` is.

use clap::error::{ContextKind, ContextValue};
use clap::{Arg, Args, Command, FromArgMatches};

use super::error::SweepError;
use crate::messages::whole_number;
use crate::scene::{preset_names, Overrides, Scene, SceneFileError};

/// The key that picks a preset rather than a setting.
const PRESET: &str = "preset";
/// The key that picks the seed of everything random (`many`'s balls, for one).
const SEED: &str = "seed";
/// Settings one GIF cannot vary: every panel shows its frames at the same pace.
const FIXED: [&str; 1] = ["frame-ms"];

/// One panel: its label and the scene it runs.
#[derive(Clone, Debug)]
pub struct Panel {
    pub label: String,
    pub scene: Scene,
}

/// A sweep as typed: the setting (as its flag is spelt, without `--`) and its values.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct Sweep {
    pub key: String,
    pub values: Vec<String>,
}

/// What one panel changes in the scene, as if typed on the command line.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Change {
    /// `--preset NAME`.
    Preset(String),
    /// `--seed N`.
    Seed(u64),
    /// One setting's flag; every other setting is `None`.
    Setting(Box<Overrides>),
}

/// The settings' flags and `--preset`, as the main command reads them.
fn flags() -> Command {
    let command = Command::new("bouncing_ball")
        .no_binary_name(true)
        .disable_help_flag(true)
        .disable_version_flag(true);
    Overrides::augment_args(command)
        .arg(Arg::new(SEED).long(SEED).value_parser(whole_number))
        .arg(Arg::new(PRESET).long(PRESET).value_parser(preset_names()))
}

/// Every key a sweep can vary, as the flags spell them: `preset` and the settings.
pub(crate) fn keys() -> Vec<String> {
    let command = flags();
    let mut keys: Vec<String> = command
        .get_arguments()
        .filter_map(|arg| arg.get_long())
        .filter(|long| !FIXED.contains(long))
        .map(str::to_string)
        .collect();
    keys.rotate_right(1); // preset first
    keys
}

impl Sweep {
    /// Reads `KEY=V1,V2,...`; the key may be spelt as its flag (`frame-ms`) or scene key
    /// (`frame_ms`).
    pub fn parse(text: &str) -> Result<Sweep, SweepError> {
        let malformed = || SweepError::Malformed {
            text: text.to_string(),
        };
        let (key, list) = text.split_once('=').ok_or_else(malformed)?;
        let key = key.trim().replace('_', "-");
        if key.is_empty() || list.trim().is_empty() {
            return Err(malformed());
        }
        if FIXED.contains(&key.as_str()) {
            return Err(SweepError::Fixed { key });
        }
        if !keys().contains(&key) {
            let near = nearest_key(&key);
            let keys = keys().join(", ");
            return Err(SweepError::UnknownKey { key, near, keys });
        }
        let values: Vec<String> = list.split(',').map(|v| v.trim().to_string()).collect();
        if values.iter().any(String::is_empty) {
            return Err(SweepError::EmptyValue {
                key,
                list: list.to_string(),
            });
        }
        Ok(Sweep { key, values })
    }

    /// Each value as the change it makes, read by its flag's parser. `typed` says whether a
    /// setting (`damping`, by its scene name) or, for `preset`, a scene was already chosen on
    /// the command line: the sweep would then fight it.
    pub(crate) fn changes(&self, typed: impl Fn(&str) -> bool) -> Result<Vec<Change>, SweepError> {
        if typed(&self.setting()) {
            let flag = match self.key.as_str() {
                PRESET => "--preset or --scene",
                _ => "its flag",
            };
            let key = self.key.clone();
            return Err(SweepError::AlsoTyped { key, flag });
        }
        let flag = format!("--{}", self.key);
        self.values
            .iter()
            .map(|value| {
                let matches = flags()
                    .try_get_matches_from([flag.as_str(), value.as_str()])
                    .map_err(SweepError::Flag)?;
                match self.key.as_str() {
                    PRESET => return Ok(Change::Preset(value.clone())),
                    SEED => return Ok(Change::Seed(matches.get_one(SEED).copied().unwrap_or(1))),
                    _ => {}
                }
                let setting = Overrides::from_arg_matches(&matches).map_err(SweepError::Flag)?;
                Ok(Change::Setting(Box::new(setting)))
            })
            .collect()
    }

    /// The panels: each value's change laid over the scene by `scene_of`, under its label.
    /// `typed` is as for [`Sweep::changes`].
    pub(crate) fn panels(
        &self,
        typed: impl Fn(&str) -> bool,
        scene_of: impl Fn(&Change) -> Result<Scene, SceneFileError>,
    ) -> Result<Vec<Panel>, SweepError> {
        let changes = self.changes(typed)?;
        let scenes = changes.iter().map(scene_of);
        let labels = (0..changes.len()).map(|i| self.label(i));
        let panels = labels.zip(scenes).map(|(label, scene)| {
            let scene = scene?;
            Ok(Panel { label, scene })
        });
        panels.collect()
    }

    /// The swept setting as a scene names it (`frame_ms`), or `preset`.
    pub(crate) fn setting(&self) -> String {
        self.key.replace('-', "_")
    }

    /// Panel `i`'s label: `damping = 0.88`.
    pub(crate) fn label(&self, i: usize) -> String {
        format!("{} = {}", self.key, self.values[i])
    }
}

/// The key clap would suggest for a flag spelt like `key`, if any (`dampign` → `damping`).
fn nearest_key(key: &str) -> Option<String> {
    let error = flags().try_get_matches_from([format!("--{key}")]).err()?;
    match error.get(ContextKind::SuggestedArg) {
        Some(ContextValue::String(flag)) => Some(flag.trim_start_matches('-').to_string()),
        Some(ContextValue::Strings(flags)) => {
            flags.first().map(|f| f.trim_start_matches('-').to_string())
        }
        _ => None,
    }
    .filter(|near| !FIXED.contains(&near.as_str()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sweep_reads_its_key_and_values_and_labels_each_panel() {
        let sweep = Sweep::parse("damping=0.5, 0.88,1").unwrap();
        assert_eq!(sweep.key, "damping");
        assert_eq!(sweep.values, ["0.5", "0.88", "1"]);
        assert_eq!(sweep.label(1), "damping = 0.88");
        assert_eq!(Sweep::parse("trail_fade=none").unwrap().key, "trail-fade");
        let changes = sweep.changes(|_| false).unwrap();
        let damping: Vec<_> = changes
            .iter()
            .map(|c| match c {
                Change::Setting(o) => o.damping,
                Change::Preset(_) | Change::Seed(_) => None,
            })
            .collect();
        assert_eq!(damping, [Some(0.5), Some(0.88), Some(1.0)]);
    }

    #[test]
    fn a_misspelt_key_is_refused_with_the_nearest() {
        let error = Sweep::parse("dampign=0.5,1").unwrap_err().to_string();
        assert!(error.contains("did you mean damping?"), "{error}");
        assert!(error.contains("preset, width, height"), "{error}");
        assert!(!error.contains("frame-ms"), "{error}");
    }

    #[test]
    fn a_value_is_refused_with_its_flags_own_message() {
        let sweep = Sweep::parse("integrator=rk4,rk5").unwrap();
        let Err(SweepError::Flag(error)) = sweep.changes(|_| false) else {
            panic!("rk5 should be refused");
        };
        assert_eq!(error.kind(), clap::error::ErrorKind::InvalidValue);
        let sweep = Sweep::parse("width=320,-320").unwrap();
        let Err(SweepError::Flag(error)) = sweep.changes(|_| false) else {
            panic!("-320 should be refused");
        };
        assert!(error.to_string().contains("from 1 to 8192"), "{error}");
    }

    #[test]
    fn malformed_sweeps_are_refused() {
        for text in ["damping", "=1,2", "damping=", "damping=1,,2", "damping= "] {
            assert!(Sweep::parse(text).is_err(), "{text} was accepted");
        }
        assert!(matches!(
            Sweep::parse("frame_ms=30,60"),
            Err(SweepError::Fixed { .. })
        ));
        let sweep = Sweep::parse("preset=moon").unwrap();
        assert!(matches!(
            sweep.changes(|key| key == "preset"),
            Err(SweepError::AlsoTyped { .. })
        ));
    }
}
