//! Kane's equations evaluated at a point: in come the equations and the values of their
//! symbols; out go the speed rates `u'` (and, with constraints, the dependent speeds), by
//! numeric factorisations with pivoting: `M u' = f` by LU; with motion constraints, `A_d` by
//! LU with full pivoting (after a check of its conditioning), then the reduced
//! `(C^T M C) u_i' = C^T (f - M g)` with `C = [I; -A_d^-1 A_i]`, `g = [0; -A_d^-1 bias]`.

use nalgebra::{DMatrix, DVector};

use crate::expr::{Arena, ExprError, ExprId, SymbolId};

use super::error::{MechanicsError, Result};
use super::kane::KaneEquations;

/// Below this reciprocal condition number `A_d` counts as losing rank.
pub const CONSTRAINT_RCOND_LIMIT: f64 = 1e-12;

/// The rates of Kane's equations at one point.
#[derive(Clone, Debug, PartialEq)]
pub struct Rates {
    /// `q'`, one per coordinate.
    pub coordinates: Vec<f64>,
    /// `u'` of the independent speeds.
    pub speeds: Vec<f64>,
    /// The dependent speeds' values (empty without constraints).
    pub dependent: Vec<f64>,
    /// `M` evaluated (over all speeds with constraints), row by row.
    pub mass_matrix: Vec<Vec<f64>>,
    /// `f` evaluated.
    pub forcing: Vec<f64>,
    /// The loads solved for (KANE(T1, ...)), in KANE's order (empty without them).
    pub loads: Vec<f64>,
}

fn rows_of(m: &DMatrix<f64>) -> Vec<Vec<f64>> {
    m.row_iter().map(|r| r.iter().copied().collect()).collect()
}

impl KaneEquations {
    /// `q'`, `u'` and the dependent speeds where `value_of` gives every other symbol's value;
    /// an error names a missing value, a singular mass matrix or constraints losing rank.
    pub fn rates_at(&self, ar: &Arena, value_of: &dyn Fn(SymbolId) -> Option<f64>) -> Result<Rates> {
        let Some(c) = &self.constraints else {
            let m = matrix(ar, &self.mass_matrix, value_of)?;
            let f = values(ar, &self.forcing, value_of)?;
            let n = m.nrows();
            let reduction =
                Reduction { c: DMatrix::identity(n, n), g: DVector::zeros(n), dependent: Vec::new() };
            return self.reduced_rates(ar, value_of, m, f, reduction);
        };
        let ad = matrix(ar, &c.a_dependent, value_of)?;
        check_rank(&ad, self, ar, value_of)?;
        let lu = ad.full_piv_lu();
        let ai = matrix(ar, &c.a_independent, value_of)?;
        let ui = self
            .speeds
            .iter()
            .map(|s| value_of(*s).ok_or_else(|| ExprError::MissingBinding(ar.symbol_info(*s).name.clone())))
            .collect::<std::result::Result<Vec<f64>, _>>()?;
        let ui = DVector::from_vec(ui);
        let b = DVector::from_vec(values(ar, &c.b, value_of)?);
        let ud = lu.solve(&-(&ai * &ui + b)).ok_or(MechanicsError::SingularConstraints)?;
        let with_ud = |s: SymbolId| match c.dependent.iter().position(|d| *d == s) {
            Some(k) => Some(ud[k]),
            None => value_of(s),
        };
        let m = matrix(ar, &self.mass_matrix, &with_ud)?;
        let f = values(ar, &self.forcing, &with_ud)?;
        let bias = DVector::from_vec(values(ar, &c.bias, &with_ud)?);
        let cd = lu.solve(&-&ai).ok_or(MechanicsError::SingularConstraints)?;
        let gd = lu.solve(&-bias).ok_or(MechanicsError::SingularConstraints)?;
        let (ni, nd) = (self.speeds.len(), c.dependent.len());
        let mut cm = DMatrix::zeros(ni + nd, ni);
        cm.view_mut((0, 0), (ni, ni)).fill_with_identity();
        cm.view_mut((ni, 0), (nd, ni)).copy_from(&cd);
        let mut g = DVector::zeros(ni + nd);
        g.rows_mut(ni, nd).copy_from(&gd);
        let reduction = Reduction { c: cm, g, dependent: ud.iter().copied().collect() };
        self.reduced_rates(ar, &with_ud, m, f, reduction)
    }

