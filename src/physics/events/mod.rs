//! Exact ball-ball contacts: event-driven dynamics inside each step, the way hard-sphere
//! molecular dynamics does it (Alder & Wainwright; Rapaport's event calendar; Lubachevsky's
//! local clocks; Sedgewick & Wayne's `CollisionSystem` is the teaching version).
//!
//! The lesson's balls never meet, and its clamp resolves a wall only after the ball has
//! crossed it. A scene needs this stage when it has `ball_collisions` and `--collisions
//! exact`: every contact, ball with ball or with a wall or floor, then happens at its moment,
//! so energy is kept to rounding where the scene keeps it (billiards), at the cost of work
//! that grows with the number of collisions rather than of balls.
//!
//! Instead of moving every ball a whole step and then mending overlaps, the step is a sequence
//! of *events* in time order: two balls touch, a ball touches a wall or floor, a ball crosses
//! into another cell of the grid. Each event changes one or two balls, and only their future
//! events are predicted again.
//!
//! - `queue`: the calendar: each ball's next event, filed by the day of the step it falls
//!   on, with only today's events in a small binary heap (a calendar queue).
//! - `lists`: balls in numbered lists (the grid's cells, the calendar's days), O(1) moves.
//! - `cells`: the uniform grid that says which balls can meet soon, and when a ball leaves
//!   its cell.
//! - [`system`]: one step of the whole scene, event after event; the rules that make inelastic
//!   collapse finish; the counts it reports.

mod cells;
mod lists;
mod queue;
pub(crate) mod system;
