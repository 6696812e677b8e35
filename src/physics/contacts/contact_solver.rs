//! The per-contact stages of a step, as Box2D v3's `contact_solver.c` has them, each a
//! function of that name taking the step's [`StepContext`]:
//!
//! - **Prepare** ([`prepare`]): find the contacts where the balls are: pairs, walls and floors
//!   that can touch within the step (the grid grows each ball by the distance it can travel).
//!   A contact with a gap is *speculative*: it only forbids closing by more than the gap. The
//!   solver works on a copy of the balls in the grid's order. Each contact gets the impulse it
//!   ended the last step with, from the warm-start memory (`super::warm_start_memory`), and the
//!   balls with contacts fall into islands (`super::island`).
//! - **Warm start** ([`warm_start`]; under gravity only): each contact pushes again with its
//!   total impulse of the sub-step before (the previous step's, at first). A stack that stood
//!   then stands now, instead of its weight having to travel up through it again, one ball per
//!   pass. A bounce is not carried: it is over once the balls part.
//! - **Solve** ([`solve`]), the velocity pass (Gauss–Seidel): contact after contact, the
//!   impulse that brings its relative normal speed to its target, added to its running total,
//!   which is never negative (contacts push, never pull). A contact that touches within the
//!   sub-step `h` bounces if `e` times its approach speed now beats the rest speed: that is
//!   its target. Slower, it stops (resting balls do not bounce, so a pile settles instead of
//!   buzzing). Box2D v3 leaves bounces to its restitution stage, from the approach speed the
//!   contact was prepared with; here a contact bounces at its approach speed of the moment, so
//!   a struck ball passes the blow on within the step.
//! - **Relax** ([`relax`]), the position pass: overlap beyond a small slop is partly pushed
//!   out, moving positions only, so no kinetic energy is added. (Box2D v3's solve pushes
//!   overlap out with extra velocity, which its relax takes away again; here the solve adds
//!   none, and the push is done here, on positions, as in Box2D v2.4.)
//! - **Restitution** ([`restitution`]): the bounces left after the sub-steps. Every listed
//!   contact has bounced in its solve; what is left is a pair the step did not list (a ball
//!   struck within the step, running into a neighbour it was not heading for), which is set
//!   apart to touching and bounces now.
//! - **Store** ([`store`]): each contact's impulse goes into the warm-start memory for the
//!   next step.
//!
//! Warm start, solve and relax work on one island's contacts; the others on the whole step's.

use super::contact::{
    both_mut, coincident_normal, deeper_than_slop, pair_gap, Body, ContactState, FixedContact, Gap,
    PairContact, Push,
};
use super::island::Island;
use super::sleep::Sleep;
use super::step_context::{StepContext, Stepping};
use super::warm_start_memory::WarmStartMemory;
use crate::physics::ball::{mass, Ball};
use crate::physics::effects::Effects;
use crate::physics::tolerances::{MAX_PAIRS_PER_BALL, PAIR_MARGIN};
use crate::physics::vec2::Vec2;
use crate::work::{tally, Work};

/// What decides, as contacts are found, whether one can touch within the step.
#[derive(Clone, Copy, Debug)]
struct Lookahead {
    /// Length of the step, frames.
    dt: f64,
    /// How far gravity alone can move a ball in the step, px.
    fall: f64,
}

impl Lookahead {
    fn new(stepping: &Stepping) -> Lookahead {
        let dt = stepping.dt;
        let fall = stepping.gravity * dt * dt;
        Lookahead { dt, fall }
    }

    /// How far `ball` can get in this step, and a little more, so that it stops at a surface
    /// instead of passing into it, and a resting pair is found again next step.
    fn margin(self, ball: &Ball) -> f64 {
        ball.velocity().length_squared().sqrt() * self.dt + self.fall + PAIR_MARGIN * ball.radius
    }

    /// Whether a contact at `separation` closing at `approach` (negative: closing) can touch
    /// within the step, with `slack` to spare.
    fn can_touch(self, separation: f64, approach: f64, slack: f64) -> bool {
        separation + approach.min(0.0) * self.dt - self.fall < slack
    }

