//! The paper's gimbal gyroscope: Kane's equations derived by kane-model equal the ones derived
//! by hand below, proven symbolically and checked at random states.

use kane_model::expr::{Arena, Equivalence, EquivalenceConfig, ExprId};
use kane_model::models::GimbalGyroscope;

// Hand derivation.
//
// Frames: B = rot(A, -a2, q1), C = rot(B, -b1, q2), D = rot(C, -c2, q3), qi' = ui.
// Angular velocities (a negative axis turns the rate's sign):
//   w_B = -u1 b2,   w_C = w_B - u2 c1,   w_D = w_C - u3 c2.
// With s = sin q2, c = cos q2, b2 = c c2 + s c3 (rotation of C about -b1), so in C's basis
//   w_C = (-u2, -u1 c, -u1 s),   w_D = (-u2, -u1 c - u3, -u1 s).
// Partial angular velocities (the paper's Table 1):
//   B: (-b2, 0, 0);  C: (-b2, -c1, 0);  D: (-b2, -c1, -c2).
// All mass centres are at the fixed point O, so no translational terms.
// Inertias: I_B = diag(I1, I1, I2) in B, I_C = diag(J1, J1, J2) in C, I_D = diag(K2, K1, K2) in D,
// which equals diag(K2, K1, K2) in C as D turns about c2 = d2.
//
// Mass matrix M_rs = sum w_r . I . w_s:
//   M11 = I1 + J1 c^2 + J2 s^2 + K1 c^2 + K2 s^2,  M22 = J1 + K2,  M33 = K1,  M13 = K1 c,
//   M12 = M23 = 0.
// Active forces: T_B = Y a2 (a2 = b2), T_C = Z b1 (b1 = c1):
//   F1 = -b2 . Y b2 + (-b2) . Z c1 = -Y,   F2 = -c1 . Z c1 = -Z,   F3 = 0.
// Inertia forces: Fr* = -sum_k w_r^k . dH_k/dt with H_k = I_k w_k about O.
// H_B = -I1 u1 b2 and b2 is fixed in A, so dH_B/dt = -I1 u1' b2 (zero when u' = 0).
// h = H_C + H_D in C = (-(J1 + K2) u2, -(J1 + K1) c u1 - K1 u3, -(J2 + K2) s u1);
// dh/dt = h' + w_C x h, and with u' = 0 (q2' = u2):
//   (dh/dt)_1 = (J2 + K2 - J1 - K1) s c u1^2 - K1 s u1 u3
//   (dh/dt)_2 = (2 J1 + K1 - J2) s u1 u2
//   (dh/dt)_3 = (K1 - J2 - 2 K2) c u1 u2 + K1 u2 u3
// Fr*_1 = b2 . dH/dt = c (dh/dt)_2 + s (dh/dt)_3 = 2 (J1 + K1 - J2 - K2) s c u1 u2 + K1 s u2 u3
// Fr*_2 = c1 . dh/dt = (J2 + K2 - J1 - K1) s c u1^2 - K1 s u1 u3
// Fr*_3 = c2 . dH_D/dt = K1 s u1 u2   (w_C x H_D has no c2 part)
// Forcing f = Fr + Fr*|u'=0:
//   f1 = -Y + 2 (J1 + K1 - J2 - K2) s c u1 u2 + K1 s u2 u3
//   f2 = -Z + (J2 + K2 - J1 - K1) s c u1^2 - K1 s u1 u3
//   f3 = K1 s u1 u2
struct Hand {
    mass_matrix: [[ExprId; 3]; 3],
    forcing: [ExprId; 3],
}

fn c(ar: &mut Arena, name: &str) -> ExprId {
    ar.constant(name).unwrap()
}

