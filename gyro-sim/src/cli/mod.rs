//! The `gyro-sim` command line: in come the arguments and the models compiled in; out go the
//! runs, their files and a summary. A model file (`--model`, or a scene's `model = "file.al"`)
//! is made ready by [`crate::model_run`]; the command line runs it in process, or execs the
//! cached binary with the model compiled in when the compiled engine is asked.

mod args;
mod bench_command;
mod error;
mod serve_command;
mod summary;
mod sweep_command;
mod sweep_plot;

use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};

use args::parse_set;
pub use summary::print_summary;

pub use error::CliError;

use crate::model_run::{model_file_of, CompiledModel, FileRunRequest, ModelRunArgs, PreparedRun};
use crate::models::{ModelFile, Registry};
use crate::problem::{Engine, Problem};
use crate::scene::{IntegratorOverrides, Scene};

/// Simulate models derived with Kane's method.
#[derive(Parser)]
#[command(name = "gyro-sim", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Run a scene, or a model file without one: writes DIR/trajectory.csv and the figures,
    /// prints a summary.
    Run(RunArgs),
    /// Work against precision: every method over a range of tolerances (fixed-step methods,
    /// steps) against a tight reference run, timed interleaved; writes
    /// DIR/work_precision.csv and DIR/work_precision.png and prints the table.
    Bench(BenchArgs),
    /// A parameter sweep: the scene once per member of a grid (`--vary NAME=START:STOP:N`) or a
    /// Latin-hypercube sample (`--vary NAME=START:STOP --samples N --seed S`), in parallel;
    /// writes DIR/sweep.csv (one row per member) and DIR/timing.csv; resumes what a killed run
    /// of the same plan left (another plan is refused; --new starts over); `--shard K/N` (or a
    /// Slurm array task) runs a disjoint slice.
    Sweep(SweepCli),
    /// Joins shard folders' sweep.csv into DIR/sweep.csv, in member order, once they are one
    /// sweep's shards, each once, holding every member exactly once.
    SweepMerge {
        /// Output folder.
        #[arg(long)]
        out: PathBuf,
        /// The shards' --out folders.
        #[arg(required = true)]
        shards: Vec<PathBuf>,
    },
    /// Serves the scene on 127.0.0.1: its 3-D view, a slider for each of its [[controls]]
    /// re-running it as moved, and the elevation plot, at the address printed.
    Serve {
        /// The scene file (TOML).
        scene: PathBuf,
        /// The port (0: any free one).
        #[arg(long, default_value_t = 8427)]
        port: u16,
    },
    /// Draws a column of DIR/sweep.csv (e.g. max_q2_deg) over one or two varied values:
    /// writes DIR/METRIC.png (or --out), failed members as crosses.
    SweepPlot {
        /// The sweep's folder.
        dir: PathBuf,
        /// The column to draw.
        #[arg(long)]
        metric: String,
        /// A varied name for an axis, once or twice (default: the sweep's first one or two).
        #[arg(long)]
        over: Vec<String>,
        /// The PNG to write.
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

/// `gyro-sim sweep`.
#[derive(clap::Args)]
struct SweepCli {
    /// The scene file (TOML).
    scene: PathBuf,
    /// NAME=START:STOP[:N] [UNIT], repeated: a parameter or initial state and its range.
    #[arg(long, required = true, value_parser = crate::study::sweep::parse_range)]
    vary: Vec<crate::study::sweep::Range>,
    /// Latin-hypercube samples over the ranges (without it, a grid of N points per range).
    #[arg(long)]
    samples: Option<usize>,
    /// The sample's seed.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// This run's slice, K/N (K from 1); defaults to the Slurm array task when set (an evenly
    /// spaced array: rank (ID-MIN)/STEP of COUNT; other sparse arrays need --shard).
    #[arg(long)]
    shard: Option<String>,
    /// Start over when the folder holds another sweep's rows (they are removed); without it
    /// such a folder is refused.
    #[arg(long)]
    new: bool,
    /// Output folder.
    #[arg(long)]
    out: PathBuf,
}

/// `gyro-sim bench`.
#[derive(clap::Args)]
struct BenchArgs {
    /// The scene file (TOML) of a built-in model.
    scene: PathBuf,
    /// Timed runs per configuration (the median is reported).
    #[arg(long, default_value_t = 5)]
    repeats: usize,
    /// Output folder.
    #[arg(long)]
    out: PathBuf,
}

/// `gyro-sim run`.
#[derive(clap::Args)]
struct RunArgs {
    /// The scene file (TOML); or give --model.
    #[arg(required_unless_present = "model", conflicts_with = "model")]
    scene: Option<PathBuf>,
    /// A model file to run without a scene: values from its INPUT lines, times and tolerances
    /// from TFINAL, INTEGSTP, ABSERR, RELERR, columns from OUTPUT.
    #[arg(long)]
    model: Option<PathBuf>,
    /// NAME=VALUE for a parameter or an initial state, with a unit if wanted ("Q2=30 deg").
    #[arg(long = "set", value_name = "NAME=VALUE", requires = "model", value_parser = parse_set)]
    sets: Vec<(String, String)>,
    /// End time (overrides the file's TFINAL).
    #[arg(long, requires = "model", allow_hyphen_values = true)]
    t_final: Option<f64>,
    /// The integrator, in place of the scene's (or the model file's): dop853, dopri5, vern7,
    /// vern9, taylor, rk4, or auto (picked by the tolerances).
    #[arg(long, value_parser = args::parse_method)]
    method: Option<String>,
    /// Relative tolerance, in place of the scene's (or the file's RELERR).
    #[arg(long, allow_hyphen_values = true, value_parser = args::parse_tolerance)]
    rtol: Option<f64>,
    /// Absolute tolerance, in place of the scene's (or the file's ABSERR).
    #[arg(long, allow_hyphen_values = true, value_parser = args::parse_tolerance)]
    atol: Option<f64>,
    /// How a model file's equations run: jit (machine code compiled in process, ready in
    /// milliseconds), compiled (a cached binary built by cargo once per file version, for the
    /// last percent of speed) or instant (evaluated, the reference the others are tested
    /// against).
    #[arg(long, value_enum, default_value = "jit")]
    engine: EngineChoice,
    /// Print the scene a --model run uses (to save and edit) and stop.
    #[arg(long, requires = "model")]
    print_scene: bool,
    /// Write no 3-D view of a --model run (by default it draws the model's frames and
    /// points, computing their placement at the output times).
    #[arg(long, requires = "model")]
    no_view: bool,
    /// Points per output interval the figures are drawn from (1 to 1000: from the
    /// integrator's dense output; the CSV rows are unchanged), in place of the scene's
    /// plot_points.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1000))]
    plot_points: Option<u32>,
    /// Integrate this many times more and print the median and the least wall time (a
    /// quick timing; files are written once).
    #[arg(long, default_value_t = 0)]
    repeat: usize,
    /// Output folder.
    #[arg(long, required_unless_present = "print_scene")]
    out: Option<PathBuf>,
}

impl RunArgs {
    /// The integrator settings given on the command line.
    fn integrator(&self) -> IntegratorOverrides {
        IntegratorOverrides { method: self.method.clone(), rtol: self.rtol, atol: self.atol }
    }

    /// What the command line gives a model file's run without a scene.
    fn model_run_args(&self) -> ModelRunArgs {
        ModelRunArgs {
            sets: self.sets.clone(),
            t_final: self.t_final,
            integrator: self.integrator(),
            view: !self.no_view,
            plot_points: self.plot_points,
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum EngineChoice {
    Jit,
    Compiled,
    Instant,
}

impl EngineChoice {
    fn engine(self) -> Engine {
        match self {
            EngineChoice::Jit => Engine::Jit,
            EngineChoice::Compiled => Engine::Compiled,
            EngineChoice::Instant => Engine::Instant,
        }
    }
}

/// Runs the command line with `registry`'s models (and `compiled`, when this binary is a
/// model file's compiled path).
pub fn main_with(registry: Registry, compiled: Option<CompiledModel>) -> ExitCode {
    if let Err(e) = crate::ode::interrupt::listen() {
        eprintln!("warning: stop signals cannot be caught ({e}): Ctrl-C ends a run without keeping its rows");
    }
    let result = match Cli::parse().command {
        Command::Run(args) => run_command(&args, registry, compiled),
        Command::Bench(args) => bench_command::bench_command(&args.scene, args.repeats, &args.out, &registry),
        Command::Sweep(a) => {
            let args = sweep_command::SweepArgs {
                scene: &a.scene,
                vary: &a.vary,
                samples: a.samples,
                seed: a.seed,
                shard: a.shard.as_deref(),
                new: a.new,
                out: &a.out,
            };
            sweep_command::sweep_command(&args, &registry)
        }
        Command::Serve { scene, port } => serve_command::serve_command(&scene, port, registry),
        Command::SweepMerge { out, shards } => sweep_command::merge_command(&out, &shards),
        Command::SweepPlot { dir, metric, over, out } => {
            let args =
                sweep_plot::SweepPlotArgs { dir: &dir, metric: &metric, over: &over, out: out.as_deref() };
            sweep_plot::sweep_plot_command(&args)
        }
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            eprintln!("{}", e.to_string().trim_end());
            crate::ode::interrupt::requested().map_or(ExitCode::FAILURE, |by| ExitCode::from(by.exit_code()))
        }
    }
}

/// `gyro-sim run`: a scene of a built-in model, or a model file (with its scene or without).
fn run_command(
    args: &RunArgs,
    registry: Registry,
    compiled: Option<CompiledModel>,
) -> Result<ExitCode, CliError> {
    let scene = match &args.scene {
        Some(path) => {
            let defaults = |model: &str| crate::model_run::file_defaults(path, model);
            let mut scene = Scene::load_with(path, &args.integrator(), &defaults)?;
            if let Some(n) = args.plot_points {
                scene.plot_points = Some(n as usize);
            }
            Some(scene)
        }
        None => None,
    };
    let file = args.model.clone().or_else(|| scene.as_ref().and_then(model_file_of));
    let Some(file) = file else {
        let scene = scene.ok_or(CliError::NoScene)?;
        if let Some((name, _, _)) = scene.specified.first() {
            let (path, name, model) = (scene.path.clone(), name.clone(), scene.model.clone());
            return Err(CliError::SpecifiedCompiled { scene: path, name, model });
        }
        let problem = crate::resolve::resolve(&scene, &registry)?;
        return finish(&scene, &problem, &scene.path, args);
    };
    let request =
        FileRunRequest { file: &file, scene, args: args.model_run_args(), engine: args.engine.engine() };
    let prepared = crate::model_run::prepare(request, registry, compiled)?;
    eprint!("{}", prepared.warnings);
    run_prepared(&prepared, args)
}

/// Runs a model file's prepared run: its problem resolved first, so implausible values stop it
/// before anything is built; then in process, or on the compiled binary when it is to be built.
fn run_prepared(prepared: &PreparedRun, args: &RunArgs) -> Result<ExitCode, CliError> {
    let scene = &prepared.scene;
    if args.print_scene {
        print!("{}", prepared.printable_scene());
        return Ok(ExitCode::SUCCESS);
    }
    if let Some(warning) = prepared.open_inputs_warning() {
        eprintln!("{warning}");
    }
    let problem = prepared.resolve()?;
    if let Some(file) = &prepared.to_compile {
        let taylor = scene.integrator.method.name() == crate::ode::TAYLOR;
        return run_compiled(file, taylor, scene.draws_model());
    }
    finish(scene, &problem, prepared.named_by(), args)
}

/// Builds (or finds) the compiled binary (with Taylor coefficients when `taylor`, the default
/// drawing's outputs when `drawn`) and runs it
/// with the same arguments: on Unix in place of this process, so signals reach it directly. A
/// cached binary that cannot be started (damaged) is removed and rebuilt once.
fn run_compiled(file: &ModelFile, taylor: bool, drawn: bool) -> Result<ExitCode, CliError> {
    let first = start_compiled(file, taylor, drawn)?;
    eprintln!(
        "the cached compiled model {} cannot be started ({}): rebuilding it",
        first.0.display(),
        first.1
    );
    let _ = std::fs::remove_file(&first.0);
    let (binary, why) = start_compiled(file, taylor, drawn)?;
    Err(CliError::CannotStart { binary, why, cache: crate::models::cache_dir() })
}

/// Builds (or finds) the binary and runs it in place of this process; returns only when it
/// could not be started: its path and why. Elsewhere than on Unix, runs it and returns its
/// exit code.
fn start_compiled(file: &ModelFile, taylor: bool, drawn: bool) -> Result<(PathBuf, String), CliError> {
    let (binary, built) = crate::models::ensure_binary(file, taylor, drawn)?;
    if built {
        eprintln!("compiled: {}", binary.display());
    }
    if let Some(why) = crate::models::not_a_program(&binary) {
        return Ok((binary, why));
    }
    let mut command = std::process::Command::new(&binary);
    command.args(std::env::args_os().skip(1));
    #[cfg(unix)]
    {
        use std::os::unix::process::CommandExt;
        let e = command.exec();
        Ok((binary, e.to_string()))
    }
    #[cfg(not(unix))]
    {
        let status = command.status().map_err(|source| CliError::Start { binary: binary.clone(), source })?;
        std::process::exit(status.code().unwrap_or(1))
    }
}

/// Runs, writes and summarises; a failure is named by `named_by` (the scene, or the model
/// file of a run without one).
fn finish(scene: &Scene, problem: &Problem, named_by: &Path, args: &RunArgs) -> Result<ExitCode, CliError> {
    let out = args.out.as_deref();
    let summary = crate::run::run_problem(problem, out)
        .map_err(|e| CliError::Run { scene: named_by.to_path_buf(), source: Box::new(e) })?;
    print_summary(&scene.title, &summary);
    println!("model {} ran {}", problem.model.info().name, problem.model.engine().label());
    if args.repeat > 0 {
        print_timing(problem, args.repeat)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// Integrates `times` more times and prints the median and least wall time.
fn print_timing(problem: &Problem, times: usize) -> Result<(), CliError> {
    let mut walls = Vec::with_capacity(times);
    for _ in 0..times {
        let t = crate::solve::solve(problem, None)?;
        walls.push(t.wall.as_secs_f64() * 1e3);
    }
    walls.sort_by(f64::total_cmp);
    println!("wall time over {times} more runs: median {:.4} ms, least {:.4} ms", walls[times / 2], walls[0]);
    Ok(())
}
