//! Collection of terms by their state-dependent part, with parameter-only parts kept whole.
//!
//! `m*L^2*s*c*u1*u2/2 + (J1 - J2)*s*c*u1*u2` becomes `(m*L^2/2 + J1 - J2)*s*c*u1*u2`: the state
//! monomial is computed once and the parameter-only coefficient can be hoisted out of a loop.

use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Node, SymbolId, SymbolKind};

impl Arena {
    /// Trigonometric canonical form in the state, with maximal parameter-only subexpressions
    /// kept as they are, and terms collected by state monomial.
    ///
    /// Parameters are the symbols for which `is_parameter` is true.
    pub fn collect_state(
        &mut self,
        e: ExprId,
        is_parameter: impl Fn(SymbolId) -> bool,
    ) -> Result<ExprId, ExprError> {
        // 1. Stand-ins for maximal parameter-only subexpressions.
        let order = self.bottom_up(&[e], |_| false);
        let mut param_only: FxHashMap<ExprId, bool> = FxHashMap::default();
        for &id in &order {
            let p = match self.node(id) {
                Node::Symbol(s) => is_parameter(*s),
                Node::Rational(_) | Node::Float(_) => true,
                n => n.children().iter().all(|c| param_only[c]),
            };
            param_only.insert(id, p);
        }
        let mut stand_in: FxHashMap<ExprId, ExprId> = FxHashMap::default();
        let mut back: FxHashMap<ExprId, ExprId> = FxHashMap::default();
        for &id in &order {
            let atomic = matches!(self.node(id), Node::Symbol(_) | Node::Rational(_) | Node::Float(_));
            if param_only[&id] && !atomic {
                let name = format!("__collect{}", id.index());
                let s = self.declare(&name, SymbolKind::Constant)?;
                let x = self.symbol_expr(s);
                stand_in.insert(id, x);
                back.insert(x, id);
            }
        }
        let stand_in_syms: Vec<SymbolId> = back.keys().filter_map(|x| self.as_symbol(*x)).collect();
        let masked = self.subs(e, &stand_in)?;
        // 2. Canonical form in the state.
        let canonical = self.trig_simplify(masked)?;
        // 3. Group the terms by their state-dependent factors.
        let groups = self.group_terms(canonical, &|free: &[SymbolId]| {
            free.iter().all(|s| is_parameter(*s) || stand_in_syms.contains(s))
        })?;
        let mut out = Vec::with_capacity(groups.len());
        for (key, cs) in groups {
            let c = self.add(&cs)?;
            let c = self.subs(c, &back)?;
            let k = self.subs(key, &back)?;
            out.push(self.mul(&[c, k])?);
        }
        self.add(&out)
    }
}

impl Arena {
    /// The terms of the sum `e` grouped by their state part: each term split into the factors
    /// whose free symbols `is_coefficient` accepts (multiplied into a coefficient) and the rest
    /// (the key); one `(key, coefficients)` per key, in order of first appearance.
    pub(crate) fn group_terms(
        &mut self,
        e: ExprId,
        is_coefficient: &impl Fn(&[SymbolId]) -> bool,
    ) -> Result<Vec<(ExprId, Vec<ExprId>)>, ExprError> {
        let terms: Vec<ExprId> = match self.node(e) {
            Node::Sum(t) => t.to_vec(),
            _ if self.is_zero(e) => Vec::new(),
            _ => vec![e],
        };
        let mut groups: Vec<(ExprId, Vec<ExprId>)> = Vec::new();
        for t in terms {
            let factors: Vec<ExprId> = match self.node(t) {
                Node::Product(f) => f.to_vec(),
                _ => vec![t],
            };
            let (mut coeff, mut state) = (Vec::new(), Vec::new());
            for f in factors {
                if is_coefficient(&self.free_symbols(&[f])) {
                    coeff.push(f);
                } else {
                    state.push(f);
                }
            }
            let key = self.mul(&state)?;
            let c = self.mul(&coeff)?;
            match groups.iter_mut().find(|(k, _)| *k == key) {
                Some((_, cs)) => cs.push(c),
                None => groups.push((key, vec![c])),
            }
        }
        Ok(groups)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn collects_by_state_monomial_and_keeps_parameters_whole() {
        let mut ar = Arena::new();
        let [m, l, a] = ["m", "l", "a"].map(|n| ar.constant(n).unwrap());
        let q = ar.variable("q").unwrap();
        let u = ar.variable("u").unwrap();
        let s = ar.sin(q).unwrap();
        let c = ar.cos(q).unwrap();
        let la = ar.sub(l, a).unwrap();
        let la2 = ar.powi(la, 2).unwrap();
        // m (l - a)^2 s u + a s u + m (s^2 + c^2) => (m (l - a)^2 + a) s u + m
        let t1 = ar.mul(&[m, la2, s, u]).unwrap();
        let t2 = ar.mul(&[a, s, u]).unwrap();
        let s2 = ar.powi(s, 2).unwrap();
        let c2 = ar.powi(c, 2).unwrap();
        let pyth = ar.add(&[s2, c2]).unwrap();
        let t3 = ar.mul(&[m, pyth]).unwrap();
        let e = ar.add(&[t1, t2, t3]).unwrap();
        let params = [m, l, a].map(|x| ar.as_symbol(x).unwrap());
        let r = ar.collect_state(e, |s| params.contains(&s)).unwrap();
        let coeff = ar.mul(&[m, la2]).unwrap();
        let coeff = ar.add(&[coeff, a]).unwrap();
        let su = ar.mul(&[coeff, s, u]).unwrap();
        let expected = ar.add(&[su, m]).unwrap();
        assert_eq!(r, expected, "{}", ar.to_text(r));
    }
}
