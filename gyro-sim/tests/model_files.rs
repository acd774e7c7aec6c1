//! A user's own model file, run as a user would with the `gyro-sim` command: `--model` without
//! a scene and scenes naming a file, on the instant path (the lowered program evaluated) and on
//! the compiled path (a cached binary, built once per file version). The instant path equals
//! the built-in compiled gimbal; a variant gimbal (rotor offset, gravity, flipped axis) runs;
//! files that do not exist, do not check, or values that are implausible are errors.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const PAPER: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/models/gimbal_gyroscope.al");
const VARIANT: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/variant_gimbal.al");
const CHAIN40: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/chain40_rigid.al");
const DISC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/rolling_disc.al");
const BICYCLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/models/whipple_bicycle.al");
const FOUR_BAR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/models/four_bar.al");
const PRESCRIBED: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/tests/data/prescribed_elbow.al");
const DISC_CONTACT: &str =
    concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/tests/data/rolling_disc_contact.al");
const STALLING: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/stalling_slider.al");
const DOUBLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/double_pendulum.al");

/// A fresh folder for one test.
fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("model_files").join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// `gyro-sim run ARGS`, with the compiled models cached in `cache`.
fn gyro_sim(args: &[&str], cache: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .arg("run")
        .args(args)
        .env("GYRO_SIM_CACHE", cache.join("cache"))
        .env("GYRO_SIM_TARGET_DIR", Path::new(env!("CARGO_TARGET_TMPDIR")).join("compiled-models"))
        // The workspace's `model-test` profile (unoptimised, no debug information): the build
        // (every dependency, in a target folder of its own) takes a fraction of a release
        // build's time; what is tested does not depend on it.
        .env("GYRO_SIM_MODEL_PROFILE", "model-test")
        .output()
        .unwrap()
}

fn text(o: &Output) -> String {
    format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr))
}

/// The CSV's rows as numbers.
fn rows(dir: &Path) -> Vec<Vec<f64>> {
    let csv = std::fs::read_to_string(dir.join("trajectory.csv")).unwrap();
    csv.lines().skip(1).map(|l| l.split(',').map(|x| x.parse().unwrap()).collect()).collect()
}

/// The data a run's `view.html` embeds (`t`, the columns the view reads, the view).
fn view_data(dir: &Path) -> serde_json::Value {
    let page = std::fs::read_to_string(dir.join("view.html")).unwrap();
    let start = r#"<script id="view-data" type="application/json">"#;
    let json = page.split_once(start).unwrap().1.split_once("</script>").unwrap().0;
    serde_json::from_str(json).unwrap()
}

/// The view data's column `name`.
fn view_column(data: &serde_json::Value, name: &str) -> Vec<f64> {
    let column = data["columns"][name].as_array().unwrap_or_else(|| panic!("no column {name}"));
    column.iter().map(|x| x.as_f64().unwrap()).collect()
}

#[test]
fn a_model_run_draws_its_frames_and_points_where_its_coordinates_put_them() {
    let dir = folder("drawing");
    let out = dir.join("out");
    let run = gyro_sim(&["--model", DOUBLE, "--engine", "instant", "--out", out.to_str().unwrap()], &dir);
    assert!(run.status.success(), "{}", text(&run));
    let csv = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    assert!(csv.starts_with("t,q1,q2\n"), "the drawing's columns stay out of the CSV: {}", &csv[..40]);
    let data = view_data(&out);
    let view = &data["view"];
    assert_eq!((view["up"].as_i64(), view["frame"].as_str()), (Some(2), Some("N")), "gravity along -N2");
    let bodies: Vec<(&str, &str, &str)> = view["bodies"]
        .as_array()
        .unwrap()
        .iter()
        .map(|b| {
            (
                b["name"].as_str().unwrap(),
                b["shape"]["kind"].as_str().unwrap(),
                b["position"][0].as_str().unwrap(),
            )
        })
        .collect();
    assert_eq!(
        bodies,
        [
            ("A", "axes", "P_O_AO_N1"),
            ("B", "axes", "P_O_BO_N1"),
            ("A (inertia)", "ellipsoid", "P_O_AO_N1"),
            ("B (inertia)", "ellipsoid", "P_O_BO_N1")
        ]
    );
    let joined: Vec<(&str, Option<&str>)> = view["points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p["name"].as_str().unwrap(), p["from"].as_str()))
        .collect();
    assert_eq!(joined, [("AO", Some("O")), ("BO", Some("P")), ("O", None), ("P", Some("O"))]);
    // Against the run's own coordinates, by hand (L = 1): BO is at A1 + B1/2, B turned by q1 + q2.
    let rows = rows(&out);
    let (x, y, z) =
        (view_column(&data, "P_O_BO_N1"), view_column(&data, "P_O_BO_N2"), view_column(&data, "P_O_BO_N3"));
    let (b11, b21) = (view_column(&data, "N_B_11"), view_column(&data, "N_B_21"));
    assert_eq!(rows.len(), x.len());
    for (k, row) in rows.iter().enumerate() {
        let (q1, q12) = (row[1], row[1] + row[2]);
        let hand = [q1.cos() + 0.5 * q12.cos(), q1.sin() + 0.5 * q12.sin(), 0.0, q12.cos(), q12.sin()];
        let drawn = [x[k], y[k], z[k], b11[k], b21[k]];
        for (d, h) in drawn.iter().zip(hand) {
            assert!((d - h).abs() < 1e-12, "row {k}: drawn {drawn:?}, by hand {hand:?}");
        }
    }
}

/// The semi-axes, orientation and position columns of the view's body `name`.
fn ellipsoid(view: &serde_json::Value, name: &str) -> ([f64; 3], String, String) {
    let body = view["bodies"].as_array().unwrap().iter().find(|b| b["name"] == name);
    let body = body.unwrap_or_else(|| panic!("no body {name}: {}", view["bodies"]));
    assert_eq!(body["shape"]["kind"], "ellipsoid", "{body}");
    assert!(body["opacity"].as_f64().unwrap() < 0.6 && body["turn"].is_null(), "{body}");
    let semi = ["a", "b", "c"].map(|k| body["shape"][k].as_f64().unwrap());
    let column = |v: &serde_json::Value| v.as_str().unwrap().to_string();
    (semi, column(&body["orientation"]["dcm"][0]), column(&body["position"][0]))
}

#[test]
fn each_gimbal_body_is_drawn_as_the_ellipsoid_of_its_inertia_sized_by_the_run_s_values() {
    let dir = folder("gimbal_ellipsoids");
    let run = |out: &Path, set: &[&str]| {
        let mut args = vec!["--model", PAPER, "--engine", "instant", "--t-final", "0.1"];
        args.extend_from_slice(set);
        args.extend(["--out", out.to_str().unwrap()]);
        let run = gyro_sim(&args, &dir);
        assert!(run.status.success(), "{}", text(&run));
        view_data(out)["view"].clone()
    };
    // The file's INPUT values: L = .3, W = .025, H1 = .6, H2 = .5, H3 = .4, M1 = M2 = 2, M3 = 50.
    let (l, w) = (0.3, 0.025);
    // a^2 = 5/(2m) (I2 + I3 - I1) and cyclically, for moments (I1, I2, I3).
    let semi = |m: f64, [i1, i2, i3]: [f64; 3]| {
        [i2 + i3 - i1, i3 + i1 - i2, i1 + i2 - i3].map(|s: f64| (2.5 / m * s).sqrt())
    };
    let gimbal = |m: f64, h: f64| {
        let (i1, i2) = (2.0 / 3.0 * m * (h * w - w * w), m / 6.0 * (h * h - (h - w) * (h - w)));
        semi(m, [i1, i1, i2])
    };
    let rotor = |h3: f64| {
        let (k1, k2) = (0.5 * 50.0 * l * l, 0.25 * 50.0 * l * l + 50.0 * h3 * h3 / 12.0);
        semi(50.0, [k2, k1, k2])
    };
    let close = |got: [f64; 3], want: [f64; 3]| {
        assert!(got.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-12), "{got:?} against {want:?}");
    };
    let view = run(&dir.join("file"), &[]);
    for (name, frame, want) in
        [("B", "A_B", gimbal(2.0, 0.6)), ("C", "A_C", gimbal(2.0, 0.5)), ("D", "A_D", rotor(0.4))]
    {
        let (got, dcm, position) = ellipsoid(&view, &format!("{name} (inertia)"));
        close(got, want);
        assert_eq!((dcm, position), (format!("{frame}_11"), format!("P_O_{name}O_A1")), "body {name}");
    }
    // The rotor's semi-axes by hand: sqrt(0.05 K1) along D1 and D3, sqrt(0.05 (2 K2 - K1)) along D2.
    close(
        rotor(0.4),
        [0.1125f64.sqrt(), (0.05 * (2.0 * (1.125 + 0.8 / 1.2) - 2.25f64)).sqrt(), 0.1125f64.sqrt()],
    );
    let set = run(&dir.join("set"), &["--set", "H3=0.8"]);
    let (got, _, _) = ellipsoid(&set, "D (inertia)");
    close(got, rotor(0.8));
    assert!(got[1] > 1.5 * rotor(0.4)[1], "a longer rotor is drawn longer: {got:?}");
}

