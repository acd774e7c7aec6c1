//! A model's runtime metadata as plain data: in come a spec and its lowered program; out goes
//! [`Meta`] (names, units, outputs), which the printer spells as a `ModelInfo` literal and
//! [`Meta::leak`] turns into a `ModelInfo` at run time.

use crate::runtime::{ModelInfo, OpCounts, OutputInfo, OutputKind};
use crate::spec::{self, ModelSpec, OrientationForm};

use super::lower::Lowered;

/// One output's metadata.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputMeta {
    /// Its name.
    pub name: String,
    /// Its unit.
    pub unit: String,
    /// What it is.
    pub kind: OutputKind,
    /// Its column names.
    pub columns: Vec<String>,
    /// The states it reads.
    pub reads: Vec<usize>,
    /// Whether it reads the speed rates.
    pub needs_rates: bool,
}

/// The metadata of a model, owned.
#[derive(Clone, Debug, PartialEq)]
pub struct Meta {
    /// The model's name.
    pub name: String,
    /// State names, coordinates then speeds.
    pub states: Vec<String>,
    /// State units.
    pub state_units: Vec<String>,
    /// Number of coordinates.
    pub n_coordinates: usize,
    /// Parameter names, in the order the program reads them.
    pub params: Vec<String>,
    /// Parameter units.
    pub param_units: Vec<String>,
    /// The parameters that are inputs (indices).
    pub inputs: Vec<usize>,
    /// The inputs without a value from the model.
    pub open_inputs: Vec<usize>,
    /// The outputs.
    pub outputs: Vec<OutputMeta>,
    /// Coordinates no equation reads.
    pub cyclic: Vec<usize>,
    /// The coordinates the configuration constraints determine.
    pub dependent_coordinates: Vec<usize>,
    /// Operations per `rhs` call and per evaluation of every output.
    pub op_counts: OpCounts,
    /// The orders whose Taylor coefficients the generated code computes straight-line.
    pub taylor_straight_line: Vec<usize>,
}

impl Meta {
    /// The metadata of `spec` lowered as `lowered`.
    pub fn of(spec: &ModelSpec, lowered: &Lowered) -> Meta {
        let names = |ids: &[crate::expr::SymbolId]| -> Vec<String> {
            ids.iter().map(|s| spec.symbol_name(*s).to_string()).collect()
        };
        let units =
            |names: &[String]| -> Vec<String> { names.iter().map(|s| spec.unit(s).to_string()).collect() };
        let (states, params) = (names(&lowered.states), names(&lowered.params));
        let outputs = spec
            .outputs
            .iter()
            .zip(&lowered.program.outputs)
            .map(|(o, code)| OutputMeta {
                name: o.name.clone(),
                unit: o.unit.clone(),
                kind: output_kind(&o.kind),
                columns: o.columns(),
                reads: code.reads.clone(),
                needs_rates: code.needs_rates,
            })
            .collect();
        let dependent_coordinates = spec
            .outputs
            .iter()
            .filter_map(|o| match &o.kind {
                spec::OutputKind::ConfigurationResiduals { dependent } => Some(dependent),
                _ => None,
            })
            .flatten()
            .filter_map(|q| states.iter().position(|s| s == q))
            .collect();
        let position = |s: &crate::expr::SymbolId| lowered.params.iter().position(|p| p == s);
        let inputs = spec.inputs.iter().filter_map(position).collect();
        let open_inputs = spec.open_inputs.iter().filter_map(position).collect();
        Meta {
            name: spec.name.clone(),
            inputs,
            open_inputs,
            dependent_coordinates,
            state_units: units(&states),
            states,
            n_coordinates: lowered.program.n_coordinates,
            param_units: units(&params),
            params,
            outputs,
            cyclic: lowered.program.cyclic.clone(),
            op_counts: lowered.program.op_counts(),
            taylor_straight_line: Vec::new(),
        }
    }

    /// A `ModelInfo` for the rest of the process: its strings and lists are leaked (a few
    /// hundred bytes per model loaded at run time).
    pub fn leak(&self) -> &'static ModelInfo {
        let outputs: Vec<OutputInfo> = self
            .outputs
            .iter()
            .map(|o| OutputInfo {
                name: leak_str(&o.name),
                unit: leak_str(&o.unit),
                kind: o.kind,
                columns: leak_strs(&o.columns),
                reads: Box::leak(o.reads.clone().into_boxed_slice()),
                needs_rates: o.needs_rates,
            })
            .collect();
        Box::leak(Box::new(ModelInfo {
            name: leak_str(&self.name),
            state_names: leak_strs(&self.states),
            state_units: leak_strs(&self.state_units),
            n_coordinates: self.n_coordinates,
            param_names: leak_strs(&self.params),
            param_units: leak_strs(&self.param_units),
            inputs: Box::leak(self.inputs.clone().into_boxed_slice()),
            open_inputs: Box::leak(self.open_inputs.clone().into_boxed_slice()),
            outputs: Box::leak(outputs.into_boxed_slice()),
            cyclic: Box::leak(self.cyclic.clone().into_boxed_slice()),
            dependent_coordinates: Box::leak(self.dependent_coordinates.clone().into_boxed_slice()),
            op_counts: self.op_counts,
            taylor_straight_line: Box::leak(self.taylor_straight_line.clone().into_boxed_slice()),
        }))
    }
}

/// The runtime kind of a spec's output kind (its frame, point or size left out).
fn output_kind(kind: &spec::OutputKind) -> OutputKind {
    use spec::OutputKind as S;
    match kind {
        S::Scalar => OutputKind::Scalar,
        S::Vector { .. } => OutputKind::Vector,
        S::Orientation { form: OrientationForm::Dcm, .. } => OutputKind::Dcm,
        S::Orientation { form: OrientationForm::Quaternion, .. } => OutputKind::Quaternion,
        S::KineticEnergy => OutputKind::KineticEnergy,
        S::PotentialEnergy => OutputKind::PotentialEnergy,
        S::AngularMomentum { .. } => OutputKind::AngularMomentum,
        S::ConfigurationResiduals { .. } => OutputKind::ConfigurationResiduals,
        S::MotionResiduals => OutputKind::MotionResiduals,
        S::ConstraintMatrix { .. } => OutputKind::ConstraintMatrix,
        S::Drawing { .. } => OutputKind::Drawing,
    }
}

fn leak_str(s: &str) -> &'static str {
    Box::leak(s.to_string().into_boxed_str())
}

fn leak_strs(v: &[String]) -> &'static [&'static str] {
    Box::leak(v.iter().map(|s| leak_str(s)).collect::<Vec<_>>().into_boxed_slice())
}
