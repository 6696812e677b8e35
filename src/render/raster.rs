//! The software rasteriser: one frame of balls and trails, drawn straight into palette
//! indices on a one-channel image whose values are indices. Circles are Pillow's, pixel for
//! pixel ([`super::ellipse`]); floors are one-pixel lines ([`super::line`]), clipped to the canvas.
//!
//! Drawing only: it reads where the balls are and never moves them.

use std::collections::HashMap;
use std::sync::Arc;

use image::{GrayImage, Luma};

use super::ellipse::fill_circle;
use super::line::draw_line;
use super::palette::{
    drawn_dots, fade_levels, quantised_fade, shade, Colours, IndexedFrame, Palette, TooManyColours,
    TrailLook,
};
use crate::physics::ball::Ball;
use crate::physics::floor::Floor;
use crate::physics::vec2::Vec2;
use crate::scene::spec::{Rgb, Scene};
use crate::work::{tally_many, Work};

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
    look: TrailLook,
}

/// The palette indices one ball is drawn with.
#[derive(Clone, Debug)]
struct BallStyle {
    ball: u8,
    /// Its trail colour's shades, laid out as [`ShadeTable::shades`].
    trail_shades: Arc<[u8]>,
    /// The most trail dots it draws: one fewer than its trail keeps.
    most_dots: usize,
}

impl BallStyle {
    fn trail_shade(&self, i: usize, n: usize) -> u8 {
        self.trail_shades[slot(i, n)]
    }
}

/// Where dot `i` of a trail of `n` points sits in a shade table: a trail of `n` draws `n - 1`
/// dots (`drawn_dots`; the newest lies under the ball), so the trails of 1 to `n - 1` points
/// take the first `(n - 1)(n - 2)/2` places.
fn slot(i: usize, n: usize) -> usize {
    (n - 1) * n.saturating_sub(2) / 2 + i
}

/// One trail colour's shades, for every trail length up to the longest trail in that
/// colour. A shade depends only on the colour, so balls of one trail colour share one table:
/// memory follows the trail colours, not the number of balls.
struct ShadeTable {
    colour: Rgb,
    longest: usize,
    /// Palette index of dot `i` of a trail of `n` at [`slot`]`(i, n)`.
    shades: Vec<u8>,
}

