//! The integrators: observed order by step halving, tolerance proportionality, errors for a
//! solution that blows up, and the stepper used step by step (stop times, interpolation, early
//! stops, the method table).

use std::ops::ControlFlow;

use gyro_sim::test_problems::{BlowUp, ClosedForm, Gaussian, Oscillator};
use gyro_sim::{
    by_name, tableau, ErkStepper, Integration, Method, OdeError, Stepper, StopReason, Tolerances,
};

/// The distance of `y` from the oscillator's solution through `(0, [0, 1])` at `t`.
fn oscillator_error(t: f64, y: &[f64]) -> f64 {
    let exact = Oscillator.solution(0.0, &[0.0, 1.0], t);
    ((y[0] - exact[0]).powi(2) + (y[1] - exact[1]).powi(2)).sqrt()
}

/// The error at `t_end` of [`Oscillator`] integrated from `(0, [0, 1])` by `method`.
fn error_at(t_end: f64, method: Method) -> f64 {
    let mut last = [0.0; 2];
    Integration::new(&Oscillator, 0.0, &[0.0, 1.0], method)
        .run(&[t_end], |_, y| {
            last.copy_from_slice(y);
            ControlFlow::Continue(())
        })
        .unwrap();
    oscillator_error(t_end, &last)
}

#[test]
fn observed_order_matches_each_tableau() {
    for (tab, order, h) in [
        (&tableau::RK4, 4.0, 0.1),
        (&tableau::DOPRI5, 5.0, 0.1),
        (&tableau::DOP853, 8.0, 0.25),
        (&tableau::VERN7, 7.0, 0.25),
    ] {
        let e1 = error_at(1.0, Method::Fixed(tab, h));
        let e2 = error_at(1.0, Method::Fixed(tab, h / 2.0));
        let observed = (e1 / e2).log2();
        assert!((observed - order).abs() < 0.3, "{}: observed order {observed}", tab.name);
    }
}

