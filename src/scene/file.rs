//! Scene files (TOML) and the bundled presets, which are the files under `scenes/`
//! compiled into the binary. Reading a file checks every key, type and range.

use std::path::Path;

use serde::Deserialize;

use super::random::Random;
use super::spec::{BallSpec, InvalidValue, Rgb, Scene, MAX_BALLS};
use crate::physics::floor::Floor;
use crate::physics::integrator::Integrator;
use crate::physics::motion::{CollisionMode, Motion, DEFAULT_ITERATIONS};

/// The bundled presets: name and TOML text, one per lesson exercise.
pub const PRESETS: &[(&str, &str)] = &[
    ("lesson", include_str!("../../scenes/lesson.toml")),
    ("elastic", include_str!("../../scenes/elastic.toml")),
    ("no-gravity", include_str!("../../scenes/no-gravity.toml")),
    ("heavy", include_str!("../../scenes/heavy.toml")),
    ("moon", include_str!("../../scenes/moon.toml")),
    ("many", include_str!("../../scenes/many.toml")),
    ("billiards", include_str!("../../scenes/billiards.toml")),
    ("slope", include_str!("../../scenes/slope.toml")),
    ("drag", include_str!("../../scenes/drag.toml")),
    ("pile", include_str!("../../scenes/pile.toml")),
    ("pyramid", include_str!("../../scenes/pyramid.toml")),
];

/// The lesson's colours, used where a file names none.
const BALL_COLOUR: Rgb = [255, 200, 60];
const TRAIL_COLOUR: Rgb = [60, 140, 255];

/// A scene file that cannot be used: where, which key, and why, in one line.
#[derive(Debug, thiserror::Error)]
pub enum SceneFileError {
    #[error("{file}: cannot read: {message}")]
    Read { file: String, message: String },
    #[error("{file}: line {line}: key `{key}`: {message}")]
    Parse {
        file: String,
        line: usize,
        key: String,
        message: String,
    },
    #[error("{file}: {invalid}")]
    Invalid { file: String, invalid: InvalidValue },
    #[error("no preset named {name:?}; the presets are: {}", preset_names().join(", "))]
    UnknownPreset { name: String },
}

/// The names of the bundled presets.
pub fn preset_names() -> Vec<&'static str> {
    PRESETS.iter().map(|(name, _)| *name).collect()
}

/// Reads a scene file; `seed` drives any random spawning it asks for.
pub fn load(path: &Path, seed: u64) -> Result<Scene, SceneFileError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| SceneFileError::Read {
        file: file.clone(),
        message: e.to_string(),
    })?;
    parse(&file, &text, seed)
}

/// Loads a bundled preset by name.
pub fn preset(name: &str, seed: u64) -> Result<Scene, SceneFileError> {
    let (_, text) =
        PRESETS
            .iter()
            .find(|(n, _)| *n == name)
            .ok_or_else(|| SceneFileError::UnknownPreset {
                name: name.to_string(),
            })?;
    parse(&format!("scenes/{name}.toml"), text, seed)
}

/// The `pile` preset with `count` balls of `radius` px spawned instead of its own: the
/// contact study and its tests heap up different piles in the same box.
pub fn pile(count: usize, radius: f64, seed: u64) -> Result<Scene, SceneFileError> {
    let mut scene = preset("pile", seed)?;
    let spawn = Spawn {
        count,
        radius,
        max_speed: 4.0,
        trail: 0,
        colours: Vec::new(),
        trail_colours: Vec::new(),
    };
    scene.balls = spawn.balls(f64::from(scene.width), f64::from(scene.height), seed);
    scene
        .validate()
        .map_err(|invalid| SceneFileError::Invalid {
            file: "scenes/pile.toml".to_string(),
            invalid,
        })?;
    Ok(scene)
}

/// Parses and validates scene-file text; `file` names it in errors.
pub fn parse(file: &str, text: &str, seed: u64) -> Result<Scene, SceneFileError> {
    let parse_error = |key: String, error: toml::de::Error| SceneFileError::Parse {
        file: file.to_string(),
        line: error
            .span()
            .map_or(1, |span| text[..span.start].matches('\n').count() + 1),
        key,
        message: error.message().replace('\n', " "),
    };
    let deserializer =
        toml::Deserializer::parse(text).map_err(|e| parse_error(String::new(), e))?;
    let raw: SceneFile = serde_path_to_error::deserialize(deserializer).map_err(|e| {
        let key = e.path().to_string();
        parse_error(key, e.into_inner())
    })?;
    let invalid = |invalid| SceneFileError::Invalid {
        file: file.to_string(),
        invalid,
    };
    let scene = raw.into_scene(seed).map_err(invalid)?;
    scene.validate().map_err(invalid)?;
    Ok(scene)
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    width: u32,
    height: u32,
    #[serde(default)]
    background: Rgb,
    #[serde(default = "default_frames")]
    frames: u32,
    #[serde(default = "default_frame_ms")]
    frame_ms: u32,
    gravity: Option<[f64; 2]>,
    drag: Option<f64>,
    walls: Option<WallsFile>,
    #[serde(default)]
    floors: Vec<FloorFile>,
    #[serde(default = "default_floor_colour")]
    floor_colour: Rgb,
    ball_collisions: Option<BallCollisionsFile>,
    #[serde(default)]
    integrator: Integrator,
    #[serde(default = "default_substeps")]
    substeps: u32,
    #[serde(default)]
    collisions: CollisionMode,
    #[serde(default = "default_iterations")]
    iterations: u32,
    #[serde(default)]
    balls: Vec<BallFile>,
    spawn: Option<Spawn>,
}

