//! Event expressions read: in comes the text of a scalar expression of named values (states,
//! output columns, parameters, `t`) with optional time derivatives (`X'`, `(e)'`, `DT(e)`); out
//! goes its expression in an arena, derivatives taken symbolically (the chain rule: each name's
//! rate is a symbol of its own), which [`crate::program::event::lower`] turns into an
//! [`EventCode`].

use std::ops::Range;

use rustc_hash::FxHashMap;
use thiserror::Error;

use crate::expr::{Arena, ExprId, Func, SymbolId, SymbolKind};
use crate::program::event::{self, EventCode, EventSlot};

use super::{parse_expression, BinOp, Expr, ExprKind};

/// A name an event expression may read.
#[derive(Clone, Debug, PartialEq)]
pub struct EventName {
    /// The name (matched regardless of case).
    pub name: String,
    /// Whether it changes in time (a state or output) or not (a parameter: its rate is zero).
    pub varies: bool,
}

/// Why an event expression cannot be lowered: where in its text, what, and what to do.
#[derive(Clone, Debug, PartialEq, Error)]
#[error("{message}")]
pub struct EventExprError {
    /// Byte range in the expression's text.
    pub span: Range<usize>,
    /// What is wrong.
    pub message: String,
    /// What to do.
    pub help: String,
}

type Res<T> = Result<T, EventExprError>;

/// Parses `src`, differentiates where it asks and lowers it, reading `names` (and `t`, `pi`,
/// unless `names` has those: the model's names come first).
pub fn lower_event(src: &str, names: &[EventName]) -> Res<EventCode> {
    let ast = parse_expression(src).map_err(|d| EventExprError {
        span: d.span,
        message: d.message,
        help: d.help.unwrap_or_else(|| "write an expression such as `ELEVATION'` or `Q2 - 80`".into()),
    })?;
    let mut b = Builder { ar: Arena::new(), names, symbols: FxHashMap::default() };
    let root = b.expr(&ast, false)?;
    // The rates `DT` made (it declares `X'` for each name it meets): known by their symbols.
    for (i, v) in b.symbols.iter_mut() {
        if b.names[*i].varies {
            v.1 = Some(b.ar.derivative_symbol(v.0).map_err(arith(&ast.span))?);
        }
    }
    let reads = |s: SymbolId| {
        b.symbols.iter().find_map(|(&i, v)| match v {
            (value, _) if *value == s => Some(EventSlot::Value(i)),
            (_, Some(rate)) if *rate == s => Some(EventSlot::Rate(i)),
            _ => None,
        })
    };
    Ok(event::lower(&b.ar, root, reads))
}

/// The arena being built and the symbols declared for the names read.
struct Builder<'a> {
    ar: Arena,
    names: &'a [EventName],
    /// Name index -> its symbol and, once asked for, its rate's symbol.
    symbols: FxHashMap<usize, (SymbolId, Option<SymbolId>)>,
}

fn error(span: &Range<usize>, message: String, help: &str) -> EventExprError {
    EventExprError { span: span.clone(), message, help: help.to_string() }
}

/// An arena failure (an exact division by zero, an overflow) at `span`.
fn arith(span: &Range<usize>) -> impl Fn(crate::expr::ExprError) -> EventExprError + '_ {
    move |e| error(span, format!("{e}"), "rewrite this part of the expression")
}

