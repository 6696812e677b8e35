//! The command line. The constants below are the default scene: edit one, run
//! `cargo run --release`, and watch what changes. Each is also a flag (`--help`).

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use bouncing_ball::budget::{
    Budget, DEFAULT_GIF_BUDGET, DEFAULT_MEMORY_BUDGET, DEFAULT_TIME_BUDGET,
};
use bouncing_ball::messages::{fail, flag, refuse, summary_line, whole_number};
use bouncing_ball::scene::file::Canvas;
use bouncing_ball::scene::{self, preset_names, Overrides, SceneFileError, TrailFade};
use bouncing_ball::stop::Stop;
use bouncing_ball::sweep::{self, Change, Sweep, SweepError, SweepOutputs};
use bouncing_ball::{compare, run, BallSpec, Outputs, Scene};
use clap::{ArgAction, CommandFactory, FromArgMatches, Parser, Subcommand};
use clap_complete::Shell;

// --- Canvas ---
/// Canvas width, px.
const WIDTH: u32 = 320;
/// Canvas height, px.
const HEIGHT: u32 = 240;

// --- Ball ---
/// Ball radius, px.
const RADIUS: f64 = 12.0;
/// Where the ball starts (x, y), px from the top-left corner.
const START: (f64, f64) = (40.0, 40.0);
/// The ball's starting velocity (vx, vy), px/frame; y grows downwards.
const INITIAL_VEL: (f64, f64) = (5.2, 0.0);

// --- Physics ---
/// Added to the downward velocity every frame, px/frame².
const GRAVITY: f64 = 0.5;
/// Share of speed a bounce keeps: 1.0 is elastic, 0.0 stops dead.
const BOUNCE_DAMPING: f64 = 0.88;

// --- Animation ---
/// How many past positions the trail shows, points.
const TRAIL_LEN: usize = 20;
/// How trail dots darken into the past: `Linear` (share (i+1)/n of the colour), `None`, or
/// `Power(p)` (that share to the power p).
const TRAIL_FADE: TrailFade = TrailFade::Linear;
/// Whether trail dots shrink into the past along with their fade.
const TRAIL_SHRINK: bool = true;
/// How many frames to simulate, frames.
const FRAMES: u32 = 200;
/// How long each frame shows, ms (GIF counts hundredths, so a multiple of 10).
const FRAME_MS: u32 = 30;

// --- Colours (red, green, blue) ---
/// Canvas colour.
const BACKGROUND: [u8; 3] = [0, 0, 0];
/// Ball colour.
const BALL_COLOUR: [u8; 3] = [255, 200, 60];
/// Trail colour at full brightness; older dots fade towards black.
const TRAIL_COLOUR: [u8; 3] = [60, 140, 255];

/// Simulates a bouncing ball and writes an animated GIF and a still PNG of its last frame.
#[derive(Parser, Debug)]
#[command(
    version,
    about,
    long_about = None,
    allow_negative_numbers = true,
    args_conflicts_with_subcommands = true,
    disable_help_flag = true,
    disable_help_subcommand = true,
    after_help = "Without --scene or --preset it runs the lesson's scene (the constants in \
                  src/main.rs). Flags you type override the scene's values; ball flags apply \
                  to every ball."
)]
struct Args {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    scene: SceneArgs,
    /// Where to write the animated GIF
    #[arg(short = 'o', long, default_value = "bouncing_ball.gif")]
    gif: PathBuf,
    /// Where to write the still PNG (the last frame)
    #[arg(long, default_value = "bouncing_ball.png")]
    png: PathBuf,
    /// Also write every frame's state as CSV (frame,ball,x,y,vx,vy); - for standard output
    #[arg(long)]
    trace: Option<PathBuf>,
    /// Also draw height, speed and energy per frame (SVG; PNG if PATH ends in .png)
    #[arg(long, value_name = "PATH")]
    plot: Option<PathBuf>,
    #[command(flatten)]
    run: RunArgs,
}

