//! The software rasteriser: one frame of balls and trails, drawn straight into palette
//! indices (imageproc's solid circles on a one-channel image whose values are indices).
//!
//! Drawing only: it reads where the balls are and never moves them.

use image::{GrayImage, Luma};
use imageproc::drawing::{draw_filled_circle_mut, draw_line_segment_mut};

use super::palette::{
    drawn_dots, fade, fade_levels, quantised_fade, shade, Colours, Palette, TooManyColours,
};
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
    /// Index of dot `i` of a trail of `n` at `(n - 1) * (n - 2) / 2 + i`: a trail of `n`
    /// draws `n - 1` dots (`drawn_dots`).
    trail_shades: Vec<u8>,
}

impl BallStyle {
    fn slot(i: usize, n: usize) -> usize {
        (n - 1) * n.saturating_sub(2) / 2 + i
    }

    fn trail_shade(&self, i: usize, n: usize) -> u8 {
        self.trail_shades[BallStyle::slot(i, n)]
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
            let slots = BallStyle::slot(0, spec.trail + 1);
            styles.push(BallStyle {
                ball,
                trail_shades: vec![0; slots],
            });
        }
        // Solid colours first, then shades of full-length trails, brightest (newest, biggest
        // dot) first: `reorder` keeps this order within each stage, and a frame where dots
        // overlap shows mostly the newest ones.
        let longest = scene.balls.iter().map(|b| b.trail).max().unwrap_or(0);
        for n in (1..=longest).rev() {
            for (spec, style) in scene.balls.iter().zip(&mut styles) {
                for i in drawn_dots(n).rev().filter(|_| n <= spec.trail) {
                    let f = levels.map_or(fade(i, n), |l| quantised_fade(fade(i, n), l));
                    style.trail_shades[BallStyle::slot(i, n)] = palette
                        .insert(shade(spec.trail_colour, f))
                        .ok_or_else(too_many)?;
                }
            }
        }
        let solid = [background, floor];
        let new_index = palette.reorder(&stages(&solid, scene, &styles));
        let [background, floor] = solid.map(|i| new_index[usize::from(i)]);
        for style in &mut styles {
            style.ball = new_index[usize::from(style.ball)];
            for shade in &mut style.trail_shades {
                *shade = new_index[usize::from(*shade)];
            }
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
    /// and shrinking into the past; the newest lies under the ball), then every ball on top,
    /// so no trail hides a ball.
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
            for (i, &(x, y)) in ball.trail.iter().enumerate().take(drawn_dots(n).end) {
                let radius = ball.radius * fade(i, n);
                fill_circle(frame, x, y, radius, style.trail_shade(i, n));
            }
        }
        for (ball, style) in balls.iter().zip(&self.styles) {
            fill_circle(frame, ball.x, ball.y, ball.radius, style.ball);
        }
    }
}

/// The colours drawn together, stage by stage: first the stage most frames show, with every
/// trail grown to full length, then each frame while trails grow (at frame `t`, a trail of
/// up to `L` points holds `min(t + 1, L)`). Every stage holds the solid colours.
fn stages(solid: &[u8], scene: &Scene, styles: &[BallStyle]) -> Vec<Colours> {
    let mut always = Colours::default();
    for &index in solid.iter().chain(styles.iter().map(|s| &s.ball)) {
        always.insert(index);
    }
    let longest = scene.balls.iter().map(|b| b.trail).max().unwrap_or(0);
    // growing[t]: what frame t draws while some trail still grows; grown: every frame after.
    let mut growing = vec![always; longest];
    let mut grown = always;
    // Balls alike in trail colour and length draw alike: look at each kind once.
    let mut seen = std::collections::HashSet::new();
    for (spec, style) in scene.balls.iter().zip(styles) {
        if !seen.insert((spec.trail_colour, spec.trail)) {
            continue;
        }
        for n in 1..=spec.trail {
            let mut dots = Colours::default();
            for i in drawn_dots(n) {
                dots.insert(style.trail_shade(i, n));
            }
            growing[n - 1] = growing[n - 1].union(&dots);
            if n == spec.trail {
                grown = grown.union(&dots);
                for stage in &mut growing[n..] {
                    *stage = stage.union(&dots);
                }
            }
        }
    }
    std::iter::once(grown).chain(growing).collect()
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
