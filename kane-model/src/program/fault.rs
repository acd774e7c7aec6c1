//! The operation that made a value not finite: in comes a section and the values of its inputs;
//! out goes the first instruction whose operands are finite and whose result is not (a division
//! by zero, the square root or logarithm of a negative number, an arc sine out of range, an
//! overflow), with its operands and the expression it computes, written with the model's names.

use crate::expr::Func;

use super::ir::{Input, Op, Section};

/// Most characters of an expression in a message.
const MAX_TEXT: usize = 160;

/// What went wrong in one operation.
#[derive(Clone, Debug, PartialEq)]
pub enum FaultKind {
    /// `a / 0`.
    DivisionByZero,
    /// `sqrt(a)` with `a < 0`.
    SqrtOfNegative,
    /// `ln(a)` with `a < 0`, or `ln(0)`.
    LogOfNonPositive,
    /// `asin(a)` or `acos(a)` with `|a| > 1`.
    OutsideArcDomain(&'static str),
    /// `a ^ b` with `a < 0` and `b` not an integer, or `0 ^ b` with `b < 0`.
    PowerOutsideDomain,
    /// Finite operands, an infinite result.
    Overflow,
    /// `a / b` with `b` a difference that cancels to near zero: a singularity approached.
    NearDivisionByZero,
}

/// A difference this small against its terms makes its quotient a singularity approached.
const NEAR_ZERO: f64 = 1e-9;

/// The first operation of a section whose result is not finite though its operands are.
#[derive(Clone, Debug, PartialEq)]
pub struct Fault {
    /// What went wrong.
    pub kind: FaultKind,
    /// The operands' values.
    pub operands: Vec<f64>,
    /// The operation's result.
    pub value: f64,
    /// The expression the operation computes, with the model's names.
    pub expression: String,
}

impl std::fmt::Display for Fault {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let a = self.operands.first().copied().unwrap_or(f64::NAN);
        match &self.kind {
            FaultKind::DivisionByZero => write!(f, "a division by zero ({a} / 0)"),
            FaultKind::SqrtOfNegative => write!(f, "the square root of a negative number, sqrt({a})"),
            FaultKind::LogOfNonPositive => {
                write!(f, "the logarithm of a number that is not positive, ln({a})")
            }
            FaultKind::OutsideArcDomain(name) => write!(f, "{name}({a}), outside [-1, 1]"),
            FaultKind::PowerOutsideDomain => {
                write!(
                    f,
                    "a power outside its domain, ({a})^({})",
                    self.operands.get(1).copied().unwrap_or(f64::NAN)
                )
            }
            FaultKind::Overflow => write!(f, "an overflow to {}", self.value),
            FaultKind::NearDivisionByZero => {
                write!(
                    f,
                    "a division by a difference that cancels to nearly zero ({a:e} against terms of {:e})",
                    self.operands.get(1).copied().unwrap_or(f64::NAN)
                )
            }
        }?;
        write!(f, " in `{}`", self.expression)
    }
}

/// The first faulty operation of `section` with inputs read by `read`; `name` writes an input
/// as the model names it. None when every value is finite or the first non-finite value comes
/// from a non-finite input.
pub fn first_fault(
    section: &Section,
    read: impl Fn(Input) -> f64,
    name: &dyn Fn(Input) -> String,
) -> Option<Fault> {
    let mut regs: Vec<f64> = Vec::with_capacity(section.ops.len());
    for (k, op) in section.ops.iter().enumerate() {
        let value = section.apply(op, &regs, &read);
        regs.push(value);
        if value.is_finite() || matches!(op, Op::Input(_) | Op::Const(_)) {
            continue;
        }
        let operands: Vec<f64> = operands(op).iter().map(|v| regs[*v as usize]).collect();
        if operands.iter().all(|v| v.is_finite()) {
            let kind = classify(op, &operands);
            let expression = clipped(text(section, k as u32, name, 5));
            return Some(Fault { kind, operands, value, expression });
        }
    }
    None
}

