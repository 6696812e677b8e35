//! The contact solver: in the stepped (clamp) mode, a scene with ball-ball collisions has every
//! contact — ball with ball, ball with wall, ball with floor — solved together and
//! iteratively, so that a pile carries its own weight and comes to rest.
//!
//! It is Box2D's *sequential impulses* (Erin Catto, GDC 2006) for frictionless discs, with
//! warm starting, a rest speed below which contacts do not bounce, and Box2D v2.4's position
//! pass; and it iterates the way Box2D v3's *soft step* and "small steps" XPBD do: each
//! iteration is a short sub-step (gravity, one velocity pass, flight, one position pass),
//! with the contacts found once per step. `docs/contacts.md` has the measurements that chose
//! this over more passes per step, softer contacts, and plain substeps.
//!
//! One step:
//!
//! 1. **Find contacts** where the balls are: pairs, walls and floors that can touch within the
//!    step (the grid grows each ball by the distance it can travel). A contact with a gap is
//!    *speculative*: it only forbids closing by more than the gap. The solver works on a copy
//!    of the balls in the grid's order, and a ball that can touch nothing takes the whole step
//!    at once, as in the lesson.
//! 2. **Islands**: the balls with contacts fall into islands, balls joined by pair contacts
//!    directly or through others. Islands share no ball, so each is solved on its own, all
//!    its sub-steps at once, while its balls are in the cache (the numbers are the same as
//!    one sweep over every contact).
//! 3. **Without gravity or drag**, balls fly straight between contacts, so an island is
//!    solved touch by touch: it flies to the time its first contact touches (a closed
//!    form), that contact alone is solved, and so on to the end of the step. Balls that
//!    start it overlapping are first set apart to touching. An island that still overlaps,
//!    or keeps colliding, is put back and takes the sub-steps.
//! 4. **Sub-steps**: otherwise, for each island, `iterations` times, for a sub-step `h` of
//!    the step:
//!    - **Kick**: the integrator adds `h`'s gravity and drag to every velocity.
//!    - **Warm start** (under gravity only): each contact pushes again with its total impulse
//!      of the sub-step before (the previous step's, at first). A stack that stood then
//!      stands now, instead of its weight having to travel up through it again, one ball per
//!      pass. A bounce is not carried: it is over once the balls part.
//!    - **Velocity pass** (Gauss–Seidel): contact after contact, the impulse that brings its
//!      relative normal speed to its target, added to its running total, which is never
//!      negative (contacts push, never pull). A contact that touches within `h` bounces if
//!      `e` times its approach speed now beats the rest speed: that is its target. Slower,
//!      it stops (resting balls do not bounce, so a pile settles instead of buzzing).
//!    - **Fly** `h` with the solved velocities.
//!    - **Position pass**: overlap beyond a small slop is partly pushed out, moving positions
//!      only, so no kinetic energy is added.
//!
//! Everything happens in a fixed order (the grid's), so the same balls give the same bytes.

use std::ops::Range;

use super::grid::Grid;
use crate::physics::ball::Ball;
use crate::physics::effects::Effects;
use crate::physics::integrate::integrator::{Forces, Movable};
use crate::physics::maths;
use crate::physics::motion::Motion;
use crate::physics::tolerances::{
    LESSON_GRAVITY, MAX_PAIRS_PER_BALL, PAIR_MARGIN, PUSH, REST_SPEED, SLOP, TOUCHES_PER_CONTACT,
};
use crate::physics::walls::Walls;
use crate::physics::work::{tally, Work};

/// The golden angle, radians: successive multiples of it spread evenly round a circle.
const GOLDEN_ANGLE: f64 = 2.399_963_229_728_653;

/// A ball as the solver moves it: centre, velocity and radius, without the trail (which
/// the solver never reads), so its copy of the balls in grid order is all it sweeps.
#[derive(Clone, Copy, Debug)]
struct Body {
    x: f64,
    y: f64,
    vx: f64,
    vy: f64,
    radius: f64,
}

impl Body {
    fn of(ball: &Ball) -> Body {
        Body {
            x: ball.x,
            y: ball.y,
            vx: ball.vx,
            vy: ball.vy,
            radius: ball.radius,
        }
    }
}

