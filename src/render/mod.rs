//! Rendering: a frame of balls drawn into palette indices, and the still PNG.
//!
//! - `palette`: the colour table, built once per scene, with the trail's faded shades.
//! - `ellipse`: solid circles, exactly the pixels Pillow's `ImageDraw.ellipse` fills.
//! - `line`: one-pixel floor segments.
//! - `outline`: one-pixel circle outlines (where `compare` says a ball should be).
//! - `raster`: draws the trail oldest first, fading and shrinking, then the ball on top.
//! - `redraw`: frame after frame, drawn again only where something changed; `dirty`: the
//!   rectangles and tiles that say where.
//! - `png`: one frame as an RGB PNG.
//! - `text`: labels in the plot's font, one palette colour, drawn into a frame.
//! - `tile`: several runs' frames side by side, labelled, in one palette (a sweep).

pub(crate) mod dirty;
pub(crate) mod ellipse;
pub(crate) mod line;
pub(crate) mod outline;
pub(crate) mod palette;
pub(crate) mod png;
pub(crate) mod raster;
pub(crate) mod redraw;
pub(crate) mod text;
pub(crate) mod tile;

pub use palette::IndexedFrame;
pub use palette::Palette;
pub(crate) use png::{write_png, write_rgb_png};
pub use raster::{to_rgb, Renderer};
pub use redraw::{Canvas, Damage};
