//! Islands, as Box2D v3 keeps them (`island.c`): the balls with a contact this step fall into
//! islands, balls joined by pair contacts directly or through others, found by union–find.
//! Islands share no ball, so each is solved on its own, all its sub-steps at once, while its
//! balls are in the cache (the numbers are the same as one sweep over every contact); and an
//! island is what falls asleep and wakes whole (`super::sleep`).
//!
//! Within an island the contacts that share a ball keep the order they were found in, which
//! is all the numbers depend on: neither the islands' order nor their balls' changes one, nor
//! the order of contacts that share none. Before its sub-steps an island's pair contacts are
//! put into *waves* ([`Islands::sort_into_waves`]), so that the processor can solve side by
//! side what the order found makes it solve one after another.

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
    /// For [`Islands::sort_into_waves`]: the wave after each ball's last contact so far, each
    /// contact's wave, and where each wave starts.
    next_wave: Vec<u32>,
    wave_of: Vec<u32>,
    wave_start: Vec<usize>,
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
        if self.list.len() == 1 {
            // One island (a pile, once it has formed): its balls and contacts are together
            // already, in the order found, and its ranges are their counts from 0.
            self.balls.clone_from(&self.with_contact);
            return;
        }
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

    /// Puts `island`'s pair contacts (of the step's `pairs`) into waves, changing no result
    /// to the bit. A contact's wave is the one after the last wave of an earlier contact that
    /// shares a ball with it, and the waves follow one another.
    ///
    /// Each velocity pass sweeps the contacts in order, and a contact reads the velocities
    /// its ball's last contact has just written. In the order found a ball's contacts come
    /// one after another (the grid lists each ball's neighbours together), so each waits for
    /// the one before. No two contacts of a wave share a ball: the processor solves them
    /// side by side. Contacts that share a ball keep their order, and contacts that share
    /// none do not change each other's numbers, so every pass gives the same numbers as in
    /// the order found (`docs/contacts.md` has the speed-up).
    pub(crate) fn sort_into_waves(&mut self, pairs: &mut [PairContact], island: &Island) {
        self.next_wave.resize(self.island_of.len(), 0);
        for &ball in &self.balls[island.balls.clone()] {
            self.next_wave[ball] = 0;
        }
        let pairs = &mut pairs[island.pairs.clone()];
        self.wave_of.clear();
        self.wave_start.clear();
        for contact in pairs.iter() {
            let wave = self.next_wave[contact.a].max(self.next_wave[contact.b]);
            self.next_wave[contact.a] = wave + 1;
            self.next_wave[contact.b] = wave + 1;
            self.wave_of.push(wave);
            // A new wave is only ever the one after the last (counted in `wave_start`).
            if wave as usize == self.wave_start.len() {
                self.wave_start.push(0);
            }
            self.wave_start[wave as usize] += 1;
        }
        // Turn the counts into where each wave starts, then place the contacts (a counting
        // sort, which keeps the order found within a wave).
        let mut start = 0;
        for slot in &mut self.wave_start {
            (*slot, start) = (start, start + *slot);
        }
        self.spare_pairs.clear();
        self.spare_pairs.extend_from_slice(pairs);
        for (contact, &wave) in self.spare_pairs.iter().zip(&self.wave_of) {
            let slot = &mut self.wave_start[wave as usize];
            pairs[*slot] = *contact;
            *slot += 1;
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::contacts::contact::ContactState;

    /// A contact between balls `a` and `b` (`a < b`), named by `key`.
    fn contact(a: usize, b: usize, key: u64) -> PairContact {
        PairContact {
            a,
            b,
            reach: 2.0,
            state: ContactState::new(Vec2::new(1.0, 0.0), 0.5, 1.0, key),
            inverse_a: 1.0,
            inverse_b: 1.0,
        }
    }

    /// `found` sorted into islands, then the island holding ball `found[0].a` into waves:
    /// the keys of the pair contacts in their new order, and the island's range of them.
    fn waves_of(found: &[PairContact], balls: usize) -> (Vec<u64>, Range<usize>) {
        let mut contacts = Contacts {
            pairs: found.to_vec(),
            ..Contacts::default()
        };
        let mut islands = Islands::default();
        islands.sort(&mut contacts, &[], balls);
        let island = islands.list[0].clone();
        islands.sort_into_waves(&mut contacts.pairs, &island);
        let keys = contacts.pairs.iter().map(|c| c.state.key).collect();
        (keys, island.pairs)
    }

    #[test]
    fn contacts_go_into_waves_in_which_no_two_share_a_ball() {
        // Wave 0: 0–1, 3–4. Wave 1: 0–2 (after 0–1), 4–5 (after 3–4). Wave 2: 1–2 (after
        // 0–2). Wave 3: 2–3 (after 1–2), though 3–4 alone would allow wave 1.
        let found = [
            contact(0, 1, 1),
            contact(0, 2, 2),
            contact(3, 4, 3),
            contact(1, 2, 4),
            contact(2, 3, 5),
            contact(4, 5, 6),
        ];
        let (keys, range) = waves_of(&found, 6);
        assert_eq!(range, 0..6);
        assert_eq!(keys, [1, 3, 2, 6, 4, 5]);
    }

    #[test]
    fn waves_keep_the_order_of_contacts_that_share_a_ball() {
        // Many seeded islands of random contacts among a few balls: the waves hold every
        // contact once, and any two that share a ball stay in the order found.
        let mut seed = 0x2545_f491_4f6c_dd1d_u64;
        let mut next = |below: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % below
        };
        for _ in 0..200 {
            let balls = 2 + next(10) as usize;
            // A chain through every ball keeps them in one island; then random pairs.
            let mut found: Vec<PairContact> = (1..balls).map(|b| contact(b - 1, b, 0)).collect();
            for _ in 0..next(30) {
                let (x, y) = (next(balls as u64) as usize, next(balls as u64) as usize);
                if x != y {
                    found.push(contact(x.min(y), x.max(y), 0));
                }
            }
            for (k, contact) in found.iter_mut().enumerate() {
                contact.state.key = k as u64;
            }
            let (keys, range) = waves_of(&found, balls);
            assert_eq!(range, 0..found.len());
            let mut sorted = keys.clone();
            sorted.sort_unstable();
            assert!(sorted.iter().copied().eq(0..found.len() as u64), "{keys:?}");
            let shares = |x: &PairContact, y: &PairContact| {
                [x.a, x.b].iter().any(|ball| [y.a, y.b].contains(ball))
            };
            for (i, &first) in keys.iter().enumerate() {
                for &later in &keys[i + 1..] {
                    let (first, later) = (&found[first as usize], &found[later as usize]);
                    assert!(
                        !shares(first, later) || first.state.key < later.state.key,
                        "contacts {} and {} share a ball but swapped order in {keys:?}",
                        first.state.key,
                        later.state.key
                    );
                }
            }
        }
    }
}
