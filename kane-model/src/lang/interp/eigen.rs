//! EIG: the eigenvalues of a matrix of numbers, `EIG(M)`, and with output names,
//! `EIG(M, VALUES, VECTORS)`, its unit eigenvectors too.
//!
//! In: the call's argument expressions. Out: the eigenvalues, ascending, as a column [`Value`];
//! with output names, VALUES is bound to that column and VECTORS to the matrix whose column `j`
//! is a unit eigenvector of value `j` (so `M VECTORS = VECTORS DIAGMAT(values)`), its
//! largest-magnitude entry positive. Complex eigenvalues (values here are real), symbols and
//! defective matrices are errors that say so.
//!
//! Autolev assigns EIG's eigenvalues to the second argument and its eigenvectors to the third;
//! the eigenvectors are columns here, the linear-algebra convention. (SymPy's parser puts
//! them in rows instead, and SymPy's Autolev-parser guide reads one with `ROWS(E2, 1)`; its
//! order of eigenvalues is not Autolev's either, so neither settles Autolev's layout.)

use nalgebra::{Complex, DMatrix, DVector};

use super::super::ast::{Expr, ExprKind};
use super::super::diagnostic::Diagnostic;
use super::value::Value;
use super::{At, Binding, IResult, Interpreter};

/// Eigenvalues closer than this (times the matrix's norm) are one repeated value.
const SAME_VALUE: f64 = 1e-6;

impl Interpreter {
    /// `EIG(M)`: the eigenvalues; `EIG(M, VALUES, VECTORS)`: those, with the names bound.
    pub(super) fn eigen(&mut self, args: &[Expr], e: &Expr) -> IResult<Value> {
        let outputs = match args {
            [_] => None,
            [_, values, vectors] => Some((output_name(values)?, output_name(vectors)?)),
            _ => {
                return Err(Diagnostic::error(e.span.clone(), "EIG takes (M) or (M, VALUES, VECTORS)")
                    .with_help(
                        "VALUES and VECTORS are the names EIG assigns the eigenvalues and eigenvectors to",
                    ))
            }
        };
        let m = self.number_matrix(&args[0], e)?;
        let n = m.nrows();
        let values = match real_eigenvalues(&m) {
            Ok(v) => v,
            Err(_) if outputs.is_none() => {
                // Complex eigenvalues, as Autolev's session shows them.
                let all: Vec<_> = m.complex_eigenvalues().iter().copied().collect();
                return Ok(Value::Shown(super::polynomial::complex_column(all)));
            }
            Err(z) => {
                return Err(Diagnostic::error(
                    e.span.clone(),
                    format!(
                        "EIG(M, VALUES, VECTORS): the matrix has complex eigenvalues ({} {:+}i and more), and complex eigenvectors are not formed",
                        z.re, z.im
                    ),
                )
                .with_help("EIG(M) alone gives complex eigenvalues, as a value to show"))
            }
        };
        let column = values.iter().map(|x| self.model.ar.float(*x)).collect::<Result<_, _>>().at(&e.span)?;
        let column = Value::Matrix { rows: n, cols: 1, data: column };
        let Some(((values_name, values_span), (vectors_name, vectors_span))) = outputs else {
            return Ok(column);
        };
        let vectors = unit_eigenvectors(&m, &values).map_err(|lambda| {
            Diagnostic::error(
                e.span.clone(),
                format!("EIG: the eigenvalue {} is repeated but has fewer independent eigenvectors than repeats (the matrix is defective)", short(lambda)),
            )
            .with_help("a defective matrix has no full set of eigenvectors; EIG(M) alone gives its eigenvalues")
        })?;
        let mut data = Vec::with_capacity(n * n);
        for i in 0..n {
            for j in 0..n {
                data.push(self.model.ar.float(vectors[(i, j)]).at(&e.span)?);
            }
        }
        self.bind_output(&values_name, &values_span, column.clone())?;
        self.bind_output(&vectors_name, &vectors_span, Value::Matrix { rows: n, cols: n, data })?;
        Ok(column)
    }

    /// A square matrix argument whose entries are all numbers.
    fn number_matrix(&mut self, a: &Expr, e: &Expr) -> IResult<DMatrix<f64>> {
        let rows = self.square_rows("EIG", std::slice::from_ref(a), e, usize::MAX)?;
        let n = rows.len();
        let mut m = DMatrix::zeros(n, n);
        for (i, row) in rows.iter().enumerate() {
            for (j, x) in row.iter().enumerate() {
                m[(i, j)] = self.model.ar.eval::<f64>(&[*x], |_| None).map(|v| v[0]).map_err(|_| {
                    Diagnostic::error(a.span.clone(), "EIG needs a matrix of numbers; this one has symbols")
                        .with_help("evaluate it first (EVALUATE(M, X = value, ...)); for the equations' eigenvalues use `kane linearize`")
                })?;
                if !m[(i, j)].is_finite() {
                    return Err(Diagnostic::error(
                        a.span.clone(),
                        format!("EIG needs finite numbers; entry ({}, {}) is {}", i + 1, j + 1, m[(i, j)]),
                    ));
                }
            }
        }
        Ok(m)
    }

