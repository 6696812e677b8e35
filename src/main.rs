//! The command line. The constants below are the default scene: edit one, run
//! `cargo run --release`, and watch what changes. Each is also a flag (`--help`).

use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;

use bouncing_ball::budget::DEFAULT_MEMORY_BUDGET;
use bouncing_ball::physics::motion::DEFAULT_ITERATIONS;
use bouncing_ball::physics::{CollisionMode, Integrator};
use bouncing_ball::scene::{self, preset_names, Overrides, SceneFileError};
use bouncing_ball::stop::Stop;
use bouncing_ball::{run, BallSpec, Outputs, RunError, Scene};
use clap::parser::ValueSource;
use clap::{ArgAction, ArgMatches, CommandFactory, FromArgMatches, Parser, Subcommand};
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
    /// Load the scene from a TOML file (- for standard input)
    #[arg(short, long, conflicts_with = "preset")]
    scene: Option<PathBuf>,
    /// Load a bundled scene
    #[arg(short, long, value_parser = preset_names())]
    preset: Option<String>,
    /// Seed for everything random (same seed, same bytes out)
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Canvas width, px
    #[arg(long, default_value_t = WIDTH)]
    width: u32,
    /// Canvas height, px
    #[arg(long, default_value_t = HEIGHT)]
    height: u32,
    /// Ball radius, px
    #[arg(long, default_value_t = RADIUS)]
    radius: f64,
    /// Start position x, px
    #[arg(long, default_value_t = START.0)]
    x: f64,
    /// Start position y, px (y grows downwards)
    #[arg(long, default_value_t = START.1)]
    y: f64,
    /// Start velocity x, px/frame
    #[arg(long, default_value_t = INITIAL_VEL.0)]
    vx: f64,
    /// Start velocity y, px/frame
    #[arg(long, default_value_t = INITIAL_VEL.1)]
    vy: f64,
    /// Gravity, px/frame² (downwards; negative pulls up)
    #[arg(short, long, default_value_t = GRAVITY)]
    gravity: f64,
    /// Share of speed kept at each bounce, 0 to 1
    #[arg(short, long, default_value_t = BOUNCE_DAMPING)]
    damping: f64,
    /// Air drag: share of speed lost per frame, 0 to 1 (the lesson's 0.998 is 0.002) [default: none]
    #[arg(long)]
    drag: Option<f64>,
    /// Ball-ball collisions with this restitution, 0 to 1 [default: none]
    #[arg(long)]
    restitution: Option<f64>,
    /// How each step turns forces into motion
    #[arg(long, value_enum, default_value_t = Integrator::default())]
    integrator: Integrator,
    /// Steps per frame (each frame split into equal steps)
    #[arg(long, default_value_t = 1)]
    substeps: u32,
    /// How wall and floor contacts are resolved
    #[arg(long, value_enum, default_value_t = CollisionMode::default())]
    collisions: CollisionMode,
    /// Contact-solver iterations per step (ball-ball collisions in clamp mode)
    #[arg(long, default_value_t = DEFAULT_ITERATIONS)]
    iterations: u32,
    /// Trail length, points (0: no trail)
    #[arg(long, default_value_t = TRAIL_LEN)]
    trail: usize,
    /// Frames to simulate
    #[arg(short = 'n', long, default_value_t = FRAMES)]
    frames: u32,
    /// Time each frame shows, ms (a multiple of 10)
    #[arg(long, default_value_t = FRAME_MS)]
    frame_ms: u32,
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
    /// Refuse a scene predicted to need more memory than this, MB
    #[arg(long, value_name = "MB", default_value_t = DEFAULT_MEMORY_BUDGET >> 20)]
    memory_budget: u64,
    /// Print nothing on success
    #[arg(short, long)]
    quiet: bool,
    /// Print help
    #[arg(short, long, action = ArgAction::HelpShort)]
    help: Option<bool>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Print a shell completion script (e.g. `bouncing_ball completions bash > ~/.bash_completion.d/bouncing_ball`)
    Completions {
        /// The shell to complete for
        shell: Shell,
    },
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
        ..Scene::empty(WIDTH, HEIGHT)
    }
}

