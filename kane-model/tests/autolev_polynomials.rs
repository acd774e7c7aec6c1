//! POLYNOMIAL, ROOTS and EIG with output names, against hand computations.

use kane_model::expr::ExprId;
use kane_model::lang::{self, Value};

fn load(src: &str) -> lang::LoadedModel {
    lang::load("p.al", src).unwrap_or_else(|r| panic!("{}", r.render()))
}

fn error(src: &str) -> String {
    lang::load("e.al", src).err().expect("an error").to_string()
}

/// A value's scalars (a scalar is one) at the named symbols' values.
fn numbers(m: &lang::LoadedModel, name: &str, at: &[(&str, f64)]) -> (usize, usize, Vec<f64>) {
    let (rows, cols, data): (usize, usize, Vec<ExprId>) = match m.value(name) {
        Some(Value::Matrix { rows, cols, data }) => (rows, cols, data),
        Some(Value::Scalar(x)) => (1, 1, vec![x]),
        other => panic!("{name}: {other:?}"),
    };
    let ar = &m.model.ar;
    let v =
        ar.eval(&data, |s| at.iter().find(|(n, _)| *n == ar.symbol_info(s).name).map(|(_, v)| *v)).unwrap();
    (rows, cols, v)
}

fn close(got: &[f64], want: &[f64], tol: f64) -> bool {
    got.len() == want.len() && got.iter().zip(want).all(|(a, b)| (a - b).abs() <= tol)
}

#[test]
fn polynomial_builds_from_coefficients_and_gives_them_back() {
    let m = load(
        "VARIABLES X\nCONSTANTS J, K, L\nP1 = POLYNOMIAL([J,K,L], X)\nP2 = POLYNOMIAL(J*X+K, X, 1)\n\
         P3 = POLYNOMIAL((X-1)*(X+2)^2, X, 3)\nP4 = POLYNOMIAL(J*X^2, X, 3)\nBACK = POLYNOMIAL(P3, X)\n\
         COLUMN = POLYNOMIAL([1;0;-2], X)\n",
    );
    let at = [("J", 2.0), ("K", 3.0), ("L", 5.0), ("X", 0.7)];
    assert!(close(&numbers(&m, "P1", &at).2, &[2.0 * 0.49 + 3.0 * 0.7 + 5.0], 1e-14));
    assert_eq!(numbers(&m, "P2", &at), (1, 2, vec![2.0, 3.0]), "a row, highest power first");
    // (X - 1)(X + 2)^2 = X^3 + 3 X^2 - 4.
    assert_eq!(numbers(&m, "P3", &at), (1, 4, vec![1.0, 3.0, 0.0, -4.0]));
    assert_eq!(numbers(&m, "P4", &at), (1, 4, vec![0.0, 2.0, 0.0, 0.0]), "padded to N + 1");
    let x = 1.3f64;
    let back = numbers(&m, "BACK", &[("X", x)]).2[0];
    assert!((back - (x - 1.0) * (x + 2.0).powi(2)).abs() < 1e-13, "{back}");
    assert!(close(&numbers(&m, "COLUMN", &at).2, &[0.49 - 2.0], 1e-15));
}

#[test]
fn polynomial_refuses_what_is_not_a_polynomial_of_that_degree() {
    let e = error("VARIABLES X\nC = POLYNOMIAL(X^3 + X, X, 2)\n");
    assert!(e.contains("not a polynomial in X of degree 2 or less"), "{e}");
    let e = error("VARIABLES X\nC = POLYNOMIAL(SIN(X), X, 4)\n");
    assert!(e.contains("not a polynomial in X of degree 4 or less"), "{e}");
    let e = error("VARIABLES X\nP = POLYNOMIAL([1,2;3,4], X)\n");
    assert!(e.contains("expected a row or column of coefficients, found a 2x2 matrix"), "{e}");
    let e = error("VARIABLES X\nC = POLYNOMIAL(X^2, 2*X, 2)\n");
    assert!(e.contains("expected the symbol the polynomial is in"), "{e}");
}

