//! The scene of a model file run without one (`gyro-sim run --model FILE`): in come the file's
//! run settings, the model's metadata and what the command line gives (`--set`, `--t-final`,
//! the integrator); out goes the scene's TOML text (printable, so a user can save it and edit
//! it further), each line with where it came from.

use kane_model::lang::run_settings::{DEFAULT_ROWS, DEFAULT_TOLERANCE, DEFAULT_T_FINAL};
use kane_model::runtime::ModelInfo;

use super::origins::{GeneratedScene, Origin};
use super::ModelRunError;
use crate::models::FileRun;
use crate::scene::{IntegratorOverrides, SceneDefaults};

/// Method when the command line gives none (Autolev's generated programs use an adaptive
/// Runge-Kutta method of this family).
const DEFAULT_METHOD: &str = "dop853";

/// What the command line asks of a model-file run.
#[derive(Clone, Debug, Default)]
pub struct ModelRunArgs {
    /// `NAME=VALUE` pairs (a value may carry a unit: `Q2=30 deg`).
    pub sets: Vec<(String, String)>,
    /// The end time given with `--t-final`.
    pub t_final: Option<f64>,
    /// The integrator settings given (`--method`, `--rtol`, `--atol`).
    pub integrator: IntegratorOverrides,
    /// A view drawing the model's frames and points (`[view] draw_model = true`).
    pub view: bool,
    /// Points per output interval the figures are drawn from (`--plot-points`).
    pub plot_points: Option<u32>,
}

/// The values a model gives its parameters and states when a run sets none (its INPUT lines;
/// NaN where it has none).
#[derive(Clone, Copy, Debug)]
pub struct ModelValues<'a> {
    /// One per parameter, in the model's order.
    pub params: &'a [f64],
    /// One per state, in the model's order.
    pub initial: &'a [f64],
}

/// The scene for `model_path`: times, method, tolerances and outputs from the file (command
/// line first), every parameter and state under `[parameters]` and `[initial]` (a `--set` in
/// place of the model's value), a view drawing the model when asked; an error naming a `--set`
/// that is neither a parameter nor a state.
pub fn scene_text(
    model_path: &str,
    run: &FileRun,
    info: &ModelInfo,
    model_values: ModelValues<'_>,
    args: &ModelRunArgs,
) -> Result<GeneratedScene, ModelRunError> {
    let mut scene = GeneratedScene::default();
    scene.push(format!("title = {:?}", format!("{} (model file)", info.name)), Origin::File);
    scene.push(format!("model = {model_path:?}"), Origin::File);
    let (t_final, from) = match (args.t_final, run.t_final) {
        (Some(t), _) => (t, Origin::Option("--t-final")),
        (None, Some(t)) => (t, Origin::Input("TFINAL")),
        (None, None) => (DEFAULT_T_FINAL, Origin::File),
    };
    scene.push(format!("t_final = {}", toml_number(t_final)), from);
    let step = run.step_within(t_final);
    let from = if step.is_some() { Origin::Input("INTEGSTP") } else { Origin::File };
    scene.push(format!("output_step = {}", toml_number(step.unwrap_or(t_final / DEFAULT_ROWS))), from);
    scene.push(format!("outputs = [{}]", outputs(run, info).join(", ")), Origin::Output);
    if let Some(n) = args.plot_points {
        scene.push(format!("plot_points = {n}"), Origin::Option("--plot-points"));
    }
    scene.push("", Origin::File);
    integrator(&mut scene, run, &args.integrator);
    values(&mut scene, info, model_values, &args.sets)?;
    if args.view {
        scene.push("", Origin::File);
        scene.push("[view]", Origin::File);
        scene.push("draw_model = true", Origin::File);
    }
    Ok(scene)
}

/// The OUTPUT names the model knows, quoted (every state when none).
fn outputs(run: &FileRun, info: &ModelInfo) -> Vec<String> {
    run.written(info).iter().map(|n| format!("{n:?}")).collect()
}

/// What a scene naming the model file takes where it gives no times or tolerances: the file's
/// TFINAL, INTEGSTP, RELERR and ABSERR, else the defaults of a run without a scene.
pub(crate) fn scene_defaults(run: &FileRun) -> SceneDefaults {
    let settings = run.settings();
    SceneDefaults {
        t_final: Some(settings.t_final),
        output_step: Some(settings.output_step),
        rtol: Some(settings.rtol),
        atol: Some(settings.atol),
    }
}

