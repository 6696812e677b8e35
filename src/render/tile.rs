//! Tiling: several runs' frames side by side on one canvas, each under its label, in one
//! palette, as a sweep shows them.
//!
//! The panels go in rows, as square a grid as fits within `MAX_CANVAS_SIDE`. Every cell is
//! as big as the largest panel, with a strip above it for the label; a smaller panel sits at
//! its cell's top-left and the rest of the cell shows the tiling's own background, as do the
//! gaps between cells. A panel's pixels are its own run's, colour for colour: each panel's
//! palette indices are mapped into one palette holding every panel's colours, and a GIF holds
//! [`MAX_COLOURS`].

use image::Luma;

use super::palette::{IndexedFrame, Palette, MAX_COLOURS};
use super::text::{draw_text, text_width, TEXT_HEIGHT};
use crate::scene::spec::{Rgb, MAX_CANVAS_SIDE};

/// Space between cells and around the edge, px.
pub const GAP: u32 = 4;
/// The label strip above each panel: one line of text and a little room below it, px.
pub const LABEL_STRIP: u32 = TEXT_HEIGHT + 4;
/// The colour of the gaps and label strips: a dark grey, apart from any scene's black.
const BACKGROUND: Rgb = [48, 48, 48];
/// The labels' colour.
const INK: Rgb = [235, 235, 235];
/// Their indices in the tiling's palette, which starts with them.
const BACKGROUND_INDEX: u8 = 0;
const INK_INDEX: u8 = 1;

/// One panel to place: its label, its size and the palette its frames index.
pub(crate) struct PanelSpec<'a> {
    pub label: &'a str,
    pub width: u32,
    pub height: u32,
    pub palette: &'a Palette,
}

/// Where the panels go on the canvas, and how their colours map into its palette.
#[derive(Clone, Debug)]
pub(crate) struct Tiling {
    width: u32,
    height: u32,
    palette: Palette,
    panels: Vec<Placed>,
    /// The canvas before any panel is pasted: background and labels.
    blank: IndexedFrame,
}

/// A panel's top-left corner on the canvas, and the canvas index of each of its indices.
#[derive(Clone, Debug)]
struct Placed {
    x: u32,
    y: u32,
    index: Vec<u8>,
}

/// Panels that cannot be tiled into one GIF.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum TileError {
    #[error("{panels} panels of {cell_width} × {cell_height} px need a canvas of at least {width} × {height} px, over the {MAX_CANVAS_SIDE} px a side this program draws; sweep fewer values or use a smaller canvas (--width, --height)")]
    TooBig {
        panels: usize,
        cell_width: u32,
        cell_height: u32,
        width: u64,
        height: u64,
    },
    #[error("the panels need {needed} colours together (with the labels'), and a GIF holds {MAX_COLOURS}; sweep fewer values, or shorter trails or fewer trail colours")]
    TooManyColours { needed: usize },
}

impl Tiling {
    /// Lays out `panels` in order, row by row; refuses a canvas over the size limit or
    /// colours that do not fit one palette.
    pub(crate) fn new(panels: &[PanelSpec]) -> Result<Tiling, TileError> {
        let cell_width = panels.iter().map(|p| p.width).max().unwrap_or(1);
        let cell_height = panels.iter().map(|p| p.height).max().unwrap_or(1);
        let (columns, width, height) = grid(panels.len(), cell_width, cell_height)?;
        let (palette, indices) = merged_palette(panels)?;
        let mut blank = IndexedFrame::from_pixel(width, height, Luma([BACKGROUND_INDEX]));
        let placed = panels
            .iter()
            .zip(indices)
            .enumerate()
            .map(|(i, (panel, index))| {
                let (column, row) = (i as u32 % columns, i as u32 / columns);
                let x = GAP + column * (cell_width + GAP);
                let top = GAP + row * (LABEL_STRIP + cell_height + GAP);
                draw_label(&mut blank, x, top, cell_width, panel.label);
                Placed {
                    x,
                    y: top + LABEL_STRIP,
                    index,
                }
            })
            .collect();
        Ok(Tiling {
            width,
            height,
            palette,
            panels: placed,
            blank,
        })
    }

