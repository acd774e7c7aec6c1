//! The run summary printed: in comes a finished run; out go its statistics, energy and
//! conserved-quantity drifts, the Euler-parameter norm, the files and the accuracy reached.

use crate::run;

/// The run's statistics, energy, files and accuracy.
pub fn print_summary(title: &str, summary: &run::RunSummary) {
    let t = &summary.trajectory;
    let energy = match t.kinetic_energy {
        Some((a, b)) => format!("; kinetic energy {a:.6e} -> {b:.6e} (change {:+.6e})", b - a),
        None => String::new(),
    };
    let files = match &summary.written {
        Some(w) => format!("; wrote {} rows to {} and {}", w.rows, w.csv.display(), w.plot.display()),
        None => String::new(),
    };
    println!(
        "{title}: {} steps ({} rejected), {} RHS evaluations, {:.3} ms{energy}{files}",
        t.stats.steps,
        t.stats.rejected,
        t.stats.rhs_evals,
        t.wall.as_secs_f64() * 1e3,
    );
    for line in conserved_drifts(t) {
        println!("{line}");
    }
    if let Some(d) = t.norm_drift {
        println!(
            "Euler-parameter norm: largest drift {:.2e} (projected back past {:.0e}: {} times); outputs use the normalised parameters",
            d.largest, d.threshold, d.projections
        );
    }
    if let Some(a) = t.accuracy {
        println!(
            "accuracy {:e} asked: {} runs; the written one (rtol {:.1e}, atol {:.1e}) differs by {:.2e} from the run before (about that run's error; the written run's is far smaller)",
            a.goal, a.runs, a.rtol, a.atol, a.estimate
        );
    }
}

/// The drift of the conserved quantities the run wrote (`ENERGY`, `LZ`, `L3`): start, end and
/// the change relative to max(1, |start|).
fn conserved_drifts(t: &crate::trajectory::Trajectory) -> Vec<String> {
    let (Some(first), Some(last)) = (t.rows.first(), t.rows.last()) else { return Vec::new() };
    t.columns
        .iter()
        .enumerate()
        .filter(|(_, c)| ["ENERGY", "LZ", "L3"].iter().any(|n| c.name.eq_ignore_ascii_case(n)))
        .map(|(k, c)| {
            let (a, b) = (first[k + 1], last[k + 1]);
            format!(
                "{}: {a:.12e} -> {b:.12e} (drift {:.2e} relative)",
                c.name,
                (b - a).abs() / a.abs().max(1.0)
            )
        })
        .collect()
}
