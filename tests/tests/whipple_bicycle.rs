//! The Whipple bicycle of the benchmark (Meijaard, Papadopoulos, Ruina and Schwab 2007), from
//! `kane-model/models/whipple_bicycle.al`: three motion constraints solved numerically, the
//! linearisation by dual numbers through the lowered right-hand side. Its lean and steer rows
//! equal the benchmark's linear equations at 0 to 10 m/s, and its equations are finite and
//! agree, between eval's pivoted LU and the generated Householder solve, exactly upright.

use kane_model::program::linearize::linearize;
use kane_model::program::{lower, Lowered};
use kane_model::spec::ModelSpec;
use rustc_hash::FxHashMap;

const BICYCLE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/models/whipple_bicycle.al");
/// The same bicycle as a study's file writes it: the torques SPECIFIED and left open, the
/// dependent speeds among the outputs, the contacts' material points by V2PTS.
const AS_WRITTEN: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/data/whipple_as_written.al");

/// The benchmark's published mass matrix `M` in roll and steer.
const M: [[f64; 2]; 2] = [[80.81722, 2.31941332208709], [2.31941332208709, 0.29784188199686]];

/// The lean and steer rows of `A` for (roll, steer, roll rate, steer rate) at speed `v`, the
/// benchmark's `-M^-1 (g K0 + v^2 K2)` and `-M^-1 v C1` (as SymPy's bicycle test writes them).
fn benchmark_rows(v: f64) -> [[f64; 4]; 2] {
    [
        [
            9.48977444677355,
            -0.891197738059089 * v * v - 0.571523173729245,
            -0.105522449805691 * v,
            -0.330515398992311 * v,
        ],
        [
            11.7194768719633,
            -1.97171508499972 * v * v + 30.9087533932407,
            3.67680523332152 * v,
            -3.08486552743311 * v,
        ],
    ]
}

struct Bicycle {
    spec: ModelSpec,
    lowered: Lowered,
    values: FxHashMap<String, f64>,
}

fn bicycle() -> Bicycle {
    bicycle_from(BICYCLE)
}

fn bicycle_from(path: &str) -> Bicycle {
    let source = std::fs::read_to_string(path).unwrap();
    let checked =
        kane_model::lang::check_for_generation(path, &source).unwrap_or_else(|r| panic!("{}", r.render()));
    assert!(checked.warnings.diagnostics.is_empty(), "{}", checked.warnings.render());
    let loaded = checked.model;
    let mut spec = loaded.into_spec("whipple_bicycle").unwrap();
    let values = spec.defaults.clone();
    let lowered = lower(&mut spec).unwrap();
    Bicycle { spec, lowered, values }
}

impl Bicycle {
    fn position(&self, list: &[kane_model::expr::SymbolId], name: &str) -> usize {
        list.iter().position(|s| self.spec.symbol_name(*s) == name).unwrap()
    }

    /// Parameters and state with `sets` applied.
    fn point(&self, sets: &[(&str, f64)]) -> (Vec<f64>, Vec<f64>) {
        let mut values = self.values.clone();
        values.extend(sets.iter().map(|(k, v)| (k.to_string(), *v)));
        let of = |s: &kane_model::expr::SymbolId| values[&self.spec.symbol_name(*s).to_ascii_uppercase()];
        (self.lowered.params.iter().map(of).collect(), self.lowered.states.iter().map(of).collect())
    }
}

#[test]
fn lean_and_steer_equal_the_benchmark_from_0_to_10_m_per_s() {
    assert_benchmark_rows(&bicycle());
}

#[test]
fn the_file_as_a_study_writes_it_linearises_to_the_benchmark_with_its_torques_as_inputs() {
    let b = bicycle_from(AS_WRITTEN);
    let inputs: Vec<&str> = b.spec.inputs.iter().map(|s| b.spec.symbol_name(*s)).collect();
    assert_eq!(inputs, ["TPHI", "TDELTA"]);
    let outputs: Vec<&str> = b.spec.outputs.iter().map(|o| o.name.as_str()).collect();
    assert!(["U1", "U4", "U6", "U1'"].iter().all(|u| outputs.contains(u)), "{outputs:?}");
    assert_benchmark_rows(&b);
    assert_table_2(&b);
}

