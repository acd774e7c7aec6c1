//! gyro-sim: integrate models derived with kane-model, from scene files to CSV and plots.
//!
//! - [`ode`]: the [`ode::System`] trait, tableaux as data, explicit Runge-Kutta integration.
//! - [`models`]: the models compiled from model files at build time (`kane_derive::model!`).
//! - [`scene`]: TOML scenes; [`run`]: running one; [`output`]: CSV and PNG.
#![warn(missing_docs)]

pub mod models;
pub mod ode;
pub mod output;
pub mod run;
pub mod scene;
