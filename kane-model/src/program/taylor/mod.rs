//! Taylor coefficients of the solution: in comes the `rhs` section of a lowered program (the
//! mass-matrix solve included); out goes a [`TaylorProgram`], the same computation as operations
//! with normalised-derivative recurrences ([`crate::runtime::taylor`]), which
//! [`TaylorProgram::coefficients`] runs over any `Float` and the printer spells as Rust. Given
//! `y(t)`, it gives `y_0 .. y_p` with `y(t + h) = sum_k y_k h^k + O(h^(p+1))`: pass `k` computes
//! coefficient `k` of every value, and the states' next coefficient is `y_{k+1} = f_k / (k + 1)`.

mod linear;
mod rewrite;

use num_traits::Float;
use thiserror::Error;

use crate::runtime::taylor as recur;
use crate::runtime::taylor::Inverse;

use super::ir::{Input, Section};

pub use rewrite::build;

/// The largest straight-line pass count ([`TaylorProgram::straight_line_cost`]) written out:
/// past it the loop is as fast (measured: BENCHMARKS.md, "Straight-line or loop") and the code
/// only costs build time.
pub const STRAIGHT_LINE_BUDGET: usize = 20_000;

/// Why a section has no Taylor program.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum TaylorError {
    /// The section reads a speed rate `u'_i`, which only outputs may read.
    #[error(
        "the section reads the speed rate u'_{0}: only a right-hand side (`rhs`) has Taylor coefficients"
    )]
    ReadsRates(usize),
    /// The section's results are not one derivative per state.
    #[error("the section has {results} results for {states} states: only a right-hand side (`rhs`) has Taylor coefficients")]
    NotARightHandSide {
        /// Results of the section.
        results: usize,
        /// States.
        states: usize,
    },
    /// The section reads a state past the last.
    #[error("the section reads state {0}, past the last")]
    UnknownState(usize),
}

/// One Taylor operation; operands are earlier values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TKind {
    /// Time: `t, 1, 0, ...`.
    Time,
    /// State `i`.
    State(u32),
    /// A constant.
    Const(f64),
    /// Section input `k` (a parameter or parameter constant): constant.
    Input(u32),
    /// `a + b`.
    Add(u32, u32),
    /// `a - b`.
    Sub(u32, u32),
    /// `-a`.
    Neg(u32),
    /// `a b`.
    Mul(u32, u32),
    /// `a^2`.
    Sqr(u32),
    /// `a s`, `s` constant.
    Scale(u32, u32),
    /// `a / b`.
    Div(u32, u32),
    /// `a / s`, `s` constant.
    DivConst(u32, u32),
    /// `sqrt(a)`.
    Sqrt(u32),
    /// `exp(a)`.
    Exp(u32),
    /// `ln(a)`.
    Ln(u32),
    /// `sin(a)`, with the value of its partner `cos(a)`.
    Sin(u32, u32),
    /// `cos(a)`, with the value of its partner `sin(a)`.
    Cos(u32, u32),
    /// `sinh(a)`, with its partner `cosh(a)`.
    Sinh(u32, u32),
    /// `cosh(a)`, with its partner `sinh(a)`.
    Cosh(u32, u32),
    /// `f(a)` with `f(a)' = a' / q` (atan, asin, acos).
    Integral(Inverse, u32, u32),
    /// `atan2(y, x)` with `r = x^2 + y^2`.
    Atan2(u32, u32, u32),
    /// `|a|`.
    Abs(u32),
    /// `sign(a)`.
    Sign(u32),
}

impl TKind {
    /// The values the operation reads (a `sin`/`cos` partner is not read).
    pub fn operands(self) -> Vec<u32> {
        let mut out = Vec::new();
        self.map_operands(|x| {
            out.push(x);
            x
        });
        out
    }

