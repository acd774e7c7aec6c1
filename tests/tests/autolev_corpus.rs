//! The 16 public Autolev files of SymPy's parser tests: each runs, and its quantities equal
//! SymPy's parse of the same file at a random point where SymPy's parser runs it (a file may
//! also be listed as rejected, with the precise error expected).
//! Fixtures: tests/data/autolev_corpus_sympy.json, made by make_corpus_fixtures.py.

use std::collections::HashMap;

use kane_model::expr::{ExprId, SymbolId};
use kane_model::lang::{self, LoadedModel, Value};
use serde::Deserialize;

#[derive(Deserialize)]
struct Fixtures {
    files: HashMap<String, FileFixture>,
}

#[derive(Deserialize)]
struct FileFixture {
    error: Option<String>,
    #[serde(default)]
    values: HashMap<String, f64>,
    #[serde(default)]
    scalars: HashMap<String, f64>,
    #[serde(default)]
    matrices: HashMap<String, Vec<Vec<f64>>>,
    #[serde(default)]
    vectors: HashMap<String, VectorFixture>,
    kane: Option<KaneFixture>,
}

#[derive(Deserialize)]
struct VectorFixture {
    frame: String,
    components: Vec<f64>,
}

#[derive(Deserialize)]
struct KaneFixture {
    mass_matrix: Vec<Vec<f64>>,
    forcing: Vec<f64>,
}

const CORPUS: &[(&str, &str)] = &[
    ("ruletest1.al", include_str!("../data/autolev-corpus/ruletest1.al")),
    ("ruletest2.al", include_str!("../data/autolev-corpus/ruletest2.al")),
    ("ruletest3.al", include_str!("../data/autolev-corpus/ruletest3.al")),
    ("ruletest4.al", include_str!("../data/autolev-corpus/ruletest4.al")),
    ("ruletest5.al", include_str!("../data/autolev-corpus/ruletest5.al")),
    ("ruletest6.al", include_str!("../data/autolev-corpus/ruletest6.al")),
    ("ruletest7.al", include_str!("../data/autolev-corpus/ruletest7.al")),
    ("ruletest8.al", include_str!("../data/autolev-corpus/ruletest8.al")),
    ("ruletest9.al", include_str!("../data/autolev-corpus/ruletest9.al")),
    ("ruletest10.al", include_str!("../data/autolev-corpus/ruletest10.al")),
    ("ruletest11.al", include_str!("../data/autolev-corpus/ruletest11.al")),
    ("ruletest12.al", include_str!("../data/autolev-corpus/ruletest12.al")),
    (
        "pydy-example-repo/chaos_pendulum.al",
        include_str!("../data/autolev-corpus/pydy-example-repo/chaos_pendulum.al"),
    ),
    (
        "pydy-example-repo/double_pendulum.al",
        include_str!("../data/autolev-corpus/pydy-example-repo/double_pendulum.al"),
    ),
    (
        "pydy-example-repo/mass_spring_damper.al",
        include_str!("../data/autolev-corpus/pydy-example-repo/mass_spring_damper.al"),
    ),
    (
        "pydy-example-repo/non_min_pendulum.al",
        include_str!("../data/autolev-corpus/pydy-example-repo/non_min_pendulum.al"),
    ),
];

/// Files rejected on purpose, with the construct each error must name.
const REJECTED: &[(&str, &str)] = &[];

/// Quantities where SymPy's parser departs from Autolev, with Autolev's value in the file's
/// symbols: INCLUDE(E, X) keeps the terms of E with X in them (2*X), SymPy's gives X's
/// coefficient.
const SYMPY_DEPARTS: &[(&str, &str, &str)] = &[("ruletest7.al", "d2", "2*X")];

fn eval(m: &LoadedModel, e: ExprId, values: &HashMap<String, f64>) -> Option<f64> {
    let ar = &m.model.ar;
    let by_name = |s: SymbolId| values.get(&ar.symbol_info(s).name.to_ascii_lowercase()).copied();
    ar.eval(&[e], by_name).ok().map(|v| v[0])
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1.0)
}

