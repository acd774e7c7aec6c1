//! Resolving a scene: in come a [`Scene`] and a [`Registry`]; out goes a [`Problem`] in model
//! units (the scene's units converted: degrees to radians, deg/s to rad/s; a top's `[axle]`
//! motion converted to Euler parameters and body rates by [`initial`]; values checked for
//! plausibility by `plausible`), or an error at the scene's line and column.

mod event_binding;
mod initial;
mod plausible;
mod presets;

pub use initial::{sleeping_threshold, steady_precession};

use kane_model::lang::units::normalised;
use kane_model::lang::units::size::{shown_per_internal, unit_size};
use kane_model::runtime::{ModelInfo, OutputKind};

use crate::models::Registry;
use crate::ode::{Method, Tolerances};
use crate::problem::SimModel;
use crate::problem::{Pick, Problem};
use crate::scene::{
    keep, output_times, plot_times, too_many_rows, Axle, Scene, SceneError, Value, ViewError, ViewSpec,
};
use initial::{norm_error, TopStart, UNIT_NORM_TOLERANCE};

/// The problem a scene describes.
pub fn resolve(scene: &Scene, registry: &Registry) -> Result<Problem, SceneError> {
    let entry = registry.find(&scene.model).ok_or_else(|| {
        scene.error_at(
            scene.model_span.clone(),
            format!("unknown model `{}`", scene.model),
            &format!("the compiled models are: {}", registry.names().join(", ")),
        )
    })?;
    let info = entry.info();
    // A scene built in code, not parsed, has had no check of its grid.
    if let Some((what, help)) = too_many_rows(scene.t_final, scene.output_step) {
        return Err(scene.error_at(0..0, what, &help));
    }
    let times = output_times(scene.t_final, scene.output_step);
    let method = method(scene);
    let written = picks(scene, info)?;
    // Both tables' mistakes at once.
    let (params, initial) = match (parameters(scene, &**entry), initial_state(scene, &**entry)) {
        (Ok(params), Ok(initial)) => (params, initial),
        (params, initial) => {
            return Err(SceneError::all(params.err().into_iter().chain(initial.err()).collect()))
        }
    };
    let view = scene_view(scene, &**entry)?;
    let problem = Problem {
        title: scene.title.clone(),
        model: entry.clone(),
        view: view_with(scene, info, view.as_ref(), &params)?,
        params,
        initial,
        times: times.clone(),
        dense_figures: scene.plot_points.is_none() && has_dense_output(method),
        plot_times: if has_dense_output(method) {
            plot_times(&times, scene.plot_points.unwrap_or(1), MAX_PLOT_POINTS)
        } else {
            Vec::new()
        },
        method,
        max_steps: scene.integrator.max_steps,
        accuracy: scene.integrator.accuracy,
        written_picks: written.len(),
        picks: with_view_picks(scene, info, view.as_ref(), written)?,
        unit_norms: unit_norms(scene, info)?,
        events: event_binding::events(scene, info)?,
    };
    if scene.axle.is_none() {
        euler_parameters_named_e(scene, info, &problem.initial)?;
    }
    plausible::check(scene, &problem)?;
    Ok(problem)
}

/// The scene's `[view]`, with the model's frames and points when it draws the model; an error
/// at `[view]` when the model has no drawing.
fn scene_view(scene: &Scene, entry: &dyn SimModel) -> Result<Option<ViewSpec>, SceneError> {
    let Some(view) = &scene.view else { return Ok(None) };
    if !view.draw_model {
        return Ok(Some(view.clone()));
    }
    match entry.drawing() {
        Some(drawing) => Ok(Some(view.with_drawing(&drawing))),
        None => Err(scene.error_at(
            scene.view_span.clone(),
            format!("[view]: draw_model = true, but the model {} has no drawing (a model file's warning above says why)", entry.info().name),
            "draw_model draws a model file's frames and points; a built-in model's scene draws its bodies with [[view.bodies]]",
        )),
    }
}

