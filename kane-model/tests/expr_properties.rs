//! Algebraic laws of the expression engine, checked on random expressions.

mod strategies;

use kane_model::expr::{Arena, Cse, Tape};
use proptest::prelude::*;
use rustc_hash::FxHashMap;
use strategies::{ast, build, close, eval_at, point, symbols};

// 256 cases by default; raise with PROPTEST_CASES.
proptest! {
    #[test]
    fn canonical_form_ignores_operand_order(a in ast()) {
        let mut ar = Arena::new();
        let fwd = build(&mut ar, &a, false);
        let rev = build(&mut ar, &a, true);
        prop_assert_eq!(fwd, rev, "{} vs {}", ar.to_text(fwd), ar.to_text(rev));
    }

    #[test]
    fn derivative_matches_central_difference(a in ast(), p in point(), which in 0usize..3) {
        let mut ar = Arena::new();
        let syms = symbols(&mut ar);
        let e = build(&mut ar, &a, false);
        let d = ar.diff(e, syms[which]).unwrap();
        let h = 1e-5;
        let (mut lo, mut hi) = (p, p);
        lo[which] -= h;
        hi[which] += h;
        if let (Some(fl), Some(fh), Some(dv)) =
            (eval_at(&ar, &syms, e, &lo), eval_at(&ar, &syms, e, &hi), eval_at(&ar, &syms, d, &p))
        {
            let fd = (fh - fl) / (2.0 * h);
            // Truncation error is O(h^2 f'''); allow for values of moderate size.
            prop_assume!(fl.abs() < 1e3 && fh.abs() < 1e3);
            prop_assert!(close(fd, dv, 1e-4), "d/d{} {} = {} but FD gives {}", which, ar.to_text(e), dv, fd);
        }
    }

    #[test]
    fn substitution_then_evaluation_equals_evaluation_with_bindings(a in ast(), p in point()) {
        let mut ar = Arena::new();
        let syms = symbols(&mut ar);
        let e = build(&mut ar, &a, false);
        // x -> the number p[0]; y -> z + p[1] - p[2], which evaluates to p[1].
        let x = ar.symbol_expr(syms[0]);
        let y = ar.symbol_expr(syms[1]);
        let z = ar.symbol_expr(syms[2]);
        let vx = ar.float(p[0]).unwrap();
        let shift = ar.float(p[1] - p[2]).unwrap();
        let vy = ar.add(&[z, shift]).unwrap();
        let map: FxHashMap<_, _> = [(x, vx), (y, vy)].into_iter().collect();
        let s = ar.subs(e, &map).unwrap();
        if let (Some(a), Some(b)) = (eval_at(&ar, &syms, e, &p), eval_at(&ar, &syms, s, &p)) {
            prop_assert!(close(a, b, 1e-9), "{a} vs {b}");
        }
    }

    #[test]
    fn expansion_and_trig_simplification_preserve_value(a in ast(), p in point()) {
        let mut ar = Arena::new();
        let syms = symbols(&mut ar);
        let e = build(&mut ar, &a, false);
        let x = ar.expand(e).unwrap();
        let t = ar.trig_simplify(e).unwrap();
        if let Some(v) = eval_at(&ar, &syms, e, &p) {
            prop_assume!(v.abs() < 1e6);
            let vx = eval_at(&ar, &syms, x, &p).unwrap();
            let vt = eval_at(&ar, &syms, t, &p).unwrap();
            prop_assert!(close(v, vx, 1e-8), "expand: {v} vs {vx}");
            prop_assert!(close(v, vt, 1e-8), "trig: {v} vs {vt}");
        }
    }

    #[test]
    fn cse_assignments_and_tape_preserve_value(a in ast(), b in ast(), p in point()) {
        let mut ar = Arena::new();
        let syms = symbols(&mut ar);
        let roots = [build(&mut ar, &a, false), build(&mut ar, &b, false)];
        let want: Option<Vec<f64>> = roots.iter().map(|r| eval_at(&ar, &syms, *r, &p)).collect();
        let Some(want) = want else { return Ok(()) };

        let cse = Cse::new(&ar, &roots);
        let line = cse.assignments(&mut ar, "cse").unwrap();
        let (assign, outs) = (line.bindings, line.roots);
        let mut env: FxHashMap<_, f64> = syms.iter().copied().zip(p).collect();
        for (sym, e) in &assign {
            let v = ar.eval(&[*e], |s| env.get(&s).copied()).unwrap()[0];
            env.insert(*sym, v);
        }
        let got = ar.eval(&outs, |s| env.get(&s).copied()).unwrap();

        let tape = Tape::compile(&ar, &roots, |s| syms.iter().position(|x| *x == s)).unwrap();
        let mut out = [0.0; 2];
        tape.eval(|k| p[k], &mut out);
        for i in 0..2 {
            prop_assert!(close(want[i], got[i], 1e-12), "cse: {} vs {}", want[i], got[i]);
            prop_assert!(close(want[i], out[i], 1e-12), "tape: {} vs {}", want[i], out[i]);
        }
    }

    #[test]
    fn sum_product_and_chain_rules(a in ast(), b in ast(), p in point()) {
        let mut ar = Arena::new();
        let syms = symbols(&mut ar);
        let (ea, eb) = (build(&mut ar, &a, false), build(&mut ar, &b, false));
        let x = syms[0];
        let (da, db) = (ar.diff(ea, x).unwrap(), ar.diff(eb, x).unwrap());
        let sum = ar.add(&[ea, eb]).unwrap();
        let prod = ar.mul(&[ea, eb]).unwrap();
        let comp = ar.sin(ea).unwrap();
        let d_sum = ar.diff(sum, x).unwrap();
        let d_prod = ar.diff(prod, x).unwrap();
        let d_comp = ar.diff(comp, x).unwrap();
        let sum_rule = ar.add(&[da, db]).unwrap();
        let t1 = ar.mul(&[da, eb]).unwrap();
        let t2 = ar.mul(&[ea, db]).unwrap();
        let prod_rule = ar.add(&[t1, t2]).unwrap();
        let ca = ar.cos(ea).unwrap();
        let chain_rule = ar.mul(&[ca, da]).unwrap();
        for (lhs, rhs) in [(d_sum, sum_rule), (d_prod, prod_rule), (d_comp, chain_rule)] {
            if let (Some(l), Some(r)) = (eval_at(&ar, &syms, lhs, &p), eval_at(&ar, &syms, rhs, &p)) {
                prop_assert!(close(l, r, 1e-9), "{l} vs {r}");
            }
        }
    }
}
