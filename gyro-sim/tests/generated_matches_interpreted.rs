//! The generated `rhs` and `outputs` equal the interpreted equations of the same model file at
//! 1000 random states, to 1e-13 relative.

use gyro_sim::gimbal_gyroscope as gimbal;
use kane_model::runtime::GeneratedModel;
use kane_tests::{interpreted_rhs, value_of, worst_generated_difference, Sampling};
use rand::{Rng, SeedableRng};

/// The paper's gimbal file, with its equations in the collected form the code is generated from.
fn gimbal_file() -> (kane_model::lang::LoadedModel, kane_model::mechanics::KaneEquations) {
    let src = include_str!("../../kane-model/models/gimbal_gyroscope.al");
    let mut loaded = kane_model::lang::load("gimbal_gyroscope.al", src).unwrap();
    let mut simplified = loaded.equations.clone().unwrap();
    loaded.model.simplify_equations(&mut simplified).unwrap();
    (loaded, simplified)
}

/// Physical geometry: the frames' thickness W is below every height, so M is positive definite
/// (random W > H gives negative inertias and a near-singular M).
fn gimbal_param(name: &str, rng: &mut rand::rngs::StdRng) -> f64 {
    if name == "W" {
        rng.random_range(0.005..0.09)
    } else {
        rng.random_range(0.1..3.0)
    }
}

fn gimbal_state(i: usize, rng: &mut rand::rngs::StdRng) -> f64 {
    if i < 3 {
        rng.random_range(-3.0..3.0)
    } else {
        rng.random_range(-20.0..20.0)
    }
}

#[test]
fn generated_rhs_equals_the_interpreted_equations() {
    // Normwise relative difference of q' and of u' (a small u'_i that is the difference of large
    // terms carries their rounding; relative to the vector it is at round-off).
    let (loaded, eqs) = gimbal_file();
    let sampling = Sampling { seed: 41, samples: 1000, param: &gimbal_param, state: &gimbal_state };
    let worst = worst_generated_difference::<gimbal::Model>(&loaded.model.ar, &eqs, &sampling);
    assert!(worst < 1e-13, "largest normwise relative difference {worst:e}");
}

#[test]
fn generated_outputs_equal_the_interpreted_ones() {
    let (loaded, eqs) = gimbal_file();
    let Some(kane_model::lang::Value::Scalar(ap)) = loaded.value("AP") else { panic!("AP") };
    let ar = &loaded.model.ar;
    let mut rng = rand::rngs::StdRng::seed_from_u64(43);
    let mut worst: f64 = 0.0;
    for _ in 0..300 {
        let mut p = gimbal::Params::default();
        let mut vals: Vec<(String, f64)> = Vec::new();
        for name in gimbal::INFO.param_names {
            let v = gimbal_param(name, &mut rng);
            gimbal::Model::set_param(&mut p, name, v);
            vals.push((name.to_string(), v));
        }
        let y: Vec<f64> = (0..6).map(|i| gimbal_state(i, &mut rng)).collect();
        vals.extend(gimbal::INFO.state_names.iter().zip(&y).map(|(n, v)| (n.to_string(), *v)));
        let (_, udot) = interpreted_rhs(ar, &eqs, &|n| vals.iter().find(|(k, _)| k == n).map(|(_, v)| *v));
        vals.extend(["U1'", "U2'", "U3'"].iter().zip(&udot).map(|(n, v)| (n.to_string(), *v)));
        let mut out = [0.0; gimbal::N_OUTPUT_COLUMNS];
        gimbal::outputs(0.0, &y, &p, &mut out);
        let want = value_of(ar, ap, &|n| vals.iter().find(|(k, _)| k == n).map(|(_, v)| *v));
        worst = worst.max((out[0] - want).abs() / want.abs().max(1.0));
    }
    assert!(worst < 1e-13, "largest relative difference {worst:e}");
}

