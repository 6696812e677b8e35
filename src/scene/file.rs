//! Scene files (TOML) and the bundled presets, which are the files under `scenes/`
//! compiled into the binary. Reading a file checks every key, type and range.

use std::io::Read;
use std::path::{Path, PathBuf};

use serde::Deserialize;

use super::overrides::Overrides;
use super::random::Random;
use super::spec::{BallSpec, InvalidValue, Rgb, Scene, TrailFade, MAX_BALLS};
use crate::physics::floor::Floor;
use crate::physics::maths;
use crate::physics::motion::{CollisionMode, Motion, DEFAULT_ITERATIONS};
use crate::physics::vec2::Vec2;
use crate::physics::Integrator;

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

/// The most bytes a scene file may hold (1 MiB): far more than any hand-written scene, and
/// a bound on what reading one costs (`[spawn]` makes crowds without long files).
pub(crate) const MAX_SCENE_BYTES: u64 = 1 << 20;

/// A scene file that cannot be used: where, which key, and why, in one line.
#[derive(Debug, thiserror::Error)]
pub enum SceneFileError {
    #[error("{file}: cannot read: {message}")]
    Read { file: String, message: String },
    #[error("{file}: {}{message}", line.map_or(String::new(), |l| format!("line {l}: ")))]
    Parse {
        file: String,
        /// None where no one line is to blame (a key missing from the whole file).
        line: Option<usize>,
        message: String,
    },
    #[error("{file}: {invalid}")]
    Invalid { file: String, invalid: InvalidValue },
    #[error("no preset named {name:?}; the presets are: {}", preset_names().join(", "))]
    UnknownPreset { name: String },
    #[error("{file}: the scene has no balls: add a [[balls]] table, or a [spawn] table with a count of 1 or more")]
    NoBalls { file: String },
}

/// The names of the bundled presets.
pub fn preset_names() -> Vec<&'static str> {
    PRESETS.iter().map(|(name, _)| *name).collect()
}

/// A canvas size typed on the command line (`--width 1920`), laid over a scene file's own
/// before its `[spawn]` places balls, so they fill the canvas the run draws.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct CanvasSize {
    pub width: Option<u32>,
    pub height: Option<u32>,
}

/// Reads a scene file (`-`: standard input); `seed` drives any random spawning it asks for.
/// Only a regular file or standard input, and at most `MAX_SCENE_BYTES` of it.
pub fn load(path: &Path, seed: u64) -> Result<Scene, SceneFileError> {
    load_on(path, seed, CanvasSize::default())
}

/// [`load`], with the balls spawned on `canvas` where it gives a size.
pub(crate) fn load_on(path: &Path, seed: u64, canvas: CanvasSize) -> Result<Scene, SceneFileError> {
    let stdin = path.as_os_str() == "-";
    let file = if stdin {
        "standard input".to_string()
    } else {
        path.display().to_string()
    };
    let read_error = |message: String| SceneFileError::Read {
        file: file.clone(),
        message,
    };
    let source: Box<dyn Read> = if stdin {
        Box::new(std::io::stdin())
    } else {
        // Looked at before opening: opening a named pipe would wait for a writer.
        let meta = std::fs::metadata(path).map_err(|e| read_error(e.to_string()))?;
        if !meta.is_file() {
            return Err(read_error(
                "not a regular file (a scene is read from a file or from standard input, -)"
                    .to_string(),
            ));
        }
        Box::new(std::fs::File::open(path).map_err(|e| read_error(e.to_string()))?)
    };
    let mut bytes = Vec::new();
    source
        .take(MAX_SCENE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| read_error(e.to_string()))?;
    if bytes.len() as u64 > MAX_SCENE_BYTES {
        return Err(read_error(format!(
            "longer than {} KiB, the most a scene file may be",
            MAX_SCENE_BYTES >> 10
        )));
    }
    let text = String::from_utf8(bytes).map_err(|_| read_error("not UTF-8 text".to_string()))?;
    // Windows editors (Notepad among them) may begin UTF-8 with a byte-order mark; TOML has
    // no place for one. Line endings need nothing: TOML takes CRLF as it takes LF.
    let text = text.strip_prefix('\u{feff}').unwrap_or(&text);
    let scene = parse_on(&file, text, seed, canvas)?;
    // An empty animation is never what a scene file run meant.
    match scene.balls.is_empty() {
        true => Err(SceneFileError::NoBalls { file }),
        false => Ok(scene),
    }
}