/// The lean and steer rows of `A` and the torques' columns of `B` equal the benchmark's.
fn assert_benchmark_rows(b: &Bicycle) {
    let rows = ["Q2", "Q5", "U2", "U5"].map(|n| b.position(&b.lowered.states, n));
    let inputs = ["TPHI", "TDELTA"].map(|n| b.position(&b.lowered.params, n));
    for v in 0..=10 {
        let v = f64::from(v);
        let (params, y) = b.point(&[("V", v)]);
        let l = linearize(&b.lowered.program, &params, 0.0, &y, &inputs);
        let want = benchmark_rows(v);
        for (k, i) in rows[2..].iter().enumerate() {
            for (j, col) in rows.iter().enumerate() {
                let (got, w) = (l.a[*i][*col], want[k][j]);
                assert!((got - w).abs() <= 1e-12 * w.abs().max(1.0), "v = {v}: A[{k}][{j}] = {got} vs {w}");
            }
        }
        // B for the roll and steer torques is M^-1.
        let det = M[0][0] * M[1][1] - M[0][1] * M[1][0];
        let inverse = [[M[1][1] / det, -M[0][1] / det], [-M[1][0] / det, M[0][0] / det]];
        for (k, i) in rows[2..].iter().enumerate() {
            for (j, w) in inverse[k].iter().enumerate() {
                let got = l.b[*i][j];
                assert!((got - w).abs() <= 1e-12 * w.abs().max(1.0), "v = {v}: B[{k}][{j}] = {got} vs {w}");
            }
        }
    }
}

#[test]
fn upright_and_nearly_upright_rates_are_finite_and_agree() {
    let b = bicycle();
    for roll in [0.0, 1e-9, 1e-3] {
        let (params, y) = b.point(&[("Q2", roll), ("V", 5.0), ("U5", 0.1)]);
        let values: FxHashMap<String, f64> = b
            .lowered
            .params
            .iter()
            .zip(&params)
            .chain(b.lowered.states.iter().zip(&y))
            .map(|(s, v)| (b.spec.symbol_name(*s).to_ascii_uppercase(), *v))
            .collect();
        let generated = kane_tests::lowered_rhs(&b.spec, &b.lowered, &values, &y);
        let by_name = |n: &str| values.get(n).copied();
        let (qdot, udot) = kane_tests::interpreted_rhs(&b.spec.model.ar, &b.spec.equations, &by_name);
        let eval: Vec<f64> = qdot.into_iter().chain(udot).collect();
        assert!(generated.iter().chain(&eval).all(|x| x.is_finite()), "roll {roll}: {generated:?} {eval:?}");
        let d = kane_tests::normwise(&generated, &eval);
        assert!(d < 1e-12, "roll {roll}: generated vs eval {d:e}");
    }
}

/// The lean and steer block of `A` (roll, steer and their rates) at speed `v`.
fn lean_steer_block(b: &Bicycle, v: f64) -> [[f64; 4]; 4] {
    let rows = ["Q2", "Q5", "U2", "U5"].map(|n| b.position(&b.lowered.states, n));
    let (params, y) = b.point(&[("V", v)]);
    let l = linearize(&b.lowered.program, &params, 0.0, &y, &[]);
    rows.map(|i| rows.map(|j| l.a[i][j]))
}

