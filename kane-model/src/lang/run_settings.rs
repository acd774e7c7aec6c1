//! What a model file says about a run: in comes a loaded file; out go its INPUT TFINAL,
//! INTEGSTP, ABSERR and RELERR, its OUTPUT names, and the settings a run takes where the file
//! gives none (the same for the simulator and for the programs CODE statements write).

use super::LoadedModel;
use crate::runtime::ModelInfo;

/// End time when neither the command line nor the file's TFINAL gives one.
pub const DEFAULT_T_FINAL: f64 = 10.0;
/// Output rows when the file gives no INTEGSTP.
pub const DEFAULT_ROWS: f64 = 100.0;
/// Tolerance when the file gives no ABSERR / RELERR.
pub const DEFAULT_TOLERANCE: f64 = 1e-8;

/// What a model file says about a run (INPUT TFINAL, INTEGSTP, ABSERR, RELERR; OUTPUT).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FileRun {
    /// The final time, `TFINAL`.
    pub t_final: Option<f64>,
    /// `INTEGSTP`: the output step.
    pub step: Option<f64>,
    /// The absolute tolerance, `ABSERR`.
    pub abserr: Option<f64>,
    /// The relative tolerance, `RELERR`.
    pub relerr: Option<f64>,
    /// The OUTPUT names other than `T`, in order (without `>`).
    pub outputs: Vec<String>,
}

impl FileRun {
    /// The run settings `loaded` gives.
    pub fn of(loaded: &LoadedModel) -> FileRun {
        let input = |n: &str| loaded.inputs.iter().find(|i| i.name.eq_ignore_ascii_case(n)).map(|i| i.value);
        let outputs = loaded
            .outputs
            .iter()
            .map(|(n, _)| n.trim_end_matches('>').to_string())
            .filter(|n| !n.eq_ignore_ascii_case("T"))
            .collect();
        FileRun {
            t_final: input("TFINAL"),
            step: input("INTEGSTP"),
            abserr: input("ABSERR"),
            relerr: input("RELERR"),
            outputs,
        }
    }

    /// The file's INTEGSTP, when it is a step within `t_final`.
    pub fn step_within(&self, t_final: f64) -> Option<f64> {
        self.step.filter(|s| *s > 0.0 && *s <= t_final)
    }

    /// The settings of a run that gives none of its own: the file's, else the defaults.
    pub fn settings(&self) -> RunSettings {
        let t_final = self.t_final.unwrap_or(DEFAULT_T_FINAL);
        RunSettings {
            t_final,
            output_step: self.step_within(t_final).unwrap_or(t_final / DEFAULT_ROWS),
            rtol: self.relerr.unwrap_or(DEFAULT_TOLERANCE),
            atol: self.abserr.unwrap_or(DEFAULT_TOLERANCE),
        }
    }

    /// The quantities a run writes: the OUTPUT names `info` knows (states or outputs), every
    /// state when there are none.
    pub fn written<'a>(&'a self, info: &'a ModelInfo) -> Vec<&'a str> {
        let known = |n: &str| info.state(n).is_some() || info.output(n).is_some();
        let outputs: Vec<&str> = self.outputs.iter().map(String::as_str).filter(|n| known(n)).collect();
        if outputs.is_empty() {
            return info.state_names.to_vec();
        }
        outputs
    }
}

/// A run's times and tolerances.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunSettings {
    /// The end time.
    pub t_final: f64,
    /// The output step.
    pub output_step: f64,
    /// The relative tolerance.
    pub rtol: f64,
    /// The absolute tolerance.
    pub atol: f64,
}