impl Args {
    /// The values the user typed (not clap's defaults), to lay over the chosen scene.
    fn overrides(&self, matches: &ArgMatches) -> Overrides {
        let typed = |id: &str| matches.value_source(id) == Some(ValueSource::CommandLine);
        Overrides {
            width: typed("width").then_some(self.width),
            height: typed("height").then_some(self.height),
            radius: typed("radius").then_some(self.radius),
            x: typed("x").then_some(self.x),
            y: typed("y").then_some(self.y),
            vx: typed("vx").then_some(self.vx),
            vy: typed("vy").then_some(self.vy),
            gravity: typed("gravity").then_some(self.gravity),
            damping: typed("damping").then_some(self.damping),
            drag: self.drag,
            restitution: self.restitution,
            trail: typed("trail").then_some(self.trail),
            frames: typed("frames").then_some(self.frames),
            frame_ms: typed("frame_ms").then_some(self.frame_ms),
            integrator: typed("integrator").then_some(self.integrator),
            substeps: typed("substeps").then_some(self.substeps),
            collisions: typed("collisions").then_some(self.collisions),
            iterations: typed("iterations").then_some(self.iterations),
        }
    }

    /// The scene to run: a file, a preset or the lesson's, with the typed flags laid over it.
    fn scene(&self, matches: &ArgMatches) -> Result<Scene, SceneFileError> {
        let mut scene = match (&self.scene, &self.preset) {
            (Some(path), _) => scene::file::load(path, self.seed)?,
            (None, Some(name)) => scene::file::preset(name, self.seed)?,
            (None, None) => lesson_scene(),
        };
        self.overrides(matches).apply(&mut scene);
        Ok(scene)
    }
}

/// The flag a scene key came from: `balls[0].frame_ms` → `--frame-ms`.
fn flag(key: &str) -> String {
    let name = key.rsplit('.').next().unwrap_or(key);
    format!("--{}", name.replace('_', "-"))
}

/// A command-line error in one line (clap adds usage and tips on more), or help and version
/// printed as clap prints them.
fn refuse(error: clap::Error) -> ExitCode {
    use clap::error::ErrorKind::{DisplayHelp, DisplayVersion};
    if matches!(error.kind(), DisplayHelp | DisplayVersion) {
        error.exit();
    }
    let text = error.to_string();
    eprintln!(
        "{}; see --help",
        text.lines().next().unwrap_or("error").trim_end()
    );
    ExitCode::from(2)
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
    let matches = match Args::command().try_get_matches() {
        Ok(matches) => matches,
        Err(error) => return refuse(error),
    };
    let args = match Args::from_arg_matches(&matches) {
        Ok(args) => args,
        Err(error) => return refuse(error),
    };
    if let Some(Command::Completions { shell }) = args.command {
        clap_complete::generate(
            shell,
            &mut Args::command(),
            "bouncing_ball",
            &mut std::io::stdout(),
        );
        return ExitCode::SUCCESS;
    }
    let scene = match args.scene(&matches) {
        Ok(scene) => scene,
        Err(error) => {
            eprintln!("error: {error}");
            return ExitCode::from(2);
        }
    };
    let outputs = Outputs {
        trace: args.trace.clone(),
        plot: args.plot.clone().or_else(|| scene.plot.clone()),
        progress: !args.quiet,
        scene_file: args.scene.clone(),
        memory_budget: args.memory_budget.saturating_mul(1 << 20),
        stop,
        ..Outputs::new(&args.gif, &args.png)
    };
    match run(&scene, &outputs) {
        Ok(summary) => {
            if !args.quiet {
                let line = format!(
                    "wrote {} ({} frames, {} bytes) and {} ({} bytes) in {:.1} ms",
                    outputs.gif.display(),
                    summary.frames,
                    summary.gif_bytes,
                    outputs.png.display(),
                    summary.png_bytes,
                    summary.elapsed.as_secs_f64() * 1000.0
                );
                // Standard output may carry the trace, or be a closed pipe: never fail on it.
                let _ = if outputs.trace_on_stdout() {
                    writeln!(std::io::stderr(), "{line}")
                } else {
                    writeln!(std::io::stdout(), "{line}")
                };
            }
            ExitCode::SUCCESS
        }
        Err(error) => {
            match &error {
                RunError::Invalid(bad) => eprintln!(
                    "error: {} {} is not allowed: {}",
                    flag(&bad.key),
                    bad.value,
                    bad.allowed
                ),
                other => eprintln!("error: {other}"),
            }
            ExitCode::from(error.exit_code())
        }
    }
}