    /// The canvas's size, px.
    pub(crate) fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// Every panel's colours and the tiling's own.
    pub fn palette(&self) -> &Palette {
        &self.palette
    }

    /// A canvas with the labels and no panel yet.
    pub(crate) fn new_frame(&self) -> IndexedFrame {
        self.blank.clone()
    }

    /// Copies `frame`, drawn with panel `i`'s palette, into its place on `canvas`.
    pub fn paste(&self, i: usize, frame: &IndexedFrame, canvas: &mut IndexedFrame) {
        let placed = &self.panels[i];
        let row = frame.width() as usize;
        let stride = canvas.width() as usize;
        let canvas = canvas.as_mut();
        for (y, source) in frame.as_raw().chunks_exact(row.max(1)).enumerate() {
            let start = (placed.y as usize + y) * stride + placed.x as usize;
            for (to, &from) in canvas[start..start + row].iter_mut().zip(source) {
                *to = placed.index[usize::from(from)];
            }
        }
    }
}

/// The columns and the canvas size for `n` cells of `cell_width` × `cell_height` (plus label
/// strip and gaps): of the grids that fit, the one whose canvas is most nearly square, then
/// the one with the fewest empty cells.
fn grid(n: usize, cell_width: u32, cell_height: u32) -> Result<(u32, u32, u32), TileError> {
    let n = n.max(1) as u64;
    let size = |columns: u64| {
        let rows = n.div_ceil(columns);
        let width = columns * u64::from(cell_width + GAP) + u64::from(GAP);
        let height = rows * u64::from(LABEL_STRIP + cell_height + GAP) + u64::from(GAP);
        (width, height, columns * rows - n)
    };
    let fits = |&(width, height, _): &(u64, u64, u64)| {
        width <= u64::from(MAX_CANVAS_SIDE) && height <= u64::from(MAX_CANVAS_SIDE)
    };
    let squareness = |&(width, height, empty): &(u64, u64, u64)| {
        // Width over height or its inverse, as a fraction compared without rounding.
        let (long, short) = (width.max(height), width.min(height));
        (long * 1_000_000 / short, empty)
    };
    let best = (1..=n).map(|c| (c, size(c))).filter(|(_, s)| fits(s));
    match best.min_by_key(|(_, s)| squareness(s)) {
        Some((columns, (width, height, _))) => Ok((columns as u32, width as u32, height as u32)),
        None => {
            // The smallest canvas any grid needs, to say how far over it is.
            let (width, height, _) = size(n.isqrt().max(1));
            Err(TileError::TooBig {
                panels: n as usize,
                cell_width,
                cell_height,
                width,
                height,
            })
        }
    }
}

/// One palette for the tiling: its background (index 0) and ink, then each panel's colours in
/// the panel's own order; and for each panel, the new index of each of its indices.
fn merged_palette(panels: &[PanelSpec]) -> Result<(Palette, Vec<Vec<u8>>), TileError> {
    let mut palette = Palette::new();
    let mut needed: Vec<Rgb> = vec![BACKGROUND, INK];
    for panel in panels {
        needed.extend_from_slice(panel.palette.colours());
    }
    let mut distinct = needed.clone();
    distinct.sort_unstable();
    distinct.dedup();
    if distinct.len() > MAX_COLOURS {
        return Err(TileError::TooManyColours {
            needed: distinct.len(),
        });
    }
    for colour in [BACKGROUND, INK] {
        palette.insert(colour);
    }
    let indices = panels
        .iter()
        .map(|panel| {
            let colours = panel.palette.colours().iter();
            colours.map(|&c| palette.insert(c).unwrap_or(0)).collect()
        })
        .collect();
    Ok((palette, indices))
}

