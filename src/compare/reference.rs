//! The reference every method is measured against: RK4 with exact collisions, its substeps
//! doubled until two runs in a row agree to [`REFERENCE_AGREEMENT`] px everywhere. Under
//! gravity alone RK4 flies the exact parabola and exact mode bounces at the exact moment, so
//! it agrees at once (sloped floors too); drag takes a few doublings; balls that collide with
//! each other part chaotically at any step and never agree, which the reference then says.

use crate::physics::tolerances::REFERENCE_AGREEMENT;
use crate::physics::{Ball, CollisionMode, Integrator, Vec2};
use crate::scene::spec::MAX_SUBSTEPS;
use crate::scene::Scene;

use super::checks::check_finite;
use super::methods::Method;
use super::table::short;
use crate::job::{Job, RunError};

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
pub struct Trajectory {
    pub balls: usize,
    /// Frame `n`'s centres at `n * balls ..`.
    pub centres: Vec<Vec2>,
    /// The balls after the last frame (their velocities give the energy).
    pub last: Vec<Ball>,
}

impl Trajectory {
    /// The centres after frame `n`.
    pub fn frame(&self, n: usize) -> &[Vec2] {
        &self.centres[n * self.balls..(n + 1) * self.balls]
    }

    /// The largest distance between the two at any ball in any frame, px.
    fn farthest_from(&self, other: &Trajectory) -> f64 {
        let pairs = self.centres.iter().zip(&other.centres);
        pairs.map(|(a, b)| (*a - *b).length()).fold(0.0, f64::max)
    }
}

/// The reference: which method it is, its path, and how closely the last doubling agreed.
#[derive(Clone, Debug)]
pub struct Reference {
    pub method: Method,
    pub trajectory: Trajectory,
    /// The largest distance between this run and the one with half its substeps, px
    /// (infinite if there was none).
    pub agreement: f64,
    pub verdict: Verdict,
}

/// How the doubling ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Two runs in a row agreed to [`REFERENCE_AGREEMENT`].
    Converged,
    /// A doubling did not even halve the difference: the runs are not closing in on one
    /// path (balls that collide part chaotically, whatever the step), so finer ones would
    /// only cost more.
    Stalled,
    /// The next doubling would pass the work or substep limit.
    AtLimit,
}

impl Reference {
    /// The reference of a validated `scene`, run as part of `job` (its stop check and its
    /// progress bar).
    pub fn of(scene: &Scene, job: &Job) -> Result<Reference, RunError> {
        let rk4 = |substeps| Method {
            integrator: Integrator::Rk4,
            substeps,
            collisions: CollisionMode::Exact,
        };
        let mut method = rk4(1);
        let mut trajectory = run(scene, method, job)?;
        let mut agreement = f64::INFINITY;
        let verdict = loop {
            let finer = rk4(method.substeps * 2);
            if finer.substeps > MAX_SUBSTEPS || work(scene, finer.substeps) > MAX_REFERENCE_STEPS {
                break Verdict::AtLimit;
            }
            let next = run(scene, finer, job)?;
            let before = agreement;
            agreement = next.farthest_from(&trajectory);
            (method, trajectory) = (finer, next);
            if agreement <= REFERENCE_AGREEMENT {
                break Verdict::Converged;
            }
            if agreement > before / 2.0 {
                break Verdict::Stalled;
            }
        };
        Ok(Reference {
            method,
            trajectory,
            agreement,
            verdict,
        })
    }

    /// What the reference is, in a line: `rk4:2:exact: agrees with rk4:1:exact to 1.5e-12 px…`.
    pub fn describe(&self) -> String {
        if self.method.substeps == 1 {
            return format!(
                "{}: not checked against a finer run (one would pass the work limit)",
                self.method
            );
        }
        let half = Method {
            substeps: self.method.substeps / 2,
            ..self.method
        };
        let verdict = match self.verdict {
            Verdict::Converged => "converged",
            Verdict::Stalled => "not converging: doubling the substeps no longer halves the difference, as when balls that collide part chaotically",
            Verdict::AtLimit => "not converged: the next doubling would pass the work limit",
        };
        format!(
            "{}: agrees with {half} to {} px at every ball and frame ({verdict}; tolerance {REFERENCE_AGREEMENT:.0e} px)",
            self.method,
            short(self.agreement)
        )
    }
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