/// The paper's lines 5-13, written out again independently of the model code.
fn moments(ar: &mut Arena) -> [ExprId; 6] {
    let [m1, m2, m3, h1, h2, h3, l, w] = ["M1", "M2", "M3", "H1", "H2", "H3", "L", "W"].map(|n| c(ar, n));
    let gimbal = |ar: &mut Arena, m: ExprId, h: ExprId| {
        // 2/3 m (h w - w^2) and 1/6 m h^2 - 1/6 m (h - w)^2
        let k = ar.rational(2, 3).unwrap();
        let hw = ar.mul(&[h, w]).unwrap();
        let w2 = ar.powi(w, 2).unwrap();
        let d = ar.sub(hw, w2).unwrap();
        let first = ar.mul(&[k, m, d]).unwrap();
        let sixth = ar.rational(1, 6).unwrap();
        let h2 = ar.powi(h, 2).unwrap();
        let hmw = ar.sub(h, w).unwrap();
        let hmw2 = ar.powi(hmw, 2).unwrap();
        let a = ar.mul(&[sixth, m, h2]).unwrap();
        let b = ar.mul(&[sixth, m, hmw2]).unwrap();
        (first, ar.sub(a, b).unwrap())
    };
    let (i1, i2) = gimbal(ar, m1, h1);
    let (j1, j2) = gimbal(ar, m2, h2);
    let half = ar.rational(1, 2).unwrap();
    let l2 = ar.powi(l, 2).unwrap();
    let k1 = ar.mul(&[half, m3, l2]).unwrap();
    let quarter = ar.rational(1, 4).unwrap();
    let twelfth = ar.rational(1, 12).unwrap();
    let h32 = ar.powi(h3, 2).unwrap();
    let a = ar.mul(&[quarter, m3, l2]).unwrap();
    let b = ar.mul(&[twelfth, m3, h32]).unwrap();
    let k2 = ar.add(&[a, b]).unwrap();
    [i1, i2, j1, j2, k1, k2]
}

fn hand_derivation(ar: &mut Arena) -> Hand {
    let [i1, _i2, j1, j2, k1, k2] = moments(ar);
    let (y, z) = (c(ar, "Y"), c(ar, "Z"));
    let q2 = ar.variable("q2").unwrap();
    let [u1, u2, u3] = ["u1", "u2", "u3"].map(|n| ar.variable(n).unwrap());
    let s = ar.sin(q2).unwrap();
    let co = ar.cos(q2).unwrap();
    let c2 = ar.powi(co, 2).unwrap();
    let s2 = ar.powi(s, 2).unwrap();
    let zero = ar.zero();
    let mul = |ar: &mut Arena, f: &[ExprId]| ar.mul(f).unwrap();

    let m11 = {
        let t = [mul(ar, &[j1, c2]), mul(ar, &[j2, s2]), mul(ar, &[k1, c2]), mul(ar, &[k2, s2])];
        let mut all = vec![i1];
        all.extend(t);
        ar.add(&all).unwrap()
    };
    let m22 = ar.add(&[j1, k2]).unwrap();
    let m13 = mul(ar, &[k1, co]);

    // (J1 + K1 - J2 - K2)
    let jk = {
        let p = ar.add(&[j1, k1]).unwrap();
        let n = ar.add(&[j2, k2]).unwrap();
        ar.sub(p, n).unwrap()
    };
    let two = ar.integer(2);
    let f1 = {
        let a = mul(ar, &[two, jk, s, co, u1, u2]);
        let b = mul(ar, &[k1, s, u2, u3]);
        let my = ar.neg(y).unwrap();
        ar.add(&[my, a, b]).unwrap()
    };
    let f2 = {
        let njk = ar.neg(jk).unwrap();
        let u1sq = ar.powi(u1, 2).unwrap();
        let a = mul(ar, &[njk, s, co, u1sq]);
        let b0 = mul(ar, &[k1, s, u1, u3]);
        let b = ar.neg(b0).unwrap();
        let mz = ar.neg(z).unwrap();
        ar.add(&[mz, a, b]).unwrap()
    };
    let f3 = mul(ar, &[k1, s, u1, u2]);
    Hand { mass_matrix: [[m11, zero, m13], [zero, m22, zero], [m13, zero, k1]], forcing: [f1, f2, f3] }
}

