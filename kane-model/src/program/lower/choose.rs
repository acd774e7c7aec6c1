//! The choice between the mass-matrix and the order-n form: in comes a spec; out goes the
//! lowered form with fewer `rhs` operations. The mass-matrix form is derived first (so its code
//! is what it was before the order-n form existed) unless an estimate of its solve alone already
//! exceeds a cap, where it is derived only if the order-n form does not beat that estimate.

use crate::mechanics::{ldlt_operations, ORDER_N_FIRST_ABOVE};
use crate::spec::ModelSpec;

use super::super::LowerError;
use super::{mass_matrix, order_n, Lowered};

/// The cheaper of the two forms of `spec`.
pub fn lower(spec: &mut ModelSpec) -> Result<Lowered, LowerError> {
    if !spec.model.order_n_candidate(&spec.equations) {
        return mass_matrix(spec);
    }
    let estimate = solve_estimate(spec);
    if estimate <= ORDER_N_FIRST_ABOVE {
        let mm = mass_matrix(spec);
        let on = order_n(spec)?;
        return pick(mm, on);
    }
    let on = order_n(spec)?;
    if let Some(l) = on.as_ref().filter(|l| l.program.rhs.op_count() < estimate) {
        return Ok(l.clone());
    }
    pick(mass_matrix(spec), on)
}

/// The order-n form when it has fewer `rhs` operations or the mass-matrix form failed.
fn pick(mm: Result<Lowered, LowerError>, on: Option<Lowered>) -> Result<Lowered, LowerError> {
    match (mm, on) {
        (Ok(m), Some(o)) if o.program.rhs.op_count() < m.program.rhs.op_count() => Ok(o),
        (Ok(m), _) => Ok(m),
        (Err(_), Some(o)) => Ok(o),
        (Err(e), None) => Err(e),
    }
}

/// Operations of `M u' = f`'s solve alone, on the structural nonzeros of `M` or, while `M` is
/// not formed, on those the model's tree allows.
fn solve_estimate(spec: &ModelSpec) -> usize {
    let eqs = &spec.equations;
    if !eqs.formed {
        return spec.model.tree_solve_estimate(eqs).unwrap_or(usize::MAX);
    }
    let ar = &spec.model.ar;
    ldlt_operations(eqs.mass_matrix.iter().map(|row| row.iter().map(|x| !ar.is_zero(*x)).collect()).collect())
}
