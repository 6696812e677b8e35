//! A simulation's first frames, kept as they were stepped, so that they can be shown again
//! without being stepped again.
//!
//! The budget's pilot (`crate::budget`) steps a scene's first frames to measure them before
//! the run starts. Where those frames are costly (exact mode on a pile: the pilot is most of
//! the physics of a short run), the pilot keeps each frame's ball motions, and the run plays
//! them back ([`Playback`]) and steps on from where the pilot stopped. A played-back frame
//! sets each ball's position and velocity and records its trail, as the step that made it
//! did, so every ball, trail included, is what stepping would have made it, to the bit.
//!
//! Kept frames take 32 bytes per ball and frame, up to [`KEPT_BYTES`]; a pilot that steps
//! past that drops them, and the run steps every frame itself.

use super::ball::Ball;
use super::simulation::Simulation;

/// The most the kept frames take, bytes (8 MiB: 262,144 ball-frames).
pub const KEPT_BYTES: usize = 8 << 20;

/// What is kept per ball and frame, bytes: position and velocity.
pub const BYTES_PER_BALL_FRAME: usize = std::mem::size_of::<[f64; 4]>();

/// How many of `frames` frames of `balls` balls can be kept: as many whole frames as fit in
/// [`KEPT_BYTES`]. The memory budget counts this many, and [`KeptFrames`] reserves room for
/// this many and keeps no more.
pub fn frames_that_fit(balls: usize, frames: usize) -> usize {
    (KEPT_BYTES / (balls.max(1) * BYTES_PER_BALL_FRAME)).min(frames)
}

/// The frames a simulation has been stepped through since it started.
#[derive(Clone, Debug)]
pub struct KeptFrames {
    /// The balls as the scene starts them, then as the frames shown so far left them.
    balls: Vec<Ball>,
    /// Each kept frame's ball motions (x, y, vx, vy), frame after frame.
    motions: Vec<[f64; 4]>,
    /// How many of the kept frames have been shown.
    shown: usize,
}

impl KeptFrames {
    /// Starts keeping the frames of `simulation`, which has not been stepped yet, with room
    /// for `frames` frames (or as many as fit, [`frames_that_fit`]) taken at once: grown
    /// frame by frame, the buffer would double past what the memory budget counts.
    pub fn new(simulation: &Simulation, frames: usize) -> KeptFrames {
        let balls = simulation.balls();
        let mut motions = Vec::new();
        motions.reserve_exact(frames_that_fit(balls.len(), frames) * balls.len());
        KeptFrames {
            balls: balls.to_vec(),
            motions,
            shown: 0,
        }
    }

    /// Keeps the frame `simulation` has just stepped. Returns `false`, keeping nothing more,
    /// once the kept frames would take more than [`KEPT_BYTES`].
    pub fn keep(&mut self, simulation: &Simulation) -> bool {
        let balls = simulation.balls();
        let bytes = (self.motions.len() + balls.len()) * BYTES_PER_BALL_FRAME;
        if bytes > KEPT_BYTES {
            return false;
        }
        let motions = balls.iter().map(|ball| [ball.x, ball.y, ball.vx, ball.vy]);
        self.motions.extend(motions);
        true
    }

    /// Shows the next kept frame; `false` if every kept frame has been shown.
    fn show_next(&mut self) -> bool {
        let n = self.balls.len();
        let Some(frame) = self.motions.get(self.shown * n..(self.shown + 1) * n) else {
            return false;
        };
        for (ball, &[x, y, vx, vy]) in self.balls.iter_mut().zip(frame) {
            (ball.x, ball.y, ball.vx, ball.vy) = (x, y, vx, vy);
            ball.record_trail();
        }
        self.shown += 1;
        true
    }
}

/// A simulation whose first frames are played back from kept frames, then stepped.
#[derive(Debug)]
pub struct Playback {
    /// The frames still to show; `None` once all are shown (or there were none).
    kept: Option<KeptFrames>,
    /// Where the kept frames end: stepped on once every one has been shown.
    simulation: Simulation,
}

impl Playback {
    /// Plays `kept` back, then steps `simulation`, which must be the simulation those frames
    /// were kept of, as the last of them left it.
    pub fn new(kept: KeptFrames, simulation: Simulation) -> Playback {
        Playback {
            kept: Some(kept),
            simulation,
        }
    }

    /// Steps `simulation` from its start: nothing to play back.
    pub fn stepping(simulation: Simulation) -> Playback {
        Playback {
            kept: None,
            simulation,
        }
    }

    /// Advances every ball by one frame: the next kept frame, or a step of the simulation.
    pub fn step(&mut self) {
        if let Some(kept) = &mut self.kept {
            if kept.show_next() {
                return;
            }
            // Every kept frame is shown: the balls are the simulation's, from here on.
            self.kept = None;
        }
        self.simulation.step();
    }

    /// The balls as they are now, in scene order.
    pub fn balls(&self) -> &[Ball] {
        match &self.kept {
            Some(kept) => &kept.balls,
            None => self.simulation.balls(),
        }
    }
}