    /// The rates from `(C^T M C) u_i' = C^T (f - M g)`; with loads solved for, from
    /// `[C^T M C, -C^T B_s; M_a C, -B_a] [u_i'; T] = [C^T (f - M g); f_a - M_a g]`.
    fn reduced_rates(
        &self,
        ar: &Arena,
        value_of: &dyn Fn(SymbolId) -> Option<f64>,
        m: DMatrix<f64>,
        f: Vec<f64>,
        r: Reduction,
    ) -> Result<Rates> {
        let fv = DVector::from_column_slice(&f);
        let reduced = r.c.transpose() * &m * &r.c;
        let forcing = r.c.transpose() * (&fv - &m * &r.g);
        let (speeds, loads) = match &self.loads {
            None => {
                let udot = reduced.lu().solve(&forcing).ok_or(MechanicsError::SingularMassMatrix)?;
                (udot.iter().copied().collect(), Vec::new())
            }
            Some(l) => {
                let (n, ni, k) = (m.nrows(), r.c.ncols(), l.loads.len());
                let ma = matrix(ar, &l.mass_rows, value_of)?;
                let b = matrix(ar, &l.load_columns, value_of)?;
                let fa = DVector::from_vec(values(ar, &l.forcing, value_of)?);
                let mut e = DMatrix::zeros(ni + k, ni + k);
                e.view_mut((0, 0), (ni, ni)).copy_from(&reduced);
                e.view_mut((0, ni), (ni, k)).copy_from(&-(r.c.transpose() * b.rows(0, n)));
                e.view_mut((ni, 0), (k, ni)).copy_from(&(&ma * &r.c));
                e.view_mut((ni, ni), (k, k)).copy_from(&-b.rows(n, k));
                let mut rhs = DVector::zeros(ni + k);
                rhs.rows_mut(0, ni).copy_from(&forcing);
                rhs.rows_mut(ni, k).copy_from(&(fa - &ma * &r.g));
                let x = e.lu().solve(&rhs).ok_or(MechanicsError::SingularMassMatrix)?;
                (x.rows(0, ni).iter().copied().collect(), x.rows(ni, k).iter().copied().collect())
            }
        };
        Ok(Rates {
            coordinates: values(ar, &self.kinematics, value_of)?,
            speeds,
            dependent: r.dependent,
            mass_matrix: rows_of(&m),
            forcing: f,
            loads,
        })
    }
}

/// `u' = C u_i' + g` (over all speeds) and the dependent speeds' values.
struct Reduction {
    c: DMatrix<f64>,
    g: DVector<f64>,
    dependent: Vec<f64>,
}

/// An error when `A_d`'s reciprocal condition number is below [`CONSTRAINT_RCOND_LIMIT`],
/// naming the configuration.
/// The smallest over the largest singular value of the `size x size` matrix `entries` (row
/// or column major alike), 0 for a zero matrix, NaN when an entry is not finite.
pub fn reciprocal_condition(size: usize, entries: &[f64]) -> f64 {
    if entries.iter().any(|v| !v.is_finite()) {
        return f64::NAN;
    }
    let sv = DMatrix::from_column_slice(size, size, entries).singular_values();
    let (hi, lo) = (sv.max(), sv.min());
    if hi > 0.0 {
        lo / hi
    } else {
        0.0
    }
}

fn check_rank(
    ad: &DMatrix<f64>,
    eqs: &KaneEquations,
    ar: &Arena,
    value_of: &dyn Fn(SymbolId) -> Option<f64>,
) -> Result<()> {
    let rcond = reciprocal_condition(ad.nrows(), ad.as_slice());
    if rcond >= CONSTRAINT_RCOND_LIMIT && rcond.is_finite() {
        return Ok(());
    }
    let at = eqs
        .coordinates
        .iter()
        .map(|q| {
            format!("{} = {}", ar.symbol_info(*q).name, value_of(*q).map_or("?".into(), |v| format!("{v}")))
        })
        .collect::<Vec<_>>()
        .join(", ");
    Err(MechanicsError::ConstraintRankLoss { rcond, at })
}

fn values(ar: &Arena, roots: &[ExprId], value_of: &dyn Fn(SymbolId) -> Option<f64>) -> Result<Vec<f64>> {
    Ok(ar.eval(roots, value_of)?)
}

fn matrix(
    ar: &Arena,
    rows: &[Vec<ExprId>],
    value_of: &dyn Fn(SymbolId) -> Option<f64>,
) -> Result<DMatrix<f64>> {
    let cols = rows.first().map_or(0, Vec::len);
    let flat: Vec<ExprId> = rows.iter().flatten().copied().collect();
    Ok(DMatrix::from_row_slice(rows.len(), cols, &values(ar, &flat, value_of)?))
}
