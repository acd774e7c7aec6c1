//! The output grid a scene asks for: in come `t_final` and `output_step` (and the plot points
//! per interval); out go the output times, the plot times between them, or why the grid would
//! hold too many rows (what is wrong and what to do).

/// Most output rows a run may ask for (every row is held in memory until it is written).
pub const MAX_OUTPUT_ROWS: usize = 10_000_000;

/// Why `t_final` and `step` make too many output rows (what is wrong, what to do), or `None`
/// when their grid has at most [`MAX_OUTPUT_ROWS`] rows.
pub fn too_many_rows(t_final: f64, step: f64) -> Option<(String, String)> {
    let rows = (t_final / step).floor() + 2.0;
    if rows <= MAX_OUTPUT_ROWS as f64 {
        return None;
    }
    let max = MAX_OUTPUT_ROWS as f64 - 2.0;
    Some((
        format!(
            "t_final = {} with output_step = {} makes {rows:.3e} output rows, more than the {MAX_OUTPUT_ROWS} allowed",
            short(t_final),
            short(step)
        ),
        format!(
            "raise output_step to at least {:.3e}, or shorten t_final to at most {:.3e}",
            t_final / max,
            step * max
        ),
    ))
}

/// `x` as written by hand: plainly when moderate, else with an exponent.
fn short(x: f64) -> String {
    if (1e-3..1e6).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Output times `i * step` (never by repeated addition) up to `t_final`, which is the last one
/// exactly. The grid must be one [`too_many_rows`] accepts.
pub fn output_times(t_final: f64, step: f64) -> Vec<f64> {
    let n = (t_final / step * (1.0 + 1e-12)).floor() as usize;
    let mut times: Vec<f64> = (0..=n).map(|i| i as f64 * step).collect();
    if (times[n] - t_final).abs() > 1e-12 * t_final {
        times.push(t_final);
    } else {
        times[n] = t_final;
    }
    times
}

/// Plot points between the output times: `per_interval - 1` evenly inside each interval, at most
/// `max_points` in all.
pub fn plot_times(times: &[f64], per_interval: usize, max_points: usize) -> Vec<f64> {
    let per = per_interval.min(max_points / times.len().max(1)).max(1);
    let mut out = Vec::with_capacity(times.len() * per);
    for w in times.windows(2) {
        out.extend((1..per).map(|k| w[0] + (w[1] - w[0]) * k as f64 / per as f64));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grids_past_the_row_limit_are_named_with_a_way_on() {
        assert!(too_many_rows(10.0, 0.01).is_none());
        let (what, help) = too_many_rows(1e300, 0.1).unwrap();
        assert!(what.contains("t_final = 1e300") && what.contains("10000000 allowed"), "{what}");
        assert!(help.contains("raise output_step") && help.contains("shorten t_final"), "{help}");
        assert!(too_many_rows(100.0, 1e-9).is_some());
        assert!(too_many_rows(1.0, 1e-320).is_some(), "a quotient overflowing to infinity");
        let edge = (MAX_OUTPUT_ROWS - 2) as f64;
        assert!(too_many_rows(edge, 1.0).is_none() && too_many_rows(edge + 1.0, 1.0).is_some());
        assert_eq!(output_times(edge, 1.0).len(), MAX_OUTPUT_ROWS - 1);
    }
}