#[test]
fn without_a_view_the_drawing_is_neither_asked_for_nor_written() {
    let dir = folder("no_view");
    let out = dir.join("out");
    let printed = gyro_sim(&["--model", DOUBLE, "--print-scene"], &dir);
    assert!(text(&printed).contains("[view]\ndraw_model = true\n"), "{}", text(&printed));
    let printed = gyro_sim(&["--model", DOUBLE, "--print-scene", "--no-view"], &dir);
    assert!(printed.status.success() && !text(&printed).contains("[view]"), "{}", text(&printed));
    let run = gyro_sim(
        &["--model", DOUBLE, "--engine", "instant", "--no-view", "--out", out.to_str().unwrap()],
        &dir,
    );
    assert!(run.status.success(), "{}", text(&run));
    assert!(out.join("trajectory.csv").is_file() && !out.join("view.html").exists());
}

#[test]
fn the_printed_scene_holds_every_value_and_runs_as_the_model_file_does() {
    let dir = folder("printed_scene");
    // Named relative to the working folder (the package's, in tests), as a user types it.
    let relative = "tests/data/double_pendulum.al";
    assert!(Path::new(relative).is_file());
    let printed = gyro_sim(&["--model", relative, "--print-scene", "--set", "Q2=10 deg"], &dir);
    let scene = text(&printed);
    for line in ["L = 1.0", "G = 9.81", "M = 1.0", "Q1 = -1.2", "Q2 = \"10 deg\"", "U1 = 0.0", "U2 = 0.0"] {
        assert!(scene.contains(&format!("\n{line}\n")), "`{line}` missing:\n{scene}");
    }
    // Saved in another folder, the scene still finds the model file.
    assert!(scene
        .contains(&format!("model = {:?}", std::fs::canonicalize(DOUBLE).unwrap().display().to_string())));
    let saved = dir.join("saved.toml");
    std::fs::write(&saved, &scene).unwrap();
    let (from_file, from_scene) = (dir.join("file"), dir.join("scene"));
    let run = gyro_sim(
        &[
            "--model",
            DOUBLE,
            "--set",
            "Q2=10 deg",
            "--engine",
            "instant",
            "--out",
            from_file.to_str().unwrap(),
        ],
        &dir,
    );
    assert!(run.status.success(), "{}", text(&run));
    let run = gyro_sim(
        &[saved.to_str().unwrap(), "--engine", "instant", "--out", from_scene.to_str().unwrap()],
        &dir,
    );
    assert!(run.status.success(), "{}", text(&run));
    assert_eq!(rows(&from_file), rows(&from_scene));
}

#[test]
fn the_energy_line_is_the_total_where_gravity_is_the_only_load_and_kinetic_elsewhere() {
    let dir = folder("energy_line");
    let out = dir.join("out");
    let out = out.to_str().unwrap();
    let summary =
        text(&gyro_sim(&["--model", DOUBLE, "--engine", "instant", "--no-view", "--out", out], &dir));
    let total = summary.split("total energy (kinetic + gravity's potential) ").nth(1).expect(&summary);
    let numbers: Vec<f64> = total.split([' ', ';', '(', ')']).filter_map(|w| w.parse().ok()).collect();
    // -1.5625e1 -> -1.5625e1 (change ...): the pendulum keeps its total energy.
    let (start, end) = (numbers[0], numbers[1]);
    assert!(start < -1.0 && ((end - start) / start).abs() < 1e-8, "{summary}");
    // A torque besides gravity: the potential is not the loads', so only the kinetic energy.
    let driven = dir.join("driven.al");
    let source = std::fs::read_to_string(DOUBLE).unwrap();
    std::fs::write(
        &driven,
        source.replace("ZERO = FR() + FRSTAR()", "TORQUE_A> = 0.1*N3>\nZERO = FR() + FRSTAR()"),
    )
    .unwrap();
    let summary = text(&gyro_sim(
        &["--model", driven.to_str().unwrap(), "--engine", "instant", "--no-view", "--out", out],
        &dir,
    ));
    assert!(summary.contains("; kinetic energy ") && !summary.contains("total energy"), "{summary}");
}