/// `view` with its lengths given by `params` (`offset = [0, 0, "D"]`); an error at `[view]`
/// for a name that is not a parameter or a length that is not positive.
fn view_with(
    scene: &Scene,
    info: &ModelInfo,
    view: Option<&ViewSpec>,
    params: &[f64],
) -> Result<Option<ViewSpec>, SceneError> {
    let Some(view) = view else { return Ok(None) };
    let value_of = |name: &str| info.param(name).map(|i| params[i]);
    let view = view.with_parameters(&value_of).map_err(|e| {
        let message = match e {
            ViewError::Unresolved { user, name } => format!(
                "view: {user} reads parameter `{name}`, which the model does not have (it has: {})",
                info.param_names.join(", ")
            ),
            e => e.to_string(),
        };
        scene.error_at(scene.view_span.clone(), message, "fix the [view] tables of the scene")
    })?;
    Ok(Some(view))
}

/// Without `[axle]`, states named E1, E2, E3, E4 (the model language's `EULER` parameters as
/// the models name them) must start at unit norm: an error at the first of them `[initial]`
/// sets (zero or non-unit parameters would scale or remove gravity silently).
fn euler_parameters_named_e(scene: &Scene, info: &ModelInfo, y: &[f64]) -> Result<(), SceneError> {
    let Some(group) = ["E4", "E1", "E2", "E3"].iter().map(|n| info.state(n)).collect::<Option<Vec<usize>>>()
    else {
        return Ok(());
    };
    let q = [y[group[0]], y[group[1]], y[group[2]], y[group[3]]];
    if norm_error(&q) <= UNIT_NORM_TOLERANCE {
        return Ok(());
    }
    let span = scene
        .initial
        .iter()
        .filter(|(name, _, _)| info.state(name).is_some_and(|i| group.contains(&i)))
        .map(|(_, _, span)| span.clone())
        .min_by_key(|span| span.start)
        .unwrap_or(0..0);
    Err(scene.error_at(
        span,
        format!(
            "the Euler parameters E4, E1, E2, E3 = ({}) have norm {}, not 1",
            q.map(|x| format!("{x}")).join(", "),
            q.iter().map(|x| x * x).sum::<f64>().sqrt()
        ),
        &format!("Euler parameters must have unit norm (to {UNIT_NORM_TOLERANCE:e}): normalise them, or give the orientation under [axle]"),
    ))
}

/// Figures are drawn from at most this many points in all.
pub(crate) const MAX_PLOT_POINTS: usize = 20_000;

/// Whether `method` interpolates inside its steps (then plot points cost no extra steps).
fn has_dense_output(method: Method) -> bool {
    matches!(method, Method::Adaptive(tab, _) if tab.dense.is_some()) || matches!(method, Method::Taylor(_))
}

/// The method the scene carries (found when it was read) with its tolerances or step.
fn method(scene: &Scene) -> Method {
    let i = &scene.integrator;
    i.method.method(Tolerances { rtol: i.rtol, atol: i.atol }, i.step)
}

/// The model's defaults with the scene's values; an error for an unknown or missing one.
fn parameters(scene: &Scene, entry: &dyn SimModel) -> Result<Vec<f64>, SceneError> {
    let info = entry.info();
    let mut values = entry.default_params();
    put_table(scene, info, &scene.parameters, Quantity::Parameter, &mut values)?;
    if let Some(i) = values.iter().position(|v| !v.is_finite()) {
        return Err(without_value(scene, "parameter", info.param_names[i], values[i], "[parameters]"));
    }
    Ok(values)
}

