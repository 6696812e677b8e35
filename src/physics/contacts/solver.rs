//! The contact solver: in the stepped (clamp) mode, a scene with ball-ball collisions has every
//! contact — ball with ball, ball with wall, ball with floor — solved together and
//! iteratively, so that a pile carries its own weight and comes to rest.
//!
//! It is Box2D's *sequential impulses* (Erin Catto, GDC 2006) for frictionless discs, with
//! warm starting, a rest speed below which contacts do not bounce, and Box2D v2.4's position
//! pass; and it iterates the way Box2D v3's *soft step* and "small steps" XPBD do: each
//! iteration is a short sub-step (gravity, one velocity pass, flight, one position pass),
//! with the contacts found once per step. `docs/contacts.md` has the measurements that chose
//! this over more passes per step, softer contacts, and plain substeps. The stages carry
//! Box2D v3's names (`solver.c`, `contact_solver.c`), each a function of that name.
//!
//! One step:
//!
//! 1. **Prepare** (`ContactSolver::prepare`): find the contacts where the balls are —
//!    pairs, walls and floors that can touch within the step (the grid grows each ball by
//!    the distance it can travel). A contact with a gap is *speculative*: it only forbids
//!    closing by more than the gap. The solver works on a copy of the balls in the grid's
//!    order. Each contact gets the impulse it ended the last step with, from the warm-start
//!    memory (`WarmStartMemory::recall`), and the balls with contacts fall into islands,
//!    balls joined by pair contacts directly or through others. Islands share no ball, so
//!    each is solved on its own, all its sub-steps at once, while its balls are in the cache
//!    (the numbers are the same as one sweep over every contact).
//! 2. **Without gravity or drag**, balls fly straight between contacts, so an island is
//!    solved touch by touch (`ContactSet::solve_free_island`): it flies to the time its
//!    first contact touches (a closed form), that contact alone is solved, and so on to the
//!    end of the step. Balls that start it overlapping are first set apart to touching. An
//!    island that still overlaps, or keeps colliding, is put back and takes the sub-steps.
//! 3. **Sub-steps** (`ContactSet::solve_in_substeps`): otherwise, for each island,
//!    `iterations` times, for a sub-step `h` of the step:
//!    - **Integrate velocities**: the integrator adds `h`'s gravity and drag to every
//!      velocity.
//!    - **Warm start** (`ContactSet::warm_start`; under gravity only): each contact pushes
//!      again with its total impulse of the sub-step before (the previous step's, at first).
//!      A stack that stood then stands now, instead of its weight having to travel up through
//!      it again, one ball per pass. A bounce is not carried: it is over once the balls part.
//!    - **Solve** (`ContactSet::solve`), the velocity pass (Gauss–Seidel): contact after
//!      contact, the impulse that brings its relative normal speed to its target, added to
//!      its running total, which is never negative (contacts push, never pull). A contact
//!      that touches within `h` bounces if `e` times its approach speed now beats the rest
//!      speed: that is its target. Slower, it stops (resting balls do not bounce, so a pile
//!      settles instead of buzzing). Box2D v3 leaves bounces to its restitution stage, from
//!      the approach speed the contact was prepared with; here a contact bounces at its
//!      approach speed of the moment, so a struck ball passes the blow on within the step.
//!      Under gravity the pass runs three times ([`LOADED_VELOCITY_PASSES`]), so that a deep
//!      heap carries its weight before the position pass moves it; without, once.
//!    - **Integrate positions**: fly `h` with the solved velocities.
//!    - **Relax** (`ContactSet::relax`), the position pass: overlap beyond a small slop is
//!      partly pushed out, moving positions only, so no kinetic energy is added. (Box2D v3's
//!      solve pushes overlap out with extra velocity, which its relax takes away again; here
//!      the solve adds none, and the push is done here, on positions, as in Box2D v2.4.)
//! 4. A ball that can touch nothing takes the whole step at once, as in the lesson, and the
//!    balls are copied back into the scene, inside its walls.
//! 5. **Restitution** (`Scratch::restitution`): the bounces left after the
//!    sub-steps. Every listed contact has bounced in its solve; what is left is a pair the
//!    step did not list (a ball struck within the step, running into a neighbour it was not
//!    heading for), which is set apart to touching and bounces now.
//! 6. **Store** (`ContactSolver::store`): each contact's impulse goes into the warm-start
//!    memory for the next step.
//! 7. **Sleep** (`ContactSolver::fall_asleep`): an island whose balls have all been slow for
//!    long enough sleeps (`super::sleep` has the rule). A sleeping ball takes no part in the
//!    stages above until an awake ball can touch it, which the grid's pairs show in step 1,
//!    and a step in which every ball sleeps does nothing at all.
//!
//! Everything happens in a fixed order (the grid's), so the same balls give the same bytes.

use std::ops::Range;

use super::grid::Grid;
use super::sleep::Sleep;
use crate::physics::ball::{mass, Ball};
use crate::physics::effects::Effects;
use crate::physics::floor::Floor;
use crate::physics::integrate::integrator::{Forces, Movable};
use crate::physics::maths;
use crate::physics::motion::Motion;
use crate::physics::tolerances::{
    LESSON_GRAVITY, LOADED_VELOCITY_PASSES, MAX_PAIRS_PER_BALL, PAIR_MARGIN, PUSH, REST_SPEED,
    SLEEP_FRAMES, SLEEP_SPEED, SLOP, TOUCHES_PER_CONTACT,
};
use crate::physics::vec2::Vec2;
use crate::physics::walls::Walls;
use crate::work::{tally, Work};

/// The golden angle, radians: successive multiples of it spread evenly round a circle.
const GOLDEN_ANGLE: f64 = 2.399_963_229_728_653;

