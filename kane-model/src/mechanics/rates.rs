//! Kane's equations evaluated at a point: in come the equations and the values of their
//! symbols; out go the speed rates `u'` (and, with constraints, the dependent speeds), by
//! numeric factorisations with pivoting: `M u' = f` by LU; with motion constraints, `A_d` by
//! LU with full pivoting (after a check of its conditioning), then the reduced
//! `(C^T M C) u_i' = C^T (f - M g)` with `C = [I; -A_d^-1 A_i]`, `g = [0; -A_d^-1 bias]`.

use nalgebra::{DMatrix, DVector};

use crate::expr::{Arena, ExprError, ExprId, SymbolId};

use super::auxiliary::SolvedLoads;
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
        if let Some(l) = &self.loads {
            return self.rates_with_loads(l, ar, value_of);
        }
        let Some(c) = &self.constraints else {
            let m = matrix(ar, &self.mass_matrix, value_of)?;
            let f = values(ar, &self.forcing, value_of)?;
            let udot = m
                .clone()
                .lu()
                .solve(&DVector::from_column_slice(&f))
                .ok_or(MechanicsError::SingularMassMatrix)?;
            let coordinates = values(ar, &self.kinematics, value_of)?;
            let speeds = udot.iter().copied().collect();
            return Ok(Rates {
                coordinates,
                speeds,
                dependent: Vec::new(),
                mass_matrix: rows_of(&m),
                forcing: f,
                loads: Vec::new(),
            });
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
        let f = DVector::from_vec(values(ar, &self.forcing, &with_ud)?);
        let bias = DVector::from_vec(values(ar, &c.bias, &with_ud)?);
        let cd = lu.solve(&-&ai).ok_or(MechanicsError::SingularConstraints)?;
        let gd = lu.solve(&-bias).ok_or(MechanicsError::SingularConstraints)?;
        let (ni, nd) = (self.speeds.len(), c.dependent.len());
        let mut cm = DMatrix::zeros(ni + nd, ni);
        cm.view_mut((0, 0), (ni, ni)).fill_with_identity();
        cm.view_mut((ni, 0), (nd, ni)).copy_from(&cd);
        let mut g = DVector::zeros(ni + nd);
        g.rows_mut(ni, nd).copy_from(&gd);
        let reduced = cm.transpose() * &m * &cm;
        let forcing = cm.transpose() * (&f - &m * g);
        let udot = reduced.lu().solve(&forcing).ok_or(MechanicsError::SingularMassMatrix)?;
        let coordinates = values(ar, &self.kinematics, &with_ud)?;
        Ok(Rates {
            coordinates,
            speeds: udot.iter().copied().collect(),
            dependent: ud.iter().copied().collect(),
            mass_matrix: rows_of(&m),
            forcing: f.iter().copied().collect(),
            loads: Vec::new(),
        })
    }

    /// The rates and the loads from `[M, -B_s; M_a, -B_a] [u'; T] = [f; f_a]` by LU with
    /// partial pivoting.
    fn rates_with_loads(
        &self,
        l: &SolvedLoads,
        ar: &Arena,
        value_of: &dyn Fn(SymbolId) -> Option<f64>,
    ) -> Result<Rates> {
        let (n, k) = (self.speeds.len(), l.loads.len());
        let m = matrix(ar, &self.mass_matrix, value_of)?;
        let ma = matrix(ar, &l.mass_rows, value_of)?;
        let b = matrix(ar, &l.load_columns, value_of)?;
        let mut e = DMatrix::zeros(n + k, n + k);
        e.view_mut((0, 0), (n, n)).copy_from(&m);
        e.view_mut((n, 0), (k, n)).copy_from(&ma);
        e.view_mut((0, n), (n + k, k)).copy_from(&-b);
        let f = values(ar, &self.forcing, value_of)?;
        let mut rhs = f.clone();
        rhs.extend(values(ar, &l.forcing, value_of)?);
        let x = e.lu().solve(&DVector::from_vec(rhs)).ok_or(MechanicsError::SingularMassMatrix)?;
        Ok(Rates {
            coordinates: values(ar, &self.kinematics, value_of)?,
            speeds: x.rows(0, n).iter().copied().collect(),
            dependent: Vec::new(),
            mass_matrix: rows_of(&m),
            forcing: f,
            loads: x.rows(n, k).iter().copied().collect(),
        })
    }
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