/// An error when two entries of a table (`[parameters]` or `[initial]`) set the same model
/// quantity (`index` finds it), as `M` and `m` do: it names both.
fn given_once<T>(
    scene: &Scene,
    table: &[(String, T, std::ops::Range<usize>)],
    index: impl Fn(&str) -> Option<usize>,
) -> Result<(), SceneError> {
    // In the order the file gives them (a table's keys may come sorted).
    let mut in_file: Vec<_> = table.iter().collect();
    in_file.sort_by_key(|(_, _, span)| span.start);
    for (k, (name, _, span)) in in_file.iter().enumerate() {
        let Some(i) = index(name) else { continue };
        if let Some((first, _, _)) = in_file[..k].iter().find(|(n, _, _)| index(n) == Some(i)) {
            return Err(scene.error_at(
                span.clone(),
                format!(
                    "`{name}` is given twice: `{first}` sets the same quantity (names are case-insensitive)"
                ),
                &format!("keep one of `{first}` and `{name}`"),
            ));
        }
    }
    Ok(())
}

/// Which of the model's quantities a scene table sets.
#[derive(Clone, Copy)]
enum Quantity {
    /// `[parameters]`.
    Parameter,
    /// `[initial]`.
    State,
}

impl Quantity {
    fn index(self, info: &ModelInfo, name: &str) -> Option<usize> {
        match self {
            Quantity::Parameter => info.param(name),
            Quantity::State => info.state(name),
        }
    }

    /// The model's names and units of this kind.
    fn names_and_units(self, info: &ModelInfo) -> (&'static [&'static str], &'static [&'static str]) {
        match self {
            Quantity::Parameter => (info.param_names, info.param_units),
            Quantity::State => (info.state_names, info.state_units),
        }
    }
}

/// `values` with the entries of a scene `table` of `quantity` put in, in the model's units;
/// every unknown name (with the nearest known one) and every wrong unit in one error.
fn put_table(
    scene: &Scene,
    info: &ModelInfo,
    table: &[(String, Value, std::ops::Range<usize>)],
    quantity: Quantity,
    values: &mut [f64],
) -> Result<(), SceneError> {
    given_once(scene, table, |n| quantity.index(info, n))?;
    let (names, units) = quantity.names_and_units(info);
    let mut found = Vec::new();
    for (name, v, span) in table {
        let Some(i) = quantity.index(info, name) else {
            let (what, plural) = match quantity {
                Quantity::Parameter => ("a parameter", "parameters"),
                Quantity::State => ("a state", "states"),
            };
            let hint = kane_model::lang::nearest_word(name, names.iter().copied())
                .map_or(String::new(), |k| format!("did you mean `{k}`? "));
            found.push(scene.error_at(
                span.clone(),
                format!("`{name}` is not {what} of {}", info.name),
                &format!("{hint}{plural}: {}", names.join(", ")),
            ));
            continue;
        };
        if let Some(x) = keep(&mut found, in_model_units(scene, name, v, units[i], span)) {
            values[i] = x;
        }
    }
    if found.is_empty() {
        Ok(())
    } else {
        Err(SceneError::all(found))
    }
}

/// The model's initial state with the scene's values.
fn initial_state(scene: &Scene, entry: &dyn SimModel) -> Result<Vec<f64>, SceneError> {
    let info = entry.info();
    let mut y = entry.initial_state();
    put_table(scene, info, &scene.initial, Quantity::State, &mut y)?;
    if let Some(axle) = &scene.axle {
        apply_axle(scene, axle, info, &mut y)?;
    }
    if let Some(i) = y.iter().position(|v| !v.is_finite()) {
        return Err(without_value(scene, "state", info.state_names[i], y[i], "[initial]"));
    }
    Ok(y)
}

/// The error for a parameter or state (`what`) whose value from the model is not finite (the
/// scene's own values were checked when it was parsed): it names the model the value came
/// from, at the scene's `model` key, and says where to set one (`table`).
fn without_value(scene: &Scene, what: &str, name: &str, value: f64, table: &str) -> SceneError {
    let origin = if scene.model.to_ascii_lowercase().ends_with(".al") {
        format!("the model file {} gives it no INPUT value", scene.model)
    } else {
        format!("the model {} has no default for it", scene.model)
    };
    let problem = if value.is_nan() { "has no value".to_string() } else { format!("is {value}") };
    scene.error_at(
        scene.model_span.clone(),
        format!("{what} `{name}` {problem}: {origin}, and the scene sets none"),
        &format!(
            "set it under {table} ({name} = ...) or with `--set {name}=VALUE`, or give it on the model file's INPUT line"
        ),
    )
}

