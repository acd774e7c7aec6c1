//! POLYNOMIAL and ROOTS: polynomials in one symbol by their coefficients, highest power first.
//!
//! In: `POLYNOMIAL([c1, ..., cn], X)`, `POLYNOMIAL(P, X, N)`, `ROOTS(P, X[, N])` and
//! `ROOTS([c1; ...; cn])`. Out: the polynomial `c1 X^(n-1) + ... + cn`; the row of P's
//! coefficients of `X^N` down to `X^0`; the column of the roots, ascending.
//!
//! What this follows: SymPy's guide "SymPy Mechanics for Autolev Users" translates
//! `Polynomial([a, b, c], x)` to the polynomial a x^2 + b x + c, and
//! `Roots(Polynomial(a*x^2 + b*x + c, x, 2))` and `Roots([1;2;3])` to the roots of those;
//! SymPy's Autolev parser tests (ruletest6.al) write `POLYNOMIAL([J,K,L],X)`,
//! `POLYNOMIAL(J*X+K,X,1)` and `ROOTS(P1, X, 2)`. So coefficients run from the highest power
//! to the constant, a row or a column alike, and `POLYNOMIAL(P, X, N)` gives P's N + 1
//! coefficients of X, highest first, as a row (which POLYNOMIAL turns back into P). A P with
//! a power of X above N, or that is no polynomial in X (after expansion), is an error rather
//! than a truncation. ROOTS with number coefficients has any degree (the companion matrix's
//! eigenvalues); with symbols, degree 1 and 2 (by formula, the smaller root first when the
//! leading coefficient is positive). Complex roots are an error naming them, as EIG's complex
//! eigenvalues are: values here are real.

use rustc_hash::FxHashMap;

use crate::expr::ExprId;

use super::super::ast::Expr;
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::poly_roots::real_roots;
use super::value::Value;
use super::{At, IResult, Interpreter};

/// The highest power POLYNOMIAL and ROOTS take from an expression (`k!` stays in an `i128`).
const HIGHEST_POWER: i64 = 30;

impl Interpreter {
    /// POLYNOMIAL or ROOTS.
    pub(super) fn polynomial_function(&mut self, upper: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        match (upper, args) {
            ("POLYNOMIAL", [c, x]) => {
                let c = self.coefficient_list(c)?;
                let x = self.scalar(x)?;
                Ok(Value::Scalar(self.polynomial(&c, x).at(&e.span)?))
            }
            ("POLYNOMIAL", [p, x, n]) => {
                let c = self.coefficients_in(p, x, Some(n))?;
                Ok(Value::Matrix { rows: 1, cols: c.len(), data: c })
            }
            ("ROOTS", [c]) => {
                let c = self.coefficient_list(c)?;
                self.roots(c, e)
            }
            ("ROOTS", [p, x, rest @ ..]) if rest.len() < 2 => {
                let c = self.coefficients_in(p, x, rest.first())?;
                self.roots(c, e)
            }
            _ => Err(Diagnostic::error(e.span.clone(), format!("{upper} takes other arguments")).with_help(
                if upper == "ROOTS" {
                    "ROOTS(P, X, N) for a polynomial P of degree N in X, or ROOTS([c1; ...; cn]) of coefficients"
                } else {
                    "POLYNOMIAL([c1, ..., cn], X) builds c1*X^(n-1) + ... + cn; POLYNOMIAL(P, X, N) gives P's coefficients"
                },
            )),
        }
    }

    /// A row or column of coefficients (a scalar is one).
    fn coefficient_list(&mut self, a: &Expr) -> IResult<Vec<ExprId>> {
        match self.eval(a)? {
            Value::Scalar(x) => Ok(vec![x]),
            Value::Matrix { rows, cols, data } if rows == 1 || cols == 1 => Ok(data),
            other => Err(Diagnostic::error(
                a.span.clone(),
                format!("expected a row or column of coefficients, found {}", describe(&other)),
            )
            .with_help("coefficients run from the highest power down: [J, K, L] is J*X^2 + K*X + L")),
        }
    }

