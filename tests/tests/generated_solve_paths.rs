//! Generated code for mass matrices of every block shape equals the interpreted equations: the
//! triple pendulum (one full 3x3 block: unrolled LDL^T), the heavy top (1x1 blocks) and the gimbal
//! (a 2x2 and a 1x1 block, in gyro-sim's tests). Normwise relative difference of `y'` at random
//! states and parameters.

use kane_model::runtime::GeneratedModel;
use nalgebra::{DMatrix, DVector};
use rand::{Rng, SeedableRng};

mod triple_pendulum {
    kane_derive::model!("models/triple_pendulum.al");
}

mod heavy_top {
    kane_derive::model!("../kane-model/models/heavy_top.al");
}

/// The largest normwise relative difference between `M::rhs` and the interpreted equations of
/// the model file `src` at `samples` random states.
fn worst_difference<M: GeneratedModel>(src: &str, samples: usize) -> f64 {
    let loaded = kane_model::lang::load("model.al", src).unwrap();
    let eqs = loaded.equations.clone().unwrap();
    let ar = &loaded.model.ar;
    let (nq, n) = (eqs.coordinates.len(), eqs.speeds.len());
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    let mut worst: f64 = 0.0;
    for _ in 0..samples {
        let mut p = M::Params::default();
        let mut vals: Vec<(String, f64)> = Vec::new();
        for name in M::INFO.param_names {
            let v = rng.random_range(0.2..2.0);
            assert!(M::set_param(&mut p, name, v));
            vals.push((name.to_ascii_uppercase(), v));
        }
        let y: Vec<f64> = (0..nq + n).map(|_| rng.random_range(-2.0..2.0)).collect();
        for (name, v) in M::INFO.state_names.iter().zip(&y) {
            vals.push((name.to_ascii_uppercase(), *v));
        }
        let at = |e| {
            ar.eval(&[e], |s| {
                let name = ar.symbol_info(s).name.to_ascii_uppercase();
                vals.iter().find(|(k, _)| *k == name).map(|(_, v)| *v)
            })
            .unwrap()[0]
        };
        let m = DMatrix::from_fn(n, n, |i, j| at(eqs.mass_matrix[i][j]));
        let f = DVector::from_fn(n, |i, _| at(eqs.forcing[i]));
        let mut want: Vec<f64> = eqs.kinematics.iter().map(|e| at(*e)).collect();
        want.extend(m.lu().solve(&f).unwrap().iter());
        let mut got = vec![0.0; nq + n];
        M::rhs(0.0, &y, &p, &mut got);
        let normwise = |a: &[f64], b: &[f64]| {
            let diff = a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max);
            diff / b.iter().map(|v| v.abs()).fold(1.0, f64::max)
        };
        worst = worst.max(normwise(&got[..nq], &want[..nq])).max(normwise(&got[nq..], &want[nq..]));
    }
    worst
}

#[test]
fn a_full_mass_matrix_is_solved_by_the_unrolled_ldlt() {
    let worst = worst_difference::<triple_pendulum::Model>(include_str!("../models/triple_pendulum.al"), 500);
    assert!(worst < 1e-12, "largest normwise relative difference {worst:e}");
}

#[test]
fn a_diagonal_mass_matrix_is_solved_entry_by_entry() {
    let worst =
        worst_difference::<heavy_top::Model>(include_str!("../../kane-model/models/heavy_top.al"), 500);
    assert!(worst < 1e-12, "largest normwise relative difference {worst:e}");
}

#[test]
fn a_wrong_solve_would_be_seen() {
    // The comparison is sharp: the pendulum's equations with one mass changed differ.
    let src = include_str!("../models/triple_pendulum.al").replace("MASS P1 = M1", "MASS P1 = 2*M1");
    let worst = worst_difference::<triple_pendulum::Model>(&src, 20);
    assert!(worst > 1e-3, "{worst:e}");
}
