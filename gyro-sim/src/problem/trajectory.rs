//! A solved problem: what [`crate::solve`] returns and [`crate::output::write`] writes. Values
//! are in model units (radians for angles).

use std::time::Duration;

use crate::ode::NormDrift;
use crate::ode::Stats;

/// One column after `t`.
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// The quantity's name in the model (`Q1`, `AP`, `L_N1`).
    pub name: String,
    /// Its unit in the model (`DEG` for an angle integrated in radians; empty when none).
    pub unit: String,
    /// Whether it is a model output (not a state).
    pub output: bool,
    /// Computed only for the 3-D view: not written to the CSV or the figures.
    pub hidden: bool,
}

impl Column {
    /// Whether the quantity is an angle.
    pub fn is_angle(&self) -> bool {
        matches!(self.unit.to_ascii_uppercase().as_str(), "DEG" | "RAD")
    }
}

/// An accuracy asked of a run and how it was reached.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accuracy {
    /// Asked: largest error relative to max(1, |value|).
    pub goal: f64,
    /// The difference between the written run and one at 100 times looser tolerances: about
    /// the looser run's error, far above the written run's.
    pub estimate: f64,
    /// Relative tolerance of the written run.
    pub rtol: f64,
    /// Absolute tolerance of the written run.
    pub atol: f64,
    /// Integrations done (their costs are summed in the statistics).
    pub runs: usize,
}

/// Rows of `t` and the columns, with what the integration cost.
#[derive(Clone, Debug)]
pub struct Trajectory {
    /// Title for plots.
    pub title: String,
    /// The columns after `t`.
    pub columns: Vec<Column>,
    /// Each row: `t`, then one value per column.
    pub rows: Vec<Vec<f64>>,
    /// Rows at the output times and the plot times between them, for figures (empty: use
    /// `rows`).
    pub plot_rows: Vec<Vec<f64>>,
    /// Integrator statistics (summed over refinement runs).
    pub stats: Stats,
    /// Wall time of the integration (outputs included, files excluded).
    pub wall: Duration,
    /// The states that were integrated (cyclic coordinates nothing needed are left out).
    pub integrated: Vec<&'static str>,
    /// Kinetic energy at the start and at the end, when the model has it as an output.
    pub kinetic_energy: Option<(f64, f64)>,
    /// Gravity's potential energy at the start and the end, where the model's only loads are
    /// gravity's (then kinetic plus potential is the total energy).
    pub potential_energy: Option<(f64, f64)>,
    /// How an asked accuracy was met.
    pub accuracy: Option<Accuracy>,
    /// How far the unit-norm states (Euler parameters) drifted, when the problem has any.
    pub norm_drift: Option<NormDrift>,
    /// The events declared and those that happened.
    pub events: super::EventLog,
    /// How the start was assembled onto the configuration constraints and how well the run
    /// kept its constraints, when the model has any.
    pub constraints: Option<Constraints>,
}

/// A run's constraints: the assembled start and the residuals along the run.
#[derive(Clone, Debug, PartialEq)]
pub struct Constraints {
    /// What assembling the initial state onto the configuration constraints did.
    pub assembly: Option<kane_model::assembly::Assembly>,
    /// The largest configuration residual at the output times.
    pub configuration: Option<f64>,
    /// The largest motion-constraint residual at the output times.
    pub motion: Option<f64>,
    /// The worst conditioning of the dependent speeds' matrix at the output times.
    pub conditioning: Option<Conditioning>,
}

/// The motion constraints' matrix of dependent speeds at its worst output time.
#[derive(Clone, Debug, PartialEq)]
pub struct Conditioning {
    /// Its smallest over largest singular value (NaN when an entry was not finite).
    pub rcond: f64,
    /// The output time it was worst at.
    pub time: f64,
    /// The coordinates then, `Q1 = 0 deg, ...`.
    pub configuration: String,
}
