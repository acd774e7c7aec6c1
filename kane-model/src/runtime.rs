//! What generated model modules implement and describe, so a simulator can drive any of them:
//! in comes nothing; out go the [`GeneratedModel`] trait and the [`ModelInfo`] metadata printed
//! beside each model.

/// One output of a generated model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutputInfo {
    /// Its name in the model.
    pub name: &'static str,
    /// Its unit (empty when none).
    pub unit: &'static str,
    /// What it is: [`crate::spec::OutputKind::label`] (`scalar`, `vector`, `kinetic_energy`, ...).
    pub kind: &'static str,
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
    /// The outputs.
    pub outputs: &'static [OutputInfo],
    /// Coordinates that no equation reads (cyclic): they can be left out of the integrated
    /// state when no output needs them.
    pub cyclic: &'static [usize],
    /// The coordinates the configuration constraints determine (solved for at the start of a
    /// run, see [`crate::assembly`]); empty for a model without such constraints.
    pub dependent_coordinates: &'static [usize],
    /// Arithmetic operations per call of `rhs` and per evaluation of every output.
    pub op_counts: (usize, usize),
    /// The orders whose Taylor coefficients the model computes straight-line (faster than the
    /// loop every other order takes); empty for a model without them.
    pub taylor_straight_line: &'static [usize],
}

impl ModelInfo {
    /// The index of a state by name (case-insensitive).
    pub fn state(&self, name: &str) -> Option<usize> {
        self.state_names.iter().position(|s| s.eq_ignore_ascii_case(name))
    }

    /// The index of an output by name (case-insensitive).
    pub fn output(&self, name: &str) -> Option<usize> {
        self.outputs.iter().position(|o| o.name.eq_ignore_ascii_case(name))
    }
}

/// Scratch rows for Taylor coefficients ([`GeneratedModel::taylor`]), reused between calls.
pub type TaylorWork = Vec<crate::codegen::taylor::recur::Row<f64>>;

/// The highest order [`GeneratedModel::taylor`] expands to.
pub const TAYLOR_MAX_ORDER: usize = crate::codegen::taylor::recur::MAX_ORDER;

/// The orders a model asks straight-line Taylor code for by default (see
/// [`ModelInfo::taylor_straight_line`] for the orders a model has).
pub const TAYLOR_UNROLLED_ORDERS: &[usize] = crate::codegen::taylor::UNROLLED_ORDERS;

/// A model compiled from its equations by [`crate::codegen`].
pub trait GeneratedModel {
    /// Parameter values (defaults from the model's INPUT).
    type Params: Clone + Default + std::fmt::Debug;
    /// Quantities of the parameters alone, computed once per parameter set.
    type Derived: Clone + std::fmt::Debug;
    /// The model's metadata.
    const INFO: ModelInfo;
    /// The initial state from INPUT, in radians (NaN where INPUT gives none).
    fn initial_state() -> Vec<f64>;
    /// Sets a parameter by name (case-insensitive); false if there is none.
    fn set_param(p: &mut Self::Params, name: &str, value: f64) -> bool;
    /// A parameter's value by name (case-insensitive).
    fn param(p: &Self::Params, name: &str) -> Option<f64>;
    /// The parameter-only quantities of `rhs`.
    fn derive(p: &Self::Params) -> Self::Derived;
    /// `dy = f(t, y)` with `d = derive(p)`: the fast path for integration.
    fn rhs_derived(t: f64, y: &[f64], p: &Self::Params, d: &Self::Derived, dy: &mut [f64]);
    /// `dy = f(t, y)`.
    fn rhs(t: f64, y: &[f64], p: &Self::Params, dy: &mut [f64]) {
        Self::rhs_derived(t, y, p, &Self::derive(p), dy)
    }
    /// Output `k` at `(t, y)` into `out` (its columns); `rates` are `u'` when the output needs
    /// them (see [`OutputInfo::needs_rates`]), else ignored.
    fn output(k: usize, t: f64, y: &[f64], rates: &[f64], p: &Self::Params, out: &mut [f64]);
    /// The derived quantities as numbers, in the order `derive` computes them (and
    /// [`LaneModel::rhs_lanes`] reads them).
    fn derived_values(d: &Self::Derived) -> &[f64];
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
    /// `y_i(t + h) = sum_k out[i * (order + 1) + k] h^k`), with `d = derive(p)`; `work` is
    /// scratch. False when the model has no Taylor coefficients (the default), or above
    /// [`TAYLOR_MAX_ORDER`].
    #[allow(unused_variables)]
    fn taylor(
        t: f64,
        y: &[f64],
        p: &Self::Params,
        d: &Self::Derived,
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
    /// the derived quantities `d` ([`GeneratedModel::derived_values`]) in it too: with a lane
    /// type, several members (parameter sets) in one evaluation.
    fn rhs_lanes<T: num_traits::Float>(t: T, y: &[T], p: &[T], d: &[T], dy: &mut [T]);
}

/// A unit quaternion (scalar first, non-negative) from direction cosines `r` (row by row, an
/// orthonormal matrix), by Shepperd's method: the largest of the four squares is found first,
/// so no square root of a small difference is taken.
pub fn quaternion_from_dcm<T: num_traits::Float>(r: &[T; 9]) -> [T; 4] {
    let one = T::one();
    let quarter = T::from(0.25).unwrap_or_else(T::nan);
    let half = T::from(0.5).unwrap_or_else(T::nan);
    let trace = r[0] + r[4] + r[8];
    let diag = [trace, r[0], r[4], r[8]];
    let k = (0..4).fold(0, |best, i| if diag[i] > diag[best] { i } else { best });
    let s = (one + diag[k] + diag[k] - trace).sqrt() * half; // |q_k|
    let f = quarter / s;
    let (a, b, c) = (r[7] - r[5], r[2] - r[6], r[3] - r[1]);
    let (d, e, g) = (r[1] + r[3], r[2] + r[6], r[5] + r[7]);
    let q = match k {
        0 => [s, a * f, b * f, c * f],
        1 => [a * f, s, d * f, e * f],
        2 => [b * f, d * f, s, g * f],
        _ => [c * f, e * f, g * f, s],
    };
    if q[0] < T::zero() {
        q.map(|x| -x)
    } else {
        q
    }
}

#[cfg(test)]
mod tests {
    use super::quaternion_from_dcm;

    #[test]
    fn quaternion_round_trips_through_its_dcm() {
        for q in
            [[0.9f64, 0.1, -0.3, 0.2], [0.05, 0.7, 0.1, -0.6], [0.0, 0.0, 0.0, 1.0], [0.1, -0.2, 0.9, 0.3]]
        {
            let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
            let [e0, e1, e2, e3] = q.map(|x| x / n);
            // Body-to-space rotation matrix of the quaternion.
            let r = [
                e0 * e0 + e1 * e1 - e2 * e2 - e3 * e3,
                2.0 * (e1 * e2 - e0 * e3),
                2.0 * (e1 * e3 + e0 * e2),
                2.0 * (e1 * e2 + e0 * e3),
                e0 * e0 - e1 * e1 + e2 * e2 - e3 * e3,
                2.0 * (e2 * e3 - e0 * e1),
                2.0 * (e1 * e3 - e0 * e2),
                2.0 * (e2 * e3 + e0 * e1),
                e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3,
            ];
            let got = quaternion_from_dcm(&r);
            let sign = if e0 < 0.0 { -1.0 } else { 1.0 };
            for (g, w) in got.iter().zip([e0, e1, e2, e3]) {
                assert!((g - sign * w).abs() < 1e-12, "{got:?} vs {q:?}");
            }
        }
    }
}
