//! One step of a scene with exact ball-ball contacts: events in time order.
//!
//! Every ball keeps its own clock (Lubachevsky): it is only moved when an event involves it,
//! and its state is valid at its clock's time. An event at time `t` moves its one or two balls
//! from their clocks to `t` along their flights, bounces them, and predicts their next events:
//! against every ball in the neighbouring cells (`crate::physics::integrate::toi`), against the
//! walls and floors (`crate::physics::integrate::exact`), and leaving the cell. At the end of
//! the step every ball is flown from its clock to the step's end.
//!
//! Two balls bounce at the moment they touch, along the line through their centres at that
//! moment, with masses ∝ radius² and the scene's restitution `e`: the relative normal speed
//! `u` becomes `−e·u`.
//!
//! **Inelastic collapse.** With `e < 1`, balls can collide infinitely often in finite time
//! (McNamara & Young): three balls in a row, or a ball pressed onto a resting pile. The
//! rules below, the first as for walls (`crate::physics::integrate::exact`), make every step
//! finish and a pile rest:
//! - **Rest rule.** At the start of each step a ball that touches, without normal speed, a
//!   wall, a floor or a ball that is itself held, and that gravity presses onto it, is *held*:
//!   that part of gravity is removed from its step, as the wall's rest rule does. A collision
//!   with `e < 1` whose rebound would be slower than `REST_SPEED`, of a ball that
//!   gravity presses onto a held ball, ends with the falling ball at rest on the held one, as
//!   on a wall (the held ball is not pushed: what holds it takes the impulse). Without this a
//!   ball landing on a resting pile would bounce between pile and ball in ever smaller steps,
//!   without end. From then on gravity presses neither ball into the other (each leans on the
//!   other as on a wall): on curved flights a held ball sliding into the one that rests on it
//!   would otherwise meet it again every few ten-thousandths of a frame.
//! - **Sleep rule** (DynamO's sleeping particles, Bannerman, Strobl & Pöschel): at the start
//!   of each step, a ball no faster than gravity makes it in one step that walls, floors and
//!   sleeping balls within 1 % of its radius hold up completely (no way left to slide:
//!   pushes along their normals alone can balance gravity) sleeps: it stops, and for the step
//!   it is a fixed obstacle. Balls may hold each other up, so the sleepers are the largest
//!   set of slow balls that holds itself up. Struck so hard that the rebound reaches
//!   `REST_SPEED`, it wakes and collides as usual. A settled pile sleeps whole and
//!   has no events at all; and once a step has found every ball asleep and resolved no
//!   event, it has left every ball as it found it (stopped, where it was), so every later
//!   step would do the same: none is taken, and a settled scene costs nothing.
//! - **TC model** (Luding & McNamara, "How to handle the inelastic collapse of a dissipative
//!   hard-sphere gas with the TC model", 1998): a collision within `TC_DURATION` of either
//!   ball's previous collision is elastic, so a cascade of collisions at one moment ends.
//! - **A cap.** A step resolves at most [`MAX_EVENTS_PER_BALL`] events per ball. If it runs
//!   out, every ball is flown to the time of the last event and the rest of the step is
//!   dropped: nothing overlaps, time is lost (and the Euler methods' gravity kick for the
//!   dropped time is taken back). [`EventCounts`] reports each such step.

mod collide;

use super::cells::Cells;
use super::queue::{Event, EventKind, Queue, NOTHING};
use crate::physics::ball::Ball;
use crate::physics::effects::Effects;
use crate::physics::integrate::exact::{self, BallBounds, Contact, Support};
use crate::physics::integrate::integrator::{Forces, Integrator};
use crate::physics::integrate::poly::Poly;
use crate::physics::integrate::toi;
use crate::physics::tolerances::{BALL_TOUCH_GAP, MAX_EVENTS_PER_BALL, SLEEP_GAP, TOUCH_SPEED};
use crate::physics::vec2::Vec2;
use crate::work::{tally, Work};

/// What the event-driven steps of the last frame did.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct EventCounts {
    /// Events resolved (ball-ball, wall and floor bounces, cell crossings).
    pub events: u64,
    /// Of those, bounces between two balls.
    pub ball_collisions: u64,
    /// Of those, bounces off (or coming to rest on) a wall, a floor's face or a floor's end.
    pub contacts: u64,
    /// The most events any single step of the frame resolved.
    pub most_in_a_step: u64,
    /// Steps that hit the cap and dropped the rest of their time.
    pub capped_steps: u64,
}

