//! The least an exact-mode event costs on this machine, to set the library's figures against.
//!
//! The `exact_events` bench's gas (equal balls of radius 3 at packing 0.3, no gravity, elastic
//! walls) is stepped two ways from the same start: by the library's exact mode, and by a bare
//! event loop that keeps only what this gas needs. The bare loop runs the same algorithm
//! (a clock per ball, one predicted event per ball, a calendar of as many days per frame as
//! balls, cells one diameter wide whose crossings are events) with each ball's whole state on
//! one 64-byte cache line, and without what the library also carries: gravity's curved
//! flights, floors, rest and sleep, the TC model, restitution. What the bare loop's cost per
//! collision gains from 1,000 to 100,000 balls is what memory adds when nothing else does.
//!
//! Both run in turns, so the host's noise falls on both alike; the table gives the median of
//! the turns. Run: `cargo run --release -p bouncing_ball_bench --example event_floor` (about
//! 10 s).

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::time::Instant;

use bouncing_ball::physics::integrate::toi;
use bouncing_ball::Scene;
use bouncing_ball_bench::{exact_gas, EXACT_GAS_RADIUS as RADIUS, EXACT_GAS_STIR as STIR};

/// Turns of each loop per size.
const TURNS: usize = 7;
/// Collision events each turn times, about (the frames per turn follow from it).
const COLLISIONS_PER_TURN: u64 = 250_000;

/// No ball, no filing, no event.
const NONE: u32 = u32::MAX;

/// What a ball's next event is: another ball's number, or one of these.
const WALL: u32 = NONE - 1;
const CELL: u32 = NONE - 2;

/// A ball of the bare loop: everything an event reads or writes of it, on one cache line.
#[derive(Clone, Copy)]
#[repr(C, align(64))]
struct Bare {
    x: f64,
    y: f64,
    vx: f64,
    vy: f64,
    /// The time its state is valid at, frames since the frame's start.
    clock: f64,
    /// Its next event: when, what (a ball's number, `WALL` or `CELL`), and for a ball the
    /// partner's course counter when it was predicted.
    time: f64,
    what: u32,
    partner_count: u32,
    /// How often it has changed course.
    count: u32,
    /// The next ball in its cell.
    next_in_cell: u32,
}

/// The bare loop's whole state.
struct BareGas {
    balls: Vec<Bare>,
    /// Per ball: its earliest predicted touch, kept while it crosses cells (time, partner,
    /// partner's counter).
    bounce: Vec<(f64, u32, u32)>,
    /// Per ball: its cell, and the side its next crossing leaves by (0..4: +x, −x, +y, −y).
    cell: Vec<u32>,
    exit: Vec<u8>,
    side: f64,
    columns: usize,
    cell_size: f64,
    first_in_cell: Vec<u32>,
    /// The calendar: per day the latest filing, the filings (time, ball, the day's previous
    /// filing), and today's filings earliest first.
    days: Vec<u32>,
    filings: Vec<(f64, u32, u32)>,
    today: usize,
    heap: BinaryHeap<Reverse<(Time, u32)>>,
    collisions: u64,
}

/// A time the heap can order (times are never NaN here).
#[derive(Clone, Copy, PartialEq)]
struct Time(f64);

impl Eq for Time {}

