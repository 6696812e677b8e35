//! A handed-in file, recognised by its content (not its name), and handed-in pictures
//! compared with the expected frames on the timeline: frame k of the work is the picture it
//! shows at k frames' time, however its encoder stored it (repeats merged into one longer
//! frame or kept, partial frames, transparency, any disposal), and its delays are checked.

use std::fs;
use std::io::Read;
use std::path::{Path, PathBuf};

use image::RgbImage;

use super::animation::{Animation, Pictures};
use super::expected::Frames;
use super::found::{Finding, First, Trouble};
use super::pixels::{diff_picture, difference, Tolerance};
use super::trajectory::TrajectoryFile;
use crate::render::dirty::Rect;
use crate::scene::Scene;

/// What a learner handed in.
pub(crate) enum Theirs {
    Images(Images),
    Trajectory(TrajectoryFile),
}

/// Handed-in pictures.
pub(crate) enum Images {
    Gif(Animation),
    /// A PNG: the last frame.
    Still(RgbImage),
    /// A folder's PNG frames in name order.
    Folder(Vec<PathBuf>),
}

impl Theirs {
    /// Reads `path` and recognises what it is; a picture must have the scene's size and fit
    /// `memory_budget` bytes before it is decoded.
    pub fn load(path: &Path, scene: &Scene, memory_budget: u64) -> Result<Theirs, Trouble> {
        if path.is_dir() {
            let mut files: Vec<PathBuf> = fs::read_dir(path)
                .and_then(|entries| entries.map(|e| Ok(e?.path())).collect())
                .map_err(Trouble::Read)?;
            files.retain(|file| file.is_file());
            files.sort();
            if files.is_empty() {
                return Err(Trouble::EmptyFolder);
            }
            return Ok(Theirs::Images(Images::Folder(files)));
        }
        let mut start = [0; 8];
        let mut file = fs::File::open(path).map_err(Trouble::Read)?;
        let read = file.read(&mut start).map_err(Trouble::Read)?;
        match &start[..read] {
            [b'G', b'I', b'F', b'8', ..] => {
                let animation = Animation::read(path, memory_budget)?;
                same_size("the GIF", (animation.width, animation.height), scene)?;
                Ok(Theirs::Images(Images::Gif(animation)))
            }
            [0x89, b'P', b'N', b'G', ..] => {
                let still = read_png(path, scene, memory_budget)?;
                Ok(Theirs::Images(Images::Still(still)))
            }
            _ => {
                let size = file.metadata().map_err(Trouble::Read)?.len();
                if size > memory_budget {
                    return Err(Trouble::NotRecognised);
                }
                let text = fs::read(path).map_err(Trouble::Read)?;
                let text = String::from_utf8(text).map_err(|_| Trouble::NotRecognised)?;
                Ok(Theirs::Trajectory(
                    TrajectoryFile::parse(&text).ok_or(Trouble::NotRecognised)??,
                ))
            }
        }
    }
}

impl Images {
    /// These pictures against `expected`, frame by frame until the first difference; with
    /// `want_picture`, the difference drawn.
    pub(crate) fn compare(
        &self,
        scene: &Scene,
        memory_budget: u64,
        expected: &mut Frames,
        tolerance: &Tolerance,
        want_picture: bool,
    ) -> Result<Finding, Trouble> {
        let frame_cs = u64::from(scene.frame_ms / 10).max(1);
        let mut source = match self {
            Images::Gif(animation) => Source::Gif(Timeline::new(animation, frame_cs)),
            Images::Folder(files) => Source::Folder(files, None, memory_budget),
            Images::Still(picture) => Source::Still(picture),
        };
        let mut first = source.first_difference(scene, expected, tolerance, want_picture)?;
        if let Source::Gif(timeline) = &source {
            // A frame shown at the wrong moment differs, even if every picture is right; the
            // moment is named first, as what makes the picture differ there.
            if let Some((frame, what)) = timeline.off_beat(scene.frame_ms) {
                if first.as_ref().is_none_or(|f: &First| frame <= f.frame) {
                    first = Some(First {
                        frame,
                        what,
                        picture: None,
                    });
                }
            }
        }
        Ok(Finding {
            frames: source.frames(),
            first,
        })
    }
}

