//! The event calendar: each ball's next event, earliest first.
//!
//! Each ball keeps only its earliest predicted event (Lubachevsky; DynamO keeps one entry per
//! particle in its global queue too), and the calendar is a binary heap of the balls ordered by
//! that event's time, with each ball's place in the heap remembered, so a new prediction moves
//! its ball up or down in O(log N) and the heap never holds more than N entries, none stale.
//!
//! A ball's own event is replaced whenever it is predicted again. An event with a partner can
//! still go out of date when the *partner* changes course: each ball has a counter that goes
//! up whenever it does, the event remembers the partner's counter, and when such an event
//! comes up with the counter moved on, its ball is predicted again instead (nothing before it
//! can have been missed: any change since was made by balls that predicted their own events).

/// What happens to a ball at its event.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum What {
    /// Nothing predicted: the event's time is infinite.
    Nothing,
    /// It touches ball number `.0`.
    Ball(u32),
    /// It touches a wall, a floor's face or a floor's end (which one the caller keeps).
    Contact,
    /// It leaves its grid cell, along `axis` (0 = x, 1 = y), towards `+1` or `−1`.
    Cell { axis: u8, towards: i8 },
}

/// One ball's next event.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Event {
    /// When, in frames since the start of the step.
    pub time: f64,
    pub what: What,
    /// The partner's counter when this was predicted (0 without a partner).
    partner_count: u32,
}

/// No event: nothing predicted.
pub const NOTHING: Event = Event {
    time: f64::INFINITY,
    what: What::Nothing,
    partner_count: 0,
};

/// The balls' next events.
#[derive(Clone, Debug, Default)]
pub struct Queue {
    next: Vec<Event>,
    /// The balls with the times of their next events, heap-ordered by time.
    heap: Vec<(f64, u32)>,
    /// Per ball: its index in `heap`.
    place: Vec<u32>,
    /// Per ball: how often it has changed course.
    counts: Vec<u32>,
}

impl Queue {
    /// A calendar of `balls` balls with nothing predicted, keeping the allocations.
    pub fn reset(&mut self, balls: usize) {
        self.next.clear();
        self.next.resize(balls, NOTHING);
        self.heap.clear();
        self.heap
            .extend((0..balls as u32).map(|ball| (f64::INFINITY, ball)));
        self.place.clear();
        self.place.extend(0..balls as u32);
        self.counts.clear();
        self.counts.resize(balls, 0);
    }

    /// `what` at `time`, as an event of a ball predicted now (it remembers the partner's
    /// counter, so it can tell later whether the partner has changed course since).
    pub fn event(&self, time: f64, what: What) -> Event {
        let partner_count = match what {
            What::Ball(other) => self.counts[other as usize],
            _ => 0,
        };
        Event {
            time,
            what,
            partner_count,
        }
    }

    /// Whether `event` still stands: it has no partner, or its partner has not changed course
    /// since it was predicted.
    pub fn current(&self, event: &Event) -> bool {
        match event.what {
            What::Ball(other) => self.counts[other as usize] == event.partner_count,
            _ => true,
        }
    }

    /// Makes `event` the next event of `ball`, replacing the one it had.
    pub fn set(&mut self, ball: usize, event: Event) {
        let earlier = event.time < self.next[ball].time;
        self.next[ball] = event;
        let at = self.place[ball] as usize;
        self.heap[at].0 = event.time;
        if earlier {
            self.sift_up(at);
        } else {
            self.sift_down(at);
        }
    }

    /// Marks `ball` as having changed course: events other balls predicted with it are out of
    /// date. (Its own event is replaced when it is predicted again.)
    pub fn changed(&mut self, ball: usize) {
        self.counts[ball] = self.counts[ball].wrapping_add(1);
    }

    /// The ball with the earliest event, and that event, if it comes no later than `end`. The
    /// flag says whether the event is current (`false`: its partner changed course since, so
    /// only the ball is to be predicted again). The caller must set the ball's next event
    /// (predict it again), or the same event comes up again.
    pub fn earliest(&self, end: f64) -> Option<(usize, Event, bool)> {
        let ball = self.heap.first()?.1 as usize;
        let event = self.next[ball];
        if event.time.total_cmp(&end).is_gt() {
            return None;
        }
        Some((ball, event, self.current(&event)))
    }

    /// Carries the events still to come over to the next step, which starts `dt` frames
    /// later: their times move back by `dt` (the same shift for all keeps the heap's order).
    pub fn carry_over(&mut self, dt: f64) {
        for event in &mut self.next {
            event.time -= dt;
        }
        for (time, _) in &mut self.heap {
            *time -= dt;
        }
    }

    fn earlier(&self, a: usize, b: usize) -> bool {
        self.heap[a].0 < self.heap[b].0
    }

    fn swap(&mut self, a: usize, b: usize) {
        self.heap.swap(a, b);
        self.place[self.heap[a].1 as usize] = a as u32;
        self.place[self.heap[b].1 as usize] = b as u32;
    }

    fn sift_up(&mut self, mut at: usize) {
        while at > 0 {
            let parent = (at - 1) / 2;
            if !self.earlier(at, parent) {
                break;
            }
            self.swap(at, parent);
            at = parent;
        }
    }

    fn sift_down(&mut self, mut at: usize) {
        loop {
            let (left, right) = (2 * at + 1, 2 * at + 2);
            let mut first = at;
            if left < self.heap.len() && self.earlier(left, first) {
                first = left;
            }
            if right < self.heap.len() && self.earlier(right, first) {
                first = right;
            }
            if first == at {
                break;
            }
            self.swap(at, first);
            at = first;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn events_come_out_earliest_first_and_out_of_date_ones_are_flagged() {
        let mut queue = Queue::default();
        queue.reset(4);
        let mut set = |ball, time, what| queue.set(ball, queue.event(time, what));
        set(0, 0.5, What::Ball(1));
        set(2, 0.75, What::Contact);
        set(3, 0.9, What::Contact);
        set(2, 0.25, What::Contact); // predicted again: replaces 0.75
        queue.changed(1); // ball 1 changed course: ball 0's event is out of date
        let popped: Vec<(usize, f64, bool)> = std::iter::from_fn(|| {
            let (ball, event, current) = queue.earliest(1.0)?;
            queue.set(ball, NOTHING); // nothing more for it
            Some((ball, event.time, current))
        })
        .collect();
        assert_eq!(
            popped,
            vec![(2, 0.25, true), (0, 0.5, false), (3, 0.9, true)],
            "expected ball 2 at 0.25, ball 0 out of date at 0.5, ball 3 at 0.9"
        );
    }

    #[test]
    fn events_carried_into_the_next_step_move_back_by_its_length() {
        let mut queue = Queue::default();
        queue.reset(2);
        queue.set(0, queue.event(1.5, What::Contact));
        assert!(
            queue.earliest(1.0).is_none(),
            "nothing is due within the step"
        );
        queue.carry_over(1.0);
        let next = queue
            .earliest(1.0)
            .map(|(ball, event, _)| (ball, event.time));
        assert_eq!(
            next,
            Some((0, 0.5)),
            "expected the event at 1.5 to come at 0.5, got {next:?}"
        );
    }
}
