//! Running a scene: parameters and initial state set with units, integration, outputs computed
//! only at output times and only those asked for, CSV and plot written atomically.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use kane_model::runtime::GeneratedModel;
use thiserror::Error;

use crate::models::{gimbal_gyroscope, heavy_top};
use crate::ode::{self, tableau, Method, OdeError, Stats, System, Tolerances};
use crate::output::{self, Column, Table};
use crate::scene::{Scene, SceneError, Value};

/// Why a run failed.
#[derive(Debug, Error)]
pub enum RunError {
    /// The scene asks for something the model does not have.
    #[error("{0}")]
    Scene(#[from] SceneError),
    /// The integration stopped.
    #[error("integration failed: {0}")]
    Ode(String),
    /// Writing the results failed.
    #[error("{0}")]
    Output(String),
}

/// What a run did.
#[derive(Clone, Debug)]
pub struct RunSummary {
    /// Integrator statistics.
    pub stats: Stats,
    /// Wall time of the integration (outputs included, files excluded).
    pub wall: Duration,
    /// The CSV written.
    pub csv: Option<PathBuf>,
    /// The plot written.
    pub plot: Option<PathBuf>,
    /// The table of results.
    pub table: Table,
    /// The states that were integrated (cyclic coordinates nothing needed are left out).
    pub integrated: Vec<&'static str>,
    /// Kinetic energy at the start and at the end (the end's cyclic coordinates at zero when
    /// they were not integrated: no energy depends on them).
    pub kinetic_energy: (f64, f64),
    /// How an asked accuracy was met, when the scene asks one.
    pub accuracy: Option<Accuracy>,
}

/// An accuracy asked of a run and how it was reached.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Accuracy {
    /// Asked: largest error relative to max(1, |value|).
    pub goal: f64,
    /// The difference between the written run and one at 100 times looser tolerances: about
    /// the looser run's error, far above the written run's.
    pub estimate: f64,
    /// Tolerances of the written run.
    pub rtol: f64,
    /// Absolute tolerance of the written run.
    pub atol: f64,
    /// Integrations done (their costs are summed in the statistics).
    pub runs: usize,
}

/// A generated model with parameters, as an ODE system.
pub struct ModelSystem<M: GeneratedModel> {
    /// Parameter values.
    params: M::Params,
    /// Their parameter-only quantities.
    derived: M::Derived,
}

impl<M: GeneratedModel> ModelSystem<M> {
    /// The system for these parameters.
    pub fn new(params: M::Params) -> Self {
        let derived = M::derive(&params);
        ModelSystem { params, derived }
    }
}

impl<M: GeneratedModel> System for ModelSystem<M> {
    fn dim(&self) -> usize {
        M::STATE_NAMES.len()
    }
    #[inline(always)]
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        M::rhs_derived(t, y, &self.params, &self.derived, dy)
    }
}

/// A system without some of its states (cyclic coordinates nothing asked for depends on): they
/// are held at zero, which no equation reads, and never integrated.
pub struct Reduced<'a, S: System> {
    inner: &'a S,
    keep: Vec<usize>,
    full: std::cell::RefCell<(Vec<f64>, Vec<f64>)>,
}

impl<'a, S: System> Reduced<'a, S> {
    /// `inner` restricted to the states `keep`.
    pub fn new(inner: &'a S, keep: Vec<usize>) -> Self {
        let n = inner.dim();
        Reduced { inner, keep, full: std::cell::RefCell::new((vec![0.0; n], vec![0.0; n])) }
    }

    /// The full state with the dropped coordinates at zero.
    pub fn expand(&self, y: &[f64], full: &mut [f64]) {
        full.fill(0.0);
        for (i, k) in self.keep.iter().enumerate() {
            full[*k] = y[i];
        }
    }
}

impl<S: System> System for Reduced<'_, S> {
    fn dim(&self) -> usize {
        self.keep.len()
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        let mut full = self.full.borrow_mut();
        let (fy, fdy) = &mut *full;
        for (i, k) in self.keep.iter().enumerate() {
            fy[*k] = y[i];
        }
        self.inner.rhs(t, fy, fdy);
        for (i, k) in self.keep.iter().enumerate() {
            dy[i] = fdy[*k];
        }
    }
}

/// Runs a scene; with `out_dir` the CSV and the plot are written there.
pub fn run(scene: &Scene, out_dir: Option<&Path>) -> Result<RunSummary, RunError> {
    match scene.model.as_str() {
        n if n == gimbal_gyroscope::Model::NAME => run_model::<gimbal_gyroscope::Model>(scene, out_dir),
        n if n == heavy_top::Model::NAME => run_model::<heavy_top::Model>(scene, out_dir),
        other => Err(RunError::Scene(scene.error_at(
            0..0,
            format!("unknown model `{other}`"),
            "see the compiled models",
        ))),
    }
}

