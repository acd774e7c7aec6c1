//! Work against precision (`gyro-sim bench`): in comes a resolved problem; out go, for every
//! method over a range of tolerances (fixed-step methods: a range of steps), the error against
//! a reference run and the median wall time. Runs are interleaved (each repeat goes over every
//! configuration once), so a slow spell of the machine spreads over all of them.

use crate::ode::{Method, Tolerances, METHODS};
use crate::output::WorkPrecisionPoint;
use crate::problem::{Pick, Problem, SolveError, Trajectory};
use crate::solve::solve;

/// What to measure.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Adaptive methods run at `10^-k` for these `k` (rtol = atol).
    pub decades: Vec<i32>,
    /// Fixed-step methods run at `output_step / 2^k` for these `k`.
    pub halvings: Vec<i32>,
    /// Timed runs per configuration (the median is reported).
    pub repeats: usize,
    /// The reference: DOP853 at this tolerance.
    pub reference_tolerance: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            decades: (3..=13).collect(),
            halvings: (0..=7).collect(),
            repeats: 5,
            reference_tolerance: 1e-14,
        }
    }
}

/// Measures every method on `problem` (its columns replaced by the states; no accuracy
/// refinement): the points, method by method, in increasing accuracy asked.
pub fn measure(problem: &Problem, options: &Options) -> Result<Vec<WorkPrecisionPoint>, SolveError> {
    let mut base = problem.clone();
    base.picks = (0..problem.model.info().state_names.len()).map(Pick::State).collect();
    base.written_picks = base.picks.len();
    base.accuracy = None;
    base.plot_times.clear();
    let reference_tol = Tolerances { rtol: options.reference_tolerance, atol: options.reference_tolerance };
    let reference = run(&base, Method::Adaptive(&crate::ode::tableau::DOP853, reference_tol))?;
    let configs = configurations(problem, options);
    let mut walls: Vec<Vec<f64>> = vec![Vec::new(); configs.len()];
    let mut points: Vec<Option<WorkPrecisionPoint>> = vec![None; configs.len()];
    for _ in 0..options.repeats.max(1) {
        for (k, (name, setting, method)) in configs.iter().enumerate() {
            let failed = |e: SolveError| WorkPrecisionPoint {
                method: name,
                setting: *setting,
                error: f64::NAN,
                median_ms: f64::NAN,
                steps: 0,
                rhs_evals: 0,
                failure: Some(e.to_string()),
            };
            let point = match run(&base, *method) {
                Ok(t) => {
                    walls[k].push(t.wall.as_secs_f64() * 1e3);
                    WorkPrecisionPoint {
                        method: name,
                        setting: *setting,
                        error: largest_error(&t, &reference),
                        median_ms: f64::NAN,
                        steps: t.stats.steps,
                        rhs_evals: t.stats.rhs_evals,
                        failure: None,
                    }
                }
                Err(e) => failed(e),
            };
            points[k] = Some(point);
        }
    }
    let mut out = Vec::with_capacity(configs.len());
    for (point, mut w) in points.into_iter().zip(walls) {
        w.sort_by(f64::total_cmp);
        let median = w.get(w.len() / 2).copied().unwrap_or(f64::NAN);
        out.extend(point.map(|p| WorkPrecisionPoint { median_ms: median, ..p }));
    }
    Ok(out)
}

/// Every method with each of its settings.
fn configurations(problem: &Problem, options: &Options) -> Vec<(&'static str, f64, Method)> {
    let step = problem.times.get(1).map_or(1.0, |t| t - problem.times[0]);
    let mut out = Vec::new();
    for m in METHODS {
        if m.adaptive {
            for k in &options.decades {
                let tol = 10f64.powi(-k);
                out.push((m.name(), tol, m.method(Tolerances { rtol: tol, atol: tol }, step)));
            }
        } else {
            for k in &options.halvings {
                let h = step / 2f64.powi(*k);
                out.push((m.name(), h, m.method(Tolerances { rtol: 0.0, atol: 0.0 }, h)));
            }
        }
    }
    out
}

fn run(base: &Problem, method: Method) -> Result<Trajectory, SolveError> {
    let mut p = base.clone();
    p.method = method;
    solve(&p, None)
}

/// The largest difference of `t` from `reference` over rows and columns, relative to
/// max(1, |reference|).
pub fn largest_error(t: &Trajectory, reference: &Trajectory) -> f64 {
    let width = reference.columns.len() + 1;
    crate::solve::largest_difference(&t.rows, &reference.rows, width)
}

/// The points as CSV text: `method,setting,error,median_ms,steps,rhs_evals,failure` (a failed
/// run's numbers empty).
pub fn to_csv(points: &[WorkPrecisionPoint]) -> String {
    let mut s = String::from("method,setting,error,median_ms,steps,rhs_evals,failure\n");
    for p in points {
        match &p.failure {
            None => s.push_str(&format!(
                "{},{:e},{:e},{:.6},{},{},\n",
                p.method, p.setting, p.error, p.median_ms, p.steps, p.rhs_evals
            )),
            Some(why) => {
                s.push_str(&format!("{},{:e},,,,,\"{}\"\n", p.method, p.setting, why.replace('"', "'")))
            }
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tighter_tolerances_give_smaller_errors_on_trial_three() {
        let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/paper/trial3.toml");
        let scene = crate::scene::Scene::load(std::path::Path::new(path)).unwrap();
        let problem = crate::resolve::resolve(&scene, &crate::models::Registry::builtin()).unwrap();
        let options =
            Options { decades: vec![4, 8], halvings: vec![5, 7], repeats: 1, reference_tolerance: 1e-13 };
        let points = measure(&problem, &options).unwrap();
        assert_eq!(points.len(), 2 * METHODS.len());
        for pair in points.chunks(2) {
            assert_eq!(pair[0].method, pair[1].method);
            assert!(pair[1].error < pair[0].error / 10.0, "{pair:?}");
            // The Taylor method raises its order (coefficient passes) rather than its steps.
            let work =
                |p: &WorkPrecisionPoint| if p.method == crate::ode::TAYLOR { p.rhs_evals } else { p.steps };
            assert!(work(&pair[1]) > work(&pair[0]), "{pair:?}");
        }
        let csv = to_csv(&points);
        assert!(
            csv.starts_with("method,setting,error,median_ms,steps,rhs_evals,failure\ndop853,1e-4,"),
            "{csv}"
        );
        assert!(points.iter().all(|p| p.failure.is_none() && p.median_ms > 0.0));
    }
}
