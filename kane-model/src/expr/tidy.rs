//! Simplification for reading: terms collected by state monomial, parameters in the user's
//! names, and whichever of the two trigonometric canonical forms reads shorter.
//!
//! `(J1*cos(q)^2 + J2*sin(q)^2 - J2)*u1'` becomes `(J1 - J2)*cos(q)^2*u1'`: expanded, reduced
//! with `sin^2 + cos^2 = 1`, grouped by the state-dependent factors, each group's coefficient
//! rewritten in the [`Abbreviations`].

use std::cmp::Reverse;

use super::abbrev::Abbreviations;
use super::arena::Arena;
use super::error::ExprError;
use super::expand::TrigBasis;
use super::node::{ExprId, Node, SymbolId, SymbolKind};
use super::number::Number;

/// One term of a [`Collected`] expression: `(+/-) scale*(coefficient) * factors`, or, for the
/// terms sharing a monomial in the variables, `(+/-) (inner terms) * factors`.
#[derive(Clone, Debug, PartialEq)]
pub struct CollectedTerm {
    /// True when the term is subtracted.
    pub negative: bool,
    /// A whole number common to the coefficient's summands, taken out of them.
    pub scale: Option<ExprId>,
    /// The coefficient's summands, positive ones first, each `(subtracted, magnitude)`; empty
    /// for a coefficient of 1 (and for a term with inner terms).
    pub coefficient: Vec<(bool, ExprId)>,
    /// Terms (parameters times functions of the coordinates) multiplying `factors` together.
    pub inner: Vec<CollectedTerm>,
    /// The state-dependent factors, functions first, then variables by derivative order; empty
    /// for a parameter-only term.
    pub factors: Vec<ExprId>,
    /// The term as one expression.
    pub value: ExprId,
}

/// An expression as a sum of terms collected by state monomial, in reading order: terms with
/// the highest time derivatives first, parameter-only terms last.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Collected {
    /// The terms; none for zero.
    pub terms: Vec<CollectedTerm>,
}

impl Collected {
    /// True for zero.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The sum of the terms.
    pub fn to_expr(&self, ar: &mut Arena) -> Result<ExprId, ExprError> {
        let values: Vec<ExprId> = self.terms.iter().map(|t| t.value).collect();
        ar.add(&values)
    }

    /// `e` as one term, not simplified (zero for the number 0).
    pub fn whole(ar: &Arena, e: ExprId) -> Collected {
        if ar.is_zero(e) {
            return Collected::default();
        }
        let term = CollectedTerm {
            negative: false,
            scale: None,
            coefficient: vec![(false, e)],
            inner: Vec::new(),
            factors: Vec::new(),
            value: e,
        };
        Collected { terms: vec![term] }
    }

    fn size(&self, ar: &Arena) -> usize {
        self.terms.iter().map(|t| ar.graph_size(t.value)).sum()
    }
}

impl Arena {
    /// `e` simplified for reading: trigonometric identities applied, terms collected by state
    /// monomial (the factors holding a symbol for which `is_parameter` is false), coefficients
    /// in the names of `names`. Of the forms keeping `cos^2` or `sin^2`, the one with fewer
    /// terms (then fewer nodes) is returned.
    pub fn tidy(
        &mut self,
        e: ExprId,
        is_parameter: impl Fn(SymbolId) -> bool,
        names: &Abbreviations,
    ) -> Result<Collected, ExprError> {
        let mut best: Option<Collected> = None;
        for basis in [TrigBasis::Cos, TrigBasis::Sin] {
            let c = self.tidy_in(e, basis, &is_parameter, names)?;
            let better = match &best {
                None => true,
                Some(b) => (c.terms.len(), c.size(self)) < (b.terms.len(), b.size(self)),
            };
            if better {
                best = Some(c);
            }
        }
        Ok(best.unwrap_or_default())
    }

