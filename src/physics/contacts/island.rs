//! Islands, as Box2D v3 keeps them (`island.c`): the balls with a contact this step fall into
//! islands, balls joined by pair contacts directly or through others, found by union–find.
//! Islands share no ball, so each is solved on its own, all its sub-steps at once, while its
//! balls are in the cache (the numbers are the same as one sweep over every contact); and an
//! island is what falls asleep and wakes whole (`super::sleep`).
//!
//! Within an island the contacts keep the order they were found in, which is all the numbers
//! depend on: neither the islands' order nor their balls' changes one.

use std::ops::Range;

use super::contact::{Contacts, FixedContact, PairContact};
use crate::physics::vec2::Vec2;

/// `island_of` for a ball without contacts.
const NO_ISLAND: usize = usize::MAX;

/// `island_of` for a ball that sleeps (it has no contacts either, and does not move).
const ASLEEP: usize = usize::MAX - 1;

/// A group of balls joined by pair contacts, directly or through others, that touches no
/// ball outside it this step: what happens in one island cannot change another. Its balls
/// are a range of [`Islands::balls`], its contacts ranges of the step's pairs and fixed
/// contacts.
#[derive(Clone, Debug, Default)]
pub(super) struct Island {
    pub balls: Range<usize>,
    pub pairs: Range<usize>,
    pub fixed: Range<usize>,
}

impl Island {
    fn ranges(&mut self) -> [&mut Range<usize>; 3] {
        [&mut self.balls, &mut self.pairs, &mut self.fixed]
    }
}

/// The step's islands, and the buffers that sort balls and contacts into them.
#[derive(Clone, Debug, Default)]
pub(super) struct Islands {
    /// Each island's balls and contacts.
    pub list: Vec<Island>,
    /// The balls (places in the solver's copy) with a contact this step, island by island.
    pub balls: Vec<usize>,
    /// Each ball's island: its place in `list`, or `NO_ISLAND`, or `ASLEEP`.
    island_of: Vec<usize>,
    /// Where an island's balls were (position, velocity) before it was tried touch by
    /// touch, to put them back if it cannot be (`super::touch_by_touch`).
    pub saved: Vec<(Vec2, Vec2)>,
    /// The balls without an island, at the start of the step.
    untouched: Vec<usize>,
    /// For finding the islands: the union–find tree, the balls with a contact in the order
    /// found, and the contacts in the order found.
    parent: Vec<usize>,
    with_contact: Vec<usize>,
    spare_pairs: Vec<PairContact>,
    spare_fixed: Vec<FixedContact>,
}

impl Islands {
    /// Groups the `count` balls with a contact this step into islands (those marked
    /// `asleep` take no part), and lists each island's balls and contacts together, keeping
    /// their order within the island: `contacts` are sorted island by island.
    pub(crate) fn sort(&mut self, contacts: &mut Contacts, asleep: &[bool], count: usize) {
        // Union–find: every ball starts as its own island; each pair contact joins two.
        let parent = &mut self.parent;
        parent.clear();
        parent.extend(0..count);
        for contact in &contacts.pairs {
            let (a, b) = (root(parent, contact.a), root(parent, contact.b));
            parent[a.max(b)] = a.min(b);
        }
        self.number(contacts, asleep, count);
        // Turn the counts into empty ranges where each island's balls and contacts will be,
        // one island after another; placing one extends its island's range (a counting sort).
        let mut starts = [0; 3];
        for island in &mut self.list {
            for (range, start) in island.ranges().into_iter().zip(&mut starts) {
                let count = range.end;
                *range = *start..*start;
                *start += count;
            }
        }
        let (islands, island_of) = (&mut self.list, &self.island_of);
        self.balls.resize(self.with_contact.len(), 0);
        for &ball in &self.with_contact {
            self.balls[claim_next_slot(&mut islands[island_of[ball]].balls)] = ball;
        }
        self.spare_pairs.clone_from(&contacts.pairs);
        for contact in &self.spare_pairs {
            contacts.pairs[claim_next_slot(&mut islands[island_of[contact.a]].pairs)] = *contact;
        }
        self.spare_fixed.clone_from(&contacts.fixed);
        for contact in &self.spare_fixed {
            let slot = claim_next_slot(&mut islands[island_of[contact.ball]].fixed);
            contacts.fixed[slot] = *contact;
        }
    }

    /// Numbers the islands of the union–find tree `parent` in the order their contacts were
    /// found, visiting only the balls with a contact (the rest stay at `NO_ISLAND`, or at
    /// `ASLEEP` for those that sleep), and counts each island's balls and contacts (in the
    /// ends of its ranges).
    ///
    /// Islands share no ball and a ball's own motion does not depend on the others', so
    /// neither the islands' order nor their balls' changes a number: only each island's
    /// contacts must keep the order they were found in.
    fn number(&mut self, contacts: &Contacts, asleep: &[bool], count: usize) {
        let (parent, island_of) = (&mut self.parent, &mut self.island_of);
        island_of.clear();
        if asleep.is_empty() {
            island_of.resize(count, NO_ISLAND);
        } else {
            let mark = |&asleep: &bool| if asleep { ASLEEP } else { NO_ISLAND };
            island_of.extend(asleep.iter().map(mark));
        }
        self.list.clear();
        self.with_contact.clear();
        let with_contact = contacts.pairs.iter().flat_map(|c| [c.a, c.b]);
        for ball in with_contact.chain(contacts.fixed.iter().map(|c| c.ball)) {
            if island_of[ball] != NO_ISLAND {
                continue;
            }
            // The tree's root names the island; the first of its balls seen numbers it.
            let first = root(parent, ball);
            for member in [first, ball] {
                if island_of[member] == NO_ISLAND {
                    island_of[member] = match island_of[first] {
                        NO_ISLAND => {
                            self.list.push(Island::default());
                            self.list.len() - 1
                        }
                        island => island,
                    };
                    self.list[island_of[member]].balls.end += 1;
                    self.with_contact.push(member);
                }
            }
        }
        for contact in &contacts.pairs {
            self.list[island_of[contact.a]].pairs.end += 1;
        }
        for contact in &contacts.fixed {
            self.list[island_of[contact.ball]].fixed.end += 1;
        }
    }

    /// The balls in no island (and awake) this step. They are listed without a branch
    /// (about half the balls of a gas, at random, which a branch would mispredict).
    pub(crate) fn untouched(&mut self) -> &[usize] {
        self.untouched.resize(self.island_of.len(), 0);
        let mut count = 0;
        for (k, &island) in self.island_of.iter().enumerate() {
            self.untouched[count] = k;
            count += usize::from(island == NO_ISLAND);
        }
        &self.untouched[..count]
    }
}

/// The ball that names `ball`'s island in the union–find tree `parent` (the island's first
/// ball), halving the path on the way so later searches are short.
fn root(parent: &mut [usize], mut ball: usize) -> usize {
    while parent[ball] != ball {
        parent[ball] = parent[parent[ball]];
        ball = parent[ball];
    }
    ball
}

/// The next free slot at the end of `range`, which grows to take it in.
fn claim_next_slot(range: &mut Range<usize>) -> usize {
    range.end += 1;
    range.end - 1
}