/// A ball as the solver moves it: centre, velocity and radius, without the trail (which
/// the solver never reads), so its copy of the balls in grid order is all it sweeps.
#[derive(Clone, Copy, Debug)]
struct Body {
    /// Centre, px.
    position: Vec2,
    /// Velocity, px/frame.
    velocity: Vec2,
    /// Radius, px.
    radius: f64,
}

impl Body {
    fn of(ball: &Ball) -> Body {
        Body {
            position: ball.position(),
            velocity: ball.velocity(),
            radius: ball.radius,
        }
    }
}

impl Movable for Body {
    fn motion(&mut self) -> [&mut f64; 4] {
        let Body {
            position, velocity, ..
        } = self;
        [
            &mut position.x,
            &mut position.y,
            &mut velocity.x,
            &mut velocity.y,
        ]
    }
}

/// The sub-step the velocity pass works in.
#[derive(Clone, Copy, Debug)]
struct SubStep {
    /// Length, frames.
    h: f64,
    /// Whether gravity presses the balls together. Only then does a contact carry a load
    /// from one sub-step to the next: without it every contact's push is an impact, and
    /// pushing again would only add energy for the next pass to take back.
    loaded: bool,
    /// Below this parting speed, px/frame, a contact does not bounce.
    rest_speed: f64,
}

impl SubStep {
    /// Velocity passes per sub-step: [`LOADED_VELOCITY_PASSES`] when gravity loads the
    /// contacts, else the one a bounce needs.
    fn velocity_passes(self) -> u32 {
        if self.loaded {
            LOADED_VELOCITY_PASSES
        } else {
            1
        }
    }
}

/// How the steps of one frame move the balls, worked out once per frame.
#[derive(Clone, Copy, Debug)]
struct Stepping<'a> {
    /// The scene's integrator and iterations.
    motion: &'a Motion,
    /// Steps in the frame.
    steps: u32,
    /// Length of a step, frames.
    dt: f64,
    /// Gravity and drag over a whole step, and over one sub-step.
    whole: Forces,
    forces: Forces,
    sub: SubStep,
    /// Whether no gravity or drag acts, so every ball flies straight between contacts.
    free: bool,
    /// Below this speed, px/frame, a ball counts as still (0 without gravity: nothing sleeps).
    sleep_speed: f64,
}

impl Stepping<'_> {
    fn new<'a>(effects: &Effects, motion: &'a Motion) -> Stepping<'a> {
        let (steps, whole) = motion.plan(effects);
        let forces = Forces::new(effects).split(steps * motion.iterations);
        let gravity = gravity(effects);
        Stepping {
            motion,
            steps,
            dt: 1.0 / f64::from(steps),
            whole,
            forces,
            sub: SubStep {
                h: forces.dt,
                loaded: gravity > 0.0,
                rest_speed: REST_SPEED * gravity / LESSON_GRAVITY,
            },
            free: whole.gravity.is_none() && whole.drag.is_none(),
            sleep_speed: SLEEP_SPEED * gravity / LESSON_GRAVITY,
        }
    }
}

/// The strength of the scene's gravity, px/frame² (0 without).
fn gravity(effects: &Effects) -> f64 {
    effects.gravity.map_or(0.0, |g| g.length())
}

/// What decides, as contacts are found, whether one can touch within the step.
#[derive(Clone, Copy, Debug)]
struct Lookahead {
    /// Length of the step, frames.
    dt: f64,
    /// How far gravity alone can move a ball in the step, px.
    fall: f64,
}

