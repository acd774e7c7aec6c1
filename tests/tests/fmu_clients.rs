//! The FMUs `kane fmu` builds, run by a real client (FMPy, from the Python registry; `tests/run`
//! installs it): each passes FMPy's validation, and FMPy's simulation of it, Model Exchange with
//! FMPy's own solver and Co-Simulation with the FMU's integrator, matches a tight `gyro-sim run`
//! of the same file; a parameter set through FMPy changes the run as `--set` does.

use std::path::{Path, PathBuf};
use std::process::Command;

use kane_tests::bins;
use kane_tests::runtimes::{self, succeeds};

fn scratch(name: &str) -> PathBuf {
    runtimes::scratch("kane-fmu", name)
}

/// A CSV's header and columns.
fn columns(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header: Vec<String> = lines.next().unwrap().split(',').map(str::to_string).collect();
    let mut cols = vec![Vec::new(); header.len()];
    for line in lines {
        for (j, v) in line.split(',').enumerate() {
            cols[j].push(v.parse::<f64>().unwrap());
        }
    }
    (header, cols)
}

/// The reference column of the FMU variable `name` in internal units (the simulator writes
/// angles in degrees).
fn reference_column(header: &[String], cols: &[Vec<f64>], name: &str) -> Vec<f64> {
    let lower = name.to_ascii_lowercase();
    let j = header
        .iter()
        .position(|h| *h == lower || h.starts_with(&format!("{lower}_")))
        .unwrap_or_else(|| panic!("no column for {name} in {header:?}"));
    let scale =
        if header[j].ends_with("_deg") || header[j].contains("_deg_") { 1f64.to_radians() } else { 1.0 };
    cols[j].iter().map(|v| v * scale).collect()
}

/// What one FMPy run is asked.
struct Client<'a> {
    kind: &'a str,
    rtol: &'a str,
    starts: &'a [&'a str],
}

/// The worst relative difference between FMPy's run of `fmu` and the simulator's of `model`.
fn difference(
    dir: &Path,
    model: &Path,
    fmu: &Path,
    names: &[&str],
    run: (f64, f64),
    client: &Client<'_>,
) -> f64 {
    let out = dir.join(format!("{}-{}.csv", client.kind, client.rtol));
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/fmpy_run.py");
    let mut python = Command::new("python3");
    python.arg(script).arg(fmu).arg(&out).args([
        client.kind,
        &run.0.to_string(),
        &run.1.to_string(),
        client.rtol,
    ]);
    succeeds(python.arg(names.join(",")).args(client.starts), "FMPy");
    let reference = dir.join(format!("reference-{}", client.starts.join("-")));
    let mut gyro = Command::new(bins::gyro_sim());
    gyro.args(["run", "--model"])
        .arg(model)
        .args(["--method", "vern9", "--rtol", "1e-13", "--atol", "1e-13"]);
    gyro.args(["--t-final", &run.0.to_string()]);
    client.starts.iter().for_each(|s| {
        gyro.args(["--set", s]);
    });
    succeeds(gyro.arg("--out").arg(&reference), "gyro-sim run");
    let (rh, rc) = columns(&reference.join("trajectory.csv"));
    let (_, got) = columns(&out);
    let mut worst: f64 = 0.0;
    for (j, name) in names.iter().enumerate() {
        let want = reference_column(&rh, &rc, name);
        assert_eq!(want.len(), got[j + 1].len(), "{name}: one row per output time ({})", out.display());
        let size = 1.0 + want.iter().map(|v| v.abs()).fold(0.0, f64::max);
        let diff = want.iter().zip(&got[j + 1]).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
        worst = worst.max(diff / size);
    }
    worst
}

fn build(dir: &Path, model_text: &str, name: &str) -> (PathBuf, PathBuf) {
    let model = dir.join(format!("{name}.al"));
    std::fs::write(&model, model_text).unwrap();
    let fmu = dir.join(format!("{name}.fmu"));
    succeeds(Command::new(bins::kane()).arg("fmu").arg(&model).arg("-o").arg(&fmu), "kane fmu");
    (model, fmu)
}

fn models_file(name: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../kane-model/models").join(name))
        .unwrap()
}

/// The FMU of `text` under FMPy's clients within `bounds.0` at FMPy's default tolerance (the
/// FMU's default experiment: a thousandth of the file's RELERR) and `bounds.1` at 1e-13,
/// Co-Simulation (the FMU's own integrator at the default experiment's tolerance) within
/// `bounds.0`.
fn fmpy_matches(name: &str, text: &str, names: &[&str], run: (f64, f64), bounds: (f64, f64)) {
    let dir = scratch(name);
    let (model, fmu) = build(&dir, text, name);
    for client in [
        Client { kind: "ModelExchange", rtol: "default", starts: &[] },
        Client { kind: "ModelExchange", rtol: "1e-13", starts: &[] },
        Client { kind: "CoSimulation", rtol: "default", starts: &[] },
        Client { kind: "CoSimulation", rtol: "1e-13", starts: &[] },
    ] {
        let bound = if client.rtol == "default" { bounds.0 } else { bounds.1 };
        let worst = difference(&dir, &model, &fmu, names, run, &client);
        eprintln!("{name}: {} at {}: worst relative difference {worst:.2e}", client.kind, client.rtol);
        assert!(
            worst <= bound,
            "{name}: {} at {} is {worst:e} off (bound {bound:e})",
            client.kind,
            client.rtol
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_gimbal_fmu_validates_and_runs_in_fmpy_as_the_simulator_does() {
    let names = ["Q1", "Q2", "Q3", "U1", "U2", "U3", "AP"];
    fmpy_matches("gimbal", &models_file("gimbal_gyroscope.al"), &names, (5.0, 0.05), (1e-6, 1e-9));
}

#[test]
fn the_bicycle_fmu_with_its_constraint_solve_runs_in_fmpy() {
    let text = models_file("whipple_bicycle.al")
        .replace("INPUT V = 0", "INPUT V = 5")
        .replace("U2 = 0,", "U2 = 0.5,");
    let text = format!("{text}\nINPUT INTEGSTP = 0.05\n");
    fmpy_matches("bicycle", &text, &["Q2", "Q5", "ENERGY"], (3.0, 0.05), (1e-6, 1e-9));
}

#[test]
fn a_parameter_set_through_fmpy_changes_the_run() {
    let dir = scratch("parameter");
    let (model, fmu) = build(&dir, &models_file("gimbal_gyroscope.al"), "gimbal");
    let names = ["Q1", "Q2", "U3"];
    let set = Client { kind: "ModelExchange", rtol: "1e-10", starts: &["Z=0", "Y=10"] };
    let worst = difference(&dir, &model, &fmu, &names, (2.0, 0.05), &set);
    assert!(worst <= 1e-7, "with Z = 0 and Y = 10 set in FMPy: {worst:e} off the simulator's run with --set");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_file_without_values_is_refused_naming_them() {
    let dir = scratch("novalue");
    let text = models_file("gimbal_gyroscope.al").replace("INPUT L = .3, ", "INPUT ");
    let model = dir.join("g.al");
    std::fs::write(&model, text).unwrap();
    let out = Command::new(bins::kane()).arg("fmu").arg(&model).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(stderr.contains("no value for L") && stderr.contains("INPUT"), "{stderr}");
    assert!(!dir.join("gimbal_gyroscope.fmu").exists() && !dir.join("g.fmu").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