fn is_angle(unit: &str) -> bool {
    matches!(unit.to_ascii_uppercase().as_str(), "DEG" | "RAD")
}

/// A scene value in the model's internal units (radians for angles).
fn internal(
    scene: &Scene,
    name: &str,
    v: &Value,
    model_unit: &str,
    span: &std::ops::Range<usize>,
) -> Result<f64, SceneError> {
    let mu = model_unit.to_ascii_uppercase();
    let given = v.unit.as_deref().map(|u| u.to_ascii_uppercase().replace(' ', ""));
    let deg = std::f64::consts::PI / 180.0;
    let wrong = |u: &str| {
        scene.error_at(
            span.clone(),
            format!(
                "`{name}` is in {}, not {u}",
                if mu.is_empty() { "no unit".to_string() } else { model_unit.to_string() }
            ),
            &format!(
                "write a plain number (in {}) or give a compatible unit",
                if mu.is_empty() { "the model's units" } else { model_unit }
            ),
        )
    };
    Ok(match (mu.as_str(), given.as_deref()) {
        ("DEG", None | Some("DEG")) => v.number * deg,
        ("DEG" | "RAD", Some("RAD")) | ("RAD", None) => v.number,
        ("RAD", Some("DEG")) => v.number * deg,
        ("RAD/SEC", None | Some("RAD/S" | "RAD/SEC")) => v.number,
        ("RAD/SEC", Some("DEG/S" | "DEG/SEC")) => v.number * deg,
        (_, None) => v.number,
        (m, Some(u)) if m == u.replace("SEC", "S") || m.replace("SEC", "S") == u.replace("SEC", "S") => {
            v.number
        }
        (_, Some(u)) => return Err(wrong(u)),
    })
}

/// `q1` + `DEG` -> `q1_deg`; `AP` + `M/SEC^2` -> `ap_m_per_s2`.
pub fn column_name(name: &str, unit: &str) -> String {
    let slug = unit
        .to_ascii_lowercase()
        .replace("sec", "s")
        .replace('/', "_per_")
        .replace(['^', ' '], "")
        .replace('*', "_");
    if slug.is_empty() {
        name.to_ascii_lowercase()
    } else {
        format!("{}_{slug}", name.to_ascii_lowercase())
    }
}

enum Pick {
    State(usize),
    Output(usize),
}

