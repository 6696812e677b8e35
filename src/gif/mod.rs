//! The animated GIF: only what changed in each frame, compressed on every core, streamed out.
//!
//! - [`delta`]: the rectangle that changed since the last frame.
//! - [`lzw`]: GIF's LZW compression, one coder per thread.
//! - [`encoder`]: frames queued in a bounded batch, compressed in parallel, written in order.

pub mod delta;
pub mod encoder;
pub mod lzw;

pub use encoder::GifWriter;