/// Exact ball-ball contacts, keeping its buffers from step to step.
#[derive(Clone, Debug)]
pub(crate) struct EventDriven {
    /// Share of the approach speed kept after a bounce (0 to 1).
    restitution: f64,
    queue: Queue,
    cells: Cells,
    /// Per ball: the time its state is valid at, and the forces of its flight this step.
    clock: Vec<f64>,
    flight: Vec<Forces>,
    /// Per ball: when it first touches another ball as predicted, which stays true while the
    /// ball keeps its course, however many cells it crosses on the way.
    bounce: Vec<Event>,
    /// Per ball: the wall or floor its predicted contact is with, when its next event is a
    /// contact (otherwise whatever an earlier prediction left, unread).
    contact: Vec<Option<Contact>>,
    /// Per ball: the surfaces it rests on at the start of the step.
    support: Vec<Support>,
    /// Per ball: whether something holds it up (part of gravity removed).
    held: Vec<bool>,
    /// Per ball: whether it sleeps this step (the sleep rule).
    asleep: Vec<bool>,
    /// Per ball: when it last collided with another ball, frames since the first step.
    last_collision: Vec<f64>,
    /// Frames since the first step, at the start of this step.
    elapsed: f64,
    /// Whether the calendar, the grid and the clocks carry over into the next step, so that
    /// it need not predict every ball's events afresh (see `EventDriven::step`).
    carried: bool,
    /// Whether the last step found every ball asleep and resolved no event: it changed
    /// nothing, so no later step can (the scene is fixed and only the steps move balls).
    settled: bool,
    counts: EventCounts,
}

/// The settings one step needs, borrowed from the simulation.
struct Step<'a> {
    integrator: Integrator,
    forces: &'a Forces,
    effects: &'a Effects,
    /// How far ahead events are predicted, frames since the step's start.
    horizon: f64,
    /// Whether nothing curves a flight (no gravity, no drag): then every ball's flight is
    /// `forces` itself.
    straight: bool,
}

impl EventDriven {
    /// Exact mode's memory per ball, bytes, for the budget: the per-ball buffers of this
    /// struct (clock, flight, predicted bounce and contact, supports, flags, last collision),
    /// the calendar's and the grid's.
    pub(crate) const BYTES_PER_BALL: u64 = (2 * size_of::<f64>()
        + size_of::<Forces>()
        + size_of::<Event>()
        + size_of::<Option<Contact>>()
        + size_of::<Support>()
        + 2 * size_of::<bool>()) as u64
        + Queue::BYTES_PER_BALL
        + Cells::BYTES_PER_BALL;

    /// Exact contacts that keep `restitution` of the approach speed.
    pub(crate) fn new(restitution: f64) -> EventDriven {
        EventDriven {
            restitution,
            queue: Queue::default(),
            cells: Cells::default(),
            clock: Vec::new(),
            flight: Vec::new(),
            bounce: Vec::new(),
            contact: Vec::new(),
            support: Vec::new(),
            held: Vec::new(),
            asleep: Vec::new(),
            last_collision: Vec::new(),
            elapsed: 0.0,
            carried: false,
            settled: false,
            counts: EventCounts::default(),
        }
    }

    /// What the steps of the last frame did.
    pub(crate) fn counts(&self) -> EventCounts {
        self.counts
    }

    /// How many balls slept in the last step (the sleep rule).
    pub(crate) fn sleeping(&self) -> usize {
        self.asleep.iter().filter(|&&asleep| asleep).count()
    }

    /// Advances `balls` by one frame of `steps` steps of `forces.dt` frames.
    pub(crate) fn frame(
        &mut self,
        balls: &mut [Ball],
        integrator: Integrator,
        steps: u32,
        forces: &Forces,
        effects: &Effects,
    ) {
        self.counts = EventCounts::default();
        for _ in 0..steps {
            if self.settled {
                return; // every ball sleeps, and nothing can wake one
            }
            tally(Work::BallCollisions);
            self.step(balls, integrator, forces, effects);
        }
    }

