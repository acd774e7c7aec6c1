//! The arena that interns expression nodes and declares symbols.

use std::hash::BuildHasher;

use hashbrown::HashTable;
use rustc_hash::{FxBuildHasher, FxHashMap};

use super::error::ExprError;
use super::node::{ExprId, Node, SymbolId, SymbolKind};
use super::number::{Number, Rational};

/// The symbol of time, declared first in every arena.
pub const TIME: SymbolId = SymbolId(0);

/// A declared symbol: its printed name and kind.
#[derive(Clone, Debug)]
pub struct Symbol {
    /// Printed name; derivatives carry one `'` per order.
    pub name: String,
    /// What the symbol stands for.
    pub kind: SymbolKind,
    /// The order-0 symbol this one is a time derivative of (itself at order 0).
    pub base: SymbolId,
}

/// Owner of all expression nodes and symbols; every expression is an [`ExprId`] into it.
///
/// Nodes are hash-consed: building a structurally equal expression twice returns the same id,
/// so the expressions form a DAG in which common subexpressions are stored once.
///
/// # Example
/// ```
/// use kane_model::expr::Arena;
/// let mut ar = Arena::new();
/// let x = ar.constant("x").unwrap();
/// let y = ar.constant("y").unwrap();
/// let a = ar.add(&[x, y]).unwrap();
/// let b = ar.add(&[y, x]).unwrap();
/// assert_eq!(a, b);
/// ```
pub struct Arena {
    nodes: Vec<Node>,
    hashes: Vec<u64>,
    table: HashTable<ExprId>,
    symbols: Vec<Symbol>,
    symbol_ids: FxHashMap<String, SymbolId>,
    derivative_of: FxHashMap<SymbolId, SymbolId>,
    pub(crate) diff_cache: FxHashMap<(ExprId, SymbolId), ExprId>,
    zero: ExprId,
    one: ExprId,
    minus_one: ExprId,
}

impl Default for Arena {
    fn default() -> Self {
        Self::new()
    }
}

impl Arena {
    /// An empty arena holding the numbers 0, 1, -1 and the symbol `t`.
    pub fn new() -> Arena {
        let mut ar = Arena {
            nodes: Vec::new(),
            hashes: Vec::new(),
            table: HashTable::new(),
            symbols: Vec::new(),
            symbol_ids: FxHashMap::default(),
            derivative_of: FxHashMap::default(),
            diff_cache: FxHashMap::default(),
            zero: ExprId(0),
            one: ExprId(0),
            minus_one: ExprId(0),
        };
        ar.zero = ar.intern(Node::Rational(Rational::ZERO));
        ar.one = ar.intern(Node::Rational(Rational::ONE));
        ar.minus_one = ar.intern(Node::Rational(Rational::MINUS_ONE));
        let t = ar.declare("t", SymbolKind::Time);
        debug_assert_eq!(t, Ok(TIME));
        ar
    }

    /// Number of distinct nodes stored.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// True if no node is stored (never, since 0, 1, -1 always are).
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// The node behind an id.
    pub fn node(&self, id: ExprId) -> &Node {
        &self.nodes[id.index()]
    }

    /// Returns the id of `node`, storing it if it is new. Callers guarantee canonical form.
    pub(crate) fn intern(&mut self, node: Node) -> ExprId {
        let hash = FxBuildHasher.hash_one(&node);
        let nodes = &self.nodes;
        if let Some(&id) = self.table.find(hash, |&id| nodes[id.index()] == node) {
            return id;
        }
        debug_assert!(node.children().iter().all(|c| c.index() < self.nodes.len()));
        let id = ExprId(u32::try_from(self.nodes.len()).expect("more than 2^32 expression nodes"));
        self.nodes.push(node);
        self.hashes.push(hash);
        let hashes = &self.hashes;
        self.table.insert_unique(hash, id, |&i| hashes[i.index()]);
        id
    }

    /// The exact number 0.
    pub fn zero(&self) -> ExprId {
        self.zero
    }

    /// The exact number 1.
    pub fn one(&self) -> ExprId {
        self.one
    }

    /// The exact number -1.
    pub fn minus_one(&self) -> ExprId {
        self.minus_one
    }

    /// The exact integer `n`.
    pub fn integer(&mut self, n: i128) -> ExprId {
        self.intern(Node::Rational(Rational::integer(n)))
    }

    /// The exact rational `num/den`.
    pub fn rational(&mut self, num: i128, den: i128) -> Result<ExprId, ExprError> {
        Ok(self.intern(Node::Rational(Rational::new(num, den)?)))
    }

    /// A floating literal; NaN and infinities are rejected.
    pub fn float(&mut self, x: f64) -> Result<ExprId, ExprError> {
        let n = super::number::float(x)?;
        Ok(self.number(n))
    }

    /// A number node.
    pub fn number(&mut self, n: Number) -> ExprId {
        match n {
            Number::Rational(r) => self.intern(Node::Rational(r)),
            Number::Float(x) => self.intern(Node::Float(x.to_bits())),
        }
    }

    /// The value of a number node, or `None` for anything else.
    pub fn as_number(&self, id: ExprId) -> Option<Number> {
        match self.node(id) {
            Node::Rational(r) => Some(Number::Rational(*r)),
            Node::Float(bits) => Some(Number::Float(f64::from_bits(*bits))),
            _ => None,
        }
    }