    /// `c[0] x^(n-1) + ... + c[n-1]`.
    fn polynomial(&mut self, c: &[ExprId], x: ExprId) -> Result<ExprId, crate::expr::ExprError> {
        let ar = &mut self.model.ar;
        let mut terms = Vec::with_capacity(c.len());
        for (k, ck) in c.iter().rev().enumerate() {
            let power = ar.powi(x, k as i64)?;
            terms.push(ar.mul(&[*ck, power])?);
        }
        ar.add(&terms)
    }

    /// The coefficients of the symbol `x` in `p`, highest power first: `n + 1` of them when `n`
    /// is given (an error if `p` has a higher power), else up to `p`'s degree. The coefficient
    /// of `x^k` is the k-th derivative at `x = 0` over `k!`, of `p` expanded.
    fn coefficients_in(&mut self, p: &Expr, x: &Expr, n: Option<&Expr>) -> IResult<Vec<ExprId>> {
        let (pv, xv) = (self.scalar(p)?, self.scalar(x)?);
        let s = self.model.ar.as_symbol(xv).ok_or_else(|| {
            Diagnostic::error(x.span.clone(), "expected the symbol the polynomial is in here")
                .with_help("a polynomial is in a name declared with CONSTANTS or VARIABLES")
        })?;
        let most = match n {
            Some(n) => match self.index_value(n)? {
                k @ 0..=HIGHEST_POWER => Some(k),
                k => {
                    return Err(Diagnostic::error(
                        n.span.clone(),
                        format!("a polynomial's degree here is 0 to {HIGHEST_POWER}, not {k}"),
                    ))
                }
            },
            None => None,
        };
        let span = &p.span;
        let ar = &mut self.model.ar;
        let at_zero: FxHashMap<ExprId, ExprId> = [(xv, ar.zero())].into_iter().collect();
        let mut d = ar.expand(pv).at(span)?;
        let mut ascending = Vec::new();
        let mut factorial: i128 = 1;
        for k in 0..=HIGHEST_POWER + 1 {
            if ar.is_zero(d) {
                break;
            }
            if k > most.unwrap_or(HIGHEST_POWER) {
                let within = most.map_or(format!("of degree {HIGHEST_POWER} or less"), |n| {
                    format!("of degree {n} or less")
                });
                return Err(Diagnostic::error(
                    span.clone(),
                    format!("this is not a polynomial in {} {within} (its expansion has a term in {0}^{k} or no polynomial form)", ar.symbol_info(s).name),
                )
                .with_help("ROOTS(P, X, N) and POLYNOMIAL(P, X, N) need P a polynomial of degree N or less in X"));
            }
            factorial *= i128::from(k.max(1));
            let value = ar.subs(d, &at_zero).at(span)?;
            let inverse = ar.rational(1, factorial).at(span)?;
            ascending.push(ar.mul(&[inverse, value]).at(span)?);
            let next = ar.diff(d, s).at(span)?;
            d = ar.expand(next).at(span)?;
        }
        if let Some(n) = most {
            ascending.resize(n as usize + 1, ar.zero());
        }
        ascending.reverse();
        Ok(ascending)
    }

