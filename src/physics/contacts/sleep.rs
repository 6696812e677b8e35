//! Sleeping islands: balls that have come to rest stop being solved until something could
//! move them, as Box2D and rapier put resting bodies to sleep.
//!
//! The rule (`docs/contacts.md` sets it beside Box2D's and rapier's):
//!
//! - **Falling asleep.** After each step, a ball slower than the sleep speed
//!   ([`SLEEP_SPEED`](crate::physics::tolerances::SLEEP_SPEED), scaled with gravity) counts one
//!   more calm step; faster, its count starts again at 0. An island of the step (balls joined
//!   by contacts, see `super::island`) whose every ball has been calm for
//!   [`SLEEP_FRAMES`](crate::physics::tolerances::SLEEP_FRAMES) frames sleeps whole: its balls
//!   stop (their velocities set to 0, as Box2D v2.4 and rapier do, so that a sleeping ball's state is
//!   exactly what it keeps) and stay where they are to the bit. The impulses its contacts
//!   ended with are kept, to warm-start them when it wakes.
//! - **Asleep.** A sleeping ball takes no gravity, no contact and no wall or floor check. When
//!   every ball sleeps, a step does nothing at all.
//! - **Waking.** A sleeping island wakes whole, its calm counts back to 0, when an awake ball
//!   can touch one of its balls within the step (the same test that lists a contact), or ends
//!   a step overlapping one (the solver's restitution pushes it). Nothing else can move a
//!   sleeping ball: a scene's gravity, walls and floors are fixed for the whole run. Without
//!   gravity nothing sleeps: nothing presses balls together, so a still ball is a free one.
//!
//! A sleeping ball takes no part in the solver's stages until an awake ball can touch it,
//! which the grid's pairs show as the step is prepared, and a step in which every ball sleeps
//! does nothing at all. Box2D v3 keeps its sleeping islands in solver sets (`solver_set.c`).

use super::step_context::StepContext;
use crate::physics::ball::Ball;
use crate::physics::tolerances::SLEEP_FRAMES;

/// `island_of` for a ball that is awake.
const AWAKE: u32 = u32::MAX;

/// Which balls sleep, in which islands, and how long each awake ball has been calm.
#[derive(Clone, Debug, Default)]
pub(super) struct Sleep {
    /// Per ball (scene order): steps in a row it ended slower than the sleep speed.
    calm: Vec<u32>,
    /// Per ball: the sleeping island it is in, or `AWAKE`.
    island_of: Vec<u32>,
    /// The sleeping islands by number; a woken island's place stays empty until reused.
    islands: Vec<SleepingIsland>,
    /// The numbers of the empty places in `islands`.
    free: Vec<u32>,
    /// How many balls sleep.
    sleeping: usize,
    /// The kept impulses of the islands woken since they were last taken.
    woken: Vec<(u64, f64)>,
}

/// An island that sleeps: its balls (scene indices) and the impulse each of its contacts
/// ended with, by contact key.
#[derive(Clone, Debug, Default)]
struct SleepingIsland {
    balls: Vec<usize>,
    impulses: Vec<(u64, f64)>,
}

impl Sleep {
    /// Makes room for `count` balls, all awake (the first step only: the count never changes).
    pub(crate) fn fit(&mut self, count: usize) {
        if self.calm.len() != count {
            *self = Sleep::default();
            self.calm.resize(count, 0);
            self.island_of.resize(count, AWAKE);
        }
    }

    /// Whether ball `ball` sleeps.
    pub(crate) fn is_asleep(&self, ball: usize) -> bool {
        self.island_of[ball] != AWAKE
    }

    /// How many balls sleep.
    pub(crate) fn sleeping(&self) -> usize {
        self.sleeping
    }

    /// Whether some ball sleeps.
    pub(crate) fn anyone_asleep(&self) -> bool {
        self.sleeping > 0
    }

    /// Whether every ball sleeps (and there is one): then nothing can move.
    pub(crate) fn everyone_asleep(&self) -> bool {
        self.sleeping > 0 && self.sleeping == self.calm.len()
    }

    /// Counts a calm step for each awake ball of `balls` slower than `speed` px/frame, and
    /// starts the count again for the others.
    fn count_calm_steps(&mut self, balls: &[Ball], speed: f64) {
        let limit = speed * speed;
        for ((calm, &island), ball) in self.calm.iter_mut().zip(&self.island_of).zip(balls) {
            if island == AWAKE {
                let still = ball.velocity().length_squared() < limit;
                *calm = if still { calm.saturating_add(1) } else { 0 };
            }
        }
    }

    /// Whether ball `ball` has been calm for `steps` steps or more.
    fn calm_for(&self, ball: usize, steps: u32) -> bool {
        self.calm[ball] >= steps
    }

    /// After a step: counts each awake ball's calm steps, and puts to sleep each island of
    /// the step (in `context`) whose balls have all been calm for [`SLEEP_FRAMES`].
    pub(crate) fn fall_asleep(&mut self, balls: &mut [Ball], context: &StepContext) {
        let stepping = &context.stepping;
        if stepping.sleep_speed == 0.0 {
            return; // without gravity nothing sleeps
        }
        self.count_calm_steps(balls, stepping.sleep_speed);
        let needed = SLEEP_FRAMES * stepping.steps;
        let (order, contacts) = (context.grid.order(), &context.contacts);
        for island in &context.islands.list {
            let members = context.islands.balls[island.balls.clone()]
                .iter()
                .map(|&k| order[k]);
            if !members.clone().all(|i| self.calm_for(i, needed)) {
                continue;
            }
            let pairs = contacts.pairs[island.pairs.clone()]
                .iter()
                .map(|c| &c.state);
            let fixed = contacts.fixed[island.fixed.clone()]
                .iter()
                .map(|c| &c.state);
            let impulses = pairs.chain(fixed).map(|state| (state.key, state.impulse));
            let impulses = impulses.filter(|&(_, impulse)| impulse > 0.0);
            self.put_to_sleep(balls, members, impulses);
        }
    }

    /// Puts the island of `members` (scene indices, awake) to sleep: each stops where it is.
    /// `impulses` are its contacts' impulses, kept for when it wakes.
    fn put_to_sleep(
        &mut self,
        balls: &mut [Ball],
        members: impl Iterator<Item = usize>,
        impulses: impl Iterator<Item = (u64, f64)>,
    ) {
        let number = self.free.pop().unwrap_or_else(|| {
            self.islands.push(SleepingIsland::default());
            (self.islands.len() - 1) as u32
        });
        let island = &mut self.islands[number as usize];
        island.balls.extend(members);
        island.impulses.extend(impulses);
        for &i in &island.balls {
            (balls[i].vx, balls[i].vy) = (0.0, 0.0);
            self.island_of[i] = number;
        }
        self.sleeping += island.balls.len();
    }

    /// Wakes the island ball `ball` sleeps in, whole (nothing if it is awake). Returns
    /// whether it slept.
    pub(crate) fn wake(&mut self, ball: usize) -> bool {
        let number = self.island_of[ball];
        if number == AWAKE {
            return false;
        }
        let island = &mut self.islands[number as usize];
        for &i in &island.balls {
            self.island_of[i] = AWAKE;
            self.calm[i] = 0;
        }
        self.sleeping -= island.balls.len();
        island.balls.clear();
        self.woken.append(&mut island.impulses);
        self.free.push(number);
        true
    }

    /// The kept impulses of the islands woken since they were last taken, for the warm
    /// start: the caller takes them (and leaves the list empty).
    pub(crate) fn woken(&mut self) -> &mut Vec<(u64, f64)> {
        &mut self.woken
    }
}
