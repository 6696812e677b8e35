//! The animated GIF: only what changed in each frame, compressed on every core, streamed out.
//!
//! - [`delta`]: the rectangle that changed since the last frame.
//! - `transparency`: unchanged pixels marked transparent, two ways.
//! - `interlace`: GIF's interlaced row order, another order for LZW to read.
//! - [`lzw`]: GIF's LZW compression, one coder per thread.
//! - `runs`: the runs of one colour a coder's dictionary holds, so that it takes a run at once.
//! - `cheapest`: each frame's smallest encoding among a few candidates.
//! - `coders`: frames compressed on every core, the caller's included.
//! - `encoder`: frames cut to what changed, handed to the coders, written in order.

pub(crate) mod cheapest;
pub(crate) mod coders;
pub mod delta;
pub(crate) mod encoder;
pub(crate) mod interlace;
pub mod lzw;
pub(crate) mod runs;
pub(crate) mod transparency;

pub use encoder::GifWriter;
