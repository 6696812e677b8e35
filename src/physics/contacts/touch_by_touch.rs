//! Islands solved touch by touch. Without gravity or drag, balls fly straight between
//! contacts, so when each contact touches has a closed form: the island flies to the time its
//! first contact touches, that contact alone is solved there, and so on to the end of the step,
//! instead of every contact once per sub-step. Balls that start the step overlapping are first
//! set apart to touching. An island that still overlaps, or keeps colliding, is put back as it
//! was and takes the sub-steps (`super::solver`).

use super::contact::{both_mut, pair_gap, Push, SubStep};
use super::contact_solver::relax;
use super::island::Island;
use super::step_context::StepContext;
use crate::physics::tolerances::TOUCHES_PER_CONTACT;

/// Solves `island` touch by touch, if it can; the caller checks that no force acts.
///
/// Balls that start the step overlapping beyond the slop are first set apart, to touching
/// (positions only): in a gas that is nearly always a pair the last step did not list
/// because it was not closing, whose balls then met after one of them was struck. Returns
/// `false`, with the balls as they were, when a contact still overlaps after that (a ball
/// pushed into a third: the sub-steps' gentler position passes sort that out) or the
/// island has more than [`TOUCHES_PER_CONTACT`] touches per contact (a cluster that keeps
/// colliding): those take the sub-steps.
pub(super) fn solve_touch_by_touch(context: &mut StepContext, island: &Island) -> bool {
    save(context, island);
    // Positions only, so no kinetic energy is added; an approaching pair then touches now.
    relax(context, island, Push::Whole);
    let mut left = context.stepping.whole.dt;
    for _ in 0..TOUCHES_PER_CONTACT * (island.pairs.len() + island.fixed.len()) {
        let Some((first, touch)) = first_touch(context, island) else {
            break;
        };
        if touch >= left {
            fly(context, island, left);
            return true;
        }
        fly(context, island, touch);
        left -= touch;
        // The rest of the step after the touch is the sub-step the contact is solved for.
        let sub = SubStep {
            h: left,
            ..context.stepping.sub
        };
        solve_touch(context, island, first, sub);
    }
    restore(context, island);
    false
}

/// Keeps where the island's balls are (position, velocity), for [`restore`].
fn save(context: &mut StepContext, island: &Island) {
    let StepContext {
        bodies, islands, ..
    } = context;
    islands.saved.clear();
    islands.saved.extend(
        islands.balls[island.balls.clone()]
            .iter()
            .map(|&i| (bodies[i].position, bodies[i].velocity)),
    );
}

/// Puts the island's balls back where [`save`] found them.
fn restore(context: &mut StepContext, island: &Island) {
    let StepContext {
        bodies, islands, ..
    } = context;
    let active = &islands.balls[island.balls.clone()];
    for (&i, &(position, velocity)) in active.iter().zip(islands.saved.iter()) {
        (bodies[i].position, bodies[i].velocity) = (position, velocity);
    }
}

/// Flies each of the island's balls straight on for `time` frames.
fn fly(context: &mut StepContext, island: &Island, time: f64) {
    context.move_each_ball(island, |stepping, body| {
        stepping.integrator.fly(body, &stepping.whole, time);
    });
}

/// Solves contact `first` of `island` (of its pairs then its fixed contacts, numbered in that
/// order), which touches now, for the sub-step `sub`.
fn solve_touch(context: &mut StepContext, island: &Island, first: usize, sub: SubStep) {
    let (bodies, contacts) = (&mut context.bodies, &mut context.contacts);
    let pairs = &mut contacts.pairs[island.pairs.clone()];
    // They touch now: a rounding error's gap must not spare them the bounce.
    if first < pairs.len() {
        let contact = &mut pairs[first];
        let (a, b) = both_mut(bodies, contact.a, contact.b);
        let gap = pair_gap(a, b, contact.reach, || contact.state.normal);
        contact.state.normal = gap.normal;
        contact.state.measure(gap.separation.min(0.0), sub.h);
        contact.solve_velocity(a, b, sub);
    } else {
        let contact = &mut contacts.fixed[island.fixed.clone()][first - pairs.len()];
        let ball = &mut bodies[contact.ball];
        contact.state.measure(contact.gap(ball).min(0.0), sub.h);
        contact.solve_velocity(ball, sub);
    }
}

/// The contact of `island` (its pairs then its fixed contacts, numbered in that order) that
/// touches first, and when; `None` if one overlaps beyond the slop.
fn first_touch(context: &StepContext, island: &Island) -> Option<(usize, f64)> {
    let (bodies, contacts) = (&context.bodies, &context.contacts);
    let pairs = contacts.pairs[island.pairs.clone()].iter();
    let fixed = contacts.fixed[island.fixed.clone()].iter();
    let touches = pairs.map(|contact| contact.touch_time(bodies));
    let touches = touches.chain(fixed.map(|contact| contact.touch_time(&bodies[contact.ball])));
    let mut first = (0, f64::INFINITY);
    for (k, touch) in touches.enumerate() {
        let touch = touch?;
        if touch < first.1 {
            first = (k, touch);
        }
    }
    Some(first)
}
