//! Generated code for mass matrices of every block shape equals the interpreted equations: the
//! triple pendulum (one full 3x3 block: unrolled LDL^T), the heavy top (1x1 blocks) and the gimbal
//! (a 2x2 and a 1x1 block, in gyro-sim's tests). Normwise relative difference of `y'` at random
//! states and parameters.

use kane_model::runtime::GeneratedModel;
use kane_tests::{worst_generated_difference, Sampling};
use rand::Rng;

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
    let sampling = Sampling {
        seed: 7,
        samples,
        param: &|_, rng| rng.random_range(0.2..2.0),
        state: &|_, rng| rng.random_range(-2.0..2.0),
    };
    worst_generated_difference::<M>(&loaded.model.ar, &eqs, &sampling)
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
