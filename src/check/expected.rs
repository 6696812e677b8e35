//! What a learner's work should be: the scene simulated and drawn frame by frame, in
//! memory, or the same scene with one of the lesson's mistakes in it.

use crate::physics::ball::Ball;
use crate::physics::simulation::Simulation;
use crate::physics::walls::Walls;
use crate::render::dirty::Rect;
use crate::render::ellipse::fill_circle;
use crate::render::palette::{IndexedFrame, Palette};
use crate::render::raster::{Circle, Renderer};
use crate::render::{Canvas, Damage};
use crate::scene::Scene;

use super::pitfalls::Pitfall;

/// The balls of a scene moving frame by frame, as the program moves them or with a mistake.
pub(crate) enum ExpectedMotion {
    Scene(Box<Simulation>),
    Mistaken {
        balls: Vec<Ball>,
        pitfall: Pitfall,
        gravity: f64,
        walls: Walls,
    },
}

impl ExpectedMotion {
    /// The scene's motion with `pitfall` in it (`None`: the program's); `None` if the scene
    /// does not move by the lesson's step, which the pitfalls are mistakes in.
    pub(crate) fn new(scene: &Scene, pitfall: Option<Pitfall>) -> Option<ExpectedMotion> {
        let simulation = scene.simulation();
        let Some(pitfall) = pitfall else {
            return Some(ExpectedMotion::Scene(Box::new(simulation)));
        };
        let (gravity, walls) = simulation.lesson_step()?;
        Some(ExpectedMotion::Mistaken {
            balls: simulation.balls().to_vec(),
            pitfall,
            gravity,
            walls,
        })
    }

    /// One frame on.
    pub(crate) fn step(&mut self) {
        match self {
            ExpectedMotion::Scene(simulation) => simulation.step(),
            ExpectedMotion::Mistaken {
                balls,
                pitfall,
                gravity,
                walls,
            } => balls
                .iter_mut()
                .for_each(|ball| pitfall.step(ball, *gravity, walls)),
        }
    }

    pub(crate) fn balls(&self) -> &[Ball] {
        match self {
            ExpectedMotion::Scene(simulation) => simulation.balls(),
            ExpectedMotion::Mistaken { balls, .. } => balls,
        }
    }
}

/// The expected frames, drawn one at a time.
pub(crate) struct Frames<'a> {
    renderer: &'a Renderer,
    motion: ExpectedMotion,
    drawing: Drawing,
    /// The renderer's colours, and for a mistake each trail's full colour.
    palette: Palette,
}

/// How the frames are drawn.
enum Drawing {
    /// As the main command draws them: only what changed is drawn again.
    Redrawn(Box<Canvas>),
    /// Whole, with every trail's newest dot too: with a mistake it need not lie under the
    /// ball (the trail recorded before the move, or drawn over the ball).
    Whole {
        frame: IndexedFrame,
        /// Each ball's full trail colour, the newest dot's.
        newest: Vec<u8>,
        trail_on_top: bool,
    },
}

impl<'a> Frames<'a> {
    /// The frames of `scene` with `pitfall` in it, as [`ExpectedMotion::new`] allows (and if a
    /// mistake's extra colours fit the palette).
    pub(crate) fn new(
        scene: &Scene,
        renderer: &'a Renderer,
        pitfall: Option<Pitfall>,
    ) -> Option<Self> {
        let mut palette = renderer.palette().clone();
        let drawing = match pitfall {
            None => Drawing::Redrawn(Box::new(Canvas::new(renderer))),
            Some(pitfall) => Drawing::Whole {
                frame: renderer.new_frame(),
                newest: scene
                    .balls
                    .iter()
                    .map(|ball| palette.insert(ball.trail_colour))
                    .collect::<Option<_>>()?,
                trail_on_top: pitfall == Pitfall::TrailOverBall,
            },
        };
        Some(Frames {
            renderer,
            motion: ExpectedMotion::new(scene, pitfall)?,
            drawing,
            palette,
        })
    }

    /// The next frame, the colours of its indices, and where it may differ from the frame
    /// before (`None`: nowhere).
    pub(crate) fn next_frame(&mut self) -> (&IndexedFrame, &Palette, Option<Rect>) {
        self.motion.step();
        let (renderer, balls) = (self.renderer, self.motion.balls());
        let (frame, changed) = match &mut self.drawing {
            Drawing::Redrawn(canvas) => {
                canvas.redraw(renderer, balls);
                let changed = match canvas.damage() {
                    Damage::Unchanged => None,
                    Damage::Whole => Some(Rect::whole(canvas.frame())),
                    Damage::Areas(areas) => areas.iter().copied().reduce(Rect::union),
                };
                (canvas.frame(), changed)
            }
            Drawing::Whole {
                frame,
                newest,
                trail_on_top,
            } => {
                renderer.draw_background(frame);
                let balls = balls.iter().enumerate();
                let circles = balls.clone().map(|(i, ball)| renderer.ball_circle(i, ball));
                let dots = balls.flat_map(|(i, ball)| {
                    let newest = ball.trail.iter().last().map(|&point| Circle {
                        x: point.x,
                        y: point.y,
                        radius: ball.radius,
                        index: newest[i],
                    });
                    renderer.trail_dots(i, ball).chain(newest)
                });
                let order: Vec<Circle> = match trail_on_top {
                    true => circles.chain(dots).collect(),
                    false => dots.chain(circles).collect(),
                };
                for c in order {
                    fill_circle(frame, c.x, c.y, c.radius, c.index);
                }
                let whole = Rect::whole(frame);
                (&*frame, Some(whole))
            }
        };
        (frame, &self.palette, changed)
    }
}