/// Where the pictures come from, one per frame of the timeline.
enum Source<'a> {
    Gif(Timeline<'a>),
    /// The files, the one read last, and the memory budget.
    Folder(&'a [PathBuf], Option<RgbImage>, u64),
    Still(&'a RgbImage),
}

impl Source<'_> {
    /// How many frames the pictures hold (`None` for a still, which is the last frame).
    fn frames(&self) -> Option<u32> {
        match self {
            Source::Gif(timeline) => Some(timeline.frames),
            Source::Folder(files, ..) => Some(files.len() as u32),
            Source::Still(_) => None,
        }
    }

    /// The first frame the pictures show differently from `expected`, beyond `tolerance`,
    /// if any; with `want_picture`, the difference drawn.
    fn first_difference(
        &mut self,
        scene: &Scene,
        expected: &mut Frames,
        tolerance: &Tolerance,
        want_picture: bool,
    ) -> Result<Option<First>, Trouble> {
        let count = self.frames();
        let last = scene.frames.saturating_sub(1);
        let shared = count.map_or(scene.frames, |n| n.min(scene.frames));
        let total = u64::from(scene.width) * u64::from(scene.height);
        // Once a frame matches with no differing pixel allowed, the next can differ only where
        // either side changed since; with some allowed, each frame is compared whole.
        let regional = !tolerance.admits(1, total);
        let mut compared = false;
        for k in 0..shared {
            let (ours, palette, our_change) = expected.next_frame();
            if count.is_none() && k != last {
                continue;
            }
            let (theirs, their_change) = self.picture(k, scene)?;
            let region = match compared && regional {
                false => Some(whole(theirs)),
                true => our_change
                    .into_iter()
                    .chain(their_change)
                    .reduce(Rect::union),
            };
            compared = true;
            let Some(region) = region else {
                continue; // neither side changed
            };
            let Some(found) = difference(ours, palette, theirs, tolerance, region) else {
                continue;
            };
            if tolerance.admits(found.pixels, total) {
                continue;
            }
            return Ok(Some(First {
                frame: k,
                what: format!(
                    "{} pixels in x {}–{}, y {}–{}",
                    found.pixels, found.x.0, found.x.1, found.y.0, found.y.1
                ),
                picture: want_picture.then(|| diff_picture(ours, palette, theirs, tolerance)),
            }));
        }
        Ok(None)
    }

    /// The picture of frame `k` (asked for in increasing order), and where it may have
    /// changed since the last one asked for.
    fn picture(&mut self, k: u32, scene: &Scene) -> Result<(&RgbImage, Option<Rect>), Trouble> {
        let picture = match self {
            Source::Gif(timeline) => return timeline.picture_at(k),
            Source::Folder(files, read, budget) => {
                let file = &files[k as usize];
                let picture =
                    read_png(file, scene, *budget).map_err(|trouble| Trouble::InFolder {
                        file: file.clone(),
                        trouble: Box::new(trouble),
                    })?;
                &*read.insert(picture)
            }
            Source::Still(picture) => *picture,
        };
        Ok((picture, Some(whole(picture))))
    }
}

/// A GIF's stored frames laid on the scene's timeline of `frame_cs` hundredths each.
struct Timeline<'a> {
    pictures: Pictures<'a>,
    /// When each stored frame starts, hundredths of a second.
    starts: Vec<u64>,
    /// When the last stored frame ends.
    total: u64,
    /// The stored frames drawn so far.
    drawn: usize,
    frame_cs: u64,
    /// How many of the scene's frames it lasts.
    frames: u32,
}

impl<'a> Timeline<'a> {
    fn new(animation: &'a Animation, frame_cs: u64) -> Timeline<'a> {
        let mut starts = Vec::new();
        let total = animation.delays().fold(0, |start, delay| {
            starts.push(start);
            start + u64::from(delay)
        });
        Timeline {
            pictures: animation.pictures(),
            frames: total.div_ceil(frame_cs) as u32,
            total,
            starts,
            drawn: 0,
            frame_cs,
        }
    }

    /// The picture shown at the start of frame `k`: every stored frame that starts by then
    /// drawn; and where it changed since the last one asked for.
    fn picture_at(&mut self, k: u32) -> Result<(&RgbImage, Option<Rect>), Trouble> {
        let now = u64::from(k) * self.frame_cs;
        while self
            .starts
            .get(self.drawn)
            .is_some_and(|&start| start <= now)
        {
            self.pictures.advance()?;
            self.drawn += 1;
        }
        let changed = self.pictures.take_changed();
        Ok((self.pictures.canvas(), changed))
    }

    /// The first stored frame that starts between two of the scene's frames (or the end,
    /// if the GIF ends between two), and the frame of the scene it falls in.
    fn off_beat(&self, frame_ms: u32) -> Option<(u32, String)> {
        if self.total == 0 {
            return Some((0, "every frame's delay is 0".to_string()));
        }
        let odd = self.starts.iter().chain([&self.total]);
        let j = odd.clone().position(|cs| cs % self.frame_cs != 0)?;
        let cs = self.starts.get(j).copied().unwrap_or(self.total);
        let what = match j < self.starts.len() {
            true => format!("stored frame {j} starts"),
            false => "the GIF ends".to_string(),
        };
        Some((
            (cs / self.frame_cs) as u32,
            format!(
                "{what} at {:.2} s, between two frames of {frame_ms} ms",
                cs as f64 / 100.0
            ),
        ))
    }
}

/// A PNG as RGB, once its size is the scene's and fits `memory_budget`.
fn read_png(path: &Path, scene: &Scene, memory_budget: u64) -> Result<RgbImage, Trouble> {
    use image::ImageDecoder;
    let bad = |error: image::ImageError| Trouble::BadPng(error.to_string());
    let reader = image::ImageReader::open(path).map_err(Trouble::Read)?;
    let reader = reader.with_guessed_format().map_err(Trouble::Read)?;
    let decoder = reader.into_decoder().map_err(bad)?;
    let (width, height) = decoder.dimensions();
    // Decoded as RGBA at most, then as RGB.
    let needs = u64::from(width) * u64::from(height) * 4;
    Trouble::over_budget(width, height, needs, memory_budget)?;
    same_size("the PNG", (width, height), scene)?;
    Ok(image::DynamicImage::from_decoder(decoder)
        .map_err(bad)?
        .to_rgb8())
}

/// The whole of `picture`.
fn whole(picture: &RgbImage) -> Rect {
    Rect {
        left: 0,
        top: 0,
        width: picture.width(),
        height: picture.height(),
    }
}

/// Refuses a picture whose size is not the scene's, saying both.
fn same_size(what: &str, theirs: (u32, u32), scene: &Scene) -> Result<(), Trouble> {
    let ours = (scene.width, scene.height);
    if theirs == ours {
        return Ok(());
    }
    Err(Trouble::Size {
        what: what.to_string(),
        theirs,
        scene: ours,
    })
}