impl Lookahead {
    fn new(effects: &Effects, dt: f64) -> Lookahead {
        let fall = gravity(effects) * dt * dt;
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

/// A contact between balls `a` and `b`, the normal pointing from `a` to `b`.
#[derive(Clone, Copy, Debug)]
struct PairContact {
    a: usize,
    b: usize,
    /// Sum of the radii, px.
    reach: f64,
    state: ContactState,
    /// 1 / mass of each ball.
    inverse_a: f64,
    inverse_b: f64,
}

/// A contact between ball `ball` and a wall or floor, seen as a line that does not move:
/// the gap is `centre · normal − offset`, the normal pointing into the free side.
#[derive(Clone, Copy, Debug)]
struct FixedContact {
    ball: usize,
    offset: f64,
    state: ContactState,
}

/// What every contact tracks while it is solved.
#[derive(Clone, Copy, Debug)]
struct ContactState {
    normal: Vec2,
    /// Gap at the start of the sub-step, px (negative: overlap).
    separation: f64,
    restitution: f64,
    /// `1 / (1/m_a + 1/m_b)`: the impulse that changes the relative normal speed by 1.
    mass: f64,
    /// Total impulse along the normal in this sub-step, never negative.
    impulse: f64,
    /// Names the contact from step to step, for the warm start.
    key: u64,
}

/// The gap between two balls, px (negative: overlap), and the normal from the first to the
/// second.
#[derive(Clone, Copy, Debug)]
struct Gap {
    separation: f64,
    normal: Vec2,
}

/// The contact solver. A scene without ball-ball collisions (or in exact mode) never
/// creates one.
#[derive(Clone, Debug)]
pub struct ContactSolver {
    settings: Settings,
    memory: WarmStartMemory,
    sleep: Sleep,
    scratch: Scratch,
}

/// The solver's settings, fixed when the scene builds it.
#[derive(Clone, Debug)]
struct Settings {
    /// Ball-ball restitution (0 to 1; the scene checks it).
    restitution: f64,
}

/// The warm-start memory, all that carries from one step to the next: the impulse each
/// contact ended the last step with, by contact key, sorted by key (only those above 0).
#[derive(Clone, Debug, Default)]
struct WarmStartMemory {
    impulses: Vec<(u64, f64)>,
}

/// The scratch space: buffers refilled every step, kept only so that a step allocates
/// nothing. No number in them carries from one step to the next.
#[derive(Clone, Debug, Default)]
struct Scratch {
    grid: Grid,
    /// The balls in the grid's order: what the solver moves. `grid.order()[k]` is the
    /// scene's index of `local[k]`.
    local: Vec<Body>,
    /// The pairs the grid finds, as places in its order.
    places: Vec<[u32; 2]>,
    /// Of those, the pairs that could not touch as the step began (see
    /// `Scratch::restitution`).
    unlisted: Vec<[u32; 2]>,
    /// This step's contacts, island by island once sorted.
    pairs: Vec<PairContact>,
    fixed: Vec<FixedContact>,
    /// The balls (of `local`) with a contact this step, island by island.
    active: Vec<usize>,
    /// Where each island's balls are in `active` and its contacts in `pairs` and `fixed`.
    islands: Vec<Island>,
    /// For finding the islands: the union–find tree, each ball's island, the balls with a
    /// contact in the order found, and the contacts in the order found.
    parent: Vec<usize>,
    island_of: Vec<usize>,
    with_contact: Vec<usize>,
    spare_pairs: Vec<PairContact>,
    spare_fixed: Vec<FixedContact>,
    /// The balls (of `local`) without a contact this step, at its start.
    untouched: Vec<usize>,
    /// Whether each ball (of `local`) sleeps this step; empty while none sleeps.
    asleep: Vec<bool>,
    /// Where an island's balls were (position, velocity), for when it cannot be solved
    /// touch by touch.
    saved: Vec<(Vec2, Vec2)>,
}

/// A group of balls joined by pair contacts, directly or through others, that touches no
/// ball outside it this step: what happens in one island cannot change another.
#[derive(Clone, Debug, Default)]
struct Island {
    balls: Range<usize>,
    pairs: Range<usize>,
    fixed: Range<usize>,
}

impl Island {
    fn ranges(&mut self) -> [&mut Range<usize>; 3] {
        [&mut self.balls, &mut self.pairs, &mut self.fixed]
    }
}

/// Some of the step's contacts, solved together: an island's (with its balls, as places in
/// the solver's copy), or a single pair's.
#[derive(Debug)]
struct ContactSet<'a> {
    balls: &'a [usize],
    pairs: &'a mut [PairContact],
    fixed: &'a mut [FixedContact],
}

/// The next place in `range`, which grows by it.
fn place(range: &mut Range<usize>) -> usize {
    range.end += 1;
    range.end - 1
}

/// `island_of` for a ball without contacts.
const NO_ISLAND: usize = usize::MAX;

/// `island_of` for a ball that sleeps (it has no contacts either, and does not move).
const ASLEEP: usize = usize::MAX - 1;

/// The ball that names `ball`'s island in the union–find tree `parent` (the island's first
/// ball), halving the path on the way so later searches are short.
fn root(parent: &mut [usize], mut ball: usize) -> usize {
    while parent[ball] != ball {
        parent[ball] = parent[parent[ball]];
        ball = parent[ball];
    }
    ball
}

impl ContactSolver {
    /// The solver's memory per ball at most, bytes, for the budget: the grid's, and up to
    /// `MAX_PAIRS_PER_BALL` contacts with their warm-start memory and the scratch they are
    /// solved in (measured: 3.3 KB a ball on 20,000 balls piled on one spot, where every
    /// ball has its most contacts; 3,500 B allows for that).
    pub const BYTES_PER_BALL: u64 = Grid::BYTES_PER_BALL + 3500;

    /// A solver for ball-ball contacts that keep `restitution` of the approach speed.
    pub fn new(restitution: f64) -> ContactSolver {
        ContactSolver {
            settings: Settings { restitution },
            memory: WarmStartMemory::default(),
            sleep: Sleep::default(),
            scratch: Scratch::default(),
        }
    }

    /// How many balls sleep now (`super::sleep`).
    pub fn sleeping(&self) -> usize {
        self.sleep.sleeping()
    }

    /// Advances every ball one frame (its substeps) under `effects`, with `motion`'s
    /// integrator and iterations; trails are the caller's business.
    pub fn step(&mut self, scene_balls: &mut [Ball], effects: &Effects, motion: &Motion) {
        let stepping = Stepping::new(effects, motion);
        self.sleep.fit(scene_balls.len());
        for _ in 0..stepping.steps {
            if self.sleep.everyone_asleep() {
                return; // nothing awake to move, or to wake anything
            }
            tally(Work::Contacts);
            self.prepare(scene_balls, effects, stepping.dt);
            // The solver works on its own copy of the balls, in the grid's order: contacts
            // then touch balls close together in memory, which keeps 100,000 balls fast.
            let mut local = std::mem::take(&mut self.scratch.local);
            self.scratch.solve_islands(&mut local, &stepping);
            self.scratch.move_untouched(&mut local, &stepping);
            let (walls, floors) = (effects.walls.as_ref(), &effects.floors);
            let order = self.scratch.grid.order();
            for (copy, &i) in local.iter_mut().zip(order) {
                copy_back(copy, &mut scene_balls[i], walls, floors);
            }
            let sleep = &mut self.sleep;
            let restitution = self.settings.restitution;
            self.scratch
                .restitution(&mut local, restitution, stepping.sub, |copy, k| {
                    copy_back(copy, &mut scene_balls[order[k]], walls, floors);
                    sleep.wake(order[k]); // it moved: its island wakes
                });
            self.scratch.local = local;
            self.store();
            self.fall_asleep(scene_balls, &stepping);
        }
    }

