//! The paper's cases: the script's INPUT case against an independent reference trajectory,
//! Trial 1 against its closed form, and the exact final time.

use gyro_sim::run;
use gyro_sim::Scene;

fn scene(path: &str) -> Scene {
    Scene::load(std::path::Path::new(&format!("{}/{path}", env!("CARGO_MANIFEST_DIR")))).unwrap()
}

#[test]
fn script_case_matches_the_reference_trajectory() {
    // tests/data/gimbal_script_case.csv: SymPy KanesMethod + SciPy DOP853 at 1e-13, confirmed by
    // Radau and heyoka (shared/references/README.md). Columns t, q1..q3, u1..u3 (rad), aP.
    let s = scene("scenes/paper/script.toml");
    let summary = run(&s, None).unwrap();
    let reference = include_str!("data/gimbal_script_case.csv");
    // The trajectory is in radians, as the reference (degrees only in the CSV).
    let worst = error_of(&summary, reference);
    assert_eq!(summary.trajectory.rows.len(), 101);
    // The scene asks accuracy 1e-9 (refining from rtol = atol = 1e-12); the reference's own
    // methods agree to about 1e-11.
    let asked = s.integrator.accuracy.unwrap();
    assert!(worst <= asked, "largest relative error against the reference: {worst:e}");
}

#[test]
fn trial_one_follows_its_closed_form() {
    // With Z = 0 and q2 = u2 = 0, f2 = 0 and M is block-diagonal: q2 stays 0 exactly, and
    // (I1 + J1) u1' = -Y, u3' = -u1'. So u1 = -Y t / (I1 + J1), u3 = U3(0) - u1,
    // q1 = -Y t^2 / (2 (I1 + J1)), q3 = U3(0) t - q1, and |a_P| = L (u1 + u3)^2 = L U3(0)^2.
    let s = scene("scenes/paper/trial1.toml");
    let summary = run(&s, None).unwrap();
    let (m1, m2, h1, h2, w, l, y, u30) = (2.0, 2.0, 0.6, 0.5, 0.025, 0.3, 10.0, 10.0);
    let i1 = 2.0 / 3.0 * m1 * (h1 * w - w * w);
    let j1 = 2.0 / 3.0 * m2 * (h2 * w - w * w);
    for row in &summary.trajectory.rows {
        let t = row[0];
        let u1 = -y * t / (i1 + j1);
        let q1 = -y * t * t / (2.0 * (i1 + j1));
        let q3 = u30 * t - q1;
        assert_eq!(row[2], 0.0, "q2 must stay exactly 0 at t = {t}");
        assert!((row[1] - q1).abs() < 1e-7 * q1.abs().max(1.0), "q1 at {t}");
        assert!((row[3] - q3).abs() < 1e-7 * q3.abs().max(1.0), "q3 at {t}");
        assert!((row[4] - u1).abs() < 1e-8 * u1.abs().max(1.0), "u1 at {t}");
        assert!((row[6] - (u30 - u1)).abs() < 1e-8 * u30, "u3 at {t}");
        assert!((row[7] - l * u30 * u30).abs() < 1e-9 * l * u30 * u30, "|a_P| at {t}");
    }
}

#[test]
fn the_last_row_is_at_t_final_exactly() {
    // 0.1 added three times is 0.30000000000000004; output times are i * step, the last t_final.
    let text = "model = \"gimbal_gyroscope\"\nt_final = 0.3\noutput_step = 0.1\n";
    let s = Scene::parse("exact.toml", text).unwrap();
    let summary = run(&s, None).unwrap();
    let times: Vec<f64> = summary.trajectory.rows.iter().map(|r| r[0]).collect();
    assert_eq!(times, vec![0.0, 0.1, 0.2, 0.3]);
    let text = "model = \"gimbal_gyroscope\"\nt_final = 0.25\noutput_step = 0.1\n";
    let s = Scene::parse("uneven.toml", text).unwrap();
    let times: Vec<f64> = run(&s, None).unwrap().trajectory.rows.iter().map(|r| r[0]).collect();
    assert_eq!(times, vec![0.0, 0.1, 0.2, 0.25]);
}

#[test]
fn a_run_writes_csv_and_plot_and_no_partial_files() {
    let dir = std::env::temp_dir().join(format!("gyro-sim-out-{}", std::process::id()));
    let s = scene("scenes/paper/trial2.toml");
    let summary = run(&s, Some(&dir)).unwrap();
    let csv = std::fs::read_to_string(summary.written.as_ref().unwrap().csv.clone()).unwrap();
    assert!(csv.starts_with("t,q1_deg,q2_deg,q3_deg,u1_rad_per_s,u2_rad_per_s,u3_rad_per_s,ap_m_per_s2\n"));
    assert_eq!(csv.lines().count(), 102);
    let png = std::fs::read(summary.written.as_ref().unwrap().plot.clone()).unwrap();
    assert_eq!(&png[1..4], b"PNG");
    let names: Vec<String> =
        std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
    assert!(names.iter().all(|n| !n.contains("partial")), "{names:?}");
    std::fs::remove_dir_all(&dir).ok();
}

/// Largest error of a run against a reference CSV (radians), relative to max(1, |value|).
fn error_of(summary: &gyro_sim::RunSummary, reference: &str) -> f64 {
    kane_tests::reference_error(&summary.trajectory.rows, reference)
}

const TRIALS: [(&str, &str); 3] = [
    ("scenes/paper/trial1.toml", include_str!("data/gimbal_trial1.csv")),
    ("scenes/paper/trial2.toml", include_str!("data/gimbal_trial2.csv")),
    ("scenes/paper/trial3.toml", include_str!("data/gimbal_trial3.csv")),
];