#[test]
fn figures_are_dense_unless_plot_points_asks_for_the_rows_alone_which_is_noted() {
    let dir = folder("plot_points");
    let sparse = dir.join("sparse.al");
    let source = std::fs::read_to_string(DOUBLE).unwrap();
    std::fs::write(&sparse, source.replace("INTEGSTP = 0.01", "INTEGSTP = 0.5")).unwrap();
    let sparse = sparse.to_str().unwrap();
    let out = dir.join("out");
    let out = out.to_str().unwrap();
    // Without --plot-points the figures come from the dense output: nothing to note.
    let auto = gyro_sim(&["--model", sparse, "--engine", "instant", "--no-view", "--out", out], &dir);
    assert!(auto.status.success() && !text(&auto).contains("note:"), "{}", text(&auto));
    let rows_only = text(&gyro_sim(
        &["--model", sparse, "--engine", "instant", "--no-view", "--plot-points", "1", "--out", out],
        &dir,
    ));
    assert!(
        rows_only.contains("integrator steps per output row: the figures, drawn from the rows alone"),
        "{rows_only}"
    );
    let dense = gyro_sim(
        &["--model", sparse, "--engine", "instant", "--no-view", "--plot-points", "10", "--out", out],
        &dir,
    );
    assert!(dense.status.success() && !text(&dense).contains("note:"), "{}", text(&dense));
    let printed = text(&gyro_sim(&["--model", sparse, "--plot-points", "10", "--print-scene"], &dir));
    assert!(printed.contains("\nplot_points = 10\n"), "{printed}");
    let refused = gyro_sim(&["--model", sparse, "--plot-points", "0", "--print-scene"], &dir);
    assert!(!refused.status.success() && text(&refused).contains("--plot-points"), "{}", text(&refused));
}

#[test]
fn a_variable_without_an_equation_is_an_open_input_and_its_point_is_drawn() {
    // H is a variable with no equation: an input of the model, zero in this run, said so.
    let dir = folder("undrawable");
    let model = dir.join("undrawable.al");
    let source = std::fs::read_to_string(DOUBLE).unwrap();
    std::fs::write(
        &model,
        source.replace("OUTPUT Q1, Q2", "VARIABLES H\nPOINTS Q\nP_O_Q> = H*N1>\nOUTPUT Q1, Q2"),
    )
    .unwrap();
    let out = dir.join("out");
    let run = gyro_sim(
        &["--model", model.to_str().unwrap(), "--engine", "instant", "--out", out.to_str().unwrap()],
        &dir,
    );
    assert!(run.status.success(), "{}", text(&run));
    assert!(text(&run).contains("warning: H is an input the model leaves open"), "{}", text(&run));
    assert!(out.join("trajectory.csv").is_file() && out.join("view.html").is_file());
}

#[test]
fn a_scene_drawing_the_model_without_outputs_writes_no_drawing_columns() {
    let dir = folder("drawn_scene");
    std::fs::copy(DOUBLE, dir.join("double_pendulum.al")).unwrap();
    let scene = dir.join("scene.toml");
    let text_of_scene =
        "model = \"double_pendulum.al\"\nt_final = 1.0\noutput_step = 0.1\n\n[view]\ndraw_model = true\n";
    std::fs::write(&scene, text_of_scene).unwrap();
    let out = dir.join("out");
    let run =
        gyro_sim(&[scene.to_str().unwrap(), "--engine", "instant", "--out", out.to_str().unwrap()], &dir);
    assert!(run.status.success(), "{}", text(&run));
    let csv = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    let header = csv.lines().next().unwrap().to_ascii_uppercase();
    assert!(
        header.starts_with("T,Q1,Q2,U1,U2") && !header.contains("P_O_") && !header.contains("N_A"),
        "{header}"
    );
    assert!(view_data(&out)["columns"]["P_O_BO_N1"].is_array());
}

#[test]
fn a_forty_link_chain_swings_with_its_energy_kept() {
    // The order-n form on the instant engine: a 40-link chain falls from 0.1 rad for 2 s.
    let dir = folder("chain40");
    let out = dir.join("out");
    let args = ["--model", CHAIN40, "--engine", "instant", "--t-final", "2", "--out", out.to_str().unwrap()];
    let run = gyro_sim(&args, &dir);
    assert!(run.status.success() && text(&run).contains("ran instant"), "{}", text(&run));
    let rows = rows(&out);
    let (e0, q40) = (rows[0][1], rows.last().unwrap()[3]);
    let drift = rows.iter().map(|r| (r[1] - e0).abs()).fold(0.0, f64::max) / e0.abs();
    // Tolerances 1e-10: the energy holds to that over the swing, and the chain moved.
    assert!(drift < 1e-9, "energy drift {drift:e}");
    assert!((q40 - 0.1).abs() > 1e-3, "the last link did not move: {q40}");
}

#[test]
fn a_rolling_disc_keeps_its_energy_and_its_contact_speeds() {
    // Two no-slip constraints, solved numerically at every evaluation, from upright (Q2 = 0).
    let dir = folder("rolling_disc");
    let out = dir.join("out");
    let run = gyro_sim(&["--model", DISC, "--engine", "instant", "--out", out.to_str().unwrap()], &dir);
    assert!(run.status.success() && text(&run).contains("ran instant"), "{}", text(&run));
    let rows = rows(&out);
    let e0 = rows[0][1];
    let drift = rows.iter().map(|r| (r[1] - e0).abs()).fold(0.0, f64::max) / e0.abs();
    assert!(drift < 1e-8, "energy drift {drift:e}");
    // The dependent speed is the rolling one: U4 = R cos(Q1) U3 (R = 0.5).
    for r in &rows {
        let (q1, u3, u4) = (r[2], r[3], r[4]);
        assert!((u4 - 0.5 * q1.cos() * u3).abs() < 1e-12, "{r:?}");
    }
    assert!(rows.len() > 10 && (rows.last().unwrap()[2] - 0.3).abs() > 0.1, "the disc did not turn");
}

