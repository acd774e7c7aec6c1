//! Why a command failed: the library's errors as they came (each with its file, line, column or
//! path and its source), and the command line's own (arguments that do not fit, a sweep
//! interrupted, a compiled model that cannot be started). `main_with` prints the message and
//! turns it into the exit code.

use std::path::PathBuf;

use thiserror::Error;

use crate::model_run::ModelRunError;
use crate::models::{CompileError, ModelFileError};
use crate::ode::interrupt::Interrupted;
use crate::output::WriteError;
use crate::problem::SolveError;
use crate::run::RunError;
use crate::scene::SceneError;
use crate::serve::ServeError;
use crate::study::sweep::{DesignError, ShardError, SweepError};

/// Why a command failed.
#[derive(Debug, Error)]
pub enum CliError {
    /// The scene is wrong, at a line and column.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// The model file cannot be read, checked or lowered.
    #[error(transparent)]
    ModelFile(#[from] ModelFileError),
    /// A model file's run cannot start.
    #[error(transparent)]
    ModelRun(Box<ModelRunError>),
    /// The model file's compiled path cannot be built.
    #[error(transparent)]
    Compile(#[from] CompileError),
    /// The model file's program cannot be compiled by the JIT engine.
    #[error(transparent)]
    Jit(#[from] kane_model::jit::JitError),
    /// An integration stopped.
    #[error(transparent)]
    Solve(Box<SolveError>),
    /// Results could not be written.
    #[error(transparent)]
    Write(#[from] WriteError),
    /// A sweep's folder could not be read, written or merged.
    #[error(transparent)]
    Sweep(#[from] SweepError),
    /// A sweep's members cannot be made.
    #[error(transparent)]
    Design(#[from] DesignError),
    /// A sweep's shard is unknown.
    #[error(transparent)]
    Shard(#[from] ShardError),
    /// The server could not start.
    #[error(transparent)]
    Serve(#[from] ServeError),
    /// A scene's run failed (a scene or view error names its file; others are given the scene's).
    #[error("{}", run_failure(scene, source))]
    Run {
        /// The scene file.
        scene: PathBuf,
        /// Why the run failed.
        #[source]
        source: Box<RunError>,
    },
    /// Neither a scene nor a model file was given.
    #[error("give a scene or --model")]
    NoScene,
    /// A scene of a compiled model gives `[specified]` formulas.
    #[error("{}: [specified] {name}: formulas are for a model file's SPECIFIED quantities, and {model} is a compiled model", scene.display())]
    SpecifiedCompiled {
        /// The scene file.
        scene: PathBuf,
        /// The first formula's quantity.
        name: String,
        /// The scene's model.
        model: String,
    },
    /// The compiled model cannot be started, even rebuilt.
    #[error("cannot start the compiled model {} even after rebuilding it: {why}\n  help: run with --engine instant, or remove {} and try again", binary.display(), cache.display())]
    CannotStart {
        /// The binary.
        binary: PathBuf,
        /// Why (the system's words, or what the file is instead of a program).
        why: String,
        /// The cache of compiled models.
        cache: PathBuf,
    },
    /// The compiled model could not be started (where it is run as a child process).
    #[cfg(not(unix))]
    #[error("cannot start the compiled model {}: {source}", binary.display())]
    Start {
        /// The binary.
        binary: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// A folder or file of the command could not be made or read.
    #[error("{}: {source}", path.display())]
    Io {
        /// The folder or file.
        path: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// A `--set` argument is not `NAME=VALUE`.
    #[error("`{text}` is not NAME=VALUE (for example --set Y=10 or --set \"Q2=30 deg\")")]
    SetForm {
        /// The argument.
        text: String,
    },
    /// A `--method` names no integrator.
    #[error("unknown integrator `{name}` ({}, or auto)", crate::ode::methods_help())]
    UnknownMethod {
        /// The name given.
        name: String,
    },
    /// A `--rtol` or `--atol` is not a positive number.
    #[error("`{text}` is not a positive number (for example 1e-9)")]
    NotPositive {
        /// The argument.
        text: String,
    },
    /// A sweep was stopped by a signal; the members done are kept.
    #[error("{by}: {kept} members done are kept in {}; run the same command again to resume", journal.display())]
    Interrupted {
        /// The signal.
        by: Interrupted,
        /// The members kept.
        kept: usize,
        /// The journal that keeps them.
        journal: PathBuf,
    },
    /// A finished member could not be written to the journal.
    #[error("the sweep's journal could not be written: {0}")]
    Journal(#[source] SweepError),
    /// The progress bar's template is wrong.
    #[error("{0}")]
    Progress(#[from] indicatif::style::TemplateError),
    /// A sweep's folder has no rows to plot.
    #[error("{}: no sweep.csv (run gyro-sim sweep --out {} first)", csv.display(), dir.display())]
    NoSweep {
        /// The rows file.
        csv: PathBuf,
        /// The folder.
        dir: PathBuf,
    },
    /// The rows file has no status column.
    #[error("{}: no status column: not a sweep's file", csv.display())]
    NoStatus {
        /// The rows file.
        csv: PathBuf,
    },
    /// A column asked for is not in the rows file.
    #[error("{}: no column `{name}`; the columns are: {}", csv.display(), columns.join(", "))]
    NoColumn {
        /// The rows file.
        csv: PathBuf,
        /// The name asked for.
        name: String,
        /// The columns to choose from.
        columns: Vec<String>,
    },
    /// `--over` names none or more than two varied names.
    #[error("--over takes one or two of the varied names ({})", varied.join(", "))]
    Over {
        /// The varied names.
        varied: Vec<String>,
    },
}

impl From<ModelRunError> for CliError {
    /// The model run's error, boxed (it keeps the generated scene's error with its origin).
    fn from(e: ModelRunError) -> CliError {
        CliError::ModelRun(Box::new(e))
    }
}

impl From<SolveError> for CliError {
    /// The integration's error, boxed (it is the largest).
    fn from(e: SolveError) -> CliError {
        CliError::Solve(Box::new(e))
    }
}

/// A run's failure as the command shows it: a scene or view error names its file, line and
/// column already; another is given the scene's path.
fn run_failure(scene: &std::path::Path, e: &RunError) -> String {
    match e {
        RunError::Scene(_) => e.to_string(),
        e => format!("{}: {e}", scene.display()),
    }
}
