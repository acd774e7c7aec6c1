//! What the mass-matrix form would cost: operations of the `LDL^T` solve of `M u' = f` on a
//! structural pattern of `M`, from `M` itself or, before `M` is formed, from a tree of links
//! (`M[r][s]` can be nonzero only where one link is the other's ancestor).

use crate::mechanics::{KaneEquations, Model};

use super::tree;

/// Above this many estimated solve operations the order-n form is tried first, and a file's
/// mass matrix is formed only when something asks for it.
pub const ORDER_N_FIRST_ABOVE: usize = 2000;

/// Operations of the `LDL^T` solve on the structural nonzeros `nz` of `M`, with fill-in (a
/// multiplication and an addition per update, a division per pivot, two triangular solves): an
/// estimate, from below, of the mass-matrix form's cost.
pub fn ldlt_operations(mut nz: Vec<Vec<bool>>) -> usize {
    let n = nz.len();
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

impl Model {
    /// The estimate of [`ldlt_operations`] on the pattern of `M` that the model's tree of links
    /// allows, before `M` is formed; `None` when the model is no such tree.
    pub fn tree_solve_estimate(&self, eqs: &KaneEquations) -> Option<usize> {
        let links = tree::frames_of(self, eqs)?;
        let n = eqs.speeds.len();
        let mut nz = vec![vec![false; n]; n];
        for (k, link) in links.iter().enumerate() {
            let mut up = Some(k);
            while let Some(a) = up {
                nz[link.speed][links[a].speed] = true;
                nz[links[a].speed][link.speed] = true;
                up = links[a].parent;
            }
        }
        Some(ldlt_operations(nz))
    }

    /// True when Kane's `M` and `f` of `eqs` may wait until asked for: the model is a tree whose
    /// order-n form is tried first.
    pub fn defers_mass_matrix(&self, eqs: &KaneEquations) -> bool {
        self.tree_solve_estimate(eqs).is_some_and(|e| e > ORDER_N_FIRST_ABOVE)
    }
}
