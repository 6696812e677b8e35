//! The box the balls bounce in: its size and how much speed a bounce keeps.
//!
//! The clamp-then-reflect itself is the lesson's, so it lives with the ball
//! (`Ball::bounce_off_walls`); this module only describes the box.

/// The four walls of a `width` × `height` box (px) and the share of speed a bounce keeps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Walls {
    pub width: f64,
    pub height: f64,
    /// 1.0 is perfectly elastic, 0.0 stops the ball dead.
    pub damping: f64,
}
