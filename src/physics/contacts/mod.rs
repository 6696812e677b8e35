//! Ball-ball collisions in the lesson's stepped (clamp) mode: the broad phase that finds which
//! balls can touch, and the contact solver that lets piles rest.
//!
//! The lesson's balls never meet. Once they do, bouncing each pair on its own is not enough:
//! a ball in a pile touches several others and the floor at once, and they must be solved
//! together or the pile sinks and buzzes. A scene needs this stage when it has
//! `ball_collisions` and the default `--collisions clamp`; without them it is never built.
//!
//! This stage owns the grid, the contact solver and its sleeping islands; the solver is laid
//! out as Box2D v3 lays out its own:
//!
//! - `grid`: a uniform grid rebuilt every step, so finding the pairs that can touch costs
//!   O(N), not O(N²).
//! - `solver` (Box2D's `solver.c`): the step, its stages in order and the sub-step loop:
//!   Box2D's sequential impulses for discs, iterated in sub-steps, island by island.
//! - `step_context` (`b2StepContext`): what every stage of a step is handed.
//! - `contact_solver` (`contact_solver.c`): the stages that sweep over the contacts, named as
//!   Box2D v3 names them: prepare, warm start, solve, relax, restitution, store.
//! - `contact`: the contacts themselves and what one contact does in each stage.
//! - `island` (`island.c`): the balls joined by contacts, each island solved on its own.
//! - `touch_by_touch`: islands without forces, solved at the moment each contact touches.
//! - `warm_start_memory`: each contact's last impulse, kept from step to step by its key in a
//!   hash table, as Box2D keeps its contacts (`table.c`).
//! - `sleep` (`solver_set.c`): islands that have come to rest sleep, and cost nothing, until
//!   an awake ball can touch them.

mod contact;
mod contact_solver;
pub(crate) mod grid;
mod island;
mod sleep;
mod solver;
mod step_context;
mod touch_by_touch;
mod warm_start_memory;

pub use grid::Grid;
pub(crate) use solver::ContactSolver;
