//! The scene of a model file run without one (`gyro-sim run --model FILE`): in come the file's
//! run settings, the model's metadata and what the command line gives (`--set`, `--t-final`,
//! the integrator); out goes the scene's TOML text (printable, so a user can save it and edit
//! it further), each line with where it came from.

use kane_model::runtime::ModelInfo;

use super::origins::{GeneratedScene, Origin};
use super::ModelRunError;
use crate::models::FileRun;
use crate::scene::IntegratorOverrides;

/// End time when neither the command line nor the file's TFINAL gives one.
const DEFAULT_T_FINAL: f64 = 10.0;
/// Output rows when the file gives no INTEGSTP.
const DEFAULT_ROWS: f64 = 100.0;
/// Method when the command line gives none (Autolev's generated programs use an adaptive
/// Runge-Kutta method of this family).
const DEFAULT_METHOD: &str = "dop853";
/// Tolerance when the file gives no ABSERR / RELERR.
const DEFAULT_TOLERANCE: f64 = 1e-8;

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
}

/// The scene for `model_path`: times, method, tolerances and outputs from the file (command
/// line first), `--set` values under `[parameters]` or `[initial]`, a view drawing the model when
/// asked; an error naming a `--set` that is neither a parameter nor a state.
pub fn scene_text(
    model_path: &str,
    run: &FileRun,
    info: &ModelInfo,
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
    let step = run.step.filter(|s| *s > 0.0 && *s <= t_final);
    let from = if step.is_some() { Origin::Input("INTEGSTP") } else { Origin::File };
    scene.push(format!("output_step = {}", toml_number(step.unwrap_or(t_final / DEFAULT_ROWS))), from);
    scene.push(format!("outputs = [{}]", outputs(run, info).join(", ")), Origin::Output);
    scene.push("", Origin::File);
    integrator(&mut scene, run, &args.integrator);
    values(&mut scene, info, &args.sets)?;
    if args.view {
        scene.push("", Origin::File);
        scene.push("[view]", Origin::File);
        scene.push("draw_model = true", Origin::File);
    }
    Ok(scene)
}

/// The OUTPUT names the model knows, quoted (every state when none).
fn outputs(run: &FileRun, info: &ModelInfo) -> Vec<String> {
    let known = |n: &str| info.state(n).is_some() || info.output(n).is_some();
    let mut outputs: Vec<&str> = run.outputs.iter().map(String::as_str).filter(|n| known(n)).collect();
    if outputs.is_empty() {
        outputs = info.state_names.to_vec();
    }
    outputs.iter().map(|n| format!("{n:?}")).collect()
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

/// The `--set` values under `[parameters]` and `[initial]`.
fn values(
    scene: &mut GeneratedScene,
    info: &ModelInfo,
    sets: &[(String, String)],
) -> Result<(), ModelRunError> {
    let (mut params, mut initial) = (Vec::new(), Vec::new());
    for (name, value) in sets {
        let line = (
            format!("{name:?} = {}", toml_value(value)),
            Origin::Set { name: name.clone(), value: value.clone() },
        );
        if info.param(name).is_some() {
            params.push(line);
        } else if info.state(name).is_some() {
            initial.push(line);
        } else {
            return Err(ModelRunError::UnknownSet {
                name: name.clone(),
                model: info.name.to_string(),
                params: info.param_names.iter().map(|p| p.to_string()).collect(),
                states: info.state_names.iter().map(|s| s.to_string()).collect(),
            });
        }
    }
    for (table, lines) in [("[parameters]", params), ("[initial]", initial)] {
        if !lines.is_empty() {
            scene.push("", Origin::File);
            scene.push(table, Origin::File);
            lines.into_iter().for_each(|(line, origin)| scene.push(line, origin));
        }
    }
    Ok(())
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
        }
    }

    fn parsed(run: &FileRun, args: &ModelRunArgs) -> Scene {
        let text = scene_text("g.al", run, &INFO, args).unwrap().text();
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
        assert_eq!(scene.parameters[0].0, "y");
        assert_eq!(scene.initial[0].1.unit.as_deref(), Some("deg"));
        let generated = scene_text("g.al", &run, &INFO, &sets).unwrap();
        let text = generated.text();
        let line_of = |start: &str| text.lines().position(|l| l.starts_with(start)).unwrap() + 1;
        assert_eq!(generated.origin(line_of("t_final")), Origin::Input("TFINAL"));
        assert_eq!(
            generated.origin(line_of("\"Q2\"")),
            Origin::Set { name: "Q2".into(), value: "30 deg".into() }
        );
        assert_eq!(generated.origin(line_of("atol")), Origin::Input("ABSERR"));
    }

    #[test]
    fn defaults_and_an_unknown_set() {
        let scene = parsed(&FileRun::default(), &args(&[]));
        assert_eq!((scene.t_final, scene.output_step), (10.0, 0.1));
        assert_eq!(scene.outputs.len(), 6, "every state");
        let e =
            scene_text("g.al", &FileRun::default(), &INFO, &args(&[("MASS", "3")])).unwrap_err().to_string();
        assert!(e.starts_with("--set MASS: gimbal_gyroscope has no parameter or state `MASS`"), "{e}");
    }
}