/// The state groups held at unit norm: `[axle]`'s Euler parameters.
fn unit_norms(scene: &Scene, info: &ModelInfo) -> Result<Vec<Vec<usize>>, SceneError> {
    match &scene.axle {
        Some(axle) => Ok(vec![axle_states(scene, info, &axle.quaternion, &[])?]),
        None => Ok(Vec::new()),
    }
}

/// The `[axle]` table applied to `y` (which holds the model's defaults and the `[initial]`
/// values): with `tilt`, its Euler parameters and rates are derived (a state set both here and
/// in `[initial]` is an error); without, the Euler parameters `y` holds must have unit norm.
fn apply_axle(scene: &Scene, axle: &Axle, info: &ModelInfo, y: &mut [f64]) -> Result<(), SceneError> {
    let quaternion = axle_states(scene, info, &axle.quaternion, &[])?;
    let rates = axle_states(scene, info, &axle.rates, &axle.quaternion)?;
    if !axle.derives() {
        let q = [y[quaternion[0]], y[quaternion[1]], y[quaternion[2]], y[quaternion[3]]];
        return unit_euler_parameters(scene, axle, info, &quaternion, q);
    }
    let derived: Vec<usize> = quaternion.iter().chain(&rates).copied().collect();
    for (name, _, span) in &scene.initial {
        if info.state(name).is_some_and(|i| derived.contains(&i)) {
            return Err(scene.error_at(
                span.clone(),
                format!("`{name}` is set twice: [axle] derives it from the axle's motion"),
                &format!("remove {name} from [initial], or remove tilt from [axle] to give the Euler parameters yourself"),
            ));
        }
    }
    let start = TopStart::from_scene(scene, axle)?;
    for (i, v) in quaternion.iter().zip(start.euler_parameters()) {
        y[*i] = v;
    }
    for (i, v) in rates.iter().zip(start.body_rates()) {
        y[*i] = v;
    }
    Ok(())
}

/// The state indices `names` of `[axle]` name; an error at a name that is not a state, or one
/// named twice (`earlier` are names the table gave before these).
fn axle_states(
    scene: &Scene,
    info: &ModelInfo,
    names: &[(String, std::ops::Range<usize>)],
    earlier: &[(String, std::ops::Range<usize>)],
) -> Result<Vec<usize>, SceneError> {
    let mut out = Vec::with_capacity(names.len());
    for (k, (name, span)) in names.iter().enumerate() {
        let Some(i) = info.state(name) else {
            return Err(scene.error_at(
                span.clone(),
                format!("`{name}` in [axle] is not a state of {}", info.name),
                &format!("states: {}", info.state_names.join(", ")),
            ));
        };
        if earlier.iter().chain(&names[..k]).any(|(n, _)| n.eq_ignore_ascii_case(name)) {
            return Err(scene.error_at(
                span.clone(),
                format!("`{name}` is named twice in [axle]"),
                "quaternion names the four Euler-parameter states, rates the three body rates, each once",
            ));
        }
        out.push(i);
    }
    Ok(out)
}

