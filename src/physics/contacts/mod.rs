//! Ball-ball collisions in the lesson's stepped (clamp) mode: the broad phase that finds which
//! balls can touch, and the contact solver that lets piles rest.
//!
//! The lesson's balls never meet. Once they do, bouncing each pair on its own is not enough:
//! a ball in a pile touches several others and the floor at once, and they must be solved
//! together or the pile sinks and buzzes. A scene needs this stage when it has
//! `ball_collisions` and the default `--collisions clamp`; without them it is never built.
//!
//! - [`grid`]: a uniform grid rebuilt every step, so finding the pairs that can touch costs
//!   O(N), not O(N²).
//! - [`solver`]: Box2D's sequential impulses for discs, iterated in sub-steps, island by
//!   island. Its own doc lists the stages, named as Box2D v3 names them: prepare, warm start,
//!   solve, relax, restitution, store.
//! - [`sleep`]: islands that have come to rest sleep, and cost nothing, until an awake ball
//!   can touch them.

pub mod grid;
pub mod sleep;
pub mod solver;

pub use grid::Grid;
pub use solver::ContactSolver;
