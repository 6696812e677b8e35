//! The physics a scene calls for, ready to apply each frame.

use crate::walls::Walls;

/// The forces and boundaries that act on every ball.
#[derive(Clone, Debug, PartialEq)]
pub struct Effects {
    /// Added to every velocity each frame, px/frame².
    pub gravity: [f64; 2],
    pub walls: Walls,
}