/// An error unless the Euler parameters `q` (scalar first) have unit norm; it points at the
/// first of them `[initial]` sets, or at `[axle]`'s quaternion when the model's defaults gave
/// them all.
fn unit_euler_parameters(
    scene: &Scene,
    axle: &Axle,
    info: &ModelInfo,
    quaternion: &[usize],
    q: [f64; 4],
) -> Result<(), SceneError> {
    if norm_error(&q) <= UNIT_NORM_TOLERANCE {
        return Ok(());
    }
    let names: Vec<&str> = quaternion.iter().map(|i| info.state_names[*i]).collect();
    let span = scene
        .initial
        .iter()
        .filter(|(name, _, _)| info.state(name).is_some_and(|i| quaternion.contains(&i)))
        .map(|(_, _, span)| span.clone())
        .min_by_key(|span| span.start)
        .unwrap_or_else(|| axle.quaternion_span.clone());
    Err(scene.error_at(
        span,
        format!(
            "the Euler parameters {} = ({}) have norm {}, not 1",
            names.join(", "),
            q.map(|x| format!("{x}")).join(", "),
            q.iter().map(|x| x * x).sum::<f64>().sqrt(),
        ),
        &format!(
            "Euler parameters must have unit norm (to {UNIT_NORM_TOLERANCE:e}): give the orientation as tilt = \"60 deg\" under [axle] and remove {} from [initial], or normalise them",
            names.join(", ")
        ),
    ))
}

/// The states and outputs asked for (every state and output but the default drawing's when
/// none are named).
fn picks(scene: &Scene, info: &ModelInfo) -> Result<Vec<Pick>, SceneError> {
    if scene.outputs.is_empty() {
        let states = (0..info.state_names.len()).map(Pick::State);
        let outputs = (0..info.outputs.len()).filter(|k| info.outputs[*k].kind != OutputKind::Drawing);
        return Ok(states.chain(outputs.map(Pick::Output)).collect());
    }
    scene
        .outputs
        .iter()
        .map(|(name, span)| {
            if let Some(i) = info.state(name) {
                Ok(Pick::State(i))
            } else if let Some(k) = info.output(name) {
                Ok(Pick::Output(k))
            } else {
                let mut known: Vec<&str> = info.state_names.to_vec();
                known.extend(info.outputs.iter().map(|o| o.name));
                Err(scene.error_at(
                    span.clone(),
                    format!("`{name}` is neither a state nor an output of {}", info.name),
                    &format!("known: {}", known.join(", ")),
                ))
            }
        })
        .collect()
}

/// `written` and after them the outputs `view` (the scene's) reads that `written` lacks; an
/// error at `[view]` for a column the model does not have.
fn with_view_picks(
    scene: &Scene,
    info: &ModelInfo,
    view: Option<&ViewSpec>,
    mut picks: Vec<Pick>,
) -> Result<Vec<Pick>, SceneError> {
    let Some(view) = view else { return Ok(picks) };
    for (user, column) in view.columns() {
        let pick = if let Some(i) = info.state(column) {
            Pick::State(i)
        } else if let Some(k) =
            info.outputs.iter().position(|o| o.columns.iter().any(|c| c.eq_ignore_ascii_case(column)))
        {
            Pick::Output(k)
        } else {
            let known: Vec<&str> = info.outputs.iter().flat_map(|o| o.columns.iter().copied()).collect();
            return Err(scene.error_at(
                scene.view_span.clone(),
                format!(
                    "[view]: {user} reads `{column}`, which {} neither has as a state nor computes",
                    info.name
                ),
                &format!("states: {}; output columns: {}", info.state_names.join(", "), known.join(", ")),
            ));
        };
        if !picks.contains(&pick) {
            picks.push(pick);
        }
    }
    Ok(picks)
}

/// A model's internal value (radians for angles) as a scene writes it for its `model_unit`, the
/// plain number [`in_model_units`] reads back as the same value.
pub fn in_scene_units(internal: f64, model_unit: &str) -> f64 {
    internal * shown_per_internal(model_unit)
}