/// `det(s I - a) = s^4 + c[1] s^3 + c[2] s^2 + c[3] s + c[4]` (Faddeev-LeVerrier).
fn characteristic(a: &[[f64; 4]; 4]) -> [f64; 5] {
    let mul = |x: &[[f64; 4]; 4], y: &[[f64; 4]; 4]| -> [[f64; 4]; 4] {
        std::array::from_fn(|i| std::array::from_fn(|j| (0..4).map(|k| x[i][k] * y[k][j]).sum()))
    };
    let mut c = [1.0, 0.0, 0.0, 0.0, 0.0];
    let mut m = [[0.0; 4]; 4];
    for k in 1..=4 {
        let am = mul(a, &m);
        m = std::array::from_fn(|i| std::array::from_fn(|j| am[i][j] + if i == j { c[k - 1] } else { 0.0 }));
        let am = mul(a, &m);
        c[k] = -(0..4).map(|i| am[i][i]).sum::<f64>() / k as f64;
    }
    c
}

/// The root of `f` in `[lo, hi]` by bisection (a sign change is asserted).
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let f_lo = f(lo);
    assert!(f_lo * f(hi) < 0.0, "no sign change in [{lo}, {hi}]");
    for _ in 0..60 {
        let mid = 0.5 * (lo + hi);
        if (f(mid) > 0.0) == (f_lo > 0.0) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn weave_and_capsize_speeds_equal_the_benchmark() {
    // The benchmark's 4.29238254 and 6.02426202 m/s: the weave pair crosses the imaginary axis
    // where the Hurwitz determinant a3 a2 a1 - a1^2 - a3^2 a0 vanishes, the capsize root where
    // a0 = det(A) does.
    let b = bicycle();
    let weave = bisect(
        |v| {
            let c = characteristic(&lean_steer_block(&b, v));
            c[1] * c[2] * c[3] - c[3] * c[3] - c[1] * c[1] * c[4]
        },
        3.0,
        5.0,
    );
    let capsize = bisect(|v| characteristic(&lean_steer_block(&b, v))[4], 5.0, 7.0);
    assert!((weave - 4.29238254).abs() < 1e-8, "weave speed {weave}");
    assert!((capsize - 6.02426202).abs() < 1e-8, "capsize speed {capsize}");
}

/// The benchmark's Table 2 (Meijaard, Papadopoulos, Ruina and Schwab 2007): the eigenvalues
/// of the lean and steer motion at 0, 1, ..., 10 m/s as printed, (real, imaginary) with the
/// imaginary part of the upper member of each complex pair.
const TABLE_2: [[(f64, f64); 4]; 11] = [
    [(5.53094371765393, 0.0), (3.13164324790656, 0.0), (-3.13164324790656, 0.0), (-5.53094371765393, 0.0)],
    [
        (3.52696170990070, 0.80774027519930),
        (3.52696170990070, -0.80774027519930),
        (-3.13423125066578, 0.0),
        (-7.11008014637442, 0.0),
    ],
    [
        (2.68234517512745, 1.68066296590675),
        (2.68234517512745, -1.68066296590675),
        (-3.07158645641514, 0.0),
        (-8.67387984831735, 0.0),
    ],
    [
        (1.70675605663975, 2.31582447384325),
        (1.70675605663975, -2.31582447384325),
        (-2.63366137253667, 0.0),
        (-10.3510146724592, 0.0),
    ],
    [
        (0.41325331521125, 3.07910818603206),
        (0.41325331521125, -3.07910818603206),
        (-1.42944427361326, 0.0),
        (-12.15861426576447, 0.0),
    ],
    [
        (-0.77534188219585, 4.46486771378823),
        (-0.77534188219585, -4.46486771378823),
        (-0.32286642900409, 0.0),
        (-14.07838969279822, 0.0),
    ],
    [
        (-1.52644486584142, 5.87673060598709),
        (-1.52644486584142, -5.87673060598709),
        (-0.00406690076970, 0.0),
        (-16.08537123098026, 0.0),
    ],
    [
        (-2.13875644258362, 7.19525913329805),
        (-2.13875644258362, -7.19525913329805),
        (0.10268170574766, 0.0),
        (-18.15788466125262, 0.0),
    ],
    [
        (-2.69348683581097, 8.46037971396931),
        (-2.69348683581097, -8.46037971396931),
        (0.14327879765713, 0.0),
        (-20.27940894394569, 0.0),
    ],
    [
        (-3.21675402252485, 9.69377351531791),
        (-3.21675402252485, -9.69377351531791),
        (0.15790184030917, 0.0),
        (-22.43788559040858, 0.0),
    ],
    [
        (-3.72016840437287, 10.90681139476287),
        (-3.72016840437287, -10.90681139476287),
        (0.16105338653172, 0.0),
        (-24.62459635017404, 0.0),
    ],
];

#[test]
fn eigenvalues_equal_the_benchmark_table_to_its_printed_digits() {
    assert_table_2(&bicycle());
}

/// The lean and steer eigenvalues equal the benchmark's Table 2.
fn assert_table_2(b: &Bicycle) {
    let mut worst = 0.0_f64;
    for (v, row) in TABLE_2.iter().enumerate() {
        let a = lean_steer_block(b, v as f64);
        let m = nalgebra::Matrix4::from_fn(|i, j| a[i][j]);
        let mut got: Vec<nalgebra::Complex<f64>> = m.complex_eigenvalues().iter().copied().collect();
        for &(re, im) in row {
            let want = nalgebra::Complex::new(re, im);
            let k = (0..got.len())
                .min_by(|&x, &y| (got[x] - want).norm().total_cmp(&(got[y] - want).norm()))
                .unwrap();
            let error = (got.remove(k) - want).norm();
            // 1e-12 relative; for the eigenvalues near zero (capsize near 6 m/s) half a unit of
            // the table's 14th decimal plus what a backward-stable eigensolver may add in
            // double precision, 4 eps |A|.
            let allowed = (1e-12 * want.norm()).max(5e-15 + 4.0 * f64::EPSILON * m.norm());
            println!("v = {v}: {want}: {error:.1e} (allowed {allowed:.1e})");
            worst = worst.max(error / want.norm());
            assert!(error <= allowed, "v = {v}: {want} off by {error:e} (allowed {allowed:e})");
        }
    }
    println!("largest relative difference from Table 2: {worst:e}");
}

#[test]
fn the_pitch_is_solved_from_the_front_contact_and_is_mirror_symmetric() {
    // CONFIG[1]: the front contact on the ground determines the pitch Q4 from roll and steer.
    let source = std::fs::read_to_string(BICYCLE).unwrap();
    let loaded = kane_model::lang::check_for_generation(BICYCLE, &source).unwrap().model;
    let values: FxHashMap<String, f64> =
        loaded.inputs.iter().map(|i| (i.name.to_ascii_uppercase(), i.value)).collect();
    let mut spec = loaded.into_spec("whipple_bicycle").unwrap();
    let model = kane_model::program::ProgramModel::new(&mut spec).unwrap();
    let info = model.info();
    assert_eq!(info.dependent_coordinates.iter().map(|k| info.state_names[*k]).collect::<Vec<_>>(), ["Q4"]);
    let params: Vec<f64> = info.param_names.iter().map(|n| values[*n]).collect();
    let pitch = |roll: f64, steer: f64| {
        let mut y: Vec<f64> = info.state_names.iter().map(|n| values[*n]).collect();
        y[info.state("Q2").unwrap()] = roll;
        y[info.state("Q5").unwrap()] = steer;
        let a = model.assemble(&params, &mut y).unwrap().unwrap();
        assert!(a.residual < 1e-15, "{a:?}");
        (y[info.state("Q4").unwrap()], a.iterations)
    };
    assert_eq!(pitch(0.0, 0.0), (0.0, 0), "upright is assembled as it stands");
    let (p, steps) = pitch(0.2, 0.3);
    assert!(steps > 0 && p.abs() > 1e-3, "pitch {p} after {steps} steps");
    let (mirror, _) = pitch(-0.2, -0.3);
    assert!((p - mirror).abs() < 1e-14, "{p} vs {mirror}");
    // Leaning alone, front wheel straight, tilts the bicycle about the line through its two
    // contacts: no pitch.
    let (lean_only, _) = pitch(0.2, 0.0);
    assert!(lean_only.abs() < 1e-15, "pitch {lean_only} at roll alone");
}
