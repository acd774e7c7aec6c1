//! The Taylor-coefficient recurrences generated `taylor` functions call: in comes a work array of normalised Taylor coefficients, one row per value
//! (value `v`'s coefficient `k` at `w[v][k]`, so `v(t + h) = sum_k w[v][k] h^k`), whose operands
//! are known through order `k`; out goes coefficient `k` of one value. Order 0 is the plain
//! operation. The code generator's evaluator (`TaylorProgram::coefficients`) and generated code
//! call the same functions, so both compute the same numbers. Rows have a fixed length
//! ([`MAX_ORDER`]` + 1`), so generated code indexes them without multiplications.
//!
//! Operands come before the value they define (SSA), so every function reads before it writes.

use num_traits::Float;

/// The highest order a Taylor expansion takes (a step at tolerance 1e-16 takes 20).
pub const MAX_ORDER: usize = 32;

/// One value's coefficients, orders `0..=MAX_ORDER`.
pub type Row<T> = [T; MAX_ORDER + 1];

/// An inverse function `f` whose derivative is `f(a)' = a' / q` ([`integral`] takes it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Inverse {
    /// `atan(a)`, with `q = 1 + a^2`.
    Atan,
    /// `asin(a)`, with `q = sqrt(1 - a^2)`.
    Asin,
    /// `acos(a)`, with `q = -sqrt(1 - a^2)`.
    Acos,
}

impl Inverse {
    /// The function's value at `x`.
    #[inline(always)]
    pub fn apply<T: Float>(self, x: T) -> T {
        match self {
            Inverse::Atan => x.atan(),
            Inverse::Asin => x.asin(),
            Inverse::Acos => x.acos(),
        }
    }
}

/// Whether this CPU has fused multiply-add, which the straight-line coefficients are compiled
/// for (x86 checks at run time, once; AArch64 always has it).
#[inline]
pub fn fused_multiply_add() -> bool {
    #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
    {
        std::is_x86_feature_detected!("fma")
    }
    #[cfg(target_arch = "aarch64")]
    {
        true
    }
    #[cfg(not(any(target_arch = "x86", target_arch = "x86_64", target_arch = "aarch64")))]
    {
        false
    }
}

/// `k` as `T`.
#[inline(always)]
pub fn count<T: Float>(k: usize) -> T {
    T::from(k).unwrap_or_else(T::nan)
}

/// `sum_{j=lo}^{hi} x_j y_{k-j}` over the coefficients of `x` and `y`.
#[inline(always)]
fn cauchy<T: Float>(w: &[Row<T>], k: usize, x: usize, y: usize, lo: usize, hi: usize) -> T {
    if lo > hi {
        return T::zero();
    }
    let xs = &w[x][lo..=hi];
    let ys = &w[y][k - hi..=k - lo];
    dot_reversed(xs, ys)
}

/// `sum_j xs[j] ys[len - 1 - j]` in four interleaved partial sums (independent chains of
/// additions, so consecutive products overlap instead of waiting on one running sum).
#[inline(always)]
fn dot_reversed<T: Float>(xs: &[T], ys: &[T]) -> T {
    let n = xs.len().min(ys.len());
    let (xs, ys) = (&xs[..n], &ys[..n]);
    let mut acc = [T::zero(); 4];
    let quads = n / 4;
    for q in 0..quads {
        for (l, a) in acc.iter_mut().enumerate() {
            let j = 4 * q + l;
            *a = *a + xs[j] * ys[n - 1 - j];
        }
    }
    let tail = (4 * quads..n).fold(T::zero(), |s, j| s + xs[j] * ys[n - 1 - j]);
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

/// `sum_{j=1}^{hi} j x_j y_{k-j}`: the sum of the derivative rules.
#[inline(always)]
fn weighted<T: Float>(w: &[Row<T>], k: usize, x: usize, y: usize, hi: usize) -> T {
    let xs = &w[x][1..=hi];
    let ys = &w[y][k - hi..k];
    let n = xs.len().min(ys.len());
    let term = |j: usize| count::<T>(j + 1) * xs[j] * ys[n - 1 - j];
    let mut acc = [T::zero(); 4];
    let quads = n / 4;
    for q in 0..quads {
        for (l, a) in acc.iter_mut().enumerate() {
            *a = *a + term(4 * q + l);
        }
    }
    let tail = (4 * quads..n).fold(T::zero(), |s, j| s + term(j));
    (acc[0] + acc[1]) + (acc[2] + acc[3]) + tail
}

/// `d = a + b`.
#[inline(always)]
pub fn add<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, b: usize) {
    w[d][k] = w[a][k] + w[b][k];
}

