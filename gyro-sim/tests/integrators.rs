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
    // DOP853's septic interpolant: as accurate between steps as at them, in a few dozen steps.
    let mut worst8: f64 = 0.0;
    let stats8 =
        integrate(&Oscillator, 0.0, &[0.0, 1.0], &times, Method::Adaptive(&tableau::DOP853, tol), |t, y| {
            worst8 = worst8.max((y[0] - t.sin()).abs()).max((y[1] - t.cos()).abs());
            Ok(())
        })
        .unwrap();
    assert!(worst8 < 1e-8, "dop853 largest error {worst8:e}");
    assert!(stats8.steps < 150, "dop853: {} steps for 1000 outputs", stats8.steps);
}

/// `y' = -2 t y`, `y = exp(-t^2)`: time enters the right-hand side, so every stage node counts.
struct Gaussian;

impl System for Gaussian {
    fn dim(&self) -> usize {
        1
    }
    fn rhs(&self, t: f64, y: &[f64], dy: &mut [f64]) {
        dy[0] = -2.0 * t * y[0];
    }
}

#[test]
fn dop853_dense_output_converges_with_its_order() {
    // Interpolation error at 0.013-spaced output times shrinks with the tolerance like the
    // steps' own error, and stays near it (a wrong extra stage or `d` row would not).
    let times: Vec<f64> = (0..=230).map(|i| i as f64 * 0.013).collect();
    let run = |tol: f64| {
        let mut worst: f64 = 0.0;
        let m = Method::Adaptive(&tableau::DOP853, Tolerances { rtol: tol, atol: tol });
        let stats = integrate(&Gaussian, 0.0, &[1.0], &times, m, |t, y| {
            worst = worst.max((y[0] - (-t * t).exp()).abs());
            Ok(())
        })
        .unwrap();
        (worst, stats.steps)
    };
    let (e6, s6) = run(1e-6);
    let (e10, s10) = run(1e-10);
    assert!(s6 < 100 && s10 < 200, "steps {s6}, {s10}");
    assert!(e6 < 1e-5, "tol 1e-6: error {e6:e}");
    assert!(e10 < 2e-9 && e10 < e6 * 1e-2, "tol 1e-10: error {e10:e} (tol 1e-6: {e6:e})");
}
