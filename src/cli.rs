//! The command line: the main command's and the subcommands' flags (clap), and how each
//! command turns them into a scene, a [`Job`] and one call into the library. `main.rs` holds
//! the learner's constants and dispatches; every failure comes back here as a [`Failure`],
//! one line and an exit code.

use std::io::Write;
use std::path::{Path, PathBuf};

use clap::error::{ContextKind, ContextValue, ErrorKind};
use clap::parser::ValueSource;
use clap::{ArgAction, ArgMatches, CommandFactory, FromArgMatches, Id, Parser, Subcommand};
use clap_complete::Shell;

use crate::budget::{Budget, DEFAULT_GIF_BUDGET, DEFAULT_MEMORY_BUDGET, DEFAULT_TIME_BUDGET};
use crate::check::pixels::Tolerance;
use crate::check::{self, Grade};
use crate::compare::methods::{self, MethodList};
use crate::job::{Job, OutputKind, Summary};
use crate::messages::{
    distance, flag, refuse, seconds, share, summary_line, whole_number, Failure,
};
use crate::scene::file::CanvasSize;
use crate::scene::{self, preset_names, Overrides, Scene, SceneFileError};
use crate::stop::Stop;
use crate::sweep::{self, Change, Sweep, SweepError};
use crate::{compare, output};

/// Simulates a bouncing ball and writes an animated GIF and a still PNG of its last frame.
#[derive(Parser, Debug)]
#[command(
    name = "bouncing_ball",
    version,
    about,
    long_about = None,
    allow_negative_numbers = true,
    disable_help_flag = true,
    after_help = "Without --scene or --preset it runs the lesson's scene (the constants in \
                  src/main.rs). Flags you type override the scene's values; ball flags apply \
                  to every ball."
)]
struct Args {
    #[command(subcommand)]
    command: Option<Subcommands>,
    #[command(flatten)]
    scene: SceneArgs,
    /// Where to write the animated GIF
    #[arg(short = 'o', long, default_value = "bouncing_ball.gif")]
    gif: PathBuf,
    /// Where to write the still PNG (the last frame) [default: the GIF's name with .png]
    #[arg(long)]
    png: Option<PathBuf>,
    #[command(flatten)]
    skip: SkipArgs,
    /// Also write every frame's state as CSV (frame,ball,x,y,vx,vy); - for standard output
    #[arg(long)]
    trace: Option<PathBuf>,
    /// Also draw height, speed and energy per frame (SVG; PNG if PATH ends in .png)
    #[arg(long, value_name = "PATH")]
    plot: Option<PathBuf>,
    #[command(flatten)]
    run: RunArgs,
}

/// What every command that runs a scene takes besides the scene and its outputs; typed
/// before or after the subcommand.
#[derive(clap::Args, Debug)]
struct RunArgs {
    /// Refuse a scene predicted to need more memory than this, MB
    #[arg(long, value_name = "MB", default_value_t = DEFAULT_MEMORY_BUDGET >> 20,
          value_parser = whole_number, allow_hyphen_values = true, global = true)]
    memory_budget: u64,
    /// Refuse a run predicted to take longer than this, seconds (fractions allowed)
    #[arg(long, value_name = "SECONDS", default_value_t = DEFAULT_TIME_BUDGET,
          value_parser = seconds, allow_hyphen_values = true, global = true)]
    time_budget: f64,
    /// Refuse a run whose GIF is predicted to be bigger than this, MB
    #[arg(long, value_name = "MB", default_value_t = DEFAULT_GIF_BUDGET >> 20,
          value_parser = whole_number, allow_hyphen_values = true, global = true)]
    gif_budget: u64,
    /// Print nothing on success
    #[arg(short, long, global = true)]
    quiet: bool,
    /// Print help
    #[arg(short, long, action = ArgAction::HelpShort, global = true)]
    help: Option<bool>,
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
    /// Seed for everything random (same seed, same bytes out) [default: 1]
    #[arg(long, value_parser = whole_number, allow_hyphen_values = true)]
    seed: Option<u64>,
    // --width to --frame-ms: the scene settings, a row each in src/scene/overrides.rs.
    #[command(flatten)]
    settings: Overrides,
}

