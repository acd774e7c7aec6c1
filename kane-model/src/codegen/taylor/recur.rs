//! The recurrences: in comes a work array of normalised Taylor coefficients (value `v`'s
//! coefficient `k` at `w[v * n1 + k]`, so `v(t + h) = sum_k w[v * n1 + k] h^k`) whose operands
//! are known through order `k`; out goes coefficient `k` of one value. Order 0 is the plain
//! operation. The evaluator ([`super::TaylorProgram::coefficients`]) and generated code call the
//! same functions, so both compute the same numbers.
//!
//! Operands come before the value they define (SSA), so every function reads before it writes.

use num_traits::Float;

use crate::expr::Func;

/// `k` as `T`.
#[inline(always)]
pub fn count<T: Float>(k: usize) -> T {
    T::from(k).unwrap_or_else(T::nan)
}

/// `sum_{j=lo}^{hi} x_j y_{k-j}` over the coefficients of `x` and `y`.
#[inline(always)]
fn cauchy<T: Float>(w: &[T], n1: usize, k: usize, x: usize, y: usize, lo: usize, hi: usize) -> T {
    if lo > hi {
        return T::zero();
    }
    let xs = &w[x * n1 + lo..=x * n1 + hi];
    let ys = &w[y * n1 + k - hi..=y * n1 + k - lo];
    xs.iter().zip(ys.iter().rev()).fold(T::zero(), |s, (a, b)| s + *a * *b)
}

/// `sum_{j=1}^{hi} j x_j y_{k-j}`: the sum of the derivative rules.
#[inline(always)]
fn weighted<T: Float>(w: &[T], n1: usize, k: usize, x: usize, y: usize, hi: usize) -> T {
    let xs = &w[x * n1 + 1..=x * n1 + hi];
    let ys = &w[y * n1 + k - hi..y * n1 + k];
    let mut j = T::zero();
    xs.iter().zip(ys.iter().rev()).fold(T::zero(), |s, (a, b)| {
        j = j + T::one();
        s + j * *a * *b
    })
}

/// `d = a + b`.
#[inline(always)]
pub fn add<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, b: usize) {
    w[d * n1 + k] = w[a * n1 + k] + w[b * n1 + k];
}

/// `d = a - b`.
#[inline(always)]
pub fn sub<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, b: usize) {
    w[d * n1 + k] = w[a * n1 + k] - w[b * n1 + k];
}

/// `d = -a`.
#[inline(always)]
pub fn neg<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize) {
    w[d * n1 + k] = -w[a * n1 + k];
}

/// `d = a b` (Leibniz's rule: the Cauchy product).
#[inline(always)]
pub fn mul<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, b: usize) {
    w[d * n1 + k] = cauchy(w, n1, k, a, b, 0, k);
}

/// `d = a^2` (the Cauchy product with each cross term once, doubled).
#[inline(always)]
pub fn sqr<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize) {
    let half = if k % 2 == 0 { k / 2 } else { k / 2 + 1 };
    let cross = if half == 0 { T::zero() } else { cauchy(w, n1, k, a, a, 0, half - 1) };
    let middle = if k % 2 == 0 { w[a * n1 + k / 2] * w[a * n1 + k / 2] } else { T::zero() };
    w[d * n1 + k] = cross + cross + middle;
}

/// `d = a s` for a constant `s` (its coefficient 0).
#[inline(always)]
pub fn scale<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, s: usize) {
    w[d * n1 + k] = w[a * n1 + k] * w[s * n1];
}

/// `d = a / b`: `d_k = (a_k - sum_{j=1}^k b_j d_{k-j}) / b_0`.
#[inline(always)]
pub fn div<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, b: usize) {
    let s = cauchy(w, n1, k, b, d, 1, k);
    w[d * n1 + k] = (w[a * n1 + k] - s) / w[b * n1];
}

/// `d = a / s` for a constant `s`.
#[inline(always)]
pub fn div_const<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, s: usize) {
    w[d * n1 + k] = w[a * n1 + k] / w[s * n1];
}

/// `d = sqrt(a)`: `d_k = (a_k - sum_{j=1}^{k-1} d_j d_{k-j}) / (2 d_0)`.
#[inline(always)]
pub fn sqrt<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize) {
    if k == 0 {
        w[d * n1] = w[a * n1].sqrt();
        return;
    }
    let s = cauchy(w, n1, k, d, d, 1, k - 1);
    w[d * n1 + k] = (w[a * n1 + k] - s) / (w[d * n1] + w[d * n1]);
}

/// `d = exp(a)`: `d_k = (1/k) sum_{j=1}^k j a_j d_{k-j}`.
#[inline(always)]
pub fn exp<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize) {
    w[d * n1 + k] = if k == 0 { w[a * n1].exp() } else { weighted(w, n1, k, a, d, k) / count(k) };
}

