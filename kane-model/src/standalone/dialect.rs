//! One section of the lowered program as statements of another language: in come a
//! [`Section`] and a [`Dialect`] (how the language spells a read, a constant, a power, a
//! function and an assignment); out go one statement per instruction, named temporaries
//! `{prefix}{k}` shared by every later use, and the texts of the section's results.

use crate::expr::Func;
use crate::program::ir::{Input, Op, Section};

use super::plan::{Plan, Source};

/// How a language spells the parts of a straight-line section.
pub(super) trait Dialect {
    /// Reading an input of the section.
    fn input(&self, input: Input) -> String;
    /// A number literal (finite).
    fn number(&self, x: f64) -> String;
    /// `a ^ k` for an integer `k` (`a` a name or a parenthesised literal).
    fn powi(&self, a: &str, k: i32) -> String;
    /// `a ^ b`.
    fn powf(&self, a: &str, b: &str) -> String;
    /// The function `f` of `a`.
    fn func(&self, f: Func, a: &str) -> String;
    /// `atan2(a, b)`.
    fn atan2(&self, a: &str, b: &str) -> String;
    /// The statement giving the new temporary `name` the value `value`.
    fn assign(&self, name: &str, value: &str) -> String;
    /// Not-a-number (a constant the program folded to NaN).
    fn nan(&self) -> String;
}

/// The section's statements and the texts of its results.
pub(super) fn print(section: &Section, dialect: &dyn Dialect, prefix: &str) -> (Vec<String>, Vec<String>) {
    let operand = |v: u32| -> String {
        match section.ops[v as usize] {
            Op::Const(c) => literal(c, dialect),
            Op::Input(k) => dialect.input(section.inputs[k as usize]),
            _ => format!("{prefix}{v}"),
        }
    };
    let live = live(section);
    let mut lines = Vec::new();
    for (i, op) in section.ops.iter().enumerate() {
        if !live[i] {
            continue;
        }
        let value = match *op {
            Op::Const(_) | Op::Input(_) => continue,
            Op::Add(a, b) => format!("{} + {}", operand(a), operand(b)),
            Op::Sub(a, b) => format!("{} - {}", operand(a), operand(b)),
            Op::Mul(a, b) => format!("{} * {}", operand(a), operand(b)),
            Op::Div(a, b) => format!("{} / {}", operand(a), operand(b)),
            Op::Neg(a) => format!("-{}", operand(a)),
            Op::Powi(a, k) => dialect.powi(&operand(a), k),
            Op::Sqrt(a) => format!("sqrt({})", operand(a)),
            Op::Powf(a, b) => dialect.powf(&operand(a), &operand(b)),
            Op::Func(f, a) => dialect.func(f, &operand(a)),
            Op::Atan2(a, b) => dialect.atan2(&operand(a), &operand(b)),
        };
        lines.push(dialect.assign(&format!("{prefix}{i}"), &value));
    }
    (lines, section.results.iter().map(|v| operand(*v)).collect())
}

/// The statements of the outputs `plan` writes and each written column's value (scaled to its
/// unit), output `k`'s temporaries prefixed `o{k}_`.
pub(super) fn row(plan: &Plan<'_>, dialect: &dyn Dialect) -> (Vec<String>, Vec<String>) {
    let mut lines = Vec::new();
    let mut cells = vec![String::new(); plan.columns.len()];
    for &k in &plan.outputs {
        let (statements, results) = print(&plan.program.outputs[k].section, dialect, &format!("o{k}_"));
        lines.extend(statements);
        for (cell, column) in cells.iter_mut().zip(&plan.columns) {
            match column.source {
                Source::Output(kk, j) if kk == k => {
                    *cell = format!("{} * {}", results[j], dialect.number(column.scale))
                }
                _ => {}
            }
        }
    }
    for (cell, column) in cells.iter_mut().zip(&plan.columns) {
        if let Source::State(i) = column.source {
            *cell = format!("{} * {}", dialect.input(Input::State(i)), dialect.number(column.scale));
        }
    }
    (lines, cells)
}

/// Which values the results need (the section may hold values no result reads).
fn live(section: &Section) -> Vec<bool> {
    let mut live = vec![false; section.ops.len()];
    section.results.iter().for_each(|r| live[*r as usize] = true);
    for i in (0..section.ops.len()).rev() {
        if !live[i] {
            continue;
        }
        let mut mark = |v: u32| live[v as usize] = true;
        match section.ops[i] {
            Op::Input(_) | Op::Const(_) => {}
            Op::Neg(a) | Op::Powi(a, _) | Op::Sqrt(a) | Op::Func(_, a) => mark(a),
            Op::Add(a, b)
            | Op::Sub(a, b)
            | Op::Mul(a, b)
            | Op::Div(a, b)
            | Op::Powf(a, b)
            | Op::Atan2(a, b) => {
                mark(a);
                mark(b)
            }
        }
    }
    live
}

/// A constant as an operand: negative ones in parentheses.
fn literal(c: f64, dialect: &dyn Dialect) -> String {
    if c.is_nan() {
        dialect.nan()
    } else if c < 0.0 {
        format!("({})", dialect.number(c))
    } else {
        dialect.number(c)
    }
}

/// `text` as a Fortran or MATLAB string literal: between single quotes, each quote doubled.
pub(super) fn single_quoted(text: &str) -> String {
    format!("'{}'", text.replace('\'', "''"))
}

/// `x` written so it reads back as the same `f64`, always with a point or an exponent
/// (`2.0`, `0.3`, `1e-7`).
pub(super) fn shortest(x: f64) -> String {
    let s = format!("{x:?}");
    if s.contains(['.', 'e', 'E', 'i', 'N']) {
        s
    } else {
        format!("{s}.0")
    }
}

/// Reading `input` from the arrays `t`, `y`, `p`, `k` and `dy` (the speeds' rates after the
/// `n_coordinates` coordinates' rates), indexed from `base` (0 or 1) as `open`/`close` spell it.
pub(super) fn array_read(
    input: Input,
    n_coordinates: usize,
    base: usize,
    brackets: (&str, &str),
    nan: &str,
) -> String {
    let (open, close) = brackets;
    match input {
        Input::Time => "t".into(),
        Input::State(i) => format!("y{open}{}{close}", i + base),
        Input::Param(i) => format!("p{open}{}{close}", i + base),
        Input::ParamConstant(i) => format!("k{open}{}{close}", i + base),
        Input::Rate(i) => format!("dy{open}{}{close}", n_coordinates + i + base),
        Input::Slot(_) => nan.into(),
    }
}

/// A C-family power with an integer exponent: a product for a square, a quotient for `-1`,
/// else `pow`.
pub(super) fn powi_by_pow(a: &str, k: i32, pow: &str) -> String {
    match k {
        2 => format!("{a} * {a}"),
        -1 => format!("1.0 / {a}"),
        _ => format!("{pow}({a}, {k}.0)"),
    }
}

/// `f`'s name in C, MATLAB, Python's math and Fortran alike (Sign is each language's own).
pub(super) fn common_name(f: Func) -> &'static str {
    match f {
        Func::Ln => "log",
        other => other.name(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals_read_back_exactly_and_look_like_reals() {
        for x in [2.0, 0.3, 1e-7, 123456789.125, 6.02e23, 1.0 / 3.0] {
            let s = shortest(x);
            assert!(s.contains(['.', 'e']), "{s}");
            assert_eq!(s.parse::<f64>().unwrap(), x);
        }
    }
}
