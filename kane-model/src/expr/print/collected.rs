//! Printing a [`Collected`] expression: `(K2 - K1)*sin(Q2)^2*U1' - Y`, in text or LaTeX.

use rustc_hash::FxHashMap;

use super::super::arena::Arena;
use super::super::node::ExprId;
use super::super::tidy::{Collected, CollectedTerm};

/// How the pieces are spelled, and the names some subexpressions are written by.
struct Style<'a> {
    open: &'static str,
    close: &'static str,
    latex: bool,
    names: Option<&'a FxHashMap<ExprId, String>>,
}

impl<'a> Style<'a> {
    fn text(names: Option<&'a FxHashMap<ExprId, String>>) -> Style<'a> {
        Style { open: "(", close: ")", latex: false, names }
    }

    fn latex(names: Option<&'a FxHashMap<ExprId, String>>) -> Style<'a> {
        Style { open: "\\left(", close: "\\right)", latex: true, names }
    }

    /// One piece (a coefficient summand or a factor), by its name when it has one.
    fn piece(&self, ar: &Arena, x: ExprId) -> String {
        match (self.names, self.latex) {
            (Some(names), false) => names.get(&x).cloned().unwrap_or_else(|| ar.to_text_named(x, names)),
            (Some(names), true) => match names.get(&x) {
                Some(name) => super::latex::symbol_latex(name, 0),
                None => ar.to_latex_named(x, names),
            },
            (None, false) => ar.to_text(x),
            (None, true) => ar.to_latex(x),
        }
    }

    /// Factors joined by `*`, or in LaTeX by a space (`\cdot` before a digit).
    fn join(&self, parts: Vec<String>) -> String {
        let mut s = String::new();
        for (i, p) in parts.into_iter().enumerate() {
            if i > 0 {
                s.push_str(match (self.latex, p.starts_with(|c: char| c.is_ascii_digit())) {
                    (false, _) => "*",
                    (true, true) => " \\cdot ",
                    (true, false) => " ",
                });
            }
            s.push_str(&p);
        }
        s
    }

    /// `a - b + c` from `(subtracted, magnitude)` pairs.
    fn signed_sum(&self, ar: &Arena, parts: &[(bool, ExprId)]) -> String {
        let mut s = String::new();
        for (i, (neg, x)) in parts.iter().enumerate() {
            s.push_str(match (i, neg) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            });
            // A summand is never a sum, so it needs no parentheses.
            s.push_str(&self.piece(ar, *x));
        }
        s
    }

    /// The magnitude of one term.
    fn term(&self, ar: &Arena, t: &CollectedTerm) -> String {
        let mut parts = Vec::new();
        if let Some(k) = t.scale {
            parts.push(self.piece(ar, k));
        }
        if !t.inner.is_empty() {
            let inner = self.collected(ar, &Collected { terms: t.inner.clone() });
            let bare = t.factors.is_empty() && !t.negative;
            parts.push(if bare { inner } else { format!("{}{inner}{}", self.open, self.close) });
        }
        if let Some(text) = self.over_whole_number(ar, t) {
            return text;
        }
        match t.coefficient.len() {
            0 => {}
            _ if t.scale.is_some() => {
                parts.push(format!("{}{}{}", self.open, self.signed_sum(ar, &t.coefficient), self.close))
            }
            1 if !t.coefficient[0].0 => parts.push(self.signed_sum(ar, &t.coefficient)),
            _ if t.factors.is_empty() && !t.negative => parts.push(self.signed_sum(ar, &t.coefficient)),
            _ => parts.push(format!("{}{}{}", self.open, self.signed_sum(ar, &t.coefficient), self.close)),
        }
        parts.extend(t.factors.iter().map(|f| self.piece(ar, *f)));
        if parts.is_empty() {
            parts.push("1".into());
        }
        self.join(parts)
    }

    /// In text, `E2*W3/2` rather than `1/2*E2*W3` for a fraction times the factors.
    fn over_whole_number(&self, ar: &Arena, t: &CollectedTerm) -> Option<String> {
        let ([(false, x)], false, None) = (t.coefficient.as_slice(), self.latex, t.scale) else {
            return None;
        };
        let r = ar.as_rational(*x).filter(|r| !r.is_integer() && !t.factors.is_empty())?;
        let mut parts: Vec<String> = t.factors.iter().map(|f| self.piece(ar, *f)).collect();
        if r.numer() != 1 {
            parts.insert(0, r.numer().to_string());
        }
        Some(format!("{}/{}", self.join(parts), r.denom()))
    }

    fn collected(&self, ar: &Arena, c: &Collected) -> String {
        if c.terms.is_empty() {
            return "0".into();
        }
        let mut s = String::new();
        for (i, t) in c.terms.iter().enumerate() {
            s.push_str(match (i, t.negative) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            });
            s.push_str(&self.term(ar, t));
        }
        s
    }
}

impl Arena {
    /// Plain text of a collected expression, e.g. `(K2 - K1)*sin(Q2)^2*U1' - Y`.
    pub fn collected_text(&self, c: &Collected) -> String {
        Style::text(None).collected(self, c)
    }

    /// Plain text of a collected expression in which the subexpressions in `names` are
    /// written by name.
    pub fn collected_text_named(&self, c: &Collected, names: &FxHashMap<ExprId, String>) -> String {
        Style::text(Some(names)).collected(self, c)
    }

    /// LaTeX of a collected expression, e.g. `\left(K_{2} - K_{1}\right) \sin\left(Q_{2}\right)^{2}`.
    pub fn collected_latex(&self, c: &Collected) -> String {
        Style::latex(None).collected(self, c)
    }

    /// LaTeX of a collected expression in which the subexpressions in `names` are written by
    /// name.
    pub fn collected_latex_named(&self, c: &Collected, names: &FxHashMap<ExprId, String>) -> String {
        Style::latex(Some(names)).collected(self, c)
    }
}
