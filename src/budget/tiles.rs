//! A sweep's budget: several panels run side by side on one canvas, one GIF of them all.

use super::cost::{time_and_size, Activity};
use super::memory::memory_of;
use super::{Budget, Estimate, OverBudget};
use crate::scene::Scene;

impl Estimate {
    /// The cost of `panels` run side by side on one `width` × `height` canvas (a sweep), refused
    /// if over `budget`: every panel's physics and drawing, and one GIF of the whole canvas,
    /// whose changed rectangle spans the panels (taken as the whole canvas in every frame some
    /// panel changes). Memory is checked first, from the scenes alone.
    pub(crate) fn of_tiles(
        panels: &[&Scene],
        width: u32,
        height: u32,
        budget: &Budget,
    ) -> Result<Estimate, OverBudget> {
        let frames = panels.iter().map(|s| s.frames).max().unwrap_or(1);
        let canvas = Scene {
            frames,
            ..Scene::empty(width, height)
        };
        let biggest = "the panels' runs and the tiled frames";
        // Each panel: its balls, trails and shades, and the one frame it is drawn into; the
        // program itself, the GIF's queue and the still are the canvas's.
        let panel_memory = |scene: &Scene| {
            let frame = u64::from(scene.width) * u64::from(scene.height);
            let bare = memory_of(&Scene::empty(scene.width, scene.height)).0;
            memory_of(scene).0.saturating_sub(bare) + frame
        };
        let memory = memory_of(&canvas).0 + panels.iter().map(|s| panel_memory(s)).sum::<u64>();
        if memory > budget.memory {
            return Err(OverBudget::Memory {
                needed: memory,
                budget: budget.memory,
                biggest,
            });
        }
        // The panels' own changes, coded as the canvas's.
        let pilots: Vec<Activity> = panels.iter().map(|scene| Activity::of(scene)).collect();
        let mut activity = Activity::default();
        for pilot in &pilots {
            activity.add(*pilot);
        }
        activity.changed_frames = activity.changed_frames.min(f64::from(frames));
        // The tiled frame is compared whole every frame; the panels' drawing and stepping are
        // counted with each panel, below.
        (
            activity.drawn_frames,
            activity.awake_ball_frames,
            activity.events,
        ) = (f64::from(frames), 0.0, 0.0);
        activity.rect_pixels = activity.changed_frames * f64::from(width) * f64::from(height);
        let parts = panels
            .iter()
            .zip(&pilots)
            .map(|(scene, pilot)| (*scene, Activity::every_frame(scene, pilot)));
        let parts: Vec<_> = parts
            .chain([(&canvas, activity)])
            .map(|(scene, activity)| time_and_size(scene, &activity))
            .collect();
        let estimate = Estimate {
            memory,
            frame_ns: parts.iter().map(|e| e.frame_ns).sum(),
            seconds: parts.iter().map(|e| e.seconds).sum(),
            gif_bytes: parts.iter().map(|e| e.gif_bytes).sum(),
            biggest,
        };
        estimate.check_time_and_size(budget)?;
        Ok(estimate)
    }
}