/// The `[integrator]` table: the command line's settings, else the file's, else the defaults.
fn integrator(scene: &mut GeneratedScene, run: &FileRun, given: &IntegratorOverrides) {
    scene.push("[integrator]", Origin::File);
    let method = given.method.as_deref().unwrap_or(DEFAULT_METHOD);
    let from = if given.method.is_some() { Origin::Option("--method") } else { Origin::File };
    scene.push(format!("method = {method:?}"), from);
    let tolerance = |option: &'static str, given: Option<f64>, input: &'static str, file: Option<f64>| match (
        given, file,
    ) {
        (Some(x), _) => (x, Origin::Option(option)),
        (None, Some(x)) => (x, Origin::Input(input)),
        (None, None) => (DEFAULT_TOLERANCE, Origin::File),
    };
    let (rtol, from) = tolerance("--rtol", given.rtol, "RELERR", run.relerr);
    scene.push(format!("rtol = {rtol:e}"), from);
    let (atol, from) = tolerance("--atol", given.atol, "ABSERR", run.abserr);
    scene.push(format!("atol = {atol:e}"), from);
}

/// `[parameters]` and `[initial]`: each `--set` value, and the model's value of every other
/// parameter and state with its unit in a comment. An input the model leaves open and a value
/// the file does not give stay out (a comment says so), so the run warns or stops as without.
fn values(
    scene: &mut GeneratedScene,
    info: &ModelInfo,
    model_values: ModelValues<'_>,
    sets: &[(String, String)],
) -> Result<(), ModelRunError> {
    let (mut params_set, mut initial_set) = (Vec::new(), Vec::new());
    for (name, value) in sets {
        let line = (
            format!("{} = {}", toml_key(name), toml_value(value)),
            Origin::Set { name: name.clone(), value: value.clone() },
        );
        if let Some(i) = info.param(name) {
            params_set.push((i, line));
        } else if let Some(i) = info.state(name) {
            initial_set.push((i, line));
        } else {
            return Err(ModelRunError::UnknownSet {
                name: name.clone(),
                model: info.name.to_string(),
                params: info.param_names.iter().map(|p| p.to_string()).collect(),
                states: info.state_names.iter().map(|s| s.to_string()).collect(),
            });
        }
    }
    let params =
        ModelColumn { names: info.param_names, units: info.param_units, values: model_values.params };
    let states =
        ModelColumn { names: info.state_names, units: info.state_units, values: model_values.initial };
    for (table, mut lines, column, open) in
        [("[parameters]", params_set, params, info.open_inputs), ("[initial]", initial_set, states, &[][..])]
    {
        lines.extend(column.unset_lines(&lines, open));
        lines.sort_by_key(|(i, _)| *i);
        if !lines.is_empty() {
            scene.push("", Origin::File);
            scene.push(table, Origin::File);
            lines.into_iter().for_each(|(_, (line, origin))| scene.push(line, origin));
        }
    }
    Ok(())
}

/// A table's line: the index of its quantity, its text and where it came from.
type TableLine = (usize, (String, Origin));

/// The parameters or the states of a model: names, units and the model's values.
struct ModelColumn<'a> {
    names: &'a [&'a str],
    units: &'a [&'a str],
    values: &'a [f64],
}

impl ModelColumn<'_> {
    /// The lines of the quantities `set` does not give: the model's value, or a comment where
    /// the quantity is an `open` input or has no value.
    fn unset_lines(&self, set: &[TableLine], open: &[usize]) -> Vec<TableLine> {
        let unset = (0..self.names.len()).filter(|i| !set.iter().any(|(k, _)| k == i));
        unset
            .map(|i| {
                let name = self.names[i];
                let line = match self.values.get(i) {
                    _ if open.contains(&i) => {
                        format!("# {name}: an input the model leaves open (0 unless given)")
                    }
                    Some(v) if v.is_finite() => {
                        let shown = crate::resolve::in_scene_units(*v, self.units[i]);
                        format!("{} = {}{}", toml_key(name), toml_number(shown), unit_comment(self.units[i]))
                    }
                    _ => format!("# {name}: the model file gives no value (give one here)"),
                };
                (i, (line, Origin::Value(name.to_string())))
            })
            .collect()
    }
}

/// `  # UNIT` after a value in the model's units (nothing for a number without one).
fn unit_comment(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!("  # {unit}")
    }
}

/// A name as a TOML key: bare when it can be, else quoted.
fn toml_key(name: &str) -> String {
    let bare = !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
    if bare {
        name.to_string()
    } else {
        format!("{name:?}")
    }
}

/// A number as TOML (always with a decimal point or exponent).
fn toml_number(x: f64) -> String {
    let s = format!("{x:?}");
    if s.contains(['.', 'e', 'E']) || !x.is_finite() {
        s
    } else {
        format!("{s}.0")
    }
}