impl Renderer {
    /// Builds the palette for a (validated) scene.
    pub fn new(scene: &Scene) -> Result<Renderer, TooManyColours> {
        let floor_colour = (!scene.floors.is_empty()).then_some(scene.floor_colour);
        let solid: Vec<_> = std::iter::once(scene.background)
            .chain(floor_colour)
            .chain(scene.balls.iter().map(|b| b.colour))
            .collect();
        let (mut tables, table_of_ball) = shade_tables(scene);
        let trails: Vec<(Rgb, usize)> = tables.iter().map(|t| (t.colour, t.longest)).collect();
        let look = TrailLook {
            fade: scene.trail_fade,
            shrink: scene.trail_shrink,
        };
        let levels = fade_levels(&solid, &trails, look)?;

        // Solid colours first, then every shade.
        let mut palette = GrowingPalette {
            palette: Palette::new(),
            solid: solid.len(),
        };
        let background = palette.insert(scene.background)?;
        let floor = match floor_colour {
            Some(colour) => palette.insert(colour)?,
            None => background,
        };
        let balls = scene
            .balls
            .iter()
            .map(|spec| palette.insert(spec.colour))
            .collect::<Result<Vec<u8>, _>>()?;
        insert_shades(&mut tables, levels, look, &mut palette)?;
        let mut palette = palette.palette;

        // Renumbered so that the colours drawn together sit together (see `stages`).
        let kinds = kinds(scene, &table_of_ball);
        let always: Vec<u8> = [background, floor]
            .into_iter()
            .chain(balls.iter().copied())
            .collect();
        let new_index = palette.reorder(&stages(&always, &tables, &kinds));
        let renumber = |index: u8| new_index[usize::from(index)];
        Ok(Renderer {
            width: scene.width,
            height: scene.height,
            palette,
            background: renumber(background),
            floors: scene.floors.clone(),
            floor: renumber(floor),
            styles: ball_styles(scene, &balls, &tables, &table_of_ball, renumber),
            look,
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

    /// The most trail dots each ball draws (one fewer than its trail keeps), ball by ball.
    pub(crate) fn most_dots(&self) -> impl Iterator<Item = usize> + '_ {
        self.styles.iter().map(|style| style.most_dots)
    }

    /// Draws `balls` into `frame`: background and floors, then every trail (oldest dot first, fading
    /// and shrinking into the past; the newest lies under the ball), then every ball on top,
    /// so no trail hides a ball.
    pub fn draw(&self, balls: &[Ball], frame: &mut IndexedFrame) {
        self.draw_background(frame);
        self.each_circle(balls, |c| fill_circle(frame, c.x, c.y, c.radius, c.index));
    }

    /// Fills `frame` with the background and draws the floors on it: what lies under the balls.
    pub(crate) fn draw_background(&self, frame: &mut IndexedFrame) {
        frame.fill(self.background);
        tally_many(Work::PixelsDrawn, frame.as_raw().len() as u64);
        let canvas = Vec2::new(f64::from(self.width), f64::from(self.height));
        for floor in &self.floors {
            if let Some((from, to)) = clip_segment(floor.from, floor.to, canvas) {
                let point = |p: Vec2| (p.x as f32, p.y as f32);
                draw_line(frame, point(from), point(to), self.floor);
            }
        }
    }

    /// Calls `draw` with every circle [`Renderer::draw`] fills for `balls`, in the order it
    /// fills them: every trail's dots, then every ball.
    pub(crate) fn each_circle(&self, balls: &[Ball], mut draw: impl FnMut(Circle)) {
        // Balls beyond the scene's have no colours, and are not drawn.
        let balls = &balls[..balls.len().min(self.styles.len())];
        for (i, ball) in balls.iter().enumerate() {
            for dot in self.trail_dots(i, ball) {
                draw(dot);
            }
        }
        for (i, ball) in balls.iter().enumerate() {
            draw(self.ball_circle(i, ball));
        }
    }

    /// The dots drawn of the trail of `ball`, ball number `i`: all but the newest point,
    /// oldest first, fading and shrinking into the past.
    pub(crate) fn trail_dots<'a>(
        &'a self,
        i: usize,
        ball: &'a Ball,
    ) -> impl Iterator<Item = Circle> + 'a {
        let (style, n) = (&self.styles[i], ball.trail.len());
        let dots = ball.trail.iter().take(drawn_dots(n).end).enumerate();
        dots.map(move |(i, &point)| Circle {
            x: point.x,
            y: point.y,
            radius: ball.radius * self.look.size_share(i, n),
            index: style.trail_shade(i, n),
        })
    }

    /// The circle of `ball` itself, ball number `i`.
    pub(crate) fn ball_circle(&self, i: usize, ball: &Ball) -> Circle {
        Circle {
            x: ball.x,
            y: ball.y,
            radius: ball.radius,
            index: self.styles[i].ball,
        }
    }
}

/// One filled circle of a frame: centre and radius, px, and its palette index.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Circle {
    pub x: f64,
    pub y: f64,
    pub radius: f64,
    pub index: u8,
}

/// The palette while the renderer fills it: a colour that does not fit is the scene's
/// error, which counts the scene's `solid` colours.
struct GrowingPalette {
    palette: Palette,
    solid: usize,
}

impl GrowingPalette {
    /// The index of `colour`, added if new.
    fn insert(&mut self, colour: Rgb) -> Result<u8, TooManyColours> {
        let too_many = TooManyColours { needed: self.solid };
        self.palette.insert(colour).ok_or(too_many)
    }
}

