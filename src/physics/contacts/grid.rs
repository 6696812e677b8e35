//! The broad phase of ball-ball collisions: a uniform grid that finds every overlapping pair
//! of balls without testing every pair against every other.
//!
//! Each frame the balls are sorted by the cell their centre is in (a counting sort into
//! buffers kept from frame to frame), then each ball is tested only against the balls in its
//! own cell and the neighbouring ones. A cell is at least as wide as the largest ball, so two
//! balls that overlap are always in the same or neighbouring cells. At a fixed density a cell
//! holds a bounded number of balls, so a frame costs O(N) instead of O(N²).

use std::ops::Range;

use crate::physics::ball::Ball;
use crate::physics::maths;
use crate::physics::tolerances::MAX_CELLS_PER_BALL;

/// A ball as the grid sees it: where it is and how big. Copied out of the balls so the pair
/// search reads one compact array in cell order.
#[derive(Clone, Copy, Debug, Default)]
struct Entry {
    x: f64,
    y: f64,
    radius: f64,
}

impl Entry {
    /// Whether the two balls overlap: centres closer than the sum of the radii.
    fn overlaps(&self, other: &Entry) -> bool {
        let (dx, dy) = (other.x - self.x, other.y - self.y);
        let reach = self.radius + other.radius;
        dx * dx + dy * dy < reach * reach
    }
}

/// A uniform grid over the balls, rebuilt every frame into the same buffers.
#[derive(Clone, Debug, Default)]
pub struct Grid {
    /// The balls sorted by cell (row by row), in the caller's order within a cell, and the
    /// index in the caller's slice of each (kept apart: the pair search does not read it).
    entries: Vec<Entry>,
    indices: Vec<usize>,
    /// The balls of cell `c` are `entries[cell_start[c]..cell_start[c + 1]]`.
    cell_start: Vec<usize>,
    /// Each ball's cell and entry (its radius grown by its margin), in the caller's order:
    /// the counting sort's scratch space. The balls are read once, into these compact
    /// entries; the sort reads them instead of the balls.
    cell_of: Vec<usize>,
    unsorted: Vec<Entry>,
    columns: usize,
    rows: usize,
}

impl Grid {
    /// The grid's memory per ball, bytes: a 32-byte entry, its cell and up to 12 cell bounds
    /// (the budget counts it before the run; `crate::budget`).
    pub(crate) const BYTES_PER_BALL: u64 = 32 + 8 + 12 * 8;

    /// An empty grid; it allocates on the first `rebuild` and reuses its buffers afterwards.
    pub fn new() -> Grid {
        Grid::default()
    }

    /// Sorts `balls` into cells. The grid covers the balls' bounding box, so it needs no
    /// canvas size and works for balls anywhere; positions that are not finite all land in
    /// the first cell rather than panic.
    pub fn rebuild(&mut self, balls: &[Ball]) {
        self.rebuild_with_margins(balls, |_| 0.0);
    }

    /// Like `rebuild`, with each ball grown by `margin(ball)` px, so that the pairs found also
    /// include those that are that close (the contact solver looks at pairs that can touch
    /// within a step).
    pub(crate) fn rebuild_with_margins(&mut self, balls: &[Ball], margin: impl Fn(&Ball) -> f64) {
        let Some(first) = balls.first() else {
            self.entries.clear();
            self.indices.clear();
            self.cell_start.clear();
            self.columns = 0;
            self.rows = 0;
            return;
        };
        let ([left, top, right, bottom], largest_radius) = self.read(balls, first, margin);
        let (width, height) = (right - left, bottom - top);
        // At least one diameter, so overlapping balls are at most one cell apart.
        let cell = cell_size(2.0 * largest_radius, width, height, balls.len());
        // `as usize` saturates and maps NaN to 0, so no position can make an index out of range.
        self.columns = (width / cell) as usize + 1;
        self.rows = (height / cell) as usize + 1;
        self.count_per_cell(left, top, cell);
        self.place_by_cell();
    }

