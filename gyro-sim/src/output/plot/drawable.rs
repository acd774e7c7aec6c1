//! What a figure can draw: values beyond [`DRAWABLE`] in magnitude are drawn at it (the CSV keeps
//! them exact), since an axis spanning them overflows the arithmetic of its ticks; a range is
//! padded without overflow.

/// The largest magnitude a figure draws.
pub(super) const DRAWABLE: f64 = 1e100;

/// `v` clipped to what a figure draws (NaN stays NaN: not drawn).
pub(super) fn clip(v: f64) -> f64 {
    v.clamp(-DRAWABLE, DRAWABLE)
}

/// Whether `v` lies beyond what a figure draws.
pub(super) fn clipped(v: f64) -> bool {
    v.abs() > DRAWABLE
}

/// The finite range of `values` after clipping, padded by 5 % (widened around a constant);
/// `(0, 1)` when none is finite.
pub(super) fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .map(clip)
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| (a.min(v), b.max(v)));
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    // A (nearly) constant series gets a visible range instead of magnified round-off.
    let scale = lo.abs().max(hi.abs()).max(1e-300);
    if hi - lo <= 1e-9 * scale {
        let mid = 0.5 * lo + 0.5 * hi;
        let half = if mid == 0.0 { 1.0 } else { 0.05 * mid.abs() };
        return (mid - half, mid + half);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad, hi + pad)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn huge_values_are_clipped_and_ranges_stay_finite() {
        let (lo, hi) = padded_range([-1.7e308, 1.7e308, f64::NAN, f64::INFINITY].into_iter());
        assert!(lo.is_finite() && hi.is_finite() && lo < -DRAWABLE * 0.99 && hi > DRAWABLE * 0.99);
        assert_eq!(padded_range([2.0, 2.0].into_iter()), (1.9, 2.1));
        assert_eq!(padded_range([f64::NAN].into_iter()), (0.0, 1.0));
        assert_eq!(padded_range([0.0, 10.0].into_iter()), (-0.5, 10.5));
        assert!(clipped(1.7e308) && !clipped(1e99));
        assert_eq!(clip(-1.7e308), -DRAWABLE);
    }
}
