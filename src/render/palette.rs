//! The GIF's colour table, built once per scene from the scene's own colours,
//! so no frame is ever colour-quantised.
//!
//! A GIF holds at most 256 colours. The background, the ball colours and every shade
//! a trail can fade through normally fit. When they do not (long trails, many trail
//! colours), the rule is: every trail fades through the same number of evenly spaced
//! shades, as many as fit, the faintest never black (`fade_levels`).
//!
//! Only colours that can be seen enter the table: a trail's newest dot lies exactly under its
//! ball and is never drawn (`drawn_dots`). A smaller table lets the GIF use shorter codes.
//! And the colours drawn together get neighbouring low indices (`Palette::reorder`): a GIF
//! frame whose indices all lie below 2^k is coded with k-bit indices.

use std::collections::HashMap;
use std::fmt;
use std::ops::Range;

use crate::physics::maths;
use crate::scene::spec::{Rgb, TrailFade};

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

impl Palette {
    /// Reorders the table so that each stage's colours take indices as low as they can, and
    /// returns the new index of each old one. A stage is the set of colours some frames draw.
    /// `stages[0]` is placed first (it should be the one most frames show); then, again and
    /// again, the stage that needs the fewest colours not yet placed (the first of equals).
    /// Colours of no stage go last. The greedy choice is gifsicle's idea, done per stage.
    pub(crate) fn reorder(&mut self, stages: &[Colours]) -> Vec<u8> {
        // The old indices in their new order, and the set of them.
        let mut order = Vec::with_capacity(self.colours.len());
        let mut placed = Colours::default();
        let mut place = |stage: &Colours, placed: &mut Colours| {
            for index in stage.indices() {
                if !placed.contains(index) {
                    placed.insert(index);
                    order.push(index);
                }
            }
        };
        let mut waiting: Vec<&Colours> = stages.iter().collect();
        let mut next = 0;
        while !waiting.is_empty() {
            place(waiting.remove(next), &mut placed);
            next = (0..waiting.len())
                .min_by_key(|&w| waiting[w].count_outside(&placed))
                .unwrap_or(0);
        }
        place(&Colours::below(self.colours.len()), &mut placed);

        let mut new_index = vec![0; self.colours.len()];
        for (new, &old) in order.iter().enumerate() {
            new_index[usize::from(old)] = new as u8;
        }
        self.colours = order.iter().map(|&old| self.rgb(old)).collect();
        for index in self.index.values_mut() {
            *index = new_index[usize::from(*index)];
        }
        new_index
    }
}

/// A set of palette indices, such as the colours some frames draw.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Colours([u64; 4]);

impl Colours {
    /// Indices `0..len`.
    fn below(len: usize) -> Colours {
        let mut all = Colours::default();
        for index in 0..len.min(MAX_COLOURS) {
            all.insert(index as u8);
        }
        all
    }

    pub(crate) fn insert(&mut self, index: u8) {
        self.0[usize::from(index / 64)] |= 1 << (index % 64);
    }

    pub(crate) fn contains(&self, index: u8) -> bool {
        self.0[usize::from(index / 64)] & (1 << (index % 64)) != 0
    }

    /// Every index in both sets.
    pub(crate) fn union(&self, other: &Colours) -> Colours {
        Colours(std::array::from_fn(|w| self.0[w] | other.0[w]))
    }

    /// How many of these indices are not in `other`.
    pub(crate) fn count_outside(&self, other: &Colours) -> u32 {
        self.0
            .iter()
            .zip(&other.0)
            .map(|(a, b)| (a & !b).count_ones())
            .sum()
    }

    /// The indices, lowest first.
    pub(crate) fn indices(&self) -> impl Iterator<Item = u8> + '_ {
        (0..=u8::MAX).filter(|&i| self.contains(i))
    }
}

impl Default for Palette {
    fn default() -> Self {
        Palette::new()
    }
}

/// The lesson's fade: dot `i` (0 = oldest) of a trail of `n` shines at `(i + 1) / n`.
pub(crate) fn fade(i: usize, n: usize) -> f64 {
    (i + 1) as f64 / n as f64
}

/// How a scene's trails look: how their dots darken and whether they shrink into the past.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct TrailLook {
    pub fade: TrailFade,
    pub shrink: bool,
}

impl TrailLook {
    /// The share of the trail colour dot `i` of a trail of `n` is drawn in.
    pub(crate) fn colour_share(&self, i: usize, n: usize) -> f64 {
        match self.fade {
            TrailFade::Linear => fade(i, n),
            TrailFade::None => 1.0,
            TrailFade::Power(p) => maths::powf(fade(i, n), p),
        }
    }

    /// The share of the ball's radius dot `i` of a trail of `n` is drawn at.
    pub(crate) fn size_share(&self, i: usize, n: usize) -> f64 {
        if self.shrink {
            fade(i, n)
        } else {
            1.0
        }
    }
}

/// The dots drawn of a trail of `n`: all but the newest. The newest is where the ball is now,
/// at fade 1, so the same circle as the ball, which is drawn over it: its shade is never seen.
pub(crate) fn drawn_dots(n: usize) -> Range<usize> {
    0..n.saturating_sub(1)
}

/// A trail colour dimmed by `fade`, each channel truncated as the lesson's `int(c * fade)`.
pub fn shade(colour: Rgb, fade: f64) -> Rgb {
    colour.map(|c| (f64::from(c) * fade) as u8)
}

/// `fade` rounded up to one of `levels` evenly spaced steps (the colour budget rule).
pub(crate) fn quantised_fade(fade: f64, levels: usize) -> f64 {
    let levels = levels as f64;
    (fade * levels).ceil() / levels
}

/// How many shades each trail may use so that `solid` colours plus the trails'
/// shades fit in a GIF: `None` when every exact shade fits, else the level count.
pub(crate) fn fade_levels(
    solid: &[Rgb],
    trails: &[(Rgb, usize)],
    look: TrailLook,
) -> Result<Option<usize>, TooManyColours> {
    let mut exact = Palette::new();
    let mut fits = solid.iter().all(|&c| exact.insert(c).is_some());
    for &(colour, len) in trails {
        for n in 1..=len {
            for i in drawn_dots(n) {
                fits = fits
                    && exact
                        .insert(shade(colour, look.colour_share(i, n)))
                        .is_some();
            }
        }
    }
    if fits {
        return Ok(None);
    }
    let mut distinct_solid = solid.to_vec();
    distinct_solid.sort_unstable();
    distinct_solid.dedup();
    let mut trail_colours: Vec<Rgb> = trails.iter().filter(|t| t.1 > 1).map(|t| t.0).collect();
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
