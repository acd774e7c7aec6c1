//! Common-subexpression elimination into ordered assignments.

use rustc_hash::FxHashMap;

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Node, SymbolId};

/// Shared subexpressions of a set of roots, in an order where each depends only on earlier ones.
///
/// Hash-consing has already merged equal subtrees; CSE picks the nodes used more than once and
/// names them, so printers and code generators compute each only once.
#[derive(Clone, Debug)]
pub struct Cse {
    /// The shared subexpressions, children before parents.
    pub temps: Vec<ExprId>,
    /// The roots.
    pub roots: Vec<ExprId>,
}

/// Ordered assignments `symbol = expression` followed by the roots written in those symbols.
#[derive(Clone, Debug)]
pub struct StraightLine {
    /// Each temporary symbol with its expression, in evaluation order.
    pub bindings: Vec<(SymbolId, ExprId)>,
    /// The roots, written in the temporaries.
    pub roots: Vec<ExprId>,
}

impl Cse {
    /// Finds the subexpressions of `roots` used more than once.
    pub fn new(ar: &Arena, roots: &[ExprId]) -> Cse {
        let order = ar.bottom_up(roots, |_| false);
        let mut uses: FxHashMap<ExprId, u32> = FxHashMap::default();
        for &id in &order {
            for c in ar.node(id).children() {
                *uses.entry(*c).or_default() += 1;
            }
        }
        for r in roots {
            *uses.entry(*r).or_default() += 1;
        }
        let temps = order
            .into_iter()
            .filter(|id| {
                uses.get(id).copied().unwrap_or(0) > 1
                    && !matches!(ar.node(*id), Node::Rational(_) | Node::Float(_) | Node::Symbol(_))
            })
            .collect();
        Cse { temps, roots: roots.to_vec() }
    }

    /// Names `prefix0, prefix1, ...` for the temporaries.
    pub fn names(&self, prefix: &str) -> FxHashMap<ExprId, String> {
        self.temps.iter().enumerate().map(|(i, id)| (*id, format!("{prefix}{i}"))).collect()
    }

    /// Straight-line form: each temporary becomes a fresh constant symbol `prefix{i}` bound to
    /// its expression written in earlier temporaries; returns the bindings and the roots.
    pub fn assignments(&self, ar: &mut Arena, prefix: &str) -> Result<StraightLine, ExprError> {
        let mut map: FxHashMap<ExprId, ExprId> = FxHashMap::default();
        let mut bindings = Vec::with_capacity(self.temps.len());
        for (i, &t) in self.temps.iter().enumerate() {
            let node = ar.node(t).clone();
            let kids: Vec<ExprId> =
                node.children().iter().map(|c| map.get(c).copied().unwrap_or(*c)).collect();
            let body = ar.rebuild(&node, &kids)?;
            let sym = ar.declare(&format!("{prefix}{i}"), super::node::SymbolKind::Constant)?;
            bindings.push((sym, body));
            map.insert(t, ar.symbol_expr(sym));
        }
        let roots = ar.subs_many(&self.roots, &map)?;
        Ok(StraightLine { bindings, roots })
    }

    /// The assignments and results as text, one per line (`x0 = ...`, then `out0 = ...`).
    pub fn to_text(&self, ar: &Arena) -> String {
        let names = self.names("x");
        let mut s = String::new();
        for (i, t) in self.temps.iter().enumerate() {
            s.push_str(&format!("x{i} = {}\n", ar.to_text_named(*t, &names)));
        }
        for (i, r) in self.roots.iter().enumerate() {
            let body = names.get(r).cloned().unwrap_or_else(|| ar.to_text_named(*r, &names));
            s.push_str(&format!("out{i} = {body}\n"));
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn shared_node_becomes_one_temp() {
        let mut ar = Arena::new();
        let [x, y] = ["x", "y"].map(|n| ar.constant(n).unwrap());
        let s = ar.add(&[x, y]).unwrap();
        let c = ar.cos(s).unwrap();
        let sn = ar.sin(s).unwrap();
        let e = ar.mul(&[c, sn]).unwrap();
        let sq = ar.powi(s, 2).unwrap();
        let e2 = ar.add(&[sq, x]).unwrap();
        let with_square = Cse::new(&ar, &[sq, e2]);
        assert_eq!(with_square.to_text(&ar), "x0 = (x + y)^2\nout0 = x0\nout1 = x + x0\n");
        let cse = Cse::new(&ar, &[e, c]);
        assert_eq!(cse.temps, vec![s, c]);
        assert_eq!(cse.to_text(&ar), "x0 = x + y\nx1 = cos(x0)\nout0 = x1*sin(x0)\nout1 = x1\n");
    }
}
