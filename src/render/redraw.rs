//! Frame after frame, drawn again only where something changed.
//!
//! In many scenes most of the canvas stays as it was from one frame to the next: a pile at
//! rest, a few balls moving among many still ones. A [`Canvas`] remembers what each ball drew
//! in the last frame: the box of whole pixels of each of its circles (its trail's dots, then
//! itself) and how long its trail was (which picks the dots' shades); for a ball at rest on
//! its own trail, a few numbers answer as well (its centre, radius and trail length). For the
//! next frame:
//!
//! - if no ball would draw anything different, nothing is drawn: the frame is the last one,
//!   pixel for pixel, and says so ([`Damage::Unchanged`]), so the GIF compares nothing;
//! - otherwise the tiles (`super::dirty::Tiles`) under each changed ball's old and new
//!   rectangles (each holding all its circles) are marked. Each run of marked tiles is
//!   cleared to the background and floors, and every circle touching it is drawn again,
//!   clipped to it, in the order a whole frame is drawn (every trail, then every ball). The
//!   GIF compares only those runs;
//! - when more than a quarter of the canvas is marked, the whole frame is drawn, as
//!   [`Renderer::draw`] does, and the next few frames too without looking (a scene moving
//!   all over, such as billiards, would pay for the looking and gain nothing).
//!
//! Why the pixels are those of a whole redraw: the pixels of a circle follow from its box of
//! whole pixels and its colour alone (`PixelBox`), so a ball whose record is the same draws
//! what it drew, however it moved below a pixel. A pixel outside every marked tile lies under
//! no circle that changed, so the same circles cover it, in the same order, as in the last
//! frame; inside, it is drawn again from scratch.

use super::dirty::{paste, Rect, Tiles};
use super::ellipse::{fill_box, PixelBox};
use super::palette::{drawn_dots, IndexedFrame};
use super::raster::Renderer;
use crate::physics::ball::Ball;
use crate::physics::vec2::Vec2;
use crate::work::{tally_many, Work};

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
    /// One ball's boxes, as it draws them now.
    boxes: Vec<PixelBox>,
    redrawn: Redrawn,
    /// Frames still to draw whole without looking at what changed, and how many the last
    /// busy spell drew ([`Canvas::busy`]).
    busy: u32,
    backoff: u32,
}

/// The most frames drawn whole in a row without looking at what changed: how late, at most,
/// a scene that calms down is drawn only where it changes.
pub const MOST_BUSY_FRAMES: u32 = 8;

/// What the last frame drew again: nothing, the whole frame, or the runs of marked tiles.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Redrawn {
    Nothing,
    Whole,
    Runs,
}

impl Canvas {
    /// A canvas for `renderer`'s scene, to draw frame after frame on.
    pub fn new(renderer: &Renderer) -> Canvas {
        let mut base = renderer.new_frame();
        renderer.draw_background(&mut base);
        Canvas {
            frame: base.clone(),
            tiles: Tiles::new(base.width(), base.height()),
            base,
            drawn: Drawn::new(renderer.most_dots()),
            runs: Vec::new(),
            boxes: Vec::new(),
            redrawn: Redrawn::Whole,
            busy: 0,
            backoff: 0,
        }
    }

    /// What a canvas remembers of a ball whose trail keeps `trail` points, bytes: the box of
    /// each circle it draws (its dots and itself), its trail's length, where its boxes start,
    /// and whether it was still.
    pub(crate) fn bytes_per_ball(trail: usize) -> u64 {
        let circles = drawn_dots(trail).len() + 1;
        let boxes = circles * size_of::<PixelBox>();
        (boxes + 2 * size_of::<usize>() + size_of::<Option<Still>>()) as u64
    }

    /// The frame as last drawn.
    pub fn frame(&self) -> &IndexedFrame {
        &self.frame
    }

