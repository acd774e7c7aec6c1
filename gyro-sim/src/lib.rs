//! gyro-sim: integrate models derived with kane-model, from scene files to CSV and plots.
//!
//! A run goes one way through the stages:
//!
//! ```text
//! scene text --scene--> Scene --resolve (+ models::Registry)--> Problem (carries its SharedModel)
//!   --solve (ode steppers)--> Trajectory --output--> CSV, PNG, events.csv, view.html
//! ```
//!
//! Each folder is a floor. Floors, lowest first; each floor imports only from itself and the
//! floors below it, and no two files import each other, directly or around a circle:
//!
//! 1. `ode/`: in come a system `y' = f(t, y)`, a start and a method; out go the states at
//!    output times (or step by step) and the cost, or an `OdeError`. Also the unit-norm
//!    projection of Euler parameters and the stop signals long loops read.
//! 2. `scene/`: in comes a scene file's TOML text; out goes a checked `Scene` (the model's name,
//!    values with their units, times, the integrator with its method found by name, the
//!    `[[events]]`, `[[controls]]` and `[view]` tables) or a `SceneError` at a line and column.
//! 3. `problem/`: what the stages hand each other: the `Problem` (model units; it carries the
//!    model, a `SharedModel` found once in the registry), and what solving gives back: the
//!    `Trajectory`, a `SolveError`, rows streamed to a `RowStream`.
//! 4. `output/`: in comes a `Trajectory`; out go the CSV, the figures, `events.csv` and the
//!    3-D view in display units, put in place as one set (or the CSV streamed as rows come).
//! 5. `solve/`: in come a `Problem` and where its rows go; out goes a `Trajectory`, or a
//!    `SolveError` explained where the run went wrong (`diagnose`), with an asked accuracy
//!    reached by refinement (`refine`) and events watched on the dense output (`events`).
//! 6. `models/`: in come generated models (built in, or a user's crate's) and model files; out
//!    goes a `Registry` of `SharedModel`s, one `SimModel` implementation per engine: compiled
//!    (`generated`; `compiled`: a cached binary for a model file), JIT (`jit`) and instant
//!    (`instant`).
//! 7. `resolve/`: in come a `Scene` and a `Registry`; out goes a `Problem` (units converted, a
//!    top's `[axle]` made Euler parameters and rates, events bound to the model, values checked
//!    for plausibility) or a `SceneError`.
//! 8. `run.rs`: in comes a scene; out go its trajectory and files (resolve, solve, output).
//! 9. `model_run/`: in comes a model file (with a scene, or a scene generated from the file
//!    and the command line's values); out goes the run made ready: the file's model on the
//!    engine asked, the scene, the problem resolved once, errors told at their origin.
//! 10. `study/`: many runs: parameter sweeps (`sweep`), members in lock step (`batch`), work
//!     against precision (`work_precision`).
//! 11. `serve/`: a scene run in a browser page, its controls as sliders.
//! 12. `cli/`: the `gyro-sim` command.
//!
//! Every module is private; what the binary, the examples, the benches, the tests and a compiled
//! model's generated driver use is re-exported here.

mod cli;
mod model_run;
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

// The front door: everything outside the crate names these, and nothing else.
pub use cli::main_with;
pub use model_run::CompiledModel;
pub use models::{
    content_hash, generated, gimbal_gyroscope, heavy_top, registry_key, FileRun, InstantSystem, JitSystem,
    ModelFile, ModelFileError, Registry,
};
pub use ode::test_problems;
pub use ode::{
    by_name, tableau, DenseOutput, ErkStepper, Integration, Method, OdeError, Outcome, Stats, Stepper,
    StopReason, System, TaylorStepper, TaylorWork, Tolerances, Unwatched, METHODS,
};
pub use output::{write, write_view, PlotError, SetError, WriteError};
pub use problem::{
    Column, Engine, Pick, Problem, RowError, RowStream, SharedModel, SimModel, SolveError, Trajectory,
    MAX_KEPT_ROWS,
};
pub use resolve::{resolve, sleeping_threshold, steady_precession};
pub use run::{run, run_with, RunError, RunSummary};
pub use scene::{
    ArrowView, BodyView, IntegratorOverrides, Length, Orientation, PointView, Scene, SceneError, Shape,
    TraceView, ViewError, ViewSpec,
};
pub use solve::{solve, solve_bound, BoundModel, ModelSystem, Reduced};
pub use study::batch::final_states;
