//! The programs `kane code` writes, run by their real runtimes (gcc, gfortran, GNU Octave, python3
//! with NumPy and SciPy): each writes the simulator's CSV header, and its rows match a tight `gyro-sim
//! run` of the same file (Verner 9(8) at 1e-13) to within the file's tolerances, on the paper's
//! gimbal (its own CODE statement), the bicycle with its constraint solve, the four-bar loop and a
//! 10-link chain. `tests/run` installs the runtimes.

use std::path::{Path, PathBuf};
use std::process::Command;

use kane_tests::bins;
use kane_tests::runtimes::{self, gcc, gfortran, octave, succeeds, table, Table};

fn models_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../kane-model/models")
}

fn scratch(name: &str) -> PathBuf {
    runtimes::scratch("kane-standalone", name)
}

/// The worst column's largest difference from `reference`, relative to 1 + that column's
/// largest magnitude.
fn worst_error(got: &Table, reference: &Table) -> (f64, String) {
    assert_eq!(got.header, reference.header, "the program's header is the simulator's");
    assert_eq!(got.rows.len(), reference.rows.len(), "one row per output time");
    let mut worst = (0.0, String::new());
    for (j, name) in reference.header.iter().enumerate() {
        let size = 1.0 + reference.rows.iter().map(|r| r[j].abs()).fold(0.0, f64::max);
        let diff = got.rows.iter().zip(&reference.rows).map(|(a, b)| (a[j] - b[j]).abs()).fold(0.0, f64::max);
        assert!(got.rows.iter().zip(&reference.rows).all(|(a, b)| a[0] == b[0]), "the same output times");
        if diff / size > worst.0 {
            worst = (diff / size, name.clone());
        }
    }
    worst
}

/// `gyro-sim run --model FILE` at 1e-13: the reference rows.
fn reference(dir: &Path, model: &Path) -> Table {
    let out = dir.join("reference");
    let mut cmd = Command::new(bins::gyro_sim());
    cmd.args(["run", "--model"]).arg(model).args(["--method", "vern9", "--rtol", "1e-13", "--atol", "1e-13"]);
    succeeds(cmd.arg("--out").arg(&out), "gyro-sim run");
    table(&out.join("trajectory.csv"))
}

/// `kane code MODEL --lang LANGUAGE -o PROGRAM`.
fn write_program(model: &Path, language: &str, program: &Path) {
    let mut cmd = Command::new(bins::kane());
    succeeds(cmd.args(["code"]).arg(model).args(["--lang", language, "-o"]).arg(program), "kane code");
}

/// The C program of `model` compiled with gcc (warnings as errors) and run: its rows.
fn c_rows(dir: &Path, model: &Path) -> Table {
    let (source, exe) = (dir.join("model.c"), dir.join("model_c"));
    write_program(model, "c", &source);
    gcc(&source, &exe);
    succeeds(&mut Command::new(&exe), "the C program");
    table(&dir.join("model.csv"))
}

/// The Fortran program of `model`, as fixed form (`.f`, the stricter layout), compiled with
/// gfortran and run: its rows.
fn fortran_rows(dir: &Path, model: &Path) -> Table {
    let (source, exe) = (dir.join("model_f.f"), dir.join("model_f"));
    write_program(model, "fortran", &source);
    gfortran(&source, &exe);
    succeeds(&mut Command::new(&exe), "the Fortran program");
    table(&dir.join("model_f.csv"))
}

/// The Python program of `model` run by python3: its rows.
fn python_rows(dir: &Path, model: &Path) -> Table {
    let program = dir.join("model_py.py");
    write_program(model, "python", &program);
    succeeds(Command::new("python3").arg(&program), "python3 (with numpy and scipy)");
    table(&dir.join("model_py.csv"))
}

/// The MATLAB program of `model` run by GNU Octave: its rows.
fn octave_rows(dir: &Path, model: &Path) -> Table {
    write_program(model, "matlab", &dir.join("model_m.m"));
    octave(dir, "model_m");
    table(&dir.join("model_m.csv"))
}

