//! The software rasteriser: one frame of balls and trails, drawn straight into palette
//! indices (imageproc's solid circles on a one-channel image whose values are indices).
//!
//! Drawing only: it reads where the balls are and never moves them.

use image::{GrayImage, Luma};
use imageproc::drawing::{draw_filled_circle_mut, draw_line_segment_mut};

use super::palette::{fade, fade_levels, quantised_fade, shade, Palette, TooManyColours};
use crate::physics::ball::Ball;
use crate::physics::floor::Floor;
use crate::scene::spec::Scene;

/// A frame as palette indices, one byte per pixel.
pub type IndexedFrame = GrayImage;

/// Draws a scene's balls with the scene's colours.
#[derive(Clone, Debug)]
pub struct Renderer {
    width: u32,
    height: u32,
    palette: Palette,
    background: u8,
    floors: Vec<Floor>,
    floor: u8,
    styles: Vec<BallStyle>,
}

/// The palette indices one ball is drawn with.
#[derive(Clone, Debug)]
struct BallStyle {
    ball: u8,
    /// Index of dot `i` of a trail of `n` at `n * (n - 1) / 2 + i`.
    trail_shades: Vec<u8>,
}

impl BallStyle {
    fn trail_shade(&self, i: usize, n: usize) -> u8 {
        self.trail_shades[n * (n - 1) / 2 + i]
    }
}

impl Renderer {
    /// Builds the palette for a (validated) scene.
    pub fn new(scene: &Scene) -> Result<Renderer, TooManyColours> {
        let floor_colour = (!scene.floors.is_empty()).then_some(scene.floor_colour);
        let solid: Vec<_> = std::iter::once(scene.background)
            .chain(floor_colour)
            .chain(scene.balls.iter().map(|b| b.colour))
            .collect();
        let trails: Vec<_> = scene
            .balls
            .iter()
            .map(|b| (b.trail_colour, b.trail))
            .collect();
        let levels = fade_levels(&solid, &trails)?;
        let mut palette = Palette::new();
        let too_many = || TooManyColours {
            needed: solid.len(),
        };
        let background = palette.insert(scene.background).ok_or_else(too_many)?;
        let floor = match floor_colour {
            Some(colour) => palette.insert(colour).ok_or_else(too_many)?,
            None => background,
        };
        let mut styles = Vec::with_capacity(scene.balls.len());
        for spec in &scene.balls {
            let ball = palette.insert(spec.colour).ok_or_else(too_many)?;
            let mut trail_shades = Vec::with_capacity(spec.trail * (spec.trail + 1) / 2);
            for n in 1..=spec.trail {
                for i in 0..n {
                    let f = levels.map_or(fade(i, n), |l| quantised_fade(fade(i, n), l));
                    let index = palette
                        .insert(shade(spec.trail_colour, f))
                        .ok_or_else(too_many)?;
                    trail_shades.push(index);
                }
            }
            styles.push(BallStyle { ball, trail_shades });
        }
        Ok(Renderer {
            width: scene.width,
            height: scene.height,
            palette,
            background,
            floors: scene.floors.clone(),
            floor,
            styles,
        })
    }

    /// The colour table every frame's indices refer to.
    pub fn palette(&self) -> &Palette {
        &self.palette
    }

    /// A blank frame of the scene's size.
    pub fn new_frame(&self) -> IndexedFrame {
        GrayImage::from_pixel(self.width, self.height, Luma([self.background]))
    }

    /// Draws `balls` into `frame`: background and floors, then every trail (oldest dot first, fading
    /// and shrinking into the past), then every ball on top, so no trail hides a ball.
    pub fn draw(&self, balls: &[Ball], frame: &mut IndexedFrame) {
        frame.fill(self.background);
        for floor in &self.floors {
            let point = |[x, y]: [f64; 2]| (x as f32, y as f32);
            draw_line_segment_mut(
                frame,
                point(floor.from),
                point(floor.to),
                Luma([self.floor]),
            );
        }
        for (ball, style) in balls.iter().zip(&self.styles) {
            let n = ball.trail.len();
            for (i, &(x, y)) in ball.trail.iter().enumerate() {
                let radius = ball.radius * fade(i, n);
                fill_circle(frame, x, y, radius, style.trail_shade(i, n));
            }
        }
        for (ball, style) in balls.iter().zip(&self.styles) {
            fill_circle(frame, ball.x, ball.y, ball.radius, style.ball);
        }
    }
}

/// A solid circle centred on the nearest pixel to `(x, y)`, radius rounded to whole pixels.
fn fill_circle(frame: &mut IndexedFrame, x: f64, y: f64, radius: f64, index: u8) {
    let centre = (x.round() as i32, y.round() as i32);
    draw_filled_circle_mut(frame, centre, radius.round() as i32, Luma([index]));
}

/// A frame's colours: each index looked up in the palette.
pub fn to_rgb(frame: &IndexedFrame, palette: &Palette) -> image::RgbImage {
    image::RgbImage::from_fn(frame.width(), frame.height(), |x, y| {
        image::Rgb(palette.rgb(frame.get_pixel(x, y)[0]))
    })
}
