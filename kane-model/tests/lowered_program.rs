//! The lowered program, run by its own evaluator, equals the interpreted equations:
//! `param_constants` then `rhs` (with the lowered solve of `M u' = f`) and the outputs, for the
//! paper's gimbal (a 2x2 and a 1x1 block) and a triple pendulum (a full 3x3 block: `LDL^T`).

use kane_model::program::ir::Input;
use kane_model::program::lower;
use nalgebra::{DMatrix, DVector};
use rand::{Rng, SeedableRng};

fn check(name: &str, src: &str, samples: usize) -> f64 {
    let loaded = kane_model::lang::load(name, src).unwrap();
    let eqs = loaded.equations.clone().unwrap();
    let mut spec = loaded.into_spec(name).unwrap();
    let lowered = lower(&mut spec).unwrap();
    let ar = &spec.model.ar;
    let (nq, n) = (eqs.coordinates.len(), eqs.speeds.len());
    let mut rng = rand::rngs::StdRng::seed_from_u64(11);
    let mut worst: f64 = 0.0;
    for _ in 0..samples {
        let p: Vec<f64> = lowered.params.iter().map(|_| rng.random_range(0.3..2.0)).collect();
        let y: Vec<f64> = (0..nq + n).map(|_| rng.random_range(-2.0..2.0)).collect();
        let mut constants = vec![0.0; lowered.program.param_constants.results.len()];
        lowered
            .program
            .param_constants
            .eval(|i| if let Input::Param(k) = i { p[k] } else { f64::NAN }, &mut constants);
        let mut dy = vec![0.0; nq + n];
        let read = |i: Input| match i {
            Input::Param(k) => p[k],
            Input::State(k) => y[k],
            Input::ParamConstant(k) => constants[k],
            Input::Time | Input::Rate(_) | Input::Slot(_) => 0.0,
        };
        lowered.program.rhs.eval(read, &mut dy);
        let at = |e| {
            ar.eval(&[e], |s| {
                let by_param = lowered.params.iter().position(|q| *q == s).map(|k| p[k]);
                by_param.or_else(|| lowered.states.iter().position(|q| *q == s).map(|k| y[k]))
            })
            .unwrap()[0]
        };
        let m = DMatrix::from_fn(n, n, |i, j| at(eqs.mass_matrix[i][j]));
        let f = DVector::from_fn(n, |i, _| at(eqs.forcing[i]));
        let udot = m.lu().solve(&f).unwrap();
        for (got, e) in dy.iter().zip(&eqs.kinematics) {
            worst = worst.max((got - at(*e)).abs());
        }
        let scale = udot.iter().fold(1.0f64, |a, v| a.max(v.abs()));
        for (got, want) in dy[nq..].iter().zip(udot.iter()) {
            worst = worst.max((got - want).abs() / scale);
        }
    }
    worst
}

#[test]
fn the_gimbals_lowered_rhs_equals_its_equations() {
    let worst = check("gimbal_gyroscope", include_str!("../models/gimbal_gyroscope.al"), 200);
    assert!(worst < 1e-12, "{worst:e}");
}

#[test]
fn a_full_mass_matrix_is_solved_by_the_lowered_ldlt() {
    let worst = check("triple_pendulum", include_str!("../../tests/models/triple_pendulum.al"), 200);
    assert!(worst < 1e-12, "{worst:e}");
}

#[test]
fn operation_counts_come_from_the_program() {
    let loaded = kane_model::lang::load("g.al", include_str!("../models/gimbal_gyroscope.al")).unwrap();
    let mut spec = loaded.into_spec("gimbal_gyroscope").unwrap();
    let lowered = lower(&mut spec).unwrap();
    let counts = lowered.program.op_counts();
    let (rhs, outputs) = (counts.rhs, counts.outputs);
    assert_eq!(rhs, lowered.program.rhs.op_count());
    // The gimbal's rhs: M, f and the 2x2 and 1x1 block solves, 38 operations before the redesign.
    assert!((30..=45).contains(&rhs), "{rhs}");
    assert!(outputs > 0);
    // |a_P| does not read q1 (cyclic in the equations and cancelled in the output).
    assert_eq!(lowered.program.cyclic, vec![0, 2]);
    assert!(!lowered.program.outputs[0].reads.contains(&0));
}
