//! A generated model's metadata: in comes nothing; out go [`ModelInfo`] and its
//! [`OutputInfo`]s, printed beside each model as constants (and built at run time for a model
//! evaluated from its lowered program).

/// What an output of a generated model is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputKind {
    /// One scalar expression of the model.
    Scalar,
    /// A vector's three measure numbers in a frame.
    Vector,
    /// A frame's direction-cosine matrix in the Newtonian frame, row by row.
    Dcm,
    /// A frame's orientation in the Newtonian frame as a unit quaternion, scalar first.
    Quaternion,
    /// The kinetic energy in the Newtonian frame.
    KineticEnergy,
    /// The potential energy of uniform gravity.
    PotentialEnergy,
    /// An angular momentum's three measure numbers in a frame.
    AngularMomentum,
    /// The residuals of the configuration constraints (zero on the constraint manifold).
    ConfigurationResiduals,
    /// The residuals of the motion constraints with the dependent speeds solved from them.
    MotionResiduals,
    /// The motion constraints' matrix of the dependent speeds, row by row.
    ConstraintMatrix,
    /// A model's default drawing: frames' direction cosines and points' positions.
    Drawing,
}

/// One output of a generated model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutputInfo {
    /// Its name in the model.
    pub name: &'static str,
    /// Its unit (empty when none).
    pub unit: &'static str,
    /// What it is (a scalar, a vector, the kinetic energy, ...).
    pub kind: OutputKind,
    /// The names of the values it writes (one for a scalar).
    pub columns: &'static [&'static str],
    /// The states it reads.
    pub reads: &'static [usize],
    /// Whether it reads the speed rates `u'` (evaluate `rhs` first).
    pub needs_rates: bool,
}

/// Everything a driver needs to know about a generated model, without its types.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ModelInfo {
    /// The model's name.
    pub name: &'static str,
    /// State names, coordinates then speeds, as declared.
    pub state_names: &'static [&'static str],
    /// Each state's unit from UNITS (empty when none); angles are integrated in radians.
    pub state_units: &'static [&'static str],
    /// Number of coordinates (the first states).
    pub n_coordinates: usize,
    /// Parameter names.
    pub param_names: &'static [&'static str],
    /// Each parameter's unit (empty when none).
    pub param_units: &'static [&'static str],
    /// The parameters that are inputs: quantities of time the model leaves to its user (a model
    /// file's SPECIFIED quantities without a formula, Autolev's "quantities to be specified"),
    /// held constant unless a run gives them as functions of time.
    pub inputs: &'static [usize],
    /// The inputs the model gives no value (zero by default).
    pub open_inputs: &'static [usize],
    /// The outputs.
    pub outputs: &'static [OutputInfo],
    /// Coordinates that no equation reads (cyclic): they can be left out of the integrated
    /// state when no output needs them.
    pub cyclic: &'static [usize],
    /// The coordinates the configuration constraints determine (solved for at the start of a
    /// run, see kane-model's `assembly`); empty for a model without such constraints.
    pub dependent_coordinates: &'static [usize],
    /// Arithmetic operations per call of `rhs` and per evaluation of every output.
    pub op_counts: OpCounts,
    /// The orders whose Taylor coefficients the model computes straight-line (faster than the
    /// loop every other order takes); empty for a model without them.
    pub taylor_straight_line: &'static [usize],
}

/// Arithmetic operations of a model's lowered program (instructions other than inputs and
/// constants).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCounts {
    /// Per call of `rhs` (the equations and the solve of `M u' = f`).
    pub rhs: usize,
    /// Per evaluation of every output.
    pub outputs: usize,
}

impl ModelInfo {
    /// The index of a state by name (case-insensitive).
    pub fn state(&self, name: &str) -> Option<usize> {
        self.state_names.iter().position(|s| s.eq_ignore_ascii_case(name))
    }

    /// The index of a parameter by name (case-insensitive).
    pub fn param(&self, name: &str) -> Option<usize> {
        self.param_names.iter().position(|p| p.eq_ignore_ascii_case(name))
    }

    /// The index of an output by name (case-insensitive).
    pub fn output(&self, name: &str) -> Option<usize> {
        self.outputs.iter().position(|o| o.name.eq_ignore_ascii_case(name))
    }
}