    /// Advances `balls` by one step of `forces.dt` frames, every contact at its moment.
    ///
    /// Without gravity and drag every flight is a straight line that nothing bends between
    /// steps, so a prediction stays true past the step's end: events are then predicted
    /// without a horizon, and the calendar, the grid and the clocks carry over into the next
    /// step, where the end of a step is only a stop to draw the frame (event-driven molecular
    /// dynamics runs this way). Anything else (gravity's kicks, drag, a capped step, a ball
    /// that left the area the grid was laid over) starts the next step afresh.
    fn step(
        &mut self,
        balls: &mut [Ball],
        integrator: Integrator,
        forces: &Forces,
        effects: &Effects,
    ) {
        let straight = forces.gravity.is_none() && forces.drag.is_none();
        let step = Step {
            integrator,
            forces,
            effects,
            horizon: if straight { f64::INFINITY } else { forces.dt },
            straight,
        };
        if !self.carried {
            self.start(balls, &step);
        }
        let (events, end) = self.run_events(balls, &step);
        self.settled = events == 0 && self.asleep.iter().all(|&asleep| asleep);
        let covered = self.fly_to(end, balls, &step);
        self.carried = straight && end == forces.dt && covered;
        if self.carried {
            self.carry_over(forces.dt);
        }
        self.elapsed += forces.dt;
        self.counts.events += events;
        self.counts.most_in_a_step = self.counts.most_in_a_step.max(events);
    }

    /// Resolves the step's events in time order, until none is left before the step's end or
    /// the cap is reached. Returns how many it resolved and how far the step got: its end, or
    /// the time of the event the cap stopped at.
    fn run_events(&mut self, balls: &mut [Ball], step: &Step) -> (u64, f64) {
        let cap = MAX_EVENTS_PER_BALL * balls.len() as u64;
        let mut events = 0;
        // Every branch predicts the ball again, which replaces its event in the calendar.
        while let Some((i, event, current)) = self.queue.earliest() {
            let now = event.time;
            if !current {
                // Its partner changed course since: predict the ball again from here.
                self.fly(&mut balls[i], i, now, step);
                self.predict(balls, i, step);
                continue;
            }
            if events == cap {
                self.counts.capped_steps += 1;
                return (events, now); // no clock is later: events come out in time order
            }
            events += 1;
            self.fly(&mut balls[i], i, now, step);
            self.resolve(balls, i, event.kind(), now, step);
        }
        (events, step.forces.dt)
    }

    /// Resolves ball `i`'s event of kind `kind`, now (ball `i` is flown there), and predicts
    /// again the events of the balls it changed.
    fn resolve(&mut self, balls: &mut [Ball], i: usize, kind: EventKind, now: f64, step: &Step) {
        let forces = step.forces;
        match kind {
            EventKind::Nothing => {}
            EventKind::Ball(j) => {
                let j = j as usize;
                self.fly(&mut balls[j], j, now, step);
                self.collide(balls, i, j, forces, now);
                self.counts.ball_collisions += 1;
                self.queue.changed(i);
                self.queue.changed(j);
                self.predict(balls, i, step);
                self.predict(balls, j, step);
            }
            EventKind::Contact => {
                if let Some(contact) = self.contact[i] {
                    contact.bounce(&mut balls[i], forces);
                    self.counts.contacts += 1;
                }
                let bounds = BallBounds::of(&balls[i], step.effects);
                self.flight[i] = bounds.supported(&balls[i], forces);
                self.held[i] = self.flight[i] != *forces;
                self.queue.changed(i);
                self.predict(balls, i, step);
            }
            EventKind::Cell { axis, towards } => {
                // The ball keeps its course, so events other balls predicted with it stand,
                // and so does its own bounce unless its partner changed course since: then
                // only the balls of the cells it now comes near need looking at.
                self.cells.shift(i, axis, towards);
                if self.queue.current(&self.bounce[i]) {
                    self.predict_near(balls, i, Some((axis, towards)), step);
                } else {
                    self.predict(balls, i, step);
                }
            }
        }
    }

