//! Stress suite: the abuse a new user tries, each case a test, driving the
//! real `gyro-sim` and `kane` programs (built by `kane_tests::bins`). No case may end in a
//! panic, an abort, a silent NaN or a lost or mixed file; each failure must be named. The
//! results are tabulated in RELIABILITY.md. Run: `cargo test --release -p kane-tests --test stress`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use kane_tests::bins;

/// A fresh folder for one test.
fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("stress").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// What a program did.
struct Ran {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

impl Ran {
    /// Exited by itself (no signal, no abort) and printed no panic.
    fn no_panic(&self) -> &Ran {
        assert!(self.code.is_some(), "killed by a signal (an abort?): {}", self.stderr);
        assert!(!self.stderr.contains("panicked"), "panicked: {}", self.stderr);
        self
    }
    /// Succeeded.
    fn ok(&self) -> &Ran {
        self.no_panic();
        assert_eq!(self.code, Some(0), "expected success: {}{}", self.stdout, self.stderr);
        self
    }
    /// Failed with an error naming `what`.
    fn fails_naming(&self, what: &[&str]) -> &Ran {
        self.no_panic();
        assert_eq!(self.code, Some(1), "expected a failure: {}{}", self.stdout, self.stderr);
        for w in what {
            assert!(self.stderr.contains(w), "the error should name `{w}`: {}", self.stderr);
        }
        self
    }
}

fn ran(out: Output) -> Ran {
    Ran {
        code: out.status.code(),
        stdout: String::from_utf8_lossy(&out.stdout).into(),
        stderr: String::from_utf8_lossy(&out.stderr).into(),
    }
}

/// `gyro-sim run SCENE --out DIR`.
fn run(scene: &Path, out: &Path) -> Ran {
    let cmd = Command::new(bins::gyro_sim()).arg("run").arg(scene).arg("--out").arg(out).output();
    ran(cmd.unwrap())
}

/// `kane ARGS`.
fn kane(args: &[&str]) -> Ran {
    ran(Command::new(bins::kane()).args(args).output().unwrap())
}

/// Writes `text` to `dir/name`.
fn file(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

/// The heavy top (EJS units) released at `tilt` with `spin`, dopri5 at 1e-9.
fn top(tilt: &str, spin: &str, t_final: f64, output_step: f64, extra: &str) -> String {
    format!(
        r#"model = "heavy_top"
outputs = ["E4", "E1", "E2", "E3", "W1", "W2", "W3", "ELEVATION", "ENERGY"]
t_final = {t_final:e}
output_step = {output_step:e}
[integrator]
method = "dopri5"
rtol = 1e-9
atol = 1e-9
{extra}
[parameters]
M = 1.0
G = 1.0
RR = 1.0
D = 1.0
[axle]
tilt = "{tilt}"
spin = "{spin}"
precession = "0 rad/s"
nutation = "0 rad/s"
quaternion = ["E4", "E1", "E2", "E3"]
rates = ["W1", "W2", "W3"]
"#
    )
}

/// The gimbal for 1 s with `params` and `initial` lines added.
fn gimbal(params: &str, initial: &str) -> String {
    format!(
        "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.05\n[integrator]\nmethod = \"dopri5\"\nrtol = 1e-9\natol = 1e-9\n[parameters]\nY = 10.0\nZ = 10.0\n{params}\n[initial]\nU3 = \"10 rad/s\"\n{initial}\n"
    )
}

/// The CSV's rows, every value checked finite.
fn finite_csv(path: &Path) -> Vec<Vec<f64>> {
    let text = std::fs::read_to_string(path).unwrap();
    let rows: Vec<Vec<f64>> =
        text.lines().skip(1).map(|l| l.split(',').map(|x| x.parse::<f64>().unwrap()).collect()).collect();
    assert!(
        rows.iter().flatten().all(|v| v.is_finite()),
        "{} holds a value that is not finite",
        path.display()
    );
    rows
}

/// A run of the top that succeeds with finite rows conserving energy to `tol`; its rows.
fn top_runs(name: &str, tilt: &str, spin: &str, t_final: f64, tol: f64) -> Vec<Vec<f64>> {
    let dir = folder(name);
    let scene = file(&dir, "top.toml", &top(tilt, spin, t_final, t_final / 20.0, "max_steps = 100000000"));
    run(&scene, &dir.join("out")).ok();
    let rows = finite_csv(&dir.join("out/trajectory.csv"));
    let energy: Vec<f64> = rows.iter().map(|r| r[9]).collect();
    let drift = energy.iter().map(|e| (e - energy[0]).abs()).fold(0.0, f64::max) / energy[0].abs().max(1.0);
    assert!(drift < tol, "energy drift {drift:e}");
    rows
}

#[test]
fn spin_0_rad_per_s() {
    top_runs("spin0", "60 deg", "0 rad/s", 5.0, 1e-7);
}

#[test]
fn spin_1e3_rad_per_s() {
    top_runs("spin1e3", "60 deg", "1e3 rad/s", 1.0, 1e-7);
}

#[test]
fn spin_1e5_rad_per_s() {
    top_runs("spin1e5", "60 deg", "1e5 rad/s", 0.1, 1e-6);
}

#[test]
fn spin_1e7_rad_per_s() {
    top_runs("spin1e7", "60 deg", "1e7 rad/s", 0.002, 1e-6);
}

#[test]
fn spin_1e7_rad_per_s_past_the_step_limit_keeps_its_rows_marked_partial() {
    let dir = folder("spin1e7_limit");
    let scene = file(&dir, "top.toml", &top("60 deg", "1e7 rad/s", 1.0, 1e-4, "max_steps = 200000"));
    let out = dir.join("out");
    run(&scene, &out).fails_naming(&["step limit", "max_steps", "trajectory.partial.csv"]);
    let rows = finite_csv(&out.join("trajectory.partial.csv"));
    assert!(rows.len() > 10, "{} rows kept", rows.len());
    assert!(!out.join("trajectory.csv").exists(), "no complete set claimed");
}

#[test]
fn top_released_exactly_vertical_stays_up() {
    let rows = top_runs("vertical", "0 deg", "10 rad/s", 10.0, 1e-9);
    assert!(rows.iter().all(|r| (r[8] - 90.0).abs() < 1e-6), "the axle stays vertical");
}

#[test]
fn top_released_horizontal() {
    top_runs("horizontal", "90 deg", "10 rad/s", 10.0, 1e-7);
}

#[test]
fn top_released_upside_down_stays_down() {
    let rows = top_runs("upside_down", "180 deg", "10 rad/s", 10.0, 1e-9);
    assert!(rows.iter().all(|r| (r[8] + 90.0).abs() < 1e-6), "the axle stays hanging");
}

#[test]
fn zero_angular_momentum_falls_like_a_pendulum() {
    let rows = top_runs("zero_momentum", "60 deg", "0 rad/s", 10.0, 1e-7);
    assert!(rows.iter().any(|r| r[8] < -50.0), "it swings down through the bottom");
}

#[test]
fn million_second_run_with_coarse_output_is_streamed() {
    let dir = folder("million_seconds");
    let scene = "model = \"free_body\"\nt_final = 1e6\noutput_step = 10.0\n[integrator]\nmethod = \"dopri5\"\nrtol = 1e-6\natol = 1e-9\n[parameters]\nI1 = 1.0\nI2 = 2.0\nI3 = 3.0\n[initial]\nE4 = 1.0\nE1 = 0.0\nE2 = 0.0\nE3 = 0.0\nW1 = \"0.001 rad/s\"\nW2 = \"0.0001 rad/s\"\nW3 = \"0.0001 rad/s\"\n";
    let scene = gyro_sim::Scene::parse(&dir.join("free.toml").display().to_string(), scene).unwrap();
    let summary = gyro_sim::run(&scene, Some(&dir.join("out"))).unwrap();
    let written = summary.written.unwrap();
    assert_eq!(written.rows, 100_001);
    // Memory holds a bounded, thinned set; every row went to the file.
    assert!(summary.trajectory.rows.len() <= gyro_sim::MAX_KEPT_ROWS + 1);
    assert_eq!(finite_csv(&written.csv).len(), 100_001);
}

#[test]
fn million_second_run_past_the_step_limit_is_named_and_partial() {
    let dir = folder("million_seconds_limit");
    let scene = file(&dir, "top.toml", &top("60 deg", "10 rad/s", 1e6, 1.0, "max_steps = 100000"));
    run(&scene, &dir.join("out")).fails_naming(&["step limit", "trajectory.partial.csv"]);
    assert!(finite_csv(&dir.join("out/trajectory.partial.csv")).len() > 100);
}

#[test]
fn gimbal_started_at_lock_runs() {
    let dir = folder("gimbal_lock");
    let scene = file(&dir, "g.toml", &gimbal("", "Q2 = \"0 deg\""));
    run(&scene, &dir.join("out")).ok();
    finite_csv(&dir.join("out/trajectory.csv"));
}

#[test]
fn gimbal_started_near_lock_runs() {
    let dir = folder("gimbal_near_lock");
    let scene = file(&dir, "g.toml", &gimbal("", "Q2 = \"1e-9 deg\""));
    run(&scene, &dir.join("out")).ok();
    finite_csv(&dir.join("out/trajectory.csv"));
}

#[test]
fn gimbal_at_lock_with_massless_gimbals_names_the_singular_mass_matrix() {
    let dir = folder("gimbal_lock_massless");
    let scene = file(&dir, "g.toml", &gimbal("M1 = 0.0\nM2 = 0.0", "Q2 = \"0 deg\""));
    run(&scene, &dir.join("out")).fails_naming(&["mass matrix singular", "t = 0", "Q2 = 0 deg"]);
}

#[test]
fn gimbal_near_lock_with_massless_gimbals() {
    let dir = folder("gimbal_near_lock_massless");
    let scene = file(&dir, "g.toml", &gimbal("M1 = 0.0\nM2 = 0.0", "Q2 = \"0.01 deg\""));
    let r = run(&scene, &dir.join("out"));
    r.no_panic();
    if r.code == Some(0) {
        finite_csv(&dir.join("out/trajectory.csv"));
    } else {
        r.fails_naming(&["integration failed"]);
    }
}

#[test]
fn negative_mass_in_a_scene_is_implausible_at_its_line() {
    let dir = folder("negative_mass");
    let scene = file(&dir, "g.toml", &gimbal("M1 = -2.0", ""));
    let line =
        std::fs::read_to_string(&scene).unwrap().lines().position(|l| l.starts_with("M1 =")).unwrap() + 1;
    let place = format!("g.toml:{line}:6: error: implausible value of M1");
    run(&scene, &dir.join("out")).fails_naming(&[&place, "the mass of", "cannot be negative"]);
}

#[test]
fn inertia_no_rigid_body_has_in_a_scene_is_implausible() {
    let dir = folder("triangle_inertia");
    let scene = file(&dir, "top.toml", &top("60 deg", "10 rad/s", 1.0, 0.1, ""));
    let text = std::fs::read_to_string(&scene).unwrap();
    let text = text.replace("[parameters]\n", "[parameters]\nAXIAL = 0.5\n");
    std::fs::write(&scene, text).unwrap();
    run(&scene, &dir.join("out")).fails_naming(&["implausible value of", "triangle inequality"]);
}

#[test]
fn negative_mass_in_a_model_file_is_implausible() {
    let dir = folder("negative_mass_file");
    let model = std::fs::read_to_string(model_path("gimbal_gyroscope.al")).unwrap();
    let model = file(&dir, "g.al", &model.replace("INPUT M1 = 2,", "INPUT M1 = -2,"));
    let out = dir.join("out");
    let r = Command::new(bins::gyro_sim())
        .args(["run", "--engine", "instant", "--model"])
        .arg(&model)
        .arg("--out")
        .arg(&out)
        .output();
    ran(r.unwrap()).fails_naming(&["implausible value of M1"]);
}

#[test]
fn t_final_1e300_is_refused_up_front() {
    let dir = folder("t_final_1e300");
    let scene = file(&dir, "top.toml", &top("60 deg", "10 rad/s", 1e300, 0.1, ""));
    run(&scene, &dir.join("out")).fails_naming(&["t_final", "output rows", "top.toml:"]);
}

#[test]
fn output_step_1e_minus_9_is_refused_up_front() {
    let dir = folder("output_step_1e-9");
    let scene = file(&dir, "top.toml", &top("60 deg", "10 rad/s", 10.0, 1e-9, ""));
    run(&scene, &dir.join("out")).fails_naming(&["output_step", "output rows"]);
}

#[test]
fn a_hundred_million_output_rows_are_refused_up_front() {
    let dir = folder("rows_1e8");
    let scene = file(&dir, "top.toml", &top("60 deg", "10 rad/s", 1e7, 0.1, ""));
    run(&scene, &dir.join("out")).fails_naming(&["1.000e8 output rows", "raise output_step"]);
}

#[test]
fn tiny_rk4_step_is_refused_up_front_by_the_step_limit() {
    let dir = folder("tiny_rk4_step");
    let text =
        gimbal("", "").replace("method = \"dopri5\"", "method = \"rk4\"\nstep = 1e-12\nmax_steps = 100000");
    let scene = file(&dir, "g.toml", &text.replace("rtol = 1e-9\natol = 1e-9\n", ""));
    run(&scene, &dir.join("out")).fails_naming(&["step = 1e-12 needs 1.000e12 steps", "max_steps = 100000"]);
}

#[test]
fn nan_parameter_is_named_at_its_key() {
    let dir = folder("nan_parameter");
    let scene = file(&dir, "g.toml", &gimbal("", "").replace("Y = 10.0", "Y = nan"));
    run(&scene, &dir.join("out")).fails_naming(&["g.toml:", "`Y`", "NaN"]);
}

#[test]
fn overflow_is_named() {
    let dir = folder("overflow");
    let scene = file(&dir, "top.toml", &top("60 deg", "1e200 rad/s", 1.0, 0.1, ""));
    run(&scene, &dir.join("out")).fails_naming(&["overflow", "W3"]);
}

#[test]
fn torque_with_unit_n_m_is_accepted_where_the_model_says_n_m() {
    let dir = folder("units_n_m");
    let scene = file(&dir, "g.toml", &gimbal("", "").replace("Y = 10.0", "Y = \"10 N*m\""));
    run(&scene, &dir.join("out")).ok();
}

#[test]
fn zero_euler_parameters_are_refused() {
    let dir = folder("zero_euler");
    let text = "model = \"free_body\"\nt_final = 1.0\noutput_step = 0.1\n[parameters]\nI1 = 1.0\nI2 = 2.0\nI3 = 3.0\n[initial]\nE4 = 0.0\nE1 = 0.0\nE2 = 0.0\nE3 = 0.0\nW1 = 1.0\n";
    let scene = file(&dir, "free.toml", text);
    run(&scene, &dir.join("out")).fails_naming(&["free.toml", "Euler parameters"]);
}

#[test]
fn non_unit_euler_parameters_are_refused() {
    let dir = folder("non_unit_euler");
    let text = "model = \"free_body\"\nt_final = 1.0\noutput_step = 0.1\n[parameters]\nI1 = 1.0\nI2 = 2.0\nI3 = 3.0\n[initial]\nE4 = 2.0\nE1 = 0.0\nE2 = 0.0\nE3 = 0.0\nW1 = 1.0\n";
    let scene = file(&dir, "free.toml", text);
    run(&scene, &dir.join("out")).fails_naming(&["free.toml", "Euler parameters", "norm"]);
}

/// A model file of the workspace.
fn model_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../kane-model/models").join(name)
}

/// The gimbal model file with `from` replaced by `to`, written into `dir`.
fn edited_gimbal(dir: &Path, from: &str, to: &str) -> PathBuf {
    let text = std::fs::read_to_string(model_path("gimbal_gyroscope.al")).unwrap();
    assert!(text.contains(from), "{from}");
    file(dir, "g.al", &text.replacen(from, to, 1))
}

#[test]
fn deleting_a_kinematic_equation_is_an_error() {
    let dir = folder("no_q2_equation");
    let path = edited_gimbal(&dir, "Q2' = U2 ", "");
    kane(&["check", path.to_str().unwrap()])
        .fails_naming(&["Q2 orients C but has no kinematic equation", "g.al:33:1"]);
}

#[test]
fn unknown_units_are_errors() {
    let dir = folder("unknown_units");
    let path = edited_gimbal(&dir, "T = SEC", "T = SCE");
    let path =
        file(&dir, "g.al", &std::fs::read_to_string(path).unwrap().replacen("Q1 = DEG", "Q1 = DGE", 1));
    kane(&["check", path.to_str().unwrap()]).fails_naming(&["DGE", "SCE", "DEG"]);
}

#[test]
fn a_duplicated_load_line_is_a_warning_naming_both_lines() {
    let dir = folder("duplicate_load");
    let path = edited_gimbal(&dir, "TORQUE_C> = Z*B1>", "TORQUE_C> = Z*B1>\nTORQUE_C> = Z*B1>");
    let r = kane(&["check", path.to_str().unwrap()]);
    r.ok();
    assert!(
        r.stderr.contains("g.al:54:1") && r.stderr.contains("given on line 53 and again on line 54"),
        "{}",
        r.stderr
    );
}

#[test]
fn ten_thousand_nested_parentheses_are_refused_at_their_place() {
    let dir = folder("nesting");
    let expr = format!("{}1{}", "(".repeat(10_000), ")".repeat(10_000));
    let path = file(&dir, "deep.al", &format!("CONSTANTS K\nX = K + {expr}\n"));
    kane(&["check", path.to_str().unwrap()]).fails_naming(&["deep.al:2:", "nest"]);
}

#[test]
fn a_twenty_thousand_term_sum_checks() {
    let dir = folder("long_sum");
    let sum: Vec<String> = (0..20_000).map(|i| format!("{i}*K")).collect();
    let path = file(&dir, "sum.al", &format!("CONSTANTS K\nX = {}\n", sum.join(" + ")));
    kane(&["check", path.to_str().unwrap()]).ok();
}

#[test]
fn seven_thousand_errors_print_the_first_fifty_and_a_count() {
    let dir = folder("errors_7000");
    let lines: Vec<String> = (0..7000).map(|i| format!("X{i} = NOPE{i}")).collect();
    let path = file(&dir, "errs.al", &format!("NEWTONIAN N\n{}\n", lines.join("\n")));
    let r = kane(&["check", path.to_str().unwrap()]);
    r.fails_naming(&["NOPE0", "and 6950 more errors"]);
    assert!(!r.stderr.contains("NOPE50`"), "only the first 50 are shown");
}

#[test]
fn kane_gen_to_dev_null_keeps_the_device() {
    let dir = folder("gen_dev_null");
    let _ = dir;
    kane(&["gen", model_path("heavy_top.al").to_str().unwrap(), "-o", "/dev/null"]).ok();
    use std::os::unix::fs::FileTypeExt;
    assert!(std::fs::metadata("/dev/null").unwrap().file_type().is_char_device());
}

#[test]
fn kane_gen_through_a_symlink_writes_its_target() {
    let dir = folder("gen_symlink");
    let target = file(&dir, "target.rs", "old");
    let link = dir.join("link.rs");
    std::os::unix::fs::symlink(&target, &link).unwrap();
    kane(&["gen", model_path("heavy_top.al").to_str().unwrap(), "-o", link.to_str().unwrap()]).ok();
    assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "still a symlink");
    assert!(std::fs::read_to_string(&target).unwrap().contains("fn rhs"), "written through");
}

