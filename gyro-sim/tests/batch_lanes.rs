//! Batch lanes: members integrated 4 and 8 at a time in lock step end where each alone ends,
//! to the tolerance asked, with a lane per member (parameters and initial states differ).

use std::ops::ControlFlow;

use gyro_sim::final_states;
use gyro_sim::gimbal_gyroscope as gimbal;
use gyro_sim::ModelSystem;
use gyro_sim::{tableau, Integration, Method, OdeError, Tolerances};
use kane_model::runtime::GeneratedModel;

fn members() -> Vec<(gimbal::Params, Vec<f64>)> {
    (0..11)
        .map(|i| {
            let mut p = gimbal::Params::default();
            gimbal::Model::set_param(&mut p, "Y", 2.0 * i as f64);
            gimbal::Model::set_param(&mut p, "Z", 20.0 - 1.5 * i as f64);
            (p, vec![0.1 * i as f64, 0.0, 0.0, 0.0, 0.0, 50.0 + 10.0 * i as f64])
        })
        .collect()
}

fn alone(p: &gimbal::Params, y0: &[f64], tol: f64) -> Vec<f64> {
    let sys = ModelSystem::<gimbal::Model>::new(p.clone());
    let mut end = Vec::new();
    let method = Method::Adaptive(&tableau::DOP853, Tolerances { rtol: tol, atol: tol });
    Integration::new(&sys, 0.0, y0, method)
        .run(&[2.0], |_, y| {
            end = y.to_vec();
            ControlFlow::Continue(())
        })
        .unwrap();
    end
}

#[test]
fn lanes_end_where_each_member_alone_ends() {
    let members = members();
    let tol = Tolerances { rtol: 1e-10, atol: 1e-10 };
    let (four, stats) = final_states::<gimbal::Model, 4>(&members, 2.0, &tableau::DOP853, tol).unwrap();
    let (eight, _) = final_states::<gimbal::Model, 8>(&members, 2.0, &tableau::DOP853, tol).unwrap();
    assert_eq!((four.len(), eight.len()), (11, 11));
    assert!(stats.steps > 100, "{stats:?}");
    for (k, (p, y0)) in members.iter().enumerate() {
        let exact = alone(p, y0, 1e-14);
        for got in [&four[k], &eight[k], &alone(p, y0, 1e-10)] {
            let err =
                got.iter().zip(&exact).map(|(a, b)| (a - b).abs() / b.abs().max(1.0)).fold(0.0, f64::max);
            assert!(err < 1e-6, "member {k}: {err:e}");
        }
        // Another member's parameters would end elsewhere: the lanes are not mixed up.
        let other = alone(&members[(k + 1) % 11].0, y0, 1e-10);
        assert!((other[3] - four[k][3]).abs() > 1e-3, "member {k}");
    }
}

#[test]
fn a_pair_without_an_error_estimate_is_refused() {
    let err = final_states::<gimbal::Model, 4>(
        &members(),
        1.0,
        &tableau::RK4,
        Tolerances { rtol: 1e-8, atol: 1e-8 },
    );
    assert!(matches!(err, Err(OdeError::NoErrorEstimate { method: "rk4" })), "{err:?}");
}
