//! A scene for a model file run without one (`gyro-sim run --model FILE`): in come the file's
//! run settings, the model's metadata and the command line's `--set` and `--t-final`; out goes
//! the scene's TOML text (printable, so a user can save it and edit it further).

use kane_model::runtime::ModelInfo;

use super::CliError;
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

/// A `--method` value: a method's name or `auto`.
pub fn parse_method(text: &str) -> Result<String, CliError> {
    let name = text.trim().to_ascii_lowercase();
    match name == crate::ode::AUTO || crate::ode::by_name(&name).is_some() {
        true => Ok(name),
        false => Err(CliError::UnknownMethod { name: text.to_string() }),
    }
}

/// A `--rtol` or `--atol` value: a positive, finite number.
pub fn parse_tolerance(text: &str) -> Result<f64, CliError> {
    match text.trim().parse::<f64>() {
        Ok(x) if x > 0.0 && x.is_finite() => Ok(x),
        _ => Err(CliError::NotPositive { text: text.to_string() }),
    }
}

/// Splits `NAME=VALUE`.
pub fn parse_set(text: &str) -> Result<(String, String), CliError> {
    match text.split_once('=') {
        Some((n, v)) if !n.trim().is_empty() && !v.trim().is_empty() => {
            Ok((n.trim().to_string(), v.trim().to_string()))
        }
        _ => Err(CliError::SetForm { text: text.to_string() }),
    }
}

/// The scene text for `model_path`: times, method, tolerances and outputs from the file (command
/// line first), `--set` values under `[parameters]` or `[initial]`, a view drawing the model when
/// asked; an error naming a `--set` that is neither a parameter nor a state.
pub fn scene_text(
    model_path: &str,
    run: &FileRun,
    info: &ModelInfo,
    args: &ModelRunArgs,
) -> Result<String, CliError> {
    let t_final = args.t_final.or(run.t_final).unwrap_or(DEFAULT_T_FINAL);
    let step = run.step.filter(|s| *s > 0.0 && *s <= t_final).unwrap_or(t_final / DEFAULT_ROWS);
    let known = |n: &str| info.state(n).is_some() || info.output(n).is_some();
    let mut outputs: Vec<&str> = run.outputs.iter().map(String::as_str).filter(|n| known(n)).collect();
    if outputs.is_empty() {
        outputs = info.state_names.to_vec();
    }
    let quoted: Vec<String> = outputs.iter().map(|n| format!("{n:?}")).collect();
    let mut text = format!(
        "title = {:?}\nmodel = {:?}\nt_final = {}\noutput_step = {}\noutputs = [{}]\n\n[integrator]\nmethod = {:?}\nrtol = {:e}\natol = {:e}\n",
        format!("{} (model file)", info.name),
        model_path,
        toml_number(t_final),
        toml_number(step),
        quoted.join(", "),
        args.integrator.method.as_deref().unwrap_or(DEFAULT_METHOD),
        args.integrator.rtol.or(run.relerr).unwrap_or(DEFAULT_TOLERANCE),
        args.integrator.atol.or(run.abserr).unwrap_or(DEFAULT_TOLERANCE),
    );
    let (mut params, mut initial) = (String::new(), String::new());
    for (name, value) in &args.sets {
        let line = format!("{name:?} = {}\n", toml_value(value));
        if info.param(name).is_some() {
            params.push_str(&line);
        } else if info.state(name).is_some() {
            initial.push_str(&line);
        } else {
            return Err(CliError::UnknownSet {
                name: name.clone(),
                model: info.name.to_string(),
                params: info.param_names.iter().map(|p| p.to_string()).collect(),
                states: info.state_names.iter().map(|s| s.to_string()).collect(),
            });
        }
    }
    if !params.is_empty() {
        text.push_str(&format!("\n[parameters]\n{params}"));
    }
    if !initial.is_empty() {
        text.push_str(&format!("\n[initial]\n{initial}"));
    }
    if args.view {
        text.push_str("\n[view]\ndraw_model = true\n");
    }
    Ok(text)
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

    #[test]
    fn the_command_lines_method_and_tolerances_come_before_the_files() {
        let run = FileRun { abserr: Some(1e-7), relerr: Some(1e-6), ..FileRun::default() };
        let scene = |integrator: IntegratorOverrides| {
            let text = scene_text("g.al", &run, &INFO, &ModelRunArgs { integrator, ..args(&[]) }).unwrap();
            Scene::parse("<command line>", &text).unwrap().integrator
        };
        let file = scene(IntegratorOverrides::default());
        assert_eq!((file.method.name(), file.rtol, file.atol), ("dop853", 1e-6, 1e-7));
        let given = IntegratorOverrides { method: Some("vern9".into()), rtol: Some(1e-11), atol: None };
        let given = scene(given);
        assert_eq!((given.method.name(), given.rtol, given.atol), ("vern9", 1e-11, 1e-7));
        let auto = IntegratorOverrides { method: Some("auto".into()), rtol: Some(1e-10), atol: Some(1e-10) };
        assert_eq!(scene(auto).method.name(), "vern9", "auto picks by the tolerances given");
        assert_eq!(parse_method("VERN7").unwrap(), "vern7");
        let e = parse_method("euler").unwrap_err().to_string();
        assert!(e.starts_with("unknown integrator `euler` (methods: dop853"), "{e}");
        assert_eq!(parse_tolerance("1e-9").unwrap(), 1e-9);
        for bad in ["-1e-9", "0", "inf", "NaN", "tight"] {
            let e = parse_tolerance(bad).unwrap_err().to_string();
            assert_eq!(e, format!("`{bad}` is not a positive number (for example 1e-9)"));
        }
    }

    #[test]
    fn the_file_settings_and_sets_make_a_scene() {
        let run = FileRun {
            t_final: Some(5.0),
            step: Some(0.05),
            abserr: Some(1e-7),
            relerr: Some(1e-7),
            outputs: vec!["Q1".into(), "AP".into(), "NOT_THERE".into()],
        };
        let text = scene_text("g.al", &run, &INFO, &args(&[("y", "10"), ("Q2", "30 deg")])).unwrap();
        let scene = Scene::parse("<command line>", &text).unwrap();
        assert_eq!((scene.t_final, scene.output_step), (5.0, 0.05));
        assert_eq!((scene.integrator.rtol, scene.integrator.atol), (1e-7, 1e-7));
        let outputs: Vec<&str> = scene.outputs.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(outputs, ["Q1", "AP"]);
        assert_eq!(scene.parameters[0].0, "y");
        assert_eq!(scene.initial[0].1.unit.as_deref(), Some("deg"));
    }

    #[test]
    fn defaults_and_an_unknown_set() {
        let text = scene_text("g.al", &FileRun::default(), &INFO, &args(&[])).unwrap();
        let scene = Scene::parse("<command line>", &text).unwrap();
        assert_eq!((scene.t_final, scene.output_step), (10.0, 0.1));
        assert_eq!(scene.outputs.len(), 6, "every state");
        let e =
            scene_text("g.al", &FileRun::default(), &INFO, &args(&[("MASS", "3")])).unwrap_err().to_string();
        assert!(e.starts_with("--set MASS: gimbal_gyroscope has no parameter or state `MASS`"), "{e}");
        assert!(parse_set("Y").is_err() && parse_set("Y=").is_err());
        assert_eq!(parse_set("Q2 = 30 deg").unwrap(), ("Q2".into(), "30 deg".into()));
    }
}