    /// Reads `balls` (the first is `first`) into compact entries, each grown by
    /// `margin(ball)`, and returns the box around their centres (left, top, right, bottom)
    /// and the largest grown radius.
    fn read(
        &mut self,
        balls: &[Ball],
        first: &Ball,
        margin: impl Fn(&Ball) -> f64,
    ) -> ([f64; 4], f64) {
        let (mut left, mut top, mut right, mut bottom) = (first.x, first.y, first.x, first.y);
        let mut largest_radius = 0.0_f64;
        self.unsorted.clear();
        for ball in balls {
            left = left.min(ball.x);
            top = top.min(ball.y);
            right = right.max(ball.x);
            bottom = bottom.max(ball.y);
            let radius = ball.radius + margin(ball);
            largest_radius = largest_radius.max(radius);
            let (x, y) = (ball.x, ball.y);
            self.unsorted.push(Entry { x, y, radius });
        }
        ([left, top, right, bottom], largest_radius)
    }

    /// The counting sort's first half: each entry's cell (cells `cell` px wide from `left`,
    /// `top`), the balls in each cell counted, and the counts turned into a running total,
    /// so `cell_start[c]` holds where cell `c` ends.
    fn count_per_cell(&mut self, left: f64, top: f64, cell: f64) {
        let last_column = self.columns - 1;
        let last_row = self.rows - 1;
        self.cell_start.clear();
        self.cell_start.resize(self.columns * self.rows + 1, 0);
        self.cell_of.clear();
        let per_cell = 1.0 / cell;
        for entry in &self.unsorted {
            // (a multiplication: a division per coordinate cost 2 % of a 100,000-ball frame)
            let column = (((entry.x - left) * per_cell) as usize).min(last_column);
            let row = (((entry.y - top) * per_cell) as usize).min(last_row);
            let cell = row * self.columns + column;
            self.cell_start[cell] += 1;
            self.cell_of.push(cell);
        }
        let mut total = 0;
        for end in &mut self.cell_start {
            total += *end;
            *end = total;
        }
    }

    /// The counting sort's second half: the balls placed last to first, each just before its
    /// cell's end. Within a cell they keep the caller's order, and `cell_start[c]` ends up
    /// where cell `c` starts.
    fn place_by_cell(&mut self) {
        let count = self.unsorted.len();
        self.entries.clear();
        self.entries.resize(count, Entry::default());
        self.indices.resize(count, 0);
        let unsorted = self.unsorted.iter().zip(&self.cell_of).enumerate();
        for (index, (entry, &cell)) in unsorted.rev() {
            let slot = &mut self.cell_start[cell];
            *slot -= 1;
            self.entries[*slot] = *entry;
            self.indices[*slot] = index;
        }
    }

    /// Replaces the contents of `places` with the pairs of balls that overlap, named as in
    /// `Grid::for_each_overlapping_place`, at most `limit` of them: balls piled on one spot
    /// make N² pairs, and memory must not follow. Places are 32-bit (a scene holds at most
    /// `MAX_BALLS`, a million): half the memory to write and read back for 100,000 balls.
    pub(crate) fn overlapping_places(&self, places: &mut Vec<[u32; 2]>, limit: usize) {
        // Every candidate is written at `found`, which moves on only past those that overlap:
        // no branch on the test, which a gas passes at random (about one in fifteen), so the
        // processor has nothing to mispredict.
        let mut found = 0;
        self.for_each_neighbourhood(|a, others| {
            if found >= limit {
                return;
            }
            if places.len() < found + others.len() {
                places.resize(found + others.len(), [0, 0]);
            }
            let entry = self.entries[a];
            for (b, other) in others.clone().zip(&self.entries[others]) {
                places[found] = [a as u32, b as u32];
                found += usize::from(entry.overlaps(other));
            }
        });
        places.truncate(found.min(limit));
    }