#[test]
fn adaptive_error_follows_the_tolerance() {
    for tab in [&tableau::DOPRI5, &tableau::DOP853, &tableau::VERN7, &tableau::VERN9] {
        let mut last = 1.0;
        for tol in [1e-6, 1e-8, 1e-10] {
            let e = error_at(1.0, Method::Adaptive(tab, Tolerances { rtol: tol, atol: tol }));
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

#[test]
fn blow_up_is_an_error_not_a_hang() {
    let r = Integration::new(
        &BlowUp,
        0.0,
        &[1.0],
        Method::Adaptive(&tableau::DOPRI5, Tolerances { rtol: 1e-8, atol: 1e-8 }),
    )
    .run(&[2.0], |_, _| ControlFlow::Continue(()));
    match r {
        Err(OdeError::StepSizeUnderflow { time, .. }) | Err(OdeError::NonFinite { time, .. }) => {
            assert!((time - 1.0).abs() < 1e-2, "stopped at {time}")
        }
        other => panic!("expected an error near t = 1, got {other:?}"),
    }
    let r = Integration::new(&BlowUp, 0.0, &[1.0], Method::Fixed(&tableau::RK4, 0.01))
        .run(&[2.0], |_, _| ControlFlow::Continue(()));
    assert!(matches!(r, Err(OdeError::NonFinite { .. })), "{r:?}");
}

#[test]
fn dense_output_is_accurate_between_steps_and_saves_steps() {
    // 1001 output times on [0, 10]: interpolated values stay within the tolerance's reach, with far
    // fewer steps than landing on every output time would need.
    let times: Vec<f64> = (0..=1000).map(|i| i as f64 * 0.01).collect();
    let tol = Tolerances { rtol: 1e-9, atol: 1e-9 };
    let mut worst: f64 = 0.0;
    let stats = Integration::new(&Oscillator, 0.0, &[0.0, 1.0], Method::Adaptive(&tableau::DOPRI5, tol))
        .run(&times, |t, y| {
            worst = worst.max((y[0] - t.sin()).abs()).max((y[1] - t.cos()).abs());
            ControlFlow::Continue(())
        })
        .unwrap()
        .stats;
    assert!(worst < 1e-7, "largest error {worst:e}");
    assert!(stats.steps < 400, "{} steps for 1000 outputs", stats.steps);
    // DOP853's septic interpolant: as accurate between steps as at them, in a few dozen steps.
    let mut worst8: f64 = 0.0;
    let stats8 = Integration::new(&Oscillator, 0.0, &[0.0, 1.0], Method::Adaptive(&tableau::DOP853, tol))
        .run(&times, |t, y| {
            worst8 = worst8.max((y[0] - t.sin()).abs()).max((y[1] - t.cos()).abs());
            ControlFlow::Continue(())
        })
        .unwrap()
        .stats;
    assert!(worst8 < 1e-8, "dop853 largest error {worst8:e}");
    assert!(stats8.steps < 150, "dop853: {} steps for 1000 outputs", stats8.steps);
}

/// The largest dense-output error of `tab` at tolerance `tol` over 231 output times of
/// [`Gaussian`] on [0, 3] (0.013 apart), and the steps taken.
fn gaussian_dense_error(tab: &'static tableau::Tableau, tol: f64) -> (f64, usize) {
    let times: Vec<f64> = (0..=230).map(|i| i as f64 * 0.013).collect();
    let mut worst: f64 = 0.0;
    let m = Method::Adaptive(tab, Tolerances { rtol: tol, atol: tol });
    let stats = Integration::new(&Gaussian, 0.0, &[1.0], m)
        .run(&times, |t, y| {
            worst = worst.max((y[0] - Gaussian.solution(0.0, &[1.0], t)[0]).abs());
            ControlFlow::Continue(())
        })
        .unwrap()
        .stats;
    (worst, stats.steps)
}

#[test]
fn dop853_dense_output_converges_with_its_order() {
    // Interpolation error at 0.013-spaced output times shrinks with the tolerance like the
    // steps' own error, and stays near it (a wrong extra stage or `d` row would not).
    let run = |tol: f64| gaussian_dense_error(&tableau::DOP853, tol);
    let (e6, s6) = run(1e-6);
    let (e10, s10) = run(1e-10);
    assert!(s6 < 100 && s10 < 200, "steps {s6}, {s10}");
    assert!(e6 < 1e-5, "tol 1e-6: error {e6:e}");
    assert!(e10 < 2e-9 && e10 < e6 * 1e-2, "tol 1e-10: error {e10:e} (tol 1e-6: {e6:e})");
}

/// Output times through an `Integration`: the values and the cost, stopping after `limit` outputs.
fn through_integration(method: Method, times: &[f64], limit: usize) -> (Vec<[f64; 2]>, gyro_sim::Stats) {
    let mut rows = Vec::new();
    let stats = Integration::new(&Oscillator, 0.0, &[0.0, 1.0], method)
        .run(times, |_, y| {
            rows.push([y[0], y[1]]);
            if rows.len() == limit {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        })
        .unwrap()
        .stats;
    (rows, stats)
}

/// The same by hand: step to the last time, interpolating the times inside each step, until
/// `limit` outputs.
fn through_stepper(method: Method, times: &[f64], limit: usize) -> (Vec<[f64; 2]>, gyro_sim::Stats) {
    let mut stepper = ErkStepper::new(&Oscillator, 0.0, &[0.0, 1.0], method).unwrap();
    stepper.set_stop_time(*times.last().unwrap());
    let mut rows = Vec::new();
    let mut next = times.iter().peekable();
    let mut y = [0.0; 2];
    while rows.len() < limit {
        while let Some(&&t) = next.peek() {
            if t > stepper.t() || rows.len() == limit {
                break;
            }
            stepper.interpolate(t, &mut y).unwrap();
            rows.push(y);
            next.next();
        }
        if rows.len() == limit
            || stepper.step().unwrap() == StopReason::StopTimeReached && next.peek().is_none()
        {
            break;
        }
    }
    (rows, stepper.stats())
}

#[test]
fn the_stepper_by_hand_gives_the_integration_s_numbers() {
    let times: Vec<f64> = (0..=500).map(|i| f64::from(i) * 0.02).collect();
    let tol = Tolerances { rtol: 1e-9, atol: 1e-9 };
    for tab in [&tableau::DOPRI5, &tableau::DOP853, &tableau::VERN7, &tableau::VERN9] {
        let m = Method::Adaptive(tab, tol);
        let (by_integration, stats) = through_integration(m, &times, usize::MAX);
        let (by_hand, hand_stats) = through_stepper(m, &times, usize::MAX);
        assert_eq!(by_integration.len(), times.len());
        assert_eq!(stats, hand_stats, "{}", tab.name);
        let bits = |rows: &[[f64; 2]]| rows.iter().flatten().map(|v| v.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&by_integration), bits(&by_hand), "{}", tab.name);
        // Most outputs fall inside steps: the interpolant did the work.
        assert!(stats.steps < times.len(), "{}: {} steps", tab.name, stats.steps);
    }
}

#[test]
fn the_stepper_lands_on_its_stop_time() {
    // Fixed steps: 0.3 shortened evenly to four steps of 0.25; the last ends on 1 exactly.
    let mut stepper =
        ErkStepper::new(&Oscillator, 0.0, &[0.0, 1.0], Method::Fixed(&tableau::RK4, 0.3)).unwrap();
    stepper.set_stop_time(1.0);
    let mut reasons = Vec::new();
    let mut times = Vec::new();
    for _ in 0..4 {
        reasons.push(stepper.step().unwrap());
        times.push(stepper.t());
    }
    assert_eq!(reasons[..3], [StopReason::StepTaken; 3]);
    assert_eq!(reasons[3], StopReason::StopTimeReached);
    assert_eq!(times, [0.25, 0.5, 0.75, 1.0]);
    // At the stop time no step is taken; a later stop time goes on from there.
    assert_eq!(stepper.step().unwrap(), StopReason::StopTimeReached);
    assert_eq!(stepper.stats().steps, 4);
    stepper.set_stop_time(1.5);
    while stepper.step().unwrap() == StopReason::StepTaken {}
    assert_eq!((stepper.t(), stepper.stats().steps), (1.5, 6));
    // Adaptive: many steps, the last on the stop time exactly.
    let tol = Tolerances { rtol: 1e-10, atol: 1e-10 };
    let mut stepper =
        ErkStepper::new(&Oscillator, 0.0, &[0.0, 1.0], Method::Adaptive(&tableau::DOP853, tol)).unwrap();
    stepper.set_stop_time(std::f64::consts::PI);
    let mut steps = 0;
    while stepper.step().unwrap() == StopReason::StepTaken {
        steps += 1;
        assert!(stepper.t() < std::f64::consts::PI);
    }
    assert_eq!(stepper.t(), std::f64::consts::PI);
    assert!(steps > 5 && stepper.y()[0].abs() < 1e-9, "{steps} steps, y {:?}", stepper.y());
}

#[test]
fn breaking_early_is_ok_with_the_cost_so_far() {
    let times: Vec<f64> = (0..=50).map(|i| f64::from(i) * 0.2).collect();
    let m = Method::Adaptive(&tableau::DOP853, Tolerances { rtol: 1e-9, atol: 1e-9 });
    let (all, full) = through_integration(m, &times, usize::MAX);
    let (some, partial) = through_integration(m, &times, 10);
    assert_eq!(some.len(), 10);
    assert_eq!(some[..], all[..10]);
    assert!(0 < partial.steps && partial.steps < full.steps, "{partial:?} vs {full:?}");
    assert_eq!(partial, through_stepper(m, &times, 10).1);
    // Landing on every output time (fixed steps) stops as early.
    let (rows, stats) = through_integration(Method::Fixed(&tableau::RK4, 0.05), &times, 3);
    assert_eq!((rows.len(), stats.steps), (3, 8));
}

#[test]
fn unknown_method_names_are_none() {
    assert!(by_name("euler").is_none());
    assert!(by_name("").is_none());
    for (name, adaptive, order) in [
        ("dop853", true, Some(8)),
        ("dopri5", true, Some(5)),
        ("vern7", true, Some(7)),
        ("vern9", true, Some(9)),
        ("rk4", false, Some(4)),
        ("taylor", true, None),
    ] {
        let info = by_name(name).unwrap();
        assert_eq!((info.name(), info.adaptive, info.order()), (name, adaptive, order));
    }
}

#[test]
fn interpolation_outside_the_last_step_is_an_error() {
    let tol = Tolerances { rtol: 1e-8, atol: 1e-8 };
    let mut stepper =
        ErkStepper::new(&Oscillator, 0.0, &[0.0, 1.0], Method::Adaptive(&tableau::DOPRI5, tol)).unwrap();
    let mut y = [0.0; 2];
    // Before the first step only t0 is known.
    assert!(matches!(stepper.interpolate(0.1, &mut y), Err(OdeError::OutsideStep { .. })));
    stepper.interpolate(0.0, &mut y).unwrap();
    assert_eq!(y, [0.0, 1.0]);
    stepper.step().unwrap();
    stepper.step().unwrap();
    let (a, b) = (stepper.step_start(), stepper.t());
    assert!(0.0 < a && a < b);
    for t in [0.0, a - 1e-9, b + 1e-9, f64::NAN] {
        assert!(matches!(stepper.interpolate(t, &mut y), Err(OdeError::OutsideStep { .. })), "t = {t}");
    }
    stepper.interpolate(0.5 * (a + b), &mut y).unwrap();
    let t = 0.5 * (a + b);
    assert!((y[0] - t.sin()).abs() < 1e-7 && (y[1] - t.cos()).abs() < 1e-7);
    assert!(matches!(stepper.interpolate(t, &mut [0.0; 3]), Err(OdeError::DimensionMismatch { .. })));
    // Without a continuous extension only the ends of a step are known.
    let mut rk4 = ErkStepper::new(&Oscillator, 0.0, &[0.0, 1.0], Method::Fixed(&tableau::RK4, 0.1)).unwrap();
    rk4.step().unwrap();
    assert!(matches!(rk4.interpolate(0.05, &mut y), Err(OdeError::NoDenseOutput { method: "rk4" })));
    rk4.interpolate(0.1, &mut y).unwrap();
    assert_eq!(y, rk4.y());
}

#[test]
fn steppers_check_dimensions_and_the_start() {
    let m = Method::Fixed(&tableau::RK4, 0.1);
    let wrong = ErkStepper::<_, 3>::new_sized(&Oscillator, 0.0, &[0.0, 1.0], m);
    assert!(matches!(wrong, Err(OdeError::DimensionMismatch { expected: 3, found: 2 })));
    assert!(matches!(ErkStepper::new(&Oscillator, 0.0, &[0.0], m), Err(OdeError::DimensionMismatch { .. })));
    assert!(matches!(
        ErkStepper::new(&Oscillator, 0.0, &[f64::NAN, 1.0], m),
        Err(OdeError::NonFinite { .. })
    ));
    // A compile-time dimension gives the same numbers as any.
    let mut sized = ErkStepper::<_, 2>::new_sized(&Oscillator, 0.0, &[0.0, 1.0], m).unwrap();
    let mut any = ErkStepper::new(&Oscillator, 0.0, &[0.0, 1.0], m).unwrap();
    for _ in 0..10 {
        sized.step().unwrap();
        any.step().unwrap();
    }
    assert_eq!(sized.y(), any.y());
}

/// The step limit holds inside every stepping loop: a fixed step far smaller than the output
/// interval stops after `max_steps` steps, before the first output time (it used to be checked
/// only between output times, so a tiny step ran for ~35 minutes), and so does an adaptive run.
#[test]
fn the_step_limit_stops_inside_an_output_interval() {
    let never = |_: f64, _: &[f64]| -> ControlFlow<()> { panic!("no output time is reached") };
    let rk4 = Method::Fixed(&tableau::RK4, 1e-9);
    let r = Integration::new(&Oscillator, 0.0, &[0.0, 1.0], rk4).max_steps(1000).run(&[1.0], never);
    match r {
        Err(e @ OdeError::TooManySteps { time, max: 1000 }) => {
            assert!((time - 1e-6).abs() < 1e-12, "stopped at {time}");
            let text = e.to_string();
            assert!(text.contains("after 1000 steps") && text.contains("raise max_steps"), "{text}");
            assert!(text.contains("loosen rtol and atol") && text.contains("raise step"), "{text}");
        }
        other => panic!("expected the step limit, got {other:?}"),
    }
    let tight = Method::Adaptive(&tableau::DOPRI5, Tolerances { rtol: 1e-12, atol: 1e-12 });
    let r = Integration::new(&Oscillator, 0.0, &[0.0, 1.0], tight).max_steps(50).run(&[100.0], never);
    assert!(matches!(r, Err(OdeError::TooManySteps { max: 50, .. })), "{r:?}");
    // The stepper alone: exactly the limit is allowed, one more is not.
    let mut stepper =
        ErkStepper::new(&Oscillator, 0.0, &[0.0, 1.0], Method::Fixed(&tableau::RK4, 0.1)).unwrap();
    stepper.set_max_steps(3);
    for _ in 0..3 {
        stepper.step().unwrap();
    }
    assert!(matches!(stepper.step(), Err(OdeError::TooManySteps { max: 3, .. })));
}

/// A fixed step too small to move the time is a step-size underflow, not an endless loop.
#[test]
fn a_fixed_step_below_the_time_resolution_underflows() {
    let rk4 = Method::Fixed(&tableau::RK4, 1e-30);
    let r =
        Integration::new(&Oscillator, 1.0, &[0.0, 1.0], rk4).run(&[2.0], |_, _| ControlFlow::Continue(()));
    assert!(matches!(r, Err(OdeError::StepSizeUnderflow { time, .. }) if time == 1.0), "{r:?}");
}

/// The largest error of one fixed step of size `h` of `tab` from the exact `y(0.5)` of
/// [`Gaussian`]: at the step's end, and of its continuous extension at a few points inside.
fn one_step_errors(tab: &'static tableau::Tableau, h: f64) -> (f64, f64) {
    let (t0, exact) = (0.5, |t: f64| Gaussian.solution(0.0, &[1.0], t)[0]);
    let mut stepper = ErkStepper::new(&Gaussian, t0, &[exact(t0)], Method::Fixed(tab, h)).unwrap();
    stepper.set_stop_time(t0 + h);
    stepper.step().unwrap();
    let end = (stepper.y()[0] - exact(t0 + h)).abs();
    let mut y = [0.0];
    let inside = [0.2, 0.45, 0.7, 0.9]
        .iter()
        .map(|theta| {
            stepper.interpolate(t0 + theta * h, &mut y).unwrap();
            (y[0] - exact(t0 + theta * h)).abs()
        })
        .fold(0.0, f64::max);
    (end, inside)
}

#[test]
fn vern9_converges_with_order_9() {
    // Ninth order needs errors well above rounding for a clean slope: 25 to 50 steps to t = 10.
    let tab = &tableau::VERN9;
    let (e1, e2) = (error_at(10.0, Method::Fixed(tab, 0.4)), error_at(10.0, Method::Fixed(tab, 0.2)));
    let observed = (e1 / e2).log2();
    println!("vern9 global errors {e1:e} {e2:e}: order {observed:.2}");
    assert!((observed - 9.0).abs() < 0.3, "vern9: observed order {observed}");
}

#[test]
fn verner_interpolants_are_as_accurate_as_the_steps() {
    // One step from the exact state, then half that step: the interpolant's error inside the
    // step shrinks at least like its local order h^(q + 1) (q = 6 for Vern7's, whose order-7
    // conditions hold to 3e-7, and 9 for Vern9's; the conditions themselves are checked in
    // tests/tableau_orders.rs) and stays within twice the step's own error at its end. The
    // asymptotic slopes (p + 1, q + 1) only show below double precision here: at these sizes the
    // next terms still count, so only lower bounds are asserted.
    for (tab, q, h) in [(&tableau::VERN7, 6.0, 0.5), (&tableau::VERN9, 9.0, 1.0)] {
        let (end1, in1) = one_step_errors(tab, h);
        let (end2, in2) = one_step_errors(tab, h / 2.0);
        let slope = (in1 / in2).log2();
        println!("{}: end {end1:e} -> {end2:e}, inside {in1:e} -> {in2:e} (slope {slope:.2})", tab.name);
        assert!(slope > q + 0.7, "{}: interpolant error slope {slope}", tab.name);
        assert!(in2 < 2.0 * end2, "{}: inside {in2:e}, end {end2:e}", tab.name);
    }
}

#[test]
fn verner_dense_output_is_accurate_between_steps() {
    // 231 output times on [0, 3] of the Gaussian: interpolated values within the tolerance and
    // shrinking with it (a wrong extra stage or `d` row would not).
    for tab in [&tableau::VERN7, &tableau::VERN9] {
        let run = |tol: f64| gaussian_dense_error(tab, tol);
        let mut first = None;
        for tol in [1e-6, 1e-8, 1e-10, 1e-12] {
            let (worst, steps) = run(tol);
            println!("{} tol {tol:e}: worst {worst:e} in {steps} steps", tab.name);
            assert!(worst < tol && steps < 100, "{} tol {tol:e}: {worst:e}, {steps} steps", tab.name);
            let e6 = *first.get_or_insert(worst);
            assert!(tol > 1e-12 || worst < 1e-4 * e6, "{}: {worst:e} against {e6:e}", tab.name);
        }
    }
}
