//! The GIF's colour table, built once per scene from the scene's own colours,
//! so no frame is ever colour-quantised.
//!
//! A GIF holds at most 256 colours. The background, the ball colours and every shade
//! a trail can fade through normally fit. When they do not (long trails, many trail
//! colours), the rule is: every trail fades through the same number of evenly spaced
//! shades, as many as fit, the faintest never black (`fade_levels`).

use std::collections::HashMap;
use std::fmt;

use crate::scene::spec::Rgb;

/// A frame as indices into the palette, one byte per pixel.
pub type IndexedFrame = image::GrayImage;

/// How many colours a GIF colour table holds.
pub const MAX_COLOURS: usize = 256;

/// A colour table and the index of each colour in it.
#[derive(Clone, Debug)]
pub struct Palette {
    colours: Vec<Rgb>,
    index: HashMap<Rgb, u8>,
}

/// A scene whose solid colours alone do not fit a GIF's colour table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TooManyColours {
    pub needed: usize,
}

impl fmt::Display for TooManyColours {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "the scene needs {} solid colours (background, balls) and at least one shade per trail colour; a GIF holds {MAX_COLOURS}",
            self.needed
        )
    }
}

impl std::error::Error for TooManyColours {}

impl Palette {
    /// An empty table.
    pub fn new() -> Palette {
        Palette {
            colours: Vec::new(),
            index: HashMap::new(),
        }
    }

    /// The index of `colour`, adding it if it is new. `None` once the table is full.
    pub fn insert(&mut self, colour: Rgb) -> Option<u8> {
        if let Some(&i) = self.index.get(&colour) {
            return Some(i);
        }
        let i = u8::try_from(self.colours.len()).ok()?;
        self.colours.push(colour);
        self.index.insert(colour, i);
        Some(i)
    }

    /// The colours, in index order.
    pub fn colours(&self) -> &[Rgb] {
        &self.colours
    }

    /// The colour at `index`.
    pub fn rgb(&self, index: u8) -> Rgb {
        self.colours[usize::from(index)]
    }
}

impl Default for Palette {
    fn default() -> Self {
        Palette::new()
    }
}

/// The lesson's fade: dot `i` (0 = oldest) of a trail of `n` shines at `(i + 1) / n`.
pub fn fade(i: usize, n: usize) -> f64 {
    (i + 1) as f64 / n as f64
}

/// A trail colour dimmed by `fade`, each channel truncated as the lesson's `int(c * fade)`.
pub fn shade(colour: Rgb, fade: f64) -> Rgb {
    colour.map(|c| (f64::from(c) * fade) as u8)
}

/// `fade` rounded up to one of `levels` evenly spaced steps (the colour budget rule).
pub fn quantised_fade(fade: f64, levels: usize) -> f64 {
    let levels = levels as f64;
    (fade * levels).ceil() / levels
}

/// How many shades each trail may use so that `solid` colours plus the trails'
/// shades fit in a GIF: `None` when every exact shade fits, else the level count.
pub fn fade_levels(
    solid: &[Rgb],
    trails: &[(Rgb, usize)],
) -> Result<Option<usize>, TooManyColours> {
    let mut exact = Palette::new();
    let mut fits = solid.iter().all(|&c| exact.insert(c).is_some());
    for &(colour, len) in trails {
        for n in 1..=len {
            for i in 0..n {
                fits = fits && exact.insert(shade(colour, fade(i, n))).is_some();
            }
        }
    }
    if fits {
        return Ok(None);
    }
    let mut distinct_solid = solid.to_vec();
    distinct_solid.sort_unstable();
    distinct_solid.dedup();
    let mut trail_colours: Vec<Rgb> = trails.iter().filter(|t| t.1 > 0).map(|t| t.0).collect();
    trail_colours.sort_unstable();
    trail_colours.dedup();
    let spare = MAX_COLOURS.saturating_sub(distinct_solid.len());
    let levels = spare / trail_colours.len().max(1);
    if levels == 0 {
        return Err(TooManyColours {
            needed: distinct_solid.len() + trail_colours.len(),
        });
    }
    Ok(Some(levels))
}
