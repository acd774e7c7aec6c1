//! Long sums as balanced trees. In: the terms of `t0 ± t1 ± ... ± tn` as the parser read them;
//! out: one expression whose depth grows with the logarithm of the term count, so a
//! 20,000-term sum is evaluated (and dropped) without deep recursion. A subtracted term becomes
//! a negated one: the same value, since addition of values is associative and commutative.

use super::ast::{BinOp, Expr, ExprKind};

/// Sums with at most this many terms keep the parser's left-deep shape (`(a + b) - c`).
pub const BALANCE_FROM: usize = 32;

/// `first` followed by `rest` (each term with the `+` or `-` before it) as one expression:
/// left-deep for short sums, balanced from [`BALANCE_FROM`] terms on.
pub fn sum(first: Expr, rest: Vec<(BinOp, Expr)>) -> Expr {
    if rest.len() + 1 < BALANCE_FROM {
        return rest.into_iter().fold(first, |lhs, (op, rhs)| joined(op, lhs, rhs));
    }
    let mut terms = Vec::with_capacity(rest.len() + 1);
    terms.push(first);
    for (op, term) in rest {
        terms.push(match op {
            BinOp::Sub => Expr { span: term.span.clone(), kind: ExprKind::Neg(Box::new(term)) },
            _ => term,
        });
    }
    balanced(terms)
}

/// `lhs op rhs`, spanning both.
fn joined(op: BinOp, lhs: Expr, rhs: Expr) -> Expr {
    let span = lhs.span.start..rhs.span.end;
    Expr { kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)), span }
}

/// The sum of `terms` (at least one), halves added recursively (depth log2 of the count).
fn balanced(mut terms: Vec<Expr>) -> Expr {
    if terms.len() == 1 {
        return terms.pop().expect("one term");
    }
    let right = terms.split_off(terms.len() / 2);
    joined(BinOp::Add, balanced(terms), balanced(right))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn name(n: &str, at: usize) -> Expr {
        Expr { kind: ExprKind::Name { name: n.into(), primes: 0, suffix: 0 }, span: at..at + 1 }
    }

    fn depth(e: &Expr) -> usize {
        match &e.kind {
            ExprKind::Binary(_, a, b) => 1 + depth(a).max(depth(b)),
            ExprKind::Neg(a) => 1 + depth(a),
            _ => 0,
        }
    }

    #[test]
    fn short_sums_stay_left_deep_and_long_ones_are_balanced() {
        let short = sum(name("A", 0), vec![(BinOp::Sub, name("B", 2)), (BinOp::Add, name("C", 4))]);
        let ExprKind::Binary(BinOp::Add, left, _) = &short.kind else { panic!("{short:?}") };
        assert!(matches!(left.kind, ExprKind::Binary(BinOp::Sub, ..)));
        assert_eq!(short.span, 0..5);
        let rest = (1..20_000).map(|i| (if i % 2 == 0 { BinOp::Add } else { BinOp::Sub }, name("K", 2 * i)));
        let long = sum(name("K", 0), rest.collect());
        assert!(depth(&long) <= 16, "depth {}", depth(&long));
        assert_eq!(long.span, 0..39_999);
    }
}