/// `d = a - b`.
#[inline(always)]
pub fn sub<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, b: usize) {
    w[d][k] = w[a][k] - w[b][k];
}

/// `d = -a`.
#[inline(always)]
pub fn neg<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize) {
    w[d][k] = -w[a][k];
}

/// `d = a b` (Leibniz's rule: the Cauchy product).
#[inline(always)]
pub fn mul<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, b: usize) {
    w[d][k] = cauchy(w, k, a, b, 0, k);
}

/// `d = a^2` (the Cauchy product with each cross term once, doubled).
#[inline(always)]
pub fn sqr<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize) {
    let half = k.div_ceil(2);
    let cross = if half == 0 { T::zero() } else { cauchy(w, k, a, a, 0, half - 1) };
    let middle = if k.is_multiple_of(2) { w[a][k / 2] * w[a][k / 2] } else { T::zero() };
    w[d][k] = cross + cross + middle;
}

/// `d = a s` for a constant `s` (its coefficient 0).
#[inline(always)]
pub fn scale<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, s: usize) {
    w[d][k] = w[a][k] * w[s][0];
}

/// `d = a / b`: `d_k = (a_k - sum_{j=1}^k b_j d_{k-j}) / b_0`.
#[inline(always)]
pub fn div<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, b: usize) {
    let s = cauchy(w, k, b, d, 1, k);
    w[d][k] = (w[a][k] - s) / w[b][0];
}

/// `d = a / s` for a constant `s`.
#[inline(always)]
pub fn div_const<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, s: usize) {
    w[d][k] = w[a][k] / w[s][0];
}

/// `d = sqrt(a)`: `d_k = (a_k - sum_{j=1}^{k-1} d_j d_{k-j}) / (2 d_0)`.
#[inline(always)]
pub fn sqrt<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize) {
    if k == 0 {
        w[d][0] = w[a][0].sqrt();
        return;
    }
    let s = cauchy(w, k, d, d, 1, k - 1);
    w[d][k] = (w[a][k] - s) / (w[d][0] + w[d][0]);
}

/// `d = exp(a)`: `d_k = (1/k) sum_{j=1}^k j a_j d_{k-j}`.
#[inline(always)]
pub fn exp<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize) {
    w[d][k] = if k == 0 { w[a][0].exp() } else { weighted(w, k, a, d, k) / count(k) };
}

/// `d = ln(a)`: `d_k = (a_k - (1/k) sum_{j=1}^{k-1} j d_j a_{k-j}) / a_0`.
#[inline(always)]
pub fn ln<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize) {
    if k == 0 {
        w[d][0] = w[a][0].ln();
        return;
    }
    let s = if k > 1 { weighted(w, k, d, a, k - 1) / count(k) } else { T::zero() };
    w[d][k] = (w[a][k] - s) / w[a][0];
}

/// `d = sin(a)`, `c` its partner `cos(a)`: `d_k = (1/k) sum_{j=1}^k j a_j c_{k-j}`.
#[inline(always)]
pub fn sin<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, c: usize) {
    w[d][k] = if k == 0 { w[a][0].sin() } else { weighted(w, k, a, c, k) / count(k) };
}

/// `d = cos(a)`, `s` its partner `sin(a)`: `d_k = -(1/k) sum_{j=1}^k j a_j s_{k-j}`.
#[inline(always)]
pub fn cos<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, s: usize) {
    w[d][k] = if k == 0 { w[a][0].cos() } else { -weighted(w, k, a, s, k) / count(k) };
}

/// `d = sinh(a)`, `c` its partner `cosh(a)`.
#[inline(always)]
pub fn sinh<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, c: usize) {
    w[d][k] = if k == 0 { w[a][0].sinh() } else { weighted(w, k, a, c, k) / count(k) };
}

/// `d = cosh(a)`, `s` its partner `sinh(a)`.
#[inline(always)]
pub fn cosh<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, s: usize) {
    w[d][k] = if k == 0 { w[a][0].cosh() } else { weighted(w, k, a, s, k) / count(k) };
}

