//! Constraints kept along a run: in come the bound model and each output time's full state; out
//! go the largest configuration and motion residuals and the worst conditioning of the
//! dependent speeds' matrix, the trajectory's [`Constraints`] report.

use kane_model::assembly::Assembly;
use kane_model::runtime::{ModelInfo, OutputKind};

use super::bound::{output_of_kind, BoundModel};
use super::diagnose;
use crate::problem::{Conditioning, Constraints};

/// The largest constraint residuals at the output times so far, by kind (configuration,
/// motion), and the worst conditioning of the dependent speeds' matrix, for a model that has
/// them.
#[derive(Clone, Debug, Default)]
pub(crate) struct Residuals {
    /// The configuration and motion residual outputs, found once.
    outputs: [Option<usize>; 2],
    configuration: Option<f64>,
    motion: Option<f64>,
    /// The constraint-matrix output, found once.
    matrix: Option<usize>,
    /// The worst conditioning so far, when the model has a constraint-matrix output.
    conditioning: Option<Conditioning>,
    scratch: Vec<f64>,
}

impl Residuals {
    /// Tracking for `info`'s residual outputs (none: nothing is computed).
    pub(crate) fn of(info: &ModelInfo) -> Residuals {
        let find = |kind: OutputKind| output_of_kind(info, kind);
        Residuals {
            outputs: [find(OutputKind::ConfigurationResiduals), find(OutputKind::MotionResiduals)],
            matrix: find(OutputKind::ConstraintMatrix),
            ..Default::default()
        }
    }

    /// Updated with the residuals and the conditioning at `(t, y)`.
    pub(crate) fn track<B: BoundModel>(&mut self, model: &B, t: f64, y: &[f64]) {
        for (k, slot) in self.outputs.iter().zip([&mut self.configuration, &mut self.motion]) {
            let Some(k) = *k else { continue };
            self.scratch.resize(model.info().outputs[k].columns.len(), 0.0);
            model.output(k, t, y, &[], &mut self.scratch);
            *slot = Some(kane_model::assembly::largest_magnitude(slot.unwrap_or(0.0), &self.scratch));
        }
        let Some(k) = self.matrix else { return };
        let rcond = diagnose::matrix_rcond(model, k, t, y, &mut self.scratch);
        let worse = match &self.conditioning {
            Some(c) => rcond.is_nan() || rcond < c.rcond,
            None => true,
        };
        if worse {
            let configuration = diagnose::configuration(model.info(), y);
            self.conditioning = Some(Conditioning { rcond, time: t, configuration });
        }
    }

    /// The run's report, when the model has constraints.
    pub(crate) fn report(self, assembly: Option<Assembly>) -> Option<Constraints> {
        let any = assembly.is_some() || self.configuration.is_some() || self.motion.is_some();
        any.then_some(Constraints {
            assembly,
            configuration: self.configuration,
            motion: self.motion,
            conditioning: self.conditioning,
        })
    }
}