/// The two residuals of a summary line `... largest residual A at the start, B at the output
/// times` (or one, `... B at the output times`).
fn residuals(summary: &str, prefix: &str) -> Vec<f64> {
    let line = summary
        .lines()
        .find(|l| l.starts_with(prefix))
        .unwrap_or_else(|| panic!("no {prefix} line in {summary}"));
    let tail = line.split("largest residual ").nth(1).unwrap();
    tail.split(", ").map(|part| part.split(' ').next().unwrap().parse().unwrap()).collect()
}

#[test]
fn a_four_bar_loop_starts_assembled_and_keeps_its_loop_closed() {
    // Q2 and Q3 in the file (0.3, 1.7) do not close the loop: the run solves them for the
    // crank angle Q1 = 1.2, then integrates with the residuals reported.
    let dir = folder("four_bar");
    let out = dir.join("out");
    let run = gyro_sim(&["--model", FOUR_BAR, "--engine", "instant", "--out", out.to_str().unwrap()], &dir);
    let summary = text(&run);
    assert!(run.status.success(), "{summary}");
    assert!(summary.contains("configuration constraints: the start assembled by"), "{summary}");
    let config = residuals(&summary, "configuration constraints:");
    assert!(config[0] < 1e-14 && config[1] < 1e-8, "{config:?}");
    let motion = residuals(&summary, "motion constraints:");
    assert!(motion[0] < 1e-12, "{motion:?}");
    // The start against the loop closed by hand: the coupler's far end on the circle of
    // radius LC about D (LA = 1, LB = 2.5, LC = 2, LD = 2.5).
    let rows = rows(&out);
    let (q1, q2, q3) = (rows[0][1], rows[0][2], rows[0][3]);
    assert_eq!(q1, 1.2);
    let end = (q1.cos() + 2.5 * q2.cos(), q1.sin() + 2.5 * q2.sin());
    let rocker = (2.5 + 2.0 * q3.cos(), 2.0 * q3.sin());
    assert!((end.0 - rocker.0).abs() < 1e-14 && (end.1 - rocker.1).abs() < 1e-14, "{end:?} {rocker:?}");
    // Columns: t, Q1, Q2, Q3, U2, U3, ENERGY; tolerances 1e-10.
    let e0 = rows[0][6];
    let drift = rows.iter().map(|r| (r[6] - e0).abs()).fold(0.0, f64::max) / e0.abs();
    assert!(drift < 1e-8, "energy drift {drift:e}");
    assert!((rows.last().unwrap()[1] - q1).abs() > 0.5, "the crank did not turn");
}

#[test]
fn a_loop_that_cannot_close_is_an_error_that_says_so() {
    let dir = folder("four_bar_open");
    let file = dir.join("open.al");
    let text_of = std::fs::read_to_string(FOUR_BAR).unwrap().replace("LD = 2.5", "LD = 9");
    std::fs::write(&file, text_of).unwrap();
    let out = dir.join("out");
    let run = gyro_sim(
        &["--model", file.to_str().unwrap(), "--engine", "instant", "--out", out.to_str().unwrap()],
        &dir,
    );
    let message = text(&run);
    assert!(!run.status.success(), "{message}");
    assert!(message.contains("the configuration constraints") && message.contains("Q2, Q3"), "{message}");
    assert!(!out.join("trajectory.csv").exists(), "no rows for a run that cannot start");
}

#[test]
fn constraints_near_rank_loss_are_a_warning_and_at_rank_loss_an_error() {
    let dir = folder("stalling");
    let out = dir.join("out");
    let run = |extra: &[&str]| {
        let mut args = vec!["--model", STALLING, "--engine", "instant", "--out", out.to_str().unwrap()];
        args.extend(extra);
        gyro_sim(&args, &dir)
    };
    // Away from Q1 = pi/2 the matrix of dependent speeds is well conditioned.
    let early = run(&["--t-final", "2"]);
    let message = text(&early);
    assert!(early.status.success(), "{message}");
    assert!(message.contains("reciprocal condition") && !message.contains("warning"), "{message}");
    // Creeping towards it: rows are written, with a warning that names when and where.
    let late = run(&["--t-final", "20"]);
    let message = text(&late);
    assert!(late.status.success(), "{message}");
    assert!(
        message.contains("warning: the motion constraints came near rank loss at t = 20, Q1 = 1.5707"),
        "{message}"
    );
    // Q2 and Q3 are cyclic (nothing reads them; not integrated here): not part of a configuration.
    assert!(!message.contains("Q2 = "), "{message}");
    // At it: no rows, the cause named.
    std::fs::remove_dir_all(&out).unwrap();
    let at = run(&["--set", "Q1=1.5707963267948966"]);
    let message = text(&at);
    assert!(!at.status.success(), "{message}");
    assert!(
        message.contains("the motion constraints lose rank at t = 0, Q1 = 1.5707963267948966"),
        "{message}"
    );
    assert!(!out.join("trajectory.csv").exists(), "no rows for a run that cannot start");
}

#[test]
fn the_torque_solved_for_a_prescribed_elbow_puts_in_the_energy_the_pendulum_gains() {
    let dir = folder("prescribed_elbow");
    let out = dir.join("out");
    let run = gyro_sim(
        &["--model", PRESCRIBED, "--engine", "instant", "--t-final", "3", "--out", out.to_str().unwrap()],
        &dir,
    );
    assert!(run.status.success(), "{}", text(&run));
    let rows = rows(&out);
    let header = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    assert!(header.starts_with("t,q1,u1,etor,energy,power"), "{header}");
    // The shoulder is free: the energy changes by the work of the elbow torque, ETOR * EA'
    // integrated by Simpson's rule over the rows.
    let h = rows[1][0] - rows[0][0];
    let n = rows.len() - 1;
    assert!(n.is_multiple_of(2) && n >= 100);
    let weight = |i: usize| {
        if i == 0 || i == n {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        }
    };
    let work: f64 = rows.iter().enumerate().map(|(i, r)| weight(i) * r[5]).sum::<f64>() * h / 3.0;
    let gained = rows[n][4] - rows[0][4];
    assert!(gained.abs() > 0.5, "the torque does work: {gained}");
    assert!((gained - work).abs() < 1e-6, "energy gained {gained} vs work {work}");
}