/// What every command that runs a scene takes besides the scene and its outputs.
#[derive(clap::Args, Debug)]
struct RunArgs {
    #[command(flatten)]
    budget: BudgetArgs,
    /// Print nothing on success
    #[arg(short, long)]
    quiet: bool,
    /// Print help
    #[arg(short, long, action = ArgAction::HelpShort)]
    help: Option<bool>,
}

/// What a run may be predicted to need before it is refused.
#[derive(clap::Args, Debug)]
struct BudgetArgs {
    /// Refuse a scene predicted to need more memory than this, MB
    #[arg(long, value_name = "MB", default_value_t = DEFAULT_MEMORY_BUDGET >> 20,
          value_parser = whole_number, allow_hyphen_values = true)]
    memory_budget: u64,
    /// Refuse a run predicted to take longer than this, seconds
    #[arg(long, value_name = "SECONDS", default_value_t = DEFAULT_TIME_BUDGET as u64,
          value_parser = whole_number, allow_hyphen_values = true)]
    time_budget: u64,
    /// Refuse a run whose GIF is predicted to be bigger than this, MB
    #[arg(long, value_name = "MB", default_value_t = DEFAULT_GIF_BUDGET >> 20,
          value_parser = whole_number, allow_hyphen_values = true)]
    gif_budget: u64,
}

impl BudgetArgs {
    fn budget(&self) -> Budget {
        Budget {
            memory: self.memory_budget.saturating_mul(1 << 20),
            seconds: self.time_budget as f64,
            gif_bytes: self.gif_budget.saturating_mul(1 << 20),
        }
    }
}

/// What to simulate: a scene file, a preset or the lesson's scene, and the flags laid over it
/// (the main command's, and every subcommand that runs a scene).
#[derive(clap::Args, Clone, Debug)]
struct SceneArgs {
    /// Load the scene from a TOML file (- for standard input)
    #[arg(short, long, conflicts_with = "preset")]
    scene: Option<PathBuf>,
    /// Load a bundled scene
    #[arg(short, long, value_parser = preset_names())]
    preset: Option<String>,
    /// Seed for everything random (same seed, same bytes out)
    #[arg(long, default_value_t = 1, value_parser = whole_number, allow_hyphen_values = true)]
    seed: u64,
    // --width to --frame-ms: the scene settings, a row each in src/scene/overrides.rs.
    #[command(flatten)]
    settings: Overrides,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Run the scene with several methods side by side, each measured against a reference: a GIF of them together, a table of time, error and energy, and optionally a work-precision plot
    Compare(Box<CompareArgs>),
    /// Print a shell completion script, for an installed binary (`cargo install --path .`), e.g. `bouncing_ball completions bash > ~/.local/share/bash-completion/completions/bouncing_ball`
    Completions {
        /// The shell to complete for
        shell: Shell,
    },
    /// Run the scene once per value of one setting, side by side in one GIF, e.g. `bouncing_ball sweep damping=0.5,0.7,0.88,1` (docs/sweep.md)
    Sweep {
        /// The setting to vary and its values: a flag's name without -- (or preset), =, values separated by commas
        #[arg(value_name = "KEY=V1,V2,...")]
        values: String,
        // Boxed: the scene's flags are most of the command line's size.
        #[command(flatten)]
        scene: Box<SceneArgs>,
        /// Where to write the tiled GIF
        #[arg(short = 'o', long, default_value = "sweep.gif")]
        gif: PathBuf,
        /// Also write the last tiled frame as a PNG
        #[arg(long)]
        png: Option<PathBuf>,
        #[command(flatten)]
        run: RunArgs,
    },
}

