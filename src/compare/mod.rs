//! `bouncing_ball compare`: one scene solved by several methods and drawn together, each
//! measured against a reference, so a learner sees on their own scene what accuracy costs.
//!
//! - [`methods`]: the methods, as `--methods` spells them (`rk4:4:exact`).
//! - `checks`: what stops a comparison midway (a signal, numbers beyond the finite).
//! - `reference`: what every method is measured against, and how far it converged.
//! - [`estimate`]: how long the whole comparison will take, predicted before any work.
//! - `measure`: the time per ball-frame, the error against the reference, the energy.
//! - `draw`: the GIF's frames: every method in its colour, the reference as outlines, the
//!   legend strip with each method's error so far.
//! - `table`: the numbers on standard output, and as CSV (`--table`).
//! - `plot`: the work-precision diagram (`--plot`): error against time, log-log.
//!
//! As [`crate::run`](mod@crate::run) does, it refuses everything it can before any work, writes every file
//! beside its target and renames them into place only at the end. The GIF holds no timing,
//! so it is the same bytes on every run; the table and the plot hold the timings.

pub(crate) mod checks;
pub(crate) mod draw;
pub mod estimate;
pub(crate) mod measure;
pub mod methods;
pub(crate) mod plot;
pub(crate) mod reference;
pub(crate) mod table;

use std::io::Write;

use crate::budget::{frame_ms_warning, long_work_warning, Budget, Estimate};
use crate::job::{Files, Job, OutputKind, RunError, Summary};
use crate::output::OutputError;
use crate::physics::{Ball, Simulation};
use crate::plot::Format;
use crate::scene::{InvalidValue, Scene};

use checks::{balls_and_frames, check_finite};
use draw::{LegendRow, Picture};
use measure::{Energy, Outcome, Role, Standing, Stray, Trust};
use methods::Method;
use reference::Reference;

/// The most ball-frames a comparison takes on: it keeps the reference's every centre (and
/// while converging, two runs of it), 16 bytes a ball-frame, so this bounds that to 128 MB.
pub(crate) const MAX_BALL_FRAMES: u64 = 1 << 22;

/// What a comparison found and wrote.
#[derive(Clone, Debug)]
pub(crate) struct Comparison {
    /// The table as the terminal shows it.
    pub table: String,
    pub summary: Summary,
}

/// Whether the balls collide with each other: then any two methods part chaotically, and the
/// frame they part at says more than the size of the error.
fn chaotic(scene: &Scene) -> bool {
    scene.ball_collisions.is_some() && scene.balls.len() > 1
}

/// Refuses a scene too big to keep the reference's path of.
fn check_size(scene: &Scene) -> Result<(), InvalidValue> {
    let ball_frames = scene.balls.len() as u64 * u64::from(scene.frames);
    if ball_frames <= MAX_BALL_FRAMES {
        return Ok(());
    }
    Err(InvalidValue {
        key: "frames".to_string(),
        value: scene.frames.to_string(),
        allowed: format!(
            "compare keeps the reference's every ball in every frame: balls × frames must be at \
             most {MAX_BALL_FRAMES} (here {} balls × {} frames)",
            scene.balls.len(),
            scene.frames
        ),
    })
}

/// Compares `methods` on `scene` and writes `job`'s outputs (the GIF, the still, the table
/// as CSV, the work-precision plot); on any error no output file is left half-written and no
/// existing file is changed.
pub(crate) fn compare(
    scene: &Scene,
    methods: &[Method],
    job: &Job,
) -> Result<Comparison, RunError> {
    scene.validate()?;
    check_size(scene)?;
    let plot_format = job.path(OutputKind::Plot).map(Format::of).transpose()?;
    let files = job.open()?;
    // Each method's memory and GIF size; the time is the whole comparison's, checked next.
    let each = Budget {
        seconds: f64::INFINITY,
        ..job.budget
    };
    for method in methods {
        Estimate::within(&method.on(scene), &each)?;
    }
    let seconds = estimate::check(scene, methods, &job.budget)?;
    let warnings = [frame_ms_warning(scene), long_work_warning(seconds)];
    job.warn(&warnings.into_iter().flatten().collect::<Vec<_>>());

    let bare = without_trails(scene);
    let reference = Reference::of(&bare, methods, job)?;
    let (strays, ends) = animate(scene, methods, job, &reference, &files)?;
    let timings = measure::time_all(&bare, methods);
    let roles: Vec<Role> = methods.iter().map(|&m| reference.role(m)).collect();
    let drifts = energy_drifts(scene, &reference, &ends, &roles);
    let (chaotic, trust) = (chaotic(scene), reference.trust(scene.frames));
    let outcomes: Vec<Outcome> = (0..methods.len())
        .map(|k| Outcome {
            method: methods[k],
            timing: timings[k],
            standing: Standing::of(roles[k], &strays[k], trust, chaotic, scene.frames),
            stray: strays[k].clone(),
            energy_drift: drifts[k],
        })
        .collect();

    let conserves = measure::conserves_energy(scene);
    let table = table::text(
        &reference.describe(),
        &outcomes,
        chaotic,
        conserves,
        trust,
        scene.frames,
    );
    let title = format!(
        "work against precision: {} · reference {}",
        balls_and_frames(scene),
        reference.method
    );
    write_table_and_plot(&files, &outcomes, chaotic, trust, plot_format, &title)?;
    let summary = job.commit(files, scene.frames)?;
    Ok(Comparison { table, summary })
}

