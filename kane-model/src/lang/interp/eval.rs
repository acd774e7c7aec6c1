//! Evaluating expressions to values: literals, names, calls, array entries, matrices and
//! operators.
//!
//! In: a parsed expression. Out: its [`Value`] (scalar, vector, dyadic or matrix), or a
//! diagnostic saying what was found where something else was needed.

use crate::expr::SymbolKind;
use crate::mechanics::{Dyadic, Vector};

use super::super::ast::{BinOp, Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::super::token::Span;
use super::value::{self, Value};
use super::{At, Binding, IResult, Interpreter};

impl Interpreter {
    /// The value of `e`.
    pub(crate) fn eval(&mut self, e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        match &e.kind {
            ExprKind::Number { value, suffix } => self.literal(*value, *suffix, e),
            ExprKind::Name { name, primes, suffix } => self.name_value(name, *primes, *suffix, e),
            ExprKind::Call { name, args } => self.call(name, args, e),
            ExprKind::Index { name, args } => self.array_entry(name, args, e),
            ExprKind::Matrix(rows) => self.matrix_literal(rows, e),
            ExprKind::Neg(x) => {
                let v = self.eval(x)?;
                let m1 = self.model.ar.minus_one();
                value::scale(&mut self.model, &v, m1).at(fail)
            }
            ExprKind::Binary(op, a, b) => self.binary(*op, a, b, e),
            ExprKind::Range(..) | ExprKind::NamedArg(..) => Err(Diagnostic::error(
                e.span.clone(),
                "a range or `name = value` is only allowed as a function argument",
            )),
        }
    }

    /// A number, or one of the special vectors and dyadics `0>`, `0>>`, `1>>`.
    fn literal(&mut self, value: f64, suffix: u8, e: &Expr) -> IResult<Value> {
        match (suffix, value) {
            (0, v) => Ok(Value::Scalar(self.number_expr(v).at(&e.span)?)),
            (1, 0.0) => Ok(Value::Vector(Vector::zero())),
            (2, 0.0) => Ok(Value::Dyadic(Dyadic::zero())),
            (2, 1.0) => {
                let n = self.model.newtonian();
                let (o, z) = (self.model.ar.one(), self.model.ar.zero());
                Ok(Value::Dyadic(Dyadic::in_frame(n, [[o, z, z], [z, o, z], [z, z, o]])))
            }
            _ => Err(Diagnostic::error(
                e.span.clone(),
                "only 0> (zero vector), 0>> and 1>> (unit dyadic) are numbers with >",
            )),
        }
    }

    /// `NAME[i, ...]`: an assigned array entry, or an entry of a matrix.
    fn array_entry(&mut self, name: &str, args: &[Expr], e: &Expr) -> IResult<Value> {
        let key = name.to_ascii_uppercase();
        let idx = args.iter().map(|a| self.index_value(a)).collect::<IResult<Vec<_>>>()?;
        if let Some(entries) = self.arrays.get(&key) {
            if let Some((_, v)) = entries.iter().find(|(i, _)| *i == idx) {
                return Ok(v.clone());
            }
        }
        // A matrix by name: assigned, or a direction-cosine matrix `N_A` (`N_A[1,2]`).
        let matrix = match self.lookup_value(&key) {
            Some(v) => Some(v),
            None => {
                let whole = Expr {
                    kind: ExprKind::Name { name: name.to_string(), suffix: 0, primes: 0 },
                    span: e.span.clone(),
                };
                self.eval(&whole).ok()
            }
        };
        if let Some(Value::Matrix { rows, cols, data }) = matrix {
            if let Some(k) = value::matrix_position(&idx, rows, cols) {
                return Ok(Value::Scalar(data[k]));
            }
        }
        Err(Diagnostic::error(e.span.clone(), format!("`{name}{idx:?}` is not defined"))
            .with_help("assign the entry first, e.g. EQN[1] = ..."))
    }

    /// `[v1>, v2>; ...]` of vectors only, the first `v`: a matrix of vectors (rows of one
    /// length).
    fn vector_matrix(&mut self, rows: &[Vec<Expr>], v: Vector, e: &Expr) -> IResult<Value> {
        let cols = rows[0].len();
        if rows.iter().any(|r| r.len() != cols) {
            return Err(Diagnostic::error(e.span.clone(), "matrix rows have different lengths"));
        }
        let mut data = vec![v];
        for x in rows.iter().flatten().skip(1) {
            match self.eval(x)? {
                Value::Vector(v) => data.push(v),
                other => {
                    return Err(Diagnostic::error(
                        x.span.clone(),
                        format!("a matrix of vectors holds vectors only, not {}", other.kind()),
                    ))
                }
            }
        }
        Ok(Value::Vectors { rows: rows.len(), cols, data })
    }

    /// `[a, b; c, d]`: a matrix of scalars; an entry may itself be a matrix, joined to its
    /// neighbours in the row (same number of rows) and to the rows above and below (same
    /// number of columns): `[FK; X]` appends X to the column FK.
    fn matrix_literal(&mut self, rows: &[Vec<Expr>], e: &Expr) -> IResult<Value> {
        let mut first = match rows.first().and_then(|r| r.first()) {
            Some(x) => Some(self.eval(x)?),
            None => None,
        };
        if let Some(Value::Vector(v)) = &first {
            return self.vector_matrix(rows, v.clone(), e);
        }
        let mut data = Vec::new();
        let (mut height, mut width) = (0, None);
        for r in rows {
            let mut blocks: Vec<(usize, usize, Vec<crate::expr::ExprId>)> = Vec::with_capacity(r.len());
            for x in r {
                let value = match first.take() {
                    Some(v) => v,
                    None => self.eval(x)?,
                };
                blocks.push(match value {
                    Value::Scalar(s) => (1, 1, vec![s]),
                    Value::Matrix { rows, cols, data } => (rows, cols, data),
                    other => {
                        return Err(Diagnostic::error(x.span.clone(), format!("a matrix holds scalars, not {}", other.kind()))
                            .with_help("take measure numbers with DOT(v>, A1>), or the column of a vector with MATRIX(A, v>)"))
                    }
                });
            }
            let h = blocks.first().map_or(0, |b| b.0);
            if blocks.iter().any(|b| b.0 != h) {
                return Err(Diagnostic::error(
                    e.span.clone(),
                    "the entries of a matrix row have different numbers of rows",
                ));
            }
            let w: usize = blocks.iter().map(|b| b.1).sum();
            if width.is_some_and(|x| x != w) {
                return Err(Diagnostic::error(e.span.clone(), "matrix rows have different lengths"));
            }
            width = Some(w);
            for i in 0..h {
                for (_, c, d) in &blocks {
                    data.extend_from_slice(&d[i * c..(i + 1) * c]);
                }
            }
            height += h;
        }
        Ok(Value::Matrix { rows: height, cols: width.unwrap_or(0), data })
    }

    /// `a op b` for values of kinds the operator takes.
    fn binary(&mut self, op: BinOp, a: &Expr, b: &Expr, e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        let (va, vb) = (self.eval(a)?, self.eval(b)?);
        // A value only Autolev's session shows stays one, written out.
        if matches!(va, Value::Shown(_)) || matches!(vb, Value::Shown(_)) {
            let sym = ["+", "-", "*", "/", "^"][op as usize];
            return Ok(Value::Shown(format!("{} {sym} {}", self.shown_text(&va), self.shown_text(&vb))));
        }
        let r = match op {
            BinOp::Add => value::add(&mut self.model, &va, &vb, false).at(fail)?,
            BinOp::Sub => value::add(&mut self.model, &va, &vb, true).at(fail)?,
            BinOp::Mul => value::mul(&mut self.model, &va, &vb).at(fail)?,
            BinOp::Div => match vb {
                Value::Scalar(d) => {
                    let one = self.model.ar.one();
                    let inv = self.model.ar.div(one, d).at(fail)?;
                    Some(value::scale(&mut self.model, &va, inv).at(fail)?)
                }
                _ => None,
            },
            BinOp::Pow => match (&va, &vb) {
                (Value::Scalar(x), Value::Scalar(y)) => {
                    Some(Value::Scalar(self.model.ar.pow(*x, *y).at(fail)?))
                }
                _ => None,
            },
        };
        r.ok_or_else(|| {
            let sym = match op {
                BinOp::Add => "+",
                BinOp::Sub => "-",
                BinOp::Mul => "*",
                BinOp::Div => "/",
                BinOp::Pow => "^",
            };
            Diagnostic::error(
                e.span.clone(),
                format!("cannot apply `{sym}` to {} and {}", va.kind(), vb.kind()),
            )
            .with_help(match op {
                BinOp::Div | BinOp::Pow => "divide by and raise to scalars only",
                BinOp::Mul => "use DOT(a>, b>) or CROSS(a>, b>) for vector products",
                _ => "add or subtract values of the same kind: scalars, vectors (>) or dyadics (>>)",
            })
        })
    }

    /// How a value is written where a shown value holds it.
    pub(crate) fn shown_text(&self, v: &Value) -> String {
        match v {
            Value::Shown(t) => format!("({t})"),
            Value::Scalar(x) => format!("({})", self.model.ar.to_text(*x)),
            other => other.kind().to_string(),
        }
    }

    /// A scalar value, or an error saying what was found instead.
    pub(crate) fn scalar(&mut self, e: &Expr) -> IResult<crate::expr::ExprId> {
        match self.eval(e)? {
            Value::Scalar(x) => Ok(x),
            other => {
                Err(Diagnostic::error(e.span.clone(), format!("expected a scalar, found {}", other.kind()))
                    .with_help("use DOT(v>, A1>) for a measure number, MAG(v>) for a magnitude"))
            }
        }
    }

    /// A vector value, or an error saying what was found instead.
    pub(crate) fn vector(&mut self, e: &Expr) -> IResult<Vector> {
        let v = self.eval(e)?;
        self.vector_of(v, e)
    }

    /// The value `v` of `e` as a vector (a scalar zero is the zero vector).
    pub(crate) fn vector_of(&self, v: Value, e: &Expr) -> IResult<Vector> {
        match v {
            Value::Vector(v) => Ok(v),
            Value::Scalar(x) if self.model.ar.is_zero(x) => Ok(Vector::zero()),
            other => {
                Err(Diagnostic::error(e.span.clone(), format!("expected a vector, found {}", other.kind()))
                    .with_help("vectors end in > (A1>, P_O_P>); write 0> for the zero vector"))
            }
        }
    }

    /// A number: the expression must evaluate to a constant.
    pub(crate) fn number(&mut self, e: &Expr) -> IResult<f64> {
        let x = self.scalar(e)?;
        self.model
            .ar
            .eval(&[x], |_| None)
            .map(|v| v[0])
            .map_err(|err| Diagnostic::error(e.span.clone(), format!("expected a number here: {err}")))
    }

    /// An exact rational for integer-looking literals, else a float literal.
    pub(crate) fn number_expr(&mut self, v: f64) -> Result<crate::expr::ExprId, crate::expr::ExprError> {
        if v.fract() == 0.0 && v.abs() < 1e15 {
            return Ok(self.model.ar.integer(v as i128));
        }
        // Decimal literals with few digits are exact ratios (0.5 = 1/2, .025 = 1/40).
        for digits in 1..=9 {
            let scale = 10f64.powi(digits);
            let n = (v * scale).round();
            if (n / scale - v).abs() <= f64::EPSILON * v.abs() {
                return self.model.ar.rational(n as i128, scale as i128);
            }
        }
        self.model.ar.float(v)
    }

    /// The value of a name: `X`, `X'` (a derivative), `V>` or `D>>`.
    fn name_value(&mut self, name: &str, primes: u8, suffix: u8, e: &Expr) -> IResult<Value> {
        let key = name.to_ascii_uppercase();
        if suffix == 0 && primes == 0 {
            return self.plain_name(name, &key, e);
        }
        if suffix == 0 {
            return self.primed_name(name, &key, primes, e);
        }
        if suffix == 1 {
            if let Some(v) = self.unit_vector(&key) {
                return Ok(Value::Vector(v));
            }
        }
        let full = format!("{key}{}", ">".repeat(suffix as usize));
        if let Some(v) = self.lookup_value(&full) {
            return Ok(v);
        }
        self.frame_origins_in(&key);
        if let Some(b) = self.builtin(&key, suffix) {
            return self.builtin_value(b, &e.span);
        }
        Err(self.unknown(name, suffix, &e.span))
    }

    /// A scalar name: T, PI, a solved unknown, a direction-cosine matrix `A_B`, a symbol or an
    /// assigned value.
    fn plain_name(&mut self, name: &str, key: &str, e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        match key {
            "T" if !self.bindings.contains_key("T") => return Ok(Value::Scalar(self.model.ar.time())),
            "PI" if !self.bindings.contains_key("PI") => {
                return Ok(Value::Scalar(self.model.ar.float(std::f64::consts::PI).at(fail)?))
            }
            _ => {}
        }
        if let Some(x) = self.solved.get(key) {
            return Ok(Value::Scalar(*x));
        }
        // A matrix assigned entry by entry (B[1,1] = ...), even one named like a frame.
        if !matches!(self.bindings.get(key), Some(Binding::Value(_) | Binding::Symbol(..))) {
            if let Some(v) = self.arrays.get(key).and_then(|a| super::value::array_value(a)) {
                return Ok(v);
            }
        }
        if !self.bindings.contains_key(key) {
            if let Some((a, b)) = self.dcm_frames(key) {
                let m = self.model.dcm(a, b).at(fail)?;
                return Ok(Value::Matrix { rows: 3, cols: 3, data: m.iter().flatten().copied().collect() });
            }
        }
        match self.bindings.get(key).or_else(|| self.bindings.get(&super::entity_key(key))) {
            Some(Binding::Symbol(x, _)) => Ok(Value::Scalar(*x)),
            Some(Binding::Value(v)) => Ok(v.clone()),
            Some(Binding::Frame(_) | Binding::Body(_)) => {
                Err(Diagnostic::error(e.span.clone(), format!("`{name}` is a frame, not a value"))
                    .with_help(format!("use its unit vectors {name}1>, {name}2>, {name}3>")))
            }
            Some(Binding::Point(_) | Binding::Particle(_)) => {
                Err(Diagnostic::error(e.span.clone(), format!("`{name}` is a point, not a value")).with_help(
                    format!(
                        "use its position, velocity or acceleration: P_O_{name}>, V_{name}_N>, A_{name}_N>"
                    ),
                ))
            }
            None => Err(self.unknown(name, 0, &e.span)),
        }
    }

    /// `X'`, `X''`: a solved or assigned derivative, a variable's derivative symbol, or the
    /// time derivative of an assigned scalar.
    fn primed_name(&mut self, name: &str, key: &str, primes: u8, e: &Expr) -> IResult<Value> {
        let fail: &Span = &e.span;
        let primed = format!("{key}{}", "'".repeat(primes as usize));
        if let Some(x) = self.solved.get(&primed) {
            return Ok(Value::Scalar(*x));
        }
        if let Some(Binding::Value(v)) = self.bindings.get(&primed) {
            return Ok(v.clone());
        }
        if self.rates_solved && primes == 1 {
            if let Some(x) = self.speed_rate_solved(&primed, &e.span)? {
                return Ok(Value::Scalar(x));
            }
        }
        match self.bindings.get(key).cloned() {
            Some(Binding::Symbol(x, _)) => {
                let s = self.model.ar.as_symbol(x).ok_or_else(|| self.unknown(name, 0, &e.span))?;
                if !self.model.ar.symbol_info(s).kind.depends_on_time()
                    || self.model.ar.symbol_info(s).kind == SymbolKind::Time
                {
                    return Ok(Value::Scalar(self.model.ar.zero()));
                }
                // A coordinate's rate is its kinematic equation's right-hand side (`Q' = U`
                // makes `Q'` read `U`, and `Q''` read `U'`).
                if let Some(rhs) = self
                    .model
                    .kinematics(s)
                    .filter(|r| self.model.ar.as_symbol(*r) != self.model.ar.derivative_symbol(s).ok())
                {
                    let mut v = rhs;
                    for _ in 1..primes {
                        v = self.model.dt(v).at(fail)?;
                    }
                    return Ok(Value::Scalar(v));
                }
                let mut d = s;
                for _ in 0..primes {
                    d = self.model.ar.derivative_symbol(d).at(fail)?;
                }
                Ok(Value::Scalar(self.model.ar.symbol_expr(d)))
            }
            Some(Binding::Value(Value::Scalar(x))) => {
                let mut v = x;
                for _ in 0..primes {
                    v = self.model.dt(v).at(fail)?;
                }
                Ok(Value::Scalar(v))
            }
            _ => Err(self.unknown(name, 0, &e.span)),
        }
    }
}
