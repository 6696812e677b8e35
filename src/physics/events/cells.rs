//! The grid of the event-driven step: which balls can touch soon, and when a ball moves into
//! another cell.
//!
//! Cells are squares at least one largest diameter wide, so two touching balls are always in
//! the same or neighbouring cells. Unlike the stepped broad phase
//! (`crate::physics::contacts::Grid`), balls move between cells in the middle of the step:
//! leaving a cell is an event like any other, and each cell keeps its balls in a linked list
//! so a move costs O(1) (Rapaport's cell lists).
//!
//! A ball changes cell only once it is a hair ([`CELL_MARGIN`] of the largest diameter) past
//! the border, and the cells are widened by twice that, so rounding can neither make a ball
//! hop back and forth across a border nor let two touching balls sit two cells apart. The
//! outermost cells reach to infinity, so a ball that leaves the area the grid was laid over
//! still has a cell.

use std::ops::Range;

use super::lists::Lists;
use crate::physics::ball::Ball;
use crate::physics::contacts::grid::cell_size;
use crate::physics::integrate::poly::Poly;
use crate::physics::tolerances::{CELL_MARGIN, MAX_CELLS_PER_BALL};
use crate::physics::vec2::Vec2;

/// Balls in cells, rebuilt at the start of every step into the same buffers.
#[derive(Clone, Debug, Default)]
pub(super) struct Cells {
    left: f64,
    top: f64,
    size: f64,
    margin: f64,
    columns: usize,
    rows: usize,
    /// The balls in each cell (a ball's cell is the number of its list: its column and row
    /// are worked out from it rather than kept, since every byte a ball keeps counts against
    /// the cache).
    balls: Lists,
}

impl Cells {
    /// Memory per ball, bytes: its place in its cell's list, and up to `MAX_CELLS_PER_BALL`
    /// cells' list heads.
    pub(crate) const BYTES_PER_BALL: u64 =
        (MAX_CELLS_PER_BALL as usize * size_of::<u32>()) as u64 + Lists::BYTES_PER_BALL;

    /// Lays a grid over the balls as they are now and over `area` (the box from the origin to
    /// this corner, if there is one: the balls will spread over it), and puts each ball in its
    /// cell.
    pub(crate) fn rebuild(&mut self, balls: &[Ball], area: Option<Vec2>) {
        let (mut left, mut top, mut right, mut bottom) = (0.0, 0.0, 0.0, 0.0);
        let mut largest = 0.0f64;
        if let Some(first) = balls.first() {
            (left, top, right, bottom) = (first.x, first.y, first.x, first.y);
        }
        if let Some(corner) = area.filter(|_| !balls.is_empty()) {
            (left, top) = (left.min(0.0), top.min(0.0));
            (right, bottom) = (right.max(corner.x), bottom.max(corner.y));
        }
        for ball in balls {
            left = f64::min(left, ball.x);
            top = f64::min(top, ball.y);
            right = f64::max(right, ball.x);
            bottom = f64::max(bottom, ball.y);
            largest = largest.max(ball.radius);
        }
        let (width, height) = (right - left, bottom - top);
        self.margin = CELL_MARGIN * 2.0 * largest;
        self.size = cell_size(
            2.0 * largest + 4.0 * self.margin,
            width,
            height,
            balls.len(),
        );
        // `as usize` saturates and maps NaN to 0, so no position can make an index out of range.
        self.columns = (width / self.size) as usize + 1;
        self.rows = (height / self.size) as usize + 1;
        (self.left, self.top) = (left, top);

        self.balls.reset(self.columns * self.rows, balls.len());
        for (i, ball) in balls.iter().enumerate() {
            let column = (((ball.x - left) / self.size) as usize).min(self.columns - 1);
            let row = (((ball.y - top) / self.size) as usize).min(self.rows - 1);
            self.balls.insert(i, self.cell([column, row]));
        }
    }

    /// Whether `ball` is inside the area the grid was laid over. Beyond it the outermost
    /// cells fill up, and the grid should be laid again.
    pub(crate) fn covers(&self, ball: &Ball) -> bool {
        let (right, bottom) = (
            self.left + self.columns as f64 * self.size,
            self.top + self.rows as f64 * self.size,
        );
        (self.left..=right).contains(&ball.x) && (self.top..=bottom).contains(&ball.y)
    }

    fn cell(&self, [column, row]: [usize; 2]) -> usize {
        row * self.columns + column
    }

    /// Ball `i`'s cell's column and row.
    fn place(&self, i: usize) -> [usize; 2] {
        // In 32 bits, where a division is the quicker (a grid's cells are numbered in 32).
        let (cell, columns) = (self.balls.list(i) as u32, self.columns as u32);
        [cell % columns, cell / columns].map(|index| index as usize)
    }

    /// Calls `visit` with every ball in ball `i`'s cell and the eight around it (`i` included).
    pub(crate) fn neighbours(&self, i: usize, visit: impl FnMut(usize)) {
        let (place, counts) = (self.place(i), [self.columns, self.rows]);
        let around = [0, 1].map(|a| around(place[a], counts[a]));
        self.visit_cells(around, visit);
    }