#[derive(Subcommand, Debug)]
enum Subcommands {
    /// Grade a learner's work against the scene: GIFs, PNGs, folders of PNG frames or trajectories, each compared with the scene drawn in memory (docs/grading.md)
    Check(Box<CheckArgs>),
    /// Run the scene with several methods side by side, each measured against a reference: a GIF of them together, a table of time, error and energy, and optionally a work-precision plot
    Compare(Box<CompareArgs>),
    /// Print a shell completion script, for an installed binary (`cargo install --path .`), e.g. `bouncing_ball completions bash > ~/.local/share/bash-completion/completions/bouncing_ball`
    Completions {
        /// The shell to complete for
        shell: Shell,
    },
    /// Run the scene once per value of one setting, side by side in one GIF, e.g. `bouncing_ball sweep damping=0.5,0.7,0.88,1` (docs/sweep.md)
    Sweep(Box<SweepArgs>),
}

/// `compare`: the scene as the main command takes it, the methods, and where the results go.
#[derive(clap::Args, Debug)]
struct CompareArgs {
    #[command(flatten)]
    scene: SceneArgs,
    /// The methods, each INTEGRATOR:SUBSTEPS:COLLISIONS (names as --integrator and
    /// --collisions spell them), separated by commas
    #[arg(long, value_name = "LIST", default_value = methods::DEFAULT_METHODS,
          value_parser = methods::parse_list)]
    methods: MethodList,
    /// Where to write the animated GIF of all methods together
    #[arg(short = 'o', long, default_value = "compare.gif")]
    gif: PathBuf,
    /// Where to write the still PNG (the last frame) [default: the GIF's name with .png]
    #[arg(long)]
    png: Option<PathBuf>,
    #[command(flatten)]
    skip: SkipArgs,
    /// Also write the table as CSV
    #[arg(long, value_name = "PATH")]
    table: Option<PathBuf>,
    /// Also draw error against time per ball-frame, log-log (SVG; PNG if PATH ends in .png)
    #[arg(long, value_name = "PATH")]
    plot: Option<PathBuf>,
}

/// The pictures a command may leave out, for a run that only traces, plots or tabulates.
#[derive(clap::Args, Debug)]
struct SkipArgs {
    /// Write no GIF
    #[arg(long, conflicts_with = "gif")]
    no_gif: bool,
    /// Write no PNG
    #[arg(long, conflicts_with = "png")]
    no_png: bool,
}

impl SkipArgs {
    /// `job` with the GIF at `gif` and the still at `png` (by default the GIF's name with
    /// `.png`), each unless left out.
    fn pictures(&self, job: Job, gif: &Path, png: Option<&PathBuf>) -> Job {
        let job = match self.no_gif {
            true => job,
            false => job.with(OutputKind::Gif, gif),
        };
        match self.no_png {
            true => job,
            false => job.with(
                OutputKind::Png,
                png.cloned().unwrap_or(gif.with_extension("png")),
            ),
        }
    }
}

/// `check`: the files to grade, the scene they should show, and how close is close enough.
#[derive(clap::Args, Debug)]
#[command(
    after_help = "Exit status, as diff and cmp: 0 if every file matches, 1 if any differs, \
                        2 if any is in trouble (not an image or a trajectory, unreadable, \
                        another size or number of frames, or a --diff that cannot be written)."
)]
struct CheckArgs {
    /// The work to grade, recognised by content: an animated GIF, a PNG (the last frame), a
    /// folder of PNG frames (in name order), a --trace CSV or the lesson's `x y vx vy` lines
    #[arg(value_name = "THEIRS", required = true)]
    theirs: Vec<PathBuf>,
    #[command(flatten)]
    scene: SceneArgs,
    /// Colour distance under which two pixels count as the same, 0 to 1 (pixelmatch's YIQ distance, as Playwright's threshold)
    #[arg(long, default_value_t = 0.0, value_parser = share)]
    threshold: f64,
    /// How many pixels of a frame may differ
    #[arg(long, value_name = "N", value_parser = whole_number)]
    max_diff_pixels: Option<u64>,
    /// What share of a frame's pixels may differ, 0 to 1
    #[arg(long, value_name = "R", value_parser = share)]
    max_diff_pixel_ratio: Option<f64>,
    /// How far a trajectory's positions (px) and velocities (px/frame) may be off
    #[arg(long, value_name = "PX", default_value_t = 0.0, value_parser = distance)]
    tolerance: f64,
    /// Write the first differing frame as expected | theirs | difference (PNG)
    #[arg(long, value_name = "FILE.png")]
    diff: Option<PathBuf>,
    /// One line per file, or one JSON object per file
    #[arg(long, value_enum, default_value_t = ReportFormat::Text)]
    format: ReportFormat,
}