#[test]
fn the_rolling_disc_s_contact_force_is_what_newton_s_second_law_asks() {
    let dir = folder("disc_contact");
    let out = dir.join("out");
    let run = gyro_sim(
        &["--model", DISC_CONTACT, "--engine", "instant", "--t-final", "3", "--out", out.to_str().unwrap()],
        &dir,
    );
    assert!(run.status.success(), "{}", text(&run));
    // Columns: t, Q2, FC1..3, then m a - m g of the mass centre (from the rates), NEWTON1..3.
    let rows = rows(&out);
    let gap = rows.iter().flat_map(|r| (0..3).map(move |i| (r[2 + i] - r[5 + i]).abs())).fold(0.0, f64::max);
    eprintln!("contact force against Newton's second law: at most {gap:.1e}");
    for r in rows {
        for i in 0..3 {
            assert!((r[2 + i] - r[5 + i]).abs() < 1e-12 * r[5 + i].abs().max(1.0), "at t = {}: {r:?}", r[0]);
        }
        assert!(r[4] > 0.0, "the plane pushes up: {r:?}");
    }
}

#[test]
fn a_prescribed_motion_read_from_a_table_follows_the_formula_it_samples() {
    let dir = folder("table_elbow");
    // The prescribed elbow without its formula: the scene gives EA as a table of its values.
    let file = dir.join("swing.al");
    let source = std::fs::read_to_string(PRESCRIBED).unwrap();
    std::fs::write(&file, source.replace("EA = AMP*SIN(W*T)", "% EA from the scene")).unwrap();
    let mut csv = String::from("t,ea\n");
    for k in 0..=120 {
        let t = 3.0 * f64::from(k) / 120.0;
        csv.push_str(&format!("{t},{}\n", 0.5 * (2.0 * t).sin()));
    }
    std::fs::write(dir.join("swing.csv"), csv).unwrap();
    let scene = |model: &str, t_final: f64, specified: &str| {
        format!(
            "model = \"{model}\"\nt_final = {t_final}\noutput_step = 0.05\noutputs = [\"Q1\", \"ETOR\"]\n\
             [integrator]\nmethod = \"dop853\"\nrtol = 1e-10\natol = 1e-10\n{specified}"
        )
    };
    let run = |name: &str, text_of: String| {
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, text_of).unwrap();
        let out = dir.join(name);
        let run =
            gyro_sim(&[path.to_str().unwrap(), "--engine", "instant", "--out", out.to_str().unwrap()], &dir);
        (run.status.success(), text(&run), out)
    };
    let (ok, message, formula_out) = run("formula", scene(PRESCRIBED, 3.0, ""));
    assert!(ok, "{message}");
    let table = "[specified]\nEA = { table = \"swing.csv\" }\n";
    let (ok, message, table_out) = run("table", scene(file.to_str().unwrap(), 3.0, table));
    assert!(ok, "{message}");
    let (exact, splined) = (rows(&formula_out), rows(&table_out));
    let largest =
        |col: usize| exact.iter().zip(&splined).map(|(a, b)| (a[col] - b[col]).abs()).fold(0.0, f64::max);
    // The spline's acceleration is second order in the row spacing (0.025 s): measured 2.3e-7 and
    // 8.5e-5 (of 6.5 N m).
    eprintln!("table against formula: Q1 {:.1e}, ETOR {:.1e}", largest(1), largest(2));
    assert!(largest(1) < 1e-6 && largest(2) < 1e-3, "Q1 {:e}, ETOR {:e}", largest(1), largest(2));
    assert!(largest(2) > 0.0, "the table is not the formula");
    let (ok, message, _) = run("short", scene(file.to_str().unwrap(), 4.0, table));
    assert!(
        !ok && message.contains("the table covers t = 0 to 3 s but the run goes from 0 to 4 s"),
        "{message}"
    );
}

#[test]
fn a_scene_gives_the_torque_a_file_leaves_specified() {
    let dir = folder("specified");
    let file = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/driven_pendulum.al");
    let scene = |torque: &str| {
        format!(
            "model = \"{file}\"\nt_final = 4.0\noutput_step = 0.1\noutputs = [\"Q\", \"U\", \"ENERGY\"]\n\
             [integrator]\nmethod = \"dop853\"\nrtol = 1e-10\natol = 1e-10\n[specified]\nT = \"{torque}\"\n"
        )
    };
    let energy = |name: &str, torque: &str| {
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, scene(torque)).unwrap();
        let out = dir.join(name);
        let run =
            gyro_sim(&[path.to_str().unwrap(), "--engine", "instant", "--out", out.to_str().unwrap()], &dir);
        assert!(run.status.success(), "{}", text(&run));
        rows(&out).iter().map(|r| r[3]).collect::<Vec<f64>>()
    };
    // A spring torque: the energy (with the spring's) is conserved; with a damper it only falls.
    let spring = energy("spring", "-K*Q");
    let drift = spring.iter().map(|e| (e - spring[0]).abs()).fold(0.0, f64::max) / spring[0].abs();
    assert!(drift < 1e-8, "energy drift {drift:e}");
    let damped = energy("damped", "-K*Q - C*U");
    assert!(damped.windows(2).all(|w| w[1] <= w[0] + 1e-9), "{damped:?}");
    assert!(damped.last().unwrap() < &(0.5 * damped[0]), "{damped:?}");
    // Without a formula the torque is zero, and the run says so and how to give it.
    let out = dir.join("none");
    let run = gyro_sim(&["--model", file, "--engine", "instant", "--out", out.to_str().unwrap()], &dir);
    assert!(run.status.success() && text(&run).contains("[specified] T ="), "{}", text(&run));
    // A compiled model has no SPECIFIED quantities to give.
    let builtin = dir.join("builtin.toml");
    std::fs::write(
        &builtin,
        "model = \"gimbal_gyroscope\"\nt_final = 1.0\noutput_step = 0.1\n[specified]\nT = \"1\"\n",
    )
    .unwrap();
    let run = gyro_sim(&[builtin.to_str().unwrap(), "--out", dir.join("b").to_str().unwrap()], &dir);
    assert!(!run.status.success() && text(&run).contains("is a compiled model"), "{}", text(&run));
}