fn default_frames() -> u32 {
    200
}
fn default_frame_ms() -> u32 {
    30
}
fn default_floor_colour() -> Rgb {
    [200, 200, 200]
}
fn default_substeps() -> u32 {
    1
}
fn default_iterations() -> u32 {
    DEFAULT_ITERATIONS
}
fn default_trail() -> usize {
    20
}
fn default_ball_colour() -> Rgb {
    BALL_COLOUR
}
fn default_trail_colour() -> Rgb {
    TRAIL_COLOUR
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct WallsFile {
    damping: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BallCollisionsFile {
    restitution: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FloorFile {
    from: [f64; 2],
    to: [f64; 2],
    damping: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BallFile {
    x: f64,
    y: f64,
    #[serde(default)]
    vx: f64,
    #[serde(default)]
    vy: f64,
    radius: f64,
    #[serde(default = "default_ball_colour")]
    colour: Rgb,
    #[serde(default = "default_trail_colour")]
    trail_colour: Rgb,
    #[serde(default = "default_trail")]
    trail: usize,
}

/// `count` balls at random positions inside the box, moving in random directions at random
/// speeds up to `max_speed`, coloured in turn from `colours` and `trail_colours`.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Spawn {
    count: usize,
    radius: f64,
    max_speed: f64,
    #[serde(default = "default_trail")]
    trail: usize,
    colours: Vec<Rgb>,
    trail_colours: Vec<Rgb>,
}

impl SceneFile {
    fn into_scene(self, seed: u64) -> Result<Scene, InvalidValue> {
        let mut balls: Vec<BallSpec> = self
            .balls
            .into_iter()
            .map(|b| BallSpec {
                x: b.x,
                y: b.y,
                vx: b.vx,
                vy: b.vy,
                radius: b.radius,
                colour: b.colour,
                trail_colour: b.trail_colour,
                trail: b.trail,
            })
            .collect();
        if let Some(spawn) = self.spawn {
            if spawn.count > MAX_BALLS {
                return Err(InvalidValue {
                    key: "spawn.count".to_string(),
                    value: spawn.count.to_string(),
                    allowed: format!("must be at most {MAX_BALLS} balls"),
                });
            }
            balls.extend(spawn.balls(f64::from(self.width), f64::from(self.height), seed));
        }
        Ok(Scene {
            width: self.width,
            height: self.height,
            background: self.background,
            balls,
            gravity: self.gravity,
            drag: self.drag,
            walls: self.walls.map(|w| w.damping),
            floors: self
                .floors
                .into_iter()
                .map(|f| Floor {
                    from: f.from,
                    to: f.to,
                    damping: f.damping,
                })
                .collect(),
            floor_colour: self.floor_colour,
            ball_collisions: self.ball_collisions.map(|c| c.restitution),
            motion: Motion {
                integrator: self.integrator,
                substeps: self.substeps,
                collisions: self.collisions,
                iterations: self.iterations,
            },
            frames: self.frames,
            frame_ms: self.frame_ms,
        })
    }
}

impl Spawn {
    fn balls(&self, width: f64, height: f64, seed: u64) -> Vec<BallSpec> {
        let mut random = Random::new(seed);
        let cycle = |colours: &[Rgb], i: usize| colours.get(i % colours.len().max(1)).copied();
        (0..self.count)
            .map(|i| {
                let r = self.radius;
                let (x, y) = (random.range(r, width - r), random.range(r, height - r));
                let angle = random.range(0.0, std::f64::consts::TAU);
                let speed = random.range(0.0, self.max_speed);
                BallSpec {
                    x,
                    y,
                    vx: speed * angle.cos(),
                    vy: speed * angle.sin(),
                    radius: r,
                    colour: cycle(&self.colours, i).unwrap_or(BALL_COLOUR),
                    trail_colour: cycle(&self.trail_colours, i).unwrap_or(TRAIL_COLOUR),
                    trail: self.trail,
                }
            })
            .collect()
    }
}
