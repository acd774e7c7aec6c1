//! The choice between the mass-matrix and the order-n form: in comes a spec; out goes the
//! lowered form with fewer `rhs` operations. The mass-matrix form is derived first (so its code
//! is what it was before the order-n form existed) unless an estimate of its solve alone already
//! exceeds a cap, where it is derived only if the order-n form does not beat that estimate.

use crate::spec::ModelSpec;

use super::super::CodegenError;
use super::{mass_matrix, order_n, Lowered};

/// Above this many estimated solve operations the order-n form is tried first.
const CAP: usize = 2000;

/// The cheaper of the two forms of `spec`.
pub fn lower(spec: &mut ModelSpec) -> Result<Lowered, CodegenError> {
    if !spec.model.order_n_candidate(&spec.equations) {
        return mass_matrix(spec);
    }
    let estimate = solve_estimate(spec);
    if estimate <= CAP {
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
fn pick(mm: Result<Lowered, CodegenError>, on: Option<Lowered>) -> Result<Lowered, CodegenError> {
    match (mm, on) {
        (Ok(m), Some(o)) if o.program.rhs.op_count() < m.program.rhs.op_count() => Ok(o),
        (Ok(m), _) => Ok(m),
        (Err(_), Some(o)) => Ok(o),
        (Err(e), None) => Err(e),
    }
}

/// Operations of `M u' = f`'s `LDL^T` solve alone on the structural nonzeros of `M`, with fill-in
/// (a multiplication and an addition per update, a division per pivot, two triangular solves):
/// an estimate, from below, of the mass-matrix form's cost.
fn solve_estimate(spec: &ModelSpec) -> usize {
    let m = &spec.equations.mass_matrix;
    let ar = &spec.model.ar;
    let n = m.len();
    let mut nz: Vec<Vec<bool>> = (0..n).map(|i| (0..n).map(|j| !ar.is_zero(m[i][j])).collect()).collect();
    let mut ops = 0;
    for k in 0..n {
        let below: Vec<usize> = (k + 1..n).filter(|i| nz[*i][k]).collect();
        ops += 1 + below.len() + below.len() * (below.len() + 1);
        for &i in &below {
            for &j in &below {
                nz[i][j] = true;
            }
        }
        ops += 4 * below.len();
    }
    ops
}
