//! Frame after frame, drawn again only where something changed.
//!
//! In many scenes most of the canvas stays as it was from one frame to the next: a pile at
//! rest, a few balls moving among many still ones. A [`Canvas`] remembers what each ball drew
//! in the last frame: its centre, its radius and its trail's drawn points, to the bit. With
//! the ball's fixed colours these decide every circle it drew. For the next frame:
//!
//! - if no ball would draw anything different, nothing is drawn: the frame is the last one,
//!   pixel for pixel, and says so ([`Damage::Unchanged`]), so the GIF compares nothing;
//! - otherwise the tiles ([`super::dirty::Tiles`]) under each changed ball's old and new
//!   circles are marked. Each run of marked tiles is cleared to the background and floors,
//!   and every circle touching it is drawn again, clipped to it, in the order a whole frame
//!   is drawn (every trail, then every ball). The GIF compares only those runs;
//! - when more than half the canvas is marked, the whole frame is drawn, as [`Renderer::draw`]
//!   does.
//!
//! Why the pixels are those of a whole redraw: a circle's pixels follow from its centre,
//! radius and colour alone, so a ball whose record is equal to the bit draws what it drew.
//! A pixel outside every marked tile lies under no circle that changed, so the same circles
//! cover it, in the same order, as in the last frame; inside, it is drawn again from scratch.

use super::dirty::{paste, Rect, Tiles};
use super::ellipse::{circle_box, fill_circle, fill_circle_within};
use super::palette::{drawn_dots, IndexedFrame};
use super::raster::Renderer;
use crate::physics::ball::Ball;
use crate::physics::work::{tally_many, Work};

/// What changed in a frame since the frame before it on the same canvas.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Damage<'a> {
    /// Nothing: every pixel is as it was.
    Unchanged,
    /// Anything may have changed.
    Whole,
    /// Only pixels inside these rectangles may have changed.
    Areas(&'a [Rect]),
}

/// A frame drawn again and again, and what each ball drew in it.
#[derive(Clone, Debug)]
pub struct Canvas {
    frame: IndexedFrame,
    /// The background with the floors on it: what lies under the balls.
    base: IndexedFrame,
    drawn: Drawn,
    tiles: Tiles,
    /// The runs of marked tiles, drawn again in the last frame.
    runs: Vec<Rect>,
    change: Change,
}

/// How the last frame was drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Change {
    Unchanged,
    Whole,
    Runs,
}

impl Canvas {
    /// A canvas over `base` (the background and floors) for balls that draw at most
    /// `most_dots` trail dots each.
    pub(super) fn new(base: IndexedFrame, most_dots: impl Iterator<Item = usize>) -> Canvas {
        Canvas {
            frame: base.clone(),
            tiles: Tiles::new(base.width(), base.height()),
            base,
            drawn: Drawn::new(most_dots),
            runs: Vec::new(),
            change: Change::Whole,
        }
    }

    /// The frame as last drawn.
    pub fn frame(&self) -> &IndexedFrame {
        &self.frame
    }

