//! Resolving a scene: in come a [`Scene`] and a [`Registry`]; out goes a [`Problem`] in model
//! units (the scene's units converted: degrees to radians, deg/s to rad/s), or an error at the
//! scene's line and column.

use kane_model::runtime::ModelInfo;

use crate::ode::{Method, Tolerances};
use crate::problem::{output_times, plot_times, Pick, Problem};
use crate::registry::{ModelEntry, Registry};
use crate::scene::{Scene, SceneError, Value};

/// The problem a scene describes.
pub fn resolve(scene: &Scene, registry: &Registry) -> Result<Problem, SceneError> {
    let entry = registry.find(&scene.model).ok_or_else(|| {
        scene.error_at(
            scene.model_span.clone(),
            format!("unknown model `{}`", scene.model),
            &format!("the compiled models are: {}", registry.names().join(", ")),
        )
    })?;
    let info = entry.info;
    let times = output_times(scene.t_final, scene.output_step);
    let method = method(scene);
    Ok(Problem {
        title: scene.title.clone(),
        model: info,
        params: parameters(scene, entry)?,
        initial: initial_state(scene, entry)?,
        times: times.clone(),
        plot_times: if has_dense_output(method) {
            plot_times(&times, PLOT_POINTS_PER_STEP, MAX_PLOT_POINTS)
        } else {
            Vec::new()
        },
        method,
        accuracy: scene.integrator.accuracy,
        picks: picks(scene, info)?,
    })
}

/// Figures are drawn from this many points per output interval when the method has dense
/// output (1: the output rows alone)...
const PLOT_POINTS_PER_STEP: usize = 1;
/// ... and at most this many in all.
const MAX_PLOT_POINTS: usize = 20_000;

/// Whether `method` interpolates inside its steps (then plot points cost no extra steps).
fn has_dense_output(method: Method) -> bool {
    matches!(method, Method::Adaptive(tab, _) if tab.dense.is_some())
}

/// The method a scene names (checked when the scene was parsed).
fn method(scene: &Scene) -> Method {
    let i = &scene.integrator;
    let info = crate::ode::by_name(&i.method).unwrap_or(crate::ode::default_method());
    info.method(Tolerances { rtol: i.rtol, atol: i.atol }, i.step)
}

/// The model's defaults with the scene's values; an error for an unknown or missing one.
fn parameters(scene: &Scene, entry: &ModelEntry) -> Result<Vec<f64>, SceneError> {
    let info = entry.info;
    let mut values = (entry.default_params)();
    for (name, v, span) in &scene.parameters {
        let Some(i) = info.param_names.iter().position(|p| p.eq_ignore_ascii_case(name)) else {
            return Err(scene.error_at(
                span.clone(),
                format!("`{name}` is not a parameter of {}", info.name),
                &format!("parameters: {}", info.param_names.join(", ")),
            ));
        };
        values[i] = in_model_units(scene, name, v, info.param_units[i], span)?;
    }
    if let Some(i) = values.iter().position(|v| !v.is_finite()) {
        return Err(scene.error_at(
            0..0,
            format!("parameter `{}` has no value", info.param_names[i]),
            "set it under [parameters] (the model file's INPUT gives none)",
        ));
    }
    Ok(values)
}

/// The model's initial state with the scene's values.
fn initial_state(scene: &Scene, entry: &ModelEntry) -> Result<Vec<f64>, SceneError> {
    let info = entry.info;
    let mut y = (entry.initial_state)();
    for (name, v, span) in &scene.initial {
        let Some(i) = info.state(name) else {
            return Err(scene.error_at(
                span.clone(),
                format!("`{name}` is not a state of {}", info.name),
                &format!("states: {}", info.state_names.join(", ")),
            ));
        };
        y[i] = in_model_units(scene, name, v, info.state_units[i], span)?;
    }
    if let Some(i) = y.iter().position(|v| !v.is_finite()) {
        return Err(scene.error_at(
            0..0,
            format!("state `{}` has no initial value", info.state_names[i]),
            "set it under [initial]",
        ));
    }
    Ok(y)
}

/// The states and outputs asked for (every state and output when none are named).
fn picks(scene: &Scene, info: &ModelInfo) -> Result<Vec<Pick>, SceneError> {
    if scene.outputs.is_empty() {
        let states = (0..info.state_names.len()).map(Pick::State);
        return Ok(states.chain((0..info.outputs.len()).map(Pick::Output)).collect());
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

/// A scene value in the model's internal units (radians for angles).
fn in_model_units(
    scene: &Scene,
    name: &str,
    v: &Value,
    model_unit: &str,
    span: &std::ops::Range<usize>,
) -> Result<f64, SceneError> {
    let mu = model_unit.to_ascii_uppercase();
    let given = v.unit.as_deref().map(|u| u.to_ascii_uppercase().replace(' ', ""));
    let deg = std::f64::consts::PI / 180.0;
    let same = |m: &str, u: &str| m.replace("SEC", "S") == u.replace("SEC", "S");
    Ok(match (mu.as_str(), given.as_deref()) {
        ("DEG", None | Some("DEG")) => v.number * deg,
        ("DEG" | "RAD", Some("RAD")) | ("RAD", None) => v.number,
        ("RAD", Some("DEG")) => v.number * deg,
        ("RAD/SEC", None | Some("RAD/S" | "RAD/SEC")) => v.number,
        ("RAD/SEC", Some("DEG/S" | "DEG/SEC")) => v.number * deg,
        (_, None) => v.number,
        (m, Some(u)) if same(m, u) => v.number,
        (_, Some(u)) => {
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
    })
}
