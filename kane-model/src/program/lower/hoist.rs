//! Parameter-only parts of expressions, replaced by fresh constants computed once per parameter
//! set: whole parameter-only subexpressions, the parameter-only terms of a sum and the
//! parameter-only factors of a product (so `m3 L^2 u1 u2 sin(q2) / 2` reads one constant).

use rustc_hash::FxHashMap;

use crate::expr::{Arena, Compiler, ExprError, ExprId, Node, SymbolId, SymbolKind, TIME};

use super::super::ir::{Input, Section};

/// Fresh constants standing for parameter-only expressions.
#[derive(Clone, Debug, Default)]
pub struct Hoisted {
    /// Each constant and the expression (in the parameters) it stands for, in first-use order.
    pub defs: Vec<(SymbolId, ExprId)>,
    by_def: FxHashMap<ExprId, SymbolId>,
    memo: FxHashMap<ExprId, ExprId>,
    param_only: FxHashMap<ExprId, bool>,
}

impl Hoisted {
    /// How a section reads symbols (time, `states`, `params`, and these constants as
    /// `Input::ParamConstant`), and the `param_constants` section computing the constants from
    /// the parameters.
    pub fn reading(
        &self,
        ar: &Arena,
        states: &[SymbolId],
        params: &[SymbolId],
    ) -> (FxHashMap<SymbolId, Input>, Section) {
        let mut symbols: FxHashMap<SymbolId, Input> = FxHashMap::default();
        symbols.insert(TIME, Input::Time);
        symbols.extend(states.iter().enumerate().map(|(i, s)| (*s, Input::State(i))));
        symbols.extend(params.iter().enumerate().map(|(i, s)| (*s, Input::Param(i))));
        let param_constants = {
            let defs: Vec<ExprId> = self.defs.iter().map(|d| d.1).collect();
            let mut lowering = Compiler::new(ar, |s| symbols.get(&s).copied(), None);
            let values = lowering.lower_all(&defs);
            lowering.builder.finish(values)
        };
        symbols.extend(self.defs.iter().enumerate().map(|(i, (s, _))| (*s, Input::ParamConstant(i))));
        (symbols, param_constants)
    }

    /// `e` with its parameter-only parts replaced by constants (`is_param` names the parameters).
    pub fn rewrite(
        &mut self,
        ar: &mut Arena,
        e: ExprId,
        is_param: &dyn Fn(SymbolId) -> bool,
    ) -> Result<ExprId, ExprError> {
        if let Some(&r) = self.memo.get(&e) {
            return Ok(r);
        }
        let out = if is_leaf(ar, e) {
            e
        } else if self.param_only(ar, e, is_param) {
            self.constant(ar, e)?
        } else {
            match ar.node(e).clone() {
                Node::Sum(terms) => self.split(ar, &terms, true, is_param)?,
                Node::Product(factors) => self.split(ar, &factors, false, is_param)?,
                Node::Pow([b, x]) => {
                    let b = self.rewrite(ar, b, is_param)?;
                    let x = self.rewrite(ar, x, is_param)?;
                    ar.pow(b, x)?
                }
                Node::Func(f, x) => {
                    let x = self.rewrite(ar, x, is_param)?;
                    ar.func(f, x)?
                }
                Node::Atan2([y, x]) => {
                    let y = self.rewrite(ar, y, is_param)?;
                    let x = self.rewrite(ar, x, is_param)?;
                    ar.atan2(y, x)?
                }
                Node::Rational(_) | Node::Float(_) | Node::Symbol(_) => e,
            }
        };
        self.memo.insert(e, out);
        Ok(out)
    }

    /// The constant standing for the parameter-only `def`.
    pub fn constant(&mut self, ar: &mut Arena, def: ExprId) -> Result<ExprId, ExprError> {
        if is_leaf(ar, def) {
            return Ok(def);
        }
        if let Some(&s) = self.by_def.get(&def) {
            return Ok(ar.symbol_expr(s));
        }
        let s = ar.declare(&format!("__hoisted{}", def.index()), SymbolKind::Constant)?;
        self.by_def.insert(def, s);
        self.defs.push((s, def));
        Ok(ar.symbol_expr(s))
    }

