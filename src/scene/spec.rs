//! What to simulate: the canvas, the balls and the effects, checked before anything runs.
//!
//! A scene is a plain description; `Simulation` turns it into moving balls and
//! `Renderer` into pixels. Every effect is optional and runs only if the scene names it.

use std::fmt;
use std::path::PathBuf;

use crate::physics::ball::Ball;
use crate::physics::effects::Effects;
use crate::physics::floor::Floor;
use crate::physics::motion::Motion;
use crate::physics::simulation::Simulation;
use crate::physics::vec2::Vec2;
use crate::physics::walls::Walls;

/// A colour as red, green, blue.
pub type Rgb = [u8; 3];

/// The largest canvas side we accept, px: bigger frames make GIFs no viewer wants.
pub(crate) const MAX_CANVAS_SIDE: u32 = 8192;
/// The longest trail we accept, points: every point is drawn every frame.
pub(crate) const MAX_TRAIL_LEN: usize = 1000;
/// The most balls a scene may hold.
pub(crate) const MAX_BALLS: usize = 1_000_000;
/// The most substeps a frame may be split into.
pub(crate) const MAX_SUBSTEPS: u32 = 10_000;
/// The most contact-solver iterations a step may take.
pub(crate) const MAX_ITERATIONS: u32 = 1000;
/// GIF stores frame delays in hundredths of a second, as a 16-bit number.
pub(crate) const MAX_FRAME_MS: u32 = 655_350;

/// Everything one run simulates and draws.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Canvas size, px.
    pub width: u32,
    pub height: u32,
    pub background: Rgb,
    pub balls: Vec<BallSpec>,
    /// Acceleration added to every ball's velocity each frame, px/frame² (None: no gravity).
    pub gravity: Option<Vec2>,
    /// Share of speed lost to the air each frame, 0 to 1 (None: no drag).
    pub drag: Option<f64>,
    /// The box's damping: share of speed each wall bounce keeps, 1 elastic, 0 dead stop
    /// (None: no walls).
    pub walls: Option<f64>,
    /// Segments the balls bounce off, each with its own damping.
    pub floors: Vec<Floor>,
    /// Colour floors are drawn in.
    pub floor_colour: Rgb,
    /// Ball-ball collisions and their restitution, 0 to 1 (None: balls pass through each other).
    pub ball_collisions: Option<f64>,
    /// Integrator, substeps and collision mode.
    pub motion: Motion,
    /// How many frames to simulate and draw.
    pub frames: u32,
    /// How long each frame shows in the GIF, ms (a multiple of 10).
    pub frame_ms: u32,
    /// Where a scene file asks for a plot of the run (`plot = "run.svg"`); `--plot` overrides it.
    pub plot: Option<PathBuf>,
    /// How trail dots darken into the past (the lesson's: linearly).
    pub trail_fade: TrailFade,
    /// Whether trail dots shrink into the past (the lesson's: yes, as they fade).
    pub trail_shrink: bool,
}

/// How a trail's dots darken into the past. With the trail's length and whether its dots
/// shrink, this is what the lesson calls the difference between a comet tail and a fairy-dust
/// shimmer. Dot `i` of `n` (0 the oldest) has the lesson's share `(i + 1) / n` of the colour,
/// or all of it, or that share to a power.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TrailFade {
    /// The lesson's: the share itself.
    Linear,
    /// No fading: every dot in the full trail colour.
    None,
    /// The share to this power: above 1 the tail darkens sooner, below 1 it glows longer.
    Power(f64),
}

/// The most a trail fade's power may be: beyond it every dot but the newest is black.
pub(crate) const MAX_FADE_POWER: f64 = 20.0;

impl fmt::Display for TrailFade {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TrailFade::Linear => write!(f, "linear"),
            TrailFade::None => write!(f, "none"),
            TrailFade::Power(p) => write!(f, "{p}"),
        }
    }
}

impl TrailFade {
    /// Refuses a power outside (0, [`MAX_FADE_POWER`]].
    fn check(self) -> Result<(), InvalidValue> {
        match self {
            TrailFade::Power(p) if !(p > 0.0 && p <= MAX_FADE_POWER) => Err(invalid(
                "trail_fade",
                p,
                format!("must be linear, none, or a power above 0 up to {MAX_FADE_POWER}"),
            )),
            _ => Ok(()),
        }
    }
}

