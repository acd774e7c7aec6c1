//! What generated model modules implement, so a simulator can drive any of them.

/// A model compiled from its equations by [`crate::codegen`].
pub trait GeneratedModel {
    /// Parameter values (defaults from the model file's INPUT).
    type Params: Clone + Default + std::fmt::Debug;
    /// Quantities of the parameters alone, computed once per parameter set.
    type Derived: Clone + std::fmt::Debug;
    /// The model's name.
    const NAME: &'static str;
    /// State names, coordinates then speeds, as declared.
    const STATE_NAMES: &'static [&'static str];
    /// Each state's unit from UNITS (empty when none); angles are integrated in radians.
    const STATE_UNITS: &'static [&'static str];
    /// Output names (the model file's OUTPUT scalars that are not states).
    const OUTPUT_NAMES: &'static [&'static str];
    /// Each output's unit from UNITS (empty when none).
    const OUTPUT_UNITS: &'static [&'static str];
    /// Parameter names.
    const PARAM_NAMES: &'static [&'static str];
    /// The initial state from INPUT, in radians (NaN where INPUT gives none).
    fn initial_state() -> Vec<f64>;
    /// Sets a parameter by name (case-insensitive); false if there is none.
    fn set_param(p: &mut Self::Params, name: &str, value: f64) -> bool;
    /// A parameter's value by name (case-insensitive).
    fn param(p: &Self::Params, name: &str) -> Option<f64>;
    /// `dy = f(t, y)`.
    fn rhs(t: f64, y: &[f64], p: &Self::Params, dy: &mut [f64]);
    /// The parameter-only quantities of `rhs`.
    fn derive(p: &Self::Params) -> Self::Derived;
    /// `dy = f(t, y)` with `d = derive(p)`: the fast path for integration.
    fn rhs_derived(t: f64, y: &[f64], p: &Self::Params, d: &Self::Derived, dy: &mut [f64]);
    /// The kinetic energy at `(t, y)`.
    fn kinetic_energy(t: f64, y: &[f64], p: &Self::Params) -> f64;
    /// The outputs at `(t, y)`.
    fn outputs(t: f64, y: &[f64], p: &Self::Params, out: &mut [f64]);
    /// Arithmetic operations per call of `rhs` and of `outputs`.
    const OP_COUNTS: (usize, usize);
    /// Coordinates that no equation reads (cyclic): they can be left out of the integrated state
    /// when no output needs them.
    const CYCLIC: &'static [usize];
    /// For each output, the states it reads.
    const OUTPUT_STATES: &'static [&'static [usize]];
}
