//! The integrators: observed order by step halving, tolerance proportionality, and errors for
//! a solution that blows up.

use gyro_sim::ode::{integrate, tableau, Method, OdeError, System, Tolerances};

/// y1' = y2, y2' = -y1: y = (sin t, cos t).
struct Oscillator;

impl System for Oscillator {
    fn dim(&self) -> usize {
        2
    }
    fn rhs(&self, _: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = y[1];
        dy[1] = -y[0];
    }
}

fn error_at_one(method: Method) -> f64 {
    let mut last = [0.0; 2];
    integrate(&Oscillator, 0.0, &[0.0, 1.0], &[1.0], method, |_, y| {
        last.copy_from_slice(y);
        Ok(())
    })
    .unwrap();
    ((last[0] - 1f64.sin()).powi(2) + (last[1] - 1f64.cos()).powi(2)).sqrt()
}

#[test]
fn observed_order_matches_each_tableau() {
    for (tab, order, h) in
        [(&tableau::RK4, 4.0, 0.1), (&tableau::DOPRI5, 5.0, 0.1), (&tableau::DOP853, 8.0, 0.25)]
    {
        let e1 = error_at_one(Method::Fixed(tab, h));
        let e2 = error_at_one(Method::Fixed(tab, h / 2.0));
        let observed = (e1 / e2).log2();
        assert!((observed - order).abs() < 0.3, "{}: observed order {observed}", tab.name);
    }
}

#[test]
fn adaptive_error_follows_the_tolerance() {
    for tab in [&tableau::DOPRI5, &tableau::DOP853] {
        let mut last = 1.0;
        for tol in [1e-6, 1e-8, 1e-10] {
            let e = error_at_one(Method::Adaptive(tab, Tolerances { rtol: tol, atol: tol }));
            assert!(e < 50.0 * tol, "{} tol {tol}: error {e}", tab.name);
            assert!(e < last, "{}", tab.name);
            last = e;
        }
    }
}

#[test]
fn each_tableau_is_consistent() {
    // Rows of a sum to c; weights sum to 1 (order conditions of order one).
    for tab in [&tableau::RK4, &tableau::DOPRI5, &tableau::DOP853] {
        for (i, row) in tab.a.iter().enumerate() {
            assert!((row.iter().sum::<f64>() - tab.c[i]).abs() < 1e-12, "{} row {i}", tab.name);
        }
        assert!((tab.b.iter().sum::<f64>() - 1.0).abs() < 1e-12, "{}", tab.name);
    }
}

/// y' = y^2, y(0) = 1: y = 1 / (1 - t) blows up at t = 1.
struct BlowUp;

impl System for BlowUp {
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&self, _: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = y[0] * y[0];
    }
}

#[test]
fn blow_up_is_an_error_not_a_hang() {
    let r = integrate(
        &BlowUp,
        0.0,
        &[1.0],
        &[2.0],
        Method::Adaptive(&tableau::DOPRI5, Tolerances { rtol: 1e-8, atol: 1e-8 }),
        |_, _| Ok(()),
    );
    match r {
        Err(OdeError::StepSizeUnderflow { time, .. }) | Err(OdeError::NonFinite { time, .. }) => {
            assert!((time - 1.0).abs() < 1e-2, "stopped at {time}")
        }
        other => panic!("expected an error near t = 1, got {other:?}"),
    }
    let r = integrate(&BlowUp, 0.0, &[1.0], &[2.0], Method::Fixed(&tableau::RK4, 0.01), |_, _| Ok(()));
    assert!(matches!(r, Err(OdeError::NonFinite { .. })), "{r:?}");
}

#[test]
fn dense_output_is_accurate_between_steps_and_saves_steps() {
    // 1001 output times on [0, 10]: interpolated values stay within the tolerance's reach, with far
    // fewer steps than landing on every output time would need.
    let times: Vec<f64> = (0..=1000).map(|i| i as f64 * 0.01).collect();
    let tol = Tolerances { rtol: 1e-9, atol: 1e-9 };
    let mut worst: f64 = 0.0;
    let stats =
        integrate(&Oscillator, 0.0, &[0.0, 1.0], &times, Method::Adaptive(&tableau::DOPRI5, tol), |t, y| {
            worst = worst.max((y[0] - t.sin()).abs()).max((y[1] - t.cos()).abs());
            Ok(())
        })
        .unwrap();
    assert!(worst < 1e-7, "largest error {worst:e}");
    assert!(stats.steps < 400, "{} steps for 1000 outputs", stats.steps);
    // DOP853 (no dense output here) lands on every output time.
    let landing =
        integrate(&Oscillator, 0.0, &[0.0, 1.0], &times, Method::Adaptive(&tableau::DOP853, tol), |_, _| {
            Ok(())
        })
        .unwrap();
    assert!(landing.steps >= 1000);
}