/// `d = f(a)` where `d' = a' / q` (atan: `q = 1 + a^2`; asin: `q = sqrt(1 - a^2)`; acos:
/// `q = -sqrt(1 - a^2)`): `k d_k = (k a_k - sum_{i=1}^{k-1} q_i (k-i) d_{k-i}) / q_0`.
#[inline(always)]
pub fn integral<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize, q: usize, f: Inverse) {
    if k == 0 {
        w[d][0] = f.apply(w[a][0]);
        return;
    }
    let kt = count::<T>(k);
    let s = if k > 1 { weighted(w, k, d, q, k - 1) } else { T::zero() };
    w[d][k] = (kt * w[a][k] - s) / (kt * w[q][0]);
}

/// `d = atan2(y, x)` with `r = x^2 + y^2`: `d' r = x y' - y x'`, so
/// `k d_k r_0 = sum_{j=1}^k j (x_{k-j} y_j - y_{k-j} x_j) - sum_{i=1}^{k-1} r_i (k-i) d_{k-i}`.
#[inline(always)]
pub fn atan2<T: Float>(w: &mut [Row<T>], k: usize, d: usize, y: usize, x: usize, r: usize) {
    if k == 0 {
        w[d][0] = w[y][0].atan2(w[x][0]);
        return;
    }
    let num = weighted(w, k, y, x, k) - weighted(w, k, x, y, k);
    let s = if k > 1 { weighted(w, k, d, r, k - 1) } else { T::zero() };
    w[d][k] = (num - s) / (count::<T>(k) * w[r][0]);
}

/// `d = |a|`, analytic while `a` keeps its sign: `d_k = sign(a_0) a_k` (`a_0 = 0` counts as
/// positive).
#[inline(always)]
pub fn abs<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize) {
    let v = w[a][k];
    w[d][k] = if w[a][0] < T::zero() { -v } else { v };
}

/// `d = sign(a)`: constant while `a` keeps its sign.
#[inline(always)]
pub fn sign<T: Float>(w: &mut [Row<T>], k: usize, d: usize, a: usize) {
    w[d][k] = if k == 0 { super::sign(w[a][0]) } else { T::zero() };
}

/// Rows ready for an expansion of `order` (at most [`MAX_ORDER`]; false, nothing done, above):
/// `rows` of them, the constant ones (`constants`) zero past order 0 and time's row
/// (`time`, if read) `t, 1, 0, ...`. Rows of varying values are written before they are read.
#[inline(always)]
pub fn start<T: Float>(
    work: &mut Vec<Row<T>>,
    rows: usize,
    order: usize,
    constants: &[usize],
    time: Option<(usize, T)>,
) -> bool {
    if order > MAX_ORDER {
        return false;
    }
    if work.len() < rows {
        work.resize(rows, [T::zero(); MAX_ORDER + 1]);
    }
    for &c in constants {
        work[c][1..=order].fill(T::zero());
    }
    if let Some((v, t)) = time {
        work[v][..=order].fill(T::zero());
        work[v][0] = t;
        if order > 0 {
            work[v][1] = T::one();
        }
    }
    true
}

/// The states' coefficient `k` from the right-hand side's coefficient `k - 1`:
/// `y_k = f_{k-1} / k` (times `1/k`, as in [`finish`]), for each `(row, result)` pair.
#[inline(always)]
pub fn states<T: Float>(w: &mut [Row<T>], k: usize, pairs: &[(usize, usize)]) {
    let inverse = T::one() / count::<T>(k);
    for &(row, result) in pairs {
        w[row][k] = w[result][k - 1] * inverse;
    }
}

/// The coefficients of every state into `out` (state-major, `order + 1` each): `y` itself, then
/// `f_{k-1} / k` from the results `results[i]` of state `i`.
#[inline(always)]
pub fn finish<T: Float>(w: &[Row<T>], order: usize, y: &[T], results: &[usize], out: &mut [T]) {
    let n1 = order + 1;
    for (i, y) in y.iter().enumerate().take(results.len()) {
        out[i * n1] = *y;
    }
    for k in 1..n1 {
        let inverse = T::one() / count::<T>(k);
        for (i, &r) in results.iter().enumerate() {
            out[i * n1 + k] = w[r][k - 1] * inverse;
        }
    }
}