    /// What the last [`Canvas::redraw`] changed.
    pub fn damage(&self) -> Damage<'_> {
        match self.change {
            Change::Unchanged => Damage::Unchanged,
            Change::Whole => Damage::Whole,
            Change::Runs => Damage::Areas(&self.runs),
        }
    }

    /// Draws `balls` as `renderer` does, pixel for pixel, drawing again only what changed
    /// since the last frame (all of it the first time).
    pub fn redraw(&mut self, renderer: &Renderer, balls: &[Ball]) {
        self.change = self.note_changes(renderer, balls);
        match self.change {
            Change::Unchanged => {}
            Change::Whole => {
                self.frame.copy_from_slice(&self.base);
                tally_many(Work::PixelsDrawn, self.frame.len() as u64);
                for circle in renderer.circles(balls) {
                    let (x, y, radius) = (circle.x, circle.y, circle.radius);
                    fill_circle(&mut self.frame, x, y, radius, circle.index);
                }
            }
            Change::Runs => self.redraw_runs(renderer, balls),
        }
        self.tiles.clear();
    }

    /// Records what each of `balls` draws now, and marks the tiles under the old and new
    /// circles of every ball that changed, until so much is marked that the whole frame
    /// is to be drawn.
    fn note_changes(&mut self, renderer: &Renderer, balls: &[Ball]) -> Change {
        let fresh = !self.drawn.valid || balls.len() != self.drawn.balls.len();
        let (mut whole, mut changed) = (fresh, fresh);
        self.drawn.valid = true;
        for (i, ball) in balls.iter().enumerate() {
            if !fresh && self.drawn.matches(i, ball) {
                continue;
            }
            changed = true;
            if !whole {
                self.mark(renderer, i);
            }
            if !self.drawn.record(i, ball) {
                // A trail longer than the scene said: this ball cannot be remembered, so
                // every frame is drawn whole.
                self.drawn.valid = false;
                whole = true;
            }
            if !whole {
                self.mark(renderer, i);
                whole = self.tiles.mostly_marked();
            }
        }
        match (changed, whole) {
            (false, _) => Change::Unchanged,
            (true, true) => Change::Whole,
            (true, false) => Change::Runs,
        }
    }

    /// Marks the tiles under every circle ball `i` drew as recorded.
    fn mark(&mut self, renderer: &Renderer, i: usize) {
        let ball = self.drawn.balls[i];
        let points = self.drawn.points(i).iter().copied();
        let dots = renderer.trail_dots(i, points, ball.trail, ball.radius);
        let boxes =
            dots.map(|dot| (dot.x, dot.y, dot.radius))
                .chain([(ball.x, ball.y, ball.radius)]);
        for (x, y, radius) in boxes {
            if let Some(rect) = circle_box(x, y, radius, &self.frame) {
                self.tiles.mark(rect);
            }
        }
    }

    /// Clears every run of marked tiles to the background and floors, and draws again every
    /// circle that touches one, in order, clipped to the runs.
    fn redraw_runs(&mut self, renderer: &Renderer, balls: &[Ball]) {
        self.tiles.runs(&mut self.runs);
        for &run in &self.runs {
            paste(&self.base, run, &mut self.frame);
            tally_many(Work::PixelsDrawn, run.area());
        }
        for circle in renderer.circles(balls) {
            let (x, y, radius) = (circle.x, circle.y, circle.radius);
            let Some(rect) = circle_box(x, y, radius, &self.frame) else {
                continue;
            };
            for clip in self.tiles.marked_runs(rect) {
                fill_circle_within(&mut self.frame, x, y, radius, circle.index, clip);
            }
        }
    }
}

/// What each ball drew in the last frame, to the bit: its centre and radius, how many points
/// its trail held, and the points of the dots drawn (all but the newest).
#[derive(Clone, Debug)]
struct Drawn {
    balls: Vec<DrawnBall>,
    /// Each ball's dots, in a slot as long as the most it draws: ball `i`'s from `starts[i]`
    /// up to `starts[i + 1]`.
    points: Vec<(f64, f64)>,
    starts: Vec<usize>,
    /// Whether the records are those of the frame: not before the first frame is drawn.
    valid: bool,
}

/// A ball as it was drawn.
#[derive(Clone, Copy, Debug, Default)]
struct DrawnBall {
    x: f64,
    y: f64,
    radius: f64,
    /// How many points its trail held.
    trail: usize,
}

impl Drawn {
    /// Room for balls drawing at most `most_dots` trail dots each; nothing recorded yet.
    fn new(most_dots: impl Iterator<Item = usize>) -> Drawn {
        let mut starts = vec![0];
        for dots in most_dots {
            starts.push(starts[starts.len() - 1] + dots);
        }
        let balls = starts.len() - 1;
        Drawn {
            balls: vec![DrawnBall::default(); balls],
            points: vec![(0.0, 0.0); starts[balls]],
            starts,
            valid: false,
        }
    }

    /// Ball `i`'s recorded dots.
    fn points(&self, i: usize) -> &[(f64, f64)] {
        let dots = drawn_dots(self.balls[i].trail).len();
        &self.points[self.starts[i]..self.starts[i] + dots]
    }

    /// Whether `ball`, as ball `i`, draws exactly what ball `i` drew.
    fn matches(&self, i: usize, ball: &Ball) -> bool {
        let was = &self.balls[i];
        let same = |a: f64, b: f64| a.to_bits() == b.to_bits();
        same(was.x, ball.x)
            && same(was.y, ball.y)
            && same(was.radius, ball.radius)
            && was.trail == ball.trail.len()
            && (self.points(i).iter())
                .zip(ball.trail.iter())
                .all(|(a, b)| same(a.0, b.0) && same(a.1, b.1))
    }

    /// Records what `ball` draws as ball `i`; false if it does not fit its slot.
    fn record(&mut self, i: usize, ball: &Ball) -> bool {
        let n = ball.trail.len();
        let dots = drawn_dots(n).len();
        if i >= self.balls.len() || self.starts[i] + dots > self.starts[i + 1] {
            return false;
        }
        self.balls[i] = DrawnBall {
            x: ball.x,
            y: ball.y,
            radius: ball.radius,
            trail: n,
        };
        let slot = &mut self.points[self.starts[i]..self.starts[i] + dots];
        for (point, &drawn) in slot.iter_mut().zip(ball.trail.iter()) {
            *point = drawn;
        }
        true
    }
}