#[test]
fn kane_gen_to_a_regular_file_replaces_it_whole() {
    let dir = folder("gen_regular");
    let out = file(&dir, "model.rs", "old");
    kane(&["gen", model_path("heavy_top.al").to_str().unwrap(), "-o", out.to_str().unwrap()]).ok();
    assert!(std::fs::read_to_string(&out).unwrap().contains("fn rhs"));
    let names: Vec<_> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(names.len(), 1, "no temporary left: {names:?}");
}

#[test]
fn two_runs_into_one_out_never_mix() {
    let dir = folder("two_runs");
    let out = dir.join("out");
    let scenes: Vec<PathBuf> = (0..2)
        .map(|k| {
            file(
                &dir,
                &format!("g{k}.toml"),
                &gimbal("", "").replace("10 rad/s", &format!("{} rad/s", 10 + k)),
            )
        })
        .collect();
    let alone: Vec<String> = scenes
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let own = dir.join(format!("alone{k}"));
            run(s, &own).ok();
            std::fs::read_to_string(own.join("trajectory.csv")).unwrap()
        })
        .collect();
    for _ in 0..3 {
        let children: Vec<_> = scenes
            .iter()
            .map(|s| {
                Command::new(bins::gyro_sim())
                    .arg("run")
                    .arg(s)
                    .arg("--out")
                    .arg(&out)
                    .stdout(std::process::Stdio::null())
                    .spawn()
                    .unwrap()
            })
            .collect();
        for mut c in children {
            assert!(c.wait().unwrap().success());
        }
        let csv = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
        assert!(alone.contains(&csv), "the CSV is one run's, whole");
    }
    let names: Vec<String> =
        std::fs::read_dir(&out).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
    assert!(names.iter().all(|n| !n.starts_with(".partial")), "no temporaries left: {names:?}");
}