/// How `check` reports.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
enum ReportFormat {
    Text,
    Json,
}

/// `sweep`: the setting and its values, the scene, and where the tiled GIF goes.
#[derive(clap::Args, Debug)]
struct SweepArgs {
    /// The setting to vary and its values: a flag's name without -- (or preset), =, values separated by commas
    #[arg(value_name = "KEY=V1,V2,...")]
    values: String,
    #[command(flatten)]
    scene: SceneArgs,
    /// Where to write the tiled GIF
    #[arg(short = 'o', long, default_value = "sweep.gif")]
    gif: PathBuf,
    /// Also write the last tiled frame as a PNG (without PATH: the GIF's name with .png)
    #[arg(long, value_name = "PATH", num_args = 0..=1)]
    png: Option<Option<PathBuf>>,
}

/// One command, parsed, with what every command shares.
pub struct Cli {
    command: Command,
    run: RunArgs,
    lesson: Scene,
    stop: Stop,
}

/// What the command line asks for.
enum Command {
    Run(Box<Args>),
    Check(Box<CheckArgs>),
    Compare(Box<CompareArgs>),
    Sweep(Box<SweepArgs>),
    Completions(Shell),
    /// Help or the version, printed as clap prints them.
    Show(clap::Error),
}

impl Cli {
    /// Parses the command line, its scene settings showing `lesson`'s values as their
    /// defaults (the scene run without `--scene` or `--preset`).
    pub fn parse(lesson: Scene) -> Result<Cli, Failure> {
        // First, so a signal at any moment later finds the run's files to clean up.
        let stop = Stop::on_signals().map_err(|error| Failure {
            line: format!("error: cannot watch for Ctrl-C: {error}"),
            code: 1,
        })?;
        // Built once: read for the flags' names, then parsing with it.
        let mut clap_command = command(&lesson);
        single_dash_long_flag(&clap_command)?;
        let parsed = clap_command
            .try_get_matches_from_mut(std::env::args_os())
            .and_then(|matches| {
                refuse_main_flags_before_a_subcommand(&matches)?;
                Args::from_arg_matches(&matches)
            });
        let mut args = match parsed {
            Ok(args) => args,
            Err(error) if shows(&error) => {
                return Ok(Cli {
                    command: Command::Show(error),
                    run: RunArgs::default(),
                    lesson,
                    stop,
                })
            }
            Err(error) => return Err(refused(error, &clap_command)),
        };
        let run = std::mem::take(&mut args.run);
        let command = match args.command.take() {
            Some(Subcommands::Check(check)) => Command::Check(check),
            Some(Subcommands::Compare(compare)) => Command::Compare(compare),
            Some(Subcommands::Sweep(sweep)) => Command::Sweep(sweep),
            Some(Subcommands::Completions { shell }) => Command::Completions(shell),
            None => Command::Run(Box::new(args)),
        };
        Ok(Cli {
            command,
            run,
            lesson,
            stop,
        })
    }

    /// Does what the command line asks.
    pub fn execute(self) -> Result<(), Failure> {
        match &self.command {
            Command::Run(args) => self.run_scene(args),
            Command::Check(args) => self.check(args),
            Command::Compare(args) => self.compare(args),
            Command::Sweep(args) => self.sweep(args),
            Command::Completions(shell) => {
                let mut out = std::io::stdout();
                clap_complete::generate(
                    *shell,
                    &mut command(&self.lesson),
                    "bouncing_ball",
                    &mut out,
                );
                Ok(())
            }
            Command::Show(message) => {
                let _ = message.print();
                Ok(())
            }
        }
    }

    /// The job every command runs its scene in: the budget, the stop flag, whether to talk.
    fn job(&self, scene: &SceneArgs) -> Job {
        let mut job = Job::new();
        job.scene_file = scene.scene.clone();
        job.budget = Budget {
            memory: self.run.memory_budget.saturating_mul(1 << 20),
            seconds: self.run.time_budget,
            gif_bytes: self.run.gif_budget.saturating_mul(1 << 20),
        };
        job.stop = self.stop.clone();
        if self.run.quiet {
            job
        } else {
            job.talking()
        }
    }

