//! LaTeX: `\frac{m L^{2} \sin\left(q_{1}\right)}{2} - \dot{q}_{1}`.

use rustc_hash::FxHashMap;

use super::super::arena::Arena;
use super::super::node::{ExprId, Func, SymbolId, SymbolKind};
use super::super::number::Number;
use super::layout::{layout, Prec, Syntax};

struct Latex<'a> {
    ar: &'a Arena,
    names: Option<&'a FxHashMap<ExprId, String>>,
}

const GREEK: [&str; 24] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "zeta", "eta", "theta", "iota", "kappa", "lambda", "mu",
    "nu", "xi", "omicron", "pi", "rho", "sigma", "tau", "upsilon", "phi", "chi", "psi", "omega",
];

/// `q1''` -> `\ddot{q}_{1}`, `theta` -> `\theta`, `I_B` -> `I_{B}`.
pub(super) fn symbol_latex(name: &str, order: u32) -> String {
    let base = name.trim_end_matches('\'');
    let split = base.find(|c: char| c.is_ascii_digit() || c == '_').unwrap_or(base.len());
    let (stem, rest) = base.split_at(split);
    let stem = if GREEK.contains(&stem.to_ascii_lowercase().as_str()) {
        format!("\\{}", stem.to_ascii_lowercase())
    } else if stem.len() > 1 {
        format!("\\mathrm{{{stem}}}")
    } else {
        stem.to_string()
    };
    let stem = match order {
        0 => stem,
        1 => format!("\\dot{{{stem}}}"),
        2 => format!("\\ddot{{{stem}}}"),
        _ => stem,
    };
    let sub = rest.trim_start_matches('_');
    let mut s = if sub.is_empty() { stem } else { format!("{stem}_{{{sub}}}") };
    if order > 2 {
        s = format!("{s}^{{({order})}}");
    }
    s
}

fn wrap(x: (String, Prec), min: Prec) -> String {
    if x.1 < min {
        format!("\\left({}\\right)", x.0)
    } else {
        x.0
    }
}

impl Syntax for Latex<'_> {
    type Out = String;
    fn number(&mut self, n: Number) -> String {
        match n {
            Number::Rational(r) => r.to_string(),
            Number::Float(x) => format!("{x:?}"),
        }
    }
    fn symbol(&mut self, s: SymbolId) -> String {
        let info = self.ar.symbol_info(s);
        let order = match info.kind {
            SymbolKind::Variable { order } | SymbolKind::Specified { order } => order,
            _ => 0,
        };
        symbol_latex(&info.name, order)
    }
    fn named(&mut self, id: ExprId) -> Option<String> {
        self.names.and_then(|n| n.get(&id)).map(|name| symbol_latex(name, 0))
    }
    fn paren(&mut self, x: String) -> String {
        format!("\\left({x}\\right)")
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
        let parts: Vec<String> = factors.into_iter().map(|f| wrap(f, Prec::Product)).collect();
        let mut s = String::new();
        for (i, p) in parts.iter().enumerate() {
            if i > 0 {
                let digit_next = p.starts_with(|c: char| c.is_ascii_digit());
                s.push_str(if digit_next { " \\cdot " } else { " " });
            }
            s.push_str(p);
        }
        s
    }
    fn quotient(&mut self, num: (String, Prec), den: (String, Prec)) -> String {
        format!("\\frac{{{}}}{{{}}}", num.0, den.0)
    }
    fn pow_int(&mut self, base: (String, Prec), k: i64) -> String {
        format!("{}^{{{k}}}", wrap(base, Prec::Atom))
    }
    fn pow(&mut self, base: (String, Prec), exp: (String, Prec)) -> String {
        format!("{}^{{{}}}", wrap(base, Prec::Atom), exp.0)
    }
    fn sqrt(&mut self, (x, _): (String, Prec)) -> String {
        format!("\\sqrt{{{x}}}")
    }
    fn func(&mut self, f: Func, (x, _): (String, Prec)) -> String {
        let name = match f {
            Func::Asin => "\\arcsin".to_string(),
            Func::Acos => "\\arccos".to_string(),
            Func::Atan => "\\arctan".to_string(),
            Func::Abs => return format!("\\left|{x}\\right|"),
            Func::Sign => "\\operatorname{sign}".to_string(),
            _ => format!("\\{}", f.name()),
        };
        format!("{name}\\left({x}\\right)")
    }
    fn atan2(&mut self, y: String, x: String) -> String {
        format!("\\operatorname{{atan2}}\\left({y}, {x}\\right)")
    }
}

impl Arena {
    /// LaTeX for `e`, with `q1'` as `\dot{q}_{1}` and quotients as `\frac`.
    pub fn to_latex(&self, e: ExprId) -> String {
        layout(self, e, &mut Latex { ar: self, names: None }, true).0
    }

    /// LaTeX in which the subexpressions in `names` are written by name (`z12` as `z_{12}`).
    pub fn to_latex_named(&self, e: ExprId, names: &FxHashMap<ExprId, String>) -> String {
        layout(self, e, &mut Latex { ar: self, names: Some(names) }, true).0
    }
}

#[cfg(test)]
mod tests {
    use crate::expr::Arena;

    #[test]
    fn prints_fractions_dots_and_functions() {
        let mut ar = Arena::new();
        let [m, l] = ["m", "L"].map(|n| ar.constant(n).unwrap());
        let q = ar.variable("q1").unwrap();
        let qs = ar.as_symbol(q).unwrap();
        let qd = ar.derivative_symbol(qs).unwrap();
        let qd = ar.symbol_expr(qd);
        let half = ar.rational(1, 2).unwrap();
        let l2 = ar.powi(l, 2).unwrap();
        let s = ar.sin(q).unwrap();
        let t = ar.mul(&[half, m, l2, s, qd]).unwrap();
        let text = ar.to_latex(t);
        assert!(text.starts_with("\\frac{"), "{text}");
        assert!(text.contains("\\sin\\left(q_{1}\\right)"), "{text}");
        assert!(text.contains("\\dot{q}_{1}"), "{text}");
        assert!(text.contains("L^{2}"), "{text}");
        assert!(text.ends_with("}{2}"), "{text}");
        let th = ar.constant("theta").unwrap();
        let r = ar.sqrt(th).unwrap();
        assert_eq!(ar.to_latex(r), "\\sqrt{\\theta}");
    }
}
