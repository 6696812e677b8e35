//! What grading a file finds: where it first differs from the expected frames, or why it
//! cannot be graded ([`Trouble`], one line each).

use std::path::PathBuf;

use image::RgbImage;

/// Why a file cannot be graded, in one line each.
#[derive(Debug, thiserror::Error)]
pub(crate) enum Trouble {
    #[error("cannot read it: {0}")]
    Read(std::io::Error),
    #[error("not an image or a trajectory: a GIF, a PNG, a folder of PNG frames, a --trace CSV or lines of x y vx vy")]
    NotRecognised,
    #[error("not a whole GIF: {0}")]
    NotWhole(String),
    #[error("not a readable PNG: {0}")]
    BadPng(String),
    #[error("a {width}×{height} picture needs {} MB to decode, over the memory budget of {} MB (--memory-budget)", needs >> 20, budget >> 20)]
    OverBudget {
        width: u32,
        height: u32,
        needs: u64,
        budget: u64,
    },
    #[error("{what} is {}×{} px, but the scene is {}×{} px", theirs.0, theirs.1, scene.0, scene.1)]
    Size {
        what: String,
        theirs: (u32, u32),
        scene: (u32, u32),
    },
    #[error("{}: {trouble}", file.display())]
    InFolder {
        file: PathBuf,
        trouble: Box<Trouble>,
    },
    #[error("an empty folder: no PNG frames in it")]
    EmptyFolder,
    #[error("line {line}: expected {expected}, got {got:?}")]
    Trajectory {
        line: usize,
        expected: &'static str,
        got: String,
    },
    #[error(
        "line {line}: expected frame {frame}, ball {ball} (rows go frame by frame, ball by ball)"
    )]
    OutOfOrder {
        line: usize,
        frame: u32,
        ball: usize,
    },
    #[error("plain x y vx vy lines hold one ball, but the scene has {balls}: give a --trace CSV")]
    PlainLines { balls: usize },
    #[error("{rows} rows do not make whole frames of the scene's {balls} balls")]
    PartFrame { rows: usize, balls: usize },
}

impl Trouble {
    /// Refuses a `width` × `height` picture that `needs` more bytes to decode than `budget`.
    pub(crate) fn over_budget(
        width: u32,
        height: u32,
        needs: u64,
        budget: u64,
    ) -> Result<(), Trouble> {
        if needs <= budget {
            return Ok(());
        }
        Err(Trouble::OverBudget {
            width,
            height,
            needs,
            budget,
        })
    }
}

/// What comparing a file with the expected frames found: how many frames it holds (`None`
/// for a still, which is the last) and where it first differs.
pub(crate) struct Finding {
    pub frames: Option<u32>,
    pub first: Option<First>,
}

/// The first frame that differs, what differs in it and, for pictures, expected | theirs |
/// difference side by side.
pub(crate) struct First {
    pub frame: u32,
    pub what: String,
    pub picture: Option<RgbImage>,
}
