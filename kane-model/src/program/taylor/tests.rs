//! Recurrences checked on identities: with `x' = 1` (so `x = x0 + h`), a state `z` with
//! `z' = g(x) - g2(x)` has Taylor coefficients zero past order 0 exactly when `g` and `g2` agree
//! as functions; and against closed forms.

use super::super::ir::{Input, Op, Section, SectionBuilder};
use super::TaylorProgram;
use crate::expr::Func;

const ORDER: usize = 12;

/// The coefficients of `[x, z_1, ...]` where `x' = 1`, `z_j' = rhs_j(x, t)` (values of `b`).
fn coefficients(x0: f64, rhs: impl Fn(&mut SectionBuilder, u32, u32) -> Vec<u32>) -> Vec<Vec<f64>> {
    let mut b = SectionBuilder::default();
    let x = b.input(Input::State(0));
    let t = b.input(Input::Time);
    let one = b.constant(1.0);
    let mut results = vec![one];
    results.extend(rhs(&mut b, x, t));
    let n = results.len();
    let section = b.finish(results);
    let program = TaylorProgram::new(&section, n).unwrap();
    let mut y = vec![0.0; n];
    y[0] = x0;
    let mut out = vec![0.0; n * (ORDER + 1)];
    assert!(program.coefficients(0.25, &y, |_| f64::NAN, ORDER, &mut out, &mut Vec::new()));
    out.chunks(ORDER + 1).map(<[f64]>::to_vec).collect()
}

fn f(b: &mut SectionBuilder, func: Func, a: u32) -> u32 {
    b.push(Op::Func(func, a))
}

/// Builds `(g(x), g2(x))`.
type Pair = Box<dyn Fn(&mut SectionBuilder, u32) -> (u32, u32)>;

/// Each pair `(g, g2)` of the same function written two ways.
fn identities() -> Vec<(&'static str, Pair)> {
    vec![
        (
            "sin^2 + cos^2 = 1",
            Box::new(|b, x| {
                let (s, c) = (f(b, Func::Sin, x), f(b, Func::Cos, x));
                let (s2, c2) = (b.push(Op::Powi(s, 2)), b.push(Op::Powi(c, 2)));
                (b.add(s2, c2), b.constant(1.0))
            }),
        ),
        ("atan(tan x) = x", outer_inner(Func::Atan, Func::Tan)),
        ("asin(sin x) = x", outer_inner(Func::Asin, Func::Sin)),
        ("acos(cos x) = x", outer_inner(Func::Acos, Func::Cos)),
        ("exp(ln x) = x", outer_inner(Func::Exp, Func::Ln)),
        (
            "sqrt(x)^2 = x",
            Box::new(|b, x| {
                let r = b.push(Op::Sqrt(x));
                (b.push(Op::Powi(r, 2)), x)
            }),
        ),
        (
            "x^3 x^-3 = 1",
            Box::new(|b, x| {
                let (p, m) = (b.push(Op::Powi(x, 3)), b.push(Op::Powi(x, -3)));
                (b.mul(p, m), b.constant(1.0))
            }),
        ),
        (
            "x^2.5 = x^2 sqrt(x)",
            Box::new(|b, x| {
                let e = b.constant(2.5);
                let p = b.push(Op::Powf(x, e));
                let (sq, r) = (b.push(Op::Powi(x, 2)), b.push(Op::Sqrt(x)));
                (p, b.mul(sq, r))
            }),
        ),
        (
            "cosh^2 - sinh^2 = 1",
            Box::new(|b, x| {
                let (s, c) = (f(b, Func::Sinh, x), f(b, Func::Cosh, x));
                let (s2, c2) = (b.mul(s, s), b.mul(c, c));
                (b.sub(c2, s2), b.constant(1.0))
            }),
        ),
        (
            "tanh cosh = sinh",
            Box::new(|b, x| {
                let (th, c) = (f(b, Func::Tanh, x), f(b, Func::Cosh, x));
                (b.mul(th, c), f(b, Func::Sinh, x))
            }),
        ),
        (
            "atan2(3 sin x, 3 cos x) = x",
            Box::new(|b, x| {
                let three = b.constant(3.0);
                let (s, c) = (f(b, Func::Sin, x), f(b, Func::Cos, x));
                let (ys, xs) = (b.mul(three, s), b.mul(c, three));
                (b.push(Op::Atan2(ys, xs)), x)
            }),
        ),
        (
            "|x - 1| = 1 - x",
            Box::new(|b, x| {
                let one = b.constant(1.0);
                let d = b.sub(x, one);
                (f(b, Func::Abs, d), b.sub(one, x))
            }),
        ),
        (
            "sign(x) x = x",
            Box::new(|b, x| {
                let s = f(b, Func::Sign, x);
                (b.mul(s, x), x)
            }),
        ),
        (
            "x^2 / x = x, 2 / x = 2 x^-1",
            Box::new(|b, x| {
                let (sq, two) = (b.push(Op::Powi(x, 2)), b.constant(2.0));
                let (q, r) = (b.div(sq, x), b.div(two, x));
                let inv = b.push(Op::Powi(x, -1));
                let (l, rr) = (b.add(q, r), b.mul(two, inv));
                (l, b.add(x, rr))
            }),
        ),
        (
            "exp(-x) exp(x) = 1",
            Box::new(|b, x| {
                let m = b.push(Op::Neg(x));
                let (e1, e2) = (f(b, Func::Exp, m), f(b, Func::Exp, x));
                (b.mul(e1, e2), b.constant(1.0))
            }),
        ),
    ]
}

/// `(outer(inner(x)), x)`.
fn outer_inner(outer: Func, inner: Func) -> Pair {
    Box::new(move |b, x| {
        let g = f(b, inner, x);
        (f(b, outer, g), x)
    })
}