/// Draws `label` centred over a cell `width` wide whose top-left is (`x`, `top`), cut to the
/// cell when it is wider.
fn draw_label(canvas: &mut IndexedFrame, x: u32, top: u32, width: u32, label: &str) {
    let mut strip = IndexedFrame::from_pixel(width, TEXT_HEIGHT, Luma([BACKGROUND_INDEX]));
    let left = width.saturating_sub(text_width(label)) / 2;
    draw_text(&mut strip, left as i32, 0, label, INK_INDEX);
    for (sx, sy, pixel) in strip.enumerate_pixels() {
        canvas.put_pixel(x + sx, top + sy, *pixel);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::raster::to_rgb;

    /// A palette of `colours`, and a `width` × `height` frame using each of its indices.
    fn panel(colours: &[Rgb], width: u32, height: u32) -> (Palette, IndexedFrame) {
        let mut palette = Palette::new();
        for &c in colours {
            palette.insert(c);
        }
        let n = colours.len() as u32;
        let frame = IndexedFrame::from_fn(width, height, |x, y| Luma([((x + y) % n) as u8]));
        (palette, frame)
    }

    fn spec<'a>(label: &'a str, palette: &'a Palette, frame: &IndexedFrame) -> PanelSpec<'a> {
        PanelSpec {
            label,
            width: frame.width(),
            height: frame.height(),
            palette,
        }
    }

    #[test]
    fn a_pasted_panel_shows_its_own_colours_at_its_origin() {
        let (a, frame_a) = panel(&[[0, 0, 0], [255, 0, 0]], 30, 20);
        let (b, frame_b) = panel(&[[0, 0, 255], [0, 0, 0], [9, 9, 9]], 40, 10);
        let tiling = Tiling::new(&[spec("a", &a, &frame_a), spec("b", &b, &frame_b)]).unwrap();
        let mut canvas = tiling.new_frame();
        tiling.paste(0, &frame_a, &mut canvas);
        tiling.paste(1, &frame_b, &mut canvas);
        let canvas = to_rgb(&canvas, tiling.palette());
        for (i, (frame, palette)) in [(&frame_a, &a), (&frame_b, &b)].into_iter().enumerate() {
            let (x, y) = (tiling.panels[i].x, tiling.panels[i].y);
            let region = image::imageops::crop_imm(&canvas, x, y, frame.width(), frame.height());
            assert!(region.to_image() == to_rgb(frame, palette), "panel {i}");
        }
        // Cells are as big as the largest panel: the second one's sits a cell to the right.
        assert_eq!(tiling.panels[1].x, GAP + 40 + GAP);
        assert_eq!(tiling.palette().colours().len(), 2 + 4, "black is shared");
    }

    #[test]
    fn four_panels_make_a_two_by_two_grid_and_three_leave_one_cell_empty() {
        let cell = |n| grid(n, 320, 240).unwrap();
        assert_eq!(cell(4).0, 2);
        assert_eq!(cell(3).0, 2);
        assert_eq!(cell(1), (1, 320 + 2 * GAP, LABEL_STRIP + 240 + 2 * GAP));
        assert_eq!(cell(9).0, 3);
    }

    #[test]
    fn a_canvas_over_the_limit_or_colours_beyond_a_gif_are_refused() {
        assert!(matches!(
            grid(5, 4000, 4000),
            Err(TileError::TooBig { panels: 5, .. })
        ));
        let many: Vec<Rgb> = (0..=255).map(|i| [i as u8, 1, 2]).collect();
        let (p, frame) = panel(&many, 8, 8);
        let (q, _) = panel(&[[7, 7, 7]], 8, 8);
        let specs = [spec("p", &p, &frame), spec("q", &q, &frame)];
        assert!(matches!(
            Tiling::new(&specs),
            Err(TileError::TooManyColours { needed: 259 })
        ));
    }
}
