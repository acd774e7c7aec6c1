//! The programs CODE ALGEBRAIC(EQN, X, ...) and CODE NONLINEAR(EQN, X, ...) ask for, and CODE
//! ALGEBRAIC() with no list (of a file with equations of motion and of one without), run by
//! their real runtimes (gcc, gfortran, GNU Octave, python3 with NumPy and SciPy): a linear
//! system's solution is the hand solution, a nonlinear one's is a root (its residuals evaluated
//! here) and `kane solve`'s, the OUTPUT quantities at the INPUT values are the simulator's first
//! row or the hand values; bad systems stop naming what is wrong.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use kane_tests::bins;
use kane_tests::runtimes::{gcc, gfortran, scratch, succeeds, table, Table};

/// What one program did when run.
struct Ran {
    language: &'static str,
    out: Output,
    csv: PathBuf,
}

/// The model `text` (`NAME.EXT` standing for each program's file) written in `dir`, its CODE
/// statements carried out by `kane code`, each program built and run.
fn run_every_language(dir: &Path, text: &str) -> Vec<Ran> {
    let mut ran = Vec::new();
    for (language, ext) in [("C", "c"), ("Fortran", "f"), ("Python", "py"), ("Octave", "m")] {
        let stem = format!("prog_{ext}");
        let model = dir.join(format!("{stem}.al"));
        std::fs::write(&model, text.replace("NAME.EXT", &format!("{stem}.{ext}"))).unwrap();
        succeeds(Command::new(bins::kane()).arg("code").arg(&model), "kane code");
        let program = dir.join(format!("{stem}.{ext}"));
        let exe = dir.join(&stem);
        let mut cmd = match ext {
            "c" => {
                gcc(&program, &exe);
                Command::new(&exe)
            }
            "f" => {
                gfortran(&program, &exe);
                Command::new(&exe)
            }
            "py" => {
                let mut python = Command::new("python3");
                python.arg(&program);
                python
            }
            _ => {
                let mut octave = Command::new("octave-cli");
                octave.args(["--quiet", "--norc", "--no-history", "--eval", &stem]).env("HOME", dir);
                octave
            }
        };
        let out = cmd
            .current_dir(dir)
            .output()
            .unwrap_or_else(|e| panic!("{language}: {e}; tests/run installs it"));
        ran.push(Ran { language, out, csv: dir.join(format!("{stem}.csv")) });
    }
    ran
}

/// The program's solution: its CSV after it ran successfully.
fn solution(ran: &Ran) -> Table {
    let stderr = String::from_utf8_lossy(&ran.out.stderr);
    assert!(ran.out.status.success(), "{}: {stderr}", ran.language);
    table(&ran.csv)
}

fn corpus_file(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("data/autolev-corpus").join(name);
    std::fs::read_to_string(path).unwrap().replace("some_filename.c", "NAME.EXT")
}

