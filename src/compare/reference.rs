//! The reference every method is measured against: RK4 with exact collisions, its substeps
//! doubled until two runs in a row agree to [`REFERENCE_AGREEMENT`] px everywhere, and at
//! least once past the finest method's, so it is finer than what it judges. Under gravity
//! alone RK4 flies the exact parabola and exact mode bounces at the exact moment, so it
//! agrees at once (sloped floors too); drag takes a few doublings; balls that collide with
//! each other part chaotically at any step and never agree, which the reference then says.
//!
//! How far its last two refinements are apart, frame by frame, is its uncertainty; the frame
//! where they first part by more than a ball's radius is its horizon, past which it no longer
//! says where the balls are, and no method is judged against it.

use crate::physics::{Ball, CollisionMode, Integrator, Vec2};
use crate::scene::spec::MAX_SUBSTEPS;
use crate::scene::Scene;

use super::checks::check_finite;
use super::measure::{Role, Trust};
use super::methods::Method;
use super::table::short;
use crate::job::{Job, RunError};

/// How closely two runs of the reference (RK4, exact collisions) with the second's substeps
/// doubled must agree, px, at every ball in every frame, for the finer to be the reference: far
/// below a pixel, and a thousand times below the error of the best method worth comparing.
pub(crate) const REFERENCE_AGREEMENT: f64 = 1e-9;

/// The most ball-steps one run of the reference may take, weighted by what a step costs
/// (a ball-ball collision step counts as [`COLLIDING_STEP_WEIGHT`]): a second or two for one
/// ball on the reference machine. The doubling stops there, converged or not, so the time is
/// bounded and the same on every machine (the reference, and so the GIF, must not depend on
/// the clock).
const MAX_REFERENCE_STEPS: u64 = 1 << 24;
/// What a ball-step with ball-ball collisions costs compared with one without (about 400 ns
/// against 30 in the budget's fitted costs).
const COLLIDING_STEP_WEIGHT: u64 = 13;

/// Every ball's centre after every frame, frame by frame, and the balls after the last.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Trajectory {
    pub balls: usize,
    /// Frame `n`'s centres at `n * balls ..`.
    pub centres: Vec<Vec2>,
    /// The balls after the last frame (their velocities give the energy).
    pub last: Vec<Ball>,
}

impl Trajectory {
    /// The centres after frame `n`.
    pub(crate) fn frame(&self, n: usize) -> &[Vec2] {
        &self.centres[n * self.balls..(n + 1) * self.balls]
    }
}

/// The reference: which method it is, its path, and how far to trust it.
#[derive(Clone, Debug)]
pub(crate) struct Reference {
    pub method: Method,
    pub trajectory: Trajectory,
    /// At each frame, the reference's own uncertainty so far: the largest distance between
    /// its last two refinements at any ball in that frame or an earlier one, px (so it only
    /// grows, and the legend reads it frame by frame at no cost). Infinite if there was only
    /// one run.
    pub uncertainty: Vec<f64>,
    /// The first frame in which the last two refinements are more than a ball's radius
    /// apart, from where the reference no longer says where the balls are; the frame count
    /// if there is none. No method is judged from here on.
    pub horizon: u32,
    pub convergence: Convergence,
    /// The finest listed method's substeps: the reference has more, unless [`Reference::limited`].
    pub finest: u32,
    /// Whether the work or substep limit stopped the doubling.
    pub limited: bool,
}

/// How the doubling ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Convergence {
    /// Two runs in a row agreed to [`REFERENCE_AGREEMENT`].
    Converged,
    /// A doubling did not even halve the difference: the runs are not closing in on one
    /// path (balls that collide part chaotically, whatever the step), so finer ones would
    /// only cost more.
    Stalled,
    /// Each doubling still halved the difference when the limit stopped it.
    Converging,
    /// The limit allowed a single run: nothing to check it against.
    Unchecked,
}