    /// Calls `found(i, j)` for every pair of balls that overlap (centres closer than the sum
    /// of the radii; touching is not overlapping), as of the last `rebuild`. Each pair comes
    /// once, with `i < j`, in an order that depends only on the balls: cell by cell, row by
    /// row. Pairs are handed over as found rather than collected, so balls piled on top of
    /// each other (N²/2 pairs) cost time but no memory.
    pub fn for_each_overlapping_pair(&self, mut found: impl FnMut(usize, usize)) {
        self.for_each_overlapping_place(|k, l| {
            let (i, j) = (self.indices[k], self.indices[l]);
            found(i.min(j), i.max(j));
        });
    }

    /// How deep the most overlapping pair of `balls` overlaps, px (0 if none does), as of the
    /// last `rebuild` with them: a measure for tests, plots and the soak run, never used to step.
    pub fn deepest_overlap(&self, balls: &[Ball]) -> f64 {
        let mut deepest: f64 = 0.0;
        self.for_each_overlapping_pair(|i, j| {
            let (a, b) = (&balls[i], &balls[j]);
            deepest = deepest.max(a.radius + b.radius - maths::hypot(b.x - a.x, b.y - a.y));
        });
        deepest
    }

    /// The same pairs in the same order, each ball named by its place in `Grid::order`
    /// (`k < l`) rather than by its index: a caller that keeps its balls in that order finds
    /// both balls of a pair near each other, without looking them up.
    fn for_each_overlapping_place(&self, mut found: impl FnMut(usize, usize)) {
        self.for_each_neighbourhood(|a, others| {
            let entry = self.entries[a];
            for (b, other) in others.clone().zip(&self.entries[others]) {
                if entry.overlaps(other) {
                    found(a, b);
                }
            }
        });
    }

    /// Calls `near(a, others)` for each place `a` in cell order with ranges of the places
    /// after it that may overlap it: the later balls of its own cell and the cell to its
    /// right, then the three cells below. Every pair of neighbouring balls is in one range.
    fn for_each_neighbourhood(&self, mut near: impl FnMut(usize, Range<usize>)) {
        for row in 0..self.rows {
            for column in 0..self.columns {
                let here = self.cells(row, column, column);
                if here.is_empty() {
                    continue;
                }
                // Each pair of cells is searched once, from the upper or left one: this cell
                // with the one to its right, and with the three below. Cells next to each other
                // in a row are next to each other in `entries`, so each is one range, and every
                // place in it comes after `a`.
                let right = self.cells(row, column, (column + 1).min(self.columns - 1));
                let below = if row + 1 < self.rows {
                    let first = column.saturating_sub(1);
                    self.cells(row + 1, first, (column + 1).min(self.columns - 1))
                } else {
                    0..0
                };
                for a in here {
                    near(a, a + 1..right.end);
                    near(a, below.clone());
                }
            }
        }
    }

    /// The balls' indices in cell order (row by row), as of the last `rebuild`: balls near
    /// each other in space are mostly near each other in this order.
    pub(crate) fn order(&self) -> &[usize] {
        &self.indices
    }

    /// The entries of the cells from `first` to `last` column (inclusive) of `row`.
    fn cells(&self, row: usize, first: usize, last: usize) -> Range<usize> {
        let start = row * self.columns;
        self.cell_start[start + first]..self.cell_start[start + last + 1]
    }
}

/// The side of a grid's square cells, px, for `balls` balls whose centres span `width` by
/// `height` px: at least `smallest` (a diameter, so that balls that can touch are at most one
/// cell apart), and wider when the balls are spread thin, so that there are never more than
/// [`MAX_CELLS_PER_BALL`] cells per ball. This grid and exact mode's
/// (`crate::physics::events`) both size their cells with it.
pub(crate) fn cell_size(smallest: f64, width: f64, height: f64, balls: usize) -> f64 {
    let most = MAX_CELLS_PER_BALL * balls.max(1) as f64;
    smallest
        .max((width * height / most).sqrt())
        .max(width.max(height) / most)
        .max(f64::MIN_POSITIVE)
}