    /// Whether balls `a` and `b`, `gap` apart, can touch within the step.
    fn pair_can_touch(self, a: &Body, b: &Body, gap: Gap) -> bool {
        let approach = (b.velocity - a.velocity).dot(gap.normal);
        // Both balls fall alike, but a ball pushed from above can close the gap by as much
        // as gravity moves it.
        let slack = PAIR_MARGIN * (a.radius + b.radius) / 2.0;
        self.can_touch(gap.separation, approach, slack)
    }
}

/// The prepare stage: finds the step's contacts among `balls` under `effects`, gives each the
/// impulse it ended the last step with (from `memory`), and sorts them into islands.
/// Sleeping balls take no part, but an island an awake ball can touch wakes first.
pub(super) fn prepare(
    context: &mut StepContext,
    balls: &[Ball],
    effects: &Effects,
    sleep: &mut Sleep,
    memory: &mut WarmStartMemory,
) {
    find_contacts(context, balls, effects, sleep);
    memory.keep(sleep.woken());
    memory.recall(&mut context.contacts);
    let StepContext {
        contacts,
        islands,
        asleep,
        ..
    } = context;
    islands.sort(contacts, asleep, balls.len());
}

/// This step's contacts, each only if it can touch within the step: each awake ball's walls
/// and floors, as the balls are copied into the grid's order; then the ball pairs from the
/// grid, in its order. First the grid's pairs wake each sleeping island an awake ball can
/// touch.
fn find_contacts(context: &mut StepContext, balls: &[Ball], effects: &Effects, sleep: &mut Sleep) {
    let lookahead = Lookahead::new(&context.stepping);
    let (grid, contacts) = (&mut context.grid, &mut context.contacts);
    grid.rebuild_with_margins(balls, |ball| lookahead.margin(ball));
    let limit = MAX_PAIRS_PER_BALL.saturating_mul(balls.len());
    grid.overlapping_places(&mut contacts.places, limit);
    if sleep.anyone_asleep() {
        wake_touched(grid.order(), &contacts.places, balls, lookahead, sleep);
    }
    copy_and_find_fixed(context, balls, effects, lookahead, sleep);
    find_pairs(context, lookahead);
}

/// Wakes each sleeping island that an awake ball can touch within the step, and then those
/// its balls can touch, until none is left to wake. `places` are the grid's pairs, `order`
/// its order.
fn wake_touched(
    order: &[usize],
    places: &[[u32; 2]],
    balls: &[Ball],
    lookahead: Lookahead,
    sleep: &mut Sleep,
) {
    let mut woke = true;
    while woke {
        woke = false;
        for &[a, b] in places {
            let (i, j) = (order[a as usize], order[b as usize]);
            if sleep.is_asleep(i) == sleep.is_asleep(j) {
                continue;
            }
            let (ball_a, ball_b) = (Body::of(&balls[i]), Body::of(&balls[j]));
            let gap = pair_gap(&ball_a, &ball_b, ball_a.radius + ball_b.radius, || {
                coincident_normal(i.max(j))
            });
            if lookahead.pair_can_touch(&ball_a, &ball_b, gap) {
                woke |= sleep.wake(i) | sleep.wake(j);
            }
        }
    }
}

/// Copies each ball into the bodies in the grid's order, and finds its walls and floors, in
/// one pass. A sleeping ball is copied but has no contact; while any ball sleeps, `asleep`
/// marks each (it is left empty otherwise: a scene where none sleeps pays nothing for it).
fn copy_and_find_fixed(
    context: &mut StepContext,
    balls: &[Ball],
    effects: &Effects,
    lookahead: Lookahead,
    sleep: &Sleep,
) {
    let StepContext {
        grid,
        bodies,
        asleep,
        contacts,
        ..
    } = context;
    bodies.clear();
    contacts.fixed.clear();
    asleep.clear();
    let sleepers = sleep.anyone_asleep();
    for (k, &i) in grid.order().iter().enumerate() {
        let ball = &Body::of(&balls[i]);
        bodies.push(*ball);
        if sleepers {
            asleep.push(sleep.is_asleep(i));
            if sleep.is_asleep(i) {
                continue;
            }
        }
        find_fixed(&mut contacts.fixed, ball, [k, i], effects, lookahead);
    }
}