    /// Prepares the step `dt`: finds its contacts, gives each the impulse it ended the last
    /// step with, and sorts them into islands. Sleeping balls take no part, but an island an
    /// awake ball can touch wakes first.
    fn prepare(&mut self, balls: &[Ball], effects: &Effects, dt: f64) {
        let scratch = &mut self.scratch;
        let restitution = self.settings.restitution;
        scratch.find(balls, effects, dt, restitution, &mut self.sleep);
        self.memory.keep(self.sleep.woken());
        self.memory.recall(&mut scratch.pairs, &mut scratch.fixed);
        scratch.sort_into_islands(balls.len());
    }

    /// Stores each contact's impulse in the warm-start memory, for the next step, and the
    /// kept impulses of islands the restitution woke.
    fn store(&mut self) {
        let scratch = &self.scratch;
        self.memory.store(&scratch.pairs, &scratch.fixed);
        self.memory.keep(self.sleep.woken());
    }

    /// Counts each awake ball's calm steps, and puts to sleep each island of the step whose
    /// balls have all been calm for [`SLEEP_FRAMES`] (the rule: `super::sleep`).
    fn fall_asleep(&mut self, balls: &mut [Ball], stepping: &Stepping) {
        if stepping.sleep_speed == 0.0 {
            return; // without gravity nothing sleeps
        }
        self.sleep.count_calm_steps(balls, stepping.sleep_speed);
        let needed = SLEEP_FRAMES * stepping.steps;
        let scratch = &self.scratch;
        let order = scratch.grid.order();
        for island in &scratch.islands {
            let members = scratch.active[island.balls.clone()]
                .iter()
                .map(|&k| order[k]);
            if !members.clone().all(|i| self.sleep.calm_for(i, needed)) {
                continue;
            }
            let pairs = scratch.pairs[island.pairs.clone()].iter().map(|c| &c.state);
            let fixed = scratch.fixed[island.fixed.clone()].iter().map(|c| &c.state);
            let impulses = pairs.chain(fixed).map(|state| (state.key, state.impulse));
            let impulses = impulses.filter(|&(_, impulse)| impulse > 0.0);
            self.sleep.put_to_sleep(balls, members, impulses);
        }
    }
}

impl WarmStartMemory {
    /// Gives each contact the impulse it ended the last step with (0 if it is new).
    fn recall(&self, pairs: &mut [PairContact], fixed: &mut [FixedContact]) {
        let remembered = &self.impulses;
        let states = pairs.iter_mut().map(|c| &mut c.state);
        for state in states.chain(fixed.iter_mut().map(|c| &mut c.state)) {
            state.impulse = remembered
                .binary_search_by_key(&state.key, |&(key, _)| key)
                .map_or(0.0, |found| remembered[found].1);
        }
    }

    /// Keeps the contacts' impulses (those above 0) for the next step's warm start.
    fn store(&mut self, pairs: &[PairContact], fixed: &[FixedContact]) {
        self.impulses.clear();
        let states = pairs.iter().map(|c| &c.state);
        self.impulses.extend(
            states
                .chain(fixed.iter().map(|c| &c.state))
                .map(|state| (state.key, state.impulse))
                .filter(|&(_, impulse)| impulse > 0.0),
        );
        self.impulses.sort_unstable_by_key(|&(key, _)| key);
    }

    /// Takes the `kept` impulses (of islands that woke) into those remembered.
    fn keep(&mut self, kept: &mut Vec<(u64, f64)>) {
        if kept.is_empty() {
            return; // the common case: nothing woke
        }
        self.impulses.append(kept);
        self.impulses.sort_unstable_by_key(|&(key, _)| key);
        self.impulses.dedup_by_key(|&mut (key, _)| key);
    }
}

impl Scratch {
    /// The bounces left after the sub-steps. A ball struck within the step leaves in a new
    /// direction and can run into a neighbour it was not heading for when the contacts were
    /// found: that pair is not among them. Each such pair that ends the step overlapping
    /// beyond the slop is set apart to touching (positions only) and bounces now, by the
    /// same rule as any contact, so that no overlap outlives the step. Momentum is kept and
    /// kinetic energy does not rise. `moved` hears of each ball it moves (by its place).
    fn restitution(
        &self,
        balls: &mut [Body],
        restitution: f64,
        sub: SubStep,
        mut moved: impl FnMut(&Body, usize),
    ) {
        let order = self.grid.order();
        for &[a, b] in &self.unlisted {
            let (a, b) = (a as usize, b as usize);
            let (ball_a, ball_b) = (&balls[a], &balls[b]);
            if !deeper_than_slop(ball_a, ball_b, ball_a.radius + ball_b.radius) {
                continue; // the common case, without a square root
            }
            let gap = gap_between(balls, order, a, b);
            let mut contact = pair_contact(balls, order, restitution, a, b, gap);
            let pair = ContactSet {
                balls: &[],
                pairs: std::slice::from_mut(&mut contact),
                fixed: &mut [],
            };
            pair.relax(balls, Push::Whole);
            contact.state.separation = 0.0;
            let (ball_a, ball_b) = two(balls, a, b);
            contact.solve_velocity(ball_a, ball_b, sub);
            moved(ball_a, a);
            moved(ball_b, b);
        }
    }

    /// This step's contacts, each only if it can touch within the step `dt`: each awake
    /// ball's walls and floors, as the balls are copied into the grid's order; then the ball
    /// pairs from the grid, in its order, with `restitution`. First the grid's pairs wake
    /// each sleeping island an awake ball can touch.
    fn find(
        &mut self,
        balls: &[Ball],
        effects: &Effects,
        dt: f64,
        restitution: f64,
        sleep: &mut Sleep,
    ) {
        let lookahead = Lookahead::new(effects, dt);
        self.grid
            .rebuild_with_margins(balls, |ball| lookahead.margin(ball));
        let limit = MAX_PAIRS_PER_BALL.saturating_mul(balls.len());
        self.grid.overlapping_places(&mut self.places, limit);
        if sleep.anyone_asleep() {
            self.wake_touched(balls, lookahead, sleep);
        }
        self.copy_and_find_fixed(balls, effects, lookahead, sleep);
        self.find_pairs(lookahead, restitution);
    }