#[test]
fn a_linear_system_is_solved_to_the_hand_solution_in_every_language() {
    // 2x + 5y = 7, 3x + 4y = 6: x = 2/7, y = 9/7 by Cramer's rule.
    let dir = scratch("kane-systems", "linear");
    for ran in run_every_language(&dir, &corpus_file("ruletest11.al")) {
        let t = solution(&ran);
        assert_eq!(t.header, ["x", "y"], "{}", ran.language);
        let (x, y) = (t.rows[0][0], t.rows[0][1]);
        assert!(
            (x - 2.0 / 7.0).abs() <= 1e-15 && (y - 9.0 / 7.0).abs() <= 1e-15,
            "{}: {x} {y}",
            ran.language
        );
        let printed = String::from_utf8_lossy(&ran.out.stdout);
        assert!(printed.contains("X = ") && printed.contains("Y = "), "{}: {printed}", ran.language);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_nonlinear_system_converges_to_a_root_and_to_kane_solves_in_every_language() {
    let dir = scratch("kane-systems", "nonlinear");
    let text = corpus_file("ruletest12.al");
    let model = dir.join("solve.al");
    std::fs::write(&model, &text).unwrap();
    let printed = succeeds(Command::new(bins::kane()).arg("solve").arg(&model).arg("--json"), "kane solve");
    let json: serde_json::Value = serde_json::from_str(&printed).unwrap();
    let want: Vec<f64> =
        json["systems"][0]["values"].as_array().unwrap().iter().map(|v| v.as_f64().unwrap()).collect();
    let (a, b, r) = (2.0, 3.0, 1.0);
    for ran in run_every_language(&dir, &text) {
        let t = solution(&ran);
        let (x, y) = (t.rows[0][0], t.rows[0][1]);
        let residuals = [a * x.powi(3) + b * y * y - r, a * x.sin().powi(2) + b * (2.0 * y).cos() - r * r];
        assert!(residuals.iter().all(|e| e.abs() <= 1e-12), "{}: residuals {residuals:?}", ran.language);
        assert!((x - want[0]).abs() <= 1e-12 && (y - want[1]).abs() <= 1e-12, "{}: {x} {y}", ran.language);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn code_algebraic_with_no_list_writes_the_outputs_at_the_input_values() {
    let dir = scratch("kane-systems", "outputs");
    let gimbal = Path::new(env!("CARGO_MANIFEST_DIR")).join("../kane-model/models/gimbal_gyroscope.al");
    let text = std::fs::read_to_string(gimbal).unwrap().replace("CODE DYNAMICS() PHASE3.M, SUBS", "");
    let text = format!("{text}\nINPUT Q2 = 20 DEG, U1 = 0.5\nCODE ALGEBRAIC() NAME.EXT\n");
    let model = dir.join("reference.al");
    std::fs::write(&model, &text).unwrap();
    let mut gyro = Command::new(bins::gyro_sim());
    gyro.args(["run", "--model"]).arg(&model).args(["--t-final", "0.05", "--out"]).arg(dir.join("reference"));
    succeeds(&mut gyro, "gyro-sim run");
    let reference = table(&dir.join("reference/trajectory.csv"));
    for ran in run_every_language(&dir, &text) {
        let t = solution(&ran);
        assert_eq!(t.header, reference.header, "{}: the simulator's header", ran.language);
        assert_eq!(t.rows.len(), 1, "{}: one row, at the INPUT values", ran.language);
        for (j, (got, want)) in t.rows[0].iter().zip(&reference.rows[0]).enumerate() {
            let bound = 1e-13 * (1.0 + want.abs());
            assert!((got - want).abs() <= bound, "{}: {} is {got}, not {want}", ran.language, t.header[j]);
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn code_algebraic_with_no_list_evaluates_a_file_without_dynamics_at_its_input_values() {
    let dir = scratch("kane-systems", "evaluation");
    let text = "% Where a two-link arm's tip is, and a plate's moment of inertia about N1> as A turns.
NEWTONIAN N
FRAMES A
CONSTANTS L1, L2, IXX, IYY
VARIABLES Q1, Q2
SIMPROT(N, A, 3, Q1)
XTIP = L1*COS(Q1) + L2*COS(Q1 + Q2)
YTIP = L1*SIN(Q1) + L2*SIN(Q1 + Q2)
IN1 = DOT(N1>, DOT(IXX*A1>*A1> + IYY*A2>*A2>, N1>))
M = [XTIP, L1; L2, IN1]
INPUT L1 = 0.4, L2 = 0.3, Q1 = 30 DEG, Q2 = 45 DEG, IXX = 2, IYY = 5
OUTPUT XTIP, YTIP, IN1, M
CODE ALGEBRAIC() NAME.EXT
";
    let (q1, q12) = (30f64.to_radians(), 75f64.to_radians());
    let (x, y, i) =
        (0.4 * q1.cos() + 0.3 * q12.cos(), 0.4 * q1.sin() + 0.3 * q12.sin(), 2.0 * 0.75 + 5.0 * 0.25);
    let want = [x, y, i, x, 0.4, 0.3, i];
    for ran in run_every_language(&dir, text) {
        let t = solution(&ran);
        let header = ["xtip", "ytip", "in1", "m_1_1", "m_1_2", "m_2_1", "m_2_2"];
        assert_eq!(t.header, header, "{}", ran.language);
        for (j, (got, want)) in t.rows[0].iter().zip(want).enumerate() {
            assert!(
                (got - want).abs() <= 1e-15 * (1.0 + want.abs()),
                "{}: {} is {got}, not {want}",
                ran.language,
                t.header[j]
            );
        }
    }
    let missing = text.replace("IXX = 2, ", "");
    for ran in run_every_language(&dir, &missing) {
        let stderr = String::from_utf8_lossy(&ran.out.stderr);
        assert!(
            stderr.contains("IXX has no value") && !ran.out.status.success(),
            "{}: {stderr}",
            ran.language
        );
    }
    let infinite =
        text.replace("OUTPUT XTIP, YTIP, IN1, M", "S = L2/SIN(Q2)\nOUTPUT S").replace("45 DEG", "0");
    for ran in run_every_language(&dir, &infinite) {
        let stderr = String::from_utf8_lossy(&ran.out.stderr);
        assert!(
            stderr.contains("S is") && stderr.contains("INPUT values") && !ran.out.status.success(),
            "{}: {stderr}",
            ran.language
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_singular_system_and_a_missing_value_stop_the_program_naming_them() {
    let dir = scratch("kane-systems", "refused");
    let linear = corpus_file("ruletest11.al");
    let singular = linear.replace("A21=3, A22=4", "A21=4, A22=10");
    let missing = linear.replace("B1=7, ", "");
    for (text, code, says) in [(singular, 1, "singular at X = 0"), (missing, 2, "B1 has no value")] {
        for ran in run_every_language(&dir, &text) {
            let stderr = String::from_utf8_lossy(&ran.out.stderr);
            assert!(stderr.contains(says), "{}: {stderr}", ran.language);
            if ran.language != "Octave" {
                assert_eq!(ran.out.status.code(), Some(code), "{}: {stderr}", ran.language);
            } else {
                assert!(!ran.out.status.success(), "Octave: {stderr}");
            }
            assert!(!ran.csv.exists(), "{}: no CSV is written", ran.language);
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
