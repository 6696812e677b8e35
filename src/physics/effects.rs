//! The physics a scene calls for. Every effect is optional: an absent one is never computed.

use super::ball::Ball;
use super::floor::Floor;
use super::vec2::Vec2;
use super::walls::Walls;
use crate::work::{tally, Work};

/// The forces and boundaries that act on every ball, each present only if the scene names it.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Effects {
    /// Added to every velocity each frame, px/frame².
    pub gravity: Option<Vec2>,
    /// Share of speed lost to the air each frame (the lesson's `v *= 1 - drag`).
    pub drag: Option<f64>,
    /// The box, with its damping.
    pub walls: Option<Walls>,
    /// Line segments the balls bounce off (the sloped floor).
    pub floors: Vec<Floor>,
}

impl Effects {
    /// The lesson's collision response: clamp-then-reflect against the box, then against
    /// every floor (swept from `from`), then the box again in case a floor pushed the ball
    /// out. Box first, so a fast ball cannot slip round a floor's end through the wall.
    pub(crate) fn clamp_and_reflect(&self, ball: &mut Ball, from: Vec2) {
        self.bounce_off_walls(ball);
        if !self.floors.is_empty() {
            for floor in &self.floors {
                tally(Work::Floor);
                floor.bounce(ball, from);
            }
            self.bounce_off_walls(ball);
        }
    }

    fn bounce_off_walls(&self, ball: &mut Ball) {
        if let Some(walls) = &self.walls {
            tally(Work::Walls);
            ball.bounce_off_walls(walls);
        }
    }
}