    /// The end of the step (or of the time it got to, `end`, if capped): every ball flown from
    /// its clock to `end`, Euler's last kick. Returns whether the grid still covers every ball.
    fn fly_to(&mut self, end: f64, balls: &mut [Ball], step: &Step) -> bool {
        let unused = step.forces.dt - end;
        let mut covered = true;
        for (i, ball) in balls.iter_mut().enumerate() {
            self.fly(ball, i, end, step);
            covered &= self.cells.covers(ball);
            let flight = Forces {
                dt: end,
                ..self.flight[i]
            };
            step.integrator.kick_after(ball, &flight);
            // Euler's first kick gave gravity for the whole step: take back the dropped part,
            // so a capped step cannot speed balls up without moving them.
            if let (Integrator::SemiImplicitEuler, Some(g)) = (step.integrator, flight.gravity) {
                let velocity = ball.velocity() - g * unused;
                (ball.vx, ball.vy) = (velocity.x, velocity.y);
            }
        }
        covered
    }

    /// Keeps the calendar, the grid and the clocks for the next step, their times moved back
    /// by the step's length `dt`.
    fn carry_over(&mut self, dt: f64) {
        self.queue.carry_over();
        for bounce in &mut self.bounce {
            bounce.time -= dt;
        }
        self.clock.fill(0.0);
    }

    /// The start of a step: balls put back inside the walls, the grid laid, what each ball
    /// rests on found, Euler's first kick, every ball's first events predicted.
    fn start(&mut self, balls: &mut [Ball], step: &Step) {
        for ball in balls.iter_mut() {
            exact::put_back(ball, step.effects);
        }
        let area = step
            .effects
            .walls
            .as_ref()
            .map(|w| Vec2::new(w.width, w.height));
        self.cells.rebuild(balls, area);
        self.queue.reset(balls.len(), step.forces.dt);
        self.clock.clear();
        self.clock.resize(balls.len(), 0.0);
        self.bounce.clear();
        self.bounce.resize(balls.len(), NOTHING);
        self.contact.clear();
        self.contact.resize(balls.len(), None);
        self.support.clear();
        self.support.extend(
            balls
                .iter()
                .map(|ball| BallBounds::of(ball, step.effects).support(ball)),
        );
        self.held.clear();
        self.held.resize(balls.len(), false);
        self.asleep.clear();
        self.asleep.resize(balls.len(), false);
        self.last_collision.resize(balls.len(), f64::NEG_INFINITY);
        if step.forces.gravity.is_some() {
            self.find_asleep(balls, step);
            self.find_held(balls, step.forces);
        }
        self.flight.clear();
        // Exactly one per ball, as the memory budget counts.
        self.flight.reserve_exact(balls.len());
        for (i, ball) in balls.iter_mut().enumerate() {
            let flight = if self.asleep[i] {
                Forces {
                    gravity: None,
                    ..*step.forces
                }
            } else {
                self.support[i].hold(step.forces)
            };
            self.flight.push(flight);
            step.integrator.kick_before(ball, &self.flight[i]);
        }
        for i in 0..balls.len() {
            self.predict(balls, i, step);
        }
    }

    /// The sleep rule (after DynamO's sleeping particles, Bannerman et al.): a ball no faster
    /// than gravity makes it in one step, held up completely (no way left to slide) by walls,
    /// floors and sleeping balls within [`SLEEP_GAP`] of it, sleeps this step: it stops and
    /// stays put. Each step decides afresh, so a ball whose support wakes or moves away falls
    /// again.
    ///
    /// Balls can hold each other up (two wedged against each other, each keeping the other
    /// from sliding), so the sleepers are found from the top down: every slow ball starts
    /// asleep, and a ball the others asleep cannot hold up wakes, until none is left to wake
    /// (the largest set that holds itself up). Growing the set from the bottom up instead
    /// would never put such a pair to sleep, and the pile around them would jiggle on.
    fn find_asleep(&mut self, balls: &mut [Ball], step: &Step) {
        let forces = step.forces;
        let Some(g) = forces.gravity else {
            return;
        };
        let sleep_speed = g.length() * forces.dt;
        let slow = |ball: &Ball| ball.velocity().length() <= sleep_speed;
        let mut candidates: Vec<usize> = (0..balls.len()).filter(|&i| slow(&balls[i])).collect();
        for &i in &candidates {
            self.asleep[i] = true;
        }
        // Lowest first (furthest along gravity): a ball that wakes can only wake the balls
        // it held up, above it, which then come later in the same pass.
        let depth = |i: usize| g.dot(balls[i].position());
        candidates.sort_by(|&a, &b| depth(b).total_cmp(&depth(a)));
        let mut changed = true;
        while changed {
            changed = false;
            for &i in &candidates {
                if !self.asleep[i] {
                    continue;
                }
                let ball = &balls[i];
                let mut support = BallBounds::of(ball, step.effects).near(ball, SLEEP_GAP);
                let asleep = &self.asleep;
                self.cells.neighbours(i, |j| {
                    if j != i && asleep[j] {
                        if let Some(n) = leaning_on(ball, &balls[j], SLEEP_GAP) {
                            support.push(n);
                        }
                    }
                });
                if !support.hold_completely(g) {
                    self.asleep[i] = false;
                    changed = true;
                }
            }
        }
        for (i, ball) in balls.iter_mut().enumerate() {
            if self.asleep[i] {
                (ball.vx, ball.vy) = (0.0, 0.0);
                self.held[i] = true;
            }
        }
    }

