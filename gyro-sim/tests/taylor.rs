//! The Taylor method on the generated models: coefficients of the gimbal and the heavy top
//! checked against the right-hand side and dual numbers (the time derivative of coefficient `k`
//! along the solution is `(k + 1)` times coefficient `k + 1`); the series' truncation error
//! falls as `h^(p+1)`; the stepper's error follows the tolerance with dense output between
//! steps; Trial 3 by the Taylor method equals the DOP853 run.

use std::ops::ControlFlow;

use gyro_sim::run;
use gyro_sim::ModelSystem;
use gyro_sim::Scene;
use gyro_sim::{gimbal_gyroscope as gimbal, heavy_top as top};
use gyro_sim::{tableau::DOP853, Integration, Method, Tolerances};
use kane_model::runtime::dual::Dual;
use kane_model::runtime::GeneratedModel;

/// Coefficients of `model` at `(t, y)` in `f64` and, with `y = y + eps f(y)`, `t = t + eps`, in
/// dual numbers; checks coefficient 1 against `f` and each derivative against the next one, at
/// `order` (a straight-line one or not).
macro_rules! check_against_duals {
    ($m:ident, $order:expr, $t:expr, $y:expr) => {{
        let p = $m::Params::default();
        let d = $m::param_constants(&p);
        let (t, y): (f64, Vec<f64>) = ($t, $y.to_vec());
        let (n, order) = (y.len(), $order);
        let n1 = order + 1;
        let mut c = vec![0.0; n * n1];
        assert!($m::taylor_with_constants(t, &y, &p, &d, order, &mut c, &mut Vec::new()));
        let mut f = vec![0.0; n];
        $m::rhs_with_constants(t, &y, &p, &d, &mut f);
        let yd: Vec<Dual<f64>> = (0..n).map(|i| Dual::new(y[i], f[i])).collect();
        let mut cd = vec![Dual::new(0.0, 0.0); n * n1];
        assert!($m::taylor_with_constants(Dual::new(t, 1.0), &yd, &p, &d, order, &mut cd, &mut Vec::new()));
        for i in 0..n {
            assert_eq!(c[i * n1], y[i]);
            assert!((c[i * n1 + 1] - f[i]).abs() <= 1e-14 * f[i].abs().max(1.0), "y_1 = f, state {i}");
        }
        for k in 0..order {
            // (k + 1) y_{k+1}, state by state, against d/dt y_k; relative to the largest.
            let want: Vec<f64> = (0..n).map(|i| (k + 1) as f64 * c[i * n1 + k + 1]).collect();
            let scale = want.iter().fold(1e-300f64, |m, v| m.max(v.abs()));
            for i in 0..n {
                let got = cd[i * n1 + k].eps;
                assert!((got - want[i]).abs() <= 1e-11 * scale, "state {i} order {k}: {got} vs {}", want[i]);
                assert!((cd[i * n1 + k].re - c[i * n1 + k]).abs() <= 1e-13 * scale * (k + 1) as f64);
            }
        }
        c
    }};
}

#[test]
fn gimbal_and_top_coefficients_match_dual_numbers() {
    // 13 by the loop; 16 straight-line (on a CPU with fused multiply-add).
    assert!(!kane_model::runtime::TAYLOR_UNROLLED_ORDERS.contains(&13));
    let c = check_against_duals!(gimbal, 13, 0.3, [0.3, 0.4, 0.1, 0.5, -0.7, 10.0]);
    assert!(c[3 * 14 + 13].abs() > 0.0, "high orders are computed");
    check_against_duals!(gimbal, 16, 0.3, [0.3, 0.4, 0.1, 0.5, -0.7, 10.0]);
    let (h, s) = (0.5f64.sqrt(), 0.4f64);
    for order in [13, 16] {
        check_against_duals!(top, order, 0.0, [h * s.cos(), h * s.sin(), 0.5, 0.5, 0.3, -0.2, 10.0]);
    }
}

/// `taylor_with_constants` (straight-line code with fused multiply-adds at these orders) against
/// `taylor_with_constants_loop` for `model` at `(t, y)`, every straight-line order: each coefficient to
/// 1e-11 of the largest of its order. The two round differently (fused products, one chain
/// against four), and the top's Euler-parameter coefficients are small sums of large terms
/// (at order 20 they differ by up to 6e-13 of the largest); a wrong term differs by far more.
macro_rules! check_unrolled_against_loop {
    ($m:ident, $t:expr, $y:expr) => {{
        let p = $m::Params::default();
        let d = $m::param_constants(&p);
        let (t, y): (f64, Vec<f64>) = ($t, $y.to_vec());
        for &order in kane_model::runtime::TAYLOR_UNROLLED_ORDERS {
            let n1 = order + 1;
            let mut unrolled = vec![f64::NAN; y.len() * n1];
            let mut looped = unrolled.clone();
            assert!($m::taylor_with_constants(t, &y, &p, &d, order, &mut unrolled, &mut Vec::new()));
            assert!($m::taylor_with_constants_loop(t, &y, &p, &d, order, &mut looped, &mut Vec::new()));
            for (j, (a, b)) in unrolled.iter().zip(&looped).enumerate() {
                let k = j % n1;
                let largest = looped.iter().skip(k).step_by(n1).fold(0.0f64, |m, c| m.max(c.abs()));
                let close = (a - b).abs() <= 1e-11 * largest;
                assert!(close, "order {order}, coefficient {j}: {a:e} (straight-line) vs {b:e} (loop)");
            }
        }
    }};
}

