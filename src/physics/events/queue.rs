//! The event calendar: predicted events in a binary heap, earliest first.
//!
//! When a ball changes course every event predicted for it is wrong. Finding and removing
//! them would cost a search; instead each ball has a counter that goes up whenever it changes
//! course, every event remembers the counters of its balls when it was predicted, and an event
//! whose counters no longer match is *stale* and is dropped when it comes up. Pushing and
//! popping are O(log N).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

/// What happens to ball `ball` at an event.
#[derive(Clone, Copy, Debug)]
pub enum What {
    /// It touches ball number `.0`.
    Ball(u32),
    /// It touches a wall, a floor's face or a floor's end (which one the caller keeps: only
    /// the latest prediction per ball is ever current, and a small event moves fast in the heap).
    Contact,
    /// It leaves its grid cell, along `axis` (0 = x, 1 = y), towards `+1` or `−1`.
    Cell { axis: u8, towards: i8 },
}

/// One predicted event.
#[derive(Clone, Copy, Debug)]
pub struct Event {
    /// When, in frames since the start of the step.
    pub time: f64,
    pub ball: u32,
    pub what: What,
    /// The counters of `ball` and of the other ball (if any) when this was predicted.
    counts: [u32; 2],
}

impl PartialEq for Event {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Event {}

impl PartialOrd for Event {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Event {
    /// Reversed, so that `BinaryHeap` (a max-heap) pops the earliest event. Ties come out in
    /// an order fixed by the sequence of pushes and pops, the same on every run.
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .time
            .total_cmp(&self.time)
            .then(other.ball.cmp(&self.ball))
    }
}

/// The predicted events of one step.
#[derive(Clone, Debug, Default)]
pub struct Queue {
    heap: BinaryHeap<Event>,
    /// Per ball: how often it has changed course this step.
    counts: Vec<u32>,
}

impl Queue {
    /// Empties the calendar for a step of `balls` balls, keeping the allocations.
    pub fn reset(&mut self, balls: usize) {
        self.heap.clear();
        self.counts.clear();
        self.counts.resize(balls, 0);
    }

    /// Adds an event at `time` for `ball`.
    pub fn push(&mut self, time: f64, ball: usize, what: What) {
        let partner = match what {
            What::Ball(other) => self.counts[other as usize],
            _ => 0,
        };
        self.heap.push(Event {
            time,
            ball: ball as u32,
            what,
            counts: [self.counts[ball], partner],
        });
    }

    /// Marks every event predicted so far for `ball` as stale: it changed course.
    pub fn changed(&mut self, ball: usize) {
        self.counts[ball] = self.counts[ball].wrapping_add(1);
    }

    /// Whether `event` was predicted before one of its balls changed course.
    fn stale(&self, event: &Event) -> bool {
        let partner = match event.what {
            What::Ball(other) => self.counts[other as usize],
            _ => 0,
        };
        event.counts != [self.counts[event.ball as usize], partner]
    }

    /// The earliest event that is not stale, if it comes no later than `end`.
    pub fn pop_until(&mut self, end: f64) -> Option<Event> {
        while let Some(event) = self.heap.peek() {
            if self.stale(event) {
                self.heap.pop();
            } else if event.time <= end {
                return self.heap.pop();
            } else {
                return None;
            }
        }
        None
    }

    /// Carries the events still to come over to the next step, which starts `dt` frames
    /// later: their times move back by `dt`, and stale events are dropped on the way.
    pub fn carry_over(&mut self, dt: f64) {
        let mut events = std::mem::take(&mut self.heap).into_vec();
        events.retain(|event| !self.stale(event));
        for event in &mut events {
            event.time -= dt;
        }
        self.heap = BinaryHeap::from(events);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_come_out_earliest_first_and_stale_ones_are_dropped() {
        let mut queue = Queue::default();
        queue.reset(3);
        queue.push(0.5, 0, What::Ball(1));
        queue.push(
            0.25,
            2,
            What::Cell {
                axis: 0,
                towards: 1,
            },
        );
        queue.push(
            0.75,
            2,
            What::Cell {
                axis: 1,
                towards: -1,
            },
        );
        queue.changed(1); // ball 1 changed course: the event at 0.5 is stale
        let times: Vec<f64> = std::iter::from_fn(|| queue.pop_until(1.0))
            .map(|e| e.time)
            .collect();
        assert_eq!(
            times,
            vec![0.25, 0.75],
            "expected 0.25 then 0.75, got {times:?}"
        );
    }

    #[test]
    fn events_carried_into_the_next_step_move_back_by_its_length_without_the_stale_ones() {
        let mut queue = Queue::default();
        queue.reset(2);
        queue.push(1.5, 0, What::Contact);
        queue.push(1.25, 1, What::Contact);
        queue.changed(1);
        assert!(
            queue.pop_until(1.0).is_none(),
            "nothing is due within the step"
        );
        queue.carry_over(1.0);
        assert_eq!(queue.heap.len(), 1, "the stale event is dropped");
        let next = queue.pop_until(1.0).map(|e| e.time);
        assert_eq!(
            next,
            Some(0.5),
            "expected the event at 1.5 to come at 0.5, got {next:?}"
        );
    }
}
