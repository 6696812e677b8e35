//! The numbers a plot shows, taken frame by frame from the same states the `--trace` CSV
//! writes (the balls right after each frame's step), so the picture and the CSV agree.
//!
//! Energies are per unit mass, in px²/frame²: kinetic `½·|v|²`, potential `g·h` with `h` the
//! distance the ball could still fall (to the floor, for the lesson's gravity).

use crate::physics::ball::kinetic_energy;
use crate::physics::ball::Ball;
use crate::physics::contacts::Grid;
use crate::physics::maths;
use crate::physics::vec2::Vec2;
use crate::scene::Scene;

/// The panel a series is drawn in, top to bottom in this order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum PlotPanel {
    Height,
    Speed,
    Energy,
    TotalEnergy,
    Overlap,
}

impl PlotPanel {
    /// The panel's vertical axis, with units.
    pub(crate) fn axis(self) -> &'static str {
        match self {
            PlotPanel::Height => "height above the floor, px",
            PlotPanel::Speed => "speed, px/frame",
            PlotPanel::Energy => "energy per unit mass, px²/frame²",
            PlotPanel::TotalEnergy => "all balls' energy, px²/frame²",
            PlotPanel::Overlap => "deepest overlap, px",
        }
    }
}

/// One line of the plot: what it is, where it is drawn, and its value in every frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    pub name: &'static str,
    pub panel: PlotPanel,
    pub values: Vec<f64>,
}

/// The series of one run, growing by one value per series each frame.
#[derive(Clone, Debug)]
pub struct Recording {
    pub series: Vec<Series>,
    /// Frames in which the single ball's vertical velocity turned from down to up: the floor
    /// bounces (empty for many balls).
    pub bounces: Vec<u32>,
    /// The box the potential energy is measured in, px.
    width: f64,
    height: f64,
    gravity: Vec2,
    /// Each ball's mass as a share of the average ball's (mass ∝ radius², as in collisions).
    mean_mass: f64,
    /// Finds the overlapping pairs, when the scene has ball-ball collisions and many balls.
    overlaps: Option<Overlaps>,
    /// The single ball's vertical velocity in the previous frame.
    last_vy: Option<f64>,
    frames: u32,
}

/// The broad phase's grid, kept from frame to frame.
#[derive(Clone, Debug, Default)]
struct Overlaps {
    grid: Grid,
}

impl Overlaps {
    /// How deep the most overlapping pair overlaps, px (0 if none does). Pairs are looked at
    /// as the grid finds them, never stored: balls piled on one spot make N² of them.
    fn deepest(&mut self, balls: &[Ball]) -> f64 {
        self.grid.rebuild(balls);
        self.grid.deepest_overlap(balls)
    }
}

fn series(name: &'static str, panel: PlotPanel) -> Series {
    Series {
        name,
        panel,
        values: Vec::new(),
    }
}

impl Recording {
    /// An empty recording of `scene`: height, speed and energy for one ball; total energies
    /// (and the deepest overlap, with ball collisions) for any other number.
    pub fn new(scene: &Scene) -> Recording {
        let one_ball = scene.balls.len() == 1;
        let series = if one_ball {
            vec![
                series("height", PlotPanel::Height),
                series("speed", PlotPanel::Speed),
                series("kinetic + potential", PlotPanel::Energy),
            ]
        } else {
            let mut all = vec![
                series("kinetic, Σ m·|v|²/2", PlotPanel::TotalEnergy),
                series("potential, Σ m·g·h", PlotPanel::TotalEnergy),
                series("kinetic + potential", PlotPanel::TotalEnergy),
            ];
            if scene.ball_collisions.is_some() {
                all.push(series("deepest overlap", PlotPanel::Overlap));
            }
            all
        };
        let masses: f64 = scene.balls.iter().map(|b| b.radius * b.radius).sum();
        Recording {
            series,
            bounces: Vec::new(),
            width: f64::from(scene.width),
            height: f64::from(scene.height),
            gravity: scene.gravity.unwrap_or(Vec2::ZERO),
            mean_mass: masses / scene.balls.len().max(1) as f64,
            overlaps: (!one_ball && scene.ball_collisions.is_some()).then(Overlaps::default),
            last_vy: None,
            frames: 0,
        }
    }

    /// How many frames are recorded.
    pub(crate) fn frames(&self) -> u32 {
        self.frames
    }

    /// The ball's height above the floor, px: how far its centre is above where it rests on
    /// the bottom wall.
    pub(crate) fn height_above_floor(&self, ball: &Ball) -> f64 {
        self.height - ball.radius - ball.y
    }

    /// Potential energy per unit mass, px²/frame²: gravity times the distance the ball could
    /// still fall along it before touching the walls gravity pulls it towards (for the
    /// lesson's downward gravity, `g·h` with `h` the height above the floor).
    pub(crate) fn potential(&self, ball: &Ball) -> f64 {
        let Vec2 { x: gx, y: gy } = self.gravity;
        let rest = |g: f64, side: f64| {
            if g < 0.0 {
                ball.radius
            } else {
                side - ball.radius
            }
        };
        gx * (rest(gx, self.width) - ball.x) + gy * (rest(gy, self.height) - ball.y)
    }

    /// Adds one frame: the balls as they are after the frame's step.
    pub fn record(&mut self, balls: &[Ball]) {
        let values: Vec<f64> = match balls {
            [ball] => {
                let kinetic = 0.5 * (ball.vx * ball.vx + ball.vy * ball.vy);
                if self.last_vy.is_some_and(|vy| vy > 0.0) && ball.vy < 0.0 {
                    self.bounces.push(self.frames);
                }
                self.last_vy = Some(ball.vy);
                vec![
                    self.height_above_floor(ball),
                    maths::hypot(ball.vx, ball.vy),
                    kinetic + self.potential(ball),
                ]
            }
            _ => {
                let share = |total: f64| {
                    if self.mean_mass > 0.0 {
                        total / self.mean_mass
                    } else {
                        0.0
                    }
                };
                let kinetic = share(kinetic_energy(balls));
                let potential = share(
                    balls
                        .iter()
                        .map(|b| b.radius * b.radius * self.potential(b))
                        .sum(),
                );
                let mut values = vec![kinetic, potential, kinetic + potential];
                if let Some(overlaps) = &mut self.overlaps {
                    values.push(overlaps.deepest(balls));
                }
                values
            }
        };
        for (series, value) in self.series.iter_mut().zip(values) {
            series.values.push(value);
        }
        self.frames += 1;
    }
}