    /// Adds to each ball's support the balls it rests on, from the bottom of a pile up: a
    /// ball rests on a neighbour that is itself held, touches it, has no normal speed
    /// relative to it, and is pressed onto it by gravity.
    fn find_held(&mut self, balls: &[Ball], forces: &Forces) {
        let held = |support: &Support| support.hold(forces) != *forces;
        let is_held = &mut self.held;
        let mut changed = true;
        while changed {
            changed = false;
            for i in 0..balls.len() {
                if is_held[i] {
                    continue;
                }
                let mut support = self.support[i];
                self.cells.neighbours(i, |j| {
                    if j != i && is_held[j] {
                        if let Some(n) = resting_on(&balls[i], &balls[j], forces) {
                            support.push(n);
                        }
                    }
                });
                if held(&support) {
                    self.support[i] = support;
                    is_held[i] = true;
                    changed = true;
                }
            }
        }
    }

    /// Moves ball `i` along its flight from its clock to `time`.
    fn fly(&mut self, ball: &mut Ball, i: usize, time: f64, step: &Step) {
        let span = time - self.clock[i];
        if span > 0.0 {
            step.integrator.fly(ball, self.flight(i, step), span);
            self.clock[i] = time;
        }
    }

    /// Ball `i`'s flight this step. In a straight step it is the step's forces, read from
    /// there: every ball's would be the same, and reading the ball's own would cost a cache
    /// line more per event (with 100,000 balls, one from main memory).
    fn flight<'s>(&'s self, i: usize, step: &'s Step) -> &'s Forces {
        if step.straight {
            step.forces
        } else {
            &self.flight[i]
        }
    }

    /// Predicts the next event of ball `i` (whose clock is now) up to the step's horizon: the
    /// earliest of touching each ball in the neighbouring cells (its bounce), leaving its cell,
    /// and its contacts with walls and floors.
    fn predict(&mut self, balls: &[Ball], i: usize, step: &Step) {
        self.bounce[i] = NOTHING;
        self.predict_near(balls, i, None, step);
    }

    /// Replaces ball `i`'s bounce (its clock is now) with an earlier one, if a ball in the
    /// cells around it touches it first; then makes the earliest of its events its next. After
    /// a move into another cell along `entered` (axis, towards) without changing course, only
    /// the cells it has come near are searched: its bounce stands unless one of those is first.
    fn predict_near(&mut self, balls: &[Ball], i: usize, entered: Option<(u8, i8)>, step: &Step) {
        let now = self.clock[i];
        let path = step.integrator.path(&balls[i], self.flight(i, step));
        let mut first = (self.bounce[i].time.min(step.horizon) - now, None);
        let visit = |j| {
            if let Some(time) = self.touch(balls, [i, j], &path, step, first.0) {
                first = (time, Some(j));
            }
        };
        match entered {
            None => self.cells.neighbours(i, visit),
            Some((axis, towards)) => self.cells.entered(i, axis, towards, visit),
        }
        if let (time, Some(j)) = first {
            self.bounce[i] = self.queue.event(now + time, EventKind::Ball(j as u32));
        }
        self.schedule(balls, i, &path, step);
    }