#[test]
fn the_bicycle_rides_self_stable_at_5_m_per_s_and_capsizes_at_8_with_its_energy_kept() {
    // A push in roll rate (U2 = 0.5 rad/s) from upright straight running at the speed V: the
    // two scenes that ride the model file, and the same through --model with --set.
    for (v, stable, scene) in [(5.0, true, "self_stable"), (8.0, false, "capsize")] {
        let dir = folder(&format!("bicycle_{v}"));
        let out = dir.join("out");
        let scene = format!("{}/scenes/bicycle/{scene}.toml", env!("CARGO_MANIFEST_DIR"));
        let run = gyro_sim(&[&scene, "--engine", "instant", "--out", out.to_str().unwrap()], &dir);
        assert!(run.status.success(), "{}", text(&run));
        assert!(
            text(&run).contains("configuration constraints: the initial state satisfies them"),
            "{}",
            text(&run)
        );
        let speed = format!("V={v}");
        let args = ["--model", BICYCLE, "--engine", "instant", "--set", &speed, "--set", "U2=0.5"];
        let same = dir.join("same");
        let again = gyro_sim(&[&args[..], &["--out", same.to_str().unwrap()]].concat(), &dir);
        assert!(again.status.success(), "{}", text(&again));
        assert_eq!(rows(&out), rows(&same), "the scene is the --model run");
        let rows = rows(&out);
        // Columns: t, Q2 (roll), Q5 (steer), ENERGY.
        let e0 = rows[0][3];
        let drift = rows.iter().map(|r| (r[3] - e0).abs()).fold(0.0, f64::max) / e0.abs();
        assert!(drift < 1e-9, "v = {v}: energy drift {drift:e}");
        let peak = rows.iter().map(|r| r[1].abs()).fold(0.0, f64::max);
        let last = rows.last().unwrap()[1].abs();
        if stable {
            assert!(last < 0.5 * peak, "v = {v}: roll {last} after a peak of {peak}");
        } else {
            assert!(last >= peak * 0.999 && last > 0.05, "v = {v}: roll {last}, peak {peak}");
        }
    }
}

#[test]
fn the_instant_path_equals_the_built_in_model() {
    let dir = folder("instant_vs_builtin");
    let scene = dir.join("trial.toml");
    let body = "t_final = 2.0\noutput_step = 0.1\noutputs = [\"Q1\", \"Q2\", \"U1\", \"U2\", \"U3\", \"AP\"]\n[integrator]\nmethod = \"dop853\"\nrtol = 1e-10\natol = 1e-10\n[parameters]\nY = 10.0\nZ = 10.0\n[initial]\nU3 = \"100 rad/s\"\n";
    std::fs::write(&scene, format!("model = \"gimbal_gyroscope\"\n{body}")).unwrap();
    let built_in = gyro_sim(&[scene.to_str().unwrap(), "--out", dir.join("a").to_str().unwrap()], &dir);
    assert!(built_in.status.success(), "{}", text(&built_in));
    std::fs::write(&scene, format!("model = {PAPER:?}\n{body}")).unwrap();
    let b_dir = dir.join("b");
    let args = [scene.to_str().unwrap(), "--engine", "instant", "--out", b_dir.to_str().unwrap()];
    let instant = gyro_sim(&args, &dir);
    assert!(instant.status.success(), "{}", text(&instant));
    assert!(text(&instant).contains("model gimbal_gyroscope ran instant"), "{}", text(&instant));
    let (a, b) = (rows(&dir.join("a")), rows(&dir.join("b")));
    assert_eq!(a.len(), 21);
    let worst = a.iter().flatten().zip(b.iter().flatten()).map(|(x, y)| (x - y).abs() / x.abs().max(1.0));
    let worst = worst.fold(0.0, f64::max);
    assert!(worst < 1e-12, "instant vs built-in: {worst:e}");
}

#[test]
fn a_variant_runs_in_one_command_with_its_file_settings_and_sets() {
    let dir = folder("variant");
    let out = dir.join("out");
    let run = gyro_sim(
        &[
            "--model",
            VARIANT,
            "--engine",
            "instant",
            "--set",
            "OFF=0.1",
            "--t-final",
            "1",
            "--out",
            out.to_str().unwrap(),
        ],
        &dir,
    );
    assert!(run.status.success(), "{}", text(&run));
    let r = rows(&out);
    // INTEGSTP 0.05 to the asked t-final; OUTPUT columns (T, the states, AP, the frames).
    assert_eq!(r.len(), 21);
    assert_eq!(r[20][0], 1.0);
    let header = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
    assert!(header
        .starts_with("t,q1_deg,q2_deg,q3_deg,u1_rad_per_s,u2_rad_per_s,u3_rad_per_s,ap_m_per_s2,a_b_11"));
    assert!(r.iter().flatten().all(|v| v.is_finite()));
    // Gravity on the offset rotor turns the outer gimbal: U1 leaves zero.
    assert!(r[20][4].abs() > 1e-3, "U1 at 1 s: {}", r[20][4]);
    let printed = gyro_sim(&["--model", VARIANT, "--set", "OFF=0.1", "--print-scene"], &dir);
    assert!(text(&printed).contains("\nOFF = 0.1\n"), "{}", text(&printed));
}

#[test]
fn missing_inconsistent_and_implausible_models_are_errors() {
    let dir = folder("errors");
    let out = dir.join("out");
    let out = out.to_str().unwrap();
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, "model = \"nowhere.al\"\nt_final = 1.0\noutput_step = 0.1\n").unwrap();
    let e = text(&gyro_sim(&[scene.to_str().unwrap(), "--out", out], &dir));
    assert!(e.contains("nowhere.al: cannot read the model file"), "{e}");
    // The offset-rotor trap: the paper's A_DO_A> = 0> kept while DO moves off O.
    let paper = std::fs::read_to_string(PAPER).unwrap();
    let trap = dir.join("trap.al");
    std::fs::write(&trap, paper.replace("P_O_DO> = 0>", "P_O_DO> = 0.1*D2>")).unwrap();
    std::fs::write(&scene, "model = \"trap.al\"\nt_final = 1.0\noutput_step = 0.1\n").unwrap();
    let run = gyro_sim(&[scene.to_str().unwrap(), "--engine", "instant", "--out", out], &dir);
    let e = text(&run);
    assert!(!run.status.success());
    assert!(e.contains("trap.al:") && e.contains("error: `A_DO_A> = 0>` contradicts"), "{e}");
    assert!(e.contains("`P_O_DO> = 0.1*D2>` implies the other value"), "{e}");
    for engine in ["instant", "compiled"] {
        let run = gyro_sim(&["--model", VARIANT, "--engine", engine, "--set", "M3=-50", "--out", out], &dir);
        let e = text(&run);
        assert!(!run.status.success() && e.contains("error: implausible value of M3"), "{engine}: {e}");
        assert!(!e.contains("compiling"), "checked before anything is built: {e}");
    }
    let e =
        text(&gyro_sim(&["--model", VARIANT, "--engine", "instant", "--set", "MASS=1", "--out", out], &dir));
    assert!(e.contains("--set MASS: variant_gimbal has no parameter or state `MASS`"), "{e}");
}