    /// Binds an output name of EIG to `v`, unless the name is a declared symbol.
    fn bind_output(&mut self, name: &str, span: &super::super::token::Span, v: Value) -> IResult<()> {
        let key = name.to_ascii_uppercase();
        if let Some(Binding::Symbol(..)) = self.bindings.get(&key) {
            return Err(Diagnostic::error(
                span.clone(),
                format!("`{name}` is a declared symbol, not a name EIG can assign"),
            )
            .with_help("give EIG's outputs names that are not declared as CONSTANTS or VARIABLES"));
        }
        self.kane_sums.remove(&key);
        self.bindings.insert(key, Binding::Value(v));
        Ok(())
    }
}

/// A number with at most six decimals, trailing zeros dropped, for messages.
pub(super) fn short(x: f64) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".into()
    } else {
        s.into()
    }
}

/// An output name of EIG: a plain name.
fn output_name(a: &Expr) -> IResult<(String, super::super::token::Span)> {
    match &a.kind {
        ExprKind::Name { name, primes: 0, suffix: 0 } => Ok((name.clone(), a.span.clone())),
        _ => Err(Diagnostic::error(a.span.clone(), "expected a name for EIG to assign here").with_help(
            "EIG(M, VALUES, VECTORS) assigns the eigenvalues to VALUES and the eigenvectors to VECTORS",
        )),
    }
}

/// The eigenvalues of `m`, ascending, or one complex eigenvalue when they are not all real.
pub(super) fn real_eigenvalues(m: &DMatrix<f64>) -> Result<Vec<f64>, Complex<f64>> {
    let values = m.complex_eigenvalues();
    let scale = values.iter().map(|z| z.norm()).fold(1.0, f64::max);
    if let Some(z) = values.iter().find(|z| z.im.abs() > 1e-12 * scale) {
        return Err(*z);
    }
    let mut real: Vec<f64> = values.iter().map(|z| z.re).collect();
    real.sort_by(f64::total_cmp);
    Ok(real)
}

/// Unit eigenvectors of `m` for its real eigenvalues `values` (ascending), as the columns of a
/// matrix: each spans the null space of `m - lambda 1` (by the SVD), a value repeated `k` times
/// the `k` right singular vectors of the smallest singular values (orthonormal). `Err(lambda)`
/// when a repeated value's null space is smaller than its repeats (a defective matrix).
pub(super) fn unit_eigenvectors(m: &DMatrix<f64>, values: &[f64]) -> Result<DMatrix<f64>, f64> {
    let n = m.nrows();
    let scale = m.norm().max(1.0);
    let mut out = DMatrix::zeros(n, n);
    let mut j = 0;
    while j < n {
        let k = values[j..].iter().take_while(|v| (**v - values[j]).abs() <= SAME_VALUE * scale).count();
        let lambda = values[j..j + k].iter().sum::<f64>() / k as f64;
        let svd = (m - DMatrix::identity(n, n) * lambda).svd(false, true);
        let v_t = svd.v_t.ok_or(lambda)?;
        if svd.singular_values[n - k] > SAME_VALUE * scale {
            return Err(lambda);
        }
        for c in 0..k {
            let mut v: DVector<f64> = v_t.row(n - k + c).transpose();
            v /= v.norm();
            out.set_column(j + c, &signed(v));
        }
        j += k;
    }
    Ok(out)
}

/// `v` with its largest-magnitude entry positive (the first of those within a relative 1e-9 of
/// the largest, so that equal magnitudes choose the same entry on every machine).
fn signed(v: DVector<f64>) -> DVector<f64> {
    let largest = v.amax();
    match v.iter().find(|x| x.abs() >= largest * (1.0 - 1e-9)) {
        Some(x) if *x < 0.0 => -v,
        _ => v,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigenvectors_of_a_general_real_matrix_satisfy_m_v_equal_lambda_v() {
        // Upper triangular: eigenvalues 1, 2, 3 on the diagonal, not symmetric.
        let m = DMatrix::from_row_slice(3, 3, &[1.0, 2.0, 3.0, 0.0, 2.0, 5.0, 0.0, 0.0, 3.0]);
        let values = real_eigenvalues(&m).unwrap();
        assert!(values.iter().zip([1.0, 2.0, 3.0]).all(|(a, b)| (a - b).abs() < 1e-13), "{values:?}");
        let v = unit_eigenvectors(&m, &values).unwrap();
        for (j, lambda) in values.iter().enumerate() {
            let col = v.column(j);
            assert!((&m * col - col * *lambda).amax() < 1e-12, "column {j}");
            assert!((col.norm() - 1.0).abs() < 1e-14);
            assert!(col.iter().any(|x| *x > 0.0 && x.abs() >= col.amax() * (1.0 - 1e-9)));
        }
        // The first is the unit vector 1: (1, 0, 0).
        assert!((v.column(0) - DVector::from_row_slice(&[1.0, 0.0, 0.0])).amax() < 1e-14);
    }

    #[test]
    fn a_repeated_value_gets_its_whole_eigenspace_and_a_jordan_block_is_refused() {
        let m = DMatrix::from_row_slice(3, 3, &[2.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 5.0]);
        let values = real_eigenvalues(&m).unwrap();
        let v = unit_eigenvectors(&m, &values).unwrap();
        assert!((v.transpose() * &v - DMatrix::identity(3, 3)).amax() < 1e-14, "orthonormal");
        assert!((&m * &v - &v * DMatrix::from_diagonal(&DVector::from_vec(values))).amax() < 1e-13);
        let jordan = DMatrix::from_row_slice(2, 2, &[1.0, 1.0, 0.0, 1.0]);
        assert!(unit_eigenvectors(&jordan, &real_eigenvalues(&jordan).unwrap()).is_err());
    }
}
