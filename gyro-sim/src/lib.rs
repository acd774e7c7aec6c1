//! gyro-sim: integrate models derived with kane-model, from scene files to CSV and plots.
//!
//! The stages, each a module with a narrow interface:
//! [`scene`] (TOML text -> [`scene::Scene`]) -> [`resolve`] (scene + [`registry`] ->
//! [`problem::Problem`] in model units) -> [`solve`] (problem -> [`trajectory::Trajectory`],
//! stepping with [`ode`]) -> [`output`] (trajectory -> CSV and PNG in display units).
//! [`run`] chains them; [`models`] holds the models compiled into the simulator.
#![warn(missing_docs)]

pub mod batch;
pub mod cli;
pub mod compiled;
mod diagnose;
pub mod events;
pub mod initial;
pub mod instant;
pub mod interrupt;
pub mod model_file;
pub mod models;
pub mod ode;
pub mod output;
mod plausible;
pub mod problem;
mod refine;
pub mod registry;
pub mod resolve;
pub mod rows;
pub mod run;
pub mod scene;
pub mod serve;
pub mod solve;
pub mod specified_table;
pub mod sweep;
pub mod trajectory;
pub mod unit_norm;
pub mod work_precision;