#[test]
fn every_recurrence_satisfies_its_identity() {
    for (name, pair) in identities() {
        let c = coefficients(0.7, |b, x, _| {
            let (g, g2) = pair(b, x);
            vec![b.sub(g, g2)]
        });
        for (k, v) in c[1].iter().enumerate().skip(1) {
            assert!(v.abs() < 1e-11, "{name}: coefficient {k} is {v:e}");
        }
        // The identity is not trivially zero: g alone has nonzero coefficients.
        let g = coefficients(0.7, |b, x, _| vec![pair(b, x).0]);
        assert!(g[1][1..].iter().any(|v| v.abs() > 1e-3), "{name}: g has no coefficients");
    }
}

#[test]
fn closed_forms_exp_sin_and_time() {
    let x0: f64 = 0.3;
    let c = coefficients(x0, |b, x, t| vec![f(b, Func::Exp, x), f(b, Func::Sin, x), t]);
    let mut factorial = 1.0;
    for k in 0..ORDER {
        // z' = g(x): z_{k+1} = g^(k)(x0) / (k! (k + 1)).
        let want_exp = x0.exp() / factorial / (k + 1) as f64;
        let want_sin = (x0 + k as f64 * std::f64::consts::FRAC_PI_2).sin() / factorial / (k + 1) as f64;
        assert!((c[1][k + 1] - want_exp).abs() < 1e-14, "exp: order {}", k + 1);
        assert!((c[2][k + 1] - want_sin).abs() < 1e-14, "sin: order {}", k + 1);
        factorial *= (k + 1) as f64;
    }
    // z' = t at t = 0.25: z = z0 + 0.25 h + h^2 / 2.
    assert_eq!(&c[3][..4], &[0.0, 0.25, 0.5, 0.0]);
    // x itself: x0, 1, 0, ...
    assert_eq!(&c[0][..3], &[x0, 1.0, 0.0]);
}

#[test]
fn a_section_that_is_no_right_hand_side_is_refused() {
    let mut b = SectionBuilder::default();
    let r = b.input(Input::Rate(0));
    let section = b.finish(vec![r]);
    let err = TaylorProgram::new(&section, 1).unwrap_err();
    assert!(err.to_string().contains("speed rate"), "{err}");
    let err = TaylorProgram::new(&section, 2).unwrap_err();
    assert!(err.to_string().contains("1 results for 2 states"), "{err}");
}

/// A top-like right-hand side: `x' = x w / 2 + y w / 2 - x y / 2`, `y' = c (x y) - c (y y) + x`,
/// `w' = 0 d` (a parameter `c`, a parameter constant `d`): linear parts to fold, a constant state.
fn foldable() -> Section {
    let mut b = SectionBuilder::default();
    let (x, y, w) = (b.input(Input::State(0)), b.input(Input::State(1)), b.input(Input::State(2)));
    let (c, d) = (b.input(Input::Param(0)), b.input(Input::ParamConstant(0)));
    let two = b.constant(2.0);
    let halves: Vec<u32> = [(x, w), (y, w), (x, y)]
        .into_iter()
        .map(|(p, q)| {
            let m = b.mul(p, q);
            b.div(m, two)
        })
        .collect();
    let s = b.add(halves[0], halves[1]);
    let xdot = b.sub(s, halves[2]);
    let (xy, yy) = (b.mul(x, y), b.mul(y, y));
    let (cxy, cyy) = (b.mul(c, xy), b.mul(yy, c));
    let diff = b.sub(cxy, cyy);
    let ydot = b.add(diff, x);
    let zero = b.constant(0.0);
    let wdot = b.mul(zero, d);
    b.finish(vec![xdot, ydot, wdot])
}

#[test]
fn folding_keeps_the_coefficients_and_drops_varying_operations() {
    let section = foldable();
    let plain = super::build(&section, 3).unwrap();
    let folded = TaylorProgram::new(&section, 3).unwrap();
    // w is constant, so x w and y w are constant multiples; the halves share one
    // multiplication, and c (x y - y y) one.
    assert!(
        folded.series_op_count() < plain.series_op_count(),
        "{} varying operations folded, {} plain",
        folded.series_op_count(),
        plain.series_op_count()
    );
    let products = |p: &TaylorProgram| {
        p.ops
            .iter()
            .filter(|o| o.series && matches!(o.kind, super::TKind::Mul(..) | super::TKind::Sqr(_)))
            .count()
    };
    assert_eq!(products(&plain), 4);
    assert_eq!(products(&folded), 2, "x y and y y: w is constant");
    let read = |i: Input| match i {
        Input::Param(_) => 1.7,
        Input::ParamConstant(_) => -0.3,
        _ => f64::NAN,
    };
    let y = [0.4, -0.9, 1.3];
    let (mut a, mut b) = (vec![0.0; 3 * (ORDER + 1)], vec![0.0; 3 * (ORDER + 1)]);
    assert!(plain.coefficients(0.0, &y, read, ORDER, &mut a, &mut Vec::new()));
    assert!(folded.coefficients(0.0, &y, read, ORDER, &mut b, &mut Vec::new()));
    for (j, (p, q)) in a.iter().zip(&b).enumerate() {
        assert!((p - q).abs() <= 1e-13 * p.abs().max(1.0), "coefficient {j}: {p:e} plain, {q:e} folded");
    }
    assert!(b[ORDER + 5].abs() > 1e-6, "the coefficients are not trivially zero");
    assert_eq!(&b[2 * (ORDER + 1)..2 * (ORDER + 1) + 3], &[1.3, 0.0, 0.0], "w is constant");
}