impl Reference {
    /// The reference of a validated `scene` for judging `methods`, run as part of `job` (its
    /// stop check and its progress bar). The substeps double until two runs agree (or stop closing in) and the
    /// reference has more substeps than every method, or until the next doubling would pass
    /// the limit.
    pub(crate) fn of(scene: &Scene, methods: &[Method], job: &Job) -> Result<Reference, RunError> {
        Reference::refined(scene, methods, most_substeps(scene), job)
    }

    /// [`Reference::of`] with at most `most` substeps (a power of two): the estimate runs it on
    /// the first frames of a scene, held to the whole scene's limit.
    pub(crate) fn refined(
        scene: &Scene,
        methods: &[Method],
        most: u32,
        job: &Job,
    ) -> Result<Reference, RunError> {
        let finest = methods.iter().map(|m| m.substeps).max().unwrap_or(1);
        let mut method = rk4(1);
        let mut trajectory = run(scene, method, job)?;
        let mut uncertainty = vec![f64::INFINITY; scene.frames as usize];
        let mut horizon = 0;
        let mut convergence = Convergence::Unchecked;
        let mut limited = false;
        // Once the doubling has converged or stalled, only the "finer than every method"
        // rule asks for more; a finer run no longer changes whether it converged.
        let settled = |v: Convergence| matches!(v, Convergence::Converged | Convergence::Stalled);
        while !(settled(convergence) && method.substeps > finest) {
            let finer = rk4(method.substeps * 2);
            if finer.substeps > most {
                limited = true;
                break;
            }
            let next = run(scene, finer, job)?;
            let before = largest(&uncertainty);
            (uncertainty, horizon) = apart(&next, &trajectory, scene);
            let agreement = largest(&uncertainty);
            if !settled(convergence) {
                convergence = if agreement <= REFERENCE_AGREEMENT {
                    Convergence::Converged
                } else if agreement > before / 2.0 {
                    Convergence::Stalled
                } else {
                    Convergence::Converging
                };
            }
            (method, trajectory) = (finer, next);
        }
        Ok(Reference {
            method,
            horizon,
            trajectory,
            uncertainty,
            convergence,
            finest,
            limited,
        })
    }

    /// The role of `method` in the table: the reference's own method is shown as the
    /// reference, since measured against itself it would show an error of 0, which says
    /// nothing.
    pub(crate) fn role(&self, method: Method) -> Role {
        if method == self.method {
            Role::Reference
        } else {
            Role::Method
        }
    }

    /// How far it can be trusted over the first `seen` frames, as every method is judged by
    /// it (the table over the whole run, the legend frame by frame).
    pub(crate) fn trust(&self, seen: u32) -> Trust {
        Trust {
            uncertainty: self.largest_uncertainty(seen),
            horizon: self.horizon,
        }
    }

    /// The largest uncertainty in the first `seen` frames before the horizon (the first
    /// frame's if the reference is trusted in none), px.
    fn largest_uncertainty(&self, seen: u32) -> f64 {
        let last = self.horizon.min(seen).max(1) as usize - 1;
        self.uncertainty.get(last).copied().unwrap_or(0.0)
    }

    /// What the reference is and how far it is trusted, a line each: `rk4:8:exact: agrees
    /// with rk4:4:exact to 1.5e-12 px…`, then its uncertainty and horizon.
    pub(crate) fn describe(&self) -> Vec<String> {
        let frames = self.uncertainty.len();
        let mut lines = vec![self.agreement()];
        if self.convergence == Convergence::Unchecked {
            return lines;
        }
        lines.push(if self.horizon as usize >= frames {
            format!(
                "its uncertainty (how far its last two refinements are apart): at most {} px over all {frames} frames",
                short(self.largest_uncertainty(self.horizon))
            )
        } else {
            format!(
                "its uncertainty (how far its last two refinements are apart): at most {} px up to frame {}; from frame {} on they are more than a ball's radius apart, so no method is judged there",
                short(self.largest_uncertainty(self.horizon)),
                self.horizon,
                self.horizon
            )
        });
        if self.limited && self.method.substeps <= self.finest {
            lines.push(format!(
                "it is not finer than the finest method ({} substeps): a finer run would pass the work limit ({MAX_REFERENCE_STEPS} weighted ball-steps, at most {MAX_SUBSTEPS} substeps)",
                self.finest
            ));
        }
        lines
    }

