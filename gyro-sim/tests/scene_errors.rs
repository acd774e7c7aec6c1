//! Malformed scenes are rejected with the file, the line and the fix.

use gyro_sim::run;
use gyro_sim::Scene;

fn error(text: &str) -> String {
    match Scene::parse("bad.toml", text) {
        Ok(s) => run(&s, None).map(|_| ()).unwrap_err().to_string(),
        Err(e) => e.to_string(),
    }
}

#[test]
fn unknown_key() {
    let e = error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\nt_finla = 2.0\n");
    assert!(e.starts_with("bad.toml:4:1: error: unknown field `t_finla`"), "{e}");
    assert!(e.contains("help:"), "{e}");
}

#[test]
fn wrong_unit() {
    let e =
        error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[initial]\nQ2 = \"3 m/s\"\n");
    assert!(e.starts_with("bad.toml:5:6: error: `Q2` is in DEG, not M/S"), "{e}");
}

#[test]
fn missing_or_unknown_model() {
    let e = error("t_final = 1.0\noutput_step = 0.1\n");
    assert!(e.contains("error: missing `model`") && e.contains("help: add model ="), "{e}");
    let e = error("model = \"gimbal\"\nt_final = 1.0\noutput_step = 0.1\n");
    assert!(
        e.starts_with("bad.toml:1:9: error: unknown model `gimbal`") && e.contains("gimbal_gyroscope"),
        "{e}"
    );
}

#[test]
fn negative_t_final() {
    let e = error("model = \"gimbal_gyroscope\"\nt_final = -5.0\noutput_step = 0.1\n");
    assert!(e.starts_with("bad.toml:2:11: error: t_final must be positive, not -5"), "{e}");
}

#[test]
fn unknown_parameter_and_output() {
    let e = error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[parameters]\nYY = 1.0\n");
    assert!(
        e.contains("bad.toml:5:6: error: `YY` is not a parameter") && e.contains("parameters: M1"),
        "{e}"
    );
    let e =
        error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\noutputs = [\"Q1\", \"AQ\"]\n");
    assert!(e.contains("`AQ` is neither a state nor an output"), "{e}");
}

#[test]
fn every_unknown_name_is_reported_at_once_with_the_name_meant() {
    let e = error(
        "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[parameters]\nM11 = 2\n[initial]\nQ11 = 0.1\nU4 = 2\n",
    );
    let lines: Vec<&str> = e.lines().collect();
    assert_eq!(lines.len(), 6, "{e}");
    assert!(lines[0].starts_with("bad.toml:5:7: error: `M11` is not a parameter of gimbal_gyroscope"), "{e}");
    assert!(lines[1].contains("help: did you mean `M1`? parameters: M1, M2, M3"), "{e}");
    assert!(
        lines[2].starts_with("bad.toml:7:7: error: `Q11` is not a state")
            && lines[3].contains("did you mean `Q1`?"),
        "{e}"
    );
    assert!(lines[4].starts_with("bad.toml:8:6: error: `U4` is not a state"), "{e}");
}

#[test]
fn accuracy_must_be_positive_and_needs_an_adaptive_method() {
    let base = "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[integrator]\n";
    let e = error(&format!("{base}method = \"dop853\"\naccuracy = -1e-6\n"));
    assert!(e.starts_with("bad.toml:6:12: error: accuracy must be positive"), "{e}");
    let e = error(&format!("{base}method = \"rk4\"\naccuracy = 1e-6\n"));
    assert!(e.starts_with("bad.toml:6:12: error: accuracy needs an adaptive method"), "{e}");
    assert!(e.contains("dop853"), "{e}");
}

#[test]
fn plot_points_must_be_in_range() {
    let e = error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\nplot_points = 0\n");
    assert!(e.starts_with("bad.toml:4:15: error: plot_points must be 1 to 1000, not 0"), "{e}");
}

#[test]
fn a_view_reading_a_column_the_model_lacks() {
    let head = "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n";
    let body = "[[view.bodies]]\nname = \"rotor\"\nshape = { kind = \"rod\", length = 1.0 }\ncolour = \"#000000\"\norientation = { quaternion = [\"Q_E0\", \"Q_E1\", \"Q_E2\", \"Q_E3\"] }\n";
    let e = error(&format!("{head}{body}"));
    assert!(e.starts_with("bad.toml:4:1: error: [view]: body rotor reads `Q_E0`"), "{e}");
    assert!(e.contains("A_D_11"), "names the columns there are: {e}");
}