/// Each ball's style, given its colour's index (`balls`) and its shade table's number
/// (`table_of_ball`), every index renumbered by `renumber`. Balls of one trail colour share
/// their table's renumbered shades.
fn ball_styles(
    scene: &Scene,
    balls: &[u8],
    tables: &[ShadeTable],
    table_of_ball: &[usize],
    renumber: impl Fn(u8) -> u8,
) -> Vec<BallStyle> {
    let tables: Vec<Arc<[u8]>> = tables
        .iter()
        .map(|table| table.shades.iter().map(|&index| renumber(index)).collect())
        .collect();
    balls
        .iter()
        .zip(table_of_ball)
        .zip(&scene.balls)
        .map(|((&ball, &table), spec)| BallStyle {
            ball: renumber(ball),
            trail_shades: Arc::clone(&tables[table]),
            most_dots: drawn_dots(spec.trail).len(),
        })
        .collect()
}

/// One shade table per trail colour, in the order the balls first use them, each sized for
/// the longest trail in its colour (its shades not yet filled in); and each ball's table.
fn shade_tables(scene: &Scene) -> (Vec<ShadeTable>, Vec<usize>) {
    let mut tables: Vec<ShadeTable> = Vec::new();
    let mut table_of: HashMap<Rgb, usize> = HashMap::new();
    let mut table_of_ball = Vec::with_capacity(scene.balls.len());
    for spec in &scene.balls {
        let table = *table_of.entry(spec.trail_colour).or_insert_with(|| {
            tables.push(ShadeTable {
                colour: spec.trail_colour,
                longest: 0,
                shades: Vec::new(),
            });
            tables.len() - 1
        });
        tables[table].longest = tables[table].longest.max(spec.trail);
        table_of_ball.push(table);
    }
    for table in &mut tables {
        table.shades = vec![0; slot(0, table.longest + 1)];
    }
    (tables, table_of_ball)
}

/// The distinct (shade table, trail length) pairs of the scene's balls, given each ball's
/// table: balls alike in both draw alike, so each kind is one stage entry.
fn kinds(scene: &Scene, table_of_ball: &[usize]) -> Vec<(usize, usize)> {
    let mut kinds: Vec<(usize, usize)> = table_of_ball
        .iter()
        .copied()
        .zip(scene.balls.iter().map(|spec| spec.trail))
        .collect();
    kinds.sort_unstable();
    kinds.dedup();
    kinds
}

/// Adds every table's shades to the palette, each dimmed to one of `levels` steps when the
/// exact shades do not fit ([`fade_levels`]), and notes their indices in the tables.
fn insert_shades(
    tables: &mut [ShadeTable],
    levels: Option<usize>,
    look: TrailLook,
    palette: &mut GrowingPalette,
) -> Result<(), TooManyColours> {
    // Shades of full-length trails first, brightest (newest, biggest dot) first: `reorder`
    // keeps this order within each stage, and a frame where dots overlap shows mostly the
    // newest ones.
    let longest = tables.iter().map(|t| t.longest).max().unwrap_or(0);
    for n in (1..=longest).rev() {
        for table in tables.iter_mut().filter(|t| n <= t.longest) {
            for i in drawn_dots(n).rev() {
                let share = look.colour_share(i, n);
                let f = levels.map_or(share, |l| quantised_fade(share, l));
                table.shades[slot(i, n)] = palette.insert(shade(table.colour, f))?;
            }
        }
    }
    Ok(())
}

/// The segment `from`-`to`, cut along its longer axis to one pixel beyond the canvas
/// (`canvas` = width, height), in floating point: the line is walked along the longer axis pixel by
/// pixel, so a floor from -1e30 to 1e30 then costs no more than one across the canvas.
/// `None` when it misses the canvas along that axis. Ends already inside stay, to the bit.
fn clip_segment(from: Vec2, to: Vec2, canvas: Vec2) -> Option<(Vec2, Vec2)> {
    let delta = to - from;
    let (major, minor) = if delta.y.abs() > delta.x.abs() {
        (1, 0)
    } else {
        (0, 1)
    };
    let (low, high) = (-1.0, canvas.axis(major) + 1.0);
    if from.axis(major).max(to.axis(major)) < low || from.axis(major).min(to.axis(major)) > high {
        return None;
    }
    // The line as `minor = intercept + slope * major`, |slope| <= 1. Floating point cannot
    // place a line finer than the last bit of its far ends, but in this form lines such as
    // y = 120 or y = x with ends at ±1e30 come out exact.
    let slope = delta.axis(minor) / delta.axis(major);
    let intercept = from.axis(minor) - slope * from.axis(major);
    let cut = |end: Vec2| {
        let along = end.axis(major).clamp(low, high);
        if along == end.axis(major) {
            return end;
        }
        Vec2::from_axes(major, along, intercept + slope * along)
    };
    Some((cut(from), cut(to)))
}

