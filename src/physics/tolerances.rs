//! Every tolerance and limit of the solvers in one place, each with its unit and the reason
//! for its value, as Box2D keeps them in `constants.h`. Units are the lesson's: pixels and
//! frames. The lesson's own step (`super::ball::Ball::step`) needs none of them: it compares
//! with the walls exactly.

// ---- Scale ----

/// The gravity the speeds below were derived for, px/frame²: the lesson's. With it at 30 ms a
/// frame standing for Earth's 9.81 m/s², 1 m = 0.5 / (9.81 · 0.03²) = 56.6 px and
/// 1 m/s = 56.6 · 0.03 = 1.7 px/frame. Speeds that stand for m/s scale with a scene's gravity.
pub(crate) const LESSON_GRAVITY: f64 = 0.5;

/// Rebound speed below which a bounce ends in rest, px/frame (at `LESSON_GRAVITY`).
///
/// Box2D and Rapier stop bouncing below 1 m/s, which is 1.7 px/frame at the lesson's scale.
/// Such a rebound rises v²/2g = 2.9 px (5 cm) and lasts 2v/g = 6.8 frames (0.2 s).
pub const REST_SPEED: f64 = 1.7;

// ---- Touching, against rounding ----

/// Normal speeds below this, px/frame, count as touching without approaching: rounding
/// after a bounce leaves about 1e-16 px/frame, a real approach is many orders more.
pub(crate) const TOUCH_SPEED: f64 = 1e-9;

/// How far (as a share of the squared reach) a touching pair on curved flights may close
/// before it counts as meeting again: well above rounding, far below a visible overlap.
pub(crate) const REBOUND_GAP: f64 = 1e-9;

/// Normal distances below this share of the radius count as touching a floor's face (exact
/// mode's walls and floors): rounding leaves about 1e-16 of a radius.
pub(crate) const FLOOR_TOUCH_GAP: f64 = 1e-9;

/// Gaps between balls below this share of their radii count as touching, for exact mode's
/// rest rule: as for floors, far above rounding and far below a pixel.
pub(crate) const BALL_TOUCH_GAP: f64 = 1e-9;

/// The most that Horner's rule can be off, as a share of `Σ|cᵢ·tⁱ|`, for the polynomials of
/// degree ≤ 8 that exact mode evaluates (a bound of 2·8 roundings of 1.1e-16 each is 3.6e-15),
/// with room to spare: a polynomial whose value now exceeds how far it can move by more than
/// this share is positive wherever it is evaluated, so its roots need not be looked for.
pub(crate) const HORNER_ROUNDING: f64 = 1e-14;

/// How many of its estimated roundings either side of a straight line's root, found by one
/// division, the bracket reaches that the root search narrows down to adjacent numbers: the
/// division and the line's value each round a few times. Too narrow a bracket misses the root
/// and the whole step is searched instead; a wider one costs only a few more tries.
pub(crate) const LINE_ROOT_ROUNDINGS: f64 = 4.0;

// ---- Exact mode's ball-ball events ----

/// The TC model's duration (Luding & McNamara), frames: a ball-ball collision within this
/// long of either ball's previous one is elastic. Collisions that all happen at one moment
/// (a ball pressed into a touching row) then pass the momentum along as in Newton's cradle,
/// a finite number of events, instead of sharing it out in infinitely many smaller ones.
pub(crate) const TC_DURATION: f64 = 1e-6;

/// How far past a cell's border a ball must be before it changes cell, as a share of the
/// largest diameter (exact mode's grid widens its cells by as much on each side): rounding
/// then cannot make a ball hop back and forth across a border, and a millionth of a diameter
/// is far below a pixel.
pub(crate) const CELL_MARGIN: f64 = 1e-6;

/// The sleep rule's gap: a ball within this share of its radius of a support leans on it.
/// A hundredth of a radius is below a pixel for any ball the canvas can show.
pub(crate) const SLEEP_GAP: f64 = 0.01;

// ---- The contact solver (clamp mode) ----