impl Builder<'_> {
    /// `e` in the arena; `inside_dt` when it is being differentiated already.
    fn expr(&mut self, e: &Expr, inside_dt: bool) -> Res<ExprId> {
        let span = &e.span;
        match &e.kind {
            ExprKind::Number { value, suffix: 0 } => self.number(*value, span),
            ExprKind::Name { name, primes, suffix: 0 } => self.name(name, *primes, inside_dt, span),
            ExprKind::Call { name, args } => self.call(name, args, inside_dt, span),
            ExprKind::Neg(x) => {
                let x = self.expr(x, inside_dt)?;
                self.ar.neg(x).map_err(arith(span))
            }
            ExprKind::Binary(op, a, b) => {
                let (a, b) = (self.expr(a, inside_dt)?, self.expr(b, inside_dt)?);
                let r = match op {
                    BinOp::Add => self.ar.add(&[a, b]),
                    BinOp::Sub => self.ar.sub(a, b),
                    BinOp::Mul => self.ar.mul(&[a, b]),
                    BinOp::Div => self.ar.div(a, b),
                    BinOp::Pow => self.ar.pow(a, b),
                };
                r.map_err(arith(span))
            }
            _ => Err(error(
                span,
                "this is not a scalar expression".into(),
                "use numbers, names, + - * / ^, parentheses, functions and ' (no vectors, matrices or ranges)",
            )),
        }
    }

    /// A number: whole numbers exact (so `x^2` differentiates as a power of two).
    fn number(&mut self, v: f64, span: &Range<usize>) -> Res<ExprId> {
        if v.fract() == 0.0 && v.abs() < 1e15 {
            return Ok(self.ar.integer(v as i128));
        }
        self.ar.float(v).map_err(arith(span))
    }

    /// A name, `t` or `pi`, with at most one prime.
    fn name(&mut self, name: &str, primes: u8, inside_dt: bool, span: &Range<usize>) -> Res<ExprId> {
        if primes > 1 || (primes == 1 && inside_dt) {
            return Err(error(
                span,
                "only one time derivative is supported".into(),
                "write X' or (expression)'",
            ));
        }
        let known = self.names.iter().position(|n| n.name.eq_ignore_ascii_case(name));
        let Some(i) = known else {
            return match name.to_ascii_lowercase().as_str() {
                "t" if primes == 0 => Ok(self.ar.time()),
                "t" => Ok(self.ar.one()),
                "pi" if primes == 0 => self.ar.float(std::f64::consts::PI).map_err(arith(span)),
                "pi" => Ok(self.ar.zero()),
                _ => Err(self.unknown(name, span)),
            };
        };
        let sym = self.symbol(i, span)?;
        if primes == 0 {
            return Ok(self.ar.symbol_expr(sym));
        }
        if !self.names[i].varies {
            return Ok(self.ar.zero());
        }
        let rate = self.ar.derivative_symbol(sym).map_err(arith(span))?;
        Ok(self.ar.symbol_expr(rate))
    }

    /// The symbol of name `i`, declared on first use (as a constant when it does not vary).
    fn symbol(&mut self, i: usize, span: &Range<usize>) -> Res<SymbolId> {
        if let Some(v) = self.symbols.get(&i) {
            return Ok(v.0);
        }
        let name = format!("{}__{i}", self.names[i].name.to_ascii_uppercase());
        let kind =
            if self.names[i].varies { SymbolKind::Variable { order: 0 } } else { SymbolKind::Constant };
        let sym = self.ar.declare(&name, kind).map_err(arith(span))?;
        self.symbols.insert(i, (sym, None));
        Ok(sym)
    }

    fn unknown(&self, name: &str, span: &Range<usize>) -> EventExprError {
        let mut known: Vec<&str> = self.names.iter().map(|n| n.name.as_str()).collect();
        known.truncate(40);
        error(
            span,
            format!("unknown name `{name}`"),
            &format!(
                "an event reads t, pi and these states, output columns and parameters: {}",
                known.join(", ")
            ),
        )
    }

    /// A function call: the elementary functions, `sqrt`, `atan2` and `DT` (`(e)'`).
    fn call(&mut self, name: &str, args: &[Expr], inside_dt: bool, span: &Range<usize>) -> Res<ExprId> {
        let upper = name.to_ascii_uppercase();
        let want = if upper == "ATAN2" { 2 } else { 1 };
        if args.len() != want {
            return Err(error(
                span,
                format!("{name} takes {want} argument(s), not {}", args.len()),
                "check the call",
            ));
        }
        match upper.as_str() {
            "DT" => {
                if inside_dt {
                    return Err(error(
                        span,
                        "only one time derivative is supported".into(),
                        "write (expression)' once",
                    ));
                }
                let x = self.expr(&args[0], true)?;
                self.ar.dt(x).map_err(arith(span))
            }
            "SQRT" => {
                let x = self.expr(&args[0], inside_dt)?;
                self.ar.sqrt(x).map_err(arith(span))
            }
            "ATAN2" => {
                let (y, x) = (self.expr(&args[0], inside_dt)?, self.expr(&args[1], inside_dt)?);
                self.ar.atan2(y, x).map_err(arith(span))
            }
            _ => {
                let f = match upper.as_str() {
                    "LOG" => Some(Func::Ln),
                    _ => Func::from_name(name),
                };
                let Some(f) = f else {
                    return Err(error(
                        span,
                        format!("unknown function `{name}`"),
                        "functions: sin cos tan asin acos atan atan2 sqrt abs sign exp ln sinh cosh tanh",
                    ));
                };
                let x = self.expr(&args[0], inside_dt)?;
                self.ar.func(f, x).map_err(arith(span))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::program::ir::Input;

    fn names() -> Vec<EventName> {
        let n = |name: &str, varies| EventName { name: name.into(), varies };
        vec![n("Q2", true), n("ELEVATION", true), n("M", false)]
    }

    /// Runs `code` with `values` for the names and `rates` for their rates at time `t`.
    fn run(code: &EventCode, t: f64, values: &[f64], rates: &[f64]) -> f64 {
        let read = |i: Input| match i {
            Input::Slot(k) => match code.slots[k] {
                EventSlot::Time => t,
                EventSlot::Value(j) => values[j],
                EventSlot::Rate(j) => rates[j],
            },
            _ => f64::NAN,
        };
        let mut out = [0.0];
        code.section.eval(read, &mut out);
        out[0]
    }

    #[test]
    fn values_rates_and_the_chain_rule() {
        let code = lower_event("q2 - 2*M + t", &names()).unwrap();
        assert_eq!(run(&code, 0.5, &[3.0, 0.0, 1.0], &[0.0; 3]), 1.5);
        let code = lower_event("(sin(Q2)*ELEVATION^2 + M*t)'", &names()).unwrap();
        let (q, e, dq, de) = (0.7f64, 1.3f64, 0.2, -0.4);
        let want = q.cos() * dq * e * e + q.sin() * 2.0 * e * de + 2.0;
        let got = run(&code, 9.0, &[q, e, 2.0], &[dq, de, 0.0]);
        assert!((got - want).abs() < 1e-14, "{got} vs {want}");
        assert!(code.slots.contains(&EventSlot::Rate(0)) && code.slots.contains(&EventSlot::Rate(1)));
        let code = lower_event("ELEVATION'", &names()).unwrap();
        assert_eq!(code.slots, vec![EventSlot::Rate(1)]);
    }

    #[test]
    fn errors_name_the_place() {
        let e = lower_event("Q2 + Q9", &names()).unwrap_err();
        assert_eq!((e.span.clone(), e.message.as_str()), (5..7, "unknown name `Q9`"), "{e:?}");
        let e = lower_event("Q2 + * 3", &names()).unwrap_err();
        assert_eq!(e.span.start, 5, "{e:?}");
        assert!(lower_event("Q2''", &names()).unwrap_err().message.contains("one time derivative"));
        assert!(lower_event("(Q2')'", &names()).unwrap_err().message.contains("one time derivative"));
        assert!(lower_event("foo(Q2)", &names()).unwrap_err().message.contains("unknown function"));
        assert!(lower_event("Q2 $", &names()).unwrap_err().message.contains("unexpected character"));
    }
}