#[test]
fn generated_code_is_generic_over_the_number_type() {
    // The same rhs in f32 and with dual numbers (the directional derivative along u1).
    use kane_model::runtime::dual::Dual;
    let p = gimbal::Params::default();
    let y = [0.1, 0.2, 0.3, 0.4, 0.5, 10.0];
    let mut d64 = [0.0; 6];
    gimbal::rhs(0.0, &y, &p, &mut d64);
    let y32: Vec<f32> = y.iter().map(|v| *v as f32).collect();
    let mut d32 = [0.0f32; 6];
    gimbal::rhs(0.0f32, &y32, &p, &mut d32);
    for i in 0..6 {
        assert!((d32[i] as f64 - d64[i]).abs() < 1e-4 * d64[i].abs().max(1.0));
    }
    let yd: Vec<Dual<f64>> =
        y.iter().enumerate().map(|(i, v)| Dual::new(*v, if i == 3 { 1.0 } else { 0.0 })).collect();
    let mut dd = [Dual::new(0.0, 0.0); 6];
    gimbal::rhs(Dual::new(0.0, 0.0), &yd, &p, &mut dd);
    let h = 1e-6;
    let (mut plus, mut minus) = ([0.0; 6], [0.0; 6]);
    let (mut yp, mut ym) = (y, y);
    yp[3] += h;
    ym[3] -= h;
    gimbal::rhs(0.0, &yp, &p, &mut plus);
    gimbal::rhs(0.0, &ym, &p, &mut minus);
    for i in 0..6 {
        assert!((dd[i].re - d64[i]).abs() <= 4.0 * f64::EPSILON * d64[i].abs().max(1.0));
        let fd = (plus[i] - minus[i]) / (2.0 * h);
        assert!((dd[i].eps - fd).abs() < 1e-6 * fd.abs().max(1.0), "d y'{i}/d u1: {} vs {fd}", dd[i].eps);
    }
}

#[test]
fn jacobian_matches_central_differences() {
    let p = gimbal::Params::default();
    let y = [0.3, -0.4, 1.1, 0.7, -0.2, 12.0];
    let mut jac = [0.0; 36];
    gimbal::jacobian(0.0, &y, &p, &mut jac);
    for col in 0..6 {
        let h = 1e-6 * y[col].abs().max(1.0);
        let (mut yp, mut ym) = (y, y);
        yp[col] += h;
        ym[col] -= h;
        let (mut fp, mut fm) = ([0.0; 6], [0.0; 6]);
        gimbal::rhs(0.0, &yp, &p, &mut fp);
        gimbal::rhs(0.0, &ym, &p, &mut fm);
        for row in 0..6 {
            let fd = (fp[row] - fm[row]) / (2.0 * h);
            assert!(
                (jac[row * 6 + col] - fd).abs() < 1e-6 * fd.abs().max(1.0),
                "J[{row}][{col}] {} vs {fd}",
                jac[row * 6 + col]
            );
        }
    }
}

#[test]
fn direction_cosine_outputs_are_the_gimbal_rotations() {
    // `OUTPUT A_B, A_C, A_D`: A_X_ij = a_i . x_j. SIMPROT(A, B, -2, Q1) turns B about -A2, so
    // A_B = [[c1, 0, -s1], [0, 1, 0], [s1, 0, c1]]; each matrix is orthonormal and
    // A_D = A_C * C_D with C_D the turn about -C2 by Q3.
    let p = gimbal::Params::default();
    let dcm = |name: &str, y: &[f64]| -> [[f64; 3]; 3] {
        let k = gimbal::INFO.output(name).unwrap();
        assert_eq!(gimbal::INFO.outputs[k].kind, kane_model::runtime::OutputKind::Dcm);
        let mut out = [0.0; 9];
        gimbal::Model::output(k, 0.0, y, &[], &p, &mut out);
        [[out[0], out[1], out[2]], [out[3], out[4], out[5]], [out[6], out[7], out[8]]]
    };
    let y: [f64; 6] = [0.7, -0.4, 1.9, 0.0, 0.0, 0.0];
    let (s1, c1) = y[0].sin_cos();
    let b = dcm("A_B", &y);
    let want = [[c1, 0.0, -s1], [0.0, 1.0, 0.0], [s1, 0.0, c1]];
    for (r, w) in b.iter().zip(&want) {
        for (x, v) in r.iter().zip(w) {
            assert!((x - v).abs() < 1e-15, "A_B {b:?} vs {want:?}");
        }
    }
    let (s3, c3) = y[2].sin_cos();
    let c_d = [[c3, 0.0, -s3], [0.0, 1.0, 0.0], [s3, 0.0, c3]];
    let (c, d) = (dcm("A_C", &y), dcm("A_D", &y));
    for i in 0..3 {
        for j in 0..3 {
            let product: f64 = (0..3).map(|k| c[i][k] * c_d[k][j]).sum();
            assert!((product - d[i][j]).abs() < 1e-15, "A_D[{i}][{j}]");
            let gram: f64 = (0..3).map(|k| d[k][i] * d[k][j]).sum();
            assert!((gram - f64::from(u8::from(i == j))).abs() < 1e-15, "A_D orthonormal");
        }
    }
    assert_eq!(gimbal::INFO.outputs[gimbal::INFO.output("A_D").unwrap()].columns[5], "A_D_23");
}
