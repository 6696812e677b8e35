//! Labels drawn into a frame: one line of text in one palette colour, for the panels of a
//! sweep and the legend of a comparison.
//!
//! The glyphs are the plot's font (DejaVu Sans, embedded), rasterised by `ab_glyph` and
//! thresholded: a pixel is lit where the glyph covers at least half of it. So a label adds one
//! colour to the palette, not a ramp of anti-aliased shades, and the GIF stays small. Each
//! glyph starts on a whole pixel, so a letter looks the same wherever it stands. The
//! rasteriser uses only f32 additions, multiplications and square roots, which every system
//! rounds alike: a label is the same pixels on every OS.

use std::sync::OnceLock;

use ab_glyph::{Font, FontRef, GlyphId, PxScale, ScaleFont};

use super::palette::IndexedFrame;

/// The height of one line of text, px: the font's ascent plus descent at this size. Nothing
/// is drawn above or below it.
pub(crate) const TEXT_HEIGHT: u32 = 18;

/// A pixel is lit where the glyph covers at least this share of it.
const LIT: f32 = 0.5;

/// The embedded font, parsed once.
fn font() -> &'static FontRef<'static> {
    static FONT: OnceLock<FontRef<'static>> = OnceLock::new();
    FONT.get_or_init(|| {
        FontRef::try_from_slice(dejavu::sans::regular()).expect("the embedded font parses")
    })
}

/// The glyphs of `text`, each with the whole pixel its origin sits at, and the width of
/// the line, px: the advances and kerning added up in f32, each glyph's start rounded.
fn layout(text: &str) -> (Vec<(GlyphId, i32)>, u32) {
    let font = font().as_scaled(PxScale::from(TEXT_HEIGHT as f32));
    let mut caret = 0.0f32;
    let mut previous: Option<GlyphId> = None;
    let mut glyphs = Vec::with_capacity(text.len());
    for c in text.chars() {
        let id = font.glyph_id(c);
        if let Some(previous) = previous {
            caret += font.kern(previous, id);
        }
        glyphs.push((id, caret.round() as i32));
        caret += font.h_advance(id);
        previous = Some(id);
    }
    (glyphs, caret.ceil() as u32)
}

/// How wide `text` is when drawn, px.
pub(crate) fn text_width(text: &str) -> u32 {
    layout(text).1
}

/// Draws `text` in palette index `colour` with its top-left corner at (`x`, `y`): lit pixels
/// stay inside `text_width(text)` × [`TEXT_HEIGHT`] from there, and inside the frame.
pub(crate) fn draw_text(frame: &mut IndexedFrame, x: i32, y: i32, text: &str, colour: u8) {
    let font = font().as_scaled(PxScale::from(TEXT_HEIGHT as f32));
    let (glyphs, width) = layout(text);
    // In i64, so a label far off the frame cannot overflow.
    let (x, y) = (i64::from(x), i64::from(y));
    let baseline = y + font.ascent().round() as i64;
    // The box the label owns, clipped to the frame: an overhanging glyph (`j`, `f`) is cut.
    let columns = x.max(0)..(x + i64::from(width)).min(i64::from(frame.width()));
    let rows = y.max(0)..(y + i64::from(TEXT_HEIGHT)).min(i64::from(frame.height()));
    for (id, dx) in glyphs {
        let glyph = id.with_scale_and_position(font.scale(), (0.0, 0.0));
        let Some(outline) = font.outline_glyph(glyph) else {
            continue; // a space
        };
        let bounds = outline.px_bounds();
        let left = x + i64::from(dx) + bounds.min.x as i64;
        let top = baseline + bounds.min.y as i64;
        outline.draw(|gx, gy, coverage| {
            let (px, py) = (left + i64::from(gx), top + i64::from(gy));
            if coverage >= LIT && columns.contains(&px) && rows.contains(&py) {
                frame.put_pixel(px as u32, py as u32, image::Luma([colour]));
            }
        });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const LABEL: &str = "damping = 0.88";

    /// A frame of index 0, with `text` drawn in index 1 at (`x`, `y`).
    fn drawn(width: u32, height: u32, x: i32, y: i32, text: &str) -> IndexedFrame {
        let mut frame = IndexedFrame::new(width, height);
        draw_text(&mut frame, x, y, text, 1);
        frame
    }

    fn lit(frame: &IndexedFrame) -> Vec<(u32, u32)> {
        frame
            .enumerate_pixels()
            .filter(|(_, _, p)| p[0] == 1)
            .map(|(x, y, _)| (x, y))
            .collect()
    }

    #[test]
    fn a_label_lights_pixels_only_inside_its_width_and_the_line_height() {
        let (x, y) = (7, 5);
        for text in [LABEL, "preset = no-gravity", "jfgy|ÉÅ_(Q)", "W"] {
            let width = text_width(text);
            let pixels = lit(&drawn(300, 40, x, y, text));
            assert!(!pixels.is_empty(), "{text:?} lit nothing");
            for (px, py) in pixels {
                let inside = (x as u32..x as u32 + width).contains(&px)
                    && (y as u32..y as u32 + TEXT_HEIGHT).contains(&py);
                assert!(
                    inside,
                    "{text:?}: ({px}, {py}) outside {width} x {TEXT_HEIGHT} at ({x}, {y})"
                );
            }
        }
    }

    #[test]
    fn a_label_is_as_wide_as_its_letters_and_no_wider() {
        let width = text_width(LABEL);
        let pixels = lit(&drawn(300, 40, 0, 0, LABEL));
        let rightmost = pixels.iter().map(|&(px, _)| px).max().unwrap();
        // The last glyph's advance leaves a little room after its ink, never a letter's worth.
        assert!(
            rightmost < width && width <= rightmost + 1 + TEXT_HEIGHT / 2,
            "ink ends at {rightmost}, width {width}"
        );
        assert_eq!(text_width(""), 0);
        assert!(lit(&drawn(50, 20, 0, 0, "")).is_empty());
        assert!(lit(&drawn(50, 20, 0, 0, "   ")).is_empty());
    }

    #[test]
    fn a_label_is_the_same_pixels_every_time_and_wherever_it_stands() {
        let here = drawn(300, 40, 3, 4, LABEL);
        assert_eq!(here, drawn(300, 40, 3, 4, LABEL));
        let there = drawn(300, 40, 20, 10, LABEL);
        let moved: Vec<_> = lit(&here).iter().map(|&(x, y)| (x + 17, y + 6)).collect();
        assert_eq!(lit(&there), moved);
    }

    #[test]
    fn a_label_past_the_frame_edges_is_clipped_without_panicking() {
        let whole = lit(&drawn(300, 40, 0, 0, LABEL));
        let cut = lit(&drawn(30, 10, -5, -3, LABEL));
        let expected: Vec<_> = whole
            .iter()
            .filter(|&&(x, y)| (5..35).contains(&x) && (3..13).contains(&y))
            .map(|&(x, y)| (x - 5, y - 3))
            .collect();
        assert!(!cut.is_empty());
        assert_eq!(cut, expected);
        assert!(lit(&drawn(30, 10, 40, 0, LABEL)).is_empty());
        assert!(lit(&drawn(30, 10, i32::MIN, i32::MAX, LABEL)).is_empty());
    }
}
