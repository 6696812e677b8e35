//! A tally of the work each stage does, kept only with the `work-tally` feature (the tests
//! turn it on), so a test can prove that work a scene does not call for never runs: physics
//! counts each effect it applies, drawing and the GIF's comparison count their pixels (a
//! frame that did not change costs nothing). Without the feature every `tally` compiles to
//! nothing. It imports nothing, so every stage may count here without knowing the others.

/// A piece of per-frame work that only some scenes call for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Work {
    /// Gravity added to one ball's velocity.
    Gravity,
    /// Drag applied to one ball's velocity.
    Drag,
    /// One ball checked against the box.
    Walls,
    /// One ball checked against one floor segment.
    Floor,
    /// One exact-mode step of ball-ball events over the whole scene (its cells and queue).
    BallCollisions,
    /// One step of the contact solver over the whole scene (grid, walls, floors, iterations).
    Contacts,
    /// One ball moved by the lesson's own step, `Ball::step`.
    LessonStep,
    /// One point added to one ball's trail by the general solvers.
    TrailPoint,
    /// Pixels written while drawing a frame (cleared or covered by a circle).
    PixelsDrawn,
    /// Pixels of two frames compared to find what changed.
    PixelsCompared,
}

#[cfg(feature = "work-tally")]
const KINDS: usize = 10;

#[cfg(feature = "work-tally")]
thread_local! {
    static COUNTS: std::cell::Cell<[u64; KINDS]> = const { std::cell::Cell::new([0; KINDS]) };
}

/// Counts one unit of `work` on this thread (with the `work-tally` feature only).
#[inline(always)]
pub(crate) fn tally(work: Work) {
    tally_many(work, 1);
}

/// Counts `units` of `work` on this thread at once (with the `work-tally` feature only).
#[inline(always)]
pub(crate) fn tally_many(work: Work, units: u64) {
    #[cfg(feature = "work-tally")]
    COUNTS.with(|counts| {
        let mut c = counts.get();
        c[work as usize] += units;
        counts.set(c);
    });
    #[cfg(not(feature = "work-tally"))]
    let _ = (work, units);
}

/// How much `work` this thread has done since the last `reset` (always 0 without the `work-tally` feature).
pub fn count(work: Work) -> u64 {
    #[cfg(feature = "work-tally")]
    return COUNTS.with(|counts| counts.get()[work as usize]);
    #[cfg(not(feature = "work-tally"))]
    {
        let _ = work;
        0
    }
}

/// Sets every count on this thread back to 0.
pub fn reset() {
    #[cfg(feature = "work-tally")]
    COUNTS.with(|counts| counts.set([0; KINDS]));
}
