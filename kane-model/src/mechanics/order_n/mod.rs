//! An order-n form of Kane's equations for tree-structured models: the speed rates `u'` as
//! explicit expressions from the articulated-body algorithm (Featherstone), linear in the number
//! of links, where the mass-matrix form `M u' = f` costs O(n^3) to solve.
//!
//! In: a [`Model`] and its [`KaneEquations`]. Out: `u'` in the speeds' order, or `None` when the
//! model is not a tree of simple rotations whose speeds are the joint rates (constraints,
//! other orientations, speeds that are not `q'`, points or loads fixed in no link), or when the
//! result does not satisfy Kane's equations numerically (their virtual power at random states:
//! no `M` is formed).

mod aba;
mod check;
mod estimate;
mod parts;
mod spatial;
mod tree;

use crate::expr::ExprId;

pub use estimate::{ldlt_operations, ORDER_N_FIRST_ABOVE};

use super::error::Result;
use super::kane::KaneEquations;
use super::model::Model;

impl Model {
    /// The speed rates `u'` of an order-n (articulated-body) form of `eqs`, when the model is a
    /// tree of simple rotations with `q' = u` and the form satisfies Kane's equations.
    pub fn order_n_rates(&mut self, eqs: &KaneEquations) -> Result<Option<Vec<ExprId>>> {
        let Some(links) = tree::links(self, eqs)? else { return Ok(None) };
        let states: Vec<_> = eqs.coordinates.iter().chain(&eqs.speeds).copied().collect();
        let Some(parts) = parts::parts(self, &links, &states)? else { return Ok(None) };
        let rates = aba::rates(self, &links, &parts, &eqs.speeds)?;
        Ok(check::agrees(self, eqs, &rates)?.then_some(rates))
    }

    /// True when the model's frames fit the order-n form (simple rotations by coordinates whose
    /// rates are speeds, no constraints); reads the model only.
    pub fn order_n_candidate(&self, eqs: &KaneEquations) -> bool {
        tree::is_candidate(self, eqs)
    }
}
