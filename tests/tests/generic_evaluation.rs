//! One expression evaluated in f64, f32 and a dual-number type: the engine's
//! evaluation is generic over `num_traits::Float`, and dual numbers give exact derivatives.

use kane_model::expr::{Arena, ExprId, SymbolId, Tape};
use kane_model::runtime::dual::Dual;

type Dual64 = Dual<f64>;

/// `x^2 sin(y) / (1 + x^2) + sqrt(1 + y^2) atan(x y) - exp(-x/3)`, with its symbols.
fn sample(ar: &mut Arena) -> (ExprId, SymbolId, SymbolId) {
    let x = ar.constant("x").unwrap();
    let y = ar.constant("y").unwrap();
    let one = ar.one();
    let x2 = ar.powi(x, 2).unwrap();
    let sy = ar.sin(y).unwrap();
    let den = ar.add(&[one, x2]).unwrap();
    let t1n = ar.mul(&[x2, sy]).unwrap();
    let t1 = ar.div(t1n, den).unwrap();
    let y2 = ar.powi(y, 2).unwrap();
    let r = ar.add(&[one, y2]).unwrap();
    let root = ar.sqrt(r).unwrap();
    let xy = ar.mul(&[x, y]).unwrap();
    let at = ar.func(kane_model::expr::Func::Atan, xy).unwrap();
    let t2 = ar.mul(&[root, at]).unwrap();
    let third = ar.rational(-1, 3).unwrap();
    let arg = ar.mul(&[third, x]).unwrap();
    let ex = ar.func(kane_model::expr::Func::Exp, arg).unwrap();
    let t3 = ar.neg(ex).unwrap();
    let e = ar.add(&[t1, t2, t3]).unwrap();
    (e, ar.as_symbol(x).unwrap(), ar.as_symbol(y).unwrap())
}

fn by_hand(x: f64, y: f64) -> f64 {
    x * x * y.sin() / (1.0 + x * x) + (1.0 + y * y).sqrt() * (x * y).atan() - (-x / 3.0).exp()
}

#[test]
fn f64_f32_and_dual_agree_with_a_hand_written_function() {
    let mut ar = Arena::new();
    let (e, sx, sy) = sample(&mut ar);
    let (x, y) = (0.7, -1.3);
    let want = by_hand(x, y);

    let v64 = ar.eval::<f64>(&[e], |s| if s == sx { Some(x) } else { Some(y) }).unwrap()[0];
    assert!((v64 - want).abs() < 1e-15, "{v64} vs {want}");

    let v32 = ar.eval::<f32>(&[e], |s| if s == sx { Some(x as f32) } else { Some(y as f32) }).unwrap()[0];
    assert!((v32 as f64 - want).abs() < 1e-5, "{v32} vs {want}");

    // Seed dx = 1: the dual part is the partial derivative with respect to x.
    let vd = ar
        .eval::<Dual64>(&[e], |s| if s == sx { Some(Dual64::new(x, 1.0)) } else { Some(Dual64::new(y, 0.0)) })
        .unwrap()[0];
    assert!((vd.re - want).abs() < 1e-15);
    let dedx = ar.diff(e, sx).unwrap();
    let sym = ar.eval::<f64>(&[dedx], |s| if s == sx { Some(x) } else { Some(y) }).unwrap()[0];
    assert!((vd.eps - sym).abs() < 1e-14, "dual {} vs symbolic {}", vd.eps, sym);
    let h = 1e-6;
    let fd = (by_hand(x + h, y) - by_hand(x - h, y)) / (2.0 * h);
    assert!((sym - fd).abs() < 1e-8, "symbolic {sym} vs finite difference {fd}");

    // The tape, too, is generic.
    let tape = Tape::compile(&ar, &[e], |s| [sx, sy].iter().position(|t| *t == s)).unwrap();
    let mut out = [Dual64::new(0.0, 0.0)];
    tape.eval(|k| [Dual64::new(x, 1.0), Dual64::new(y, 0.0)][k], &mut out);
    assert!((out[0].re - want).abs() < 1e-15 && (out[0].eps - sym).abs() < 1e-14);
}