/// Contacts are found this share of a radius before they could touch within the step, so a
/// resting contact keeps its warm start from step to step.
pub(crate) const PAIR_MARGIN: f64 = 0.1;

/// Velocity passes in each sub-step when gravity loads the contacts. A heap carries its
/// weight only if the velocity pass has all but converged before the position pass moves the
/// balls. With one pass, the 47 rows of a heap of 10,000 balls sink a little in every sub-step,
/// the position pass lifts them back, and the lift keeps the heap churning at up to 3 px/frame
/// for good. With three, that heap comes to rest within 800 frames, at a third more cost per
/// frame while it falls (`docs/contacts.md`). Without gravity nothing presses on a contact, and
/// the one pass a bounce needs is enough.
pub(crate) const LOADED_VELOCITY_PASSES: u32 = 3;

/// Overlap the position pass leaves alone, as a share of the radius: correcting every last
/// bit of it moves resting balls every step, and they never come to rest (Box2D's "linear
/// slop" plays this part).
pub const SLOP: f64 = 0.005;

/// Share of the overlap beyond the slop the position pass removes each sub-step (Box2D's
/// Baumgarte factor): all of it at once overshoots where many contacts push on one ball.
pub(crate) const PUSH: f64 = 0.2;

// ---- Sleep (the contact solver) ----

/// Speed below which a ball counts as still, px/frame (at `LESSON_GRAVITY`; it scales with
/// the scene's gravity, and without gravity nothing sleeps). Box2D v3 puts a body to sleep
/// below 0.05 m/s (its `sleepThreshold`), which is 0.085 px/frame at the lesson's scale: a
/// sixth of what gravity adds in one frame, so a ball that falls, bounces or is pushed is
/// never still for long; far above the hundredths of a pixel a frame a settled pile trembles
/// by. (rapier's threshold is higher: 0.4 m/s, 0.68 px/frame.)
pub const SLEEP_SPEED: f64 = 0.085;

/// How long every ball of an island must stay below [`SLEEP_SPEED`] before the island
/// sleeps, frames: rapier's `time_until_sleep`, 2 s, at the lesson's 30 ms a frame. Box2D
/// waits 0.5 s (17 frames), which is enough for bodies with friction; frictionless balls
/// creep. A ball wedged between a wall and the balls below can slide off at under
/// 0.04 px/frame for 25 frames, then fall 12 px (the `pile` preset's did, with one velocity
/// pass): after 17 calm frames its island would sleep with it still up there, after 67 it
/// has fallen.
pub(crate) const SLEEP_FRAMES: u32 = 67;

// ---- Limits: work and memory bounded whatever the scene ----

/// The most bounces resolved exactly in one step of one ball (walls and floors).
pub(crate) const MAX_EVENTS_PER_STEP: u32 = 64;

/// The most events one exact step may resolve, per ball.
pub const MAX_EVENTS_PER_BALL: u64 = 64;

/// The most surfaces (walls, floors, other balls) exact mode keeps a ball resting on at once:
/// more than this at once hold a ball completely anyway, and a fixed array of them needs no
/// allocation.
pub(crate) const MAX_SUPPORTS: usize = 8;

/// The most ball-ball contacts a step takes on, per ball. A pile of equal balls touches at
/// most six neighbours each; balls spawned on top of one another could make N² pairs, and
/// the memory for them. Pairs beyond this wait for a later step, once the pile has spread.
pub(crate) const MAX_PAIRS_PER_BALL: usize = 16;

/// How many touches per contact an island without forces may take, solved one by one at
/// their times, before it is solved in sub-steps instead: a chain of balls passes a blow
/// along in a few touches; more means a cluster that keeps colliding.
pub(crate) const TOUCHES_PER_CONTACT: usize = 4;

/// A grid never has more than about this many cells per ball: when balls are spread thin
/// the cells grow instead, so memory and the time spent visiting empty cells stay O(N).
pub(crate) const MAX_CELLS_PER_BALL: f64 = 4.0;