#[test]
fn derived_equations_are_proven_equal_to_the_hand_derivation() {
    let mut g = GimbalGyroscope::new().unwrap();
    let eqs = g.model.kane().unwrap();
    let hand = hand_derivation(&mut g.model.ar);
    let cfg = EquivalenceConfig::default();
    for r in 0..3 {
        for s in 0..3 {
            let verdict = g.model.ar.equivalent(eqs.mass_matrix[r][s], hand.mass_matrix[r][s], &cfg).unwrap();
            assert_eq!(
                verdict,
                Equivalence::Proven,
                "M[{r}][{s}]: {}",
                g.model.ar.to_text(eqs.mass_matrix[r][s])
            );
        }
        let verdict = g.model.ar.equivalent(eqs.forcing[r], hand.forcing[r], &cfg).unwrap();
        assert_eq!(verdict, Equivalence::Proven, "f[{r}]: {}", g.model.ar.to_text(eqs.forcing[r]));
    }
    // The kinematic equations are q' = u.
    assert_eq!(eqs.kinematics, g.u.to_vec());
}

#[test]
fn derived_equations_agree_with_the_hand_derivation_at_random_states() {
    use rand::{Rng, SeedableRng};
    let mut g = GimbalGyroscope::new().unwrap();
    let eqs = g.model.kane().unwrap();
    let hand = hand_derivation(&mut g.model.ar);
    let ar = &g.model.ar;
    let syms = ar.free_symbols(&[eqs.mass_matrix[0][0], eqs.forcing[0], eqs.forcing[1], hand.forcing[2]]);
    let mut rng = rand::rngs::StdRng::seed_from_u64(1);
    for _ in 0..200 {
        let vals: Vec<(kane_model::expr::SymbolId, f64)> =
            syms.iter().map(|s| (*s, rng.random_range(-3.0..3.0))).collect();
        let at = |e: ExprId| ar.eval(&[e], |s| vals.iter().find(|v| v.0 == s).map(|v| v.1)).unwrap()[0];
        for r in 0..3 {
            for s in 0..3 {
                let (a, b) = (at(eqs.mass_matrix[r][s]), at(hand.mass_matrix[r][s]));
                assert!((a - b).abs() <= 1e-12 * a.abs().max(1.0), "M[{r}][{s}] {a} vs {b}");
            }
            let (a, b) = (at(eqs.forcing[r]), at(hand.forcing[r]));
            assert!((a - b).abs() <= 1e-12 * a.abs().max(1.0), "f[{r}] {a} vs {b}");
        }
    }
}

#[test]
fn script_case_initial_acceleration_matches_the_reference() {
    // At t = 0 of the script case (Y = 0, Z = 10, U3 = 10, rest 0): u2' = -Z / (J1 + K2).
    // The reference trajectory (shared/references/gimbal_script_case.csv) has u2 = -0.27661574
    // at t = 0.05, i.e. u2' = -5.532 to first order.
    let mut g = GimbalGyroscope::new().unwrap();
    let eqs = g.model.kane().unwrap();
    let values = [
        ("L", 0.3),
        ("W", 0.025),
        ("H1", 0.6),
        ("H2", 0.5),
        ("H3", 0.4),
        ("M1", 2.0),
        ("M2", 2.0),
        ("M3", 50.0),
        ("Y", 0.0),
        ("Z", 10.0),
        ("q1", 0.0),
        ("q2", 0.0),
        ("q3", 0.0),
        ("u1", 0.0),
        ("u2", 0.0),
        ("u3", 10.0),
    ];
    let ar = &g.model.ar;
    let f2 = ar.eval_named(eqs.forcing[1], &values).unwrap();
    let m22 = ar.eval_named(eqs.mass_matrix[1][1], &values).unwrap();
    let u2dot = f2 / m22;
    assert!((u2dot - (-5.5325)).abs() < 1e-3, "{u2dot}");
    assert!((u2dot * 0.05 - (-0.27661574)).abs() < 1e-3);
}