/// The quotient of `section` at the inputs `read` whose divisor is a sum or difference that
/// cancels most nearly to zero (below `NEAR_ZERO` of its largest term), named: where the
/// values are finite but a singularity is near. The fault's operands are the divisor and the
/// largest term.
pub fn near_division_by_zero(
    section: &Section,
    read: impl Fn(Input) -> f64,
    name: &dyn Fn(Input) -> String,
) -> Option<Fault> {
    let mut regs: Vec<f64> = Vec::with_capacity(section.ops.len());
    for op in &section.ops {
        let value = section.apply(op, &regs, &read);
        regs.push(value);
    }
    let cancellation = |d: u32| match section.ops[d as usize] {
        Op::Add(a, b) | Op::Sub(a, b) => {
            let scale = regs[a as usize].abs().max(regs[b as usize].abs());
            (scale > 0.0).then(|| (regs[d as usize].abs() / scale, scale))
        }
        _ => None,
    };
    let divisor = |op: &Op| match *op {
        Op::Div(_, b) => Some(b),
        Op::Powi(a, k) if k < 0 => Some(a),
        _ => None,
    };
    let (k, d, scale) = section
        .ops
        .iter()
        .enumerate()
        .filter_map(|(k, op)| {
            divisor(op).and_then(|d| cancellation(d).map(|(rel, scale)| (k, d, rel, scale)))
        })
        .filter(|c| c.2 < NEAR_ZERO)
        .min_by(|x, y| x.2.total_cmp(&y.2))
        .map(|(k, d, _, scale)| (k, d, scale))?;
    let expression = clipped(text(section, k as u32, name, 5));
    Some(Fault {
        kind: FaultKind::NearDivisionByZero,
        operands: vec![regs[d as usize], scale],
        value: regs[k],
        expression,
    })
}

/// `expression` cut to [`MAX_TEXT`] characters.
fn clipped(expression: String) -> String {
    if expression.chars().count() > MAX_TEXT {
        expression.chars().take(MAX_TEXT).chain("...".chars()).collect()
    } else {
        expression
    }
}

/// The values an instruction reads.
fn operands(op: &Op) -> Vec<u32> {
    match *op {
        Op::Input(_) | Op::Const(_) => vec![],
        Op::Add(a, b) | Op::Sub(a, b) | Op::Mul(a, b) | Op::Div(a, b) | Op::Powf(a, b) | Op::Atan2(a, b) => {
            vec![a, b]
        }
        Op::Neg(a) | Op::Powi(a, _) | Op::Sqrt(a) | Op::Func(_, a) => vec![a],
    }
}

/// Why `op` on finite `operands` gave a value that is not finite.
fn classify(op: &Op, operands: &[f64]) -> FaultKind {
    let a = operands[0];
    match *op {
        Op::Div(..) if operands[1] == 0.0 => FaultKind::DivisionByZero,
        Op::Powi(..) if a == 0.0 => FaultKind::DivisionByZero,
        Op::Sqrt(_) if a < 0.0 => FaultKind::SqrtOfNegative,
        Op::Func(Func::Ln, _) if a <= 0.0 => FaultKind::LogOfNonPositive,
        Op::Func(f @ (Func::Asin | Func::Acos), _) if a.abs() > 1.0 => FaultKind::OutsideArcDomain(f.name()),
        Op::Powf(..) if a <= 0.0 => FaultKind::PowerOutsideDomain,
        _ => FaultKind::Overflow,
    }
}

