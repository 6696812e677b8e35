//! The `--plot` picture of a run: for one ball its height above the floor, speed and
//! mechanical energy against frame, bounces marked; for many balls their total kinetic and
//! potential energy and, with ball collisions, the deepest overlap. SVG, or PNG for a path
//! ending in `.png`.
//!
//! It reads the states the run produces (the same ones the trace writes) and the scene's
//! settings; nothing in physics, scene, render or gif imports it.
//!
//! - `record`: the numbers, one per series per frame.
//! - `draw`: the picture, with plotters.

pub(crate) mod draw;
pub(crate) mod record;

use std::io::{self, Write};
use std::path::Path;
use std::sync::OnceLock;

use image::ImageEncoder;
use plotters::coord::Shift;
use plotters::prelude::{
    BitMapBackend, DrawingArea, DrawingAreaErrorKind, DrawingBackend, IntoDrawingArea, SVGBackend,
    WHITE,
};
use plotters::style::{register_font, FontStyle};

use crate::output::{commit_all, AtomicFile, OutputError};
use crate::physics::ball::Ball;
use crate::physics::vec2::Vec2;
use crate::scene::{InvalidValue, Scene};
use record::Recording;

/// The most frames a plot records: it draws a point per frame per series, so this bounds its
/// memory (a few MB) and the size of the picture.
pub(crate) const MAX_PLOT_FRAMES: u32 = 100_000;

/// The picture's file format, chosen by the path's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Format {
    Svg,
    Png,
}

impl Format {
    /// PNG for a path ending in `.png`, SVG for `.svg` or no extension; any other extension
    /// is refused rather than given content it does not promise.
    pub(crate) fn of(path: &Path) -> Result<Format, InvalidValue> {
        let extension = path.extension().map(|e| e.to_ascii_lowercase());
        match extension.as_ref().and_then(|e| e.to_str()) {
            None | Some("svg") => Ok(Format::Svg),
            Some("png") => Ok(Format::Png),
            Some(_) => Err(InvalidValue {
                key: "plot".to_string(),
                value: path.display().to_string(),
                allowed: "must end in .svg or .png (no extension: SVG)".to_string(),
            }),
        }
    }
}

/// A plot being recorded during a run, written when the run ends.
#[derive(Clone, Debug)]
pub(crate) struct Plot {
    format: Format,
    recording: Recording,
    title: Vec<String>,
}

impl Plot {
    /// A plot of `scene` to be written at `path` (whose extension picks the format).
    pub(crate) fn new(scene: &Scene, path: &Path) -> Result<Plot, InvalidValue> {
        let format = Format::of(path)?;
        if scene.frames > MAX_PLOT_FRAMES {
            return Err(InvalidValue {
                key: "frames".to_string(),
                value: scene.frames.to_string(),
                allowed: format!(
                    "must be at most {MAX_PLOT_FRAMES} with a plot (it draws every frame)"
                ),
            });
        }
        Ok(Plot {
            format,
            recording: Recording::new(scene),
            title: settings(scene),
        })
    }

    /// Adds one frame: the balls right after the frame's step.
    pub fn record(&mut self, balls: &[Ball]) {
        self.recording.record(balls);
    }

    /// Draws the recording and writes it to `out`.
    pub(crate) fn write(&self, mut out: impl Write) -> io::Result<()> {
        use_embedded_font()?;
        let size = draw::size(&self.recording, &self.title);
        match self.format {
            Format::Svg => {
                let mut text = String::new();
                {
                    let root = SVGBackend::with_string(&mut text, size).into_drawing_area();
                    draw::draw(&root, &self.recording, &self.title).map_err(io::Error::other)?;
                }
                out.write_all(text.as_bytes())
            }
            Format::Png => write_png(out, size, |root| {
                draw::draw(root, &self.recording, &self.title)
            }),
        }
    }
}

/// A plotters drawing area over an RGB buffer, and what drawing on it can fail with.
pub(crate) type BitmapArea<'a> = DrawingArea<BitMapBackend<'a>, Shift>;
pub(crate) type BitmapAreaError =
    DrawingAreaErrorKind<<BitMapBackend<'static> as DrawingBackend>::ErrorType>;

/// Lets `draw` paint on a white canvas of `size` px and saves it as a PNG at `path`, whole
/// or not at all: the accuracy study's plots.
pub fn save_png(
    path: &Path,
    size: (u32, u32),
    draw: impl FnOnce(&BitmapArea) -> Result<(), BitmapAreaError>,
) -> Result<(), OutputError> {
    let file = AtomicFile::create(path)?;
    write_png(file.file(), size, |root| {
        root.fill(&WHITE)?;
        draw(root)?;
        root.present()
    })
    .map_err(OutputError::at(path))?;
    commit_all(vec![file])?;
    Ok(())
}

/// Lets `draw` paint on a black canvas of `size` px, then writes it to `out` as a PNG.
pub(crate) fn write_png(
    out: impl Write,
    size: (u32, u32),
    draw: impl FnOnce(&BitmapArea) -> Result<(), BitmapAreaError>,
) -> io::Result<()> {
    use_embedded_font()?;
    let mut rgb = vec![0u8; size.0 as usize * size.1 as usize * 3];
    draw(&BitMapBackend::with_buffer(&mut rgb, size).into_drawing_area())
        .map_err(io::Error::other)?;
    image::codecs::png::PngEncoder::new(out)
        .write_image(&rgb, size.0, size.1, image::ExtendedColorType::Rgb8)
        .map_err(io::Error::other)
}

/// The settings that shape the curves, for the title: how many balls, the solver
/// (integrator, substeps, collision mode), the walls' damping and the forces.
fn settings(scene: &Scene) -> Vec<String> {
    let motion = scene.motion;
    let balls = scene.balls.len();
    let mut parts = vec![
        format!("{balls} ball{}", if balls == 1 { "" } else { "s" }),
        flag_name(motion.integrator),
        format!(
            "{} substep{}",
            motion.substeps,
            if motion.substeps == 1 { "" } else { "s" }
        ),
        format!("collisions {}", flag_name(motion.collisions)),
        match scene.walls {
            Some(damping) => format!("damping {damping}"),
            None => "no walls".to_string(),
        },
        match scene.gravity {
            Some(Vec2 { x: 0.0, y: g }) => format!("gravity {g} px/frame²"),
            Some(Vec2 { x: gx, y: gy }) => format!("gravity ({gx}, {gy}) px/frame²"),
            None => "no gravity".to_string(),
        },
    ];
    if let Some(drag) = scene.drag {
        parts.push(format!("drag {drag}"));
    }
    if !scene.floors.is_empty() {
        parts.push(format!("{} floors", scene.floors.len()));
    }
    if let Some(restitution) = scene.ball_collisions {
        parts.push(format!("ball collisions, restitution {restitution}"));
    }
    if balls != 1 {
        parts.push("mass ∝ radius², average ball = 1".to_string());
    }
    parts
}

/// A value as its flag spells it (`semi-implicit-euler`), not as Rust prints it.
pub fn flag_name(value: impl crate::scene::Named) -> String {
    value.name().to_string()
}

/// Makes plotters' "sans-serif" the DejaVu Sans compiled into the program, so text needs no
/// system font. Safe to call any number of times; registers once.
pub(crate) fn use_embedded_font() -> io::Result<()> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let registered = *REGISTERED.get_or_init(|| {
        register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular()).is_ok()
    });
    if registered {
        Ok(())
    } else {
        Err(io::Error::other("the embedded font did not load"))
    }
}