#[test]
fn a_run_killed_between_its_csv_and_its_figures_leaves_the_earlier_set() {
    let dir = folder("killed");
    let out = dir.join("out");
    let good = file(&dir, "good.toml", &gimbal("", ""));
    run(&good, &out).ok();
    let before: Vec<Vec<u8>> =
        ["trajectory.csv", "trajectory.png"].iter().map(|n| std::fs::read(out.join(n)).unwrap()).collect();
    // A long run streaming its CSV: killed while the CSV is being written, before any figure.
    let long = file(&dir, "long.toml", &top("60 deg", "10 rad/s", 5e4, 0.01, ""));
    let mut child = Command::new(bins::gyro_sim())
        .arg("run")
        .arg(&long)
        .arg("--out")
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .spawn()
        .unwrap();
    // Sets are staged beside the folder, in `.out.gyro-sim/`.
    let work = dir.join(".out.gyro-sim");
    let staged_csv = || {
        std::fs::read_dir(&work).ok()?.filter_map(|e| e.ok()).find_map(|e| {
            let csv = e.path().join("trajectory.csv");
            std::fs::metadata(&csv).is_ok_and(|m| m.len() > 100_000).then_some(csv)
        })
    };
    while staged_csv().is_none() {
        assert!(child.try_wait().unwrap().is_none(), "the long run ended before it was killed");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    child.kill().unwrap();
    child.wait().unwrap();
    let after: Vec<Vec<u8>> =
        ["trajectory.csv", "trajectory.png"].iter().map(|n| std::fs::read(out.join(n)).unwrap()).collect();
    assert!(before == after, "the earlier set is intact");
    // The next run into the folder is complete and removes the killed run's staging folder.
    run(&good, &out).ok();
    let left: Vec<String> = std::fs::read_dir(&work)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().to_string())
        .filter(|n| n != "commit.lock")
        .collect();
    assert!(left.is_empty(), "staging left behind: {left:?}");
}

