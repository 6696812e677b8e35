//! The event calendar: each ball's next event, earliest first.
//!
//! Each ball keeps only its earliest predicted event (Lubachevsky; DynamO keeps one entry per
//! particle in its global queue too), so the calendar never holds more than N events, none
//! stale. It is a *calendar queue* (Brown; Paul's O(1) queue for event-driven molecular
//! dynamics): the step is cut into as many days as there are balls, each day a list of the
//! balls whose events fall on it, and only today's events sit in a binary heap (with each
//! ball's place in it remembered). Filing an event on a later day costs O(1); a heap of the
//! whole scene would cost O(log N) and a walk through memory far too big for the cache on
//! every event, since the ball whose event just came up goes from the top to near the bottom.
//! A day holds about one event, so today's heap is tiny; should the events crowd into one day,
//! the heap still keeps each one O(log N). Events after the step's end wait outside the
//! calendar, which is laid out again when they are carried into the next step.
//!
//! A ball's own event is replaced whenever it is predicted again. An event with a partner can
//! still go out of date when the *partner* changes course: each ball has a counter that goes
//! up whenever it does, the event remembers the partner's counter, and when such an event
//! comes up with the counter moved on, its ball is predicted again instead (nothing before it
//! can have been missed: any change since was made by balls that predicted their own events).

use super::lists::Lists;

/// What kind of event a ball has next: what happens to it then.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum EventKind {
    /// Nothing predicted: the event's time is infinite.
    Nothing,
    /// It touches ball number `.0`.
    Ball(u32),
    /// It touches a wall, a floor's face or a floor's end (which one the caller keeps).
    Contact,
    /// It leaves its grid cell, along `axis` (0 = x, 1 = y), towards `+1` or `−1`.
    Cell { axis: u8, towards: i8 },
}

/// One ball's next event, in 16 bytes: its kind is kept as one 32-bit number (`What`), so
/// that an event fills a quarter of a cache line and never straddles two. Each ball keeps two
/// of these, its next event and its bounce, and with 100,000 balls every byte a ball keeps
/// counts against what the cache holds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Event {
    /// When, in frames since the start of the step.
    pub time: f64,
    what: What,
    /// The partner's counter when this was predicted (0 without a partner).
    partner_count: u32,
}

impl Event {
    /// What happens then.
    pub fn kind(&self) -> EventKind {
        self.what.kind()
    }
}

/// An [`EventKind`] as one number: a ball's own number for a bounce with it, and the largest
/// few numbers (no ball's: a scene has far fewer balls) for the others.
#[derive(Clone, Copy, Debug, PartialEq)]
struct What(u32);

impl What {
    const NOTHING: u32 = u32::MAX;
    const CONTACT: u32 = u32::MAX - 1;
    /// The first of the four cell crossings: `CELL - (2·axis + 1)` towards −1 and
    /// `CELL - 2·axis` towards +1 (with `axis` 0 or 1).
    const CELL: u32 = u32::MAX - 2;
    /// The largest ball number an event holds: the next four are the cell crossings'.
    const LARGEST_BALL: u32 = What::CELL - 4;

    const fn of(kind: EventKind) -> What {
        What(match kind {
            EventKind::Nothing => What::NOTHING,
            EventKind::Ball(j) => j,
            EventKind::Contact => What::CONTACT,
            EventKind::Cell { axis, towards } => {
                What::CELL - 2 * axis as u32 - (towards < 0) as u32
            }
        })
    }

    fn kind(self) -> EventKind {
        match self.0 {
            What::NOTHING => EventKind::Nothing,
            What::CONTACT => EventKind::Contact,
            j if j <= What::LARGEST_BALL => EventKind::Ball(j),
            cell => {
                let below = What::CELL - cell;
                let towards = if below % 2 == 1 { -1 } else { 1 };
                EventKind::Cell {
                    axis: (below / 2) as u8,
                    towards,
                }
            }
        }
    }
}

/// No event: nothing predicted.
pub(super) const NOTHING: Event = Event {
    time: f64::INFINITY,
    what: What::of(EventKind::Nothing),
    partner_count: 0,
};

/// Not in today's heap.
const NOWHERE: u32 = u32::MAX;

/// The balls' next events.
#[derive(Clone, Debug, Default)]
pub(super) struct Queue {
    next: Vec<Event>,
    /// Per ball: how often it has changed course.
    counts: Vec<u32>,
    /// The step's length, frames: later events wait for the next step.
    length: f64,
    /// Days per frame (a multiplication is cheaper than a division, on every event).
    days_per_frame: f64,
    /// The balls whose events come on each day of the step after today.
    days: Lists,
    /// The day now: no event is on an earlier one.
    today: usize,
    /// The balls whose events come today (or earlier), with their times, heap-ordered by time.
    heap: Vec<(f64, u32)>,
    /// Per ball: its index in `heap`, or `NOWHERE`.
    place: Vec<u32>,
}

impl Queue {
    /// Memory per ball, bytes: its next event and counter, its place in a day's list (one
    /// day per ball), and its place in today's heap (whose buffer may grow to twice that).
    pub(crate) const BYTES_PER_BALL: u64 = (size_of::<Event>()
        + size_of::<u32>()
        + size_of::<u32>()
        + 2 * size_of::<(f64, u32)>()
        + size_of::<u32>()) as u64
        + Lists::BYTES_PER_BALL;

    /// A calendar of `balls` balls with nothing predicted, for a step `length` frames long,
    /// keeping the allocations.
    pub fn reset(&mut self, balls: usize, length: f64) {
        self.next.clear();
        self.next.resize(balls, NOTHING);
        self.counts.clear();
        self.counts.resize(balls, 0);
        self.length = length;
        self.days_per_frame = self.days_count() as f64 / length;
        self.lay_out();
    }

