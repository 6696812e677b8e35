//! How long a comparison will take, predicted before any work, so that one over the time
//! budget (`--time-budget`) is refused at once instead of after minutes.
//!
//! A comparison runs the physics of the scene many times: the reference's refinements, each
//! method once to draw it, and each method again and again to time it. Each run is costed by
//! `PhysicsPilot`, the budget's prediction of a whole run from a pilot. Only the number of
//! the reference's refinements cannot be known up front: it takes as many doublings as the
//! scene needs to converge. A pilot finds out on the scene's first frames, and the whole run
//! is assumed to need at least as many, and at least one doubling past the finest method,
//! within the reference's work limit.

use crate::budget::{Budget, OverBudget, PhysicsPilot};
use crate::job::Job;
use crate::physics::{CollisionMode, Integrator};
use crate::scene::Scene;

use super::measure::timing_seconds;
use super::methods::Method;
use super::reference::{most_substeps, rk4, Reference};
use super::without_trails;

/// The pilot of the reference's doubling runs on a prefix of the scene short enough to take
/// about this long even if it doubles to the work limit, seconds (predicted).
const PILOT_SECONDS: f64 = 0.2;

/// The predicted seconds of comparing `methods` on a validated `scene`: the reference's runs,
/// each method's drawn run and its timing runs (the drawing itself is not counted: next to
/// the physics of many runs it is small).
pub fn estimate_seconds(scene: &Scene, methods: &[Method]) -> f64 {
    let bare = without_trails(scene);
    let mut costs = Costs {
        scene: &bare,
        pilots: Vec::new(),
    };
    let first = costs.of(rk4(1));
    let last = last_substeps(&bare, methods, first);
    // Its refinements after the first: 2, 4, … up to the last.
    let finer: f64 = (1..=last.ilog2()).map(|k| costs.of(rk4(1 << k))).sum();
    let runs: Vec<f64> = methods.iter().map(|&m| costs.of(m)).collect();
    first + finer + runs.iter().sum::<f64>() + timing_seconds(&runs)
}

/// The predicted seconds of runs of a scene by several methods. One pilot serves every
/// method with the same integrator and collisions, whatever its substeps (the reference's
/// refinements, and a listed method that is one of them): each pilot costs about as much as
/// a run of the scene's first frames, and a comparison's runs differ mostly in substeps.
struct Costs<'a> {
    scene: &'a Scene,
    pilots: Vec<((Integrator, CollisionMode), PhysicsPilot)>,
}

impl Costs<'_> {
    fn of(&mut self, method: Method) -> f64 {
        let scene = method.on(self.scene);
        let solver = (method.integrator, method.collisions);
        let piloted = self
            .pilots
            .iter()
            .position(|(piloted, _)| *piloted == solver);
        let k = piloted.unwrap_or_else(|| {
            self.pilots.push((solver, PhysicsPilot::of(&scene)));
            self.pilots.len() - 1
        });
        self.pilots[k].1.seconds(&scene)
    }
}

/// Refuses a comparison predicted to take longer than `budget` allows; returns the seconds
/// it is predicted to take.
pub fn check(scene: &Scene, methods: &[Method], budget: &Budget) -> Result<f64, OverBudget> {
    let seconds = estimate_seconds(scene, methods);
    budget.check_seconds(seconds)?;
    Ok(seconds)
}

/// The substeps of the reference's last run on `scene`, from a pilot: the reference's own
/// doubling on the scene's first frames, held to the whole scene's work limit. `first`, the
/// predicted seconds of its first run on the whole scene, sizes the prefix, so that the pilot
/// is short even if it doubles to the limit.
fn last_substeps(scene: &Scene, methods: &[Method], first: f64) -> u32 {
    let most = most_substeps(scene);
    let share = PILOT_SECONDS / (f64::from(2 * most - 1) * first);
    let frames = (f64::from(scene.frames) * share).clamp(1.0, f64::from(scene.frames)) as u32;
    let prefix = Scene {
        frames,
        ..scene.clone()
    };
    // A pilot whose balls leave the finite numbers foretells a refused run; count the most.
    Reference::refined(&prefix, methods, most, &Job::new())
        .map_or(most, |pilot| pilot.method.substeps)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compare::methods::LESSON;
    use crate::scene::file::preset;

    #[test]
    fn a_comparison_of_more_frames_is_predicted_to_take_longer() {
        let moon = |frames| Scene {
            frames,
            ..preset("moon", 1).unwrap()
        };
        let methods = [LESSON, rk4(4)];
        let short = estimate_seconds(&moon(20), &methods);
        let long = estimate_seconds(&moon(200), &methods);
        assert!(
            0.0 < short && short < long,
            "20 frames predicted at {short} s, 200 at {long} s"
        );
    }

    #[test]
    fn runs_that_differ_only_in_substeps_share_one_pilot_and_cost_more_with_more() {
        let scene = Scene {
            frames: 20,
            ..preset("moon", 1).unwrap()
        };
        let mut costs = Costs {
            scene: &scene,
            pilots: Vec::new(),
        };
        let (one, four) = (costs.of(rk4(1)), costs.of(rk4(4)));
        costs.of(LESSON);
        costs.of(rk4(2));
        assert_eq!(
            costs.pilots.len(),
            2,
            "RK4 at 1, 2 and 4 substeps and the lesson's method: expected 2 pilots"
        );
        assert!(
            four > 2.0 * one,
            "4 substeps predicted at {four} s, 1 at {one} s: expected the steps to cost more"
        );
    }
}
