//! Random expression trees for property tests, built into an arena in any operand order.

use kane_model::expr::{Arena, ExprId, Func, SymbolId};
use proptest::prelude::*;

/// Names of the symbols random expressions use.
pub const SYMBOLS: [&str; 3] = ["x", "y", "z"];

/// A random expression tree, independent of any arena.
#[derive(Clone, Debug)]
pub enum Ast {
    Sym(usize),
    Int(i64),
    Rat(i64, i64),
    Float(f64),
    Add(Vec<Ast>),
    Mul(Vec<Ast>),
    /// Integer power; negative powers take `1 + e^2` as base so they stay finite.
    Pow(Box<Ast>, i64),
    /// Square root of `1 + e^2`.
    Sqrt(Box<Ast>),
    Func(Func, Box<Ast>),
}

/// Trees of bounded depth and width over [`SYMBOLS`].
pub fn ast() -> impl Strategy<Value = Ast> {
    let leaf = prop_oneof![
        4 => (0..SYMBOLS.len()).prop_map(Ast::Sym),
        1 => (-5i64..6).prop_map(Ast::Int),
        1 => (-5i64..6, 1i64..5).prop_map(|(p, q)| Ast::Rat(p, q)),
        1 => (-2.0f64..2.0).prop_map(Ast::Float),
    ];
    leaf.prop_recursive(4, 40, 4, |inner| {
        prop_oneof![
            3 => prop::collection::vec(inner.clone(), 2..4).prop_map(Ast::Add),
            3 => prop::collection::vec(inner.clone(), 2..4).prop_map(Ast::Mul),
            1 => (inner.clone(), -2i64..4).prop_map(|(a, k)| Ast::Pow(Box::new(a), k)),
            1 => inner.clone().prop_map(|a| Ast::Sqrt(Box::new(a))),
            2 => (prop::sample::select(vec![Func::Sin, Func::Cos, Func::Atan, Func::Tanh]), inner)
                .prop_map(|(f, a)| Ast::Func(f, Box::new(a))),
        ]
    })
}

/// Builds `ast` into `ar`; `reverse` builds every sum and product with its operands reversed.
pub fn build(ar: &mut Arena, ast: &Ast, reverse: bool) -> ExprId {
    let ordered = |v: &[Ast]| -> Vec<Ast> {
        let mut v = v.to_vec();
        if reverse {
            v.reverse();
        }
        v
    };
    match ast {
        Ast::Sym(i) => ar.constant(SYMBOLS[*i]).unwrap(),
        Ast::Int(n) => ar.integer(*n as i128),
        Ast::Rat(p, q) => ar.rational(*p as i128, *q as i128).unwrap(),
        Ast::Float(x) => ar.float(*x).unwrap(),
        Ast::Add(v) => {
            let ids: Vec<ExprId> = ordered(v).iter().map(|a| build(ar, a, reverse)).collect();
            ar.add(&ids).unwrap()
        }
        Ast::Mul(v) => {
            let ids: Vec<ExprId> = ordered(v).iter().map(|a| build(ar, a, reverse)).collect();
            ar.mul(&ids).unwrap()
        }
        Ast::Pow(a, k) => {
            let b = build(ar, a, reverse);
            let base = if *k < 0 { one_plus_square(ar, b) } else { b };
            ar.powi(base, *k).unwrap()
        }
        Ast::Sqrt(a) => {
            let b = build(ar, a, reverse);
            let base = one_plus_square(ar, b);
            ar.sqrt(base).unwrap()
        }
        Ast::Func(f, a) => {
            let b = build(ar, a, reverse);
            ar.func(*f, b).unwrap()
        }
    }
}

fn one_plus_square(ar: &mut Arena, b: ExprId) -> ExprId {
    let sq = ar.powi(b, 2).unwrap();
    let one = ar.one();
    ar.add(&[one, sq]).unwrap()
}

/// The symbols of [`SYMBOLS`], declared in `ar`.
pub fn symbols(ar: &mut Arena) -> Vec<SymbolId> {
    SYMBOLS
        .iter()
        .map(|n| {
            let e = ar.constant(n).unwrap();
            ar.as_symbol(e).unwrap()
        })
        .collect()
}

/// Values for [`SYMBOLS`].
pub fn point() -> impl Strategy<Value = [f64; 3]> {
    [-1.5f64..1.5, -1.5f64..1.5, -1.5f64..1.5]
}

/// Evaluates `e` at `p`.
pub fn eval_at(ar: &Arena, syms: &[SymbolId], e: ExprId, p: &[f64; 3]) -> Option<f64> {
    ar.eval(&[e], |s| syms.iter().position(|x| *x == s).map(|i| p[i])).ok().map(|v| v[0])
}

/// True when `a` and `b` agree to `tol` relative to their size.
pub fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * a.abs().max(b.abs()).max(1.0)
}