    /// Empties the days and today's heap and files every ball's event again, from the first day.
    fn lay_out(&mut self) {
        let balls = self.next.len();
        self.days.reset(balls.max(1), balls);
        self.today = 0;
        self.heap.clear();
        self.place.clear();
        self.place.resize(balls, NOWHERE);
        for ball in 0..balls {
            self.file(ball);
        }
    }

    /// An event of kind `kind` at `time`, as an event of a ball predicted now (it remembers
    /// the partner's counter, so it can tell later whether the partner has changed course
    /// since).
    pub(crate) fn event(&self, time: f64, kind: EventKind) -> Event {
        let partner_count = match kind {
            EventKind::Ball(other) => self.counts[other as usize],
            _ => 0,
        };
        Event {
            time,
            what: What::of(kind),
            partner_count,
        }
    }

    /// Whether `event` still stands: it has no partner, or its partner has not changed course
    /// since it was predicted.
    pub(crate) fn current(&self, event: &Event) -> bool {
        match event.kind() {
            EventKind::Ball(other) => self.counts[other as usize] == event.partner_count,
            _ => true,
        }
    }

    /// Makes `event` the next event of `ball`, replacing the one it had.
    pub(crate) fn set(&mut self, ball: usize, event: Event) {
        if self.place[ball] == NOWHERE {
            self.days.remove(ball);
        } else {
            self.take_from_heap(ball);
        }
        self.next[ball] = event;
        self.file(ball);
    }

    /// Marks `ball` as having changed course: events other balls predicted with it are out of
    /// date. (Its own event is replaced when it is predicted again.)
    pub(crate) fn changed(&mut self, ball: usize) {
        self.counts[ball] = self.counts[ball].wrapping_add(1);
    }

    /// The ball with the earliest event within the step, and that event. The flag says whether
    /// the event is current (`false`: its partner changed course since, so only the ball is to
    /// be predicted again). The caller must set the ball's next event (predict it again), or
    /// the same event comes up again.
    pub(crate) fn earliest(&mut self) -> Option<(usize, Event, bool)> {
        while self.heap.is_empty() {
            if self.today + 1 >= self.days_count() {
                return None;
            }
            self.today += 1;
            while let Some(ball) = self.days.first(self.today) {
                self.days.remove(ball);
                self.push(ball);
            }
        }
        let ball = self.heap[0].1 as usize;
        let event = self.next[ball];
        Some((ball, event, self.current(&event)))
    }

    /// Carries the events still to come over to the next step, which starts a step's length
    /// later: their times move back by that much, and the calendar is laid out afresh.
    pub(crate) fn carry_over(&mut self) {
        for event in &mut self.next {
            event.time -= self.length;
        }
        self.lay_out();
    }

    fn days_count(&self) -> usize {
        self.next.len().max(1)
    }

    /// Puts `ball`, in neither a day nor the heap, where its event's time says: today's heap,
    /// a later day, or nowhere if it comes after the step.
    fn file(&mut self, ball: usize) {
        let time = self.next[ball].time;
        if time.is_nan() || time > self.length {
            return;
        }
        // `as usize` saturates (and maps NaN to 0), so the day is always in range; an event a
        // rounding error before today is filed today.
        let day = ((time * self.days_per_frame) as usize)
            .min(self.days_count() - 1)
            .max(self.today);
        if day == self.today {
            self.push(ball);
        } else {
            self.days.insert(ball, day);
        }
    }

    fn push(&mut self, ball: usize) {
        self.heap.push((self.next[ball].time, ball as u32));
        let at = self.heap.len() - 1;
        self.place[ball] = at as u32;
        self.sift_up(at);
    }

    fn take_from_heap(&mut self, ball: usize) {
        let at = self.place[ball] as usize;
        self.place[ball] = NOWHERE;
        let last = self.heap.pop().expect("a ball with a place is in the heap");
        if at < self.heap.len() {
            self.heap[at] = last;
            self.place[last.1 as usize] = at as u32;
            self.sift_up(at);
            self.sift_down(at);
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
        queue.reset(4, 1.0);
        let mut set = |ball, time, kind| queue.set(ball, queue.event(time, kind));
        set(0, 0.5, EventKind::Ball(1));
        set(2, 0.75, EventKind::Contact);
        set(3, 0.9, EventKind::Contact);
        set(2, 0.25, EventKind::Contact); // predicted again: replaces 0.75
        queue.changed(1); // ball 1 changed course: ball 0's event is out of date
        let popped: Vec<(usize, f64, bool)> = std::iter::from_fn(|| {
            let (ball, event, current) = queue.earliest()?;
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
    fn every_kind_of_event_reads_back_as_it_was_set() {
        let mut kinds = vec![EventKind::Nothing, EventKind::Contact];
        // Up to the largest ball number it holds, just below the other kinds' six numbers.
        kinds.extend([0, 1, 7, u32::MAX - 6].map(EventKind::Ball));
        for axis in 0..2 {
            for towards in [-1, 1] {
                kinds.push(EventKind::Cell { axis, towards });
            }
        }
        for kind in kinds {
            let read = What::of(kind).kind();
            assert_eq!(read, kind, "set {kind:?}, read {read:?}");
        }
    }

    #[test]
    fn events_carried_into_the_next_step_move_back_by_its_length() {
        let mut queue = Queue::default();
        queue.reset(2, 1.0);
        queue.set(0, queue.event(1.5, EventKind::Contact));
        assert!(queue.earliest().is_none(), "nothing is due within the step");
        queue.carry_over();
        let next = queue.earliest().map(|(ball, event, _)| (ball, event.time));
        assert_eq!(
            next,
            Some((0, 0.5)),
            "expected the event at 1.5 to come at 0.5, got {next:?}"
        );
    }
}