impl PartialOrd for Time {
    fn partial_cmp(&self, other: &Time) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Time {
    fn cmp(&self, other: &Time) -> std::cmp::Ordering {
        self.0.total_cmp(&other.0)
    }
}

impl BareGas {
    fn new(scene: &Scene) -> BareGas {
        let side = f64::from(scene.width);
        let columns = ((side / (2.0 * RADIUS)) as usize).max(1);
        let count = scene.balls.len();
        let mut gas = BareGas {
            balls: Vec::with_capacity(count),
            bounce: vec![(f64::INFINITY, NONE, 0); count],
            cell: vec![0; count],
            exit: vec![0; count],
            side,
            columns,
            cell_size: side / columns as f64,
            first_in_cell: vec![NONE; columns * columns],
            days: Vec::new(),
            filings: Vec::new(),
            today: 0,
            heap: BinaryHeap::new(),
            collisions: 0,
        };
        for (i, spec) in scene.balls.iter().enumerate() {
            gas.balls.push(Bare {
                x: spec.x,
                y: spec.y,
                vx: spec.vx,
                vy: spec.vy,
                clock: 0.0,
                time: f64::INFINITY,
                what: NONE,
                partner_count: 0,
                count: 0,
                next_in_cell: NONE,
            });
            let at = |p: f64| ((p / gas.cell_size) as usize).min(columns - 1);
            gas.link(i, at(spec.y) * columns + at(spec.x));
        }
        gas.lay_out();
        for i in 0..count {
            gas.predict(i, None);
        }
        gas
    }

    fn link(&mut self, i: usize, cell: usize) {
        self.cell[i] = cell as u32;
        self.balls[i].next_in_cell = self.first_in_cell[cell];
        self.first_in_cell[cell] = i as u32;
    }

    /// Takes ball `i` out of its cell's list (a cell holds about one ball: a short walk).
    fn unlink(&mut self, i: usize) {
        let cell = self.cell[i] as usize;
        let after = self.balls[i].next_in_cell;
        if self.first_in_cell[cell] == i as u32 {
            self.first_in_cell[cell] = after;
            return;
        }
        let mut at = self.first_in_cell[cell];
        while self.balls[at as usize].next_in_cell != i as u32 {
            at = self.balls[at as usize].next_in_cell;
        }
        self.balls[at as usize].next_in_cell = after;
    }

    fn fly(&mut self, i: usize, time: f64) {
        let ball = &mut self.balls[i];
        ball.x += ball.vx * (time - ball.clock);
        ball.y += ball.vy * (time - ball.clock);
        ball.clock = time;
    }

    /// Files ball `i`'s event under its day; an old filing stays, and is skipped when its time
    /// is no longer the ball's.
    fn file(&mut self, i: usize) {
        let time = self.balls[i].time;
        if time > 1.0 {
            return;
        }
        let days = self.days.len();
        let day = ((time * days as f64) as usize).clamp(self.today, days - 1);
        if day == self.today {
            self.heap.push(Reverse((Time(time), i as u32)));
        } else {
            self.filings.push((time, i as u32, self.days[day]));
            self.days[day] = (self.filings.len() - 1) as u32;
        }
    }

    fn lay_out(&mut self) {
        self.days.clear();
        self.days.resize(self.balls.len(), NONE);
        self.filings.clear();
        self.today = 0;
        self.heap.clear();
        for i in 0..self.balls.len() {
            self.file(i);
        }
    }

    /// The ball with the earliest event of the frame, and its time.
    fn earliest(&mut self) -> Option<(usize, f64)> {
        loop {
            while self.heap.is_empty() {
                self.today += 1;
                if self.today >= self.days.len() {
                    return None;
                }
                let mut at = self.days[self.today];
                while at != NONE {
                    let (time, ball, before) = self.filings[at as usize];
                    self.heap.push(Reverse((Time(time), ball)));
                    at = before;
                }
            }
            let Reverse((Time(time), ball)) = self.heap.pop().expect("not empty");
            if self.balls[ball as usize].time == time {
                return Some((ball as usize, time));
            }
        }
    }

    /// The earliest touch of ball `i` with a ball of `cell`, if before `first.0`.
    fn search(&self, i: usize, cell: usize, first: &mut (f64, u32)) {
        let ball = self.balls[i];
        let mut j = self.first_in_cell[cell];
        while j != NONE {
            let other = &self.balls[j as usize];
            if j as usize != i {
                let behind = ball.clock - other.clock;
                let offset = [
                    other.x + other.vx * behind - ball.x,
                    other.y + other.vy * behind - ball.y,
                ];
                let velocity = [other.vx - ball.vx, other.vy - ball.vy];
                if let Some(time) =
                    toi::straight(offset.into(), velocity.into(), 2.0 * RADIUS, first.0)
                {
                    *first = (time, j);
                }
            }
            j = other.next_in_cell;
        }
    }