/// `scene` without trails: what the reference and the timings run (trails are drawing).
fn without_trails(scene: &Scene) -> Scene {
    let mut bare = scene.clone();
    for ball in &mut bare.balls {
        ball.trail = 0;
    }
    bare
}

/// Each method's energy drift, given its balls in the last frame (`ends`): against the
/// first frame's energy if the scene keeps its energy, else against the reference's, which
/// needs a reference trusted to the last frame and says nothing of the reference's own method.
fn energy_drifts(
    scene: &Scene,
    reference: &Reference,
    ends: &[Vec<Ball>],
    roles: &[Role],
) -> Vec<Option<f64>> {
    let energy = Energy::new(scene);
    let start = energy.of(scene.simulation().balls());
    let conserves = measure::conserves_energy(scene);
    let target = if conserves {
        start
    } else {
        energy.of(&reference.trajectory.last)
    };
    let judged = |role| conserves || (role == Role::Method && reference.horizon >= scene.frames);
    let drift = |balls: &Vec<Ball>| (energy.of(balls) - target) / start.abs();
    ends.iter()
        .zip(roles)
        .map(|(balls, &role)| Some(drift(balls)).filter(|d| d.is_finite() && judged(role)))
        .collect()
}

/// Simulates every method frame by frame beside the reference, measuring how far each
/// strays and drawing them together into the GIF; writes the last frame as the still.
/// Returns how far each strayed, and its balls in the last frame.
fn animate(
    scene: &Scene,
    methods: &[Method],
    job: &Job,
    reference: &Reference,
    files: &Files,
) -> Result<(Vec<Stray>, Vec<Vec<Ball>>), RunError> {
    let (chaotic, trust) = (chaotic(scene), reference.trust(scene.frames));
    let reference_row = draw::reference_row(reference.method, trust, scene.frames);
    let mut widest = draw::widest_rows(methods, trust, chaotic, scene.frames);
    widest.push(reference_row.clone());
    let mut picture = Picture::new(scene, methods.len(), reference_row, &widest)?;
    let mut gif = files.start_gif(picture.size(), picture.palette(), scene.frame_ms)?;
    let mut simulations: Vec<Simulation> =
        methods.iter().map(|m| m.on(scene).simulation()).collect();
    let mut strays = vec![Stray::until(reference.horizon); methods.len()];
    job.progress().add_frames(scene.frames);
    for n in 0..scene.frames {
        job.stop_if_asked(n, scene.frames)?;
        let centres = reference.trajectory.frame(n as usize);
        for ((simulation, stray), &method) in simulations.iter_mut().zip(&mut strays).zip(methods) {
            simulation.step();
            check_finite(scene, method, simulation.balls(), n)?;
            stray.frame(n, simulation.balls(), centres);
        }
        let legend: Vec<LegendRow> = methods
            .iter()
            .zip(&strays)
            .map(|(&method, stray)| {
                let trust = reference.trust(n + 1);
                let standing = Standing::of(reference.role(method), stray, trust, chaotic, n + 1);
                LegendRow::new(method, standing)
            })
            .collect();
        let balls: Vec<&[Ball]> = simulations.iter().map(Simulation::balls).collect();
        picture.draw(&balls, centres, &legend);
        gif.write_frame(picture.frame())?;
        job.progress().frame_done();
    }
    files.finish_pictures(gif, picture.frame(), picture.palette())?;
    let ends = simulations.iter().map(|s| s.balls().to_vec()).collect();
    Ok((strays, ends))
}

/// Writes the CSV and the plot, each if asked for (`format` is the plot's).
fn write_table_and_plot(
    files: &Files,
    outcomes: &[Outcome],
    chaotic: bool,
    trust: Trust,
    format: Option<Format>,
    title: &str,
) -> Result<(), OutputError> {
    if let Some(out) = files.writer(OutputKind::Table)? {
        table::write_csv(out, outcomes, chaotic, trust)
            .map_err(files.error_at(OutputKind::Table))?;
    }
    if let (Some(mut out), Some(format)) = (files.writer(OutputKind::Plot)?, format) {
        plot::write(&mut out, format, outcomes, chaotic, trust, title)
            .and_then(|()| out.flush())
            .map_err(files.error_at(OutputKind::Plot))?;
    }
    Ok(())
}