#[test]
fn view_columns_are_computed_but_not_written() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/paper/trial3.toml");
    let scene = Scene::load(std::path::Path::new(path)).unwrap();
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("view_columns");
    let summary = run(&scene, Some(&dir)).unwrap();
    let t = &summary.trajectory;
    assert!(t.columns.iter().any(|c| c.name == "A_D_11" && c.hidden));
    assert!(t.columns.iter().filter(|c| !c.hidden).all(|c| !c.name.starts_with("A_")));
    let csv = std::fs::read_to_string(dir.join("trajectory.csv")).unwrap();
    assert_eq!(
        csv.lines().next().unwrap(),
        "t,q1_deg,q2_deg,q3_deg,u1_rad_per_s,u2_rad_per_s,u3_rad_per_s,ap_m_per_s2"
    );
    let page = std::fs::read_to_string(dir.join("view.html")).unwrap();
    assert!(page.contains("\"A_D_11\""), "the view carries the rotor's direction cosines");
}

/// Columns a view reads that the CSV does not ask for are not part of the accuracy estimate: the
/// loops preset refines its tolerances (accuracy = 1e-8) the same with and without its view.
#[test]
fn a_view_does_not_change_the_refined_run() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/ejs/loops.toml");
    let with_view = Scene::load(std::path::Path::new(path)).unwrap();
    assert!(with_view.view.is_some(), "loops has a [view] reading L, omega and N");
    let without = Scene { view: None, ..with_view.clone() };
    let a = run(&with_view, None).unwrap().trajectory;
    let b = run(&without, None).unwrap().trajectory;
    assert!(a.columns.iter().any(|c| c.hidden) && !b.columns.iter().any(|c| c.hidden));
    assert_eq!((a.stats.steps, a.stats.rhs_evals), (b.stats.steps, b.stats.rhs_evals));
    let (ra, rb) = (a.accuracy.unwrap(), b.accuracy.unwrap());
    assert_eq!((ra.runs, ra.rtol, ra.estimate), (rb.runs, rb.rtol, rb.estimate));
    let written = 1 + b.columns.len();
    assert!(a.rows.iter().zip(&b.rows).all(|(x, y)| x[..written] == y[..]));
}

/// Output grids too large to hold are refused before anything is allocated, at `output_step`,
/// saying how to go on (`t_final = 1e300` panicked, `output_step = 1e-9` tried 40 GB).
#[test]
fn output_grids_too_large_are_refused_up_front() {
    let grid = |t_final: &str, step: &str| {
        error(&format!("model = \"gimbal_gyroscope\"\nt_final = {t_final}\noutput_step = {step}\n"))
    };
    let e = grid("1e300", "0.1");
    assert!(e.starts_with("bad.toml:3:15: error: t_final = 1e300 with output_step = 0.1 makes"), "{e}");
    assert!(e.contains("more than the 10000000 allowed"), "{e}");
    assert!(e.contains("help: raise output_step to at least") && e.contains("shorten t_final"), "{e}");
    let e = grid("100.0", "1e-9");
    assert!(
        e.starts_with("bad.toml:3:15: error: t_final = 100 with output_step = 1e-9 makes 1.000e11"),
        "{e}"
    );
    let e = grid("1e8", "1.0");
    assert!(e.contains("1.000e8 output rows"), "{e}");
    // A grid at the limit's scale but under it is accepted (parsed; not run here).
    let ok = "model = \"gimbal_gyroscope\"\nt_final = 1e6\noutput_step = 0.5\n";
    assert!(Scene::parse("ok.toml", ok).is_ok());
}

/// `max_steps` under [integrator]: a positive whole number; a fixed step needing more steps than
/// it allows is refused at `step`; an adaptive run reaching it stops saying where and how to go on.
#[test]
fn max_steps_is_a_scene_key_and_reaching_it_says_how_to_go_on() {
    let base = "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[integrator]\n";
    let e = error(&format!("{base}max_steps = 0\n"));
    assert!(e.starts_with("bad.toml:5:13: error: max_steps must be at least 1, not 0"), "{e}");
    let e = error(&format!("{base}method = \"rk4\"\nstep = 1e-9\n"));
    assert!(e.starts_with("bad.toml:6:8: error: step = 1e-9 needs 1.000e9 steps"), "{e}");
    assert!(e.contains("more than max_steps = 10000000") && e.contains("help: raise step"), "{e}");
    let e = error(&format!("{base}method = \"rk4\"\nstep = 0.001\nmax_steps = 100\n"));
    assert!(e.starts_with("bad.toml:6:8: error: step = 1e-3 needs 1.000e3 steps"), "{e}");
    let e = error(&format!("{base}method = \"dop853\"\nrtol = 1e-12\natol = 1e-12\nmax_steps = 5\n"));
    assert!(e.contains("integration failed: stopped at t = "), "{e}");
    assert!(
        e.contains("after 5 steps, the step limit")
            && e.contains("help: raise max_steps under [integrator] (now 5)"),
        "{e}"
    );
    // Enough steps: the run completes.
    let ok = format!("{base}method = \"rk4\"\nstep = 0.01\nmax_steps = 100\n");
    let scene = Scene::parse("ok.toml", &ok).unwrap();
    assert_eq!(scene.integrator.max_steps, 100);
    let summary = run(&scene, None).unwrap();
    assert_eq!(summary.trajectory.stats.steps, 100);
}