/// A `--set` value as TOML: a number as it is, a number with a unit as a string.
fn toml_value(v: &str) -> String {
    match v.parse::<f64>() {
        Ok(x) if x.is_finite() => toml_number(x),
        _ => format!("{v:?}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::gimbal_gyroscope::INFO;
    use crate::scene::Scene;

    fn args(sets: &[(&str, &str)]) -> ModelRunArgs {
        ModelRunArgs {
            sets: sets.iter().map(|(n, v)| (n.to_string(), v.to_string())).collect(),
            t_final: None,
            integrator: IntegratorOverrides::default(),
            view: true,
            plot_points: None,
        }
    }

    /// The gimbal's own values.
    fn values() -> ModelValues<'static> {
        use std::sync::OnceLock;
        static VALUES: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
        let (params, initial) = VALUES.get_or_init(|| {
            use crate::models::gimbal_gyroscope::Model as G;
            use kane_model::runtime::GeneratedModel;
            let p = <G as GeneratedModel>::Params::default();
            (INFO.param_names.iter().map(|n| G::param(&p, n).unwrap()).collect(), G::initial_state())
        });
        ModelValues { params, initial }
    }

    fn parsed(run: &FileRun, args: &ModelRunArgs) -> Scene {
        let text = scene_text("g.al", run, &INFO, values(), args).unwrap().text();
        Scene::parse("<command line>", &text).unwrap()
    }

    #[test]
    fn the_command_lines_method_and_tolerances_come_before_the_files() {
        let run = FileRun { abserr: Some(1e-7), relerr: Some(1e-6), ..FileRun::default() };
        let scene = |integrator: IntegratorOverrides| {
            parsed(&run, &ModelRunArgs { integrator, ..args(&[]) }).integrator
        };
        let file = scene(IntegratorOverrides::default());
        assert_eq!((file.method.name(), file.rtol, file.atol), ("dop853", 1e-6, 1e-7));
        let given = IntegratorOverrides { method: Some("vern9".into()), rtol: Some(1e-11), atol: None };
        let given = scene(given);
        assert_eq!((given.method.name(), given.rtol, given.atol), ("vern9", 1e-11, 1e-7));
        let auto = IntegratorOverrides { method: Some("auto".into()), rtol: Some(1e-10), atol: Some(1e-10) };
        assert_eq!(scene(auto).method.name(), "vern9", "auto picks by the tolerances given");
    }

    #[test]
    fn the_file_settings_and_sets_make_a_scene_whose_lines_know_their_origin() {
        let run = FileRun {
            t_final: Some(5.0),
            step: Some(0.05),
            abserr: Some(1e-7),
            relerr: Some(1e-7),
            outputs: vec!["Q1".into(), "AP".into(), "NOT_THERE".into()],
        };
        let sets = args(&[("y", "10"), ("Q2", "30 deg")]);
        let scene = parsed(&run, &sets);
        assert_eq!((scene.t_final, scene.output_step), (5.0, 0.05));
        assert_eq!((scene.integrator.rtol, scene.integrator.atol), (1e-7, 1e-7));
        let outputs: Vec<&str> = scene.outputs.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(outputs, ["Q1", "AP"]);
        let value = |table: &[(String, crate::scene::Value, _)], name: &str| {
            table.iter().find(|(n, _, _)| n == name).map(|(_, v, _)| v.clone()).unwrap()
        };
        assert_eq!(value(&scene.parameters, "y").number, 10.0);
        assert_eq!(value(&scene.initial, "Q2").unit.as_deref(), Some("deg"));
        // Every other quantity at the model's value, so the printed scene is the run's.
        let names = |table: &[(String, crate::scene::Value, _)]| {
            let mut names: Vec<String> = table.iter().map(|(n, _, _)| n.to_ascii_uppercase()).collect();
            names.sort();
            names
        };
        let sorted = |list: &[&str]| {
            let mut list: Vec<String> = list.iter().map(|n| n.to_string()).collect();
            list.sort();
            list
        };
        assert_eq!(names(&scene.parameters), sorted(INFO.param_names));
        assert_eq!(names(&scene.initial), sorted(INFO.state_names));
        for (i, name) in INFO.param_names.iter().enumerate().filter(|(_, n)| **n != "Y") {
            assert_eq!(value(&scene.parameters, name).number, values().params[i], "{name}");
        }
        assert_eq!(value(&scene.initial, "Q1").number, values().initial[0]);
        let generated = scene_text("g.al", &run, &INFO, values(), &sets).unwrap();
        let text = generated.text();
        let line_of = |start: &str| text.lines().position(|l| l.starts_with(start)).unwrap() + 1;
        assert_eq!(generated.origin(line_of("t_final")), Origin::Input("TFINAL"));
        assert_eq!(
            generated.origin(line_of("Q2 =")),
            Origin::Set { name: "Q2".into(), value: "30 deg".into() }
        );
        assert_eq!(generated.origin(line_of("atol")), Origin::Input("ABSERR"));
    }

    #[test]
    fn defaults_and_an_unknown_set() {
        let scene = parsed(&FileRun::default(), &args(&[]));
        assert_eq!((scene.t_final, scene.output_step), (10.0, 0.1));
        assert_eq!(scene.outputs.len(), 6, "every state");
        let e = scene_text("g.al", &FileRun::default(), &INFO, values(), &args(&[("MASS", "3")]))
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("--set MASS: gimbal_gyroscope has no parameter or state `MASS`"), "{e}");
    }
}