fn run_model<M: GeneratedModel>(scene: &Scene, out_dir: Option<&Path>) -> Result<RunSummary, RunError> {
    let mut params = M::Params::default();
    for (name, v, span) in &scene.parameters {
        let x = internal(scene, name, v, "", span)?;
        if !M::set_param(&mut params, name, x) {
            return Err(scene
                .error_at(
                    span.clone(),
                    format!("`{name}` is not a parameter of {}", M::NAME),
                    &format!("parameters: {}", M::PARAM_NAMES.join(", ")),
                )
                .into());
        }
    }
    if let Some(p) = M::PARAM_NAMES.iter().find(|p| !M::param(&params, p).is_some_and(f64::is_finite)) {
        return Err(scene
            .error_at(
                0..0,
                format!("parameter `{p}` has no value"),
                "set it under [parameters] (the model file's INPUT gives none)",
            )
            .into());
    }
    let mut y = M::initial_state();
    for (name, v, span) in &scene.initial {
        let Some(i) = M::STATE_NAMES.iter().position(|s| s.eq_ignore_ascii_case(name)) else {
            return Err(scene
                .error_at(
                    span.clone(),
                    format!("`{name}` is not a state of {}", M::NAME),
                    &format!("states: {}", M::STATE_NAMES.join(", ")),
                )
                .into());
        };
        y[i] = internal(scene, name, v, M::STATE_UNITS[i], span)?;
    }
    if let Some(i) = y.iter().position(|v| !v.is_finite()) {
        return Err(scene
            .error_at(
                0..0,
                format!("state `{}` has no initial value", M::STATE_NAMES[i]),
                "set it under [initial]",
            )
            .into());
    }
    // What to write: the states and outputs asked for (all when none are named).
    let mut picks: Vec<(Pick, Column)> = Vec::new();
    let mut add = |p: Pick, name: &str, unit: &str| {
        let output = matches!(p, Pick::Output(_));
        let column = Column {
            name: column_name(name, unit),
            label: name.to_string(),
            degrees: unit.eq_ignore_ascii_case("DEG"),
            angle: is_angle(unit),
            output,
        };
        picks.push((p, column));
    };
    if scene.outputs.is_empty() {
        for (i, s) in M::STATE_NAMES.iter().enumerate() {
            add(Pick::State(i), s, M::STATE_UNITS[i]);
        }
        for (j, o) in M::OUTPUT_NAMES.iter().enumerate() {
            add(Pick::Output(j), o, M::OUTPUT_UNITS[j]);
        }
    } else {
        for (name, span) in &scene.outputs {
            if let Some(i) = M::STATE_NAMES.iter().position(|s| s.eq_ignore_ascii_case(name)) {
                add(Pick::State(i), M::STATE_NAMES[i], M::STATE_UNITS[i]);
            } else if let Some(j) = M::OUTPUT_NAMES.iter().position(|s| s.eq_ignore_ascii_case(name)) {
                add(Pick::Output(j), M::OUTPUT_NAMES[j], M::OUTPUT_UNITS[j]);
            } else {
                let mut known: Vec<&str> = M::STATE_NAMES.to_vec();
                known.extend(M::OUTPUT_NAMES);
                return Err(scene
                    .error_at(
                        span.clone(),
                        format!("`{name}` is neither a state nor an output of {}", M::NAME),
                        &format!("known: {}", known.join(", ")),
                    )
                    .into());
            }
        }
    }
    let needs_outputs = picks.iter().any(|(p, _)| matches!(p, Pick::Output(_)));
    // Output times as i * step (never by repeated addition); the last one is t_final exactly.
    let n = (scene.t_final / scene.output_step * (1.0 + 1e-12)).floor() as usize;
    let mut times: Vec<f64> = (0..=n).map(|i| i as f64 * scene.output_step).collect();
    if (times[n] - scene.t_final).abs() > 1e-12 * scene.t_final {
        times.push(scene.t_final);
    } else {
        times[n] = scene.t_final;
    }
    let method = match scene.integrator.method.as_str() {
        "rk4" => Method::Fixed(&tableau::RK4, scene.integrator.step),
        "dop853" => Method::Adaptive(
            &tableau::DOP853,
            Tolerances { rtol: scene.integrator.rtol, atol: scene.integrator.atol },
        ),
        _ => Method::Adaptive(
            &tableau::DOPRI5,
            Tolerances { rtol: scene.integrator.rtol, atol: scene.integrator.atol },
        ),
    };
    // Cyclic coordinates that no column and no asked output reads are not integrated.
    let mut needed = vec![false; M::STATE_NAMES.len()];
    for (p, _) in &picks {
        match p {
            Pick::State(i) => needed[*i] = true,
            Pick::Output(j) => M::OUTPUT_STATES[*j].iter().for_each(|i| needed[*i] = true),
        }
    }
    let keep: Vec<usize> =
        (0..M::STATE_NAMES.len()).filter(|i| needed[*i] || !M::CYCLIC.contains(i)).collect();
    let full_sys = ModelSystem::<M>::new(params.clone());
    let sys = Reduced::new(&full_sys, keep.clone());
    let y_reduced: Vec<f64> = keep.iter().map(|k| y[*k]).collect();
    let ke_start = M::kinetic_energy(0.0, &y, &params);
    // One integration at `method`: the rows written and the full state at t_final.
    let integrate_at = |method: Method| -> Result<Integration, RunError> {
        let mut full_y = vec![0.0; M::STATE_NAMES.len()];
        let mut y_end = y.clone();
        let mut rows: Vec<Vec<f64>> = Vec::with_capacity(times.len());
        let mut outs = vec![0.0; M::OUTPUT_NAMES.len()];
        let stats = ode::integrate(&sys, 0.0, &y_reduced, &times, method, |t, y_red| {
            sys.expand(y_red, &mut full_y);
            y_end.copy_from_slice(&full_y);
            let y = &full_y[..];
            if needs_outputs {
                M::outputs(t, y, &params, &mut outs);
            }
            let mut row = Vec::with_capacity(picks.len() + 1);
            row.push(t);
            for (p, col) in &picks {
                let v = match p {
                    Pick::State(i) => y[*i],
                    Pick::Output(j) => outs[*j],
                };
                if !v.is_finite() {
                    return Err(format!("{} is not finite ({v}) at t = {t}", col.label));
                }
                row.push(if col.degrees { v.to_degrees() } else { v });
            }
            rows.push(row);
            Ok(())
        })
        .map_err(|e| match e {
            OdeError::NonFinite { time, index, value } => RunError::Ode(format!(
                "state {} is not finite ({value}) at t = {time}",
                M::STATE_NAMES[keep[index]]
            )),
            other => RunError::Ode(other.to_string()),
        })?;
        Ok(Integration { stats, rows, y_end })
    };
    let start = Instant::now();
    let degrees: Vec<bool> = picks.iter().map(|p| p.1.degrees).collect();
    let (Integration { stats, rows, y_end }, accuracy) = match (scene.integrator.accuracy, method) {
        (Some(goal), Method::Adaptive(tab, tol)) => refine(goal, tab, tol, &degrees, integrate_at)?,
        _ => (integrate_at(method)?, None),
    };
    let wall = start.elapsed();
    let ke_end = M::kinetic_energy(scene.t_final, &y_end, &params);
    let table = Table { title: scene.title.clone(), columns: picks.into_iter().map(|p| p.1).collect(), rows };
    let (csv, plot) = match out_dir {
        Some(dir) => {
            std::fs::create_dir_all(dir).map_err(|e| RunError::Output(format!("{}: {e}", dir.display())))?;
            let csv = dir.join("trajectory.csv");
            output::write_csv(&table, &csv).map_err(RunError::Output)?;
            let plot = dir.join("trajectory.png");
            output::write_plot(&table, &plot).map_err(RunError::Output)?;
            (Some(csv), Some(plot))
        }
        None => (None, None),
    };
    Ok(RunSummary {
        stats,
        wall,
        csv,
        plot,
        table,
        integrated: keep.iter().map(|k| M::STATE_NAMES[*k]).collect(),
        kinetic_energy: (ke_start, ke_end),
        accuracy,
    })
}