#[test]
fn straight_line_coefficients_equal_the_loops() {
    if !kane_model::__private::taylor::fused_multiply_add() {
        eprintln!("this CPU has no fused multiply-add: taylor_with_constants takes the loop at every order");
    }
    check_unrolled_against_loop!(gimbal, 0.3, [0.3, 0.4, 0.1, 0.5, -0.7, 10.0]);
    check_unrolled_against_loop!(gimbal, 0.0, [0.0, 0.0, 0.0, 0.0, 0.0, 100.0]);
    let (h, s) = (0.5f64.sqrt(), 0.4f64);
    check_unrolled_against_loop!(top, 0.0, [h * s.cos(), h * s.sin(), 0.5, 0.5, 0.3, -0.2, 10.0]);
    check_unrolled_against_loop!(top, 1.0, [0.8660254037844386, 0.0, 0.0, 0.5, 0.0, 0.0, 10.0]);
}

/// The gimbal of Trial 3 (Y = Z = 10, U3 = 100 rad/s) as an ODE system.
fn trial3() -> (ModelSystem<gimbal::Model>, Vec<f64>) {
    let mut p = gimbal::Params::default();
    gimbal::Model::set_param(&mut p, "Y", 10.0);
    gimbal::Model::set_param(&mut p, "Z", 10.0);
    (ModelSystem::new(p), vec![0.0, 0.0, 0.0, 0.0, 0.0, 100.0])
}

/// The states at `times` from `method`.
fn states_at(sys: &ModelSystem<gimbal::Model>, y0: &[f64], times: &[f64], method: Method) -> Vec<Vec<f64>> {
    let mut rows = Vec::new();
    Integration::new(sys, 0.0, y0, method)
        .run(times, |_, y| {
            rows.push(y.to_vec());
            ControlFlow::Continue(())
        })
        .unwrap();
    rows
}

fn largest_difference(a: &[Vec<f64>], b: &[Vec<f64>]) -> f64 {
    a.iter().flatten().zip(b.iter().flatten()).fold(0.0, |m, (x, y)| m.max((x - y).abs() / y.abs().max(1.0)))
}

#[test]
fn the_truncated_series_errs_as_h_to_the_order_plus_one() {
    let (sys, y0) = trial3();
    let p = sys.params().clone();
    let d = gimbal::param_constants(&p);
    let order = 6;
    let n1 = order + 1;
    let mut c = vec![0.0; 6 * n1];
    assert!(gimbal::taylor_with_constants(0.0, &y0, &p, &d, order, &mut c, &mut Vec::new()));
    let tight = Method::Adaptive(&DOP853, Tolerances { rtol: 1e-15, atol: 1e-15 });
    let error_at = |h: f64| {
        let exact = &states_at(&sys, &y0, &[h], tight)[0];
        let series: Vec<f64> =
            (0..6).map(|i| c[i * n1..(i + 1) * n1].iter().rev().fold(0.0, |a, ck| a * h + ck)).collect();
        largest_difference(&[series], std::slice::from_ref(exact))
    };
    let (e1, e2) = (error_at(2e-2), error_at(1e-2));
    let ratio = e1 / e2;
    // Order 6: the error is the first term left out, O(h^7): halving h divides it by 2^7 = 128.
    assert!(e2 > 1e-9, "the error must stand above the reference's: {e2:e}");
    assert!((64.0..256.0).contains(&ratio), "errors {e1:e}, {e2:e}: ratio {ratio}");
}

#[test]
fn the_stepper_follows_the_tolerance_with_dense_output_between_steps() {
    let (sys, y0) = trial3();
    let times: Vec<f64> = (0..=2000).map(|i| i as f64 * 5e-4).collect();
    let reference =
        states_at(&sys, &y0, &times, Method::Adaptive(&DOP853, Tolerances { rtol: 1e-14, atol: 1e-14 }));
    let mut last = f64::INFINITY;
    for tol in [1e-6, 1e-9, 1e-12] {
        let method = Method::Taylor(Tolerances { rtol: tol, atol: tol });
        let mut steps = 0;
        let mut rows = Vec::new();
        let stats = Integration::new(&sys, 0.0, &y0, method)
            .run(&times, |_, y| {
                rows.push(y.to_vec());
                ControlFlow::Continue(())
            })
            .unwrap()
            .stats;
        steps += stats.steps;
        let error = largest_difference(&rows, &reference);
        // Most output times fall inside steps: they come from the series.
        assert!(steps * 4 < times.len(), "tol {tol:e}: {steps} steps for {} times", times.len());
        assert!(error < 1e3 * tol, "tol {tol:e}: error {error:e}");
        assert!(error < last, "tol {tol:e}: error {error:e} is no smaller than {last:e}");
        last = error;
    }
}

#[test]
fn trial_three_by_taylor_equals_the_dop853_run() {
    let path = format!("{}/scenes/paper/trial3.toml", env!("CARGO_MANIFEST_DIR"));
    let scene = Scene::load(std::path::Path::new(&path)).unwrap();
    let reference = run(&scene, None).unwrap();
    let mut taylor = scene.clone();
    taylor.integrator.method = gyro_sim::by_name("taylor").unwrap();
    let summary = run(&taylor, None).unwrap();
    let asked = scene.integrator.accuracy.unwrap();
    let (a, b) = (&summary.trajectory.rows, &reference.trajectory.rows);
    assert_eq!(a.len(), b.len());
    let worst = largest_difference(a, b);
    assert!(worst <= asked, "Trial 3: taylor differs from dop853 by {worst:e} (asked {asked:e})");
}
