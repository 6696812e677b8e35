//! The warm-start memory: the impulse each contact ended the last step with, kept from one
//! step to the next by the contact's key, so that the contact pushes as hard from the first
//! sub-step of the next (`super::contact_solver`'s warm start).
//!
//! Box2D v3 keeps the contacts themselves from step to step and finds them through a hash set
//! of their pairs (`table.c`). Here the contacts are found anew every step and only their
//! impulses are kept, in a hash table of the same kind: open addressing with linear probing,
//! at most half full. Every contact of a step is looked up once and stored once, so each
//! costs a probe or two, where a list sorted by key cost a sort and a binary search.

use super::contact::Contacts;

/// The key of a free slot. No contact has it: a pair's key holds its two balls' indices, the
/// smaller in its low half, and a wall's or floor's key holds its ball's index in its high
/// half; neither can be `u32::MAX`.
const FREE: u64 = u64::MAX;

/// The fewest slots a table that holds anything has.
const FEWEST_SLOTS: usize = 16;

/// The impulses above 0 that the contacts ended the last step with, by contact key.
#[derive(Clone, Debug, Default)]
pub(super) struct WarmStartMemory {
    /// `(key, impulse)`, each at the first slot from its key's hash on that was free when it
    /// came; `FREE` keys mark the free slots, which hold an impulse of 0. A power of two long,
    /// or empty.
    slots: Vec<(u64, f64)>,
    /// The slots in use.
    count: usize,
}

impl WarmStartMemory {
    /// Gives each contact the impulse it ended the last step with (0 if it is new).
    pub(super) fn recall(&self, contacts: &mut Contacts) {
        let states = contacts.pairs.iter_mut().map(|c| &mut c.state);
        for state in states.chain(contacts.fixed.iter_mut().map(|c| &mut c.state)) {
            state.impulse = self.impulse(state.key);
        }
    }

    /// Keeps the contacts' impulses (those above 0) for the next step's warm start, in place
    /// of the last step's.
    pub(super) fn store(&mut self, contacts: &Contacts) {
        let pairs = contacts.pairs.iter().map(|c| &c.state);
        let states = pairs.chain(contacts.fixed.iter().map(|c| &c.state));
        let pushing = states.filter(|state| state.impulse > 0.0);
        self.empty_for(pushing.clone().count());
        for state in pushing {
            self.insert(state.key, state.impulse);
        }
    }

    /// Takes the `kept` impulses (of islands that woke) in beside those remembered, leaving
    /// `kept` empty. (A woken island's contacts were asleep, so none is remembered already.)
    pub(super) fn keep(&mut self, kept: &mut Vec<(u64, f64)>) {
        if kept.is_empty() {
            return; // the common case: nothing woke
        }
        let count = self.count + kept.len();
        if 2 * count > self.slots.len() {
            let remembered = std::mem::take(&mut self.slots);
            self.empty_for(count);
            for (key, impulse) in remembered.into_iter().filter(|&(key, _)| key != FREE) {
                self.insert(key, impulse);
            }
        }
        for (key, impulse) in kept.drain(..) {
            self.insert(key, impulse);
        }
    }

    /// The impulse remembered for the contact `key`, or 0 (which a free slot holds).
    fn impulse(&self, key: u64) -> f64 {
        if self.slots.is_empty() {
            return 0.0;
        }
        self.slots[self.find(key)].1
    }

    /// Remembers `impulse` for `key`, unless `key` is remembered already. There must be a
    /// free slot ([`WarmStartMemory::empty_for`] leaves half of them free).
    fn insert(&mut self, key: u64, impulse: f64) {
        let slot = self.find(key);
        if self.slots[slot].0 == FREE {
            self.slots[slot] = (key, impulse);
            self.count += 1;
        }
    }

    /// The slot that holds `key`, or else the free slot where it would go: the first of
    /// either from its home slot on.
    fn find(&self, key: u64) -> usize {
        let mut slot = self.home(key);
        while ![key, FREE].contains(&self.slots[slot].0) {
            slot = (slot + 1) & (self.slots.len() - 1);
        }
        slot
    }

    /// Forgets every impulse, and makes room for `count` of them with at least half the
    /// slots left free, so that a probe soon finds a free one.
    fn empty_for(&mut self, count: usize) {
        let slots = if count == 0 {
            0
        } else {
            (2 * count).next_power_of_two().max(FEWEST_SLOTS)
        };
        self.slots.clear();
        self.slots.resize(slots, (FREE, 0.0));
        self.count = 0;
    }