    /// The roots of the polynomial with coefficients `c` (highest power first), as a column.
    fn roots(&mut self, c: Vec<ExprId>, e: &Expr) -> IResult<Value> {
        let numbers = self.model.ar.eval::<f64>(&c, |_| None).ok();
        let ar = &self.model.ar;
        let kept = match &numbers {
            Some(v) => v.iter().skip_while(|x| **x == 0.0).count(),
            None => c.iter().skip_while(|x| ar.is_zero(**x)).count(),
        };
        if kept < 2 {
            let what = if kept == 0 { "zero: every value is a root" } else { "a constant: it has no roots" };
            return Err(Diagnostic::error(e.span.clone(), format!("ROOTS: the polynomial is {what}"))
                .with_help("ROOTS needs a polynomial of degree 1 or more"));
        }
        if let Some(x) = numbers.iter().flatten().find(|x| !x.is_finite()) {
            return Err(Diagnostic::error(
                e.span.clone(),
                format!("ROOTS needs finite coefficients, not {x}"),
            ));
        }
        match numbers {
            Some(v) => self.number_roots(&v, &e.span),
            None => Ok(Value::column(self.symbolic_roots(&c[c.len() - kept..], &e.span)?)),
        }
    }

    /// The real roots of number coefficients as a column; complex ones as Autolev's session
    /// shows them (a model cannot use them).
    fn number_roots(&mut self, c: &[f64], span: &Span) -> IResult<Value> {
        match real_roots(c) {
            Ok(roots) => {
                let column =
                    roots.into_iter().map(|r| self.model.ar.float(r)).collect::<Result<_, _>>().at(span)?;
                Ok(Value::column(column))
            }
            Err(z) => Ok(Value::Shown(complex_column(z))),
        }
    }

    /// Degree 1 and 2 with symbols in the coefficients, by formula.
    fn symbolic_roots(&mut self, c: &[ExprId], span: &Span) -> IResult<Vec<ExprId>> {
        let ar = &mut self.model.ar;
        match *c {
            [a, b] => {
                let r = ar.div(b, a).at(span)?;
                Ok(vec![ar.neg(r).at(span)?])
            }
            [a, b, c] => {
                // (-b -+ sqrt(b^2 - 4 a c)) / (2 a)
                let (b2, four) = (ar.powi(b, 2).at(span)?, ar.integer(4));
                let four_ac = ar.mul(&[four, a, c]).at(span)?;
                let disc = ar.sub(b2, four_ac).at(span)?;
                if let Ok([d]) = ar.eval::<f64>(&[disc], |_| None).as_deref() {
                    if *d < 0.0 {
                        return Err(Diagnostic::error(
                            span.clone(),
                            format!("ROOTS: the polynomial has complex roots (its discriminant is {d}), which values here cannot hold"),
                        ));
                    }
                }
                let root = ar.sqrt(disc).at(span)?;
                let two = ar.integer(2);
                let two_a = ar.mul(&[two, a]).at(span)?;
                let minus_b = ar.neg(b).at(span)?;
                let mut out = Vec::with_capacity(2);
                for sign in [-1, 1] {
                    let sign = ar.integer(sign);
                    let signed = ar.mul(&[sign, root]).at(span)?;
                    let top = ar.add(&[minus_b, signed]).at(span)?;
                    out.push(ar.div(top, two_a).at(span)?);
                }
                Ok(out)
            }
            _ => Err(Diagnostic::error(
                span.clone(),
                format!("ROOTS of a polynomial of degree {} with symbols in its coefficients is not supported", c.len() - 1),
            )
            .with_help("with symbols, ROOTS solves degree 1 and 2; EVALUATE the coefficients to numbers for any degree")),
        }
    }
}

/// "a matrix of 2x3", "a vector", ... for messages.
fn describe(v: &Value) -> String {
    match v {
        Value::Matrix { rows, cols, .. } => format!("a {rows}x{cols} matrix"),
        other => other.kind().to_string(),
    }
}

/// `[a + bi; c - di]`, sorted by real then imaginary part.
pub(super) fn complex_column(mut z: Vec<nalgebra::Complex<f64>>) -> String {
    z.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
    let named: Vec<String> = z
        .iter()
        .map(|z| match z.im {
            0.0 => format!("{}", z.re),
            im => format!("{} {} {}i", z.re, if im < 0.0 { '-' } else { '+' }, im.abs()),
        })
        .collect();
    format!("[{}]", named.join("; "))
}