/// A value's unit is compared with the model's `UNITS` regardless of case and spacing: the
/// gimbal says `UNITS Y = N*M`, so `"10 N*m"`, `"10 n * m"` and `"10 N m"` are all 10 N*M.
#[test]
fn units_compare_regardless_of_case_and_spacing() {
    let registry = gyro_sim::Registry::builtin();
    for unit in ["N*m", "n * m", "N m", "N*M"] {
        let text = format!("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[parameters]\nY = \"10 {unit}\"\n");
        let scene = Scene::parse("units.toml", &text).unwrap();
        let problem = gyro_sim::resolve(&scene, &registry).unwrap_or_else(|e| panic!("{unit}: {e}"));
        let y = problem.model.info().param_names.iter().position(|p| *p == "Y").unwrap();
        assert_eq!(problem.params[y], 10.0, "{unit}");
    }
    let e = error(
        "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[parameters]\nY = \"10 Nm\"\n",
    );
    assert!(e.starts_with("bad.toml:5:5: error: `Y` is in N*M, not NM"), "{e}");
}

/// NaN and infinite values in a scene are refused at the key (they used to reach the model and
/// be reported as "has no value" at line 1:1).
#[test]
fn nan_and_infinite_values_are_refused_at_their_key() {
    let head = "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n";
    let e = error(&format!("{head}[parameters]\nY = nan\n"));
    assert!(e.starts_with("bad.toml:5:5: error: `Y` is NaN, not a finite number"), "{e}");
    assert!(e.contains("help: give Y a finite value"), "{e}");
    let e = error(&format!("{head}[initial]\nU3 = -inf\n"));
    assert!(e.starts_with("bad.toml:5:6: error: `U3` is -inf, not a finite number"), "{e}");
    let e = error(&format!("{head}[parameters]\nZ = \"inf N*m\"\n"));
    assert!(e.starts_with("bad.toml:5:5: error: `Z` is inf, not a finite number"), "{e}");
}

/// A parameter the model file gives no INPUT value is named with where its value should have
/// come from, at the scene's `model` key.
#[test]
fn a_parameter_without_a_value_names_the_model_file() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("no_input_value");
    std::fs::create_dir_all(&dir).unwrap();
    let gimbal = include_str!("../../kane-model/models/gimbal_gyroscope.al");
    let model: String =
        gimbal.lines().filter(|l| !l.starts_with("INPUT M1")).map(|l| format!("{l}\n")).collect();
    std::fs::write(dir.join("no_m1.al"), model).unwrap();
    std::fs::write(dir.join("scene.toml"), "model = \"no_m1.al\"\nt_final = 0.1\noutput_step = 0.05\n")
        .unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", "scene.toml", "--engine", "instant", "--out", "out"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stderr).to_string() + &String::from_utf8_lossy(&out.stdout);
    assert!(!out.status.success(), "{text}");
    assert!(
        text.contains("scene.toml:1:9: error: parameter `M1` has no value: the model file no_m1.al gives it no INPUT value, and the scene sets none"),
        "{text}"
    );
    assert!(text.contains("help: set it under [parameters] (M1 = ...)"), "{text}");
    // A run of the file alone names the flag that gives the value.
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", "--model", "no_m1.al", "--engine", "instant", "--out", "out_model"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(!out.status.success() && text.contains("`--set M1=VALUE`"), "{text}");
}

#[test]
fn a_quantity_given_twice_in_two_spellings_names_both() {
    let e = error(
        "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[parameters]\nY = 1.0\ny = 2.0\n",
    );
    assert!(e.starts_with("bad.toml:6:5: error: `y` is given twice: `Y` sets the same quantity"), "{e}");
    let e = error(
        "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[initial]\nu3 = 1.0\nU3 = 2.0\n",
    );
    assert!(e.contains("`U3` is given twice: `u3` sets the same quantity"), "{e}");
}

/// `gyro-sim run` with `args` in `dir`: its exit success and what it printed.
fn run_in(dir: &std::path::Path, args: &[&str]) -> (bool, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .arg("run")
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stderr).to_string() + &String::from_utf8_lossy(&out.stdout),
    )
}