/// Value `v` of `section` as an expression, inputs named by `name`, `depth` levels deep (deeper
/// operands written `...`).
pub(crate) fn text(section: &Section, v: u32, name: &dyn Fn(Input) -> String, depth: usize) -> String {
    let op = &section.ops[v as usize];
    if depth == 0 && !matches!(op, Op::Input(_) | Op::Const(_)) {
        return "...".to_string();
    }
    let sub = |w: u32| {
        let inner = text(section, w, name, depth.saturating_sub(1));
        let simple = match section.ops[w as usize] {
            Op::Input(_) | Op::Const(_) | Op::Func(..) | Op::Sqrt(_) | Op::Atan2(..) => true,
            Op::Neg(x) => matches!(section.ops[x as usize], Op::Input(_) | Op::Const(_)),
            _ => false,
        };
        if simple || inner == "..." {
            inner
        } else {
            format!("({inner})")
        }
    };
    let negated = |w: u32| match section.ops[w as usize] {
        Op::Neg(inner) => Some(inner),
        _ => None,
    };
    match *op {
        Op::Input(k) => name(section.inputs[k as usize]),
        Op::Const(c) => format!("{c}"),
        // `a + (-b)` and `(-a) + b` read as differences.
        Op::Add(a, b) => match (negated(a), negated(b)) {
            (_, Some(nb)) => format!("{} - {}", sub(a), sub(nb)),
            (Some(na), None) => format!("{} - {}", sub(b), sub(na)),
            (None, None) => format!("{} + {}", sub(a), sub(b)),
        },
        Op::Sub(a, b) => format!("{} - {}", sub(a), sub(b)),
        Op::Mul(a, b) => format!("{}*{}", sub(a), sub(b)),
        Op::Div(a, b) => format!("{}/{}", sub(a), sub(b)),
        Op::Neg(a) => format!("-{}", sub(a)),
        Op::Powi(a, k) => format!("{}^{k}", sub(a)),
        Op::Sqrt(a) => format!("sqrt({})", text(section, a, name, depth.saturating_sub(1))),
        Op::Powf(a, b) => format!("{}^{}", sub(a), sub(b)),
        Op::Func(f, a) => format!("{}({})", f.name(), text(section, a, name, depth.saturating_sub(1))),
        Op::Atan2(a, b) => format!(
            "atan2({}, {})",
            text(section, a, name, depth.saturating_sub(1)),
            text(section, b, name, depth.saturating_sub(1))
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::program::ir::SectionBuilder;

    fn named(input: Input) -> String {
        match input {
            Input::State(i) => format!("Q{}", i + 1),
            Input::Param(i) => format!("P{}", i + 1),
            Input::Time => "T".into(),
            other => format!("{other:?}"),
        }
    }

    /// `P1 / (Q1 - 1) + sqrt(P2 - T)`.
    fn section() -> Section {
        let mut b = SectionBuilder::default();
        let (q, p1, p2, t) = (
            b.input(Input::State(0)),
            b.input(Input::Param(0)),
            b.input(Input::Param(1)),
            b.input(Input::Time),
        );
        let one = b.constant(1.0);
        let d = b.sub(q, one);
        let ratio = b.div(p1, d);
        let gap = b.sub(p2, t);
        let root = b.push(Op::Sqrt(gap));
        let sum = b.add(ratio, root);
        b.finish(vec![sum])
    }

    fn at(q: f64, t: f64) -> impl Fn(Input) -> f64 {
        move |input| match input {
            Input::State(_) => q,
            Input::Param(0) => 2.0,
            Input::Param(_) => 1.0,
            Input::Time => t,
            _ => f64::NAN,
        }
    }

    #[test]
    fn the_first_faulty_operation_is_named_with_its_operands_and_expression() {
        let s = section();
        assert_eq!(first_fault(&s, at(0.5, 0.5), &named), None);
        let div = first_fault(&s, at(1.0, 0.5), &named).unwrap();
        assert_eq!(div.kind, FaultKind::DivisionByZero);
        assert_eq!(div.expression, "P1/(Q1 - 1)");
        assert!(div.to_string().starts_with("a division by zero (2 / 0) in `P1/(Q1 - 1)`"), "{div}");
        let root = first_fault(&s, at(0.5, 1.25), &named).unwrap();
        assert_eq!((root.kind.clone(), root.operands.clone()), (FaultKind::SqrtOfNegative, vec![-0.25]));
        assert_eq!(root.expression, "sqrt(P2 - T)");
        // A non-finite input is not an operation's fault.
        assert_eq!(first_fault(&s, at(f64::NAN, 0.5), &named), None);
    }

    #[test]
    fn a_divisor_that_cancels_to_nearly_zero_is_a_singularity_approached() {
        let s = section();
        assert_eq!(near_division_by_zero(&s, at(0.5, 0.5), &named), None);
        let near = near_division_by_zero(&s, at(1.0 + 1e-12, 0.5), &named).unwrap();
        assert_eq!(near.kind, FaultKind::NearDivisionByZero);
        assert_eq!(near.expression, "P1/(Q1 - 1)");
        assert!((near.operands[0] - 1e-12).abs() < 1e-15 && near.operands[1] > 1.0, "{near:?}");
    }

    #[test]
    fn sums_with_a_negated_term_read_as_differences() {
        let mut b = SectionBuilder::default();
        let (t, q) = (b.input(Input::Time), b.input(Input::State(0)));
        let one = b.constant(1.0);
        let minus_t = b.push(Op::Neg(t));
        let gap = b.add(minus_t, one);
        let root = b.push(Op::Sqrt(gap));
        let minus_q = b.push(Op::Neg(q));
        let sum = b.add(root, minus_q);
        let s = b.finish(vec![sum]);
        assert_eq!(text(&s, gap, &named, 5), "1 - T");
        assert_eq!(text(&s, sum, &named, 5), "sqrt(1 - T) - Q1");
        assert_eq!(text(&s, minus_t, &named, 5), "-T");
    }

    #[test]
    fn logarithms_arc_sines_powers_and_overflow_are_told_apart() {
        let kind = |op: Op, operands: &[f64]| classify(&op, operands);
        assert_eq!(kind(Op::Func(Func::Ln, 0), &[-1.0]), FaultKind::LogOfNonPositive);
        assert_eq!(kind(Op::Func(Func::Ln, 0), &[0.0]), FaultKind::LogOfNonPositive);
        assert_eq!(kind(Op::Func(Func::Asin, 0), &[1.5]), FaultKind::OutsideArcDomain("asin"));
        assert_eq!(kind(Op::Powf(0, 1), &[-2.0, 0.5]), FaultKind::PowerOutsideDomain);
        assert_eq!(kind(Op::Mul(0, 1), &[1e200, 1e200]), FaultKind::Overflow);
        assert_eq!(kind(Op::Func(Func::Exp, 0), &[1000.0]), FaultKind::Overflow);
    }
}
