//! What `check` says about each file: one line (`match: 200 frames, 6.00 s`, or where it
//! first differs and which of the lesson's mistakes it looks like), or one JSON object; and
//! the exit code, as `diff` and `cmp` give it.

use std::path::{Path, PathBuf};

use serde_json::{json, Value};

use super::found::{Finding, Trouble};
use super::pitfalls::Pitfall;
use crate::scene::Scene;

/// How a file compares, worst last.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Grade {
    Match,
    Differs,
    /// The file could not be graded, or holds another number of frames.
    Trouble,
}

impl Grade {
    /// 0 for a match, 1 for a difference, 2 for trouble, as `diff` and `cmp` exit.
    pub(crate) fn exit_code(self) -> u8 {
        self as u8
    }

    pub(crate) fn name(self) -> &'static str {
        match self {
            Grade::Match => "match",
            Grade::Differs => "differs",
            Grade::Trouble => "trouble",
        }
    }
}

/// The verdict on one file.
#[derive(Clone, Debug)]
pub struct Verdict {
    pub path: PathBuf,
    pub grade: Grade,
    /// What is said after the path.
    pub text: String,
    /// The frames it holds (`None` for a still or a file that could not be read).
    pub frames: Option<u32>,
    /// The first frame that differs.
    pub first_difference: Option<u32>,
    pub pitfall: Option<Pitfall>,
}

impl Verdict {
    /// The verdict of a finding: a match, where it first differs and the mistake it
    /// looks like, or (trouble) another number of frames, with how the shared ones compare.
    pub(crate) fn of(
        path: &Path,
        scene: &Scene,
        finding: &Finding,
        pitfall: Option<Pitfall>,
    ) -> Verdict {
        let at = |frame: u32| seconds(scene, frame);
        let mut text = match &finding.first {
            None => match finding.frames {
                None => format!("match: the last frame (frame {})", scene.frames - 1),
                Some(n) => format!("match: {n} frames, {}", at(n)),
            },
            Some(first) => {
                format!(
                    "differs from frame {} ({}): {}",
                    first.frame,
                    at(first.frame),
                    first.what
                )
            }
        };
        if let Some(pitfall) = pitfall {
            text += &format!("; it looks like {}", pitfall.explain());
        }
        let mut grade = match finding.first {
            None => Grade::Match,
            Some(_) => Grade::Differs,
        };
        if let Some(n) = finding.frames.filter(|&n| n != scene.frames) {
            let shared = if finding.first.is_some() {
                text
            } else {
                format!("the {} shared frames match", n.min(scene.frames))
            };
            text = format!(
                "it has {n} frames ({}), but the scene has {} ({}); {shared}",
                at(n),
                scene.frames,
                at(scene.frames)
            );
            grade = Grade::Trouble;
        }
        Verdict {
            path: path.to_path_buf(),
            grade,
            text,
            frames: finding.frames,
            first_difference: finding.first.as_ref().map(|f| f.frame),
            pitfall,
        }
    }

    /// The verdict on a file that cannot be graded.
    pub(crate) fn trouble(path: &Path, trouble: &Trouble) -> Verdict {
        Verdict {
            path: path.to_path_buf(),
            grade: Grade::Trouble,
            text: format!("error: {trouble}"),
            frames: None,
            first_difference: None,
            pitfall: None,
        }
    }

    /// `PATH: what is said`.
    pub fn line(&self) -> String {
        format!("{}: {}", self.path.display(), self.text)
    }

    /// The verdict as a JSON object.
    pub(crate) fn json(&self) -> Value {
        json!({
            "file": self.path.display().to_string(),
            "verdict": self.grade.name(),
            "exit_code": self.grade.exit_code(),
            "message": self.text,
            "frames": self.frames,
            "first_difference": self.first_difference,
            "pitfall": self.pitfall.map(|p| json!({"name": p.name(), "explain": p.explain()})),
        })
    }
}

/// The time frame `frame` starts, as `0.78 s`.
fn seconds(scene: &Scene, frame: u32) -> String {
    format!(
        "{:.2} s",
        f64::from(frame) * f64::from(scene.frame_ms) / 1000.0
    )
}

/// After several files: how many match, differ and are in trouble.
pub(crate) fn summary(verdicts: &[Verdict]) -> String {
    let count = |grade| verdicts.iter().filter(|v| v.grade == grade).count();
    format!(
        "{} files: {} match, {} differ, {} in trouble",
        verdicts.len(),
        count(Grade::Match),
        count(Grade::Differs),
        count(Grade::Trouble)
    )
}