/// A scene value in the model's internal units (radians for angles and their rates).
fn in_model_units(
    scene: &Scene,
    name: &str,
    v: &Value,
    model_unit: &str,
    span: &std::ops::Range<usize>,
) -> Result<f64, SceneError> {
    // Compared regardless of case and spacing, SEC as S (`10 n * m` is in N*M).
    let mu = normalised(model_unit);
    let given = v.unit.as_deref().map(normalised);
    Ok(match given.as_deref() {
        None => v.number / shown_per_internal(&mu),
        Some(u) if u == mu => v.number / shown_per_internal(&mu),
        Some(u) => match convertible(&mu, u) {
            Some(factor) => v.number * factor,
            None => {
                let shown = if mu.is_empty() { "no unit" } else { model_unit };
                return Err(scene.error_at(
                    span.clone(),
                    format!("`{name}` is in {shown}, not {u}"),
                    &format!(
                        "write a plain number (in {}) or give a compatible unit",
                        if mu.is_empty() { "the model's units" } else { model_unit }
                    ),
                ));
            }
        },
    })
}

/// The factor a value in `given` is multiplied by to be in the model's unit `declared` (both
/// normalised), read as INPUT lines read units: into SI where nothing is declared, radians for
/// angles, else into the declared unit; None when the two do not measure the same thing.
fn convertible(declared: &str, given: &str) -> Option<f64> {
    let given = unit_size(given).ok()?;
    if declared.is_empty() {
        return Some(given.si);
    }
    let declared = unit_size(declared).ok()?;
    if declared.dim != given.dim {
        return None;
    }
    // Angles are radians inside the model, whatever unit the CSV shows.
    let angle = declared.dim[3] != 0;
    Some(if angle { given.si } else { given.si / declared.si })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scene_and_set_values_read_units_as_input_lines_do() {
        let close = |a: Option<f64>, b: f64| a.is_some_and(|a| (a - b).abs() <= 1e-12 * b.abs());
        let rev = 2.0 * std::f64::consts::PI;
        assert!(close(convertible("RAD/S", "RPM"), rev / 60.0), "600 rpm on a speed in rad/s");
        assert!(close(convertible("M", "CM"), 0.01));
        assert!(close(convertible("M", "MM"), 0.001));
        assert!(close(convertible("", "DEG"), std::f64::consts::PI / 180.0), "an angle with no UNITS");
        assert!(close(convertible("", "CM"), 0.01));
        assert!(close(convertible("DEG/S", "RPM"), rev / 60.0), "angles are radians inside");
        assert_eq!(convertible("M", "KG"), None);
        assert_eq!(convertible("M", "FURLONG"), None);
    }

    const HEAD: &str = "model = \"heavy_top\"\nt_final = 1.0\noutput_step = 0.1\n";
    const NAMES: &str = "quaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\n";

    fn initial(text: &str) -> Result<(Vec<f64>, &'static ModelInfo), SceneError> {
        let scene = Scene::parse("top.toml", &format!("{HEAD}{text}"))?;
        resolve(&scene, &Registry::builtin()).map(|p| (p.initial, p.model.info()))
    }

    fn state(y: &[f64], info: &ModelInfo, name: &str) -> f64 {
        y[info.state(name).unwrap()]
    }

    #[test]
    fn the_axle_gives_euler_parameters_and_rates() {
        let text = format!(
            "[axle]\ntilt = \"60 deg\"\nspin = \"10 rad/s\"\nprecession = \"-1 rad/s\"\nnutation = \"0.5 rad/s\"\n{NAMES}rates = [\"W1\", \"W2\", \"W3\"]\n"
        );
        let (y, info) = initial(&text).unwrap();
        let want = TopStart { tilt: 60f64.to_radians(), spin: 10.0, precession: -1.0, nutation: 0.5 };
        let [e4, e1, e2, e3] = want.euler_parameters();
        let [w1, w2, w3] = want.body_rates();
        for (name, v) in [("E4", e4), ("E1", e1), ("E2", e2), ("E3", e3), ("W1", w1), ("W2", w2), ("W3", w3)]
        {
            assert_eq!(state(&y, info, name), v, "{name}");
        }
        assert!((w2 + 60f64.to_radians().sin()).abs() < 1e-15 && w1 == 0.5 && w3 == 10.0);
    }

    #[test]
    fn without_rates_the_initial_table_gives_them() {
        let text = format!("[initial]\nW3 = 5.0\n[axle]\ntilt = \"30 deg\"\n{NAMES}");
        let (y, info) = initial(&text).unwrap();
        assert_eq!(state(&y, info, "W3"), 5.0);
        assert_eq!(state(&y, info, "E1"), 15f64.to_radians().sin());
    }

    #[test]
    fn a_state_set_in_both_tables_is_an_error_at_its_initial_line() {
        let text = format!("[initial]\nW2 = 1.0\nE1 = 0.5\n[axle]\ntilt = \"30 deg\"\n{NAMES}");
        let e = initial(&text).unwrap_err().to_string();
        assert!(e.starts_with("top.toml:6:6: error: `E1` is set twice: [axle] derives it"), "{e}");
        assert!(e.contains("help: remove E1 from [initial]"), "{e}");
        // Rates too, when [axle] names them.
        let text = format!(
            "[initial]\nw2 = 1.0\n[axle]\ntilt = \"30 deg\"\n{NAMES}rates = [\"W1\", \"W2\", \"W3\"]\n"
        );
        let e = initial(&text).unwrap_err().to_string();
        assert!(e.starts_with("top.toml:5:6: error: `w2` is set twice"), "{e}");
    }

    #[test]
    fn euler_parameters_given_directly_must_have_unit_norm() {
        let text = format!("[initial]\nE4 = 1.0\nE1 = 0.5\nE2 = 0.0\nE3 = 0.0\n[axle]\n{NAMES}");
        let e = initial(&text).unwrap_err().to_string();
        assert!(
            e.starts_with(
                "top.toml:5:6: error: the Euler parameters E4, E1, E2, E3 = (1, 0.5, 0, 0) have norm 1.118"
            ),
            "{e}"
        );
        assert!(e.contains("tilt = \"60 deg\" under [axle]"), "{e}");
        // Within 1e-9 of unit norm is accepted; without [axle], states named E1..E4 are checked.
        let c = 30f64.to_radians().cos();
        let s = 30f64.to_radians().sin();
        let ok = format!("[initial]\nE4 = {c}\nE1 = {}\nE2 = 0.0\nE3 = 0.0\n[axle]\n{NAMES}", s + 5e-10);
        assert!(initial(&ok).is_ok());
        let e = initial("[initial]\nE4 = 1.0\nE1 = 0.5\nE2 = 0.0\nE3 = 0.0\n").unwrap_err().to_string();
        assert!(
            e.starts_with(
                "top.toml:5:6: error: the Euler parameters E4, E1, E2, E3 = (1, 0.5, 0, 0) have norm 1.118"
            ),
            "{e}"
        );
    }

    #[test]
    fn axle_names_must_be_states_named_once_and_values_in_fitting_units() {
        let bad = "[axle]\ntilt = \"30 deg\"\nquaternion = [\"E4\", \"E1\", \"E2\", \"Q3\"]\n";
        let e = initial(bad).unwrap_err().to_string();
        assert!(e.starts_with("top.toml:6:33: error: `Q3` in [axle] is not a state of heavy_top"), "{e}");
        assert!(e.contains("states: E1, E2, E3, E4, W1, W2, W3"), "{e}");
        let twice = "[axle]\ntilt = \"30 deg\"\nquaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\nrates = [\"W1\", \"E1\", \"W3\"]\n";
        let e = initial(twice).unwrap_err().to_string();
        assert!(e.starts_with("top.toml:7:16: error: `E1` is named twice in [axle]"), "{e}");
        let unit = format!("[axle]\ntilt = \"10 rad/s\"\n{NAMES}");
        let e = initial(&unit).unwrap_err().to_string();
        assert!(e.starts_with("top.toml:5:8: error: `tilt` in [axle] is an angle, not in RAD/S"), "{e}");
        assert!(e.contains("help: write a number with deg or rad"), "{e}");
    }
}
