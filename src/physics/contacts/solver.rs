//! The contact solver's orchestration, as Box2D v3's `solver.c` has it: the step, its stages
//! in order, and the sub-step loop. In the stepped (clamp) mode, a scene with ball-ball
//! collisions has every contact — ball with ball, ball with wall, ball with floor — solved
//! together and iteratively, so that a pile carries its own weight and comes to rest.
//!
//! It is Box2D's *sequential impulses* (Erin Catto, GDC 2006) for frictionless discs, with
//! warm starting, a rest speed below which contacts do not bounce, and Box2D v2.4's position
//! pass; and it iterates the way Box2D v3's *soft step* and "small steps" XPBD do: each
//! iteration is a short sub-step (gravity, one velocity pass, flight, one position pass),
//! with the contacts found once per step. `docs/contacts.md` has the measurements that chose
//! this over more passes per step, softer contacts, and plain substeps. The stages carry
//! Box2D v3's names, and every stage is handed the step's one [`StepContext`].
//!
//! One step (`ContactSolver::one_step`; a frame is `steps` of them):
//!
//! 1. **Prepare** (`super::contact_solver`): the contacts that can touch within the step,
//!    each with the impulse it ended the last step with, sorted into islands
//!    (`super::island`) that are each solved on their own.
//! 2. **Without gravity or drag**, an island is solved touch by touch
//!    (`super::touch_by_touch`), if it can be.
//! 3. **Sub-steps** ([`solve_in_substeps`]): otherwise, for each island, `iterations` times,
//!    for a sub-step `h` of the step, the stages of [`Stage`] in order:
//!    - **Integrate velocities**: the integrator adds `h`'s gravity and drag to every
//!      velocity.
//!    - **Warm start** (under gravity only): each contact pushes again with its impulse of
//!      the sub-step before.
//!    - **Solve**, the velocity pass. Under gravity it runs three times
//!      (`LOADED_VELOCITY_PASSES`), so that a deep heap carries its weight before the
//!      position pass moves it; without, once.
//!    - **Integrate positions**: fly `h` with the solved velocities.
//!    - **Relax**, the position pass: overlap beyond a small slop partly pushed out.
//! 4. A ball that can touch nothing takes the whole step at once, as in the lesson, and the
//!    balls are copied back into the scene, inside its walls.
//! 5. **Restitution**: the bounces left after the sub-steps, of pairs the step did not list.
//! 6. **Store**: each contact's impulse goes into the warm-start memory for the next step.
//! 7. **Sleep** (`super::sleep`): an island whose balls have all been slow for long enough
//!    sleeps.
//!
//! Everything happens in a fixed order (the grid's), so the same balls give the same bytes.

use super::contact::{Body, Push};
use super::contact_solver;
use super::grid::Grid;
use super::island::Island;
use super::sleep::Sleep;
use super::step_context::{StepContext, Stepping};
use super::touch_by_touch::solve_touch_by_touch;
use super::warm_start_memory::WarmStartMemory;
use crate::physics::ball::Ball;
use crate::physics::effects::Effects;
use crate::physics::floor::Floor;
use crate::physics::motion::Motion;
use crate::physics::walls::Walls;
use crate::work::{tally, Work};

/// The contact solver. A scene without ball-ball collisions (or in exact mode) never
/// creates one.
#[derive(Clone, Debug)]
pub(crate) struct ContactSolver {
    /// What carries from one step to the next: each contact's last impulse, for warm starting.
    memory: WarmStartMemory,
    /// The sleeping islands, and how long each awake ball has been calm.
    sleep: Sleep,
    /// What the stages of a step share, refilled every step.
    context: StepContext,
}

/// The stages of a sub-step, in the order they run, named as Box2D v3 names them
/// (`b2SolverStageType` in `solver.c`). Box2D's enum also has the stages that run once a
/// step: here prepare, restitution and store are the calls of `ContactSolver::one_step`
/// around the sub-steps.
#[derive(Clone, Copy, Debug)]
enum Stage {
    /// The sub-step's gravity and drag into every velocity ([`integrate_velocities`]).
    IntegrateVelocities,
    /// Each contact pushes again with its last impulse (`contact_solver::warm_start`).
    WarmStart,
    /// The velocity pass, [`Stepping::velocity_passes`] times (`contact_solver::solve`).
    Solve,
    /// Every ball flies the sub-step with its solved velocity ([`integrate_positions`]).
    IntegratePositions,
    /// The position pass (`contact_solver::relax`).
    Relax,
}

/// A sub-step: every stage, in order.
const SUB_STEP: [Stage; 5] = [
    Stage::IntegrateVelocities,
    Stage::WarmStart,
    Stage::Solve,
    Stage::IntegratePositions,
    Stage::Relax,
];

impl ContactSolver {
    /// The solver's memory per ball at most, bytes, for the budget: the grid's, and up to
    /// `MAX_PAIRS_PER_BALL` contacts with their warm-start memory and the scratch they are
    /// solved in, with what their growth by doubling and the warm-start memory's half-free
    /// hash table leave spare (measured: 5,233 B a ball in all, the grid's included, on
    /// 20,000 balls piled on one spot, where every ball has its most contacts;
    /// `tests/allocations.rs` holds the estimate to that).
    pub(crate) const BYTES_PER_BALL: u64 = Grid::BYTES_PER_BALL + 5300;