    /// The operation with each operand `x` replaced by `f(x)`.
    pub fn map_operands(self, mut f: impl FnMut(u32) -> u32) -> TKind {
        use TKind as K;
        match self {
            K::Time | K::State(_) | K::Const(_) | K::Input(_) => self,
            K::Add(a, b) => K::Add(f(a), f(b)),
            K::Sub(a, b) => K::Sub(f(a), f(b)),
            K::Neg(a) => K::Neg(f(a)),
            K::Mul(a, b) => K::Mul(f(a), f(b)),
            K::Sqr(a) => K::Sqr(f(a)),
            K::Scale(a, s) => K::Scale(f(a), f(s)),
            K::Div(a, b) => K::Div(f(a), f(b)),
            K::DivConst(a, s) => K::DivConst(f(a), f(s)),
            K::Sqrt(a) => K::Sqrt(f(a)),
            K::Exp(a) => K::Exp(f(a)),
            K::Ln(a) => K::Ln(f(a)),
            K::Sin(a, p) => K::Sin(f(a), p),
            K::Cos(a, p) => K::Cos(f(a), p),
            K::Sinh(a, p) => K::Sinh(f(a), p),
            K::Cosh(a, p) => K::Cosh(f(a), p),
            K::Integral(g, a, q) => K::Integral(g, f(a), f(q)),
            K::Atan2(y, x, r) => K::Atan2(f(y), f(x), f(r)),
            K::Abs(a) => K::Abs(f(a)),
            K::Sign(a) => K::Sign(f(a)),
        }
    }
}

/// A Taylor operation and whether its value varies (reads a state or time); constant values
/// are computed at order 0 only.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TaylorOp {
    /// What it computes.
    pub kind: TKind,
    /// It reads a state or time.
    pub series: bool,
}

/// A right-hand side as Taylor operations.
#[derive(Clone, Debug, PartialEq)]
pub struct TaylorProgram {
    /// What [`TKind::Input`] reads (the section's inputs).
    pub inputs: Vec<Input>,
    /// The operations; operation `v` defines value `v`.
    pub ops: Vec<TaylorOp>,
    /// The value of `y_i'` for each state `i`.
    pub results: Vec<usize>,
    /// `(value, result)` for each state the operations read: its coefficient `k` is
    /// `result_{k-1} / k`.
    pub states: Vec<(usize, usize)>,
    /// The constant values (zero past order 0).
    pub constants: Vec<usize>,
    /// The value of time, if read.
    pub time: Option<usize>,
}

impl TaylorProgram {
    /// The Taylor program of a right-hand side with `n_states` states, its linear operations
    /// folded.
    pub fn new(section: &Section, n_states: usize) -> Result<Self, TaylorError> {
        build(section, n_states).map(linear::fold)
    }

    /// The normalised Taylor coefficients of the solution through `(t, y)`, orders `0..=order`,
    /// into `out` (state-major: state `i`'s coefficient `k` at `out[i * (order + 1) + k]`);
    /// `read` gives parameters and parameter constants; `work` is scratch (reused to save
    /// allocating). False (nothing done) for an order above [`crate::runtime::TAYLOR_MAX_ORDER`].
    pub fn coefficients<T: Float>(
        &self,
        t: T,
        y: &[T],
        read: impl Fn(Input) -> T,
        order: usize,
        out: &mut [T],
        work: &mut Vec<recur::Row<T>>,
    ) -> bool {
        self.coefficients_by(t, y, read, order, out, work, |w, order| {
            (1..order).for_each(|k| self.pass(w, k))
        })
    }

    /// [`Self::coefficients`] with the passes `1..order` run by `passes(w, order)` (which must
    /// compute what [`Self::pass`] does for each): order 0 and the states' last coefficient are
    /// computed here.
    #[allow(clippy::too_many_arguments)]
    pub fn coefficients_by<T: Float>(
        &self,
        t: T,
        y: &[T],
        read: impl Fn(Input) -> T,
        order: usize,
        out: &mut [T],
        work: &mut Vec<recur::Row<T>>,
        passes: impl FnOnce(&mut [recur::Row<T>], usize),
    ) -> bool {
        let nv = self.ops.len();
        if !recur::start(work, nv, order, &self.constants, self.time.map(|v| (v, t))) {
            return false;
        }
        let w = &mut work[..nv];
        for (v, op) in self.ops.iter().enumerate() {
            match op.kind {
                TKind::Time => {}
                TKind::State(i) => w[v][0] = y[i as usize],
                TKind::Const(c) => w[v][0] = T::from(c).unwrap_or_else(T::nan),
                TKind::Input(k) => w[v][0] = read(self.inputs[k as usize]),
                kind => apply(kind, w, 0, v),
            }
        }
        passes(w, order);
        recur::finish(w, order, y, &self.results, out);
        true
    }