/// Every language's rows of the model file `text` (named `name`) within `bound` of the reference.
fn every_language_matches(name: &str, text: &str, bound: f64) {
    let dir = scratch(name);
    let model = dir.join(format!("{name}.al"));
    std::fs::write(&model, text).unwrap();
    let reference = reference(&dir, &model);
    for (language, rows) in [
        ("C", c_rows(&dir, &model)),
        ("Fortran", fortran_rows(&dir, &model)),
        ("Python", python_rows(&dir, &model)),
        ("Octave", octave_rows(&dir, &model)),
    ] {
        let (error, column) = worst_error(&rows, &reference);
        eprintln!("{name}: {language}: worst relative error {error:.2e} ({column})");
        assert!(
            error <= bound,
            "{name}: the {language} program is {error:e} off in {column} (bound {bound:e})"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

fn model_text(name: &str) -> String {
    std::fs::read_to_string(models_dir().join(name)).unwrap()
}

#[test]
fn the_gimbal_in_every_language_matches_the_simulator_to_its_tolerances() {
    // RELERR = ABSERR = 1e-7 over 5 s.
    every_language_matches("gimbal", &model_text("gimbal_gyroscope.al"), 1e-5);
}

#[test]
fn the_bicycle_with_its_constraint_solve_matches_in_every_language() {
    // At 5 m/s (self-stable) from a roll rate; the yaw, pitch and front-wheel rates are solved at
    // each step.
    let text = model_text("whipple_bicycle.al")
        .replace("INPUT V = 0", "INPUT V = 5")
        .replace("U2 = 0,", "U2 = 0.5,");
    let text = format!("{text}\nINPUT TFINAL = 3, INTEGSTP = 0.05, ABSERR = 1.0E-09, RELERR = 1.0E-09\n");
    every_language_matches("bicycle", &text, 1e-7);
}

#[test]
fn the_four_bar_loop_matches_in_every_language() {
    // Its own TFINAL = 5 s at 1e-10.
    every_language_matches("four_bar", &model_text("four_bar.al"), 1e-7);
}

/// A planar chain of `n` links pinned end to end, released from a bend.
fn chain(n: usize) -> String {
    let list = |p: &str| (1..=n).map(|i| format!("{p}{i}")).collect::<Vec<_>>().join(", ");
    let mut s = vec![
        "NEWTONIAN N".to_string(),
        format!("BODIES {}", list("B")),
        format!("POINTS O, {}", list("J")),
        format!("CONSTANTS L, M, G\nVARIABLES Q{{{n}}}', U{{{n}}}'"),
        "V_O_N> = 0>".to_string(),
    ];
    for i in 1..=n {
        let (parent, pin) =
            if i == 1 { ("N".into(), "O".into()) } else { (format!("B{}", i - 1), format!("J{}", i - 1)) };
        s.push(format!("SIMPROT({parent}, B{i}, 3, Q{i})\nQ{i}' = U{i}"));
        s.push(format!("P_{pin}_B{i}O> = L/2*B{i}1>\nP_{pin}_J{i}> = L*B{i}1>"));
        s.push(format!("V2PTS(N, B{i}, {pin}, B{i}O)\nV2PTS(N, B{i}, {pin}, J{i})"));
        s.push(format!("MASS B{i} = M\nINERTIA B{i}, 0, 0, M*L^2/12"));
    }
    s.push("GRAVITY(-G*N2>)\nZERO = FR() + FRSTAR()\nKANE()".to_string());
    s.push(format!(
        "INPUT L = 0.5, M = 1, G = 9.81, {}",
        (1..=n).map(|i| format!("Q{i} = 0.1, U{i} = 0")).collect::<Vec<_>>().join(", ")
    ));
    s.push("INPUT TFINAL = 1, INTEGSTP = 0.05, ABSERR = 1.0E-08, RELERR = 1.0E-08".to_string());
    s.join("\n") + "\n"
}

#[test]
fn a_ten_link_chain_matches_in_every_language() {
    every_language_matches("chain10", &chain(10), 1e-6);
}

#[test]
fn the_paper_file_unchanged_writes_phase3_m_and_octave_runs_it() {
    let dir = scratch("phase3");
    let model = dir.join("gimbal_gyroscope.al");
    std::fs::copy(models_dir().join("gimbal_gyroscope.al"), &model).unwrap();
    let printed = succeeds(Command::new(bins::kane()).arg("code").arg(&model), "kane code");
    assert!(printed.contains("PHASE3.m"), "{printed}");
    octave(&dir, "PHASE3");
    let rows = table(&dir.join("PHASE3.csv"));
    let (error, column) = worst_error(&rows, &reference(&dir, &model));
    assert!(error <= 1e-5, "Trial 1 from PHASE3.m is {error:e} off in {column}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn code_statements_it_cannot_write_are_errors_at_their_line_and_its_options_are_accepted() {
    let dir = scratch("refused");
    let base = model_text("gimbal_gyroscope.al").replace("CODE DYNAMICS() PHASE3.M, SUBS", "");
    for (line, says) in [
        ("CODE DYNAMICS() PHASE3.M, FAST", "CODE option `FAST`"),
        ("CODE DYNAMICS() PHASE3.XYZ", "PHASE3.XYZ"),
        ("CODE ODE() OUT.C", "CODE ODE() programs are not written"),
        ("CODE ALGEBRAIC()", "CODE ALGEBRAIC() names no file"),
        ("CODE DYNAMICS() NOWHERE/PHASE3.M", "in a folder that does not exist"),
    ] {
        let model = dir.join("g.al");
        std::fs::write(&model, format!("{base}{line}\n")).unwrap();
        let out = Command::new(bins::kane()).arg("code").arg(&model).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{stderr}");
        assert!(stderr.contains(says) && stderr.contains("g.al:"), "{line}: {stderr}");
    }
    let model = dir.join("options.al");
    std::fs::create_dir_all(dir.join("c")).unwrap();
    std::fs::write(&model, format!("{base}CODE DYNAMICS() c/GIMBAL.C, NOSUBS\n")).unwrap();
    succeeds(Command::new(bins::kane()).arg("code").arg(&model), "kane code with NOSUBS");
    assert!(dir.join("c/GIMBAL.c").is_file(), "NOSUBS writes the program, in the folder named");
    let model = dir.join("none.al");
    std::fs::write(&model, &base).unwrap();
    let out = Command::new(bins::kane()).arg("code").arg(&model).output().unwrap();
    assert!(String::from_utf8_lossy(&out.stderr).contains("no CODE statement"));
    std::fs::remove_dir_all(&dir).unwrap();
}
