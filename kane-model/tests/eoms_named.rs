//! `kane eoms` on a 40-link planar chain with relative angles: the text stays under 1 MB, and
//! every printed quantity, read back with the named intermediates it uses, equals the derived
//! one at a pseudo-random state.

mod common;

use std::hash::{Hash, Hasher};

use common::kane;
use kane_model::expr::{Arena, ExprId};
use kane_model::lang::{load, LoadedModel, Value};

const LINKS: usize = 40;

/// The chain, one statement per line: link `i` turns by `Qi` relative to link `i - 1`.
fn chain(n: usize) -> String {
    let f: Vec<String> = (1..=n).map(|i| format!("F{i}")).collect();
    let mut out = vec![
        "NEWTONIAN N".to_string(),
        format!("FRAMES {}", f.join(", ")),
        "POINTS O".into(),
        format!("PARTICLES {}", (1..=n).map(|i| format!("P{i}")).collect::<Vec<_>>().join(", ")),
        format!("CONSTANTS L{{{n}}}, M{{{n}}}, G"),
        format!("VARIABLES Q{{{n}}}', U{{{n}}}'"),
    ];
    out.extend((1..=n).map(|i| format!("SIMPROT({}, F{i}, 3, Q{i})", if i == 1 { "N" } else { &f[i - 2] })));
    out.extend((1..=n).map(|i| format!("Q{i}' = U{i}")));
    out.extend(["V_O_N> = 0>".to_string(), "P_O_P1> = L1*F11>".into()]);
    out.extend((2..=n).map(|i| format!("P_P{}_P{i}> = L{i}*F{i}1>", i - 1)));
    out.push("V2PTS(N, F1, O, P1)".into());
    out.extend((2..=n).map(|i| format!("V2PTS(N, F{i}, P{}, P{i})", i - 1)));
    out.push(format!("MASS {}", (1..=n).map(|i| format!("P{i} = M{i}")).collect::<Vec<_>>().join(", ")));
    out.extend(["GRAVITY(-G*N2>)".to_string(), "ZERO = FR() + FRSTAR()".into(), "KANE()".into()]);
    out.join("\n") + "\n"
}

/// The printed quantities as assignments of the model language: `z1 = ...` as printed,
/// `M[i,j]` as `MASiXj`, `f[i]` as `FRCi`, `ZERO[i]` as `EQNi`.
fn as_assignments(eoms: &str) -> Vec<String> {
    let mut out = Vec::new();
    for line in eoms.lines().take_while(|l| !l.starts_with("% Partial velocities")) {
        let Some((lhs, rhs)) = line.split_once(" = ") else { continue };
        let index = |s: &str| s.split(['[', ']']).nth(1).unwrap_or_default().replace(',', "X");
        let name = match lhs {
            _ if lhs.starts_with('z') => lhs.to_string(),
            _ if lhs.starts_with("M[") => format!("MAS{}", index(lhs)),
            _ if lhs.starts_with("f[") => format!("FRC{}", index(lhs)),
            _ if lhs.starts_with("ZERO[") => format!("EQN{}", index(lhs)),
            _ => continue,
        };
        out.push(format!("{name} = {rhs}"));
    }
    out
}

/// A reproducible pseudo-random value for the symbol `name`, in a range that suits its kind.
fn value_of(name: &str) -> f64 {
    let mut h = std::collections::hash_map::DefaultHasher::new();
    name.hash(&mut h);
    let unit = (h.finish() >> 11) as f64 / (1u64 << 53) as f64;
    match name.chars().next() {
        Some('Q') => std::f64::consts::PI * (2.0 * unit - 1.0),
        Some('L' | 'M') => 0.5 + unit,
        Some('G') => 9.81,
        _ => 2.0 * unit - 1.0,
    }
}

/// The values of `xs` at the state of [`value_of`].
fn eval(ar: &Arena, xs: &[ExprId]) -> Vec<f64> {
    ar.eval(xs, |s| Some(value_of(&ar.symbol_info(s).name))).expect("every symbol has a value")
}

fn scalar(m: &LoadedModel, name: &str) -> ExprId {
    match m.value(name) {
        Some(Value::Scalar(x)) => x,
        _ => panic!("{name} was not read back as a scalar"),
    }
}

fn assert_close(what: &str, printed: f64, derived: f64) {
    let tol = 1e-9 * (1.0 + derived.abs());
    assert!((printed - derived).abs() <= tol, "{what}: printed {printed}, derived {derived}");
}

