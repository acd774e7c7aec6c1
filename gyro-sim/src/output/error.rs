//! Why results could not be written: each variant names the file and keeps the error beneath it
//! (the system's, the CSV writer's, the figure's, the view's, the output set's) as its source.

use std::path::PathBuf;

use thiserror::Error;

use super::plot::PlotError;
use super::set::SetError;
use crate::scene::ViewError;

/// Why results could not be written.
#[derive(Debug, Error)]
pub enum WriteError {
    /// A file could not be made, written, renamed or removed.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// What the system said.
        #[source]
        source: std::io::Error,
    },
    /// A CSV file could not be written.
    #[error("{}: {source}", path.display())]
    Csv {
        /// The file.
        path: PathBuf,
        /// What the CSV writer said.
        #[source]
        source: csv::Error,
    },
    /// A figure could not be drawn.
    #[error("{}: {source}", path.display())]
    Plot {
        /// The figure's file.
        path: PathBuf,
        /// What failed in drawing it.
        #[source]
        source: PlotError,
    },
    /// The 3-D view's tables do not fit the run.
    #[error("{}: {source}", path.display())]
    View {
        /// The view's file.
        path: PathBuf,
        /// What does not fit.
        #[source]
        source: ViewError,
    },
    /// A CSV being written row by row was already closed.
    #[error("{}: already closed", path.display())]
    Closed {
        /// The file.
        path: PathBuf,
    },
    /// A CSV writer shared between threads failed earlier (a thread panicked holding it).
    #[error("the CSV writer failed")]
    Poisoned,
    /// The output set could not be staged or put in place.
    #[error(transparent)]
    Set(#[from] SetError),
}

impl WriteError {
    /// The error `source` at `path`, a system error.
    pub fn io(path: impl Into<PathBuf>, source: std::io::Error) -> WriteError {
        WriteError::Io { path: path.into(), source }
    }

    /// The error `source` at `path`, the CSV writer's.
    pub fn csv(path: impl Into<PathBuf>, source: csv::Error) -> WriteError {
        WriteError::Csv { path: path.into(), source }
    }
}