    /// Pass `k >= 1` on rows whose coefficients below `k` are known: the states' coefficient
    /// `k`, then every varying value's.
    pub fn pass<T: Float>(&self, w: &mut [recur::Row<T>], k: usize) {
        recur::states(w, k, &self.states);
        for (v, op) in self.ops.iter().enumerate() {
            if op.series && !matches!(op.kind, TKind::Time | TKind::State(_)) {
                apply(op.kind, w, k, v);
            }
        }
    }

    /// Terms the straight-line code of `order` writes out: a varying product-like operation
    /// (a Cauchy sum) costs `k` terms at pass `k`, any other varying operation one.
    pub fn straight_line_cost(&self, order: usize) -> usize {
        let series = self.ops.iter().filter(|o| o.series && !matches!(o.kind, TKind::Time | TKind::State(_)));
        let (mut cauchy, mut linear) = (0usize, 0usize);
        for op in series {
            match op.kind {
                TKind::Add(..) | TKind::Sub(..) | TKind::Neg(_) | TKind::Scale(..) | TKind::DivConst(..) => {
                    linear += 1
                }
                _ => cauchy += 1,
            }
        }
        cauchy.saturating_mul(order * (order + 1) / 2).saturating_add(linear.saturating_mul(order))
    }

    /// The orders of `asked` whose straight-line code is within [`STRAIGHT_LINE_BUDGET`],
    /// ascending and without repeats.
    pub fn straight_line_orders(&self, asked: &[usize]) -> Vec<usize> {
        let mut orders: Vec<usize> = asked
            .iter()
            .copied()
            .filter(|&o| {
                (2..=recur::MAX_ORDER).contains(&o) && self.straight_line_cost(o) <= STRAIGHT_LINE_BUDGET
            })
            .collect();
        orders.sort_unstable();
        orders.dedup();
        orders
    }

    /// Arithmetic operations whose value varies (each costs up to `k` products at order `k`).
    pub fn series_op_count(&self) -> usize {
        self.ops.iter().filter(|o| o.series && !matches!(o.kind, TKind::Time | TKind::State(_))).count()
    }
}

/// Coefficient `k` of value `d`, computed by `kind` (an arithmetic operation).
fn apply<T: Float>(kind: TKind, w: &mut [recur::Row<T>], k: usize, d: usize) {
    use recur as r;
    let u = |v: u32| v as usize;
    match kind {
        TKind::Add(a, b) => r::add(w, k, d, u(a), u(b)),
        TKind::Sub(a, b) => r::sub(w, k, d, u(a), u(b)),
        TKind::Neg(a) => r::neg(w, k, d, u(a)),
        TKind::Mul(a, b) => r::mul(w, k, d, u(a), u(b)),
        TKind::Sqr(a) => r::sqr(w, k, d, u(a)),
        TKind::Scale(a, s) => r::scale(w, k, d, u(a), u(s)),
        TKind::Div(a, b) => r::div(w, k, d, u(a), u(b)),
        TKind::DivConst(a, s) => r::div_const(w, k, d, u(a), u(s)),
        TKind::Sqrt(a) => r::sqrt(w, k, d, u(a)),
        TKind::Exp(a) => r::exp(w, k, d, u(a)),
        TKind::Ln(a) => r::ln(w, k, d, u(a)),
        TKind::Sin(a, c) => r::sin(w, k, d, u(a), u(c)),
        TKind::Cos(a, s) => r::cos(w, k, d, u(a), u(s)),
        TKind::Sinh(a, c) => r::sinh(w, k, d, u(a), u(c)),
        TKind::Cosh(a, s) => r::cosh(w, k, d, u(a), u(s)),
        TKind::Integral(f, a, q) => r::integral(w, k, d, u(a), u(q), f),
        TKind::Atan2(y, x, rr) => r::atan2(w, k, d, u(y), u(x), u(rr)),
        TKind::Abs(a) => r::abs(w, k, d, u(a)),
        TKind::Sign(a) => r::sign(w, k, d, u(a)),
        TKind::Time | TKind::State(_) | TKind::Const(_) | TKind::Input(_) => {}
    }
}

#[cfg(test)]
mod tests;