#[test]
fn a_forty_link_chain_prints_in_intermediates_and_reads_back_equal() {
    let src = chain(LINKS);
    let path = std::env::temp_dir().join(format!("kane_eoms_chain{LINKS}_{}.al", std::process::id()));
    std::fs::write(&path, &src).unwrap();
    let (ok, out, err) = kane(&["eoms", path.to_str().unwrap()]);
    std::fs::remove_file(&path).ok();
    assert!(ok, "{err}");
    assert!(out.len() < 1_000_000, "eoms printed {} bytes", out.len());
    assert!(out.starts_with("% Intermediates") && out.contains("\nz1 = "), "no intermediates");

    let derived = load("chain.al", &src).unwrap();
    let e = derived.equations.as_ref().unwrap();
    let kept: Vec<&str> = src.lines().filter(|l| !l.starts_with("ZERO") && !l.starts_with("KANE")).collect();
    let back_src = format!("{}\n{}\n", kept.join("\n"), as_assignments(&out).join("\n"));
    let back = load("chain_read_back.al", &back_src).unwrap_or_else(|r| panic!("{r:?}"));
    let n = LINKS;
    let names = |stem: &'static str| (1..=n).map(move |i| format!("{stem}{i}"));
    let mass_names = (1..=n).flat_map(|i| (1..=n).map(move |j| format!("MAS{i}X{j}")));
    let printed: Vec<ExprId> =
        mass_names.chain(names("FRC")).chain(names("EQN")).map(|k| scalar(&back, &k)).collect();
    let printed = eval(&back.model.ar, &printed);
    let ar = &derived.model.ar;
    let mut roots: Vec<ExprId> = e.mass_matrix.iter().flatten().copied().collect();
    roots.extend(&e.forcing);
    let values = eval(ar, &roots);
    let (mass, forcing) = values.split_at(n * n);
    let udot: Vec<f64> = e.speed_derivatives.iter().map(|u| value_of(&ar.symbol_info(*u).name)).collect();
    for i in 0..n {
        for j in 0..n {
            assert_close(&format!("M[{},{}]", i + 1, j + 1), printed[i * n + j], mass[i * n + j]);
        }
        assert_close(&format!("f[{}]", i + 1), printed[n * n + i], forcing[i]);
        let zero = forcing[i] - (0..n).map(|j| mass[i * n + j] * udot[j]).sum::<f64>();
        assert_close(&format!("ZERO[{}]", i + 1), printed[n * n + n + i], zero);
    }
}

/// The chain of rigid links pinned end to end (bodies `Bi` with mass centres at mid-link).
fn rigid_chain(n: usize) -> String {
    let b: Vec<String> = (1..=n).map(|i| format!("B{i}")).collect();
    let joint = |i: usize| if i == 0 { "O".to_string() } else { format!("J{i}") };
    let mut out = vec![
        "NEWTONIAN N".to_string(),
        format!("BODIES {}", b.join(", ")),
        format!("POINTS O, {}", (1..n).map(joint).collect::<Vec<_>>().join(", ")),
        format!("CONSTANTS L{{{n}}}, M{{{n}}}, I{{{n}}}, G"),
        format!("VARIABLES Q{{{n}}}', U{{{n}}}'"),
        "V_O_N> = 0>".into(),
    ];
    for i in 1..=n {
        let parent = if i == 1 { "N" } else { &b[i - 2] };
        out.push(format!("SIMPROT({parent}, B{i}, 3, Q{i})\nQ{i}' = U{i}"));
        out.push(format!(
            "P_{}_B{i}O> = L{i}/2*B{i}1>\nV2PTS(N, B{i}, {}, B{i}O)",
            joint(i - 1),
            joint(i - 1)
        ));
        if i < n {
            out.push(format!(
                "P_{}_{}> = L{i}*B{i}1>\nV2PTS(N, B{i}, {}, {})",
                joint(i - 1),
                joint(i),
                joint(i - 1),
                joint(i)
            ));
        }
        out.push(format!("MASS B{i} = M{i}\nINERTIA B{i}, 0, I{i}, I{i}"));
    }
    out.extend(["GRAVITY(-G*N2>)".to_string(), "ZERO = FR() + FRSTAR()".into(), "KANE()".into()]);
    out.join("\n") + "\n"
}

#[test]
fn a_long_partial_velocity_table_is_left_out_unless_asked_for() {
    let path = std::env::temp_dir().join(format!("kane_eoms_rigid{LINKS}_{}.al", std::process::id()));
    std::fs::write(&path, rigid_chain(LINKS)).unwrap();
    let file = path.to_str().unwrap();
    let (ok, out, err) = kane(&["eoms", file]);
    let (ok_all, all, err_all) = kane(&["eoms", file, "--partials"]);
    std::fs::remove_file(&path).ok();
    assert!(ok && ok_all, "{err}{err_all}");
    assert!(out.len() < 1_000_000, "eoms printed {} bytes", out.len());
    let note = out.lines().last().unwrap();
    assert!(note.contains("left out") && note.contains("--partials"), "{note}");
    assert!(!out.contains("V_B40O_N> / U1 ="));
    assert!(all.starts_with(out.rsplit_once("\n% Partial").unwrap().0), "the equations are the same");
    assert!(
        all.contains("V_B40O_N> / U1 = ") && all.contains("W_B40_N> / U40 = N3>"),
        "the table is printed whole"
    );
}