/// The colours drawn together, stage by stage: first the stage most frames show, with every
/// trail grown to full length, then each frame while trails grow (at frame `t`, a trail of
/// up to `L` points holds `min(t + 1, L)`). Every stage holds the `always` colours (background,
/// floor, balls). `kinds` are the distinct (shade table, trail length) pairs of the balls.
fn stages(always: &[u8], tables: &[ShadeTable], kinds: &[(usize, usize)]) -> Vec<Colours> {
    let mut solid = Colours::default();
    for &index in always {
        solid.insert(index);
    }
    let longest = kinds.iter().map(|&(_, trail)| trail).max().unwrap_or(0);
    // growing[t]: what frame t draws while some trail still grows; grown: every frame after.
    let mut growing = vec![solid; longest];
    let mut grown = solid;
    for &(table, trail) in kinds {
        let table = &tables[table];
        for n in 1..=trail {
            let mut dots = Colours::default();
            for i in drawn_dots(n) {
                dots.insert(table.shades[slot(i, n)]);
            }
            growing[n - 1] = growing[n - 1].union(&dots);
            if n == trail {
                grown = grown.union(&dots);
                for stage in &mut growing[n..] {
                    *stage = stage.union(&dots);
                }
            }
        }
    }
    std::iter::once(grown).chain(growing).collect()
}

/// A frame's colours: each index looked up in the palette.
pub fn to_rgb(frame: &IndexedFrame, palette: &Palette) -> image::RgbImage {
    image::RgbImage::from_fn(frame.width(), frame.height(), |x, y| {
        image::Rgb(palette.rgb(frame.get_pixel(x, y)[0]))
    })
}

#[cfg(test)]
mod tests {
    use super::super::palette::fade;
    use super::*;
    use crate::scene::spec::BallSpec;

    const CANVAS: Vec2 = Vec2::new(320.0, 240.0);

    #[test]
    fn a_segment_inside_the_canvas_keeps_its_ends_to_the_bit() {
        // Through its line's equation the far end would come out 7e-15 off (50.900000000000006).
        let (from, to) = (Vec2::new(10.3, 20.7), Vec2::new(100.1, 50.9));
        assert_eq!(clip_segment(from, to, CANVAS), Some((from, to)));
    }

    #[test]
    fn a_segment_reaching_far_beyond_is_cut_one_pixel_beyond_the_canvas_along_its_longer_axis() {
        let level = clip_segment(Vec2::new(-1e30, 120.0), Vec2::new(1e30, 120.0), CANVAS);
        assert_eq!(
            level,
            Some((Vec2::new(-1.0, 120.0), Vec2::new(321.0, 120.0)))
        );
        let upright = clip_segment(Vec2::new(100.0, -1e30), Vec2::new(100.0, 1e30), CANVAS);
        assert_eq!(
            upright,
            Some((Vec2::new(100.0, -1.0), Vec2::new(100.0, 241.0)))
        );
    }

    #[test]
    fn a_segment_wholly_beside_the_canvas_is_dismissed() {
        for (from, to) in [
            (Vec2::new(-1e30, 50.0), Vec2::new(-5.0, 60.0)),
            (Vec2::new(330.0, 50.0), Vec2::new(1e30, 60.0)),
            (Vec2::new(50.0, -1e30), Vec2::new(60.0, -5.0)),
            (Vec2::new(50.0, 250.0), Vec2::new(60.0, 1e30)),
        ] {
            assert_eq!(clip_segment(from, to, CANVAS), None, "{from:?} to {to:?}");
        }
    }

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
                for i in drawn_dots(n) {
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
            9 * 8 / 2,
            "sized by the longest trail, 9 points: 1 + 2 + ... + 8 drawn dots"
        );
    }
}