/// `Q' = U`, `U' = sqrt(1 - t)`: the rate turns NaN past t = 1.
struct Blowup;

static BLOWUP: kane_model::runtime::ModelInfo = kane_model::runtime::ModelInfo {
    name: "blowup",
    state_names: &["Q", "U"],
    state_units: &["", ""],
    n_coordinates: 1,
    param_names: &[],
    param_units: &[],
    inputs: &[],
    open_inputs: &[],
    outputs: &[],
    cyclic: &[],
    dependent_coordinates: &[],
    op_counts: kane_model::runtime::OpCounts { rhs: 0, outputs: 0 },
    taylor_straight_line: &[],
};

impl gyro_sim::System for Blowup {
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = y[1];
        dy[1] = (1.0 - t).sqrt();
    }
}

impl gyro_sim::SimModel for Blowup {
    fn info(&self) -> &'static kane_model::runtime::ModelInfo {
        &BLOWUP
    }
    fn engine(&self) -> gyro_sim::Engine {
        gyro_sim::Engine::Compiled
    }
    fn initial_state(&self) -> Vec<f64> {
        vec![0.0, 0.0]
    }
    fn default_params(&self) -> Vec<f64> {
        Vec::new()
    }
    fn solve(
        &self,
        problem: &gyro_sim::Problem,
        rows_to: Option<&gyro_sim::RowStream>,
    ) -> Result<gyro_sim::Trajectory, gyro_sim::SolveError> {
        gyro_sim::solve_bound(problem, self, rows_to)
    }
}