impl std::str::FromStr for TrailFade {
    type Err = String;

    /// `linear`, `none`, or a power from above 0 to `MAX_FADE_POWER` (`2`, `0.5`).
    fn from_str(text: &str) -> Result<TrailFade, String> {
        match text.trim() {
            "linear" => Ok(TrailFade::Linear),
            "none" => Ok(TrailFade::None),
            number => match number.parse::<f64>() {
                Ok(p) if p > 0.0 && p <= MAX_FADE_POWER => Ok(TrailFade::Power(p)),
                _ => Err(format!(
                    "must be linear, none, or a power above 0 up to {MAX_FADE_POWER} (e.g. 2)"
                )),
            },
        }
    }
}

/// One ball as the scene starts it.
#[derive(Clone, Debug, PartialEq)]
pub struct BallSpec {
    /// Centre, px.
    pub x: f64,
    pub y: f64,
    /// Velocity, px/frame.
    pub vx: f64,
    pub vy: f64,
    /// Radius, px.
    pub radius: f64,
    pub colour: Rgb,
    pub trail_colour: Rgb,
    /// How many past positions the trail keeps (0: no trail).
    pub trail: usize,
}

/// A value the scene cannot run with: which one, what it was, and what is allowed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InvalidValue {
    /// The key, as written in a scene file (`balls[2].radius`, `damping`).
    pub key: String,
    pub value: String,
    pub allowed: String,
}

impl fmt::Display for InvalidValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} = {} is not allowed: {}",
            self.key, self.value, self.allowed
        )
    }
}

impl std::error::Error for InvalidValue {}

fn invalid(key: &str, value: impl fmt::Display, allowed: impl Into<String>) -> InvalidValue {
    InvalidValue {
        key: key.to_string(),
        value: value.to_string(),
        allowed: allowed.into(),
    }
}

/// A share of something, such as damping: a finite number from 0 to 1.
fn check_share(key: &str, value: f64) -> Result<(), InvalidValue> {
    if (0.0..=1.0).contains(&value) {
        Ok(())
    } else {
        Err(invalid(key, value, "must be from 0 to 1"))
    }
}

fn check_finite(key: &str, value: f64) -> Result<(), InvalidValue> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(invalid(key, value, "must be a finite number"))
    }
}

impl Scene {
    /// A black `width` × `height` canvas with no balls and no effects, one frame at 30 ms:
    /// a base to fill in with struct-update syntax.
    pub fn empty(width: u32, height: u32) -> Scene {
        Scene {
            width,
            height,
            background: [0, 0, 0],
            balls: Vec::new(),
            gravity: None,
            drag: None,
            walls: None,
            floors: Vec::new(),
            floor_colour: [200, 200, 200],
            ball_collisions: None,
            motion: Motion::default(),
            frames: 1,
            frame_ms: 30,
            plot: None,
            trail_fade: TrailFade::Linear,
            trail_shrink: true,
        }
    }

    /// The scene set in motion: every ball at its start, under the effects the scene names.
    pub fn simulation(&self) -> Simulation {
        let balls = self
            .balls
            .iter()
            .map(|b| Ball::new(b.x, b.y, b.vx, b.vy, b.radius, b.trail))
            .collect();
        Simulation::new(balls, self.effects(), self.motion, self.ball_collisions)
    }

    /// The forces and boundaries the scene names.
    pub fn effects(&self) -> Effects {
        Effects {
            gravity: self.gravity,
            drag: self.drag,
            walls: self.walls.map(|damping| Walls {
                width: f64::from(self.width),
                height: f64::from(self.height),
                damping,
            }),
            floors: self.floors.clone(),
        }
    }

