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

/// The tick labels of an axis spanning `lo..hi` (see [`tick_label`]); a tick within a
/// billionth of the span of zero (round-off of the tick arithmetic) is labelled 0.
pub(super) fn tick_labels(lo: f64, hi: f64) -> impl Fn(&f64) -> String {
    let zero = 1e-9 * (hi - lo).abs();
    move |v: &f64| if v.abs() <= zero { "0".into() } else { tick_label(*v) }
}

/// An axis tick's label: at most 6 significant digits, trailing zeros dropped, never `-0` (so
/// neither `-0.0` nor `0.6000000000000001`); very large or small magnitudes in exponent form.
pub(super) fn tick_label(v: f64) -> String {
    if v == 0.0 {
        return "0".into();
    }
    if !v.is_finite() {
        return format!("{v}");
    }
    let magnitude = v.abs().log10().floor() as i32;
    if !(-4..7).contains(&magnitude) {
        let text = format!("{v:.5e}");
        let (mantissa, exponent) = text.split_once('e').unwrap_or((&text, "0"));
        return format!("{}e{exponent}", trimmed(mantissa));
    }
    // Five decimals past the leading digit: a value this large never rounds to zero.
    let decimals = (5 - magnitude).clamp(0, 10) as usize;
    trimmed(&format!("{v:.decimals$}")).to_string()
}

/// A decimal number's text without trailing zeros after its point (nor the point itself).
fn trimmed(text: &str) -> &str {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        text
    }
}

/// The width of a series' line, px: 1 when it has more points than a quarter of the pixels
/// across (a thicker line's joints would draw a staircase with gaps), else 2.
pub(super) fn line_width(points: usize, pixels_across: u32) -> u32 {
    if points > pixels_across as usize / 4 {
        1
    } else {
        2
    }
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

    #[test]
    fn tick_labels_are_short_and_never_minus_zero() {
        let label = tick_label;
        assert_eq!(label(-0.0), "0");
        assert_eq!(label(0.6000000000000001), "0.6");
        assert_eq!(label(3000.5), "3000.5");
        assert_eq!(label(-70.0), "-70");
        assert_eq!(label(25000.0), "25000");
        assert_eq!(label(0.15), "0.15");
        assert_eq!(label(-1e-17), "-1e-17");
        assert_eq!(label(1.5e8), "1.5e8");
        assert_eq!(label(2.5e-5), "2.5e-5");
        assert_eq!(label(1e100), "1e100");
        assert_eq!(label(f64::NAN), "NaN");
        let axis = tick_labels(-0.3, 0.3);
        assert_eq!(axis(&5.551115123125783e-17), "0");
        assert_eq!(axis(&-0.1), "-0.1");
        assert_eq!(tick_labels(1e-15, 3e-15)(&2e-15), "2e-15");
    }

    #[test]
    fn dense_series_are_drawn_one_pixel_wide() {
        assert_eq!(line_width(101, 500), 2);
        assert_eq!(line_width(1001, 500), 1);
    }
}