/// Compares every quantity the fixture has and this implementation defines; returns
/// (compared, mismatches).
fn compare(name: &str, m: &mut LoadedModel, f: &FileFixture) -> (usize, Vec<String>) {
    let mut compared = 0;
    let mut bad = Vec::new();
    for (k, want) in &f.scalars {
        let Some(Value::Scalar(e)) = m.value(k) else { continue };
        if let Some((_, _, autolev)) = SYMPY_DEPARTS.iter().find(|(n, q, _)| *n == name && q == k) {
            assert_eq!(&m.model.ar.to_text(e), autolev, "{name}: {k}");
            continue;
        }
        let Some(got) = eval(m, e, &f.values) else { continue };
        compared += 1;
        if !close(got, *want) {
            bad.push(format!("{name}: {k} = {got}, SymPy {want}"));
        }
    }
    for (k, want) in &f.matrices {
        let Some(Value::Matrix { rows, cols, data }) = m.value(k) else { continue };
        if rows != want.len() || cols != want[0].len() {
            bad.push(format!("{name}: {k} is {rows}x{cols}, SymPy {}x{}", want.len(), want[0].len()));
            continue;
        }
        compared += 1;
        for i in 0..rows {
            for j in 0..cols {
                match eval(m, data[i * cols + j], &f.values) {
                    Some(got) if close(got, want[i][j]) => {}
                    got => bad.push(format!("{name}: {k}[{i}][{j}] = {got:?}, SymPy {}", want[i][j])),
                }
            }
        }
    }
    for (k, want) in &f.vectors {
        let Some(Value::Vector(v)) = m.value(&format!("{k}>")) else { continue };
        let Some(frame) = m.model.frame(&want.frame) else { continue };
        let Ok(comps) = m.model.express(&v, frame) else { continue };
        compared += 1;
        for (i, c) in comps.iter().enumerate() {
            match eval(m, *c, &f.values) {
                Some(got) if close(got, want.components[i]) => {}
                got => bad.push(format!(
                    "{name}: {k}> . {}{} = {got:?}, SymPy {}",
                    want.frame,
                    i + 1,
                    want.components[i]
                )),
            }
        }
    }
    if let (Some(k), Some(eqs)) = (&f.kane, &m.equations) {
        compared += 1;
        let n = k.forcing.len();
        for i in 0..n {
            for j in 0..n {
                match eval(m, eqs.mass_matrix[i][j], &f.values) {
                    Some(got) if close(got, k.mass_matrix[i][j]) => {}
                    got => bad.push(format!("{name}: M[{i}][{j}] = {got:?}, SymPy {}", k.mass_matrix[i][j])),
                }
            }
            match eval(m, eqs.forcing[i], &f.values) {
                Some(got) if close(got, k.forcing[i]) => {}
                got => bad.push(format!("{name}: f[{i}] = {got:?}, SymPy {}", k.forcing[i])),
            }
        }
    }
    (compared, bad)
}

#[test]
fn corpus_files_match_sympy_or_are_rejected_precisely() {
    let fixtures: Fixtures = serde_json::from_str(include_str!("../data/autolev_corpus_sympy.json")).unwrap();
    let mut mismatches = Vec::new();
    let mut summary = Vec::new();
    for (name, src) in CORPUS {
        let f = &fixtures.files[*name];
        match lang::load(name, src) {
            Ok(mut m) => {
                if let Some(e) = &f.error {
                    // SymPy's parser cannot run it (ruletest6's complex roots, ruletest10's
                    // second orientation of a frame): nothing to compare with.
                    summary.push(format!(
                        "{name}: loads; SymPy's parser fails ({})",
                        e.lines().next().unwrap_or("")
                    ));
                    continue;
                }
                let (n, bad) = compare(name, &mut m, f);
                assert!(n > 0, "{name}: nothing compared");
                summary.push(format!("{name}: {n} quantities compared"));
                mismatches.extend(bad);
            }
            Err(report) => {
                let (_, want) = REJECTED
                    .iter()
                    .find(|(n, _)| n == name)
                    .unwrap_or_else(|| panic!("{name} rejected:\n{report}"));
                let text = report.to_string();
                assert!(text.contains(want), "{name}: expected `{want}` in\n{text}");
                assert!(text.contains(&format!("{name}:")), "errors name the file: {text}");
            }
        }
    }
    assert!(mismatches.is_empty(), "{}\n\n{}", mismatches.join("\n"), summary.join("\n"));
}

#[test]
fn corpus_files_pass_the_kinematics_check_but_the_pendulum_whose_velocity_has_the_wrong_sign() {
    for (name, src) in CORPUS {
        let checked = lang::check(name, src);
        if *name != "pydy-example-repo/non_min_pendulum.al" {
            if let Err(r) = checked {
                panic!("{name}:\n{r}");
            }
            continue;
        }
        // `V_P_N> = DT(P_P_PN>, N)` for P located from the fixed PN: the sign is wrong.
        let Err(r) = checked else { panic!("{name} checked") };
        let text = r.to_string();
        let line = |start: &str| src.lines().position(|l| l.starts_with(start)).unwrap() + 1;
        assert!(
            text.contains(&format!("{name}:{}:1: error: `V_P_N>=DT(P_P_PN>, N)`", line("V_P_N>"))),
            "{text}"
        );
        assert!(text.contains(&format!("{name}:{}:1: note:", line("P_PN_P>"))), "{text}");
    }
}