#[test]
fn roots_of_number_coefficients_any_degree() {
    let m = load(
        "VARIABLES X\nR1 = ROOTS(POLYNOMIAL([1,-6,11,-6], X), X, 3)\nR2 = ROOTS([1;-6;11;-6])\n\
         R3 = ROOTS([2, -3, -2])\nR5 = ROOTS((X-1)*(X-2)*(X-3)*(X-4)*(X-5), X, 5)\nR6 = ROOTS([1;-2;1])\n\
         R7 = ROOTS(X - 4, X, 3)\n",
    );
    // (X - 1)(X - 2)(X - 3) = X^3 - 6 X^2 + 11 X - 6.
    assert!(close(&numbers(&m, "R1", &[]).2, &[1.0, 2.0, 3.0], 1e-13));
    let (rows, cols, r2) = numbers(&m, "R2", &[]);
    assert!((rows, cols) == (3, 1) && close(&r2, &[1.0, 2.0, 3.0], 1e-13), "a column: {r2:?}");
    // 2 X^2 - 3 X - 2 = (2 X + 1)(X - 2).
    assert!(close(&numbers(&m, "R3", &[]).2, &[-0.5, 2.0], 1e-14));
    assert!(close(&numbers(&m, "R5", &[]).2, &[1.0, 2.0, 3.0, 4.0, 5.0], 1e-10));
    assert!(close(&numbers(&m, "R6", &[]).2, &[1.0, 1.0], 1e-7), "a double root");
    assert!(close(&numbers(&m, "R7", &[]).2, &[4.0], 1e-15), "leading zero coefficients dropped");
}

#[test]
fn roots_with_symbols_by_formula() {
    let m = load(
        "VARIABLES X\nCONSTANTS J, K, L\nP1 = POLYNOMIAL([J,K,L], X)\nR1 = ROOTS(P1, X, 2)\n\
         R2 = ROOTS(J*X + K, X, 1)\nR3 = ROOTS(POLYNOMIAL(P1, X, 2))\n",
    );
    // J X^2 + K X + L = (X - 2)(X - 3) for J = 1, K = -5, L = 6; the smaller root first.
    let at = [("J", 1.0), ("K", -5.0), ("L", 6.0)];
    assert!(close(&numbers(&m, "R1", &at).2, &[2.0, 3.0], 1e-14));
    assert!(close(&numbers(&m, "R3", &at).2, &[2.0, 3.0], 1e-14));
    // 2 X^2 - 3 X - 2 = (2 X + 1)(X - 2), each root a zero of P1.
    let at = [("J", 2.0), ("K", -3.0), ("L", -2.0)];
    assert!(close(&numbers(&m, "R1", &at).2, &[-0.5, 2.0], 1e-14));
    assert!(close(&numbers(&m, "R2", &at).2, &[1.5], 1e-15));
}

#[test]
fn complex_roots_are_shown_and_unsupported_roots_are_errors_that_say_so() {
    let m = load("R = ROOTS([1;2;3])\n");
    assert!(
        matches!(m.value("R"), Some(Value::Shown(r)) if r.contains("-1 - 1.4142135623730951i")),
        "{:?}",
        m.value("R")
    );
    let e = error("VARIABLES X\nCONSTANTS J\nR = ROOTS(J*X^3 + X, X, 3)\n");
    assert!(
        e.contains("ROOTS of a polynomial of degree 3 with symbols in its coefficients is not supported"),
        "{e}"
    );
    let e = error("VARIABLES X\nCONSTANTS J\nR = ROOTS(J*X^2 + 1 + J^2*X^2 - X^2*(J+J^2), X, 2)\n");
    assert!(e.contains("ROOTS: the polynomial is a constant"), "{e}");
    let m = load("VARIABLES X\nR = ROOTS(X^2 + 2*X + 5, X, 2)\n");
    assert!(matches!(m.value("R"), Some(Value::Shown(r)) if r.contains("-1 - 2i")), "{:?}", m.value("R"));
}

