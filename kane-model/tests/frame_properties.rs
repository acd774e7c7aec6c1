//! Frame laws on random orientations of all 24 three-angle sequences: direction-cosine matrices
//! are orthonormal and compose, and the angular velocity is the one the DCM's rate implies.

use kane_model::expr::{ExprId, SymbolId};
use kane_model::mechanics::{FrameId, Mat3, Model, Orientation};
use proptest::prelude::*;

/// The 12 sequences with no axis repeated consecutively.
fn sequences() -> Vec<[u8; 3]> {
    let mut v = Vec::new();
    for a in 1..=3u8 {
        for b in 1..=3u8 {
            for c in 1..=3u8 {
                if a != b && b != c {
                    v.push([a, b, c]);
                }
            }
        }
    }
    v
}

struct Setup {
    m: Model,
    frame: FrameId,
    q: [ExprId; 3],
    u: [ExprId; 3],
}

fn setup(axes: [u8; 3], body_fixed: bool) -> Setup {
    let mut m = Model::new("N");
    let n = m.newtonian();
    let q = ["q1", "q2", "q3"].map(|s| m.ar.variable(s).unwrap());
    let u = ["u1", "u2", "u3"].map(|s| m.ar.variable(s).unwrap());
    let b = m.add_frame("B").unwrap();
    let o = if body_fixed {
        Orientation::BodyFixed { axes, angles: q }
    } else {
        Orientation::SpaceFixed { axes, angles: q }
    };
    m.orient(b, n, o).unwrap();
    m.set_coordinates(&q).unwrap();
    m.set_speeds(&u).unwrap();
    for i in 0..3 {
        m.set_kinematics(q[i], u[i]).unwrap();
    }
    Setup { m, frame: b, q, u }
}

fn eval_mat(s: &Setup, c: &Mat3, vals: &[(SymbolId, f64)]) -> [[f64; 3]; 3] {
    let mut out = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            out[i][j] = s.m.ar.eval(&[c[i][j]], |x| vals.iter().find(|v| v.0 == x).map(|v| v.1)).unwrap()[0];
        }
    }
    out
}

fn values(s: &Setup, q: [f64; 3], u: [f64; 3]) -> Vec<(SymbolId, f64)> {
    let sym = |e: ExprId| s.m.ar.as_symbol(e).unwrap();
    s.q.iter().zip(q).chain(s.u.iter().zip(u)).map(|(e, v)| (sym(*e), v)).collect()
}

proptest! {
    #[test]
    fn dcm_is_orthonormal_and_omega_matches_its_rate(
        seq in 0usize..12,
        body_fixed in any::<bool>(),
        q in [-3.0f64..3.0, -1.4f64..1.4, -3.0f64..3.0],
        u in [-2.0f64..2.0, -2.0f64..2.0, -2.0f64..2.0],
    ) {
        let axes = sequences()[seq];
        let mut s = setup(axes, body_fixed);
        let n = s.m.newtonian();
        let c = s.m.dcm(n, s.frame).unwrap();
        let vals = values(&s, q, u);
        let cm = eval_mat(&s, &c, &vals);
        for i in 0..3 {
            for j in 0..3 {
                let dot: f64 = (0..3).map(|k| cm[k][i] * cm[k][j]).sum();
                let want = if i == j { 1.0 } else { 0.0 };
                prop_assert!((dot - want).abs() < 1e-12, "C^T C [{}][{}] = {}", i, j, dot);
            }
        }
        // dC/dt by central difference along q' = u, then w x b_j = db_j/dt in B's components.
        let h = 1e-6;
        let shifted = |sign: f64| {
            let qq = [q[0] + sign * h * u[0], q[1] + sign * h * u[1], q[2] + sign * h * u[2]];
            eval_mat(&s, &c, &values(&s, qq, u))
        };
        let (cp, cmn) = (shifted(1.0), shifted(-1.0));
        let w = s.m.angular_velocity(s.frame, n).unwrap();
        let wb = s.m.express(&w, s.frame).unwrap();
        let wv: Vec<f64> = wb.iter().map(|e| s.m.ar.eval(&[*e], |x| vals.iter().find(|v| v.0 == x).map(|v| v.1)).unwrap()[0]).collect();
        // S = C^T dC/dt; w1 = S[2][1], w2 = S[0][2], w3 = S[1][0].
        let sk = |a: usize, b: usize| -> f64 { (0..3).map(|k| cm[k][a] * (cp[k][b] - cmn[k][b]) / (2.0 * h)).sum() };
        let fd = [sk(2, 1), sk(0, 2), sk(1, 0)];
        for i in 0..3 {
            prop_assert!((fd[i] - wv[i]).abs() < 1e-6, "{axes:?} body_fixed={body_fixed}: w{} {} vs {}", i + 1, wv[i], fd[i]);
        }
    }

    #[test]
    fn dcms_compose_and_vectors_round_trip(q in [-3.0f64..3.0, -3.0f64..3.0, -3.0f64..3.0], seq in 0usize..12) {
        let mut s = setup(sequences()[seq], true);
        let n = s.m.newtonian();
        let c = s.m.add_frame("C").unwrap();
        let p = s.m.ar.variable("p").unwrap();
        s.m.orient(c, s.frame, Orientation::Axis { axis: -2, angle: p }).unwrap();
        let mut vals = values(&s, q, [0.0; 3]);
        vals.push((s.m.ar.as_symbol(p).unwrap(), 0.4));
        let nb = s.m.dcm(n, s.frame).unwrap();
        let bc = s.m.dcm(s.frame, c).unwrap();
        let nc = s.m.dcm(n, c).unwrap();
        let (nb, bc, nc) = (eval_mat(&s, &nb, &vals), eval_mat(&s, &bc, &vals), eval_mat(&s, &nc, &vals));
        for i in 0..3 {
            for j in 0..3 {
                let prod: f64 = (0..3).map(|k| nb[i][k] * bc[k][j]).sum();
                prop_assert!((prod - nc[i][j]).abs() < 1e-12);
            }
        }
        // a x b = -(b x a), and (a . b) is the same in any frame.
        let a = s.m.unit(c, 1);
        let b = s.m.unit(n, 2);
        let ab = s.m.cross(&a, &b).unwrap();
        let ba = s.m.cross(&b, &a).unwrap();
        let sum = s.m.add_vectors(&ab, &ba).unwrap();
        let sum_n = s.m.express(&sum, n).unwrap();
        for e in sum_n {
            let v = s.m.ar.eval(&[e], |x| vals.iter().find(|v| v.0 == x).map(|v| v.1)).unwrap()[0];
            prop_assert!(v.abs() < 1e-12);
        }
    }
}
