//! The comparison's picture: the scene once, every method's balls and trails in its own
//! colour, the reference's balls as outlines over them, and under the canvas a legend strip
//! naming each method in its colour with its error so far. Nothing in it depends on the
//! clock, so the GIF is the same bytes on every run.

use crate::physics::{Ball, Vec2};
use crate::render::ellipse::fill_circle;
use crate::render::outline::outline_circle;
use crate::render::palette::{IndexedFrame, Palette, TooManyColours};
use crate::render::raster::Renderer;
use crate::render::text::{draw_text, text_width, TEXT_HEIGHT};
use crate::scene::{BallSpec, Rgb, Scene};

use super::measure::{Standing, Trust};
use super::methods::{Method, MAX_METHODS};
use super::table::short;

/// Each method's colour, in the order `--methods` lists them (the first is the lesson's ball
/// colour): far apart in hue, and bright on the lesson's black.
pub(crate) const COLOURS: [Rgb; MAX_METHODS] = [
    [255, 200, 60],
    [90, 200, 255],
    [255, 90, 90],
    [120, 230, 120],
    [200, 120, 255],
    [255, 150, 60],
    [230, 90, 200],
    [60, 200, 200],
];

/// Space around and between the legend's rows, px.
const GAP: u32 = 4;

/// What the legend says of one method in one frame: its name and how far it has strayed.
pub(crate) struct LegendRow {
    pub label: String,
    pub status: String,
}

impl LegendRow {
    /// The row of `method`, standing as `standing` so far.
    pub(crate) fn new(method: Method, standing: Standing) -> LegendRow {
        let status = match standing {
            Standing::Reference => "the reference".to_string(),
            Standing::Parted(frame) => format!("parted at frame {frame}"),
            Standing::AsFarAsKnown(frame) => {
                format!("agrees as far as the reference can tell (frame {frame})")
            }
            // The number is in the table; here it would widen every GIF by a third.
            Standing::BelowUncertainty(_) => "below the reference's uncertainty".to_string(),
            Standing::Error(px) => format!("error {} px", short(px)),
        };
        LegendRow {
            label: method.to_string(),
            status,
        }
    }

    /// The row as drawn.
    fn text(&self) -> String {
        format!("{}  {}", self.label, self.status)
    }
}

/// The longest texts a legend row of each of `methods` can show over `frames` frames against
/// a reference trusted as `trust` (`chaotic` when the balls collide), for the picture's width.
pub(crate) fn widest_rows(
    methods: &[Method],
    trust: Trust,
    chaotic: bool,
    frames: u32,
) -> Vec<String> {
    let mut statuses = vec![
        Standing::Error(8888.88),
        Standing::Error(8.8e-88),
        Standing::Parted(trust.horizon.min(frames)),
        Standing::BelowUncertainty(0.0),
        Standing::Reference,
    ];
    if !trust.tells(chaotic, frames) {
        statuses.push(Standing::AsFarAsKnown(trust.horizon));
    }
    let rows = methods
        .iter()
        .flat_map(|&m| statuses.iter().map(move |&s| LegendRow::new(m, s)));
    rows.map(|row| row.text()).collect()
}

/// The legend's last row: the reference, and up to which frame it is trusted if not to the
/// end.
pub(crate) fn reference_row(method: Method, trust: Trust, frames: u32) -> String {
    if trust.horizon < frames {
        format!(
            "reference {method} (outlines), trusted up to frame {}",
            trust.horizon
        )
    } else {
        format!("reference {method} (outlines)")
    }
}

/// Draws the comparison's frames.
pub(crate) struct Picture {
    renderer: Renderer,
    /// The scene's part of the frame, as the renderer draws it.
    canvas: IndexedFrame,
    /// The whole frame: the canvas, then the legend strip.
    frame: IndexedFrame,
    background: u8,
    /// Each method's ball colour, then the reference's outline colour.
    inks: Vec<u8>,
    /// All methods' balls, one method after another, as the renderer takes them.
    balls: Vec<Ball>,
    /// The legend's last row, naming the reference.
    reference: String,
}

/// The reference's outline: white, or black on a light background.
fn outline_colour(background: Rgb) -> Rgb {
    let light = background.iter().map(|&c| u32::from(c)).sum::<u32>() > 3 * 128;
    if light {
        [0, 0, 0]
    } else {
        [255, 255, 255]
    }
}

/// The scene as the renderer should see it: every method's copy of every ball in the
/// method's colour, the last method first so the first listed (the lesson's, by default) is
/// drawn on top; then a ball in each legend colour (the methods', the outline's) that is never
/// drawn, so the palette holds them even for a scene without balls, and leaves room for them
/// when trails are dimmed to fit.
fn drawn_scene(scene: &Scene, methods: usize) -> Scene {
    let colours = &COLOURS[..methods];
    let mut balls = Vec::with_capacity((scene.balls.len() + 1) * methods + 1);
    for colour in colours.iter().rev() {
        balls.extend(scene.balls.iter().map(|spec| BallSpec {
            colour: *colour,
            trail_colour: *colour,
            ..spec.clone()
        }));
    }
    let inks = colours
        .iter()
        .copied()
        .chain([outline_colour(scene.background)]);
    balls.extend(inks.map(|colour| BallSpec {
        x: 0.0,
        y: 0.0,
        vx: 0.0,
        vy: 0.0,
        radius: 1.0,
        colour,
        trail_colour: colour,
        trail: 0,
    }));
    Scene {
        balls,
        ..scene.clone()
    }
}

