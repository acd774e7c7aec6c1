//! Orientation helpers generated outputs call: in come direction cosines; out goes a unit
//! quaternion.

/// A unit quaternion (scalar first, non-negative) from direction cosines `r` (row by row, an
/// orthonormal matrix), by Shepperd's method: the largest of the four squares is found first,
/// so no square root of a small difference is taken.
pub fn quaternion_from_dcm<T: num_traits::Float>(r: &[T; 9]) -> [T; 4] {
    let one = T::one();
    let quarter = T::from(0.25).unwrap_or_else(T::nan);
    let half = T::from(0.5).unwrap_or_else(T::nan);
    let trace = r[0] + r[4] + r[8];
    let diag = [trace, r[0], r[4], r[8]];
    let k = (0..4).fold(0, |best, i| if diag[i] > diag[best] { i } else { best });
    let s = (one + diag[k] + diag[k] - trace).sqrt() * half; // |q_k|
    let f = quarter / s;
    let (a, b, c) = (r[7] - r[5], r[2] - r[6], r[3] - r[1]);
    let (d, e, g) = (r[1] + r[3], r[2] + r[6], r[5] + r[7]);
    let q = match k {
        0 => [s, a * f, b * f, c * f],
        1 => [a * f, s, d * f, e * f],
        2 => [b * f, d * f, s, g * f],
        _ => [c * f, e * f, g * f, s],
    };
    if q[0] < T::zero() {
        q.map(|x| -x)
    } else {
        q
    }
}

#[cfg(test)]
mod tests {
    use super::quaternion_from_dcm;

    #[test]
    fn quaternion_round_trips_through_its_dcm() {
        for q in
            [[0.9f64, 0.1, -0.3, 0.2], [0.05, 0.7, 0.1, -0.6], [0.0, 0.0, 0.0, 1.0], [0.1, -0.2, 0.9, 0.3]]
        {
            let n = q.iter().map(|x| x * x).sum::<f64>().sqrt();
            let [e0, e1, e2, e3] = q.map(|x| x / n);
            // Body-to-space rotation matrix of the quaternion.
            let r = [
                e0 * e0 + e1 * e1 - e2 * e2 - e3 * e3,
                2.0 * (e1 * e2 - e0 * e3),
                2.0 * (e1 * e3 + e0 * e2),
                2.0 * (e1 * e2 + e0 * e3),
                e0 * e0 - e1 * e1 + e2 * e2 - e3 * e3,
                2.0 * (e2 * e3 - e0 * e1),
                2.0 * (e1 * e3 - e0 * e2),
                2.0 * (e2 * e3 + e0 * e1),
                e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3,
            ];
            let got = quaternion_from_dcm(&r);
            let sign = if e0 < 0.0 { -1.0 } else { 1.0 };
            for (g, w) in got.iter().zip([e0, e1, e2, e3]) {
                assert!((g - sign * w).abs() < 1e-12, "{got:?} vs {q:?}");
            }
        }
    }
}