/// Adds to `fixed` the walls and floors of `effects` that `ball` (body `k`, the scene's ball
/// `i`) can touch within the step.
fn find_fixed(
    fixed: &mut Vec<FixedContact>,
    ball: &Body,
    [k, i]: [usize; 2],
    effects: &Effects,
    lookahead: Lookahead,
) {
    let centre = ball.position;
    let mut touch = |id: u64, normal: Vec2, surface: f64, restitution: f64| {
        let offset = surface + ball.radius;
        let separation = centre.dot(normal) - offset;
        let approach = ball.velocity.dot(normal);
        if lookahead.can_touch(separation, approach, PAIR_MARGIN * ball.radius) {
            let key = (i as u64) << 32 | (u64::from(u32::MAX) - id);
            let state = ContactState::new(normal, restitution, mass(ball.radius), key);
            fixed.push(FixedContact {
                ball: k,
                offset,
                state,
            });
        }
    };
    if let Some(walls) = &effects.walls {
        tally(Work::Walls);
        // Each wall as a line: its inward normal, and `normal · point` on it.
        let sides = [
            (Vec2::new(1.0, 0.0), 0.0),
            (Vec2::new(-1.0, 0.0), -walls.width),
            (Vec2::new(0.0, 1.0), 0.0),
            (Vec2::new(0.0, -1.0), -walls.height),
        ];
        for (id, (normal, surface)) in sides.into_iter().enumerate() {
            touch(id as u64, normal, surface, walls.damping);
        }
    }
    // The walls are surfaces 0 to 3; the floors follow.
    for (n, floor) in effects.floors.iter().enumerate() {
        tally(Work::Floor);
        let (normal, distance) = floor.nearest(centre);
        touch(
            4 + n as u64,
            normal,
            centre.dot(normal) - distance,
            floor.damping,
        );
    }
}

/// The ball pairs the grid finds that can touch within the step, in its order, with the
/// step's restitution; the others are kept aside as `unlisted`.
fn find_pairs(context: &mut StepContext, lookahead: Lookahead) {
    let StepContext {
        restitution,
        grid,
        bodies,
        asleep,
        contacts,
        ..
    } = context;
    let order = grid.order();
    // The grid names each pair by the balls' places in its order, which are their places
    // in `bodies`: `a < b`, close together in memory, no lookup needed.
    contacts.pairs.clear();
    contacts.unlisted.clear();
    let sleepers = !asleep.is_empty();
    for &[a, b] in &contacts.places {
        let (a, b) = (a as usize, b as usize);
        if sleepers && asleep[a] && asleep[b] {
            continue; // two sleeping balls: neither moves
        }
        let (ball_a, ball_b) = (&bodies[a], &bodies[b]);
        let gap = gap_between(bodies, order, a, b);
        // (A sleeping ball and an awake one that can touch woke in `wake_touched`.)
        if lookahead.pair_can_touch(ball_a, ball_b, gap) {
            let contact = pair_contact(bodies, order, *restitution, a, b, gap);
            contacts.pairs.push(contact);
        } else {
            contacts.unlisted.push([a as u32, b as u32]);
        }
    }
}

/// The gap between balls `a` and `b` (places in `balls`, the grid's order; `order` gives
/// their scene indices) and the normal from `a` to `b`.
fn gap_between(balls: &[Body], order: &[usize], a: usize, b: usize) -> Gap {
    let (ball_a, ball_b) = (&balls[a], &balls[b]);
    // The scene's index of the later ball names the normal of balls at one spot.
    let coincident = || coincident_normal(order[a].max(order[b]));
    pair_gap(ball_a, ball_b, ball_a.radius + ball_b.radius, coincident)
}

/// The contact between balls `a` and `b` (as in [`gap_between`]) with `restitution`, `gap`
/// apart.
fn pair_contact(
    balls: &[Body],
    order: &[usize],
    restitution: f64,
    a: usize,
    b: usize,
    gap: Gap,
) -> PairContact {
    let (ball_a, ball_b) = (&balls[a], &balls[b]);
    // The key names the pair by its scene indices, which do not change.
    let (i, j) = (order[a].min(order[b]), order[a].max(order[b]));
    let key = (j as u64) << 32 | i as u64;
    let (mass_a, mass_b) = (mass(ball_a.radius), mass(ball_b.radius));
    let mass = mass_a * mass_b / (mass_a + mass_b);
    PairContact {
        a,
        b,
        reach: ball_a.radius + ball_b.radius,
        state: ContactState::new(gap.normal, restitution, mass, key),
        inverse_a: 1.0 / mass_a,
        inverse_b: 1.0 / mass_b,
    }
}