/// `d = ln(a)`: `d_k = (a_k - (1/k) sum_{j=1}^{k-1} j d_j a_{k-j}) / a_0`.
#[inline(always)]
pub fn ln<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize) {
    if k == 0 {
        w[d * n1] = w[a * n1].ln();
        return;
    }
    let s = if k > 1 { weighted(w, n1, k, d, a, k - 1) / count(k) } else { T::zero() };
    w[d * n1 + k] = (w[a * n1 + k] - s) / w[a * n1];
}

/// `d = sin(a)`, `c` its partner `cos(a)`: `d_k = (1/k) sum_{j=1}^k j a_j c_{k-j}`.
#[inline(always)]
pub fn sin<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, c: usize) {
    w[d * n1 + k] = if k == 0 { w[a * n1].sin() } else { weighted(w, n1, k, a, c, k) / count(k) };
}

/// `d = cos(a)`, `s` its partner `sin(a)`: `d_k = -(1/k) sum_{j=1}^k j a_j s_{k-j}`.
#[inline(always)]
pub fn cos<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, s: usize) {
    w[d * n1 + k] = if k == 0 { w[a * n1].cos() } else { -weighted(w, n1, k, a, s, k) / count(k) };
}

/// `d = sinh(a)`, `c` its partner `cosh(a)`.
#[inline(always)]
pub fn sinh<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, c: usize) {
    w[d * n1 + k] = if k == 0 { w[a * n1].sinh() } else { weighted(w, n1, k, a, c, k) / count(k) };
}

/// `d = cosh(a)`, `s` its partner `sinh(a)`.
#[inline(always)]
pub fn cosh<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, s: usize) {
    w[d * n1 + k] = if k == 0 { w[a * n1].cosh() } else { weighted(w, n1, k, a, s, k) / count(k) };
}

/// `d = f(a)` where `d' = a' / q` (atan: `q = 1 + a^2`; asin: `q = sqrt(1 - a^2)`; acos:
/// `q = -sqrt(1 - a^2)`): `k d_k = (k a_k - sum_{i=1}^{k-1} q_i (k-i) d_{k-i}) / q_0`.
#[inline(always)]
pub fn integral<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize, q: usize, f: Func) {
    if k == 0 {
        w[d * n1] = f.apply(w[a * n1]);
        return;
    }
    let kt = count::<T>(k);
    let s = if k > 1 { weighted(w, n1, k, d, q, k - 1) } else { T::zero() };
    w[d * n1 + k] = (kt * w[a * n1 + k] - s) / (kt * w[q * n1]);
}

/// `d = atan2(y, x)` with `r = x^2 + y^2`: `d' r = x y' - y x'`, so
/// `k d_k r_0 = sum_{j=1}^k j (x_{k-j} y_j - y_{k-j} x_j) - sum_{i=1}^{k-1} r_i (k-i) d_{k-i}`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn atan2<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, y: usize, x: usize, r: usize) {
    if k == 0 {
        w[d * n1] = w[y * n1].atan2(w[x * n1]);
        return;
    }
    let num = weighted(w, n1, k, y, x, k) - weighted(w, n1, k, x, y, k);
    let s = if k > 1 { weighted(w, n1, k, d, r, k - 1) } else { T::zero() };
    w[d * n1 + k] = (num - s) / (count::<T>(k) * w[r * n1]);
}

/// `d = |a|`, analytic while `a` keeps its sign: `d_k = sign(a_0) a_k` (`a_0 = 0` counts as
/// positive).
#[inline(always)]
pub fn abs<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize) {
    let v = w[a * n1 + k];
    w[d * n1 + k] = if w[a * n1] < T::zero() { -v } else { v };
}

/// `d = sign(a)`: constant while `a` keeps its sign.
#[inline(always)]
pub fn sign<T: Float>(w: &mut [T], n1: usize, k: usize, d: usize, a: usize) {
    w[d * n1 + k] = if k == 0 { Func::Sign.apply(w[a * n1]) } else { T::zero() };
}

/// The states' coefficient `k` from the right-hand side's coefficient `k - 1`:
/// `y_k = f_{k-1} / k`, for each `(slot, result)` pair.
#[inline(always)]
pub fn states<T: Float>(w: &mut [T], n1: usize, k: usize, pairs: &[(usize, usize)]) {
    let kt = count::<T>(k);
    for &(slot, result) in pairs {
        w[slot * n1 + k] = w[result * n1 + k - 1] / kt;
    }
}

/// The coefficients of every state into `out` (state-major, `order + 1` each): `y` itself, then
/// `f_{k-1} / k` from the results `results[i]` of state `i`.
#[inline(always)]
pub fn finish<T: Float>(w: &[T], n1: usize, y: &[T], results: &[usize], out: &mut [T]) {
    for (i, &r) in results.iter().enumerate() {
        out[i * n1] = y[i];
        for k in 1..n1 {
            out[i * n1 + k] = w[r * n1 + k - 1] / count(k);
        }
    }
}