/// Loads a bundled preset by name.
pub fn preset(name: &str, seed: u64) -> Result<Scene, SceneFileError> {
    preset_on(name, seed, CanvasSize::default())
}

/// [`preset`], with the balls spawned on `canvas` where it gives a size.
pub(crate) fn preset_on(
    name: &str,
    seed: u64,
    canvas: CanvasSize,
) -> Result<Scene, SceneFileError> {
    let (_, text) =
        PRESETS
            .iter()
            .find(|(n, _)| *n == name)
            .ok_or_else(|| SceneFileError::UnknownPreset {
                name: name.to_string(),
            })?;
    parse_on(&format!("scenes/{name}.toml"), text, seed, canvas)
}

/// Parses and validates scene-file text; `file` names it in errors.
pub fn parse(file: &str, text: &str, seed: u64) -> Result<Scene, SceneFileError> {
    parse_on(file, text, seed, CanvasSize::default())
}

/// [`parse`], with the balls spawned on `canvas` where it gives a size.
fn parse_on(
    file: &str,
    text: &str,
    seed: u64,
    canvas: CanvasSize,
) -> Result<Scene, SceneFileError> {
    let parse_error = |key: String, error: toml::de::Error| {
        let span = error.span().unwrap_or(0..0);
        let start = span.start.min(text.len());
        let end = span.end.clamp(start, text.len());
        let line = text[..start].matches('\n').count() + 1;
        let line_text = text.lines().nth(line - 1).unwrap_or("");
        let message = error.message().replace('\n', " ");
        let whole_file = key.is_empty() || key == ".";
        let missing = message.starts_with("missing field");
        SceneFileError::Parse {
            file: file.to_string(),
            line: (!(whole_file && missing)).then_some(line),
            message: plain_message(&message, &key, &text[start..end], line_text),
        }
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
    let scene = raw.on(canvas).into_scene(seed).map_err(invalid)?;
    scene.validate().map_err(invalid)?;
    Ok(scene)
}

/// The TOML reader's message in the words of a scene file: keys (not fields) named as
/// written, tables by their header, numbers (not Rust types). `key` is where it happened
/// (`balls[0]`), `at` the text the reader points at, `line_text` that whole line.
fn plain_message(message: &str, key: &str, at: &str, line_text: &str) -> String {
    let within = match key {
        "" | "." => String::new(),
        key => format!(" in `{key}`"),
    };
    let quoted = |rest: &str| rest.split('`').nth(1).unwrap_or("").to_string();
    if let Some(rest) = message.strip_prefix("missing field") {
        return format!("missing key `{}`{within}", quoted(rest));
    }
    if let Some(rest) = message.strip_prefix("unknown field") {
        let allowed = rest.split_once("expected ").map_or("", |(_, a)| a);
        let allowed = allowed.trim_start_matches("one of ");
        let unknown = quoted(rest);
        // The nearest allowed key by the similarity clap's suggestions use (`gravty`).
        let near = allowed
            .split(", ")
            .map(|key| key.trim_matches('`'))
            .map(|key| (strsim::jaro(&unknown, key), key))
            .filter(|(likeness, _)| *likeness > 0.7)
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .map_or(String::new(), |(_, key)| format!("; did you mean `{key}`?"));
        return format!("unknown key `{unknown}`{near}; the keys allowed here are {allowed}");
    }
    if message.starts_with("unclosed array table") || message.starts_with("unclosed table") {
        let name: String = line_text
            .trim_start()
            .trim_start_matches('[')
            .chars()
            .take_while(|c| !matches!(c, ']' | '#' | '='))
            .collect();
        let (open, close) = if message.starts_with("unclosed array") {
            ("[[", "]]")
        } else {
            ("[", "]")
        };
        return format!("unclosed {open}{}{close} table", name.trim());
    }
    if message.starts_with("duplicate key") && !at.is_empty() && !at.contains('\n') {
        return format!("duplicate key `{}`", at.trim());
    }
    // A whole number's real range, where it is a setting with one (`width`: 1 to 8192).
    let setting = key.rsplit('.').next().unwrap_or(key);
    let whole = match Overrides::whole_range(setting) {
        Some(range) => format!(
            "expected a whole number from {} to {}",
            range.start(),
            range.end()
        ),
        None => "expected a whole number".to_string(),
    };
    let plain = message
        .replace("expected u8", "expected a whole number from 0 to 255")
        .replace("expected u32", &whole)
        .replace("expected usize", &whole)
        .replace("expected f64", "expected a number");
    match key {
        "" | "." => plain,
        key => format!("key `{key}`: {plain}"),
    }
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
    /// `[x, y]` as the file writes it (the scene holds it as a `Vec2`, as it holds floors).
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
    /// Where to draw the plot of the run, relative to the current folder (as `--plot` is).
    plot: Option<PathBuf>,
    trail_fade: Option<FadeFile>,
    #[serde(default = "default_trail_shrink")]
    trail_shrink: bool,
}

/// How a file spells a trail fade: `"linear"`, `"none"`, or a power (`2.0`, or `"2"`).
#[derive(Deserialize)]
#[serde(untagged)]
enum FadeFile {
    Name(String),
    Power(f64),
}

impl FadeFile {
    fn read(self) -> Result<TrailFade, InvalidValue> {
        let text = match self {
            FadeFile::Name(name) => name,
            FadeFile::Power(power) => power.to_string(),
        };
        text.parse().map_err(|allowed| InvalidValue {
            key: "trail_fade".to_string(),
            value: text,
            allowed,
        })
    }
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
fn default_trail_shrink() -> bool {
    true
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
/// A `[spawn]` without colours takes the lesson's.
fn default_colours() -> Vec<Rgb> {
    vec![BALL_COLOUR]
}
fn default_trail_colours() -> Vec<Rgb> {
    vec![TRAIL_COLOUR]
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

/// A `[[floors]]` table. The physics layer's `Floor` has no serde (as `Integrator` and
/// `CollisionMode` have none: their names are read in `super::names`), so the file's spelling
/// of a floor lives here; a hand-written `Deserialize` for `Floor` would be longer than this.
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

impl FloorFile {
    /// The floor as the scene holds it.
    fn floor(&self) -> Floor {
        Floor {
            from: Vec2::from(self.from),
            to: Vec2::from(self.to),
            damping: self.damping,
        }
    }
}

impl BallFile {
    /// The ball as the scene holds it.
    fn spec(&self) -> BallSpec {
        BallSpec {
            x: self.x,
            y: self.y,
            vx: self.vx,
            vy: self.vy,
            radius: self.radius,
            colour: self.colour,
            trail_colour: self.trail_colour,
            trail: self.trail,
        }
    }
}

/// `count` balls at random positions inside the box, moving in random directions at random
/// speeds up to `max_speed`, coloured in turn from `colours` and `trail_colours`: a `[spawn]`
/// table. Public, with [`Spawn::new`] and [`Spawn::overlapping_balls`], so the lab
/// (`bouncing_ball_lab::scenes`) can heap up its own piles of balls spawned as scene files
/// spawn them.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Spawn {
    count: usize,
    radius: f64,
    max_speed: f64,
    #[serde(default = "default_trail")]
    trail: usize,
    #[serde(default = "default_colours")]
    colours: Vec<Rgb>,
    #[serde(default = "default_trail_colours")]
    trail_colours: Vec<Rgb>,
}

impl SceneFile {
    /// The file with `canvas`'s size in place of its own, where `canvas` gives one.
    fn on(self, canvas: CanvasSize) -> SceneFile {
        SceneFile {
            width: canvas.width.unwrap_or(self.width),
            height: canvas.height.unwrap_or(self.height),
            ..self
        }
    }

    fn into_scene(self, seed: u64) -> Result<Scene, InvalidValue> {
        let floors: Vec<Floor> = self.floors.iter().map(FloorFile::floor).collect();
        let mut balls: Vec<BallSpec> = self.balls.iter().map(BallFile::spec).collect();
        if let Some(spawn) = &self.spawn {
            balls.extend(self.spawned(spawn, seed, &floors)?);
        }
        Ok(Scene {
            width: self.width,
            height: self.height,
            background: self.background,
            balls,
            gravity: self.gravity.map(Vec2::from),
            drag: self.drag,
            walls: self.walls.map(|w| w.damping),
            floors,
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
            plot: self.plot,
            trail_fade: self
                .trail_fade
                .map_or(Ok(TrailFade::Linear), FadeFile::read)?,
            trail_shrink: self.trail_shrink,
        })
    }

    /// The balls `spawn` places in this file's box, above `floors`: apart if they collide,
    /// anywhere if they pass through each other (as the `many` preset's always have).
    fn spawned(
        &self,
        spawn: &Spawn,
        seed: u64,
        floors: &[Floor],
    ) -> Result<Vec<BallSpec>, InvalidValue> {
        if spawn.count > MAX_BALLS {
            return Err(InvalidValue {
                key: "spawn.count".to_string(),
                value: spawn.count.to_string(),
                allowed: format!("must be at most {MAX_BALLS} balls"),
            });
        }
        let (width, height) = (f64::from(self.width), f64::from(self.height));
        let spawned = match self.ball_collisions {
            Some(_) => spawn.balls(width, height, seed, floors),
            None => spawn.overlapping_balls_above(width, height, seed, floors),
        };
        spawned.ok_or_else(|| InvalidValue {
            key: "spawn.count".to_string(),
            value: spawn.count.to_string(),
            allowed: format!(
                "there is no room for that many balls of radius {} above the floors",
                spawn.radius
            ),
        })
    }
}

impl Spawn {
    /// `count` balls of `radius` px at speeds up to `max_speed` px/frame, with no trails and
    /// the default colours.
    pub fn new(count: usize, radius: f64, max_speed: f64) -> Spawn {
        Spawn {
            count,
            radius,
            max_speed,
            trail: 0,
            colours: Vec::new(),
            trail_colours: Vec::new(),
        }
    }

    /// The balls, spread over the box so that they never overlap when they fit side by side:
    /// the box is cut into equal square slots (the largest that give one per ball above the
    /// floors), the balls go into slots picked at random, each at a random spot inside its
    /// slot. A slot narrower than a ball gets the ball at its centre: so many balls cannot
    /// help overlapping. `None` if the floors leave no room for them.
    fn balls(&self, width: f64, height: f64, seed: u64, floors: &[Floor]) -> Option<Vec<BallSpec>> {
        let mut random = Random::new(seed);
        let r = self.radius;
        // Smaller slots until enough lie wholly above the floors (all do without floors).
        let (side, corner, mut order) = (self.count..=self.count.saturating_mul(64))
            .step_by(self.count.div_ceil(8).max(1))
            .find_map(|slots_wanted| {
                let (columns, rows) = slots(width, height, slots_wanted)?;
                let side = width / columns as f64;
                let corner = Vec2::new(0.0, (height - rows as f64 * side) / 2.0);
                let reach = r + (side / 2.0 - r).max(0.0) * std::f64::consts::SQRT_2;
                // Each slot's centre from the corner (added last, as the spot's is).
                let centre = |slot: usize| {
                    let k = Vec2::new((slot % columns) as f64, (slot / columns) as f64);
                    (k + Vec2::new(0.5, 0.5)) * side
                };
                let free: Vec<Vec2> = (0..columns * rows)
                    .map(centre)
                    .filter(|&c| above_floors(corner + c, reach, floors))
                    .collect();
                (free.len() >= self.count).then_some((side, corner, free))
            })?;
        // The first `count` of the slots shuffled (Fisher–Yates, stopped early).
        for i in 0..self.count {
            let pick = i + (random.next_u64() % (order.len() - i) as u64) as usize;
            order.swap(i, pick);
        }
        let play = (side / 2.0 - r).max(0.0);
        let balls = order[..self.count].iter().enumerate().map(|(i, &centre)| {
            let jitter = Vec2::new(random.range(-play, play), random.range(-play, play));
            let spot = corner + (centre + jitter);
            // `max`/`min` rather than `clamp`, which panics on a radius too big for the
            // box (validation names that one).
            let x = spot.x.max(r).min(width - r);
            let y = spot.y.max(r).min(height - r);
            self.ball(i, x, y, &mut random)
        });
        Some(balls.collect())
    }

    /// The balls at uniformly random spots, overlapping where chance puts them: for balls
    /// that pass through each other, and for the contact study's piles
    /// (`bouncing_ball_lab::scenes::pile`), whose measured figures (`docs/contacts.md`) are
    /// for these.
    pub fn overlapping_balls(&self, width: f64, height: f64, seed: u64) -> Vec<BallSpec> {
        self.overlapping_balls_above(width, height, seed, &[])
            .unwrap_or_default()
    }

    /// [`Spawn::overlapping_balls`], each ball drawn again until it lies wholly above the
    /// floors; `None` if one is drawn [`SPAWN_TRIES`] times without.
    fn overlapping_balls_above(
        &self,
        width: f64,
        height: f64,
        seed: u64,
        floors: &[Floor],
    ) -> Option<Vec<BallSpec>> {
        let mut random = Random::new(seed);
        let r = self.radius;
        (0..self.count)
            .map(|i| {
                let spot = (0..SPAWN_TRIES)
                    .map(|_| Vec2::new(random.range(r, width - r), random.range(r, height - r)))
                    .find(|&spot| above_floors(spot, r, floors))?;
                Some(self.ball(i, spot.x, spot.y, &mut random))
            })
            .collect()
    }

    /// Ball number `i` at `(x, y)`, moving in a random direction at a random speed.
    fn ball(&self, i: usize, x: f64, y: f64, random: &mut Random) -> BallSpec {
        let cycle = |colours: &[Rgb]| colours.get(i % colours.len().max(1)).copied();
        let angle = random.range(0.0, std::f64::consts::TAU);
        let speed = random.range(0.0, self.max_speed);
        BallSpec {
            x,
            y,
            vx: speed * maths::cos(angle),
            vy: speed * maths::sin(angle),
            radius: self.radius,
            colour: cycle(&self.colours).unwrap_or(BALL_COLOUR),
            trail_colour: cycle(&self.trail_colours).unwrap_or(TRAIL_COLOUR),
            trail: self.trail,
        }
    }
}

/// How many spots a spawned ball may be drawn at before the floors are taken to leave it no
/// room.
const SPAWN_TRIES: usize = 10_000;

/// Whether a disc of radius `reach` at `centre` lies wholly above every floor: clear of the
/// segment, and not below it where it spans the disc's x (y grows downwards).
fn above_floors(centre: Vec2, reach: f64, floors: &[Floor]) -> bool {
    floors.iter().all(|floor| {
        let [from, to] = floor.ends();
        let (_, distance) = floor.nearest(centre);
        let (left, right) = (from.x.min(to.x), from.x.max(to.x));
        let under = left < right
            && (left..=right).contains(&centre.x)
            && centre.y > from.y + (to.y - from.y) * (centre.x - from.x) / (to.x - from.x);
        distance >= reach && !under
    })
}

/// The columns and rows of the largest square slots, a whole number across the width, of
/// which at least `count` fit in a `width` × `height` box (`None` for an empty box).
fn slots(width: f64, height: f64, count: usize) -> Option<(usize, usize)> {
    if !(width >= 1.0 && height >= 1.0) {
        return None;
    }
    // From about √(count·width/height) columns, but at least enough for square slots to fit
    // the height once: then `count` columns surely give `count` slots, so the loop is short.
    let fewest = ((count as f64 * width / height).sqrt().floor()).max((width / height).ceil());
    let mut columns = (fewest as usize).max(1);
    loop {
        let rows = (height * columns as f64 / width) as usize;
        if columns * rows >= count {
            return Some((columns, rows));
        }
        columns += 1;
    }
}
