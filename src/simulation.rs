//! A scene in motion: the balls and the effects acting on them, advanced one frame at a time.

use crate::ball::Ball;
use crate::collisions::Collisions;
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
    /// Present only if the scene calls for ball-ball collisions (it owns the grid).
    collisions: Option<Collisions>,
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
            collisions: scene.ball_collisions.map(Collisions::new),
        }
    }

    /// Advances every ball by one frame: each step (substep) moves every ball, then resolves
    /// ball-ball contacts if the scene has them, so more substeps also catch faster pairs;
    /// the trails record where the balls ended the frame. The step's forces are worked out
    /// once per frame, for all balls.
    pub fn step(&mut self) {
        let (steps, forces) = self.motion.plan(&self.effects);
        for _ in 0..steps {
            for ball in &mut self.balls {
                self.motion.step(ball, &self.effects, &forces);
            }
            if let Some(collisions) = &mut self.collisions {
                collisions.resolve(&mut self.balls);
                if let Some(walls) = &self.effects.walls {
                    for ball in &mut self.balls {
                        walls.contain(ball);
                    }
                }
            }
        }
        for ball in &mut self.balls {
            ball.record_trail();
        }
    }

    /// Whether ball-ball collisions (and so the broad-phase grid) exist in this simulation.
    pub fn has_ball_collisions(&self) -> bool {
        self.collisions.is_some()
    }

    /// The balls as they are now, in scene order.
    pub fn balls(&self) -> &[Ball] {
        &self.balls
    }
}
