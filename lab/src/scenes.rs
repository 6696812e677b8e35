//! Scenes the tests and examples build from the presets: the contact study's piles.

use bouncing_ball::scene::file::{preset, SceneFileError, Spawn};
use bouncing_ball::Scene;

/// The `pile` preset with `count` balls of `radius` px spawned instead of its own: the
/// contact study and its tests heap up different piles in the same box. They are placed
/// uniformly at random, overlaps and all, as when the study was measured.
pub fn pile(count: usize, radius: f64, seed: u64) -> Result<Scene, SceneFileError> {
    let mut scene = preset("pile", seed)?;
    let spawn = Spawn::new(count, radius, 4.0);
    scene.balls = spawn.overlapping_balls(f64::from(scene.width), f64::from(scene.height), seed);
    scene
        .validate()
        .map_err(|invalid| SceneFileError::Invalid {
            file: "scenes/pile.toml".to_string(),
            invalid,
        })?;
    Ok(scene)
}
