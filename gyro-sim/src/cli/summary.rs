//! The run summary printed: in comes a finished run; out go its statistics, energy and
//! conserved-quantity drifts, the Euler-parameter norm, the files and the accuracy reached.

use crate::run;

/// The run's statistics, energy, files and accuracy.
pub fn print_summary(title: &str, summary: &run::RunSummary) {
    let t = &summary.trajectory;
    let energy = match (t.kinetic_energy, t.potential_energy) {
        (Some((ka, kb)), Some((pa, pb))) => {
            let (a, b) = (ka + pa, kb + pb);
            format!(
                "; total energy (kinetic + gravity's potential) {a:.6e} -> {b:.6e} (change {:+.6e}; kinetic {ka:.6e} -> {kb:.6e})",
                b - a
            )
        }
        (Some((a, b)), None) => format!("; kinetic energy {a:.6e} -> {b:.6e} (change {:+.6e})", b - a),
        _ => String::new(),
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
    if let Some(note) = summary.written.as_ref().and_then(|w| aliasing_note(t, w.rows)) {
        println!("{note}");
    }
    for line in conserved_drifts(t) {
        println!("{line}");
    }
    if let Some(d) = t.norm_drift {
        println!(
            "Euler-parameter norm: largest drift {:.2e} (projected back past {:.0e}: {} times); outputs use the normalised parameters",
            d.largest, d.threshold, d.projections
        );
    }
    if let Some(c) = &t.constraints {
        constraint_lines(c).iter().for_each(|l| println!("{l}"));
    }
    for line in event_lines(&t.events) {
        println!("{line}");
    }
    if let Some(a) = t.accuracy {
        println!(
            "accuracy {:e} asked: {} runs; the written one (rtol {:.1e}, atol {:.1e}) differs by {:.2e} from the run before (about that run's error; the written run's is far smaller)",
            a.goal, a.runs, a.rtol, a.atol, a.estimate
        );
    }
}

/// A note when the figures are drawn from the `rows` alone while the integrator stepped several
/// times per row (the motion may be faster than the rows show).
fn aliasing_note(t: &crate::problem::Trajectory, rows: usize) -> Option<String> {
    if !t.plot_rows.is_empty() || rows < 2 {
        return None;
    }
    let per_row = t.stats.steps as f64 / (rows - 1) as f64;
    (per_row >= crate::problem::STEPS_PER_ROW_DENSE).then(|| {
        format!(
            "note: {per_row:.0} integrator steps per output row: the figures, drawn from the rows alone, may miss a motion faster than the rows; --plot-points 10 (plot_points = 10 in a scene) draws them from the dense output"
        )
    })
}

/// One line per event declared: how many times it happened and the first times; and the
/// event that stopped the run.
fn event_lines(log: &crate::problem::EventLog) -> Vec<String> {
    const SHOWN: usize = 3;
    let mut lines: Vec<String> = log
        .names
        .iter()
        .enumerate()
        .map(|(i, name)| {
            let times: Vec<f64> = log.records.iter().filter(|r| r.event == i).map(|r| r.row[0]).collect();
            let first: Vec<String> = times.iter().take(SHOWN).map(|t| format!("{t:.9}")).collect();
            let more = if times.len() > SHOWN { ", ..." } else { "" };
            match times.len() {
                0 => format!("event {name}: none"),
                n => format!("event {name}: {n} at t = {}{more}", first.join(", ")),
            }
        })
        .collect();
    if let Some((name, t)) = &log.stopped {
        lines.push(format!(
            "stopped by event {name} at t = {t:.12}: rows at the output times before it, then a last row at it"
        ));
    }
    lines.extend(event_warnings(log));
    lines
}

/// A warning per event whose sign changes outran the steps (crossings may be missing) or the
/// output rows (crossings the rows cannot show).
fn event_warnings(log: &crate::problem::EventLog) -> Vec<String> {
    let name = |i: usize| log.names.get(i).map_or("?", String::as_str);
    let mut lines: Vec<String> = log
        .unsettled
        .iter()
        .map(|u| {
            format!(
                "warning: event {}: its sign changes may be incomplete near t = {:.9} ({} step(s)): its value came near zero faster than a split of the step to {:.1e} s could settle, so two crossings closer than that, or a touch of zero without a crossing, may be missed there; tighten rtol and atol under [integrator] for shorter steps",
                name(u.event), u.t, u.steps, u.width
            )
        })
        .collect();
    lines.extend(log.crowded.iter().map(|c| {
        format!(
            "warning: event {}: {} crossings between the rows at t = {} and {} (the closest {:.3e} s apart): the rows cannot show them, events.csv lists each; an output_step of {:.3e} or less would put a row between them",
            name(c.event), c.most, c.from, c.to, c.gap, c.gap
        )
    }));
    lines
}

/// The assembled start and the largest constraint residuals of the run.
fn constraint_lines(c: &crate::problem::Constraints) -> Vec<String> {
    let mut lines = Vec::new();
    if let Some(a) = &c.assembly {
        let start = if a.iterations == 0 {
            "the initial state satisfies them".to_string()
        } else {
            let moved: Vec<String> =
                a.moved.iter().map(|(name, from, to)| format!("{name} {from} -> {to}")).collect();
            format!("the start assembled by {} Newton steps ({})", a.iterations, moved.join(", "))
        };
        let along = c.configuration.map_or(String::new(), |r| format!(", {r:.2e} at the output times"));
        lines.push(format!(
            "configuration constraints: {start}; largest residual {:.2e} at the start{along}",
            a.residual
        ));
    }
    if let Some(r) = c.motion {
        lines.push(format!(
            "motion constraints: dependent speeds solved at every evaluation; largest residual {r:.2e} at the output times"
        ));
    }
    if let Some(k) = &c.conditioning {
        lines.push(conditioning_line(k));
    }
    lines
}

/// Below this reciprocal condition number the dependent speeds may have lost half their digits.
const NEAR_RANK_LOSS: f64 = 1e-8;

/// The worst conditioning of the dependent speeds' matrix, a warning when it came near rank
/// loss.
fn conditioning_line(k: &crate::problem::Conditioning) -> String {
    if k.rcond >= NEAR_RANK_LOSS {
        format!(
            "motion constraints: matrix of dependent speeds reciprocal condition {:.2e} at worst (t = {})",
            k.rcond, k.time
        )
    } else {
        format!(
            "warning: the motion constraints came near rank loss at t = {}, {}: their matrix of dependent speeds has reciprocal condition {:.2e}, so the dependent speeds there may have lost up to {:.0} of their 16 digits",
            k.time,
            k.configuration,
            k.rcond,
            -k.rcond.log10()
        )
    }
}

/// The drift of the conserved quantities the run wrote (`ENERGY`, `LZ`, `L3`): start, end and
/// the change relative to max(1, |start|).
fn conserved_drifts(t: &crate::problem::Trajectory) -> Vec<String> {
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