/// `compare`: the scene as the main command takes it, the methods, and where the results go.
#[derive(clap::Args, Debug)]
struct CompareArgs {
    #[command(flatten)]
    scene: SceneArgs,
    /// The methods, each INTEGRATOR:SUBSTEPS:COLLISIONS (names as --integrator and
    /// --collisions spell them), separated by commas
    #[arg(long, value_name = "LIST", default_value = compare::methods::DEFAULT_METHODS,
          value_parser = compare::methods::parse_list)]
    methods: compare::methods::MethodList,
    /// Where to write the animated GIF of all methods together
    #[arg(short = 'o', long, default_value = "compare.gif")]
    gif: PathBuf,
    /// Where to write the still PNG (the last frame)
    #[arg(long, default_value = "compare.png")]
    png: PathBuf,
    /// Also write the table as CSV
    #[arg(long, value_name = "PATH")]
    table: Option<PathBuf>,
    /// Also draw error against time per ball-frame, log-log (SVG; PNG if PATH ends in .png)
    #[arg(long, value_name = "PATH")]
    plot: Option<PathBuf>,
    #[command(flatten)]
    run: RunArgs,
}

/// The lesson's scene, from the constants at the top of this file.
fn lesson_scene() -> Scene {
    Scene {
        background: BACKGROUND,
        balls: vec![BallSpec {
            x: START.0,
            y: START.1,
            vx: INITIAL_VEL.0,
            vy: INITIAL_VEL.1,
            radius: RADIUS,
            colour: BALL_COLOUR,
            trail_colour: TRAIL_COLOUR,
            trail: TRAIL_LEN,
        }],
        gravity: Some([0.0, GRAVITY]),
        walls: Some(BOUNCE_DAMPING),
        frames: FRAMES,
        frame_ms: FRAME_MS,
        trail_fade: TRAIL_FADE,
        trail_shrink: TRAIL_SHRINK,
        ..Scene::empty(WIDTH, HEIGHT)
    }
}

impl SceneArgs {
    /// The scene to run: a file, a preset or the lesson's, with the typed flags laid over it.
    fn scene(&self) -> Result<Scene, SceneFileError> {
        // A typed canvas size is there before any ball is spawned, so spawned balls fill it.
        let canvas = Canvas {
            width: self.settings.width,
            height: self.settings.height,
        };
        let mut scene = match (&self.scene, &self.preset) {
            (Some(path), _) => scene::file::load_on(path, self.seed, canvas)?,
            (None, Some(name)) => scene::file::preset_on(name, self.seed, canvas)?,
            (None, None) => lesson_scene(),
        };
        self.settings.apply(&mut scene);
        Ok(scene)
    }

    /// The scene with a sweep's change laid over it, as if it had been typed too.
    fn changed(&self, change: &Change) -> Result<Scene, SceneFileError> {
        let args = match change {
            Change::Preset(name) => SceneArgs {
                preset: Some(name.clone()),
                ..self.clone()
            },
            Change::Setting(setting) => SceneArgs {
                settings: setting.or(&self.settings),
                ..self.clone()
            },
        };
        args.scene()
    }
}

/// The command line, its scene settings showing the lesson's values as their defaults.
fn command() -> clap::Command {
    let defaults = |command| Overrides::defaults_from(&lesson_scene(), command);
    defaults(Args::command())
        .mut_subcommand("sweep", defaults)
        .mut_subcommand("compare", defaults)
}

fn main() -> ExitCode {
    // First, so a signal at any moment later finds the run's files to clean up.
    let stop = match Stop::on_signals() {
        Ok(stop) => stop,
        Err(error) => {
            eprintln!("error: cannot watch for Ctrl-C: {error}");
            return ExitCode::from(1);
        }
    };
    let matches = match command().try_get_matches() {
        Ok(matches) => matches,
        Err(error) => return refuse(error),
    };
    let args = match Args::from_arg_matches(&matches) {
        Ok(args) => args,
        Err(error) => return refuse(error),
    };
    match args.command {
        Some(Command::Completions { shell }) => {
            let mut out = std::io::stdout();
            clap_complete::generate(shell, &mut command(), "bouncing_ball", &mut out);
            return ExitCode::SUCCESS;
        }
        Some(Command::Sweep {
            values,
            scene,
            gif,
            png,
            run,
            ..
        }) => {
            let outputs = SweepOutputs {
                gif,
                png,
                progress: !run.quiet,
                scene_file: scene.scene.clone(),
                budget: run.budget.budget(),
                stop,
            };
            return run_sweep(&values, &scene, &outputs);
        }
        Some(Command::Compare(compare)) => return compare_methods(compare, stop),
        None => {}
    }
    let scene = match args.scene.scene() {
        Ok(scene) => scene,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::from(2);
        }
    };
    let outputs = Outputs {
        trace: args.trace.clone(),
        plot: args.plot.clone().or_else(|| scene.plot.clone()),
        progress: !args.run.quiet,
        scene_file: args.scene.scene.clone(),
        budget: args.run.budget.budget(),
        stop,
        ..Outputs::new(&args.gif, &args.png)
    };
    match run(&scene, &outputs) {
        Ok(summary) => {
            if !args.run.quiet {
                let line = summary_line(&summary);
                // Standard output may carry the trace, or be a closed pipe: never fail on it.
                let _ = if outputs.trace_on_stdout() {
                    writeln!(std::io::stderr(), "{line}")
                } else {
                    writeln!(std::io::stdout(), "{line}")
                };
            }
            ExitCode::SUCCESS
        }
        Err(error) => fail(&error, |name| match name {
            "plot" => args.plot.is_some(),
            setting => args.scene.settings.is_typed(setting),
        }),
    }
}

