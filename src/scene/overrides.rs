//! Values typed on the command line that replace a scene's own (`--preset moon --damping 1`).

use super::spec::Scene;
use crate::physics::motion::CollisionMode;
use crate::physics::Integrator;

/// Each `Some` replaces the scene's value; ball values apply to every ball.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overrides {
    pub width: Option<u32>,
    pub height: Option<u32>,
    pub radius: Option<f64>,
    pub x: Option<f64>,
    pub y: Option<f64>,
    pub vx: Option<f64>,
    pub vy: Option<f64>,
    /// Downward gravity, px/frame²; 0 removes gravity.
    pub gravity: Option<f64>,
    /// The walls' damping; adds the box if the scene has none.
    pub damping: Option<f64>,
    /// Air drag per frame; 0 removes drag.
    pub drag: Option<f64>,
    /// Ball-ball restitution; adds ball-ball collisions if the scene has none.
    pub restitution: Option<f64>,
    pub trail: Option<usize>,
    pub frames: Option<u32>,
    pub frame_ms: Option<u32>,
    pub integrator: Option<Integrator>,
    pub substeps: Option<u32>,
    pub collisions: Option<CollisionMode>,
    pub iterations: Option<u32>,
}

/// `Some(value)` unless it is zero: a zero-strength effect is no effect, and costs nothing.
fn unless_zero(value: f64) -> Option<f64> {
    (value != 0.0).then_some(value)
}

impl Overrides {
    /// Writes every given value into `scene`.
    pub fn apply(&self, scene: &mut Scene) {
        fn set<T: Copy>(target: &mut T, value: Option<T>) {
            if let Some(v) = value {
                *target = v;
            }
        }
        set(&mut scene.width, self.width);
        set(&mut scene.height, self.height);
        for ball in &mut scene.balls {
            set(&mut ball.radius, self.radius);
            set(&mut ball.x, self.x);
            set(&mut ball.y, self.y);
            set(&mut ball.vx, self.vx);
            set(&mut ball.vy, self.vy);
            set(&mut ball.trail, self.trail);
        }
        if let Some(g) = self.gravity {
            scene.gravity = unless_zero(g).map(|g| [0.0, g]);
        }
        if let Some(drag) = self.drag {
            scene.drag = unless_zero(drag);
        }
        if self.damping.is_some() {
            scene.walls = self.damping;
        }
        if self.restitution.is_some() {
            scene.ball_collisions = self.restitution;
        }
        set(&mut scene.frames, self.frames);
        set(&mut scene.frame_ms, self.frame_ms);
        set(&mut scene.motion.integrator, self.integrator);
        set(&mut scene.motion.substeps, self.substeps);
        set(&mut scene.motion.collisions, self.collisions);
        set(&mut scene.motion.iterations, self.iterations);
    }
}
