//! A square linear system solved in straight-line code by Householder reflections: in come the
//! values of a matrix `A`; out goes its factorisation `A = Q R`, which solves `A x = r` for any
//! right-hand side values. Backward stable with no pivoting, so there are no branches: the
//! reflector's sign comes from `sign(x) + 1 - sign(x)^2` (1 at zero). A column that is exactly
//! dependent at run time gives a zero reflector, hence non-finite results; near rank loss the
//! results grow with the condition number (`eval` reports it by name).
// Matrix code reads clearest with indices.
#![allow(clippy::needless_range_loop)]

use super::super::ir::{Op, SectionBuilder};
use crate::expr::Func;

/// `A = Q R`: the reflectors `v_j` (over rows `j..m`) with `2 / v_j . v_j`, and `R`.
pub struct Factored {
    reflectors: Vec<(Vec<u32>, u32)>,
    r: Vec<Vec<u32>>,
}

/// Factors the `m x m` matrix of values `a` (rows).
pub fn factor(b: &mut SectionBuilder, mut a: Vec<Vec<u32>>) -> Factored {
    let m = a.len();
    let (one, two) = (b.constant(1.0), b.constant(2.0));
    let zero = b.constant(0.0);
    let mut reflectors = Vec::with_capacity(m);
    for j in 0..m {
        let x: Vec<u32> = (j..m).map(|i| a[i][j]).collect();
        let squares: Vec<u32> = x.iter().map(|v| b.mul(*v, *v)).collect();
        let norm = {
            let s = sum(b, &squares, zero);
            b.push(Op::Sqrt(s))
        };
        let sign = b.push(Op::Func(Func::Sign, x[0]));
        let sign2 = b.mul(sign, sign);
        let sign = {
            let t = b.sub(one, sign2);
            b.add(sign, t)
        };
        // v = x + sign |x| e1; v.v = 2 |x| (|x| + sign x0); R[j][j] = -sign |x|.
        let signed_norm = b.mul(sign, norm);
        let mut v = x.clone();
        v[0] = b.add(x[0], signed_norm);
        let vv = {
            let s = b.mul(sign, x[0]);
            let t = b.add(norm, s);
            let u = b.mul(norm, t);
            b.mul(two, u)
        };
        let scale = b.div(two, vv);
        for k in j + 1..m {
            let column: Vec<u32> = (j..m).map(|i| a[i][k]).collect();
            let updated = reflect(b, &v, scale, &column, zero);
            for (i, u) in (j..m).zip(updated) {
                a[i][k] = u;
            }
        }
        a[j][j] = b.push(Op::Neg(signed_norm));
        reflectors.push((v, scale));
    }
    Factored { reflectors, r: a }
}

impl Factored {
    /// `x` with `A x = rhs`, for the values `rhs`.
    pub fn solve(&self, b: &mut SectionBuilder, rhs: &[u32]) -> Vec<u32> {
        let m = rhs.len();
        let zero = b.constant(0.0);
        let mut y = rhs.to_vec();
        for (j, (v, scale)) in self.reflectors.iter().enumerate() {
            let tail = reflect(b, v, *scale, &y[j..], zero);
            y.splice(j.., tail);
        }
        let mut x = vec![zero; m];
        for i in (0..m).rev() {
            let known: Vec<u32> = (i + 1..m).map(|k| b.mul(self.r[i][k], x[k])).collect();
            let s = sum(b, &known, zero);
            let t = b.sub(y[i], s);
            x[i] = b.div(t, self.r[i][i]);
        }
        x
    }
}

/// `c - scale (v . c) v`.
fn reflect(b: &mut SectionBuilder, v: &[u32], scale: u32, c: &[u32], zero: u32) -> Vec<u32> {
    let products: Vec<u32> = v.iter().zip(c).map(|(a, x)| b.mul(*a, *x)).collect();
    let dot = sum(b, &products, zero);
    let f = b.mul(scale, dot);
    v.iter()
        .zip(c)
        .map(|(a, x)| {
            let t = b.mul(f, *a);
            b.sub(*x, t)
        })
        .collect()
}

/// The sum of `terms` (0 for none).
pub fn sum(b: &mut SectionBuilder, terms: &[u32], zero: u32) -> u32 {
    let mut it = terms.iter();
    let Some(&first) = it.next() else { return zero };
    it.fold(first, |acc, t| b.add(acc, *t))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::program::ir::Input;

    /// Solves `a x = r` through the lowered code.
    fn solve(a: &[[f64; 3]; 3], r: [f64; 3]) -> Vec<f64> {
        let mut b = SectionBuilder::default();
        let values: Vec<Vec<u32>> =
            (0..3).map(|i| (0..3).map(|j| b.input(Input::Slot(3 * i + j))).collect()).collect();
        let rhs: Vec<u32> = (0..3).map(|i| b.input(Input::Slot(9 + i))).collect();
        let f = factor(&mut b, values);
        let x = f.solve(&mut b, &rhs);
        let section = b.finish(x);
        let mut out = vec![0.0; 3];
        section.eval(
            |i| {
                if let Input::Slot(k) = i {
                    if k < 9 {
                        a[k / 3][k % 3]
                    } else {
                        r[k - 9]
                    }
                } else {
                    0.0
                }
            },
            &mut out,
        );
        out
    }

    #[test]
    fn solves_where_the_leading_entries_vanish() {
        // The first column starts with zeros, as a constraint matrix at a symmetric state.
        let a = [[0.0, 2.0, 1.0], [0.0, -1.0, 3.0], [4.0, 0.5, 0.0]];
        let x_true = [0.3, -1.2, 2.5];
        let r: Vec<f64> = a.iter().map(|row| row.iter().zip(x_true).map(|(p, q)| p * q).sum()).collect();
        let x = solve(&a, [r[0], r[1], r[2]]);
        for (g, w) in x.iter().zip(x_true) {
            assert!((g - w).abs() < 1e-14, "{x:?}");
        }
    }

    #[test]
    fn a_singular_matrix_gives_no_finite_answer() {
        let a = [[1.0, 2.0, 3.0], [0.0, 1.0, 5.0], [0.0, 0.0, 0.0]];
        let x = solve(&a, [1.0, 2.0, 3.0]);
        assert!(x.iter().any(|v| !v.is_finite()), "{x:?}");
    }
}
