//! Named intermediates, as Autolev's Z variables: `z1 = cos(Q2)`, then expressions in `z1`.
//!
//! Printing a DAG as trees repeats every shared subexpression at each use, so the text can
//! grow exponentially with the DAG. Naming each subexpression that would be printed more than
//! once, and printing it once, keeps the text proportional to the DAG.

use rustc_hash::FxHashMap;

use super::super::arena::Arena;
use super::super::node::{ExprId, Node};
use super::latex::symbol_latex;

/// Subexpressions named `z1, z2, ...` for printing some roots; each defined before it is used.
#[derive(Clone, Debug, Default)]
pub struct Intermediates {
    /// The named subexpressions, children before parents.
    pub order: Vec<ExprId>,
    /// The name of each.
    pub names: FxHashMap<ExprId, String>,
}

impl Intermediates {
    /// Names the subexpressions of `roots` that printing them would write more than once
    /// (a named node is written once, in its definition), except those as short as their name:
    /// symbols, numbers, powers of a symbol, `-x`, `2*x`, and products of at most three symbols.
    pub fn new(ar: &Arena, roots: &[ExprId]) -> Intermediates {
        let order = ar.bottom_up(roots, |_| false);
        let mut printed: FxHashMap<ExprId, u64> = FxHashMap::default();
        for r in roots {
            *printed.entry(*r).or_default() += 1;
        }
        let mut named = Vec::new();
        for &id in order.iter().rev() {
            let times = printed.get(&id).copied().unwrap_or(0);
            let name_it = times > 1 && !short(ar, id);
            if name_it {
                named.push(id);
            }
            let each = if name_it { 1 } else { times };
            for c in ar.node(id).children() {
                *printed.entry(*c).or_default() += each;
            }
        }
        named.reverse();
        let prefix = free_prefix(ar);
        let names = named.iter().enumerate().map(|(i, id)| (*id, format!("{prefix}{}", i + 1))).collect();
        Intermediates { order: named, names }
    }

    /// True when nothing is named.
    pub fn is_empty(&self) -> bool {
        self.order.is_empty()
    }

    /// `e` as plain text in the names (its own name when it is named).
    pub fn text(&self, ar: &Arena, e: ExprId) -> String {
        self.names.get(&e).cloned().unwrap_or_else(|| ar.to_text_named(e, &self.names))
    }

    /// `e` as LaTeX in the names (its own name when it is named).
    pub fn latex(&self, ar: &Arena, e: ExprId) -> String {
        match self.names.get(&e) {
            Some(name) => symbol_latex(name, 0),
            None => ar.to_latex_named(e, &self.names),
        }
    }

    /// The definitions, in order: each name with its expression as plain text.
    pub fn text_lines(&self, ar: &Arena) -> Vec<(String, String)> {
        self.order.iter().map(|id| (self.names[id].clone(), ar.to_text_named(*id, &self.names))).collect()
    }

    /// The definitions, in order: each name and its expression, as LaTeX.
    pub fn latex_lines(&self, ar: &Arena) -> Vec<(String, String)> {
        self.order
            .iter()
            .map(|id| (symbol_latex(&self.names[id], 0), ar.to_latex_named(*id, &self.names)))
            .collect()
    }
}

/// True for a node printed about as short as a name.
fn short(ar: &Arena, id: ExprId) -> bool {
    let atomic = |x: ExprId| match ar.node(x) {
        Node::Rational(_) | Node::Float(_) | Node::Symbol(_) => true,
        Node::Pow([b, e]) => matches!(ar.node(*b), Node::Symbol(_)) && ar.as_number(*e).is_some(),
        _ => false,
    };
    match ar.node(id) {
        Node::Product(f) => {
            let others = f.iter().filter(|x| ar.as_number(**x).is_none()).count();
            others <= 1 || (f.len() <= 3 && f.iter().all(|x| atomic(*x)))
        }
        _ => atomic(id),
    }
}

/// A prefix `z` (or `zz`, ...) such that no symbol of `ar` is the prefix and a number.
fn free_prefix(ar: &Arena) -> String {
    let mut prefix = String::from("z");
    let clash = |p: &str| {
        ar.symbols().any(|(_, s)| {
            let n = s.name.to_ascii_lowercase();
            n.strip_prefix(p).is_some_and(|rest| !rest.is_empty() && rest.chars().all(|c| c.is_ascii_digit()))
        })
    };
    while clash(&prefix) {
        prefix.push('z');
    }
    prefix
}

#[cfg(test)]
mod tests {
    use super::Intermediates;
    use crate::expr::Arena;

    #[test]
    fn a_shared_subexpression_is_printed_once_as_z1() {
        let mut ar = Arena::new();
        let [x, y] = ["x", "y"].map(|n| ar.constant(n).unwrap());
        let s = ar.add(&[x, y]).unwrap();
        let c = ar.cos(s).unwrap();
        let c2 = ar.powi(c, 2).unwrap();
        let r1 = ar.add(&[c2, x]).unwrap();
        let r2 = ar.mul(&[c, y]).unwrap();
        let z = Intermediates::new(&ar, &[r1, r2, x]);
        assert_eq!(z.text_lines(&ar), [("z1".to_string(), "cos(x + y)".to_string())]);
        assert_eq!(z.text(&ar, r1), "x + z1^2");
        assert_eq!(z.text(&ar, r2), "y*z1");
        assert_eq!(z.text(&ar, x), "x");
        assert_eq!(z.latex(&ar, c), "z_{1}");
        assert_eq!(z.latex_lines(&ar)[0].0, "z_{1}");
    }

    #[test]
    fn short_pieces_stay_inline_and_a_root_used_twice_is_named() {
        let mut ar = Arena::new();
        let [x, y] = ["x", "y"].map(|n| ar.constant(n).unwrap());
        let xy = ar.mul(&[x, y]).unwrap();
        let s = ar.add(&[xy, y]).unwrap();
        let z = Intermediates::new(&ar, &[xy, xy, s, s]);
        assert_eq!(z.text_lines(&ar), [("z1".to_string(), "y + x*y".to_string())]);
        assert_eq!(z.text(&ar, s), "z1");
        assert_eq!(z.text(&ar, xy), "x*y");
    }

    #[test]
    fn text_grows_with_the_dag_not_the_tree() {
        let mut ar = Arena::new();
        let z1 = ar.constant("z1").unwrap();
        let mut e = ar.constant("x").unwrap();
        // Each level uses the one below twice: a tree of 2^60 leaves, a DAG of 180 nodes.
        for _ in 0..60 {
            let c = ar.cos(e).unwrap();
            let s = ar.sin(e).unwrap();
            e = ar.add(&[c, s, z1]).unwrap();
        }
        let z = Intermediates::new(&ar, &[e]);
        let lines = z.text_lines(&ar);
        assert_eq!(lines.len(), 59);
        assert!(lines.iter().all(|(name, _)| name.starts_with("zz")), "the model's z1 is not reused");
        let total: usize = lines.iter().map(|(n, d)| n.len() + d.len()).sum::<usize>() + z.text(&ar, e).len();
        assert!(total < 4_000, "{total}");
    }
}