    /// Predicts ball `i`'s next event. After a crossing (`entered`: the side it crossed), its
    /// bounce stands unless a ball of the cells it has come near is first.
    fn predict(&mut self, i: usize, entered: Option<u8>) {
        let now = self.balls[i].clock;
        let n = self.columns as i64;
        let cell = self.cell[i] as i64;
        let (column, row) = (cell % n, cell / n);
        // The cells from one before to one after; clipped to the grid below.
        let near = |c: i64| c - 1..c + 2;
        let mut first = (f64::INFINITY, NONE);
        let (columns, rows) = match entered {
            None => (near(column), near(row)),
            Some(side) => {
                first = (self.bounce[i].0 - now, self.bounce[i].1);
                match side {
                    0 => (column + 1..column + 2, near(row)),
                    1 => (column - 1..column, near(row)),
                    2 => (near(column), row + 1..row + 2),
                    _ => (near(column), row - 1..row),
                }
            }
        };
        for r in rows.start.max(0)..rows.end.min(n) {
            for c in columns.start.max(0)..columns.end.min(n) {
                self.search(i, (r * n + c) as usize, &mut first);
            }
        }
        let partner_count = if first.1 == NONE {
            0
        } else {
            self.balls[first.1 as usize].count
        };
        self.bounce[i] = (now + first.0, first.1, partner_count);
        let mut next = (first.0, first.1, partner_count);
        let ball = self.balls[i];
        let to = |target: f64, p: f64, v: f64| ((target - p) / v).max(0.0);
        let wall = |p: f64, v: f64| match v {
            v if v > 0.0 => to(self.side - RADIUS, p, v),
            v if v < 0.0 => to(RADIUS, p, v),
            _ => f64::INFINITY,
        };
        let crossing = |p: f64, v: f64, k: i64| match v {
            v if v > 0.0 && k + 1 < n => to((k + 1) as f64 * self.cell_size, p, v),
            v if v < 0.0 && k > 0 => to(k as f64 * self.cell_size, p, v),
            _ => f64::INFINITY,
        };
        let (across, down) = (
            crossing(ball.x, ball.vx, column),
            crossing(ball.y, ball.vy, row),
        );
        if across.min(down) < next.0 {
            let (time, side) = if across <= down {
                (across, u8::from(ball.vx < 0.0))
            } else {
                (down, 2 + u8::from(ball.vy < 0.0))
            };
            next = (time, CELL, 0);
            self.exit[i] = side;
        }
        let walls = wall(ball.x, ball.vx).min(wall(ball.y, ball.vy));
        if walls < next.0 {
            next = (walls, WALL, 0);
        }
        let ball = &mut self.balls[i];
        (ball.time, ball.what, ball.partner_count) = (now + next.0, next.1, next.2);
        self.file(i);
    }