    /// A solver for ball-ball contacts that keep `restitution` of the approach speed.
    pub(crate) fn new(restitution: f64) -> ContactSolver {
        ContactSolver {
            memory: WarmStartMemory::default(),
            sleep: Sleep::default(),
            context: StepContext {
                restitution,
                ..StepContext::default()
            },
        }
    }

    /// How many balls sleep now (`super::sleep`).
    pub(crate) fn sleeping(&self) -> usize {
        self.sleep.sleeping()
    }

    /// Advances every ball one frame (its substeps) under `effects`, with `motion`'s
    /// integrator and iterations; trails are the caller's business.
    pub(crate) fn step(&mut self, scene_balls: &mut [Ball], effects: &Effects, motion: &Motion) {
        self.context.stepping = Stepping::new(effects, motion);
        self.sleep.fit(scene_balls.len());
        for _ in 0..self.context.stepping.steps {
            if self.sleep.everyone_asleep() {
                return; // nothing awake to move, or to wake anything
            }
            tally(Work::Contacts);
            self.one_step(scene_balls, effects);
        }
    }

    /// One step: its stages in order.
    fn one_step(&mut self, scene_balls: &mut [Ball], effects: &Effects) {
        let (context, sleep, memory) = (&mut self.context, &mut self.sleep, &mut self.memory);
        contact_solver::prepare(context, scene_balls, effects, sleep, memory);
        solve_islands(context);
        move_untouched(context);
        let (walls, floors) = (effects.walls.as_ref(), &effects.floors);
        for (body, &i) in context.bodies.iter().zip(context.grid.order()) {
            copy_back(body, &mut scene_balls[i], walls, floors);
        }
        contact_solver::restitution(context, |body, i| {
            copy_back(body, &mut scene_balls[i], walls, floors);
            sleep.wake(i); // it moved: its island wakes
        });
        contact_solver::store(context, memory, sleep);
        sleep.fall_asleep(scene_balls, context);
    }
}

/// Solves every island, one after another: touch by touch if no force acts and the island
/// allows, in sub-steps otherwise. Islands share no ball, so each is solved on its own, all
/// its sub-steps at once, while its few balls and contacts are in the cache.
fn solve_islands(context: &mut StepContext) {
    for k in 0..context.islands.list.len() {
        let island = context.islands.list[k].clone();
        if context.stepping.free && solve_touch_by_touch(context, &island) {
            continue;
        }
        solve_in_substeps(context, &island);
    }
}

/// The island's `iterations` sub-steps, Box2D v3's soft step: each runs the stages of
/// [`SUB_STEP`] in order, over the island's contacts put into waves first (the same numbers,
/// sooner: `super::island`).
fn solve_in_substeps(context: &mut StepContext, island: &Island) {
    let StepContext {
        islands, contacts, ..
    } = context;
    islands.sort_into_waves(&mut contacts.pairs, island);
    for _ in 0..context.stepping.iterations {
        for stage in SUB_STEP {
            execute(stage, context, island);
        }
    }
}

/// Runs one stage of a sub-step on `island`.
fn execute(stage: Stage, context: &mut StepContext, island: &Island) {
    match stage {
        Stage::IntegrateVelocities => integrate_velocities(context, island),
        Stage::WarmStart => contact_solver::warm_start(context, island),
        Stage::Solve => {
            for _ in 0..context.stepping.velocity_passes() {
                contact_solver::solve(context, island);
            }
        }
        Stage::IntegratePositions => integrate_positions(context, island),
        Stage::Relax => contact_solver::relax(context, island, Push::Part),
    }
}

/// The integrate velocities stage: the integrator adds a sub-step's gravity and drag to
/// each of the island's velocities (before the flight, for the integrators that kick first).
fn integrate_velocities(context: &mut StepContext, island: &Island) {
    context.move_each_ball(island, |stepping, body| {
        stepping.integrator.kick_before(body, &stepping.forces);
    });
}

/// The integrate positions stage: each of the island's balls flies a sub-step with its
/// solved velocity (then takes the kick of the integrators that kick after).
fn integrate_positions(context: &mut StepContext, island: &Island) {
    context.move_each_ball(island, |stepping, body| {
        let (integrator, forces) = (stepping.integrator, &stepping.forces);
        integrator.fly(body, forces, forces.dt);
        integrator.kick_after(body, forces);
    });
}

/// A ball that can touch nothing in this step takes it in one go, as in the lesson (a
/// sleeping one does not move).
fn move_untouched(context: &mut StepContext) {
    let StepContext {
        stepping,
        bodies,
        islands,
        ..
    } = context;
    for &k in islands.untouched() {
        stepping.integrator.step(&mut bodies[k], &stepping.whole);
    }
}

/// Puts the solver's `copy` of a ball back into the scene's `ball`, inside the `walls`.
fn copy_back(copy: &Body, ball: &mut Ball, walls: Option<&Walls>, floors: &[Floor]) {
    let from = ball.position();
    let (position, velocity) = (copy.position, copy.velocity);
    (ball.x, ball.y, ball.vx, ball.vy) = (position.x, position.y, velocity.x, velocity.y);
    for floor in floors {
        floor.undo_crossing(ball, from);
    }
    // Last: whatever put it back, the box holds it.
    if let Some(walls) = walls {
        ball.keep_inside(walls);
    }
}