    /// The slot where the search for `key` starts: Fibonacci hashing, the key times 2⁶⁴ over
    /// the golden ratio, whose top bits mix every bit of both its halves.
    fn home(&self, key: u64) -> usize {
        let bits = self.slots.len().trailing_zeros();
        (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> (64 - bits)) as usize
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::contacts::contact::{ContactState, FixedContact};
    use crate::physics::vec2::Vec2;

    /// A wall contact named `key` that ended its step with `impulse`.
    fn fixed(key: u64, impulse: f64) -> FixedContact {
        let mut state = ContactState::new(Vec2::new(0.0, 1.0), 0.5, 1.0, key);
        state.impulse = impulse;
        FixedContact {
            ball: 0,
            offset: 0.0,
            state,
        }
    }

    /// Asserts that `memory` keeps half its slots free, and that no lookup walks far past
    /// its key's home slot (the hash spreads the keys).
    fn assert_at_most_half_full_with_short_probes(memory: &WarmStartMemory) {
        let slots = memory.slots.len();
        assert!(
            2 * memory.count <= slots,
            "{} impulses in {slots} slots: more than half full",
            memory.count
        );
        let walked = |(slot, &(key, _)): (usize, &(u64, f64))| {
            (key != FREE).then(|| slot.wrapping_sub(memory.home(key)) & (slots - 1))
        };
        let longest = memory.slots.iter().enumerate().filter_map(walked).max();
        assert!(
            longest.unwrap_or(0) <= 8,
            "a lookup walks {longest:?} slots past its home: expected at most 8"
        );
    }

    #[test]
    fn a_contact_recalls_the_impulse_it_stored_and_a_new_one_recalls_none() {
        // Keys as contacts have them, many sharing a half, so they crowd the same slots.
        let keys: Vec<u64> = (0..300_u64).map(|k| ((k % 17) << 32) | (k / 17)).collect();
        let mut contacts = Contacts {
            fixed: keys.iter().map(|&k| fixed(k, k as f64 + 0.5)).collect(),
            ..Contacts::default()
        };
        contacts.fixed.push(fixed((7 << 32) | 99, 0.0)); // pushing with nothing: not kept
        let mut memory = WarmStartMemory::default();
        memory.store(&contacts);
        assert_eq!(memory.count, keys.len());
        assert_at_most_half_full_with_short_probes(&memory);
        contacts.fixed.push(fixed(1 << 40, 3.0)); // new this step
        for contact in &mut contacts.fixed {
            contact.state.impulse = -1.0;
        }
        memory.recall(&mut contacts);
        let recalled: Vec<f64> = contacts.fixed.iter().map(|c| c.state.impulse).collect();
        let stored = keys.iter().map(|&k| k as f64 + 0.5);
        let expected: Vec<f64> = stored.chain([0.0, 0.0]).collect();
        assert_eq!(recalled, expected);
    }

    #[test]
    fn kept_impulses_join_those_stored_and_the_stored_one_wins_a_shared_key() {
        let mut memory = WarmStartMemory::default();
        let stored: Vec<FixedContact> = (0..20).map(|k| fixed(k, 1.0)).collect();
        memory.store(&Contacts {
            fixed: stored,
            ..Contacts::default()
        });
        let mut kept: Vec<(u64, f64)> = (15..60).map(|k| (k, 2.0)).collect();
        memory.keep(&mut kept);
        assert!(kept.is_empty());
        assert_eq!(memory.count, 60);
        assert_at_most_half_full_with_short_probes(&memory);
        let impulses: Vec<f64> = (0..61).map(|k| memory.impulse(k)).collect();
        let expected: Vec<f64> = (0..61)
            .map(|k| match k {
                0..20 => 1.0,
                20..60 => 2.0,
                _ => 0.0,
            })
            .collect();
        assert_eq!(impulses, expected);
        memory.store(&Contacts::default());
        assert_eq!((memory.count, memory.impulse(3)), (0, 0.0));
    }

    #[test]
    fn the_table_grows_only_when_more_than_half_of_it_would_be_full() {
        let mut memory = WarmStartMemory::default();
        memory.store(&Contacts {
            fixed: (0..20).map(|k| fixed(k, 1.0)).collect(),
            ..Contacts::default()
        });
        assert_eq!(memory.slots.len(), 64);
        // 32 impulses in 64 slots: half full, as the table may be.
        memory.keep(&mut (20..32).map(|k| (k, 2.0)).collect());
        assert_eq!((memory.count, memory.slots.len()), (32, 64));
        // One more: it grows.
        memory.keep(&mut vec![(32, 2.0)]);
        assert_eq!((memory.count, memory.slots.len()), (33, 128));
        assert_at_most_half_full_with_short_probes(&memory);
        assert_eq!(
            (memory.impulse(0), memory.impulse(31), memory.impulse(32)),
            (1.0, 2.0, 2.0)
        );
    }

    #[test]
    fn keys_that_share_a_home_slot_each_find_their_own_even_past_the_tables_end() {
        // Five keys whose search starts at the last slot of 16: they fill it, then wrap round
        // to the first slots.
        let mut memory = WarmStartMemory::default();
        memory.empty_for(5);
        assert_eq!(memory.slots.len(), 16);
        let last = memory.slots.len() - 1;
        let crowded: Vec<u64> = (0..).filter(|&k| memory.home(k) == last).take(6).collect();
        let stored = &crowded[..5];
        for (n, &key) in stored.iter().enumerate() {
            memory.insert(key, n as f64 + 1.0);
        }
        let slots: Vec<u64> = [last, 0, 1, 2, 3].map(|slot| memory.slots[slot].0).into();
        assert_eq!(slots, stored);
        let recalled: Vec<f64> = crowded.iter().map(|&key| memory.impulse(key)).collect();
        assert_eq!(recalled, [1.0, 2.0, 3.0, 4.0, 5.0, 0.0]);
        memory.insert(stored[2], 9.0); // remembered already: kept as it was
        assert_eq!((memory.count, memory.impulse(stored[2])), (5, 3.0));
        assert_at_most_half_full_with_short_probes(&memory);
    }
}