#[test]
fn the_compiled_path_builds_once_per_file_version() {
    let dir = folder("compiled");
    let model = dir.join("my_gimbal.al");
    std::fs::copy(VARIANT, &model).unwrap();
    let out = dir.join("out");
    let base = ["--model", model.to_str().unwrap(), "--t-final", "1", "--out", out.to_str().unwrap()];
    let args = [&base[..], &["--engine", "compiled"]].concat();
    let first = gyro_sim(&args, &dir);
    assert!(first.status.success(), "{}", text(&first));
    assert!(text(&first).contains("compiling the model"), "{}", text(&first));
    assert!(text(&first).contains("model my_gimbal ran compiled"), "{}", text(&first));
    let compiled_rows = rows(&out);
    let compiled_view = view_data(&out);
    let again = gyro_sim(&args, &dir);
    assert!(again.status.success() && !text(&again).contains("compiling"), "{}", text(&again));
    let instant = gyro_sim(&[&base[..], &["--engine", "instant"]].concat(), &dir);
    assert!(instant.status.success(), "{}", text(&instant));
    let instant_rows = rows(&out);
    let worst = compiled_rows.iter().flatten().zip(instant_rows.iter().flatten());
    let worst = worst.map(|(x, y)| (x - y).abs() / x.abs().max(1.0)).fold(0.0, f64::max);
    assert!(worst < 1e-12, "compiled vs instant {worst:e}");
    let jit = gyro_sim(&[&base[..], &["--engine", "jit"]].concat(), &dir);
    assert!(jit.status.success() && text(&jit).contains("ran jit"), "{}", text(&jit));
    let worst = compiled_rows.iter().flatten().zip(rows(&out).into_iter().flatten());
    let worst = worst.map(|(x, y)| (x - y).abs() / x.abs().max(1.0)).fold(0.0, f64::max);
    assert!(worst < 1e-12, "compiled vs jit {worst:e}");
    // The compiled binary computes the model's drawing as the instant path does.
    let instant_view = view_data(&out);
    assert_eq!(compiled_view["view"], instant_view["view"]);
    let names: Vec<&String> = instant_view["columns"].as_object().unwrap().keys().collect();
    assert!(names.iter().any(|n| n.starts_with("P_O_")) && names.len() > 20, "{names:?}");
    for name in names {
        let pairs = view_column(&compiled_view, name).into_iter().zip(view_column(&instant_view, name));
        let worst = pairs.map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
        assert!(worst < 1e-12, "{name}: compiled vs instant {worst:e}");
    }
    // An edit of INPUT values alone needs no build, and the binary runs with the new values.
    let edited = std::fs::read_to_string(&model).unwrap().replace("OFF = 0.05", "OFF = 0.08");
    std::fs::write(&model, &edited).unwrap();
    let input_edit = gyro_sim(&args, &dir);
    assert!(input_edit.status.success() && !text(&input_edit).contains("compiling"), "{}", text(&input_edit));
    assert!(text(&input_edit).contains("ran compiled"), "{}", text(&input_edit));
    let compiled_rows = rows(&out);
    assert!(gyro_sim(&[&base[..], &["--engine", "instant"]].concat(), &dir).status.success());
    let instant_after = rows(&out);
    let worst = compiled_rows.iter().flatten().zip(instant_after.iter().flatten());
    let worst = worst.map(|(x, y)| (x - y).abs() / x.abs().max(1.0)).fold(0.0, f64::max);
    assert!(worst < 1e-12, "compiled vs instant after the INPUT edit {worst:e}");
    assert_ne!(compiled_rows, instant_rows, "the new offset moves the rotor");
    // Any other edit builds exactly once more.
    std::fs::write(&model, edited + "% an edit outside INPUT\n").unwrap();
    let after_edit = gyro_sim(&args, &dir);
    assert!(after_edit.status.success() && text(&after_edit).contains("compiling"), "{}", text(&after_edit));
    let settled = gyro_sim(&args, &dir);
    assert!(settled.status.success() && !text(&settled).contains("compiling"), "{}", text(&settled));
    let settled_rows = rows(&out);
    // A damaged cached binary is rebuilt once, and the run goes on.
    let built = text(&after_edit);
    let binary = built.lines().find_map(|l| l.strip_prefix("compiled: ")).expect("the binary's path");
    // The built-in models stay out of the binary (the simulator's own names them 58 times).
    let bytes = std::fs::read(binary.trim()).unwrap();
    assert!(!bytes.windows(b"heavy_top".len()).any(|w| w == b"heavy_top"), "a built-in model linked in");
    std::fs::write(binary.trim(), b"not a program").unwrap();
    let repaired = gyro_sim(&args, &dir);
    assert!(repaired.status.success(), "{}", text(&repaired));
    assert!(
        text(&repaired).contains("cannot be started") && text(&repaired).contains("rebuilding it"),
        "{}",
        text(&repaired)
    );
    assert_eq!(rows(&out), settled_rows, "the rebuilt binary gives the same rows");
}

#[test]
fn without_a_toolchain_the_compiled_path_says_so() {
    let dir = folder("no_toolchain");
    let model = dir.join("lonely.al");
    // Content no other test builds, so no cached binary exists for it.
    let text_of = std::fs::read_to_string(VARIANT).unwrap() + "% no toolchain here\n";
    std::fs::write(&model, text_of).unwrap();
    let run = Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", "--model", model.to_str().unwrap(), "--engine", "compiled"])
        .args(["--out", dir.join("out").to_str().unwrap()])
        .env("GYRO_SIM_CACHE", dir.join("cache"))
        .env("GYRO_SIM_TARGET_DIR", dir.join("target"))
        .env_remove("CARGO")
        .env("PATH", dir.join("empty"))
        .output()
        .unwrap();
    let e = text(&run);
    assert!(!run.status.success(), "{e}");
    assert!(
        e.contains("needs a Rust toolchain, and `cargo` was not found") && e.contains("--engine instant"),
        "{e}"
    );
}

