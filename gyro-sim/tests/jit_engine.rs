//! The JIT engine computes what the evaluator (the instant engine) computes: `rhs`, every output
//! the Taylor coefficients and the parameter constants, at random states of the gimbal, the heavy top, the bicycle, the
//! four-bar loop, the rolling disc and the 40-link chain.

use std::path::Path;
use std::sync::Arc;

use gyro_sim::ModelFile;
use kane_model::jit::JitModel;
use kane_model::program::ProgramModel;
use proptest::prelude::*;

const MODELS: [&str; 6] = [
    "../kane-model/models/gimbal_gyroscope.al",
    "../kane-model/models/heavy_top.al",
    "../kane-model/models/whipple_bicycle.al",
    "../kane-model/models/four_bar.al",
    "tests/data/rolling_disc.al",
    "tests/data/chain40_rigid.al",
];

/// Each model's evaluator (its drawing's outputs included) and its JIT-compiled twin.
fn models() -> &'static [(Arc<ProgramModel>, JitModel)] {
    static MODELS_MADE: std::sync::OnceLock<Vec<(Arc<ProgramModel>, JitModel)>> = std::sync::OnceLock::new();
    MODELS_MADE.get_or_init(|| {
        MODELS
            .iter()
            .map(|m| {
                let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(m);
                let source = std::fs::read_to_string(&path).unwrap();
                let file = ModelFile::from_source(&path, source, true).unwrap();
                let jit = JitModel::new(file.program.clone()).unwrap();
                (file.program, jit)
            })
            .collect()
    })
}

/// The largest difference, relative to the larger magnitude (at least 1).
fn relative(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs() / x.abs().max(y.abs()).max(1.0)).fold(0.0, f64::max)
}

/// Parameters near the defaults (1 where a model has none), scaled by `scale`.
fn params_of(model: &ProgramModel, scale: &[f64]) -> Vec<f64> {
    let defaults = model.default_params();
    defaults
        .iter()
        .enumerate()
        .map(|(i, &p)| if p.is_finite() { p } else { 1.0 } * scale[i % scale.len()])
        .collect()
}

fn check_model(which: usize, t: f64, raw: &[f64], scale: &[f64], order: usize) -> Result<(), TestCaseError> {
    let (evaluator, jit) = &models()[which];
    let info = evaluator.info();
    let n = info.state_names.len();
    let y: Vec<f64> = (0..n).map(|i| raw[i % raw.len()] * (1.0 + i as f64 / n as f64)).collect();
    let params = params_of(evaluator, scale);
    let constants = evaluator.param_constants(&params);
    let jit_constants = jit.param_constants(&params);
    prop_assert!(relative(&constants, &jit_constants) <= 1e-13, "{}: parameter constants", MODELS[which]);
    let (mut want, mut got) = (vec![0.0; n], vec![0.0; n]);
    evaluator.rhs(t, &y, &params, &constants, &mut want, &mut Vec::new());
    jit.rhs(t, &y, &params, &jit_constants, &mut got);
    prop_assert!(relative(&want, &got) <= 1e-13, "{}: rhs {want:?} against {got:?}", MODELS[which]);
    let rates = &want[info.n_coordinates..];
    for (k, output) in info.outputs.iter().enumerate() {
        let width = output.columns.len().max(9);
        let (mut want, mut got) = (vec![0.0; width], vec![0.0; width]);
        evaluator.output(k, t, &y, rates, &params, &mut want, &mut Vec::new());
        jit.output(k, t, &y, rates, &params, &mut got);
        let columns = output.columns.len();
        prop_assert!(
            relative(&want[..columns], &got[..columns]) <= 1e-13,
            "{}: output {}",
            MODELS[which],
            output.name
        );
    }
    check_taylor(which, t, &y, &params, order)
}

/// The Taylor coefficients through `(t, y)` up to `order`, on both engines, of a model that has
/// them.
fn check_taylor(which: usize, t: f64, y: &[f64], params: &[f64], order: usize) -> Result<(), TestCaseError> {
    let (evaluator, jit) = &models()[which];
    if evaluator.taylor_program().is_err() {
        return Ok(());
    }
    let constants = evaluator.param_constants(params);
    // Orders the JIT writes out and orders it loops over are both drawn.
    let (mut want, mut got) = (vec![0.0; y.len() * (order + 1)], vec![0.0; y.len() * (order + 1)]);
    let done = evaluator.taylor(t, y, params, &constants, order, &mut want, &mut Vec::new());
    prop_assert_eq!(done, Ok(true));
    prop_assert!(jit.taylor(t, y, params, &constants, order, &mut got, &mut Vec::new()));
    prop_assert!(jit.prepare_taylor() == Some(Ok(())), "{}: Taylor coefficients not compiled", MODELS[which]);
    // Near a singular configuration the coefficients grow without bound and their sums cancel:
    // any order of summation gives different digits there, so such states are not compared.
    let largest = want.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    prop_assume!(largest < 1e12);
    // Each coefficient to 1e-13 of the largest of its order (at least 1) where the JIT loops as
    // the evaluator does; orders written out sum as the generated Rust does (fused, in chains),
    // so there to 1e-10: the rolling disc's order 12 has differed by 1.2e-11 of its largest
    // coefficient, the four-bar loop's coefficients are small sums of large terms.
    // A closed loop's (the four-bar's dependent coordinates, solved through the loop) cancel
    // further near a singular configuration: order 8 has differed by 3e-8 there, so 1e-7.
    let straight_line = if evaluator.info().dependent_coordinates.is_empty() { 1e-10 } else { 1e-7 };
    let tolerance = if jit.taylor_straight_line().contains(&order) { straight_line } else { 1e-13 };
    let n1 = order + 1;
    for (j, (a, b)) in want.iter().zip(&got).enumerate() {
        let scale = want.iter().skip(j % n1).step_by(n1).fold(1.0f64, |m, c| m.max(c.abs()));
        prop_assert!(
            (a - b).abs() <= tolerance * scale,
            "{}: Taylor coefficient {j} of order {order}: {a:e} against {b:e}",
            MODELS[which]
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn the_jit_engine_equals_the_evaluator(
        which in 0..MODELS.len(),
        t in -3.0..3.0f64,
        raw in prop::collection::vec(-2.0..2.0f64, 1..12),
        scale in prop::collection::vec(0.5..2.0f64, 1..6),
        order in 1..=24usize,
    ) {
        check_model(which, t, &raw, &scale, order)?;
    }
}

#[test]
fn every_model_compiles_and_names_its_outputs() {
    for ((evaluator, jit), name) in models().iter().zip(MODELS) {
        assert_eq!(evaluator.info().name, jit.info().name, "{name}");
        assert!(!evaluator.info().outputs.is_empty(), "{name}");
        for k in 0..evaluator.info().outputs.len() {
            jit.prepare_output(k).unwrap();
        }
        let has_taylor = evaluator.taylor_program().is_ok();
        assert_eq!(jit.prepare_taylor().is_some(), has_taylor, "{name}");
        if has_taylor {
            jit.prepare_taylor().unwrap().unwrap();
        }
    }
    let (_, gimbal) = &models()[0];
    assert!(gimbal.taylor_straight_line().contains(&16), "the gimbal's order 16 is written out");
}
