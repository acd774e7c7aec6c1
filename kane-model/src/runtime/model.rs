//! The generated-model traits: in comes nothing; out go [`GeneratedModel`] (what every
//! generated model module implements) and [`LaneModel`] (its optional `rhs_lanes`), with the
//! Taylor constants their signatures name.

use super::taylor;
use super::ModelInfo;

/// Scratch rows for Taylor coefficients ([`GeneratedModel::taylor`]), reused between calls.
pub type TaylorWork = Vec<taylor::Row<f64>>;

/// The highest order [`GeneratedModel::taylor`] expands to.
pub const TAYLOR_MAX_ORDER: usize = taylor::MAX_ORDER;

/// The orders a model asks straight-line Taylor code for by default (one function each, every
/// loop written out), spread over those the Taylor stepper takes at tolerances 1e-4 to 1e-16 (it
/// picks the one of a model's orders nearest the order it would choose). Not every order: each
/// costs build time. See [`ModelInfo::taylor_straight_line`] for the orders a model has.
pub const TAYLOR_UNROLLED_ORDERS: &[usize] = &[8, 12, 14, 16, 20];

/// A model compiled from its equations by kane-model's code generator.
pub trait GeneratedModel {
    /// Parameter values (defaults from the model's INPUT).
    type Params: Clone + Default + std::fmt::Debug;
    /// Quantities of the parameters alone, computed once per parameter set.
    type ParamConstants: Clone + std::fmt::Debug;
    /// The model's metadata.
    const INFO: ModelInfo;
    /// The initial state from INPUT, in radians (NaN where INPUT gives none).
    fn initial_state() -> Vec<f64>;
    /// Sets a parameter by name (case-insensitive); false if there is none.
    fn set_param(p: &mut Self::Params, name: &str, value: f64) -> bool;
    /// A parameter's value by name (case-insensitive).
    fn param(p: &Self::Params, name: &str) -> Option<f64>;
    /// The parameter-only quantities of `rhs`.
    fn param_constants(p: &Self::Params) -> Self::ParamConstants;
    /// `dy = f(t, y)` with `d = param_constants(p)`: the fast path for integration.
    fn rhs_with_constants(t: f64, y: &[f64], p: &Self::Params, d: &Self::ParamConstants, dy: &mut [f64]);
    /// `dy = f(t, y)`.
    fn rhs(t: f64, y: &[f64], p: &Self::Params, dy: &mut [f64]) {
        Self::rhs_with_constants(t, y, p, &Self::param_constants(p), dy)
    }
    /// Output `k` at `(t, y)` into `out` (its columns); `rates` are `u'` when the output needs
    /// them (see [`OutputInfo::needs_rates`](super::OutputInfo::needs_rates)), else ignored.
    fn output(k: usize, t: f64, y: &[f64], rates: &[f64], p: &Self::Params, out: &mut [f64]);
    /// The parameter constants as numbers, in the order `param_constants` computes them (and
    /// [`LaneModel::rhs_lanes`] reads them).
    fn constant_values(d: &Self::ParamConstants) -> &[f64];
    /// Output `k` at `(t, y)` into `out` and its time derivative along `y' = dy` into `rate`
    /// (dual numbers through the output's code); meaningful only for an output that reads no
    /// speed rates (its rate would need `u''`).
    fn output_rate(
        k: usize,
        t: f64,
        y: &[f64],
        dy: &[f64],
        p: &Self::Params,
        out: &mut [f64],
        rate: &mut [f64],
    );
    /// The normalised Taylor coefficients of the solution through `(t, y)`, orders `0..=order`,
    /// into `out` (state `i`'s coefficient `k` at `out[i * (order + 1) + k]`, so
    /// `y_i(t + h) = sum_k out[i * (order + 1) + k] h^k`), with `d = param_constants(p)`; `work` is
    /// scratch. False when the model has no Taylor coefficients (the default), or above
    /// [`TAYLOR_MAX_ORDER`].
    #[allow(unused_variables)]
    fn taylor(
        t: f64,
        y: &[f64],
        p: &Self::Params,
        d: &Self::ParamConstants,
        order: usize,
        out: &mut [f64],
        work: &mut TaylorWork,
    ) -> bool {
        false
    }
}

/// A generated model with `rhs_lanes` (generated where asked: for batches of members).
pub trait LaneModel: GeneratedModel {
    /// `dy = f(t, y)` in any number type, the parameters `p` (in `INFO.param_names` order) and
    /// the parameter constants `d` ([`GeneratedModel::constant_values`]) in it too: with a lane
    /// type, several members (parameter sets) in one evaluation.
    fn rhs_lanes<T: num_traits::Float>(t: T, y: &[T], p: &[T], d: &[T], dy: &mut [T]);
}
