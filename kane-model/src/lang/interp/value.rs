//! Values of Autolev expressions: scalars, vectors, dyadics and matrices of scalars.
//!
//! In: values and the model whose arena they live in. Out: sums, scalings and products of
//! values of matching kinds (`None` where the kinds do not combine).

use crate::expr::ExprId;
use crate::mechanics::{Dyadic, Model, Result, Vector};

/// A value an expression evaluates to.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A scalar expression.
    Scalar(ExprId),
    /// A vector.
    Vector(Vector),
    /// A dyadic.
    Dyadic(Dyadic),
    /// A value Autolev's session shows but a model cannot use (complex roots and eigenvalues,
    /// FACTORIAL of a symbol), as it prints.
    Shown(String),
    /// A matrix of vectors, row-major (`[COEF(V>, U1), COEF(V>, U2)]`: partial velocities).
    Vectors {
        /// The number of rows.
        rows: usize,
        /// The number of columns.
        cols: usize,
        /// Entries, row by row.
        data: Vec<Vector>,
    },
    /// A matrix of scalars, row-major.
    Matrix {
        /// The number of rows.
        rows: usize,
        /// The number of columns.
        cols: usize,
        /// Entries, row by row.
        data: Vec<ExprId>,
    },
}

/// The matrix an array assigned entry by entry makes (`EQN[1]`, `EQN[2]` a column; `B[1,1]`,
/// ..., `B[2,3]` a 2x3 matrix), when every entry is a scalar and none is missing.
pub(crate) fn array_value(entries: &[(Vec<i64>, Value)]) -> Option<Value> {
    let dims = entries.first()?.0.len();
    if !(1..=2).contains(&dims) || entries.iter().any(|(i, _)| i.len() != dims || i.iter().any(|k| *k < 1)) {
        return None;
    }
    let rows = entries.iter().map(|(i, _)| i[0]).max()? as usize;
    let cols = if dims == 2 { entries.iter().map(|(i, _)| i[1]).max()? as usize } else { 1 };
    let mut data: Vec<Option<ExprId>> = vec![None; rows * cols];
    for (i, v) in entries {
        let Value::Scalar(x) = v else { return None };
        let at = (i[0] as usize - 1) * cols + if dims == 2 { i[1] as usize - 1 } else { 0 };
        data[at] = Some(*x);
    }
    Some(Value::Matrix { rows, cols, data: data.into_iter().collect::<Option<Vec<_>>>()? })
}

impl Value {
    /// A word for messages: "a scalar", "a vector", ...
    pub fn kind(&self) -> &'static str {
        match self {
            Value::Scalar(_) => "a scalar",
            Value::Vector(_) => "a vector",
            Value::Dyadic(_) => "a dyadic",
            Value::Matrix { .. } => "a matrix",
            Value::Vectors { .. } => "a matrix of vectors",
            Value::Shown(_) => {
                "a value only Autolev's session shows (complex numbers, FACTORIAL of a symbol)"
            }
        }
    }

    /// A column matrix.
    pub fn column(data: Vec<ExprId>) -> Value {
        Value::Matrix { rows: data.len(), cols: 1, data }
    }
}

/// The 0-based position in a `rows x cols` matrix of 1-based indices `[i]` (a column or row
/// vector) or `[i, j]`, if in range.
pub fn matrix_position(idx: &[i64], rows: usize, cols: usize) -> Option<usize> {
    let (i, j) = match idx {
        [i] if cols == 1 => (*i, 1),
        [j] if rows == 1 => (1, *j),
        [i, j] => (*i, *j),
        _ => return None,
    };
    (i >= 1 && j >= 1 && (i as usize) <= rows && (j as usize) <= cols)
        .then(|| (i as usize - 1) * cols + j as usize - 1)
}

/// `a + b` (or `a - b` with `negate`) for values of the same kind.
pub fn add(m: &mut Model, a: &Value, b: &Value, negate: bool) -> Result<Option<Value>> {
    let b = if negate { scale(m, b, m.ar.minus_one())? } else { b.clone() };
    Ok(Some(match (a, &b) {
        (Value::Scalar(x), Value::Scalar(y)) => Value::Scalar(m.ar.add(&[*x, *y])?),
        (Value::Vector(x), Value::Vector(y)) => Value::Vector(m.add_vectors(x, y)?),
        (Value::Dyadic(x), Value::Dyadic(y)) => Value::Dyadic(m.add_dyadics(x, y)?),
        (Value::Matrix { rows, cols, data }, Value::Matrix { rows: r2, cols: c2, data: d2 })
            if rows == r2 && cols == c2 =>
        {
            let data = data
                .iter()
                .zip(d2)
                .map(|(x, y)| m.ar.add(&[*x, *y]))
                .collect::<std::result::Result<_, _>>()?;
            Value::Matrix { rows: *rows, cols: *cols, data }
        }
        _ => return Ok(None),
    }))
}

/// `k * v` for a scalar `k`.
pub fn scale(m: &mut Model, v: &Value, k: ExprId) -> Result<Value> {
    Ok(match v {
        Value::Shown(text) => Value::Shown(format!("{}*({text})", m.ar.to_text(k))),
        Value::Vectors { rows, cols, data } => Value::Vectors {
            rows: *rows,
            cols: *cols,
            data: data.iter().map(|x| m.scale(x, k)).collect::<Result<_>>()?,
        },
        Value::Scalar(x) => Value::Scalar(m.ar.mul(&[k, *x])?),
        Value::Vector(x) => Value::Vector(m.scale(x, k)?),
        Value::Dyadic(x) => Value::Dyadic(m.scale_dyadic(x, k)?),
        Value::Matrix { rows, cols, data } => Value::Matrix {
            rows: *rows,
            cols: *cols,
            data: data.iter().map(|x| m.ar.mul(&[k, *x])).collect::<std::result::Result<_, _>>()?,
        },
    })
}

/// `a * b`: scalar products, vector outer products (a dyadic), dyadic-vector dots, and matrix
/// products.
pub fn mul(m: &mut Model, a: &Value, b: &Value) -> Result<Option<Value>> {
    Ok(Some(match (a, b) {
        (Value::Scalar(k), v) | (v, Value::Scalar(k)) => scale(m, v, *k)?,
        (Value::Vector(x), Value::Vector(y)) => Value::Dyadic(m.outer(x, y)?),
        (Value::Dyadic(d), Value::Vector(v)) => Value::Vector(m.dyadic_dot(d, v)?),
        (Value::Matrix { rows, cols, data }, Value::Matrix { rows: r2, cols: c2, data: d2 })
            if cols == r2 =>
        {
            let mut out = Vec::with_capacity(rows * c2);
            for i in 0..*rows {
                for j in 0..*c2 {
                    let terms: Vec<ExprId> = (0..*cols)
                        .map(|k| m.ar.mul(&[data[i * cols + k], d2[k * c2 + j]]))
                        .collect::<std::result::Result<_, _>>()?;
                    out.push(m.ar.add(&terms)?);
                }
            }
            Value::Matrix { rows: *rows, cols: *c2, data: out }
        }
        _ => return Ok(None),
    }))
}