    /// Wakes each sleeping island that an awake ball can touch within the step, and then
    /// those its balls can touch, until none is left to wake.
    fn wake_touched(&self, balls: &[Ball], lookahead: Lookahead, sleep: &mut Sleep) {
        let order = self.grid.order();
        let mut woke = true;
        while woke {
            woke = false;
            for &[a, b] in &self.places {
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

    /// Copies each ball into `local` in the grid's order, and finds its walls and floors,
    /// in one pass. A sleeping ball is copied but has no contact; while any ball sleeps,
    /// `asleep` marks each (it is left empty otherwise: a scene where none sleeps pays
    /// nothing for it).
    fn copy_and_find_fixed(
        &mut self,
        balls: &[Ball],
        effects: &Effects,
        lookahead: Lookahead,
        sleep: &Sleep,
    ) {
        self.local.clear();
        self.fixed.clear();
        self.asleep.clear();
        let sleepers = sleep.anyone_asleep();
        for (k, &i) in self.grid.order().iter().enumerate() {
            let ball = &Body::of(&balls[i]);
            self.local.push(*ball);
            if sleepers {
                self.asleep.push(sleep.is_asleep(i));
                if sleep.is_asleep(i) {
                    continue;
                }
            }
            let centre = ball.position;
            let mut touch = |id: u64, normal: Vec2, surface: f64, restitution: f64| {
                let offset = surface + ball.radius;
                let separation = centre.dot(normal) - offset;
                let approach = ball.velocity.dot(normal);
                if lookahead.can_touch(separation, approach, PAIR_MARGIN * ball.radius) {
                    self.fixed.push(FixedContact {
                        ball: k,
                        offset,
                        state: ContactState::new(
                            normal,
                            separation,
                            restitution,
                            mass(ball.radius),
                            (i as u64) << 32 | (u64::from(u32::MAX) - id),
                        ),
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
            for (k, floor) in effects.floors.iter().enumerate() {
                tally(Work::Floor);
                let (normal, distance) = floor.nearest(centre);
                touch(
                    4 + k as u64,
                    normal,
                    centre.dot(normal) - distance,
                    floor.damping,
                );
            }
        }
    }

    /// The ball pairs the grid finds that can touch within the step, in its order, with
    /// `restitution`; the others are kept aside as `unlisted`.
    fn find_pairs(&mut self, lookahead: Lookahead, restitution: f64) {
        let (balls, order) = (&self.local, self.grid.order());
        // The grid names each pair by the balls' places in its order, which are their places
        // in `local`: `a < b`, close together in memory, no lookup needed.
        self.pairs.clear();
        self.unlisted.clear();
        let sleepers = !self.asleep.is_empty();
        for &[a, b] in &self.places {
            let (a, b) = (a as usize, b as usize);
            if sleepers && self.asleep[a] && self.asleep[b] {
                continue; // two sleeping balls: neither moves
            }
            let (ball_a, ball_b) = (&balls[a], &balls[b]);
            let gap = gap_between(balls, order, a, b);
            // (A sleeping ball and an awake one that can touch woke in `wake_touched`.)
            if lookahead.pair_can_touch(ball_a, ball_b, gap) {
                let contact = pair_contact(balls, order, restitution, a, b, gap);
                self.pairs.push(contact);
            } else {
                self.unlisted.push([a as u32, b as u32]);
            }
        }
    }

    /// Groups the balls with a contact this step into islands — balls joined by pair
    /// contacts, directly or through others — and lists each island's balls and contacts
    /// together, keeping their order within the island.
    fn sort_into_islands(&mut self, count: usize) {
        // Union–find: every ball starts as its own island; each pair contact joins two.
        let parent = &mut self.parent;
        parent.clear();
        parent.extend(0..count);
        for contact in &self.pairs {
            let (a, b) = (root(parent, contact.a), root(parent, contact.b));
            parent[a.max(b)] = a.min(b);
        }
        self.number_islands(count);
        // Turn the counts into empty ranges where each island's balls and contacts will be,
        // one island after another; placing one extends its island's range (a counting sort).
        let mut starts = [0; 3];
        for island in &mut self.islands {
            for (range, start) in island.ranges().into_iter().zip(&mut starts) {
                let count = range.end;
                *range = *start..*start;
                *start += count;
            }
        }
        let (islands, island_of) = (&mut self.islands, &self.island_of);
        self.active.resize(self.with_contact.len(), 0);
        for &ball in &self.with_contact {
            self.active[place(&mut islands[island_of[ball]].balls)] = ball;
        }
        self.spare_pairs.clone_from(&self.pairs);
        for contact in &self.spare_pairs {
            self.pairs[place(&mut islands[island_of[contact.a]].pairs)] = *contact;
        }
        self.spare_fixed.clone_from(&self.fixed);
        for contact in &self.spare_fixed {
            self.fixed[place(&mut islands[island_of[contact.ball]].fixed)] = *contact;
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
    fn number_islands(&mut self, count: usize) {
        let (parent, island_of) = (&mut self.parent, &mut self.island_of);
        island_of.clear();
        if self.asleep.is_empty() {
            island_of.resize(count, NO_ISLAND);
        } else {
            let mark = |&asleep: &bool| if asleep { ASLEEP } else { NO_ISLAND };
            island_of.extend(self.asleep.iter().map(mark));
        }
        self.islands.clear();
        self.with_contact.clear();
        let with_contact = self.pairs.iter().flat_map(|c| [c.a, c.b]);
        for ball in with_contact.chain(self.fixed.iter().map(|c| c.ball)) {
            if island_of[ball] != NO_ISLAND {
                continue;
            }
            // The tree's root names the island; the first of its balls seen numbers it.
            let first = root(parent, ball);
            for member in [first, ball] {
                if island_of[member] == NO_ISLAND {
                    island_of[member] = match island_of[first] {
                        NO_ISLAND => {
                            self.islands.push(Island::default());
                            self.islands.len() - 1
                        }
                        island => island,
                    };
                    self.islands[island_of[member]].balls.end += 1;
                    self.with_contact.push(member);
                }
            }
        }
        for contact in &self.pairs {
            self.islands[island_of[contact.a]].pairs.end += 1;
        }
        for contact in &self.fixed {
            self.islands[island_of[contact.ball]].fixed.end += 1;
        }
    }

    /// Solves every island, one after another: touch by touch if `stepping` is free and the
    /// island allows, in sub-steps otherwise. Islands share no ball, so each is solved on
    /// its own, all its sub-steps at once, while its few balls and contacts are in the cache.
    fn solve_islands(&mut self, balls: &mut [Body], stepping: &Stepping) {
        for island in &self.islands {
            let mut set = ContactSet {
                balls: &self.active[island.balls.clone()],
                pairs: &mut self.pairs[island.pairs.clone()],
                fixed: &mut self.fixed[island.fixed.clone()],
            };
            if stepping.free && set.solve_free_island(balls, stepping, &mut self.saved) {
                continue;
            }
            set.solve_in_substeps(balls, stepping);
        }
    }

    /// A ball that can touch nothing in this step takes it in one go, as in the lesson (a
    /// sleeping one does not move).
    /// They are listed first without a branch (about half the balls of a gas, at random,
    /// which a branch would mispredict).
    fn move_untouched(&mut self, balls: &mut [Body], stepping: &Stepping) {
        self.untouched.resize(balls.len(), 0);
        let mut count = 0;
        for (k, &island) in self.island_of.iter().enumerate() {
            self.untouched[count] = k;
            count += usize::from(island == NO_ISLAND);
        }
        for &k in &self.untouched[..count] {
            stepping
                .motion
                .integrator
                .step(&mut balls[k], &stepping.whole);
        }
    }
}

/// Puts the solver's `copy` of a ball back into the scene's `ball`, inside the `walls`.
fn copy_back(copy: &Body, ball: &mut Ball, walls: Option<&Walls>, floors: &[Floor]) {
    let from = ball.position();
    let (position, velocity) = (copy.position, copy.velocity);
    (ball.x, ball.y, ball.vx, ball.vy) = (position.x, position.y, velocity.x, velocity.y);
    for floor in floors {
        floor.undo_crossing(ball, from);
    }
    // Last: whatever put it back, the box holds it.
    if let Some(walls) = walls {
        ball.keep_inside(walls);
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
        state: ContactState::new(gap.normal, gap.separation, restitution, mass, key),
        inverse_a: 1.0 / mass_a,
        inverse_b: 1.0 / mass_b,
    }
}

impl ContactSet<'_> {
    /// The island's `iterations` sub-steps, Box2D v3's soft step: each integrates the
    /// velocities, warm starts, solves, integrates the positions and relaxes.
    fn solve_in_substeps(&mut self, balls: &mut [Body], stepping: &Stepping) {
        for _ in 0..stepping.motion.iterations {
            self.integrate_velocities(balls, stepping);
            self.warm_start(balls);
            for _ in 0..stepping.sub.velocity_passes() {
                self.solve(balls, stepping.sub);
            }
            self.integrate_positions(balls, stepping);
            self.relax(balls, Push::Part);
        }
    }

    /// The integrator adds a sub-step's gravity and drag to each ball's velocity (before
    /// the flight, for the integrators that kick first).
    fn integrate_velocities(&self, balls: &mut [Body], stepping: &Stepping) {
        for &i in self.balls {
            stepping
                .motion
                .integrator
                .kick_before(&mut balls[i], &stepping.forces);
        }
    }

    /// Each ball flies a sub-step with its solved velocity (then takes the kick of the
    /// integrators that kick after).
    fn integrate_positions(&self, balls: &mut [Body], stepping: &Stepping) {
        let (integrator, forces) = (stepping.motion.integrator, &stepping.forces);
        for &i in self.balls {
            integrator.fly(&mut balls[i], forces, forces.dt);
            integrator.kick_after(&mut balls[i], forces);
        }
    }

    /// Applies each contact's impulse of the last sub-step again, and measures its gap anew.
    fn warm_start(&mut self, balls: &mut [Body]) {
        for contact in self.pairs.iter_mut() {
            let (a, b) = two(balls, contact.a, contact.b);
            let gap = pair_gap(a, b, contact.reach, || contact.state.normal);
            (contact.state.separation, contact.state.normal) = (gap.separation, gap.normal);
            contact.push_velocities(a, b, contact.state.impulse);
        }
        for contact in self.fixed.iter_mut() {
            let ball = &mut balls[contact.ball];
            contact.state.separation = contact.gap(ball);
            let impulse = contact.state.impulse / contact.state.mass;
            ball.velocity += impulse * contact.state.normal;
        }
    }

    /// The velocity pass: one Gauss–Seidel sweep over every contact's velocity.
    fn solve(&mut self, balls: &mut [Body], sub: SubStep) {
        for contact in self.pairs.iter_mut() {
            let (a, b) = two(balls, contact.a, contact.b);
            contact.solve_velocity(a, b, sub);
        }
        for contact in self.fixed.iter_mut() {
            contact.solve_velocity(&mut balls[contact.ball], sub);
        }
    }

    /// The position pass: one Gauss–Seidel pass that pushes contacts overlapping beyond the
    /// slop apart by `push`, positions only.
    fn relax(&self, balls: &mut [Body], push: Push) {
        for contact in self.pairs.iter() {
            let (a, b) = two(balls, contact.a, contact.b);
            if !deeper_than_slop(a, b, contact.reach) {
                continue; // the common case, without a square root
            }
            let allowed = SLOP * contact.reach / 2.0;
            let gap = pair_gap(a, b, contact.reach, || contact.state.normal);
            if gap.separation < -allowed {
                // Each ball moves its share: the lighter one more.
                let push = push.distance(gap.separation, allowed) * contact.state.mass;
                let (share_a, share_b) = (push * contact.inverse_a, push * contact.inverse_b);
                a.position -= share_a * gap.normal;
                b.position += share_b * gap.normal;
            }
        }
        for contact in self.fixed.iter() {
            let ball = &mut balls[contact.ball];
            let separation = contact.gap(ball);
            let allowed = SLOP * ball.radius;
            if separation < -allowed {
                let push = push.distance(separation, allowed);
                ball.position += push * contact.state.normal;
            }
        }
    }

    /// Solves an island touch by touch, if it can. When no force acts (the caller checks) the
    /// balls fly in straight lines, so when each contact touches has a closed form: the
    /// island flies to the first touch, that contact alone is solved there, and so on to the
    /// end of the step, instead of every contact once per sub-step.
    ///
    /// Balls that start the step overlapping beyond the slop are first set apart, to touching
    /// (positions only): in a gas that is nearly always a pair the last step did not list
    /// because it was not closing, whose balls then met after one of them was struck. Returns
    /// `false`, with the balls as they were, when a contact still overlaps after that (a ball
    /// pushed into a third: the sub-steps' gentler position passes sort that out) or the
    /// island has more than [`TOUCHES_PER_CONTACT`] touches per contact (a cluster that keeps
    /// colliding): those take the sub-steps. `saved` is scratch space.
    fn solve_free_island(
        &mut self,
        balls: &mut [Body],
        stepping: &Stepping,
        saved: &mut Vec<(Vec2, Vec2)>,
    ) -> bool {
        let (active, whole) = (self.balls, &stepping.whole);
        saved.clear();
        saved.extend(
            active
                .iter()
                .map(|&i| (balls[i].position, balls[i].velocity)),
        );
        let fly = |balls: &mut [Body], time: f64| {
            for &i in active {
                stepping.motion.integrator.fly(&mut balls[i], whole, time);
            }
        };
        // Positions only, so no kinetic energy is added; an approaching pair then touches now.
        self.relax(balls, Push::Whole);
        let mut left = whole.dt;
        for _ in 0..TOUCHES_PER_CONTACT * (self.pairs.len() + self.fixed.len()) {
            let Some((first, touch)) = self.first_touch(balls) else {
                break;
            };
            if touch >= left {
                fly(balls, left);
                return true;
            }
            fly(balls, touch);
            left -= touch;
            // The rest of the step after the touch is the sub-step the contact is solved for.
            self.solve_touch(
                first,
                balls,
                SubStep {
                    h: left,
                    ..stepping.sub
                },
            );
        }
        for (&i, &(position, velocity)) in active.iter().zip(saved.iter()) {
            (balls[i].position, balls[i].velocity) = (position, velocity);
        }
        false
    }

    /// Solves contact `first` (of the pairs then the fixed contacts, numbered in that
    /// order), which touches now, for the sub-step `sub`.
    fn solve_touch(&mut self, first: usize, balls: &mut [Body], sub: SubStep) {
        // They touch now: a rounding error's gap must not spare them the bounce.
        if first < self.pairs.len() {
            let contact = &mut self.pairs[first];
            let (a, b) = two(balls, contact.a, contact.b);
            let gap = pair_gap(a, b, contact.reach, || contact.state.normal);
            (contact.state.separation, contact.state.normal) =
                (gap.separation.min(0.0), gap.normal);
            contact.solve_velocity(a, b, sub);
        } else {
            let contact = &mut self.fixed[first - self.pairs.len()];
            let ball = &mut balls[contact.ball];
            contact.state.separation = contact.gap(ball).min(0.0);
            contact.solve_velocity(ball, sub);
        }
    }

    /// The contact of the pairs then the fixed contacts (numbered in that order) that
    /// touches first, and when; `None` if one overlaps beyond the slop.
    fn first_touch(&self, balls: &[Body]) -> Option<(usize, f64)> {
        let touches = self.pairs.iter().map(|contact| contact.touch_time(balls));
        let touches = touches.chain(
            self.fixed
                .iter()
                .map(|contact| contact.touch_time(&balls[contact.ball])),
        );
        let mut first = (0, f64::INFINITY);
        for (k, touch) in touches.enumerate() {
            let touch = touch?;
            if touch < first.1 {
                first = (k, touch);
            }
        }
        Some(first)
    }
}

/// How far the position pass moves balls that overlap beyond the slop.
#[derive(Clone, Copy, Debug)]
enum Push {
    /// [`PUSH`] of the overlap beyond the slop: a sub-step's share, so that a ball pushed by
    /// many contacts does not overshoot.
    Part,
    /// All of it, to touching: for the few pairs of an island solved touch by touch.
    Whole,
}

impl Push {
    /// The distance to move two balls (or a ball and a wall) apart that are `separation`
    /// apart (negative), where `allowed` is the slop.
    fn distance(self, separation: f64, allowed: f64) -> f64 {
        match self {
            Push::Part => -(separation + allowed) * PUSH,
            Push::Whole => -separation,
        }
    }
}

impl ContactState {
    fn new(normal: Vec2, separation: f64, restitution: f64, mass: f64, key: u64) -> ContactState {
        ContactState {
            normal,
            separation,
            restitution,
            mass,
            impulse: 0.0,
            key,
        }
    }

    /// The velocity pass for one contact whose relative normal speed is `speed` (negative:
    /// closing): updates the running total and returns the impulse to apply now.
    fn impulse_change(&mut self, speed: f64, sub: SubStep) -> f64 {
        // It bounces if it touches within the sub-step closing fast enough for its rebound,
        // `e` times the approach speed now, to beat the rest speed. Now, not when the contact
        // was found: a ball struck in this step passes the blow on to the next (a resting
        // ball hit from above bounces off the floor and throws the striker back up).
        let rebound = -self.restitution * speed;
        let bounces = rebound > sub.rest_speed && self.separation + speed * sub.h < 0.0;
        let target = if bounces {
            rebound
        } else {
            // Resting, or speculative: close by no more than the gap within the sub-step.
            -self.separation.max(0.0) / sub.h
        };
        let total = (self.impulse + self.mass * (target - speed)).max(0.0);
        let change = total - self.impulse;
        // A bounce is over once the balls part: it is not pushed again in the next sub-step.
        self.impulse = if bounces || !sub.loaded { 0.0 } else { total };
        change
    }
}

impl PairContact {
    /// The velocity pass for this contact.
    fn solve_velocity(&mut self, a: &mut Body, b: &mut Body, sub: SubStep) {
        let speed = (b.velocity - a.velocity).dot(self.state.normal);
        let change = self.state.impulse_change(speed, sub);
        self.push_velocities(a, b, change);
    }

    /// When the balls, flying straight, first touch (infinite if never, 0 if they touch
    /// now); `None` if they overlap by more than the slop, which the position pass handles.
    fn touch_time(&self, balls: &[Body]) -> Option<f64> {
        let (a, b) = (&balls[self.a], &balls[self.b]);
        let p = b.position - a.position;
        let v = b.velocity - a.velocity;
        // |p + v·t| = reach: a quadratic in t, whose smaller root is the touch.
        let gap = p.length_squared() - self.reach * self.reach;
        let closing = p.dot(v);
        if gap <= 0.0 {
            // A pair that has just bounced touches still, or overlaps by a rounding error.
            let closest = self.reach * (1.0 - SLOP / 2.0);
            return match closing {
                _ if p.length_squared() < closest * closest => None,
                c if c < 0.0 => Some(0.0),
                _ => Some(f64::INFINITY),
            };
        }
        let discriminant = closing * closing - v.length_squared() * gap;
        if closing >= 0.0 || discriminant < 0.0 {
            return Some(f64::INFINITY);
        }
        // `gap / (−p·v + √…)` is that root without cancellation.
        Some(gap / (-closing + discriminant.sqrt()))
    }

    /// Gives `b` the impulse `impulse` along the normal and `a` the opposite one.
    fn push_velocities(&self, a: &mut Body, b: &mut Body, impulse: f64) {
        let normal = self.state.normal;
        let (da, db) = (impulse * self.inverse_a, impulse * self.inverse_b);
        a.velocity -= da * normal;
        b.velocity += db * normal;
    }
}

impl FixedContact {
    /// The velocity pass for this contact.
    fn solve_velocity(&mut self, ball: &mut Body, sub: SubStep) {
        let normal = self.state.normal;
        let change = self.state.impulse_change(ball.velocity.dot(normal), sub) / self.state.mass;
        ball.velocity += change * normal;
    }

    /// When the ball, flying straight, reaches the line (infinite if never, 0 if it touches
    /// now); `None` if it is past the line by more than the slop.
    fn touch_time(&self, ball: &Body) -> Option<f64> {
        let separation = self.gap(ball);
        let approach = ball.velocity.dot(self.state.normal);
        match separation {
            s if s < -SLOP * ball.radius => None,
            _ if approach >= 0.0 => Some(f64::INFINITY),
            s => Some((-s / approach).max(0.0)),
        }
    }

    /// The gap between the ball and the line, px.
    fn gap(&self, ball: &Body) -> f64 {
        ball.position.dot(self.state.normal) - self.offset
    }
}

/// Whether balls `a` and `b`, whose radii add up to `reach`, overlap by more than the slop
/// ([`SLOP`] of their mean radius). Compared squared, without a square root.
fn deeper_than_slop(a: &Body, b: &Body, reach: f64) -> bool {
    let closest = reach - SLOP * reach / 2.0;
    (b.position - a.position).length_squared() < closest * closest
}

/// The gap between two balls whose radii add up to `reach`, and the normal from `a` to `b`
/// (`fallback()` if their centres coincide).
fn pair_gap(a: &Body, b: &Body, reach: f64, fallback: impl FnOnce() -> Vec2) -> Gap {
    let d = b.position - a.position;
    let distance = d.length_squared().sqrt();
    if distance > 0.0 {
        let normal = d / distance;
        Gap {
            separation: distance - reach,
            normal,
        }
    } else {
        Gap {
            separation: -reach,
            normal: fallback(),
        }
    }
}

/// Balls `a` and `b` (`a < b`), both mutable.
fn two(balls: &mut [Body], a: usize, b: usize) -> (&mut Body, &mut Body) {
    let (head, tail) = balls.split_at_mut(b);
    (&mut head[a], &mut tail[0])
}

/// The normal for two balls at exactly the same centre, where the line between centres has
/// no direction. Any fixed direction would separate a pair, but a heap spawned on one spot
/// would then spread along a single line; so ball `j` leaves at `j` golden angles, which
/// fans successive balls out evenly round the circle, and depends on nothing but `j`.
fn coincident_normal(j: usize) -> Vec2 {
    let angle = GOLDEN_ANGLE * j as f64;
    Vec2::new(maths::cos(angle), maths::sin(angle))
}