#[test]
fn the_command_lines_method_and_tolerances_replace_the_scenes_and_bad_ones_are_named() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("integrator_arguments");
    std::fs::create_dir_all(&dir).unwrap();
    let scene = "model = \"gimbal_gyroscope\"\nt_final = 0.5\noutput_step = 0.05\n[integrator]\nmethod = \"dopri5\"\nrtol = 1e-6\natol = 1e-6\n";
    std::fs::write(dir.join("scene.toml"), scene).unwrap();
    let steps = |said: &str| -> usize {
        let head = said.split(" steps (").next().unwrap();
        head.rsplit(' ').next().unwrap().parse().unwrap()
    };
    let (ok, file) = run_in(&dir, &["scene.toml", "--out", "file"]);
    assert!(ok, "{file}");
    let (ok, tight) = run_in(&dir, &["scene.toml", "--rtol", "1e-11", "--atol", "1e-11", "--out", "tight"]);
    assert!(ok, "{tight}");
    assert!(steps(&tight) > 3 * steps(&file), "tighter tolerances take more steps: {file}\n{tight}");
    let (ok, vern9) = run_in(
        &dir,
        &["scene.toml", "--method", "VERN9", "--rtol", "1e-11", "--atol", "1e-11", "--out", "v"],
    );
    assert!(ok, "{vern9}");
    assert!(steps(&vern9) < steps(&tight), "a ninth-order method takes fewer steps: {tight}\n{vern9}");
    let (ok, said) = run_in(&dir, &["scene.toml", "--rtol", "-1e-9", "--out", "bad"]);
    assert!(!ok && said.contains("`-1e-9` is not a positive number"), "{said}");
    let (ok, said) = run_in(&dir, &["scene.toml", "--method", "euler", "--out", "bad"]);
    assert!(!ok && said.contains("unknown integrator `euler` (methods: dop853"), "{said}");
    assert!(!dir.join("bad").exists(), "nothing is written for refused arguments");
    let gimbal = include_str!("../../kane-model/models/gimbal_gyroscope.al");
    std::fs::write(dir.join("gimbal.al"), gimbal).unwrap();
    let model = ["--model", "gimbal.al", "--engine", "instant"];
    let (ok, said) = run_in(&dir, &[&model[..], &["--t-final", "-3", "--out", "bad"]].concat());
    assert!(!ok && said.starts_with("--t-final: error: t_final must be positive, not -3"), "{said}");
    let (ok, said) =
        run_in(&dir, &[&model[..], &["--method", "rk4", "--rtol", "1e-10", "--print-scene"]].concat());
    assert!(ok && said.contains("method = \"rk4\"\nrtol = 1e-10\n"), "{said}");
}

#[test]
fn a_view_length_naming_no_parameter_is_an_error_at_the_view() {
    let head = "model = \"heavy_top\"\nt_final = 1.0\noutput_step = 0.1\n[axle]\ntilt = \"30 deg\"\nspin = 5\nquaternion = [\"E4\", \"E1\", \"E2\", \"E3\"]\nrates = [\"W1\", \"W2\", \"W3\"]\n";
    let view = "[[view.bodies]]\nname = \"rotor\"\nshape = { kind = \"ellipsoid\", a = \"R\", b = 1.0, c = 0.2 }\ncolour = \"#3b7dd8\"\norientation = { quaternion = [\"E4\", \"E1\", \"E2\", \"E3\"] }\noffset = [0.0, 0.0, \"D\"]\n";
    let e = error(&format!("{head}{view}"));
    assert!(e.starts_with("bad.toml:9:1: error: view: body rotor reads parameter `R`, which the model does not have (it has: "), "{e}");
    let e = error(&format!("{head}{}", view.replace("\"R\"", "\"-1*D\"")));
    assert!(e.contains("view: body rotor: shape sizes [-1.0, 1.0, 0.2] must be positive"), "{e}");
    let e = error(&format!("{head}{}", view.replace("\"R\"", "\"R+1\"")));
    assert!(e.contains("`R+1` is not a length: give a number, a parameter's name"), "{e}");
}

#[test]
fn a_built_in_model_has_no_drawing_to_draw() {
    let e =
        error("model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[view]\ndraw_model = true\n");
    assert!(e.starts_with("bad.toml:4:1: error: [view]: draw_model = true"), "{e}");
    assert!(e.contains("[[view.bodies]]"), "{e}");
}

#[test]
fn missing_times_are_both_reported_at_once() {
    let e = error("model = \"gimbal_gyroscope\"\n");
    assert!(e.contains("missing `t_final`") && e.contains("missing `output_step`"), "{e}");
}