#[test]
fn an_edited_gimbal_runs_on_the_jit_engine_without_a_toolchain() {
    let dir = folder("jit_no_toolchain");
    let model = dir.join("edited_gimbal.al");
    // A changed axis (the inner gimbal turns about B3 instead of -B1) and an offset mass centre.
    let source = std::fs::read_to_string(VARIANT).unwrap();
    let edited = source
        .replace("SIMPROT(B, C, -1, Q2)", "SIMPROT(B, C, 3, Q2)")
        .replace("P_O_DO> = OFF*D2>", "P_O_DO> = OFF*D2> + 0.02*D1>");
    assert_ne!(edited, source);
    std::fs::write(&model, edited).unwrap();
    let out = dir.join("out");
    let run = Command::new(env!("CARGO_BIN_EXE_gyro-sim"))
        .args(["run", "--model", model.to_str().unwrap(), "--out", out.to_str().unwrap()])
        .env("GYRO_SIM_CACHE", dir.join("cache"))
        .env("GYRO_SIM_TARGET_DIR", dir.join("target"))
        .env_remove("CARGO")
        .env("PATH", dir.join("empty"))
        .current_dir(&dir)
        .output()
        .unwrap();
    assert!(run.status.success() && text(&run).contains("ran jit"), "{}", text(&run));
    assert!(!dir.join("cache").exists() && !dir.join("target").exists(), "nothing was built");
    let jit_rows = rows(&out);
    let instant = gyro_sim(
        &["--model", model.to_str().unwrap(), "--engine", "instant", "--out", out.to_str().unwrap()],
        &dir,
    );
    assert!(instant.status.success(), "{}", text(&instant));
    assert_eq!(jit_rows, rows(&out), "the JIT engine computes the evaluator's operations");
}

#[test]
fn an_initial_angle_in_degrees_on_the_input_line_starts_the_run_there() {
    // UNITS Q = DEG: the INPUT value is in degrees, and so are the CSV column and the scene
    // `--print-scene` writes.
    let dir = folder("input_degrees");
    let file = dir.join("pendulum_deg.al");
    let source =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/examples/pendulum.al"))
            .unwrap()
            .replace("Q = 30 deg", "Q = 30")
            .replace("KANE()", "KANE()\nUNITS Q = DEG");
    std::fs::write(&file, source).unwrap();
    let out = dir.join("out");
    let o = gyro_sim(
        &["--model", file.to_str().unwrap(), "--t-final", "0.1", "--out", out.to_str().unwrap()],
        &dir,
    );
    assert!(o.status.success(), "{}", text(&o));
    assert!((rows(&out)[0][1] - 30.0).abs() < 1e-12, "starts at {} deg", rows(&out)[0][1]);
    let o = gyro_sim(&["--model", file.to_str().unwrap(), "--print-scene"], &dir);
    let printed = text(&o);
    let line = printed.lines().find(|l| l.starts_with("Q = ")).unwrap_or_else(|| panic!("{printed}"));
    let value: f64 = line["Q = ".len()..].split_whitespace().next().unwrap().parse().unwrap();
    assert!((value - 30.0).abs() < 1e-12 && line.ends_with("# DEG"), "{line}");
}

#[test]
fn a_speed_in_degrees_per_second_is_read_run_and_written_in_degrees_per_second() {
    // UNITS U = DEG/S: the INPUT value, `--set` and the CSV column are in deg/s; the model runs
    // in rad/s. Without gravity U stays and Q grows by U*t.
    let dir = folder("input_deg_per_s");
    let file = dir.join("spinner.al");
    let source =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/examples/pendulum.al"))
            .unwrap()
            .replace("G = 9.81 m/s^2, Q = 30 deg, U = 0", "G = 0, Q = 0, U = 10")
            .replace("KANE()", "KANE()\nUNITS Q = DEG, U = DEG/S");
    std::fs::write(&file, source).unwrap();
    let run = |extra: &[&str], name: &str| {
        let out = dir.join(name);
        let mut args = vec!["--model", file.to_str().unwrap(), "--t-final", "1"];
        args.extend(extra);
        args.extend(["--out", out.to_str().unwrap()]);
        let o = gyro_sim(&args, &dir);
        assert!(o.status.success(), "{}", text(&o));
        let header = std::fs::read_to_string(out.join("trajectory.csv")).unwrap();
        assert!(header.starts_with("t,q_deg,u_deg_per_s"), "{}", header.lines().next().unwrap());
        rows(&out)
    };
    let last = |r: &[Vec<f64>]| r.last().unwrap().clone();
    let plain = last(&run(&[], "plain"));
    assert!((plain[2] - 10.0).abs() < 1e-9, "U = {} deg/s", plain[2]);
    assert!((plain[1] - 10.0).abs() < 1e-9, "Q(1) = {} deg", plain[1]);
    let set = last(&run(&["--set", "U=1 rad/s"], "set_rad"));
    assert!((set[2] - 1f64.to_degrees()).abs() < 1e-9, "1 rad/s is {} deg/s", set[2]);
    let instant = last(&run(&["--engine", "instant", "--set", "U=20"], "instant"));
    assert!((instant[1] - 20.0).abs() < 1e-9, "Q(1) = {} deg", instant[1]);
}

#[test]
fn a_scene_naming_a_model_file_takes_the_file_s_times_where_it_gives_none() {
    let dir = folder("scene_file_times");
    let source =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/examples/pendulum.al"))
            .unwrap();
    std::fs::write(dir.join("pendulum.al"), format!("{source}INPUT TFINAL = 2, INTEGSTP = 0.25\n")).unwrap();
    let times = |scene: &str, name: &str| {
        let path = dir.join(format!("{name}.toml"));
        std::fs::write(&path, format!("model = \"pendulum.al\"\n{scene}[parameters]\nL = 2\n")).unwrap();
        let out = dir.join(name);
        let run = gyro_sim(&[path.to_str().unwrap(), "--no-view", "--out", out.to_str().unwrap()], &dir);
        assert!(run.status.success(), "{}", text(&run));
        rows(&out).iter().map(|r| r[0]).collect::<Vec<f64>>()
    };
    assert_eq!(times("", "from_file"), [0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75, 2.0]);
    assert_eq!(times("t_final = 1.0\n", "own_end"), [0.0, 0.25, 0.5, 0.75, 1.0]);
    assert_eq!(times("output_step = 1.0\n", "own_step"), [0.0, 1.0, 2.0]);
}