impl gyro_sim::BoundModel for Blowup {
    fn info(&self) -> &'static kane_model::runtime::ModelInfo {
        &BLOWUP
    }
    fn output(&self, _: usize, _: f64, _: &[f64], _: &[f64], _: &mut [f64]) {}
    fn output_rate(&self, _: usize, _: f64, _: &[f64], _: &[f64], _: &mut [f64], _: &mut [f64]) {}
}

#[test]
fn a_rate_turning_nan_in_a_fixed_step_run_is_named_with_the_time_and_the_state_where_it_did() {
    use gyro_sim::{tableau::RK4, Method};
    // The model a registry would hold for it.
    let model: gyro_sim::SharedModel = std::sync::Arc::new(Blowup);
    let problem = gyro_sim::Problem {
        title: "blowup".into(),
        model,
        params: Vec::new(),
        initial: vec![0.0, 0.0],
        times: (0..=20).map(|i| 0.1 * i as f64).collect(),
        plot_times: Vec::new(),
        dense_figures: false,
        method: Method::Fixed(&RK4, 0.01),
        max_steps: 1_000_000,
        accuracy: None,
        picks: vec![gyro_sim::Pick::State(0), gyro_sim::Pick::State(1)],
        written_picks: 2,
        unit_norms: Vec::new(),
        events: Vec::new(),
        view: None,
    };
    let error = gyro_sim::solve(&problem, None).unwrap_err().to_string();
    // Found again from the last good output (t = 1): the first stage past t = 1 of the step.
    assert!(error.contains("the rate of U is NaN at t = 1.005"), "{error}");
    assert!(error.contains("at the state Q = 0.40"), "{error}");
}

#[test]
fn rows_streamed_to_disk_are_the_bytes_written_at_once() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../gyro-sim/scenes");
    for preset in ["ejs/cusp.toml", "paper/trial3.toml"] {
        let text = std::fs::read_to_string(root.join(preset)).unwrap();
        // Without `accuracy` a run with a folder streams its rows (refinement keeps them).
        let text: String = text.lines().filter(|l| !l.starts_with("accuracy")).collect::<Vec<_>>().join("\n");
        let scene = gyro_sim::Scene::parse(preset, &text).unwrap();
        let dir = folder(&format!("streamed_{}", preset.replace('/', "_")));
        let streamed = gyro_sim::run(&scene, Some(&dir.join("streamed"))).unwrap();
        let at_once = gyro_sim::run(&scene, None).unwrap();
        gyro_sim::write(&at_once.trajectory, &dir.join("at_once")).unwrap();
        let read = |d: &str| std::fs::read(dir.join(d).join("trajectory.csv")).unwrap();
        assert!(read("streamed") == read("at_once"), "{preset}: the streamed CSV differs");
        assert_eq!(streamed.written.unwrap().rows, at_once.trajectory.rows.len());
    }
}