    /// Checks every value, so the simulation and the encoder never see one they cannot handle.
    pub fn validate(&self) -> Result<(), InvalidValue> {
        for (key, side) in [("width", self.width), ("height", self.height)] {
            if !(1..=MAX_CANVAS_SIDE).contains(&side) {
                return Err(invalid(
                    key,
                    side,
                    format!("must be 1 to {MAX_CANVAS_SIDE} px"),
                ));
            }
        }
        self.validate_effects()?;
        if !(1..=MAX_SUBSTEPS).contains(&self.motion.substeps) {
            return Err(invalid(
                "substeps",
                self.motion.substeps,
                format!("must be 1 to {MAX_SUBSTEPS}"),
            ));
        }
        if !(1..=MAX_ITERATIONS).contains(&self.motion.iterations) {
            return Err(invalid(
                "iterations",
                self.motion.iterations,
                format!("must be 1 to {MAX_ITERATIONS}"),
            ));
        }
        if self.frames == 0 {
            return Err(invalid("frames", 0, "must be at least 1"));
        }
        if !self.frame_ms.is_multiple_of(10) || self.frame_ms > MAX_FRAME_MS {
            return Err(invalid(
                "frame_ms",
                self.frame_ms,
                format!("must be a multiple of 10 up to {MAX_FRAME_MS} (GIF counts hundredths of a second)"),
            ));
        }
        self.trail_fade.check()?;
        if self.balls.len() > MAX_BALLS {
            return Err(invalid(
                "balls",
                self.balls.len(),
                format!("must be at most {MAX_BALLS} balls"),
            ));
        }
        for (i, ball) in self.balls.iter().enumerate() {
            self.validate_ball(i, ball)?;
        }
        Ok(())
    }

    /// Checks the forces and boundaries: each strength finite or a share, each floor a
    /// segment of finite, distinct ends.
    fn validate_effects(&self) -> Result<(), InvalidValue> {
        if let Some(gravity) = self.gravity {
            check_finite("gravity", gravity.x)?;
            check_finite("gravity", gravity.y)?;
        }
        if let Some(drag) = self.drag {
            check_share("drag", drag)?;
        }
        if let Some(damping) = self.walls {
            check_share("walls.damping", damping)?;
        }
        if let Some(restitution) = self.ball_collisions {
            check_share("ball_collisions.restitution", restitution)?;
        }
        for (i, floor) in self.floors.iter().enumerate() {
            validate_floor(i, floor)?;
        }
        Ok(())
    }

    fn validate_ball(&self, i: usize, ball: &BallSpec) -> Result<(), InvalidValue> {
        let key = |name: &str| format!("balls[{i}].{name}");
        for (name, value) in [
            ("x", ball.x),
            ("y", ball.y),
            ("vx", ball.vx),
            ("vy", ball.vy),
            ("radius", ball.radius),
        ] {
            check_finite(&key(name), value)?;
        }
        let (width, height) = (f64::from(self.width), f64::from(self.height));
        if ball.radius <= 0.0 || 2.0 * ball.radius >= width.min(height) {
            return Err(invalid(
                &key("radius"),
                ball.radius,
                format!("must be > 0 with 2·radius < width ({width}) and height ({height})"),
            ));
        }
        let inside = |name: &str, value: f64, side: f64| {
            if value < ball.radius || value > side - ball.radius {
                Err(invalid(
                    &key(name),
                    value,
                    format!(
                        "the ball must start inside the box: {} to {} px",
                        ball.radius,
                        side - ball.radius
                    ),
                ))
            } else {
                Ok(())
            }
        };
        inside("x", ball.x, width)?;
        inside("y", ball.y, height)?;
        if ball.trail > MAX_TRAIL_LEN {
            return Err(invalid(
                &key("trail"),
                ball.trail,
                format!("must be 0 to {MAX_TRAIL_LEN} points"),
            ));
        }
        Ok(())
    }
}

/// Checks floor number `i`: finite ends that differ, and a damping that is a share.
fn validate_floor(i: usize, floor: &Floor) -> Result<(), InvalidValue> {
    let key = |name: &str| format!("floors[{i}].{name}");
    for (name, Vec2 { x, y }) in [("from", floor.from), ("to", floor.to)] {
        check_finite(&key(name), x)?;
        check_finite(&key(name), y)?;
    }
    if floor.from == floor.to {
        return Err(invalid(
            &key("to"),
            format!("{:?}", floor.to.to_array()),
            "must differ from `from`",
        ));
    }
    check_share(&key("damping"), floor.damping)
}