    /// Makes the earliest of ball `i`'s bounce, its leaving its cell and its contacts with
    /// walls and floors (along `path`, from its clock) its next event.
    fn schedule(&mut self, balls: &[Ball], i: usize, path: &[Poly; 2], step: &Step) {
        let now = self.clock[i];
        let bounce = self.bounce[i];
        // The earliest so far, as time from now; later candidates are not looked for.
        let mut first = (bounce.time.min(step.horizon) - now, bounce.kind());
        if let Some((time, axis, towards)) = self.cells.exit(i, path, first.0) {
            first = (time, EventKind::Cell { axis, towards });
        }
        // Walls and floors last: with the horizon cut short, far ones are skipped unsolved.
        let ball = &balls[i];
        let bounds = BallBounds::of(ball, step.effects);
        let found = bounds.first_contact(ball, path, first.0);
        if let Some((time, contact)) =
            found.filter(|&(time, _)| time < first.0 || first.1 == EventKind::Nothing)
        {
            first = (time, EventKind::Contact);
            // Written only when it is the next event, and read only then: most predictions
            // find none, and leave the ball's 40 bytes here untouched.
            self.contact[i] = Some(contact);
        }
        let next = match first {
            (_, EventKind::Ball(_)) => bounce,
            (_, EventKind::Nothing) => NOTHING,
            (time, kind) => self.queue.event(now + time, kind),
        };
        self.queue.set(i, next);
    }

    /// When, of the pair `[i, j]`, ball `i` (whose clock is now, and whose centre moves along
    /// `path`) first touches ball `j`, as time from now, if that is earlier than `end`.
    #[inline(always)] // called for every neighbour: a call would cost more than the test
    fn touch(
        &self,
        balls: &[Ball],
        [i, j]: [usize; 2],
        path: &[Poly; 2],
        step: &Step,
        end: f64,
    ) -> Option<f64> {
        if j == i {
            return None;
        }
        let (ball, other) = (&balls[i], &balls[j]);
        let reach = ball.radius + other.radius;
        let behind = self.clock[i] - self.clock[j];
        // Straight flights (the Euler methods, or nothing to curve them) need no polynomials.
        let straight = |forces: &Forces| {
            matches!(
                step.integrator,
                Integrator::ExplicitEuler | Integrator::SemiImplicitEuler
            ) || (forces.gravity.is_none() && forces.drag.is_none())
        };
        let touch = if straight(self.flight(i, step)) && straight(self.flight(j, step)) {
            let offset = other.position() + other.velocity() * behind - ball.position();
            let velocity = other.velocity() - ball.velocity();
            toi::straight(offset, velocity, reach, end)
        } else {
            // The other ball as it will be now, so both flights start at the same moment.
            let mut there = Ball::new(other.x, other.y, other.vx, other.vy, other.radius, 0);
            if behind > 0.0 {
                step.integrator.fly(&mut there, &self.flight[j], behind);
            }
            let theirs = step.integrator.path(&there, &self.flight[j]);
            let relative: [Poly; 2] = [0, 1].map(|axis| theirs[axis] - path[axis]);
            toi::first_touch(&relative, reach, end)
        };
        touch.filter(|&time| time < end)
    }
}

/// The normal (from `below` to `ball`) of the contact `ball` rests on `below` through, if it
/// touches it with no normal speed between them and gravity presses it on.
fn resting_on(ball: &Ball, below: &Ball, forces: &Forces) -> Option<Vec2> {
    let n = leaning_on(ball, below, BALL_TOUCH_GAP)?;
    let still = (ball.velocity() - below.velocity()).dot(n).abs() <= TOUCH_SPEED;
    (still && exact::pressed(forces, n)).then_some(n)
}

/// The normal (from `below` to `ball`) if the gap between them is at most `gap` of their
/// radii.
fn leaning_on(ball: &Ball, below: &Ball, gap: f64) -> Option<Vec2> {
    let offset = ball.position() - below.position();
    let distance = offset.length();
    let reach = ball.radius + below.radius;
    if distance == 0.0 || distance - reach > gap * reach {
        return None;
    }
    Some(offset / distance)
}

#[cfg(test)]
mod tests;