    /// The first line of [`Reference::describe`]: how closely the last doubling agreed.
    fn agreement(&self) -> String {
        if self.convergence == Convergence::Unchecked {
            return format!(
                "{}: not checked against a finer run (one would pass the work limit), so no method is judged",
                self.method
            );
        }
        let half = rk4(self.method.substeps / 2);
        let verdict = match self.convergence {
            Convergence::Converged => "converged",
            Convergence::Stalled => "not converging: doubling the substeps no longer halves the difference, as when balls that collide part chaotically",
            _ => "not converged: the next doubling would pass the work limit",
        };
        format!(
            "{}: agrees with {half} to {} px at every ball and frame ({verdict}; tolerance {REFERENCE_AGREEMENT:.0e} px)",
            self.method,
            short(largest(&self.uncertainty))
        )
    }
}

/// RK4 with exact collisions and `substeps`: the reference's method.
pub(crate) fn rk4(substeps: u32) -> Method {
    Method {
        integrator: Integrator::Rk4,
        substeps,
        collisions: CollisionMode::Exact,
    }
}

/// The most substeps a run of the reference on `scene` may take: the largest power of two
/// within the substep and work limits (1 at least: there is always a first run).
pub(crate) fn most_substeps(scene: &Scene) -> u32 {
    let within =
        |substeps| substeps <= MAX_SUBSTEPS && work(scene, substeps) <= MAX_REFERENCE_STEPS;
    let mut most = 1;
    while within(most * 2) {
        most *= 2;
    }
    most
}

/// The largest of an uncertainty over the whole run: its last frame's (0 for no frame).
fn largest(uncertainty: &[f64]) -> f64 {
    uncertainty.last().copied().unwrap_or(0.0)
}

/// How far two runs are apart: at each frame the largest distance at any ball in that frame
/// or an earlier one, px, and the first frame in which some ball is more than its radius off
/// (the frame count if none).
fn apart(finer: &Trajectory, coarser: &Trajectory, scene: &Scene) -> (Vec<f64>, u32) {
    let mut horizon = None;
    let mut so_far = 0.0;
    let distances = (0..scene.frames as usize)
        .map(|n| {
            let pairs = finer
                .frame(n)
                .iter()
                .zip(coarser.frame(n))
                .zip(&scene.balls);
            so_far = pairs.fold(so_far, |far: f64, ((a, b), ball)| {
                let distance = (*a - *b).length();
                if distance > ball.radius && horizon.is_none() {
                    horizon = Some(n as u32);
                }
                far.max(distance)
            });
            so_far
        })
        .collect();
    (distances, horizon.unwrap_or(scene.frames))
}

/// The weighted ball-steps of one run of `scene` with `substeps`.
fn work(scene: &Scene, substeps: u32) -> u64 {
    let weight = match scene.ball_collisions {
        Some(_) => COLLIDING_STEP_WEIGHT,
        None => 1,
    };
    let balls = scene.balls.len() as u64;
    u64::from(scene.frames) * u64::from(substeps) * balls * weight
}

/// Every centre of a run of `scene` solved by `method`.
fn run(scene: &Scene, method: Method, job: &Job) -> Result<Trajectory, RunError> {
    let mut simulation = method.on(scene).simulation();
    let balls = scene.balls.len();
    let mut centres = Vec::with_capacity(balls * scene.frames as usize);
    job.progress().add_frames(scene.frames);
    for n in 0..scene.frames {
        job.stop_if_asked(n, scene.frames)?;
        simulation.step();
        check_finite(scene, method, simulation.balls(), n)?;
        centres.extend(simulation.balls().iter().map(|b| b.position()));
        job.progress().frame_done();
    }
    let last = simulation.balls().to_vec();
    Ok(Trajectory {
        balls,
        centres,
        last,
    })
}
