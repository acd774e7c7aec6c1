//! Walking the DAG bottom-up and rebuilding nodes from new children.

use rustc_hash::{FxHashMap, FxHashSet};

use super::arena::Arena;
use super::error::ExprError;
use super::node::{ExprId, Node, SymbolId};

impl Arena {
    /// Every node reachable from `roots`, children before parents, not descending below `stop`.
    pub(crate) fn bottom_up(&self, roots: &[ExprId], stop: impl Fn(ExprId) -> bool) -> Vec<ExprId> {
        let mut seen: FxHashSet<ExprId> = FxHashSet::default();
        let mut stack: Vec<ExprId> = roots.to_vec();
        let mut out = Vec::new();
        while let Some(id) = stack.pop() {
            if !seen.insert(id) {
                continue;
            }
            out.push(id);
            if !stop(id) {
                stack.extend(self.node(id).children().iter().copied().filter(|c| !seen.contains(c)));
            }
        }
        // Children always have smaller ids than their parents, so id order is a topological order.
        out.sort_unstable();
        out
    }

    /// Rebuilds `node` with its children replaced by `kids`, through the canonical constructors.
    pub(crate) fn rebuild(&mut self, node: &Node, kids: &[ExprId]) -> Result<ExprId, ExprError> {
        match node {
            Node::Rational(_) | Node::Float(_) | Node::Symbol(_) => Ok(self.intern(node.clone())),
            Node::Sum(_) => self.add(kids),
            Node::Product(_) => self.mul(kids),
            Node::Pow(_) => self.pow(kids[0], kids[1]),
            Node::Func(f, _) => self.func(*f, kids[0]),
            Node::Atan2(_) => self.atan2(kids[0], kids[1]),
        }
    }

    /// Applies `leaf_or_node` bottom-up over the DAG of `roots`: for each node, the function may
    /// return a replacement given the already-mapped children; `None` means rebuild from them.
    pub(crate) fn map_bottom_up(
        &mut self,
        roots: &[ExprId],
        stop: impl Fn(ExprId) -> bool,
        mut replace: impl FnMut(&mut Arena, ExprId, &[ExprId]) -> Result<Option<ExprId>, ExprError>,
    ) -> Result<Vec<ExprId>, ExprError> {
        let order = self.bottom_up(roots, &stop);
        let mut map: FxHashMap<ExprId, ExprId> = FxHashMap::default();
        let mut kids = Vec::new();
        for id in order {
            let node = self.node(id).clone();
            kids.clear();
            let descended = !stop(id);
            if descended {
                kids.extend(node.children().iter().map(|c| map[c]));
            }
            let new = match replace(self, id, &kids)? {
                Some(r) => r,
                None if !descended || kids.as_slice() == node.children() => id,
                None => self.rebuild(&node, &kids)?,
            };
            map.insert(id, new);
        }
        Ok(roots.iter().map(|r| map[r]).collect())
    }

    /// The symbols `e` depends on, sorted by declaration.
    pub fn free_symbols(&self, roots: &[ExprId]) -> Vec<SymbolId> {
        let mut syms: Vec<SymbolId> =
            self.bottom_up(roots, |_| false).into_iter().filter_map(|id| self.as_symbol(id)).collect();
        syms.sort_unstable();
        syms
    }

    /// True when `e` is a polynomial in `syms`: they appear only in sums, products and powers
    /// with positive integer exponents (so the terms of `e` expanded that hold none of them are
    /// `e` with them zero).
    pub fn is_polynomial_in(&self, e: ExprId, syms: &[SymbolId]) -> bool {
        // Per node: (holds one of syms, is a polynomial in them), children first.
        let mut seen: FxHashMap<ExprId, (bool, bool)> = FxHashMap::default();
        for id in self.bottom_up(&[e], |_| false) {
            let node = self.node(id);
            let kids: Vec<(bool, bool)> = node.children().iter().map(|c| seen[c]).collect();
            let holds = matches!(node, Node::Symbol(s) if syms.contains(s)) || kids.iter().any(|k| k.0);
            let poly = kids.iter().all(|k| k.1)
                && match node {
                    Node::Pow([_, x]) => match self.node(*x) {
                        Node::Rational(r) => !kids[0].0 || (r.is_integer() && r.numer() > 0),
                        _ => !holds,
                    },
                    Node::Func(..) | Node::Atan2(_) => !holds,
                    _ => true,
                };
            seen.insert(id, (holds, poly));
        }
        seen[&e].1
    }

    /// Number of distinct nodes in the expression graph of `e`.
    pub fn graph_size(&self, e: ExprId) -> usize {
        self.bottom_up(&[e], |_| false).len()
    }

    /// True when `e` contains the symbol `s`.
    pub fn depends_on(&self, e: ExprId, s: SymbolId) -> bool {
        self.free_symbols(&[e]).contains(&s)
    }

    /// Replaces every occurrence of the keys of `map` (any subexpression) by its value.
    ///
    /// # Example
    /// ```
    /// use kane_model::expr::Arena;
    /// use rustc_hash::FxHashMap;
    /// let mut ar = Arena::new();
    /// let x = ar.constant("x").unwrap();
    /// let y = ar.constant("y").unwrap();
    /// let e = ar.mul(&[x, y]).unwrap();
    /// let two = ar.integer(2);
    /// let map: FxHashMap<_, _> = [(x, two)].into_iter().collect();
    /// let r = ar.subs(e, &map).unwrap();
    /// assert_eq!(r, ar.mul(&[two, y]).unwrap());
    /// ```
    pub fn subs(&mut self, e: ExprId, map: &FxHashMap<ExprId, ExprId>) -> Result<ExprId, ExprError> {
        Ok(self.subs_many(&[e], map)?[0])
    }

    /// [`Arena::subs`] over several roots sharing one traversal.
    pub fn subs_many(
        &mut self,
        roots: &[ExprId],
        map: &FxHashMap<ExprId, ExprId>,
    ) -> Result<Vec<ExprId>, ExprError> {
        if map.is_empty() {
            return Ok(roots.to_vec());
        }
        self.map_bottom_up(roots, |id| map.contains_key(&id), |_, id, _| Ok(map.get(&id).copied()))
    }
}