    /// The main command: the scene, its GIF and still, and a trace and a plot if asked for.
    fn run_scene(&self, args: &Args) -> Result<(), Failure> {
        let scene = args.scene.scene(&self.lesson).map_err(Failure::input)?;
        let job = args
            .skip
            .pictures(self.job(&args.scene), &args.gif, args.png.as_ref())
            .with_optional(OutputKind::Trace, args.trace.as_ref())
            .with_optional(OutputKind::Plot, args.plot.as_ref().or(scene.plot.as_ref()));
        nothing_left_out(&job, "--trace or --plot")?;
        let summary = crate::run(&scene, &job)
            .map_err(|error| Failure::of_run(&error, args.scene.typed(args.plot.is_some())))?;
        self.say(&job, "", &summary);
        Ok(())
    }

    /// `compare`: the scene by every method, the table printed and the files written.
    fn compare(&self, args: &CompareArgs) -> Result<(), Failure> {
        // Each method sets these three; typed for the scene they would be silently replaced.
        for name in ["integrator", "substeps", "collisions"] {
            if args.scene.settings.is_typed(name) {
                return Err(Failure::input(format!("{} is not allowed with compare: each method sets it; list them with --methods INTEGRATOR:SUBSTEPS:COLLISIONS", flag(name))));
            }
        }
        let scene = args.scene.scene(&self.lesson).map_err(Failure::input)?;
        let job = args
            .skip
            .pictures(self.job(&args.scene), &args.gif, args.png.as_ref())
            .with_optional(OutputKind::Table, args.table.as_ref())
            .with_optional(OutputKind::Plot, args.plot.as_ref());
        nothing_left_out(&job, "--table or --plot")?;
        let done = compare::compare(&scene, &args.methods, &job)
            .map_err(|error| Failure::of_run(&error, args.scene.typed(args.plot.is_some())))?;
        self.say(&job, &done.table, &done.summary);
        Ok(())
    }

    /// `check THEIRS...`: a verdict line (or JSON object) per file, a summary after several,
    /// and the exit code of the worst: 0 match, 1 differs, 2 trouble.
    fn check(&self, args: &CheckArgs) -> Result<(), Failure> {
        let scene = args.scene.scene(&self.lesson).map_err(Failure::input)?;
        let job = self
            .job(&args.scene)
            .with_optional(OutputKind::Diff, args.diff.as_ref());
        let options = check::Options {
            pixels: Tolerance {
                threshold: args.threshold,
                max_diff_pixels: args.max_diff_pixels,
                max_diff_pixel_ratio: args.max_diff_pixel_ratio,
            },
            tolerance: args.tolerance,
            ..check::Options::default()
        };
        let verdicts = check::check(&scene, &args.theirs, &options, &job).map_err(|error| {
            // Anything that stops the grading is trouble, a file that cannot be written too.
            let failure = Failure::of_run(&error, |name| args.scene.settings.is_typed(name));
            Failure { code: 2, ..failure }
        })?;
        let mut out = std::io::stdout().lock();
        // -q: only what did not match.
        let said = verdicts
            .iter()
            .filter(|v| !self.run.quiet || v.grade != Grade::Match);
        for verdict in said {
            let _ = match args.format {
                ReportFormat::Text => writeln!(out, "{}", verdict.line()),
                ReportFormat::Json => writeln!(out, "{}", verdict.json()),
            };
        }
        if verdicts.len() > 1 && matches!(args.format, ReportFormat::Text) && !self.run.quiet {
            let _ = writeln!(out, "{}", check::verdict::summary(&verdicts));
        }
        let worst = verdicts.iter().map(|v| v.grade).max();
        match worst.map_or(0, Grade::exit_code) {
            0 => Ok(()),
            code => Err(Failure {
                line: String::new(),
                code,
            }),
        }
    }

