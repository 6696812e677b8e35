//! What only the integration tests reach into: parts of the stages that they test on their
//! own (the GIF's coders and queue, the palette, the tiling's layout, the plot's recording,
//! the work tally). These modules are private to the crate; the program, the examples, the
//! benches and the lab never need them, so they are not part of its API.

pub use crate::budget::memory::kept_frames_bytes;
pub use crate::check::animation::lzw_indices;
pub use crate::gif::coders::THREADS_VARIABLE;
pub use crate::gif::encoder::{queue_frames, MAX_QUEUED_FRAMES, QUEUE_PIXELS};
pub use crate::gif::interlace::interlace;
pub use crate::gif::transparency::{
    mark_mixed_stretches, mark_unchanged, mixed_neighbours, transparent_index,
};
pub use crate::plot::record::Recording;
pub use crate::render::dirty::Rect;
pub use crate::render::ellipse::fill_circle;
pub use crate::render::palette::{shade, MAX_COLOURS};
pub use crate::render::redraw::MOST_BUSY_FRAMES;
pub use crate::render::tile::{GAP, LABEL_STRIP};
pub use crate::scene::overrides::Overrides;

/// The tally of the work each stage does (with the `work-tally` feature).
pub mod work {
    pub use crate::work::{count, reset, Work};
}