/// The columns of an n x n matrix value, and its eigenvalue column.
fn eigen(m: &lang::LoadedModel, values: &str, vectors: &str) -> (Vec<f64>, Vec<Vec<f64>>) {
    let (n, one, lambda) = numbers(m, values, &[]);
    let (r, c, v) = numbers(m, vectors, &[]);
    assert_eq!((one, r, c), (1, n, n));
    (lambda, (0..n).map(|j| (0..n).map(|i| v[i * n + j]).collect()).collect())
}

#[test]
fn eig_with_output_names_gives_unit_eigenvectors_as_columns() {
    let m = load(
        "M = [2,1,0; 1,3,1; 0,1,4]\nEIG(M, VALS, VECS)\nEV = EIG(M)\nCOMPLEX ON\nN = [1,2;3,0]\n\
         EIG(N, NV, NW)\nR = [5,4,2;4,5,2;2,2,2]\nEIG(R, RV, RW)\n",
    );
    let a = [[2.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 4.0]];
    let (lambda, v) = eigen(&m, "VALS", "VECS");
    assert_eq!(lambda, numbers(&m, "EV", &[]).2, "the values EIG(M) gives, in its order");
    assert!(lambda.windows(2).all(|w| w[0] < w[1]), "ascending: {lambda:?}");
    for (l, v) in lambda.iter().zip(&v) {
        let av: Vec<f64> = a.iter().map(|row| row.iter().zip(v).map(|(x, y)| x * y).sum()).collect();
        assert!(close(&av, &v.iter().map(|x| l * x).collect::<Vec<_>>(), 1e-12), "M v = lambda v");
        assert!((v.iter().map(|x| x * x).sum::<f64>() - 1.0).abs() < 1e-14);
        let big = v.iter().copied().fold(0.0f64, |a, x| if x.abs() > a.abs() { x } else { a });
        assert!(big > 0.0, "largest entry positive: {v:?}");
    }
    // Not symmetric: 3 with (1, 1)/sqrt(2); -2 with (2, -3)/sqrt(13), sign turned.
    let (lambda, v) = eigen(&m, "NV", "NW");
    assert!(close(&lambda, &[-2.0, 3.0], 1e-14), "{lambda:?}");
    let (s2, s13) = (2f64.sqrt(), 13f64.sqrt());
    assert!(
        close(&v[0], &[-2.0 / s13, 3.0 / s13], 1e-14) && close(&v[1], &[1.0 / s2, 1.0 / s2], 1e-14),
        "{v:?}"
    );
    // A repeated eigenvalue 1 (twice) and 10: its eigenvectors span the plane x . (2, 2, 1) = 0.
    let (lambda, v) = eigen(&m, "RV", "RW");
    assert!(close(&lambda, &[1.0, 1.0, 10.0], 1e-13), "{lambda:?}");
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    assert!(dot(&v[0], &[2.0, 2.0, 1.0]).abs() < 1e-13 && dot(&v[1], &[2.0, 2.0, 1.0]).abs() < 1e-13);
    assert!(dot(&v[0], &v[1]).abs() < 1e-13, "independent (orthogonal)");
    assert!(close(&v[2], &[2.0 / 3.0, 2.0 / 3.0, 1.0 / 3.0], 1e-13), "{v:?}");
}

#[test]
fn eig_with_output_names_refuses_what_it_cannot_give() {
    let e = error("EIG([0,-1;1,0], V, W)\n");
    assert!(e.contains("complex eigenvalues"), "{e}");
    let e = error("EIG([1,1;0,1], V, W)\n");
    assert!(
        e.contains("the eigenvalue 1 is repeated but has fewer independent eigenvectors than repeats"),
        "{e}"
    );
    let e = error("EIG([1,0;0,2], V)\n");
    assert!(e.contains("EIG takes (M) or (M, VALUES, VECTORS)"), "{e}");
    let e = error("EIG([1,0;0,2], V, W[1])\n");
    assert!(e.contains("expected a name for EIG to assign here"), "{e}");
    let e = error("CONSTANTS W\nEIG([1,0;0,2], V, W)\n");
    assert!(e.contains("`W` is a declared symbol"), "{e}");
}