    /// `sweep KEY=V1,V2,...`: the scene once per value, as if each were typed, tiled into one
    /// GIF.
    fn sweep(&self, args: &SweepArgs) -> Result<(), Failure> {
        let scene = &args.scene;
        let typed = |name: &str| match name {
            "preset" => scene.preset.is_some() || scene.scene.is_some(),
            "seed" => scene.seed.is_some(),
            setting => scene.settings.is_typed(setting),
        };
        let sweep = Sweep::parse(&args.values).map_err(Failure::input)?;
        if scene.scene.as_deref().is_some_and(output::is_stdout) {
            return Err(Failure::input("--scene -: a sweep reads its scene once per panel; give a file, not standard input"));
        }
        let mut job = self.job(scene).with(OutputKind::Gif, &args.gif);
        if let Some(path) = &args.png {
            let path = path.clone().unwrap_or(args.gif.with_extension("png"));
            job = job.with(OutputKind::Png, path);
        }
        let result = sweep
            .panels(typed, |change| scene.changed(change, &self.lesson))
            .and_then(|panels| sweep::run(&panels, &job));
        let summary = result.map_err(|error| match error {
            SweepError::Flag(error) => refuse(error, Some("sweep")),
            SweepError::Run(error) => {
                Failure::of_run(&error, |name| name == sweep.setting() || typed(name))
            }
            other => Failure {
                line: format!("error: {other}"),
                code: other.exit_code(),
            },
        })?;
        self.say(&job, "", &summary);
        Ok(())
    }

    /// Prints `before` (a table), then the summary line, unless quiet: on standard output, or
    /// on stderr when standard output carries an output (`--trace -`). A closed pipe (`| head`)
    /// is no reason to fail once the files are written.
    fn say(&self, job: &Job, before: &str, summary: &Summary) {
        if self.run.quiet {
            return;
        }
        let text = format!("{before}{}\n", summary_line(summary));
        let _ = if job.writes_to_stdout() {
            std::io::stderr().write_all(text.as_bytes())
        } else {
            std::io::stdout().write_all(text.as_bytes())
        };
    }
}

impl Default for RunArgs {
    fn default() -> RunArgs {
        RunArgs {
            memory_budget: DEFAULT_MEMORY_BUDGET >> 20,
            time_budget: DEFAULT_TIME_BUDGET,
            gif_budget: DEFAULT_GIF_BUDGET >> 20,
            quiet: false,
            help: None,
        }
    }
}

/// clap's error in one line, with a hint where the mistake is a common one: a sweep's values
/// separated by spaces (`damping=0.5 1.0`).
fn refused(error: clap::Error, command: &clap::Command) -> Failure {
    let subcommand = typed_subcommand(command);
    let unexpected = match error.get(ContextKind::InvalidArg) {
        Some(ContextValue::String(word)) => word.clone(),
        _ => String::new(),
    };
    let failure = refuse(error, subcommand.as_deref());
    let stray_value = !unexpected.is_empty() && !unexpected.starts_with('-');
    match subcommand.as_deref() {
        Some("sweep") if stray_value => failure.hinted(&format!(
            "a sweep's values are one word, separated by commas without spaces (KEY=V1,V2), so {unexpected} is no value of it"
        )),
        _ => failure,
    }
}

/// Refuses a long flag typed with one dash (`-damping 0.5`), which clap would read as the
/// short `-d` with the value `amping`.
fn single_dash_long_flag(command: &clap::Command) -> Result<(), Failure> {
    let long_flags: Vec<&str> = std::iter::once(command)
        .chain(command.get_subcommands())
        .flat_map(|c| c.get_arguments().filter_map(|arg| arg.get_long()))
        .collect();
    // Read lossily: a path need not be Unicode (std::env::args would panic on one).
    for word in std::env::args_os().skip(1) {
        let word = word.to_string_lossy();
        let Some(name) = word.strip_prefix('-').filter(|name| !name.starts_with('-')) else {
            continue;
        };
        let name = name.split('=').next().unwrap_or(name);
        if name.len() > 1 && long_flags.contains(&name) {
            return Err(Failure::input(format!(
                "{word}: a long flag takes two dashes: --{name}; see --help"
            )));
        }
    }
    Ok(())
}

/// The subcommand typed on the command line, if any: the first word that names one.
fn typed_subcommand(command: &clap::Command) -> Option<String> {
    let names: Vec<&str> = command.get_subcommands().map(|c| c.get_name()).collect();
    std::env::args_os()
        .skip(1)
        .map(|word| word.to_string_lossy().into_owned())
        .find(|word| names.contains(&word.as_str()))
}