    /// One frame of events, then every ball flown to its end and the calendar laid out again.
    fn frame(&mut self) {
        while let Some((i, now)) = self.earliest() {
            self.fly(i, now);
            match self.balls[i].what {
                WALL => {
                    let ball = &mut self.balls[i];
                    // Reflect each axis whose wall the ball meets: a hair further along its
                    // velocity it would be outside (rounding may leave it just short).
                    let inside = RADIUS..=self.side - RADIUS;
                    if !inside.contains(&(ball.x + ball.vx.signum() * 1e-9)) {
                        ball.vx = -ball.vx;
                    }
                    if !inside.contains(&(ball.y + ball.vy.signum() * 1e-9)) {
                        ball.vy = -ball.vy;
                    }
                    ball.count += 1;
                    self.collisions += 1;
                    self.predict(i, None);
                }
                CELL => {
                    let side = self.exit[i];
                    let n = self.columns as i64;
                    let step = [1, -1, n, -n][usize::from(side)];
                    let cell = (i64::from(self.cell[i]) + step) as usize;
                    self.unlink(i);
                    self.link(i, cell);
                    let (_, partner, partner_count) = self.bounce[i];
                    let stands =
                        partner == NONE || self.balls[partner as usize].count == partner_count;
                    self.predict(i, stands.then_some(side));
                }
                partner => {
                    let j = partner as usize;
                    if self.balls[j].count != self.balls[i].partner_count {
                        self.predict(i, None); // the partner changed course since
                        continue;
                    }
                    self.fly(j, now);
                    self.bounce_pair(i, j);
                    self.collisions += 1;
                    self.predict(i, None);
                    self.predict(j, None);
                }
            }
        }
        for i in 0..self.balls.len() {
            self.fly(i, 1.0);
            let ball = &mut self.balls[i];
            ball.clock = 0.0;
            ball.time -= 1.0;
            self.bounce[i].0 -= 1.0;
        }
        self.lay_out();
    }

    /// Equal masses, elastic: the normal components of the velocities swap.
    fn bounce_pair(&mut self, i: usize, j: usize) {
        let (a, b) = (self.balls[i], self.balls[j]);
        let (dx, dy) = (b.x - a.x, b.y - a.y);
        let distance = dx.hypot(dy);
        let n = [dx / distance, dy / distance];
        let approach = (b.vx - a.vx) * n[0] + (b.vy - a.vy) * n[1];
        for (k, sign) in [(i, 1.0), (j, -1.0)] {
            let ball = &mut self.balls[k];
            ball.vx += sign * approach * n[0];
            ball.vy += sign * approach * n[1];
            ball.count += 1;
        }
    }
}

/// Runs `frames` frames of `step`, which returns the collision events of its frame, and
/// returns the nanoseconds per collision event.
fn time_turn(frames: u32, mut step: impl FnMut() -> u64) -> f64 {
    let start = Instant::now();
    let collisions: u64 = (0..frames).map(|_| step()).sum();
    start.elapsed().as_nanos() as f64 / collisions.max(1) as f64
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

fn main() {
    println!("balls    collisions/frame (library, bare)    ns per collision event (library, bare)");
    let mut first: Option<[f64; 2]> = None;
    for count in [1_000, 10_000, 100_000] {
        let scene = exact_gas(count);
        let mut library = scene.simulation();
        let mut bare = BareGas::new(&scene);
        let mut library_frame = || {
            library.step();
            let counts = library.event_counts().expect("exact mode counts events");
            counts.ball_collisions + counts.contacts
        };
        let mut bare_frame = || {
            let before = bare.collisions;
            bare.frame();
            bare.collisions - before
        };
        let stirred: [u64; 2] = [
            (0..STIR).map(|_| library_frame()).sum(),
            (0..STIR).map(|_| bare_frame()).sum(),
        ];
        let per_frame = stirred.map(|c| c / u64::from(STIR));
        let frames = (COLLISIONS_PER_TURN / per_frame[0].max(1)).max(1) as u32;
        let (mut library_ns, mut bare_ns) = (Vec::new(), Vec::new());
        for _ in 0..TURNS {
            library_ns.push(time_turn(frames, &mut library_frame));
            bare_ns.push(time_turn(frames, &mut bare_frame));
        }
        let ns = [median(library_ns), median(bare_ns)];
        let base = *first.get_or_insert(ns);
        println!(
            "{count:>7}  {:>10} {:>10}    {:>8.0} {:>8.0}   growth from 1,000: {:.2}x {:.2}x",
            per_frame[0],
            per_frame[1],
            ns[0],
            ns[1],
            ns[0] / base[0],
            ns[1] / base[1]
        );
    }
}
