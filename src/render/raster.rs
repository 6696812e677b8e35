//! The software rasteriser: one frame of balls and trails, drawn straight into palette
//! indices on a one-channel image whose values are indices. Circles are Pillow's, pixel for
//! pixel ([`super::ellipse`]); floors are imageproc's line segments, clipped to the canvas.
//!
//! Drawing only: it reads where the balls are and never moves them.

use std::collections::HashMap;
use std::sync::Arc;

use image::{GrayImage, Luma};
use imageproc::drawing::draw_line_segment_mut;

use super::ellipse::fill_circle;
use super::palette::{
    fade, fade_levels, quantised_fade, shade, IndexedFrame, Palette, TooManyColours,
};
use crate::physics::ball::Ball;
use crate::physics::floor::Floor;
use crate::scene::spec::{Rgb, Scene};

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
    /// Index of dot `i` of a trail of `n` at `n * (n - 1) / 2 + i`. A shade depends only on
    /// the trail colour, so balls of one trail colour share one table, as long as their
    /// longest trail needs: memory follows the trail colours, not the number of balls.
    trail_shades: Arc<[u8]>,
}

impl BallStyle {
    fn trail_shade(&self, i: usize, n: usize) -> u8 {
        self.trail_shades[n * (n - 1) / 2 + i]
    }
}

/// One trail colour's shades, for every trail up to `longest` points, laid out as
/// [`BallStyle::trail_shades`].
#[derive(Default)]
struct ShadeTable {
    longest: usize,
    shades: Vec<u8>,
}

impl ShadeTable {
    /// Adds the shades of trails up to `trail` points in `colour` to the table and the
    /// palette (faded to `levels` steps when given). `None` once the palette is full.
    fn extend_to(
        &mut self,
        trail: usize,
        colour: Rgb,
        levels: Option<usize>,
        palette: &mut Palette,
    ) -> Option<()> {
        for n in self.longest + 1..=trail {
            for i in 0..n {
                let f = levels.map_or(fade(i, n), |l| quantised_fade(fade(i, n), l));
                self.shades.push(palette.insert(shade(colour, f))?);
            }
        }
        self.longest = self.longest.max(trail);
        Some(())
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
        let mut longest: HashMap<Rgb, usize> = HashMap::new();
        for ball in &scene.balls {
            let len = longest.entry(ball.trail_colour).or_default();
            *len = (*len).max(ball.trail);
        }
        let trails: Vec<(Rgb, usize)> = longest.into_iter().collect();
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
        // Ball by ball as before, so the palette's order (and the GIF's bytes) stay the
        // same: a trail longer than its colour's table so far extends that table.
        let mut tables: Vec<ShadeTable> = Vec::new();
        let mut table_of: HashMap<Rgb, usize> = HashMap::new();
        let mut uses = Vec::with_capacity(scene.balls.len());
        for spec in &scene.balls {
            let ball = palette.insert(spec.colour).ok_or_else(too_many)?;
            let table = *table_of.entry(spec.trail_colour).or_insert_with(|| {
                tables.push(ShadeTable::default());
                tables.len() - 1
            });
            tables[table]
                .extend_to(spec.trail, spec.trail_colour, levels, &mut palette)
                .ok_or_else(too_many)?;
            uses.push((ball, table));
        }
        let tables: Vec<Arc<[u8]>> = tables.into_iter().map(|t| t.shades.into()).collect();
        let styles = uses
            .into_iter()
            .map(|(ball, table)| BallStyle {
                ball,
                trail_shades: Arc::clone(&tables[table]),
            })
            .collect();
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
        let canvas = [f64::from(self.width), f64::from(self.height)];
        for floor in &self.floors {
            if let Some((from, to)) = clip_segment(floor.from, floor.to, canvas) {
                let point = |[x, y]: [f64; 2]| (x as f32, y as f32);
                draw_line_segment_mut(frame, point(from), point(to), Luma([self.floor]));
            }
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

/// The segment `from`-`to`, cut along its longer axis to one pixel beyond the canvas
/// (`canvas` = width, height), in floating point: imageproc walks the longer axis pixel by
/// pixel, so a floor from -1e30 to 1e30 then costs no more than one across the canvas.
/// `None` when it misses the canvas along that axis. Ends already inside stay, to the bit.
fn clip_segment(from: [f64; 2], to: [f64; 2], canvas: [f64; 2]) -> Option<([f64; 2], [f64; 2])> {
    let delta = [to[0] - from[0], to[1] - from[1]];
    let (major, minor) = if delta[1].abs() > delta[0].abs() {
        (1, 0)
    } else {
        (0, 1)
    };
    let (low, high) = (-1.0, canvas[major] + 1.0);
    if from[major].max(to[major]) < low || from[major].min(to[major]) > high {
        return None;
    }
    // The line as `minor = intercept + slope * major`, |slope| <= 1. Floating point cannot
    // place a line finer than the last bit of its far ends, but in this form lines such as
    // y = 120 or y = x with ends at ±1e30 come out exact.
    let slope = delta[minor] / delta[major];
    let intercept = from[minor] - slope * from[major];
    let cut = |end: [f64; 2]| {
        let along = end[major].clamp(low, high);
        if along == end[major] {
            return end;
        }
        let mut point = [0.0; 2];
        point[major] = along;
        point[minor] = intercept + slope * along;
        point
    };
    Some((cut(from), cut(to)))
}

/// A frame's colours: each index looked up in the palette.
pub fn to_rgb(frame: &IndexedFrame, palette: &Palette) -> image::RgbImage {
    image::RgbImage::from_fn(frame.width(), frame.height(), |x, y| {
        image::Rgb(palette.rgb(frame.get_pixel(x, y)[0]))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::spec::BallSpec;

    fn ball(trail_colour: Rgb, trail: usize) -> BallSpec {
        BallSpec {
            x: 50.0,
            y: 50.0,
            vx: 0.0,
            vy: 0.0,
            radius: 5.0,
            colour: [255, 200, 60],
            trail_colour,
            trail,
        }
    }

    #[test]
    fn balls_of_one_trail_colour_share_a_table_that_gives_every_ball_its_exact_shades() {
        let (blue, red) = ([60, 140, 255], [255, 90, 90]);
        let scene = Scene {
            balls: vec![ball(blue, 5), ball(red, 3), ball(blue, 2), ball(blue, 9)],
            ..Scene::empty(100, 100)
        };
        let renderer = Renderer::new(&scene).unwrap();
        for (spec, style) in scene.balls.iter().zip(&renderer.styles) {
            for n in 1..=spec.trail {
                for i in 0..n {
                    let got = renderer.palette.rgb(style.trail_shade(i, n));
                    let want = shade(spec.trail_colour, fade(i, n));
                    assert_eq!(got, want, "trail {} dot {i} of {n}", spec.trail);
                }
            }
        }
        let styles = &renderer.styles;
        assert!(Arc::ptr_eq(
            &styles[0].trail_shades,
            &styles[3].trail_shades
        ));
        assert!(!Arc::ptr_eq(
            &styles[0].trail_shades,
            &styles[1].trail_shades
        ));
        assert_eq!(
            styles[3].trail_shades.len(),
            9 * 10 / 2,
            "sized by the longest trail"
        );
    }
}
