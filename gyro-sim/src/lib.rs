//! gyro-sim: integrate models derived with kane-model, from scene files to CSV and plots.
#![warn(missing_docs)]

mod cli;
mod models;
mod ode;
mod output;
mod problem;
mod resolve;
mod run;
mod scene;
mod serve;
mod solve;
mod study;

pub use cli::{main_with, CompiledModel};
pub use models::{content_hash, gimbal_gyroscope, heavy_top, registry_key, FileRun, ModelFile, Registry};
pub use ode::{
    by_name, integrate, integrate_limited, tableau, DenseOutput, ErkStepper, Method, OdeError, Stats,
    StopReason, System, Tolerances, METHODS,
};
pub use output::{write, write_view};
pub use problem::{Column, Engine, ModelEntry, Pick, Problem, Trajectory, MAX_KEPT_ROWS};
pub use resolve::{resolve, sleeping_threshold, steady_precession};
pub use run::{run, run_with, RunSummary};
pub use scene::{ArrowView, BodyView, Orientation, Scene, Shape, TraceView, ViewSpec};
pub use solve::{solve_bound, BoundModel, ModelSystem, Reduced};
pub use study::batch::final_states;