/// One integration's cost, rows written and full state at t_final.
struct Integration {
    stats: Stats,
    rows: Vec<Vec<f64>>,
    y_end: Vec<f64>,
}

/// Tolerances shrink by this factor from one run to the next when an accuracy is asked.
const REFINEMENT: f64 = 100.0;
/// The smallest relative tolerance the refinement tries (round-off dominates below).
const SMALLEST_RTOL: f64 = 1e-14;

/// Runs at `tol`, `tol / 100`, ... until two successive runs differ by at most `goal` (relative to
/// max(1, |value|), angles in radians); returns the finer run, whose error is well below that
/// difference (the coarser run's error, to a few percent, for pairs of order 5 and 8).
fn refine(
    goal: f64,
    tab: &'static tableau::Tableau,
    mut tol: Tolerances,
    degrees: &[bool],
    integrate_at: impl Fn(Method) -> Result<Integration, RunError>,
) -> Result<(Integration, Option<Accuracy>), RunError> {
    let mut total = Stats::default();
    let mut add = |s: Stats| {
        total.steps += s.steps;
        total.rejected += s.rejected;
        total.rhs_evals += s.rhs_evals;
    };
    let first = integrate_at(Method::Adaptive(tab, tol))?;
    add(first.stats);
    let mut coarse = first.rows;
    let mut runs = 1;
    loop {
        let finer = Tolerances { rtol: tol.rtol / REFINEMENT, atol: tol.atol / REFINEMENT };
        if finer.rtol < SMALLEST_RTOL {
            return Err(RunError::Ode(format!(
                "accuracy {goal:e} not reached: runs at rtol {:e} and below still differ by more; ask a looser accuracy",
                tol.rtol
            )));
        }
        let fine = integrate_at(Method::Adaptive(tab, finer))?;
        add(fine.stats);
        runs += 1;
        let estimate = largest_difference(&coarse, &fine.rows, degrees);
        if estimate <= goal {
            let accuracy = Accuracy { goal, estimate, rtol: finer.rtol, atol: finer.atol, runs };
            return Ok((Integration { stats: total, ..fine }, Some(accuracy)));
        }
        coarse = fine.rows;
        tol = finer;
    }
}

/// The largest difference of two runs' rows relative to max(1, |value|), angles in radians.
fn largest_difference(a: &[Vec<f64>], b: &[Vec<f64>], degrees: &[bool]) -> f64 {
    let mut worst: f64 = 0.0;
    for (ra, rb) in a.iter().zip(b) {
        for (k, (x, y)) in ra[1..].iter().zip(&rb[1..]).enumerate() {
            let (x, y) = if degrees[k] { (x.to_radians(), y.to_radians()) } else { (*x, *y) };
            worst = worst.max((x - y).abs() / y.abs().max(1.0));
        }
    }
    worst
}