#[test]
fn every_trial_matches_its_independent_reference_to_the_accuracy_it_asks() {
    // References: the hand-derived equations integrated by SciPy DOP853 at 1e-13
    // (tests/data/make_trial_references.py). Each scene asks `accuracy` of the trajectory.
    for (path, reference) in TRIALS {
        let s = scene(path);
        let asked = s.integrator.accuracy.expect("the paper's scenes ask an accuracy");
        let summary = run(&s, None).unwrap();
        let e = error_of(&summary, reference);
        let reached = summary.trajectory.accuracy.unwrap();
        println!(
            "{path}: error {e:.2e}, asked {asked:e}, {} runs, estimate {:.2e}",
            reached.runs, reached.estimate
        );
        assert!(e <= asked, "{path}: {e:e} > {asked:e}");
        assert!(reached.estimate <= asked && reached.runs >= 2);
    }
}

#[test]
fn the_per_step_tolerance_alone_does_not_give_trial_3_its_accuracy() {
    // Without `accuracy`, Trial 3 at rtol = atol = 1e-9 misses 1e-7 (global error about 170
    // times the per-step tolerance): the refinement above is what meets it.
    let (path, reference) = TRIALS[2];
    let mut s = scene(path);
    s.integrator.accuracy = None;
    let summary = run(&s, None).unwrap();
    assert!(summary.trajectory.accuracy.is_none());
    let e = error_of(&summary, reference);
    assert!(e > 1e-7, "{e:e}");
}

#[test]
fn a_loose_start_is_refined_until_the_accuracy_is_met() {
    let (path, reference) = TRIALS[1];
    let mut s = scene(path);
    s.integrator.rtol = 1e-5;
    s.integrator.atol = 1e-5;
    s.integrator.accuracy = Some(1e-8);
    let summary = run(&s, None).unwrap();
    let reached = summary.trajectory.accuracy.unwrap();
    assert!(reached.runs >= 3, "{reached:?}");
    assert!(reached.rtol <= 1e-9, "{reached:?}");
    assert!(error_of(&summary, reference) <= 1e-8);
}

#[test]
fn an_accuracy_below_round_off_is_refused_with_a_reason() {
    let (path, _) = TRIALS[2];
    let mut s = scene(path);
    s.integrator.accuracy = Some(1e-15);
    let e = run(&s, None).unwrap_err().to_string();
    assert!(e.contains("accuracy 1e-15 not reached") && e.contains("looser"), "{e}");
}

#[test]
fn cyclic_coordinates_nothing_needs_are_not_integrated() {
    // Q2 and the speeds need neither q1 nor q3; |a_P| needs q3 (P is on the rotor) but not q1.
    let base = "model = \"gimbal_gyroscope\"\nt_final = 5.0\noutput_step = 0.05\n";
    let speeds = format!("{base}outputs = [\"Q2\", \"U1\", \"U2\", \"U3\"]\n[parameters]\nY = 10.0\nZ = 10.0\n[initial]\nU3 = 100.0\n");
    let s = Scene::parse("speeds.toml", &speeds).unwrap();
    let reduced = run(&s, None).unwrap();
    assert_eq!(reduced.trajectory.integrated, vec!["Q2", "U1", "U2", "U3"]);
    let with_ap = format!("{base}outputs = [\"Q2\", \"AP\"]\n");
    let s = Scene::parse("ap.toml", &with_ap).unwrap();
    assert_eq!(run(&s, None).unwrap().trajectory.integrated, vec!["Q2", "Q3", "U1", "U2", "U3"]);
    // The reduced run gives the same numbers as the full one.
    let full = run(&scene("scenes/paper/trial2.toml"), None).unwrap();
    let s = Scene::parse("t2.toml", &format!("{base}outputs = [\"Q2\", \"U1\", \"U2\", \"U3\"]\n[integrator]\nrtol = 1e-10\natol = 1e-10\n[parameters]\nY = 10.0\nZ = 10.0\n[initial]\nU3 = 10.0\n")).unwrap();
    let part = run(&s, None).unwrap();
    // Both runs are within 2e-8 of the reference (different state sizes give different steps).
    for (a, b) in full.trajectory.rows.iter().zip(&part.trajectory.rows) {
        // full: t, q1, q2, q3, u1, u2, u3, ap; part: t, q2, u1, u2, u3
        for (x, y) in [(a[2], b[1]), (a[4], b[2]), (a[5], b[3]), (a[6], b[4])] {
            assert!((x - y).abs() < 1e-7 * x.abs().max(1.0), "{x} vs {y}");
        }
    }
}

#[test]
fn trial_one_kinetic_energy_grows_by_the_work_of_the_torque() {
    // Only Y acts, on u1 (generalized force -Y): dT/dt = -Y u1, so
    // T(t) - T(0) = Y^2 t^2 / (2 (I1 + J1)) with u1 = -Y t / (I1 + J1).
    let summary = run(&scene("scenes/paper/trial1.toml"), None).unwrap();
    let (m1, m2, h1, h2, w, y, t) = (2.0, 2.0, 0.6, 0.5, 0.025, 10.0, 5.0);
    let i1 = 2.0 / 3.0 * m1 * (h1 * w - w * w);
    let j1 = 2.0 / 3.0 * m2 * (h2 * w - w * w);
    let (start, end) = summary.trajectory.kinetic_energy.unwrap();
    let k1 = 50.0 * 0.3f64 * 0.3 / 2.0;
    assert!((start - k1 * 100.0 / 2.0).abs() < 1e-9, "T(0) = K1 U3^2 / 2: {start}");
    let work = y * y * t * t / (2.0 * (i1 + j1));
    assert!(((end - start) - work).abs() < 1e-6 * work, "{} vs {work}", end - start);
}