    /// What the last [`Canvas::redraw`] changed.
    pub fn damage(&self) -> Damage<'_> {
        match self.redrawn {
            Redrawn::Nothing => Damage::Unchanged,
            Redrawn::Whole => Damage::Whole,
            Redrawn::Runs => Damage::Areas(&self.runs),
        }
    }

    /// Draws `balls` as `renderer` does, pixel for pixel, drawing again only what changed
    /// since the last frame (all of it the first time).
    pub fn redraw(&mut self, renderer: &Renderer, balls: &[Ball]) {
        self.redrawn = match self.busy.checked_sub(1) {
            Some(left) => {
                self.busy = left;
                Redrawn::Whole
            }
            None => self.note_changes(renderer, balls),
        };
        match self.redrawn {
            Redrawn::Nothing => {}
            Redrawn::Whole => renderer.draw(balls, &mut self.frame),
            Redrawn::Runs => self.redraw_runs(renderer, balls),
        }
        self.tiles.clear();
    }

    /// Records what each of `balls` draws now, and marks the tiles under the old and new
    /// rectangles of every ball that changed, unless so much is marked that the whole frame
    /// is to be drawn (then [`Canvas::busy`]).
    fn note_changes(&mut self, renderer: &Renderer, balls: &[Ball]) -> Redrawn {
        let fresh = !self.drawn.valid || balls.len() != self.drawn.trails.len();
        self.drawn.valid = true;
        let mut changed = fresh;
        for (i, ball) in balls.iter().enumerate().take(self.drawn.trails.len()) {
            let still = Still::of(ball);
            if !fresh && still.is_some() && self.drawn.stills[i] == still {
                continue; // a ball at rest on its own trail, as it was: the quick answer
            }
            self.drawn.stills[i] = still;
            self.measure(renderer, i, ball);
            let trail = ball.trail.len();
            if !fresh && self.drawn.matches(i, trail, &self.boxes) {
                continue;
            }
            changed = true;
            if !fresh {
                self.mark(i);
            }
            if !self.drawn.record(i, trail, &self.boxes) {
                // A trail longer than the scene said: the ball cannot be remembered.
                return self.busy();
            }
            if !fresh {
                self.mark(i);
                if self.tiles.much_marked() {
                    return self.busy();
                }
            }
        }
        if !changed {
            self.backoff = 0;
            return Redrawn::Nothing;
        }
        if fresh {
            return Redrawn::Whole;
        }
        self.backoff = 0;
        Redrawn::Runs
    }

    /// Puts the boxes of every circle ball `i`, `ball`, draws now in `self.boxes`.
    fn measure(&mut self, renderer: &Renderer, i: usize, ball: &Ball) {
        let frame = &self.frame;
        let circles = (renderer.trail_dots(i, ball)).chain([renderer.ball_circle(i, ball)]);
        let boxes = &mut self.boxes;
        boxes.clear();
        circles.for_each(|c| {
            let pixels = PixelBox::of(c.x, c.y, c.radius, frame);
            boxes.push(pixels.unwrap_or(PixelBox::NOTHING));
        });
    }

    /// Much of the canvas changed: the whole frame is drawn, and so are the next few without
    /// looking at what changed, twice as many each time in a row (up to [`MOST_BUSY_FRAMES`]),
    /// so a scene that keeps moving all over pays for the looking only now and then. The
    /// records go out of date, and the first frame after is recorded afresh.
    fn busy(&mut self) -> Redrawn {
        self.drawn.valid = false;
        self.backoff = (2 * self.backoff).clamp(1, MOST_BUSY_FRAMES);
        self.busy = self.backoff;
        Redrawn::Whole
    }

    /// Marks the tiles under the rectangle holding every circle ball `i` drew as recorded.
    fn mark(&mut self, i: usize) {
        let on_canvas = self.drawn.boxes(i).iter().filter_map(|b| b.on(&self.frame));
        if let Some(rect) = on_canvas.reduce(Rect::union) {
            self.tiles.mark(rect);
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
        let (frame, tiles) = (&mut self.frame, &self.tiles);
        renderer.each_circle(balls, |circle| {
            let pixels = PixelBox::of(circle.x, circle.y, circle.radius, frame);
            let Some((pixels, rect)) = pixels.and_then(|p| Some((p, p.on(frame)?))) else {
                return;
            };
            for clip in tiles.marked_runs(rect) {
                fill_box(frame, pixels, circle.index, clip);
            }
        });
    }
}

/// A ball whose every trail point lies on its centre, to the bit: its centre and radius (as
/// bits) and how many points its trail holds. Two frames of one ball with the same `Still`
/// draw the same circles, so a ball at rest (asleep, or never moving) is answered by
/// comparing a few numbers, without measuring its circles.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Still {
    centre: [u64; 2],
    radius: u64,
    trail: usize,
}

impl Still {
    /// `None` when some trail point lies off the ball's centre.
    fn of(ball: &Ball) -> Option<Still> {
        let centre = [ball.x.to_bits(), ball.y.to_bits()];
        let on_centre = |point: &Vec2| [point.x.to_bits(), point.y.to_bits()] == centre;
        ball.trail.iter().all(on_centre).then_some(Still {
            centre,
            radius: ball.radius.to_bits(),
            trail: ball.trail.len(),
        })
    }
}

/// What each ball drew in the last frame: how many points its trail held (which, with a
/// dot's place, picks its shade), and its circles' boxes of whole pixels
/// ([`PixelBox::NOTHING`] for a circle that filled nothing).
#[derive(Clone, Debug)]
struct Drawn {
    trails: Vec<usize>,
    /// Each ball as it was when its boxes were last measured, if it was still then: the
    /// circles it drew were those a still ball there draws, and have not changed since.
    stills: Vec<Option<Still>>,
    /// Each ball's boxes, its dots then itself, in a slot as long as the most it draws:
    /// ball `i`'s from `starts[i]` up to `starts[i + 1]`.
    boxes: Vec<PixelBox>,
    starts: Vec<usize>,
    /// Whether the records are those of the frame: not before the first frame is drawn.
    valid: bool,
}

impl Drawn {
    /// Room for balls drawing at most `most_dots` trail dots each; nothing recorded yet.
    fn new(most_dots: impl Iterator<Item = usize>) -> Drawn {
        let mut starts = vec![0];
        for dots in most_dots {
            starts.push(starts[starts.len() - 1] + dots + 1);
        }
        let balls = starts.len() - 1;
        Drawn {
            trails: vec![0; balls],
            stills: vec![None; balls],
            boxes: vec![PixelBox::NOTHING; starts[balls]],
            starts,
            valid: false,
        }
    }

    /// Ball `i`'s recorded boxes.
    fn boxes(&self, i: usize) -> &[PixelBox] {
        let circles = drawn_dots(self.trails[i]).len() + 1;
        &self.boxes[self.starts[i]..self.starts[i] + circles]
    }

    /// Whether ball `i`, its trail holding `trail` points, draws `boxes` exactly as recorded.
    fn matches(&self, i: usize, trail: usize, boxes: &[PixelBox]) -> bool {
        self.trails[i] == trail && self.boxes(i) == boxes
    }

    /// Records that ball `i`, its trail holding `trail` points, draws `boxes`; false if they
    /// do not fit its slot.
    fn record(&mut self, i: usize, trail: usize, boxes: &[PixelBox]) -> bool {
        let start = self.starts[i];
        if start + boxes.len() > self.starts[i + 1] {
            return false;
        }
        self.trails[i] = trail;
        self.boxes[start..start + boxes.len()].copy_from_slice(boxes);
        true
    }
}