    /// Calls `visit` with every ball in the cells that ball `i`'s last move, along `axis`
    /// towards `towards`, brought around it: the far row (or column) of its new neighbourhood,
    /// three cells (fewer at the grid's edge, none past it).
    pub(crate) fn entered(&self, i: usize, axis: u8, towards: i8, visit: impl FnMut(usize)) {
        let (place, counts) = (self.place(i), [self.columns, self.rows]);
        let mut cells = [0, 1].map(|a| around(place[a], counts[a]));
        let a = usize::from(axis);
        // Past the first cell this wraps to `usize::MAX`, past the last it reaches `count`.
        let far = place[a].wrapping_add_signed(isize::from(towards));
        if far >= counts[a] {
            return;
        }
        cells[a] = far..far + 1;
        self.visit_cells(cells, visit);
    }

    /// Calls `visit` with every ball in the cells of the given column and row ranges.
    fn visit_cells(&self, [columns, rows]: [Range<usize>; 2], mut visit: impl FnMut(usize)) {
        for r in rows {
            for c in columns.clone() {
                for j in self.balls.balls(r * self.columns + c) {
                    visit(j);
                }
            }
        }
    }

    /// When ball `i`, whose centre moves along `path`, first leaves its cell within `left`
    /// frames, along which axis and towards which side.
    pub(crate) fn exit(&self, i: usize, path: &[Poly; 2], left: f64) -> Option<(f64, u8, i8)> {
        let counts = [self.columns, self.rows];
        let origin = [self.left, self.top];
        let place = self.place(i);
        let mut first: Option<(f64, u8, i8)> = None;
        for axis in 0..2u8 {
            let a = usize::from(axis);
            let index = place[a];
            let low = origin[a] + index as f64 * self.size - self.margin;
            let high = low + self.size + 2.0 * self.margin;
            let mut try_border = |border: f64, towards: i8| {
                if let Some(time) = crossing(&path[a], border, towards, left) {
                    if first.is_none_or(|(earliest, _, _)| time < earliest) {
                        first = Some((time, axis, towards));
                    }
                }
            };
            // The outermost cells reach to infinity: they have no border on the outer side.
            if index + 1 < counts[a] {
                try_border(high, 1);
            }
            if index > 0 {
                try_border(low, -1);
            }
        }
        first
    }

    /// Moves ball `i` into the next cell along `axis` towards `towards`.
    pub(crate) fn shift(&mut self, i: usize, axis: u8, towards: i8) {
        let mut place = self.place(i);
        let at = &mut place[usize::from(axis)];
        *at = at.wrapping_add_signed(isize::from(towards));
        self.balls.remove(i);
        self.balls.insert(i, self.cell(place));
    }
}

/// The cell indices from one before `index` to one after it, clipped to `0..count`.
fn around(index: usize, count: usize) -> Range<usize> {
    // Half-open, not `..=`: an inclusive range costs an extra test at every step of the loop.
    index.saturating_sub(1)..(index + 2).min(count)
}

/// When a coordinate moving along `path` first passes `border` going towards `towards`
/// (+1: upwards), within `left` frames. A straight flight needs one division (the cell's
/// margin absorbs its rounding); a curved one the polynomial's first root.
fn crossing(path: &Poly, border: f64, towards: i8, left: f64) -> Option<f64> {
    let side = f64::from(towards);
    if path.degree() <= 1 {
        let (start, speed) = (path.coefficient(0), path.coefficient(1));
        if speed * side <= 0.0 {
            return None; // moving away from it, or not at all
        }
        let time = ((border - start) / speed).max(0.0);
        return (time <= left).then_some(time);
    }
    // The distance to the far side of the border, which falls below zero on passing it.
    (*path * -side + side * border).first_negative(left)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_ball_goes_into_the_cell_around_its_centre_wherever_the_grid_lies() {
        // Balls far from the origin, without walls: the grid starts at the top-left ball.
        let balls: Vec<Ball> = (0..50)
            .map(|k| {
                let (x, y) = (
                    300.0 + f64::from(k * 37 % 400),
                    500.0 + f64::from(k * 53 % 400),
                );
                Ball::new(x, y, 0.0, 0.0, 3.0, 0)
            })
            .collect();
        let mut cells = Cells::default();
        cells.rebuild(&balls, None);
        for (i, ball) in balls.iter().enumerate() {
            let at = cells.place(i);
            let low = [cells.left, cells.top].map(|origin| origin - cells.margin);
            let cell_low = [0, 1].map(|a| low[a] + at[a] as f64 * cells.size);
            let inside = [ball.x, ball.y].iter().zip(cell_low).all(|(&centre, low)| {
                (low..=low + cells.size + 2.0 * cells.margin).contains(&centre)
            });
            assert!(
                inside,
                "ball at ({}, {}) put in cell {at:?}",
                ball.x, ball.y
            );
        }
    }

    #[test]
    fn a_grid_at_its_most_cells_per_ball_holds_what_the_memory_budget_counts() {
        // 10,000 balls of radius 1, 100 px apart: the cells widen until there are
        // `MAX_CELLS_PER_BALL` a ball (a little more: a row and a column are added at the
        // edges), the most a grid has.
        let balls: Vec<Ball> = (0..10_000)
            .map(|k| {
                let (column, row) = (f64::from(k % 100), f64::from(k / 100));
                Ball::new(column * 100.0, row * 100.0, 0.0, 0.0, 1.0, 0)
            })
            .collect();
        let mut cells = Cells::default();
        cells.rebuild(&balls, None);
        let held = cells.balls.bytes();
        let per_ball = held as f64 / balls.len() as f64;
        let counted = Cells::BYTES_PER_BALL as f64;
        assert!(
            (per_ball - counted).abs() < 1.0,
            "the grid holds {per_ball} bytes a ball; the budget counts {counted}"
        );
    }
}
