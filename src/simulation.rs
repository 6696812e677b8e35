//! A scene in motion: the balls and the effects acting on them, advanced one frame at a time.

use crate::ball::Ball;
use crate::effects::Effects;
use crate::motion::Motion;
use crate::scene::Scene;
use crate::walls::Walls;

/// The moving state of a scene.
#[derive(Clone, Debug)]
pub struct Simulation {
    balls: Vec<Ball>,
    effects: Effects,
    motion: Motion,
}

impl Simulation {
    /// Puts every ball of a (validated) scene at its start.
    pub fn new(scene: &Scene) -> Simulation {
        let balls = scene
            .balls
            .iter()
            .map(|b| Ball::new(b.x, b.y, b.vx, b.vy, b.radius, b.trail))
            .collect();
        let effects = Effects {
            gravity: scene.gravity,
            drag: scene.drag,
            walls: scene.walls.map(|damping| Walls {
                width: f64::from(scene.width),
                height: f64::from(scene.height),
                damping,
            }),
            floors: scene.floors.clone(),
        };
        Simulation {
            balls,
            effects,
            motion: scene.motion,
        }
    }

    /// Advances every ball by one frame.
    pub fn step(&mut self) {
        for ball in &mut self.balls {
            ball.step(&self.effects, &self.motion);
        }
    }

    /// The balls as they are now, in scene order.
    pub fn balls(&self) -> &[Ball] {
        &self.balls
    }
}