/// `sweep KEY=V1,V2,...`: the scene once per value, as if each were typed, tiled into one GIF.
fn run_sweep(values: &str, args: &SceneArgs, outputs: &SweepOutputs) -> ExitCode {
    let typed = |name: &str| match name {
        "preset" => args.preset.is_some() || args.scene.is_some(),
        setting => args.settings.is_typed(setting),
    };
    let sweep = match Sweep::parse(values) {
        Ok(sweep) => sweep,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::from(2);
        }
    };
    if args
        .scene
        .as_deref()
        .is_some_and(bouncing_ball::output::is_stdout)
    {
        eprintln!("error: --scene -: a sweep reads its scene once per panel; give a file, not standard input");
        return ExitCode::from(2);
    }
    let result = sweep
        .panels(typed, |change| args.changed(change))
        .and_then(|panels| sweep::run(&panels, outputs));
    match result {
        Ok(summary) => {
            if outputs.progress {
                // Standard output may be a closed pipe: never fail on it.
                let _ = writeln!(std::io::stdout(), "{}", summary_line(&summary));
            }
            ExitCode::SUCCESS
        }
        Err(SweepError::Flag(error)) => refuse(error),
        Err(SweepError::Run(error)) => fail(&error, |name| name == sweep.setting() || typed(name)),
        Err(other) => {
            eprintln!("error: {other}");
            ExitCode::from(other.exit_code())
        }
    }
}

/// `compare`: runs the scene by every method, prints the table and what was written.
fn compare_methods(args: Box<CompareArgs>, stop: Stop) -> ExitCode {
    let CompareArgs {
        scene: scene_args,
        methods,
        gif,
        png,
        table,
        plot,
        run,
        ..
    } = *args;
    // Each method sets these three; typed for the scene they would be silently replaced.
    for name in ["integrator", "substeps", "collisions"] {
        if scene_args.settings.is_typed(name) {
            eprintln!("error: {} is not allowed with compare: each method sets it; list them with --methods INTEGRATOR:SUBSTEPS:COLLISIONS", flag(name));
            return ExitCode::from(2);
        }
    }
    let scene = match scene_args.scene() {
        Ok(scene) => scene,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::from(2);
        }
    };
    let plot_typed = plot.is_some();
    let outputs = compare::CompareOutputs {
        methods,
        gif,
        png,
        table,
        plot,
        scene_file: scene_args.scene.clone(),
        budget: run.budget.budget(),
        stop,
    };
    match compare::compare(&scene, &outputs) {
        Ok(done) => {
            if !run.quiet {
                let line = summary_line(&done.summary);
                // A closed pipe (`| head`) is no reason to fail once the files are written.
                let _ = writeln!(std::io::stdout(), "{}{line}", done.table);
            }
            ExitCode::SUCCESS
        }
        Err(error) => fail(&error, |name| match name {
            "plot" => plot_typed,
            setting => scene_args.settings.is_typed(setting),
        }),
    }
}