/// Refuses a job that would write nothing (`--no-gif --no-png` alone), naming `others`, the
/// outputs that could be asked for instead.
fn nothing_left_out(job: &Job, others: &str) -> Result<(), Failure> {
    match job.outputs.is_empty() {
        true => Err(Failure::input(format!(
            "--no-gif and --no-png leave nothing to write; ask for {others}, or drop one of them"
        ))),
        false => Ok(()),
    }
}

/// Refuses a main-command flag typed before a subcommand (`-p moon compare`), which the
/// subcommand would otherwise ignore; the flags every command shares (`-q compare`) may come
/// first.
fn refuse_main_flags_before_a_subcommand(matches: &ArgMatches) -> Result<(), clap::Error> {
    let Some(subcommand) = matches.subcommand_name() else {
        return Ok(());
    };
    let command = Args::command();
    // Only the main command's own flags: not the shared ones, nor the groups clap makes.
    let own_flag = |id: &Id| {
        let arg = command.get_arguments().find(|arg| arg.get_id() == id);
        arg.is_some_and(|arg| !arg.is_global_set())
    };
    let typed = matches.ids().find(|id| {
        matches.value_source(id.as_str()) == Some(ValueSource::CommandLine) && own_flag(id)
    });
    match typed {
        Some(id) => Err(command.clone().error(
            ErrorKind::ArgumentConflict,
            format!(
                "--{} cannot come before the subcommand {subcommand}: type it after {subcommand}",
                id.as_str().replace('_', "-")
            ),
        )),
        None => Ok(()),
    }
}

/// Whether clap's "error" is help or the version, to print and succeed.
fn shows(error: &clap::Error) -> bool {
    use clap::error::ErrorKind::{DisplayHelp, DisplayVersion};
    matches!(error.kind(), DisplayHelp | DisplayVersion)
}

impl SceneArgs {
    /// The scene to run: a file, a preset or `lesson`, with the typed flags laid over it.
    fn scene(&self, lesson: &Scene) -> Result<Scene, SceneFileError> {
        // A typed canvas size is there before any ball is spawned, so spawned balls fill it.
        let canvas = CanvasSize {
            width: self.settings.width,
            height: self.settings.height,
        };
        let mut scene = match (&self.scene, &self.preset) {
            (Some(path), _) => scene::file::load_on(path, self.seed(), canvas)?,
            (None, Some(name)) => scene::file::preset_on(name, self.seed(), canvas)?,
            (None, None) => lesson.clone(),
        };
        self.settings.apply(&mut scene);
        Ok(scene)
    }

    /// Whether the user typed the setting `name` (`plot`: whether `plot_typed`), to name a
    /// refused value as they know it.
    fn typed(&self, plot_typed: bool) -> impl Fn(&str) -> bool + '_ {
        move |name| match name {
            "plot" => plot_typed,
            setting => self.settings.is_typed(setting),
        }
    }

    /// The seed of everything random: as typed, or 1.
    fn seed(&self) -> u64 {
        self.seed.unwrap_or(1)
    }

    /// The scene with a sweep's change laid over it, as if it had been typed too.
    fn changed(&self, change: &Change, lesson: &Scene) -> Result<Scene, SceneFileError> {
        let args = match change {
            Change::Preset(name) => SceneArgs {
                preset: Some(name.clone()),
                ..self.clone()
            },
            Change::Setting(setting) => SceneArgs {
                settings: setting.or(&self.settings),
                ..self.clone()
            },
            Change::Seed(seed) => SceneArgs {
                seed: Some(*seed),
                ..self.clone()
            },
        };
        args.scene(lesson)
    }
}

/// The command line, its scene settings showing `lesson`'s values as their defaults.
fn command(lesson: &Scene) -> clap::Command {
    let defaults = |command| Overrides::defaults_from(lesson, command);
    // Each of compare's methods sets these: they are refused there, so its help leaves them out.
    let per_method = |command: clap::Command| {
        ["integrator", "substeps", "collisions"]
            .into_iter()
            .fold(command, |command, id| {
                command.mut_arg(id, |arg| arg.hide(true))
            })
    };
    defaults(Args::command())
        .mut_subcommand("sweep", defaults)
        .mut_subcommand("compare", |command| per_method(defaults(command)))
        .mut_subcommand("check", defaults)
}