    /// A sum (`is_sum`) or product of `parts` with its parameter-only parts as one constant; a
    /// product keeps a factor -1 outside (a negation is free in the sums around it).
    fn split(
        &mut self,
        ar: &mut Arena,
        parts: &[ExprId],
        is_sum: bool,
        is_param: &dyn Fn(SymbolId) -> bool,
    ) -> Result<ExprId, ExprError> {
        let (mut fixed, rest): (Vec<ExprId>, Vec<ExprId>) =
            parts.iter().partition(|p| self.param_only(ar, **p, is_param));
        let mut out = Vec::with_capacity(parts.len());
        if !is_sum {
            if let Some(pos) = fixed.iter().position(|p| *p == ar.minus_one()) {
                fixed.remove(pos);
                out.push(ar.minus_one());
            }
        }
        if !fixed.is_empty() {
            let group = if is_sum { ar.add(&fixed)? } else { ar.mul(&fixed)? };
            out.push(self.constant(ar, group)?);
        }
        for r in rest {
            out.push(self.rewrite(ar, r, is_param)?);
        }
        if is_sum {
            ar.add(&out)
        } else {
            ar.mul(&out)
        }
    }

    /// True for an expression in the parameters alone (numbers included); remembered per node,
    /// so a DAG is walked once however often its parts are asked about.
    fn param_only(&mut self, ar: &Arena, e: ExprId, is_param: &dyn Fn(SymbolId) -> bool) -> bool {
        if let Some(&p) = self.param_only.get(&e) {
            return p;
        }
        for id in ar.bottom_up(&[e], |x| self.param_only.contains_key(&x)) {
            if self.param_only.contains_key(&id) {
                continue;
            }
            let p = match ar.node(id) {
                Node::Symbol(s) => is_param(*s),
                Node::Rational(_) | Node::Float(_) => true,
                n => n.children().iter().all(|c| self.param_only[c]),
            };
            self.param_only.insert(id, p);
        }
        self.param_only[&e]
    }
}

fn is_leaf(ar: &Arena, e: ExprId) -> bool {
    matches!(ar.node(e), Node::Rational(_) | Node::Float(_) | Node::Symbol(_))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameter_factors_and_terms_become_one_constant_each() {
        let mut ar = Arena::new();
        let m = ar.constant("m").unwrap();
        let l = ar.constant("l").unwrap();
        let q = ar.variable("q").unwrap();
        let u = ar.variable("u").unwrap();
        let (ms, ls) = (ar.as_symbol(m).unwrap(), ar.as_symbol(l).unwrap());
        let is_param = move |s: SymbolId| s == ms || s == ls;
        // -m l^2 u sin(q) / 2 + m + l
        let l2 = ar.powi(l, 2).unwrap();
        let half = ar.rational(-1, 2).unwrap();
        let s = ar.sin(q).unwrap();
        let prod = ar.mul(&[half, m, l2, u, s]).unwrap();
        let e = ar.add(&[prod, m, l]).unwrap();
        let mut h = Hoisted::default();
        let r = h.rewrite(&mut ar, e, &is_param).unwrap();
        assert_eq!(h.defs.len(), 2, "{}", ar.to_text(r));
        // The rewritten expression has the same value.
        let vals = [("m", 2.0), ("l", 0.3), ("q", 0.7), ("u", -1.5)];
        let mut with_defs: Vec<(String, f64)> = vals.iter().map(|(n, v)| (n.to_string(), *v)).collect();
        for (sym, def) in &h.defs {
            let v = ar.eval_named(*def, &vals).unwrap();
            with_defs.push((ar.symbol_info(*sym).name.clone(), v));
        }
        let named: Vec<(&str, f64)> = with_defs.iter().map(|(n, v)| (n.as_str(), *v)).collect();
        let want = ar.eval_named(e, &vals).unwrap();
        let got = ar.eval_named(r, &named).unwrap();
        assert!((want - got).abs() < 1e-14, "{want} vs {got}");
    }

    #[test]
    fn a_negated_parameter_product_keeps_its_sign_outside() {
        let mut ar = Arena::new();
        let m = ar.constant("m").unwrap();
        let k = ar.constant("k").unwrap();
        let u = ar.variable("u").unwrap();
        let (ms, ks) = (ar.as_symbol(m).unwrap(), ar.as_symbol(k).unwrap());
        let is_param = move |s: SymbolId| s == ms || s == ks;
        let mk = ar.mul(&[m, k, u]).unwrap();
        let neg = ar.neg(mk).unwrap();
        let mut h = Hoisted::default();
        let a = h.rewrite(&mut ar, mk, &is_param).unwrap();
        let b = h.rewrite(&mut ar, neg, &is_param).unwrap();
        assert_eq!(h.defs.len(), 1, "m k and -m k share one constant");
        assert_eq!(b, ar.neg(a).unwrap());
    }
}