    fn tidy_in(
        &mut self,
        e: ExprId,
        basis: TrigBasis,
        is_parameter: &impl Fn(SymbolId) -> bool,
        names: &Abbreviations,
    ) -> Result<Collected, ExprError> {
        let canonical = self.trig_canonical_many(&[e], basis)?[0];
        let groups =
            self.group_terms(canonical, &|free: &[SymbolId]| free.iter().copied().all(is_parameter))?;
        let mut pairs = Vec::with_capacity(groups.len());
        for (key, cs) in groups {
            let c = self.add(&cs)?;
            let c = if names.is_empty() { c } else { names.rewrite(self, c)? };
            if !self.is_zero(c) {
                pairs.push((c, key));
            }
        }
        let mut terms = self.nest_by_variables(pairs)?;
        let one = self.one();
        let rank = |ar: &Arena, t: &CollectedTerm| {
            let key = t.factors.iter().map(|f| factor_rank(ar, *f).0).max().unwrap_or(0);
            (Reverse(key), t.factors.is_empty(), t.factors.first().copied().unwrap_or(one))
        };
        terms.sort_by_key(|t| rank(self, t));
        Ok(Collected { terms })
    }

    /// Terms `c * key` grouped by the variables in `key`: `(a + b*cos(q)^2)*u1'` for
    /// `a*u1' + b*cos(q)^2*u1'`.
    fn nest_by_variables(&mut self, pairs: Vec<(ExprId, ExprId)>) -> Result<Vec<CollectedTerm>, ExprError> {
        let mut groups: Vec<(ExprId, Vec<(ExprId, ExprId)>)> = Vec::new();
        for (c, key) in pairs {
            let factors: Vec<ExprId> = match self.node(key) {
                Node::Product(f) => f.to_vec(),
                _ => vec![key],
            };
            let (vars, funcs): (Vec<ExprId>, Vec<ExprId>) =
                factors.into_iter().partition(|f| factor_rank(self, *f).0 > 0);
            let (vars, funcs) = (self.mul(&vars)?, self.mul(&funcs)?);
            match groups.iter_mut().find(|(v, _)| *v == vars) {
                Some((_, g)) => g.push((c, funcs)),
                None => groups.push((vars, vec![(c, funcs)])),
            }
        }
        let mut terms = Vec::with_capacity(groups.len());
        for (vars, group) in groups {
            if let [(c, funcs)] = group.as_slice() {
                let key = self.mul(&[*funcs, vars])?;
                terms.push(self.collected_term(*c, key)?);
                continue;
            }
            let mut inner = Vec::with_capacity(group.len());
            for (c, funcs) in group {
                inner.push(self.collected_term(c, funcs)?);
            }
            inner.sort_by_key(|t| (!t.factors.is_empty(), t.factors.first().copied()));
            let negatives = inner.iter().filter(|t| t.negative).count();
            let negative = 2 * negatives > inner.len() || (2 * negatives == inner.len() && inner[0].negative);
            if negative {
                inner.iter_mut().for_each(flip);
            }
            let values: Vec<ExprId> = inner.iter().map(|t| t.value).collect();
            let sum = self.add(&values)?;
            let value = self.mul(&[sum, vars])?;
            let mut factors = self.collected_term(self.one(), vars)?.factors;
            factors.sort_by_key(|f| factor_rank(self, *f));
            terms.push(CollectedTerm {
                negative,
                scale: None,
                coefficient: Vec::new(),
                inner,
                factors,
                value,
            });
        }
        Ok(terms)
    }

    /// The term `c * key` with its sign pulled out and its pieces in reading order.
    fn collected_term(&mut self, c: ExprId, key: ExprId) -> Result<CollectedTerm, ExprError> {
        let value = self.mul(&[c, key])?;
        let one = self.one();
        let mut factors: Vec<ExprId> = match self.node(key) {
            Node::Product(f) => f.to_vec(),
            _ if key == one => Vec::new(),
            _ => vec![key],
        };
        factors.sort_by_key(|f| factor_rank(self, *f));
        let summands: Vec<ExprId> = match self.node(c) {
            Node::Sum(t) => t.to_vec(),
            _ => vec![c],
        };
        let mut parts = Vec::with_capacity(summands.len());
        for t in summands {
            let neg = self.is_negated(t);
            let mag = if neg { self.neg(t)? } else { t };
            parts.push((neg, mag));
        }
        let negatives = parts.iter().filter(|p| p.0).count();
        let negative = 2 * negatives > parts.len();
        if negative {
            parts.iter_mut().for_each(|p| p.0 = !p.0);
        }
        parts.sort_by_key(|p| p.0);
        if parts.len() == 1 && parts[0].1 == one && !factors.is_empty() {
            parts.clear();
        }
        let scale = self.common_whole_factor(&mut parts)?;
        Ok(CollectedTerm { negative, scale, coefficient: parts, inner: Vec::new(), factors, value })
    }