/// The legend's height for `methods` methods and the reference, px.
fn legend_height(methods: usize) -> u32 {
    1 + GAP + (methods as u32 + 1) * (TEXT_HEIGHT + GAP)
}

/// Where a row's text starts: after its swatch, a ball as tall as the text.
fn text_left() -> i32 {
    (2 * GAP + TEXT_HEIGHT + GAP) as i32
}

impl Picture {
    /// A picture of `scene` with `methods` methods and a last legend row `reference`, wide
    /// enough for the widest legend row among `widest` (the longest texts a row can show).
    pub(crate) fn new(
        scene: &Scene,
        methods: usize,
        reference: String,
        widest: &[String],
    ) -> Result<Picture, TooManyColours> {
        let renderer = Renderer::new(&drawn_scene(scene, methods))?;
        let palette = renderer.palette();
        let index = |colour: Rgb| {
            let at = palette.colours().iter().position(|&c| c == colour);
            at.expect("every colour of the drawn scene is in its palette") as u8
        };
        let mut inks: Vec<u8> = COLOURS[..methods].iter().map(|&c| index(c)).collect();
        inks.push(index(outline_colour(scene.background)));
        // One more column for the canvas's right edge when the legend is the wider.
        let legend = widest
            .iter()
            .map(|t| text_left() as u32 + text_width(t) + GAP + 1);
        let width = legend.fold(scene.width, u32::max);
        let background = index(scene.background);
        let frame = IndexedFrame::from_pixel(
            width,
            scene.height + legend_height(methods),
            image::Luma([background]),
        );
        Ok(Picture {
            canvas: renderer.new_frame(),
            renderer,
            frame,
            background,
            inks,
            balls: Vec::new(),
            reference,
        })
    }

    /// The colours the frames use.
    pub fn palette(&self) -> &Palette {
        self.renderer.palette()
    }

    /// The frame's size, px.
    pub(crate) fn size(&self) -> (u32, u32) {
        self.frame.dimensions()
    }

    /// The frame last drawn.
    pub(crate) fn frame(&self) -> &IndexedFrame {
        &self.frame
    }

    /// Draws one frame: each method's `balls` (in `--methods` order; the first on top), the reference's
    /// `centres` as outlines of the balls' radii, and the `legend`, one row per method.
    pub(crate) fn draw(&mut self, methods: &[&[Ball]], centres: &[Vec2], legend: &[LegendRow]) {
        self.balls.clear();
        for balls in methods.iter().rev() {
            self.balls.extend(balls.iter().cloned());
        }
        self.renderer.draw(&self.balls, &mut self.canvas);
        let outline = self.inks[methods.len()];
        for (ball, centre) in methods[0].iter().zip(centres) {
            outline_circle(&mut self.canvas, centre.x, centre.y, ball.radius, outline);
        }
        self.frame.fill(self.background);
        image::imageops::replace(&mut self.frame, &self.canvas, 0, 0);
        self.draw_edges(outline);
        self.draw_legend(legend);
    }

    /// The canvas's bottom edge, and its right edge where the legend is wider, so the box the
    /// balls move in stands apart from the legend.
    fn draw_edges(&mut self, ink: u8) {
        let (width, height) = self.canvas.dimensions();
        for x in 0..self.frame.width() {
            self.frame.put_pixel(x, height, image::Luma([ink]));
        }
        if self.frame.width() > width {
            for y in 0..height {
                self.frame.put_pixel(width, y, image::Luma([ink]));
            }
        }
    }

    /// The legend strip: a swatch and a line of text per method, then the reference's.
    fn draw_legend(&mut self, legend: &[LegendRow]) {
        let top = self.canvas.height() + 1 + GAP;
        let radius = f64::from(TEXT_HEIGHT) / 2.0;
        let swatch_x = f64::from(2 * GAP) + radius;
        for (row, ink) in self.inks.iter().enumerate() {
            let y = top + row as u32 * (TEXT_HEIGHT + GAP);
            let centre_y = f64::from(y) + radius;
            let text = match legend.get(row) {
                Some(entry) => {
                    fill_circle(&mut self.frame, swatch_x, centre_y, radius, *ink);
                    entry.text()
                }
                None => {
                    outline_circle(&mut self.frame, swatch_x, centre_y, radius, *ink);
                    self.reference.clone()
                }
            };
            draw_text(&mut self.frame, text_left(), y as i32, &text, *ink);
        }
    }
}