impl Movable for Body {
    fn motion(&mut self) -> [&mut f64; 4] {
        [&mut self.x, &mut self.y, &mut self.vx, &mut self.vy]
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
    normal: [f64; 2],
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

/// The contact solver, with buffers and last step's impulses kept from step to step. A scene
/// without ball-ball collisions (or in exact mode) never creates one.
#[derive(Clone, Debug)]
pub struct ContactSolver {
    /// Ball-ball restitution (0 to 1; the scene checks it).
    restitution: f64,
    grid: Grid,
    pairs: Vec<PairContact>,
    fixed: Vec<FixedContact>,
    /// Last step's impulses by contact key, sorted by key: the warm start.
    remembered: Vec<(u64, f64)>,
    /// The balls in the grid's order: what the solver moves. `grid.order()[k]` is the
    /// scene's index of `local[k]`.
    local: Vec<Body>,
    /// The pairs the grid finds, as places in its order.
    places: Vec<[u32; 2]>,
    /// Of those, the pairs that could not touch as the step began (see `settle_unlisted`).
    unlisted: Vec<[u32; 2]>,
    /// The balls (of `local`) with a contact this step, island by island.
    active: Vec<usize>,
    /// Where each island's balls are in `active` and its contacts in `pairs` and `fixed`.
    islands: Vec<Island>,
    /// Scratch space for finding the islands: the union–find tree, each ball's island, and
    /// the contacts in the order found.
    parent: Vec<usize>,
    island_of: Vec<usize>,
    /// The balls with a contact, in order.
    with_contact: Vec<usize>,
    /// Scratch space: the balls (of `local`) without a contact this step, at its start.
    untouched: Vec<usize>,
    spare_pairs: Vec<PairContact>,
    spare_fixed: Vec<FixedContact>,
    /// Where an island's balls were, for when it cannot be solved touch by touch.
    saved: Vec<[f64; 4]>,
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

/// The next place in `range`, which grows by it.
fn place(range: &mut Range<usize>) -> usize {
    range.end += 1;
    range.end - 1
}

/// `island_of` for a ball without contacts.
const NO_ISLAND: usize = usize::MAX;

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
    /// A solver for ball-ball contacts that keep `restitution` of the approach speed.
    pub fn new(restitution: f64) -> ContactSolver {
        ContactSolver {
            restitution,
            grid: Grid::new(),
            pairs: Vec::new(),
            fixed: Vec::new(),
            remembered: Vec::new(),
            local: Vec::new(),
            places: Vec::new(),
            unlisted: Vec::new(),
            active: Vec::new(),
            islands: Vec::new(),
            parent: Vec::new(),
            island_of: Vec::new(),
            with_contact: Vec::new(),
            untouched: Vec::new(),
            spare_pairs: Vec::new(),
            spare_fixed: Vec::new(),
            saved: Vec::new(),
        }
    }

    /// Advances every ball one frame (its substeps) under `effects`, with `motion`'s
    /// integrator and iterations; trails are the caller's business.
    pub fn step(&mut self, scene_balls: &mut [Ball], effects: &Effects, motion: &Motion) {
        let (steps, whole) = motion.plan(effects);
        let iterations = motion.iterations;
        let forces = Forces::new(effects).split(steps * iterations);
        let gravity = effects.gravity.map_or(0.0, |[gx, gy]| maths::hypot(gx, gy));
        let sub = SubStep {
            h: forces.dt,
            loaded: gravity > 0.0,
            rest_speed: REST_SPEED * gravity / LESSON_GRAVITY,
        };
        let dt = 1.0 / f64::from(steps);
        // Without gravity or drag every ball flies in a straight line between contacts.
        let free = whole.gravity.is_none() && whole.drag.is_none();
        for _ in 0..steps {
            tally(Work::Contacts);
            self.find(scene_balls, effects, dt);
            self.recall();
            self.sort_into_islands(scene_balls.len());
            // The solver works on its own copy of the balls, in the grid's order: contacts
            // then touch balls close together in memory, which keeps 100,000 balls fast.
            let mut local = std::mem::take(&mut self.local);
            let balls = &mut local[..];
            // Islands share no ball, so each is solved on its own, all its sub-steps at once,
            // while its few balls and contacts are in the cache.
            for island in &self.islands {
                let active = &self.active[island.balls.clone()];
                let pairs = &mut self.pairs[island.pairs.clone()];
                let fixed = &mut self.fixed[island.fixed.clone()];
                let island = (active, &mut *pairs, &mut *fixed);
                let setting = (motion, &whole, sub);
                if free && solve_free_island(island, balls, setting, &mut self.saved) {
                    continue;
                }
                for _ in 0..iterations {
                    for &i in active {
                        motion.integrator.kick_before(&mut balls[i], &forces);
                    }
                    warm_start(pairs, fixed, balls);
                    solve_velocities(pairs, fixed, balls, sub);
                    for &i in active {
                        motion.integrator.fly(&mut balls[i], &forces, forces.dt);
                        motion.integrator.kick_after(&mut balls[i], &forces);
                    }
                    solve_positions(pairs, fixed, balls, Push::Part);
                }
            }
            // A ball that can touch nothing in this step takes it in one go, as in the lesson.
            // They are listed first without a branch (about half the balls of a gas, at
            // random, which a branch would mispredict).
            self.untouched.resize(local.len(), 0);
            let mut count = 0;
            for (k, &island) in self.island_of.iter().enumerate() {
                self.untouched[count] = k;
                count += usize::from(island == NO_ISLAND);
            }
            for &k in &self.untouched[..count] {
                motion.integrator.step(&mut local[k], &whole);
            }
            let walls = effects.walls.as_ref();
            for (copy, &i) in local.iter_mut().zip(self.grid.order()) {
                copy_back(copy, &mut scene_balls[i], walls);
            }
            self.settle_unlisted(&mut local, sub, |copy, k| {
                copy_back(copy, &mut scene_balls[self.grid.order()[k]], walls);
            });
            self.local = local;
            self.remember();
        }
    }

    /// A ball struck within the step leaves in a new direction and can run into a neighbour
    /// it was not heading for when the contacts were found: that pair is not among them. Each
    /// such pair that ends the step overlapping beyond the slop is set apart to touching
    /// (positions only) and bounces now, by the same rule as any contact, so that no overlap
    /// outlives the step. Momentum is kept and kinetic energy does not rise.
    /// `moved` hears of each ball it moves (by its place).
    fn settle_unlisted(
        &self,
        balls: &mut [Body],
        sub: SubStep,
        mut moved: impl FnMut(&Body, usize),
    ) {
        for &[a, b] in &self.unlisted {
            let (a, b) = (a as usize, b as usize);
            let (ball_a, ball_b) = (&balls[a], &balls[b]);
            if !deeper_than_slop(ball_a, ball_b, ball_a.radius + ball_b.radius) {
                continue; // the common case, without a square root
            }
            let order = self.grid.order();
            let gap = gap_between(balls, order, a, b);
            let mut contact = pair_contact(balls, order, self.restitution, (a, b), gap);
            solve_positions(std::slice::from_ref(&contact), &[], balls, Push::Whole);
            contact.state.separation = 0.0;
            let (ball_a, ball_b) = two(balls, a, b);
            contact.solve_velocity(ball_a, ball_b, sub);
            moved(ball_a, a);
            moved(ball_b, b);
        }
    }

    /// This step's contacts, each only if it can touch within the step `dt`: each ball's
    /// walls and floors, as the balls are copied into the grid's order; then the ball pairs
    /// from the grid, in its order.
    fn find(&mut self, balls: &[Ball], effects: &Effects, dt: f64) {
        let gravity = effects.gravity.map_or(0.0, |[gx, gy]| maths::hypot(gx, gy));
        // How far gravity alone can move a ball in the step.
        let fall = gravity * dt * dt;
        // How far each ball can get in this step, and a little more, so that it stops at a
        // surface instead of passing into it, and a resting pair is found again next step.
        let margin = |ball: &Ball| {
            (ball.vx * ball.vx + ball.vy * ball.vy).sqrt() * dt + fall + PAIR_MARGIN * ball.radius
        };
        // Whether a contact at `separation` closing at `approach` (negative: closing) can
        // touch within the step, with `slack` to spare.
        let can_touch = |separation: f64, approach: f64, fall: f64, slack: f64| {
            separation + approach.min(0.0) * dt - fall < slack
        };
        self.grid.rebuild_with_margins(balls, margin);
        // Each ball's copy in the grid's order, and its walls and floors, in one pass.
        self.local.clear();
        self.fixed.clear();
        for (k, &i) in self.grid.order().iter().enumerate() {
            let ball = &Body::of(&balls[i]);
            self.local.push(*ball);
            let centre = [ball.x, ball.y];
            let mut touch = |id: u64, normal: [f64; 2], surface: f64, restitution: f64| {
                let offset = surface + ball.radius;
                let separation = dot(centre, normal) - offset;
                let approach = dot([ball.vx, ball.vy], normal);
                if can_touch(separation, approach, fall, PAIR_MARGIN * ball.radius) {
                    self.fixed.push(FixedContact {
                        ball: k,
                        offset,
                        state: ContactState::new(
                            normal,
                            separation,
                            restitution,
                            mass(ball),
                            (i as u64) << 32 | (u64::from(u32::MAX) - id),
                        ),
                    });
                }
            };
            if let Some(walls) = &effects.walls {
                tally(Work::Walls);
                // Each wall as a line: its inward normal, and `normal · point` on it.
                let sides = [
                    ([1.0, 0.0], 0.0),
                    ([-1.0, 0.0], -walls.width),
                    ([0.0, 1.0], 0.0),
                    ([0.0, -1.0], -walls.height),
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
                    dot(centre, normal) - distance,
                    floor.damping,
                );
            }
        }
        let (balls, order) = (&self.local, self.grid.order());

        // The grid names each pair by the balls' places in its order, which are their places
        // in `local`: `a < b`, close together in memory, no lookup needed.
        self.pairs.clear();
        self.unlisted.clear();
        let limit = MAX_PAIRS_PER_BALL.saturating_mul(balls.len());
        self.grid.overlapping_places(&mut self.places, limit);
        for &[a, b] in &self.places {
            let (a, b) = (a as usize, b as usize);
            let (ball_a, ball_b) = (&balls[a], &balls[b]);
            let gap @ (separation, normal) = gap_between(balls, order, a, b);
            let approach = dot([ball_b.vx - ball_a.vx, ball_b.vy - ball_a.vy], normal);
            // Both balls fall alike, but a ball pushed from above can close the gap by as
            // much as gravity moves it.
            let slack = PAIR_MARGIN * (ball_a.radius + ball_b.radius) / 2.0;
            if can_touch(separation, approach, fall, slack) {
                let contact = pair_contact(balls, order, self.restitution, (a, b), gap);
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
        // Number the islands in the order their contacts were found, visiting only the balls
        // with a contact (the rest stay at `NO_ISLAND`), and count each island's balls.
        // Islands share no ball and a ball's own motion does not depend on the others', so
        // neither the islands' order nor their balls' changes a number: only each island's
        // contacts must keep the order they were found in.
        let island_of = &mut self.island_of;
        island_of.clear();
        island_of.resize(count, NO_ISLAND);
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
        let islands = &mut self.islands;
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

    /// Gives each contact the impulse it ended the last step with (0 if it is new).
    fn recall(&mut self) {
        let remembered = &self.remembered;
        let states = self.pairs.iter_mut().map(|c| &mut c.state);
        for state in states.chain(self.fixed.iter_mut().map(|c| &mut c.state)) {
            state.impulse = remembered
                .binary_search_by_key(&state.key, |&(key, _)| key)
                .map_or(0.0, |found| remembered[found].1);
        }
    }

    /// Keeps the impulses for the next step's warm start.
    fn remember(&mut self) {
        self.remembered.clear();
        let states = self.pairs.iter().map(|c| &c.state);
        self.remembered.extend(
            states
                .chain(self.fixed.iter().map(|c| &c.state))
                .map(|state| (state.key, state.impulse))
                .filter(|&(_, impulse)| impulse > 0.0),
        );
        self.remembered.sort_unstable_by_key(|&(key, _)| key);
    }
}

/// Puts the solver's `copy` of a ball back into the scene's `ball`, inside the `walls`.
fn copy_back(copy: &Body, ball: &mut Ball, walls: Option<&Walls>) {
    (ball.x, ball.y, ball.vx, ball.vy) = (copy.x, copy.y, copy.vx, copy.vy);
    if let Some(walls) = walls {
        ball.keep_inside(walls);
    }
}

/// The gap between balls `a` and `b` (places in `balls`, the grid's order; `order` gives
/// their scene indices) and the normal from `a` to `b`.
fn gap_between(balls: &[Body], order: &[usize], a: usize, b: usize) -> (f64, [f64; 2]) {
    let (ball_a, ball_b) = (&balls[a], &balls[b]);
    // The scene's index of the later ball names the normal of balls at one spot.
    let coincident = || coincident_normal(order[a].max(order[b]));
    pair_gap(ball_a, ball_b, ball_a.radius + ball_b.radius, coincident)
}

/// The contact between balls `a` and `b` (as in [`gap_between`]), `separation` apart along
/// `normal`.
fn pair_contact(
    balls: &[Body],
    order: &[usize],
    restitution: f64,
    (a, b): (usize, usize),
    (separation, normal): (f64, [f64; 2]),
) -> PairContact {
    let (ball_a, ball_b) = (&balls[a], &balls[b]);
    // The key names the pair by its scene indices, which do not change.
    let (i, j) = (order[a].min(order[b]), order[a].max(order[b]));
    let key = (j as u64) << 32 | i as u64;
    let (mass_a, mass_b) = (mass(ball_a), mass(ball_b));
    let mass = mass_a * mass_b / (mass_a + mass_b);
    PairContact {
        a,
        b,
        reach: ball_a.radius + ball_b.radius,
        state: ContactState::new(normal, separation, restitution, mass, key),
        inverse_a: 1.0 / mass_a,
        inverse_b: 1.0 / mass_b,
    }
}

/// Applies each contact's impulse of the last sub-step again, and measures its gap anew.
fn warm_start(pairs: &mut [PairContact], fixed: &mut [FixedContact], balls: &mut [Body]) {
    for contact in pairs.iter_mut() {
        let (a, b) = two(balls, contact.a, contact.b);
        let (separation, normal) = pair_gap(a, b, contact.reach, || contact.state.normal);
        (contact.state.separation, contact.state.normal) = (separation, normal);
        contact.push_velocities(a, b, contact.state.impulse);
    }
    for contact in fixed.iter_mut() {
        let ball = &mut balls[contact.ball];
        contact.state.separation = contact.gap(ball);
        let impulse = contact.state.impulse / contact.state.mass;
        ball.vx += impulse * contact.state.normal[0];
        ball.vy += impulse * contact.state.normal[1];
    }
}

/// Solves an island touch by touch, if it can. When no force acts (the caller checks) the
/// balls fly in straight lines, so when each contact touches has a closed form: the island
/// flies to the first touch, that contact alone is solved there, and so on to the end of the
/// step, instead of every contact once per sub-step.
///
/// Balls that start the step overlapping beyond the slop are first set apart, to touching
/// (positions only): in a gas that is nearly always a pair the last step did not list
/// because it was not closing, whose balls then met after one of them was struck. Returns
/// `false`, with the balls as they were, when a contact still overlaps after that (a ball
/// pushed into a third: the sub-steps' gentler position passes sort that out) or the island
/// has more than [`TOUCHES_PER_CONTACT`] touches per contact (a cluster that keeps
/// colliding): those take the sub-steps. `saved` is scratch space.
fn solve_free_island(
    island: (&[usize], &mut [PairContact], &mut [FixedContact]),
    balls: &mut [Body],
    (motion, whole, sub): (&Motion, &Forces, SubStep),
    saved: &mut Vec<[f64; 4]>,
) -> bool {
    let (active, pairs, fixed) = island;
    saved.clear();
    saved.extend(active.iter().map(|&i| {
        let ball = &balls[i];
        [ball.x, ball.y, ball.vx, ball.vy]
    }));
    let fly = |balls: &mut [Body], time: f64| {
        for &i in active {
            motion.integrator.fly(&mut balls[i], whole, time);
        }
    };
    // Positions only, so no kinetic energy is added; an approaching pair then touches now.
    solve_positions(pairs, fixed, balls, Push::Whole);
    let mut left = whole.dt;
    for _ in 0..TOUCHES_PER_CONTACT * (pairs.len() + fixed.len()) {
        let Some((first, touch)) = first_touch(pairs, fixed, balls) else {
            break;
        };
        if touch >= left {
            fly(balls, left);
            return true;
        }
        fly(balls, touch);
        left -= touch;
        // The rest of the step after the touch is the sub-step the contact is solved for.
        let sub = SubStep { h: left, ..sub };
        // They touch now: a rounding error's gap must not spare them the bounce.
        if first < pairs.len() {
            let contact = &mut pairs[first];
            let (a, b) = two(balls, contact.a, contact.b);
            let (separation, normal) = pair_gap(a, b, contact.reach, || contact.state.normal);
            (contact.state.separation, contact.state.normal) = (separation.min(0.0), normal);
            contact.solve_velocity(a, b, sub);
        } else {
            let contact = &mut fixed[first - pairs.len()];
            let ball = &mut balls[contact.ball];
            contact.state.separation = contact.gap(ball).min(0.0);
            contact.solve_velocity(ball, sub);
        }
    }
    for (&i, &[x, y, vx, vy]) in active.iter().zip(saved.iter()) {
        let ball = &mut balls[i];
        (ball.x, ball.y, ball.vx, ball.vy) = (x, y, vx, vy);
    }
    false
}

/// The contact of `pairs` then `fixed` (numbered in that order) that touches first, and when;
/// `None` if one overlaps beyond the slop.
fn first_touch(
    pairs: &[PairContact],
    fixed: &[FixedContact],
    balls: &[Body],
) -> Option<(usize, f64)> {
    let touches = pairs.iter().map(|contact| contact.touch_time(balls));
    let touches = touches.chain(
        fixed
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

/// One Gauss–Seidel pass over every contact's velocity.
fn solve_velocities(
    pairs: &mut [PairContact],
    fixed: &mut [FixedContact],
    balls: &mut [Body],
    sub: SubStep,
) {
    for contact in pairs.iter_mut() {
        let (a, b) = two(balls, contact.a, contact.b);
        contact.solve_velocity(a, b, sub);
    }
    for contact in fixed.iter_mut() {
        contact.solve_velocity(&mut balls[contact.ball], sub);
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

/// One Gauss–Seidel pass that pushes contacts overlapping beyond the slop apart by `push`,
/// positions only.
fn solve_positions(pairs: &[PairContact], fixed: &[FixedContact], balls: &mut [Body], push: Push) {
    for contact in pairs {
        let (a, b) = two(balls, contact.a, contact.b);
        if !deeper_than_slop(a, b, contact.reach) {
            continue; // the common case, without a square root
        }
        let allowed = SLOP * contact.reach / 2.0;
        let (separation, [nx, ny]) = pair_gap(a, b, contact.reach, || contact.state.normal);
        if separation < -allowed {
            // Each ball moves its share: the lighter one more.
            let push = push.distance(separation, allowed) * contact.state.mass;
            let (share_a, share_b) = (push * contact.inverse_a, push * contact.inverse_b);
            a.x -= share_a * nx;
            a.y -= share_a * ny;
            b.x += share_b * nx;
            b.y += share_b * ny;
        }
    }
    for contact in fixed {
        let ball = &mut balls[contact.ball];
        let separation = contact.gap(ball);
        let allowed = SLOP * ball.radius;
        if separation < -allowed {
            let push = push.distance(separation, allowed);
            ball.x += push * contact.state.normal[0];
            ball.y += push * contact.state.normal[1];
        }
    }
}

impl ContactState {
    fn new(
        normal: [f64; 2],
        separation: f64,
        restitution: f64,
        mass: f64,
        key: u64,
    ) -> ContactState {
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
    fn solve(&mut self, speed: f64, sub: SubStep) -> f64 {
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
        let [nx, ny] = self.state.normal;
        let speed = (b.vx - a.vx) * nx + (b.vy - a.vy) * ny;
        let change = self.state.solve(speed, sub);
        self.push_velocities(a, b, change);
    }

    /// When the balls, flying straight, first touch (infinite if never, 0 if they touch
    /// now); `None` if they overlap by more than the slop, which the position pass handles.
    fn touch_time(&self, balls: &[Body]) -> Option<f64> {
        let (a, b) = (&balls[self.a], &balls[self.b]);
        let p = [b.x - a.x, b.y - a.y];
        let v = [b.vx - a.vx, b.vy - a.vy];
        // |p + v·t| = reach: a quadratic in t, whose smaller root is the touch.
        let gap = dot(p, p) - self.reach * self.reach;
        let closing = dot(p, v);
        if gap <= 0.0 {
            // A pair that has just bounced touches still, or overlaps by a rounding error.
            let closest = self.reach * (1.0 - SLOP / 2.0);
            return match closing {
                _ if dot(p, p) < closest * closest => None,
                c if c < 0.0 => Some(0.0),
                _ => Some(f64::INFINITY),
            };
        }
        let discriminant = closing * closing - dot(v, v) * gap;
        if closing >= 0.0 || discriminant < 0.0 {
            return Some(f64::INFINITY);
        }
        // `gap / (−p·v + √…)` is that root without cancellation.
        Some(gap / (-closing + discriminant.sqrt()))
    }

    /// Gives `b` the impulse `impulse` along the normal and `a` the opposite one.
    fn push_velocities(&self, a: &mut Body, b: &mut Body, impulse: f64) {
        let [nx, ny] = self.state.normal;
        let (da, db) = (impulse * self.inverse_a, impulse * self.inverse_b);
        a.vx -= da * nx;
        a.vy -= da * ny;
        b.vx += db * nx;
        b.vy += db * ny;
    }
}

impl FixedContact {
    /// The velocity pass for this contact.
    fn solve_velocity(&mut self, ball: &mut Body, sub: SubStep) {
        let [nx, ny] = self.state.normal;
        let change = self.state.solve(ball.vx * nx + ball.vy * ny, sub) / self.state.mass;
        ball.vx += change * nx;
        ball.vy += change * ny;
    }

    /// When the ball, flying straight, reaches the line (infinite if never, 0 if it touches
    /// now); `None` if it is past the line by more than the slop.
    fn touch_time(&self, ball: &Body) -> Option<f64> {
        let separation = self.gap(ball);
        let approach = dot([ball.vx, ball.vy], self.state.normal);
        match separation {
            s if s < -SLOP * ball.radius => None,
            _ if approach >= 0.0 => Some(f64::INFINITY),
            s => Some((-s / approach).max(0.0)),
        }
    }

    /// The gap between the ball and the line, px.
    fn gap(&self, ball: &Body) -> f64 {
        dot([ball.x, ball.y], self.state.normal) - self.offset
    }
}

/// Whether balls `a` and `b`, whose radii add up to `reach`, overlap by more than the slop
/// ([`SLOP`] of their mean radius). Compared squared, without a square root.
fn deeper_than_slop(a: &Body, b: &Body, reach: f64) -> bool {
    let closest = reach - SLOP * reach / 2.0;
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    dx * dx + dy * dy < closest * closest
}

/// Mass of a ball: radius² (flat discs of equal density).
fn mass(ball: &Body) -> f64 {
    ball.radius * ball.radius
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

/// The gap between two balls whose radii add up to `reach`, and the normal from `a` to `b`
/// (`fallback()` if their centres coincide).
fn pair_gap(
    a: &Body,
    b: &Body,
    reach: f64,
    fallback: impl FnOnce() -> [f64; 2],
) -> (f64, [f64; 2]) {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    let distance = (dx * dx + dy * dy).sqrt();
    if distance > 0.0 {
        (distance - reach, [dx / distance, dy / distance])
    } else {
        (-reach, fallback())
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
fn coincident_normal(j: usize) -> [f64; 2] {
    let angle = GOLDEN_ANGLE * j as f64;
    [maths::cos(angle), maths::sin(angle)]
}
