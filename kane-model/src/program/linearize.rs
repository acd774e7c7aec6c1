//! A lowered program linearised about a point: in come the program, its parameters' values, a
//! time and state, and which parameters are inputs; out go `A = d(y')/dy` and
//! `B = d(y')/d(inputs)`, one forward-mode dual-number pass through the program per column
//! (the parameter-only `param_constants` section included for inputs, and the numeric
//! constraint solve with it): exact to rounding, with no symbolic differentiation and no finite
//! differences.

use crate::runtime::dual::Dual;

use super::ir::{Input, Program};

/// The state and input matrices at one point, and the rates there.
#[derive(Clone, Debug, PartialEq)]
pub struct Linearization {
    /// `A[i][j] = d(y'_i)/d(y_j)`.
    pub a: Vec<Vec<f64>>,
    /// `B[i][k] = d(y'_i)/d(p_inputs[k])`.
    pub b: Vec<Vec<f64>>,
    /// `y'` at the point.
    pub rates: Vec<f64>,
}

/// Which value carries the derivative part.
#[derive(Clone, Copy)]
enum Seed {
    State(usize),
    Param(usize),
}

/// The linearisation of `program` at time `t` and state `y` with parameters `params`; `inputs`
/// are the positions (in `params`) of the parameters taken as inputs.
pub fn linearize(program: &Program, params: &[f64], t: f64, y: &[f64], inputs: &[usize]) -> Linearization {
    let a_columns: Vec<Column> =
        (0..y.len()).map(|j| column(program, params, t, y, Seed::State(j))).collect();
    let b_columns: Vec<Column> =
        inputs.iter().map(|k| column(program, params, t, y, Seed::Param(*k))).collect();
    let rows = |cols: &[Column]| -> Vec<Vec<f64>> {
        (0..y.len()).map(|i| cols.iter().map(|c| c.1[i]).collect()).collect()
    };
    let rates = a_columns.first().map(|c| c.0.clone()).unwrap_or_default();
    Linearization { a: rows(&a_columns), b: rows(&b_columns), rates }
}

/// `y'` and its derivative in one direction.
type Column = (Vec<f64>, Vec<f64>);

/// `y'` and its derivative along `seed`.
fn column(program: &Program, params: &[f64], t: f64, y: &[f64], seed: Seed) -> Column {
    let param = |k: usize| match seed {
        Seed::Param(p) if p == k => Dual::variable(params[k]),
        _ => Dual::constant(params[k]),
    };
    let mut constants = vec![Dual::constant(0.0); program.param_constants.results.len()];
    program
        .param_constants
        .eval(|i| if let Input::Param(k) = i { param(k) } else { Dual::constant(f64::NAN) }, &mut constants);
    let state = |k: usize| match seed {
        Seed::State(s) if s == k => Dual::variable(y[k]),
        _ => Dual::constant(y[k]),
    };
    let read = |i: Input| match i {
        Input::Time => Dual::constant(t),
        Input::State(k) => state(k),
        Input::Param(k) => param(k),
        Input::ParamConstant(k) => constants[k],
        Input::Rate(_) | Input::Slot(_) => Dual::constant(f64::NAN),
    };
    let mut out = vec![Dual::constant(0.0); program.rhs.results.len()];
    program.rhs.eval(read, &mut out);
    (out.iter().map(|d| d.re).collect(), out.iter().map(|d| d.eps).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::program::ir::{Op, SectionBuilder};

    /// `q' = u`, `u' = -k sin q + p`: A = [[0, 1], [-k cos q, 0]], B (input p) = [[0], [1]].
    #[test]
    fn a_pendulum_linearises_exactly() {
        let mut b = SectionBuilder::default();
        let (q, u, k, p) = (
            b.input(Input::State(0)),
            b.input(Input::State(1)),
            b.input(Input::Param(0)),
            b.input(Input::Param(1)),
        );
        let s = b.push(Op::Func(crate::expr::Func::Sin, q));
        let ks = b.mul(k, s);
        let n = b.push(Op::Neg(ks));
        let udot = b.add(n, p);
        let rhs = b.finish(vec![u, udot]);
        let program = Program {
            param_constants: SectionBuilder::default().finish(vec![]),
            rhs,
            outputs: vec![],
            cyclic: vec![],
            n_coordinates: 1,
        };
        let l = linearize(&program, &[3.0, 0.5], 0.0, &[0.4, 0.2], &[1]);
        assert_eq!(l.a, vec![vec![0.0, 1.0], vec![-3.0 * 0.4f64.cos(), 0.0]]);
        assert_eq!(l.b, vec![vec![0.0], vec![1.0]]);
        assert_eq!(l.rates, vec![0.2, -3.0 * 0.4f64.sin() + 0.5]);
    }
}