    /// The greatest whole number dividing every summand's coefficient (when there are several
    /// and it is above 1), divided out of them.
    fn common_whole_factor(&mut self, parts: &mut [(bool, ExprId)]) -> Result<Option<ExprId>, ExprError> {
        if parts.len() < 2 {
            return Ok(None);
        }
        let mut g: i128 = 0;
        for (_, x) in parts.iter() {
            let (n, _) = self.split_coefficient(*x);
            match n {
                Number::Rational(r) if r.is_integer() => g = gcd(g, r.numer().abs()),
                _ => return Ok(None),
            }
        }
        if g <= 1 {
            return Ok(None);
        }
        let k = self.integer(g);
        for (_, x) in parts.iter_mut() {
            *x = self.div(*x, k)?;
        }
        Ok(Some(k))
    }
}

/// `t` negated for printing: a subtracted term is added; an added one with several summands
/// has their signs changed, any other is subtracted.
fn flip(t: &mut CollectedTerm) {
    if !t.negative && t.coefficient.len() > 1 {
        t.coefficient.iter_mut().for_each(|p| p.0 = !p.0);
        t.coefficient.sort_by_key(|p| p.0);
    } else {
        t.negative = !t.negative;
    }
}

fn gcd(a: i128, b: i128) -> i128 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// Where a state factor goes in a printed monomial: functions of the coordinates first, then
/// variables by derivative order, each group in declaration order.
fn factor_rank(ar: &Arena, f: ExprId) -> (u32, ExprId) {
    let base = match ar.node(f) {
        Node::Pow([b, _]) => *b,
        _ => f,
    };
    let class = match ar.node(base) {
        Node::Symbol(s) => match ar.symbol_info(*s).kind {
            SymbolKind::Variable { order } | SymbolKind::Specified { order } => 1 + order,
            _ => 1,
        },
        _ => 0,
    };
    (class, base)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn picks_the_sine_form_when_it_is_shorter_and_keeps_names() {
        let mut ar = Arena::new();
        let [k1, k2] = ["K1", "K2"].map(|n| ar.constant(n).unwrap());
        let q = ar.variable("Q2").unwrap();
        let u = ar.variable("U1").unwrap();
        let us = ar.as_symbol(u).unwrap();
        let ud = ar.derivative_symbol(us).unwrap();
        let ud = ar.symbol_expr(ud);
        let s = ar.sin(q).unwrap();
        let s2 = ar.powi(s, 2).unwrap();
        // (K2 - K1)*sin(Q2)^2*U1'
        let d = ar.sub(k2, k1).unwrap();
        let e = ar.mul(&[d, s2, ud]).unwrap();
        let is_param = |x: SymbolId| ar.symbol_info(x).kind == SymbolKind::Constant;
        let params: Vec<SymbolId> = ar.symbols().map(|(x, _)| x).filter(|x| is_param(*x)).collect();
        let c = ar.tidy(e, |x| params.contains(&x), &Abbreviations::default()).unwrap();
        assert_eq!(c.terms.len(), 1);
        assert_eq!(ar.collected_text(&c), "(K2 - K1)*sin(Q2)^2*U1'");
        let whole = Collected::whole(&ar, e);
        assert_eq!(whole.to_expr(&mut ar).unwrap(), e);
        let back = c.to_expr(&mut ar).unwrap();
        let diff = ar.sub(back, e).unwrap();
        assert_eq!(ar.simplify(diff).unwrap(), ar.zero());
    }
}
