//! Where a frame may have changed: rectangles of the canvas (and copying one from frame to
//! frame), and the tiles a redraw marks under every circle that moved, read back as
//! rectangles.
//!
//! Knows pixels and rectangles, nothing of balls.

use std::ops::Range;

use super::palette::IndexedFrame;

/// A rectangle of a frame, px from the top-left corner.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Rect {
    pub left: u32,
    pub top: u32,
    pub width: u32,
    pub height: u32,
}

impl Rect {
    /// The whole of `frame`.
    pub(crate) fn whole(frame: &IndexedFrame) -> Rect {
        Rect {
            left: 0,
            top: 0,
            width: frame.width(),
            height: frame.height(),
        }
    }

    /// The top-left pixel only: what a frame identical to the last one still writes, so
    /// that it still counts as a frame and keeps its time on screen.
    pub(crate) fn corner() -> Rect {
        Rect {
            left: 0,
            top: 0,
            width: 1,
            height: 1,
        }
    }

    /// The smallest rectangle holding both.
    pub fn union(self, other: Rect) -> Rect {
        let left = self.left.min(other.left);
        let top = self.top.min(other.top);
        let right = (self.left + self.width).max(other.left + other.width);
        let bottom = (self.top + self.height).max(other.top + other.height);
        Rect {
            left,
            top,
            width: right - left,
            height: bottom - top,
        }
    }

    /// How many pixels it holds.
    pub(crate) fn area(self) -> u64 {
        u64::from(self.width) * u64::from(self.height)
    }

    /// Where each of its rows lies in the bytes of a frame `frame_width` px wide, top first.
    pub(crate) fn rows(self, frame_width: u32) -> impl Iterator<Item = Range<usize>> {
        let (width, left) = (frame_width as usize, self.left as usize);
        let top = self.top as usize;
        (top..top + self.height as usize).map(move |y| {
            let start = y * width + left;
            start..start + self.width as usize
        })
    }
}

/// Copies `rect` of `from` onto the same place in `onto` (both the same size).
pub fn paste(from: &IndexedFrame, rect: Rect, onto: &mut IndexedFrame) {
    let onto: &mut [u8] = onto;
    for span in rect.rows(from.width()) {
        onto[span.clone()].copy_from_slice(&from.as_raw()[span]);
    }
}

/// The side of a tile, px: small enough that a few moving balls mark little of the canvas,
/// large enough that a ball covers only a few tiles.
pub(crate) const TILE: u32 = 32;

/// The canvas cut into square tiles of [`TILE`] px, each marked or not.
#[derive(Clone, Debug)]
pub(crate) struct Tiles {
    width: u32,
    height: u32,
    /// Tiles per row and per column.
    columns: usize,
    rows: usize,
    marked: Vec<bool>,
    /// The marked tiles' numbers (row-major), in the order they were marked: what to unmark.
    list: Vec<usize>,
}

impl Tiles {
    /// No tile marked, on a canvas of `width` × `height` px.
    pub(crate) fn new(width: u32, height: u32) -> Tiles {
        let columns = width.div_ceil(TILE) as usize;
        let rows = height.div_ceil(TILE) as usize;
        Tiles {
            width,
            height,
            columns,
            rows,
            marked: vec![false; columns * rows],
            list: Vec::new(),
        }
    }

    /// Whether more than a quarter of the canvas is marked. Drawing a run again costs more
    /// per pixel than drawing the whole frame (each circle in it is cut to it, and a circle
    /// across two runs is traced twice), so beyond this the whole frame is drawn.
    pub(crate) fn much_marked(&self) -> bool {
        4 * self.list.len() > self.marked.len()
    }

    /// Marks every tile `rect` (on the canvas) touches.
    pub(crate) fn mark(&mut self, rect: Rect) {
        let (columns, rows) = self.spans(rect);
        for row in rows {
            for tile in row * self.columns + columns.start..row * self.columns + columns.end {
                if !self.marked[tile] {
                    self.marked[tile] = true;
                    self.list.push(tile);
                }
            }
        }
    }

    /// Unmarks every tile.
    pub(crate) fn clear(&mut self) {
        for &tile in &self.list {
            self.marked[tile] = false;
        }
        self.list.clear();
    }

    /// The marked tiles as rectangles on the canvas, each a run of marked tiles along a row
    /// (written into `out`, cleared first).
    pub(crate) fn runs(&self, out: &mut Vec<Rect>) {
        out.clear();
        let everywhere = Rect {
            left: 0,
            top: 0,
            width: self.width,
            height: self.height,
        };
        out.extend(self.marked_runs(everywhere));
    }

    /// The marked runs of tiles `rect` touches, each as the rectangle of the canvas it covers:
    /// where a circle inside `rect` must be drawn again.
    pub(crate) fn marked_runs(&self, rect: Rect) -> impl Iterator<Item = Rect> + '_ {
        let (columns, rows) = self.spans(rect);
        rows.flat_map(move |row| {
            let marked = &self.marked[row * self.columns..(row + 1) * self.columns];
            let mut column = columns.start;
            std::iter::from_fn(move || {
                while column < columns.end && !marked[column] {
                    column += 1;
                }
                let first = column;
                while column < columns.end && marked[column] {
                    column += 1;
                }
                (first < column).then(|| self.rect(first..column, row))
            })
        })
    }

    /// The columns and rows of tiles `rect` touches.
    fn spans(&self, rect: Rect) -> (Range<usize>, Range<usize>) {
        let tile = TILE as usize;
        let span = |start: u32, len: u32, tiles: usize| {
            let (start, end) = (start as usize, (start + len) as usize);
            (start / tile).min(tiles)..end.div_ceil(tile).min(tiles)
        };
        (
            span(rect.left, rect.width, self.columns),
            span(rect.top, rect.height, self.rows),
        )
    }

    /// The canvas under tiles `columns` of tile row `row`.
    fn rect(&self, columns: Range<usize>, row: usize) -> Rect {
        let tile = TILE as usize;
        let (left, top) = ((columns.start * tile) as u32, (row * tile) as u32);
        let right = ((columns.end * tile) as u32).min(self.width);
        let bottom = (top + TILE).min(self.height);
        Rect {
            left,
            top,
            width: right - left,
            height: bottom - top,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn marked_tiles_read_back_as_runs_along_each_row_cut_to_the_canvas() {
        let mut tiles = Tiles::new(100, 70);
        // Tiles (column, row) (1, 0) and (2, 0), and (3, 2) at the canvas's corner.
        tiles.mark(Rect {
            left: 40,
            top: 5,
            width: 30,
            height: 10,
        });
        tiles.mark(Rect {
            left: 99,
            top: 69,
            width: 1,
            height: 1,
        });
        let mut runs = Vec::new();
        tiles.runs(&mut runs);
        let rect = |left, top, width, height| Rect {
            left,
            top,
            width,
            height,
        };
        assert_eq!(runs, vec![rect(32, 0, 64, 32), rect(96, 64, 4, 6)]);
        let under: Vec<Rect> = tiles.marked_runs(rect(0, 0, 100, 40)).collect();
        assert_eq!(under, vec![rect(32, 0, 64, 32)]);
        tiles.clear();
        tiles.runs(&mut runs);
        assert_eq!(runs, vec![]);
    }
}
