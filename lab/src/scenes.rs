//! Scenes the tests and examples build from the presets: the contact study's piles, and a
//! pile that a late ball wakes.

use bouncing_ball::physics::{Floor, Vec2};
use bouncing_ball::scene::file::{preset, SceneFileError, Spawn};
use bouncing_ball::Scene;

/// The `pile` preset with `count` balls of `radius` px spawned instead of its own: the
/// contact study and its tests heap up different piles in the same box. They are placed
/// uniformly at random, overlaps and all, as when the study was measured.
pub fn pile(count: usize, radius: f64, seed: u64) -> Result<Scene, SceneFileError> {
    let mut scene = preset("pile", seed)?;
    let spawn = Spawn::new(count, radius, 4.0);
    scene.balls = spawn.overlapping_balls(f64::from(scene.width), f64::from(scene.height), seed);
    checked(scene)
}

/// `scene`, built from the pile preset, if it is valid.
fn checked(scene: Scene) -> Result<Scene, SceneFileError> {
    scene
        .validate()
        .map_err(|invalid| SceneFileError::Invalid {
            file: "scenes/pile.toml".to_string(),
            invalid,
        })?;
    Ok(scene)
}

/// The pile's first balls and one more that arrives once they rest, to wake them: the `pile`
/// preset's 150 balls spawned over the lower half of its box (overlaps and all, so they heap
/// as in the preset, a little faster), and a last ball at the top end of a floor above them,
/// 250 px long and 2 px lower at its other end. The ball slides down the floor for about 350
/// frames (at g·2/250 it covers 250 px in √(2·250·250/(0.5·2)) ≈ 350 frames) and drops
/// 80 px onto the pile at about 9 px/frame, long after the pile has come to rest.
pub fn late_drop(seed: u64) -> Result<Scene, SceneFileError> {
    let mut scene = preset("pile", seed)?;
    let (width, height) = (f64::from(scene.width), f64::from(scene.height));
    let radius = 6.0;
    let spawn = Spawn::new(150, radius, 4.0);
    scene.balls = spawn.overlapping_balls(width, height / 2.0, seed);
    for ball in &mut scene.balls {
        ball.y += height / 2.0;
    }
    let (from, to) = (Vec2::new(10.0, 100.0), Vec2::new(260.0, 102.0));
    scene.floors = vec![Floor {
        from,
        to,
        damping: 0.5,
    }];
    let mut late = scene.balls[0].clone();
    (late.x, late.y, late.vx, late.vy) = (20.0, from.y - radius, 0.0, 0.0);
    scene.balls.push(late);
    checked(scene)
}