    /// The terms of `e`: its summands when it is a sum, else `e` alone.
    pub fn terms(&self, e: ExprId) -> Vec<ExprId> {
        match self.node(e) {
            Node::Sum(t) => t.to_vec(),
            _ => vec![e],
        }
    }

    /// The factors of `e`: its factors when it is a product, else `e` alone.
    pub fn factors(&self, e: ExprId) -> Vec<ExprId> {
        match self.node(e) {
            Node::Product(f) => f.to_vec(),
            _ => vec![e],
        }
    }

    /// The value of an exact rational node.
    pub fn as_rational(&self, id: ExprId) -> Option<Rational> {
        match self.node(id) {
            Node::Rational(r) => Some(*r),
            _ => None,
        }
    }

    /// The symbol of a symbol node.
    pub fn as_symbol(&self, id: ExprId) -> Option<SymbolId> {
        match self.node(id) {
            Node::Symbol(s) => Some(*s),
            _ => None,
        }
    }

    /// Declares (or finds) the symbol `name` of the given kind and returns its expression.
    pub fn symbol(&mut self, name: &str, kind: SymbolKind) -> Result<ExprId, ExprError> {
        let sym = self.declare(name, kind)?;
        Ok(self.symbol_expr(sym))
    }

    /// A constant parameter named `name`.
    pub fn constant(&mut self, name: &str) -> Result<ExprId, ExprError> {
        self.symbol(name, SymbolKind::Constant)
    }

    /// Time `t` (declared by [`Arena::new`]).
    pub fn time(&mut self) -> ExprId {
        self.intern(Node::Symbol(TIME))
    }

    /// A time-dependent variable `name` (order 0).
    pub fn variable(&mut self, name: &str) -> Result<ExprId, ExprError> {
        self.symbol(name, SymbolKind::Variable { order: 0 })
    }

    /// A specified function of time `name` (order 0).
    pub fn specified(&mut self, name: &str) -> Result<ExprId, ExprError> {
        self.symbol(name, SymbolKind::Specified { order: 0 })
    }

    /// The expression made of one symbol.
    pub fn symbol_expr(&mut self, sym: SymbolId) -> ExprId {
        self.intern(Node::Symbol(sym))
    }

    /// Declares a symbol, or returns the existing one if it has the same kind.
    pub fn declare(&mut self, name: &str, kind: SymbolKind) -> Result<SymbolId, ExprError> {
        if let Some(&id) = self.symbol_ids.get(name) {
            return if self.symbols[id.index()].kind == kind {
                Ok(id)
            } else {
                Err(ExprError::SymbolKindClash(name.to_string()))
            };
        }
        let id = SymbolId(self.symbols.len() as u32);
        self.symbols.push(Symbol { name: name.to_string(), kind, base: id });
        self.symbol_ids.insert(name.to_string(), id);
        Ok(id)
    }

    /// The symbol declared as `name`.
    pub fn lookup(&self, name: &str) -> Option<SymbolId> {
        self.symbol_ids.get(name).copied()
    }

    /// Information on a symbol.
    pub fn symbol_info(&self, sym: SymbolId) -> &Symbol {
        &self.symbols[sym.index()]
    }

    /// All declared symbols, in declaration order.
    pub fn symbols(&self) -> impl Iterator<Item = (SymbolId, &Symbol)> {
        self.symbols.iter().enumerate().map(|(i, s)| (SymbolId(i as u32), s))
    }

    /// The symbol standing for the time derivative of `sym` (`q` -> `q'`), declared on first use.
    pub fn derivative_symbol(&mut self, sym: SymbolId) -> Result<SymbolId, ExprError> {
        if let Some(&d) = self.derivative_of.get(&sym) {
            return Ok(d);
        }
        let info = self.symbols[sym.index()].clone();
        let kind = match info.kind {
            SymbolKind::Variable { order } => SymbolKind::Variable { order: order + 1 },
            SymbolKind::Specified { order } => SymbolKind::Specified { order: order + 1 },
            SymbolKind::Constant | SymbolKind::Time => return Err(ExprError::NotTimeDependent(info.name)),
        };
        let name = format!("{}'", info.name);
        let d = self.declare(&name, kind)?;
        self.symbols[d.index()].base = info.base;
        self.derivative_of.insert(sym, d);
        Ok(d)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interning_returns_the_same_id() {
        let mut ar = Arena::new();
        let a = ar.integer(7);
        let b = ar.integer(7);
        assert_eq!(a, b);
        assert_eq!(ar.integer(0), ar.zero());
    }

    #[test]
    fn derivative_symbols_chain() {
        let mut ar = Arena::new();
        let q = ar.variable("q1").unwrap();
        let s = ar.as_symbol(q).unwrap();
        let d1 = ar.derivative_symbol(s).unwrap();
        let d2 = ar.derivative_symbol(d1).unwrap();
        assert_eq!(ar.symbol_info(d2).name, "q1''");
        assert_eq!(ar.symbol_info(d2).kind, SymbolKind::Variable { order: 2 });
        assert_eq!(ar.symbol_info(d2).base, s);
        assert_eq!(ar.derivative_symbol(s).unwrap(), d1);
    }

    #[test]
    fn kind_clash_is_an_error() {
        let mut ar = Arena::new();
        ar.constant("m").unwrap();
        assert_eq!(ar.variable("m"), Err(ExprError::SymbolKindClash("m".into())));
        assert_eq!(ar.constant("t"), Err(ExprError::SymbolKindClash("t".into())));
        let t = ar.time();
        assert_eq!(ar.as_symbol(t), Some(TIME));
    }
}