/// The warm start stage of `island`: applies each contact's impulse of the last sub-step
/// again, and measures its gap anew.
pub(super) fn warm_start(context: &mut StepContext, island: &Island) {
    let h = context.stepping.sub.h;
    let (bodies, contacts) = (&mut context.bodies, &mut context.contacts);
    for contact in &mut contacts.pairs[island.pairs.clone()] {
        let (a, b) = both_mut(bodies, contact.a, contact.b);
        let gap = pair_gap(a, b, contact.reach, || contact.state.normal);
        contact.state.normal = gap.normal;
        contact.state.measure(gap.separation, h);
        contact.push_velocities(a, b, contact.state.impulse);
    }
    for contact in &mut contacts.fixed[island.fixed.clone()] {
        let ball = &mut bodies[contact.ball];
        contact.state.measure(contact.gap(ball), h);
        let impulse = contact.state.impulse / contact.state.mass;
        ball.velocity += impulse * contact.state.normal;
    }
}

/// The solve stage of `island`, the velocity pass: one Gauss–Seidel sweep over every
/// contact's velocity.
pub(super) fn solve(context: &mut StepContext, island: &Island) {
    let sub = context.stepping.sub;
    let (bodies, contacts) = (&mut context.bodies, &mut context.contacts);
    for contact in &mut contacts.pairs[island.pairs.clone()] {
        let (a, b) = both_mut(bodies, contact.a, contact.b);
        contact.solve_velocity(a, b, sub);
    }
    for contact in &mut contacts.fixed[island.fixed.clone()] {
        contact.solve_velocity(&mut bodies[contact.ball], sub);
    }
}

/// The relax stage of `island`, the position pass: one Gauss–Seidel pass that pushes
/// contacts overlapping beyond the slop apart by `push`, positions only.
pub(super) fn relax(context: &mut StepContext, island: &Island, push: Push) {
    let (bodies, contacts) = (&mut context.bodies, &context.contacts);
    for contact in &contacts.pairs[island.pairs.clone()] {
        let (a, b) = both_mut(bodies, contact.a, contact.b);
        contact.relax(a, b, push);
    }
    for contact in &contacts.fixed[island.fixed.clone()] {
        contact.relax(&mut bodies[contact.ball], push);
    }
}

/// The restitution stage: the bounces left after the sub-steps. A ball struck within the step
/// leaves in a new direction and can run into a neighbour it was not heading for when the
/// contacts were found: that pair is not among them. Each such pair that ends the step
/// overlapping beyond the slop is set apart to touching (positions only) and bounces now, by
/// the same rule as any contact, so that no overlap outlives the step. Momentum is kept and
/// kinetic energy does not rise. `moved` hears of each ball it moves, with its scene index.
pub(super) fn restitution(context: &mut StepContext, mut moved: impl FnMut(&Body, usize)) {
    let StepContext {
        stepping,
        restitution,
        grid,
        bodies,
        contacts,
        ..
    } = context;
    let order = grid.order();
    for &[a, b] in &contacts.unlisted {
        let (a, b) = (a as usize, b as usize);
        let (ball_a, ball_b) = (&bodies[a], &bodies[b]);
        if !deeper_than_slop(ball_a, ball_b, ball_a.radius + ball_b.radius) {
            continue; // the common case, without a square root
        }
        let gap = gap_between(bodies, order, a, b);
        let mut contact = pair_contact(bodies, order, *restitution, a, b, gap);
        let (ball_a, ball_b) = both_mut(bodies, a, b);
        contact.relax(ball_a, ball_b, Push::Whole);
        contact.state.measure(0.0, stepping.sub.h);
        contact.solve_velocity(ball_a, ball_b, stepping.sub);
        moved(ball_a, order[a]);
        moved(ball_b, order[b]);
    }
}

/// The store stage: each contact's impulse into the warm-start `memory`, for the next step,
/// and the kept impulses of islands the restitution woke.
pub(super) fn store(context: &StepContext, memory: &mut WarmStartMemory, sleep: &mut Sleep) {
    memory.store(&context.contacts);
    memory.keep(sleep.woken());
}
