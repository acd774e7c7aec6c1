//! Autolev-like plain text: `m*L^2*sin(q1)/2 - u1'`.

use rustc_hash::FxHashMap;

use super::super::arena::Arena;
use super::super::node::{ExprId, Func, SymbolId};
use super::super::number::Number;
use super::layout::{layout, Prec, Syntax};

struct Text<'a> {
    ar: &'a Arena,
    names: Option<&'a FxHashMap<ExprId, String>>,
}

fn wrap(x: (String, Prec), min: Prec) -> String {
    if x.1 < min {
        format!("({})", x.0)
    } else {
        x.0
    }
}

impl Syntax for Text<'_> {
    type Out = String;
    fn number(&mut self, n: Number) -> String {
        match n {
            Number::Rational(r) => r.to_string(),
            Number::Float(x) => format!("{x:?}"),
        }
    }
    fn symbol(&mut self, s: SymbolId) -> String {
        self.ar.symbol_info(s).name.clone()
    }
    fn named(&mut self, id: ExprId) -> Option<String> {
        self.names.and_then(|n| n.get(&id).cloned())
    }
    fn paren(&mut self, x: String) -> String {
        format!("({x})")
    }
    fn sum(&mut self, terms: Vec<(bool, String)>) -> String {
        let mut s = String::new();
        for (i, (neg, t)) in terms.into_iter().enumerate() {
            match (i, neg) {
                (0, true) => s.push('-'),
                (0, false) => {}
                (_, true) => s.push_str(" - "),
                (_, false) => s.push_str(" + "),
            }
            s.push_str(&t);
        }
        s
    }
    fn neg(&mut self, x: (String, Prec)) -> String {
        format!("-{}", wrap(x, Prec::Product))
    }
    fn product(&mut self, factors: Vec<(String, Prec)>) -> String {
        factors.into_iter().map(|f| wrap(f, Prec::Product)).collect::<Vec<_>>().join("*")
    }
    fn quotient(&mut self, num: (String, Prec), den: (String, Prec)) -> String {
        format!("{}/{}", wrap(num, Prec::Product), wrap(den, Prec::Pow))
    }
    fn pow_int(&mut self, base: (String, Prec), k: i64) -> String {
        format!("{}^{k}", wrap(base, Prec::Atom))
    }
    fn pow(&mut self, base: (String, Prec), exp: (String, Prec)) -> String {
        format!("{}^{}", wrap(base, Prec::Atom), wrap(exp, Prec::Atom))
    }
    fn sqrt(&mut self, (x, _): (String, Prec)) -> String {
        format!("sqrt({x})")
    }
    fn func(&mut self, f: Func, (x, _): (String, Prec)) -> String {
        format!("{}({x})", f.name())
    }
    fn atan2(&mut self, y: String, x: String) -> String {
        format!("atan2({y}, {x})")
    }
}

impl Arena {
    /// Plain Autolev-like text, for example `m*L^2*sin(q1)/2 - u1'`.
    pub fn to_text(&self, e: ExprId) -> String {
        layout(self, e, &mut Text { ar: self, names: None }, true).0
    }

    /// Plain text in which the subexpressions in `names` are written by name.
    pub fn to_text_named(&self, e: ExprId, names: &FxHashMap<ExprId, String>) -> String {
        layout(self, e, &mut Text { ar: self, names: Some(names) }, true).0
    }
}

#[cfg(test)]
mod tests {
    use crate::expr::Arena;

    #[test]
    fn prints_like_autolev() {
        let mut ar = Arena::new();
        let [m, l] = ["m", "L"].map(|n| ar.constant(n).unwrap());
        let q = ar.variable("q1").unwrap();
        let qs = ar.as_symbol(q).unwrap();
        let qd = ar.derivative_symbol(qs).unwrap();
        let qd = ar.symbol_expr(qd);
        let half = ar.rational(1, 2).unwrap();
        let l2 = ar.powi(l, 2).unwrap();
        let s = ar.sin(q).unwrap();
        let t = ar.mul(&[half, m, l2, s]).unwrap();
        let e = ar.sub(t, qd).unwrap();
        let text = ar.to_text(e);
        assert!(text == "m*L^2*sin(q1)/2 - q1'" || text == "-q1' + m*L^2*sin(q1)/2", "{text}");
    }

    #[test]
    fn quotients_negatives_and_roots() {
        let mut ar = Arena::new();
        let [x, y] = ["x", "y"].map(|n| ar.constant(n).unwrap());
        let q = ar.div(x, y).unwrap();
        assert_eq!(ar.to_text(q), "x/y");
        let s = ar.add(&[x, y]).unwrap();
        let r = ar.sqrt(s).unwrap();
        assert_eq!(ar.to_text(r), "sqrt(x + y)");
        let inv = ar.powi(s, -2).unwrap();
        assert_eq!(ar.to_text(inv), "1/(x + y)^2");
        let n = ar.neg(x).unwrap();
        assert_eq!(ar.to_text(n), "-x");
        let three = ar.integer(3);
        let d = ar.sub(three, x).unwrap();
        assert_eq!(ar.to_text(d), "-x + 3");
        let f = ar.float(0.25).unwrap();
        let g = ar.mul(&[f, x]).unwrap();
        assert_eq!(ar.to_text(g), "0.25*x");
        let a = ar.atan2(y, x).unwrap();
        assert_eq!(ar.to_text(a), "atan2(y, x)");
    }
}
