//! The EJS heavy top: Kane's equations reduce to Euler's equations with the gravity torque, and
//! energy and the two angular-momentum integrals are constant along them.

use kane_model::expr::{Equivalence, EquivalenceConfig, ExprId, SymbolId};
use kane_model::models::HeavyTop;
use nalgebra::{Matrix3, Vector3};
use rand::{Rng, SeedableRng};

#[test]
fn kane_reduces_to_eulers_equations_with_gravity_torque() {
    let mut top = HeavyTop::new().unwrap();
    let eqs = top.model.kane().unwrap();
    let [m, g, r, d] = top.constants;
    let [e0, e1, e2, e3] = top.e;
    let [w1, w2, w3] = top.w;
    let ar = &mut top.model.ar;
    // About the support: I1 = I2 = 26/125 M R^2 + M d^2, I3 = 2/5 M R^2.
    let k = ar.rational(26, 125).unwrap();
    let r2 = ar.powi(r, 2).unwrap();
    let d2 = ar.powi(d, 2).unwrap();
    let a = ar.mul(&[k, m, r2]).unwrap();
    let b = ar.mul(&[m, d2]).unwrap();
    let i1 = ar.add(&[a, b]).unwrap();
    let k3 = ar.rational(2, 5).unwrap();
    let i3 = ar.mul(&[k3, m, r2]).unwrap();
    let z = ar.zero();
    let expected_m = [[i1, z, z], [z, i1, z], [z, z, i3]];
    // n3 in body components: (2(e1 e3 - e0 e2), 2(e2 e3 + e0 e1), ...); gravity torque about the
    // support: d r3 x (-M g n3) = M g d (n3.r2, -n3.r1, 0).
    let two = ar.integer(2);
    let p13 = ar.mul(&[e1, e3]).unwrap();
    let p02 = ar.mul(&[e0, e2]).unwrap();
    let p23 = ar.mul(&[e2, e3]).unwrap();
    let p01 = ar.mul(&[e0, e1]).unwrap();
    let da = ar.sub(p13, p02).unwrap();
    let n3_1 = ar.mul(&[two, da]).unwrap();
    let db = ar.add(&[p23, p01]).unwrap();
    let n3_2 = ar.mul(&[two, db]).unwrap();
    let mgd = ar.mul(&[m, g, d]).unwrap();
    let torque1 = ar.mul(&[mgd, n3_2]).unwrap();
    let t2 = ar.mul(&[mgd, n3_1]).unwrap();
    let torque2 = ar.neg(t2).unwrap();
    // Euler: I1 w1' = (I2 - I3) w2 w3 + N1, I2 w2' = (I3 - I1) w3 w1 + N2, I3 w3' = N3.
    let i1_i3 = ar.sub(i1, i3).unwrap();
    let g1 = ar.mul(&[i1_i3, w2, w3]).unwrap();
    let f1 = ar.add(&[g1, torque1]).unwrap();
    let i3_i1 = ar.sub(i3, i1).unwrap();
    let g2 = ar.mul(&[i3_i1, w3, w1]).unwrap();
    let f2 = ar.add(&[g2, torque2]).unwrap();
    let expected_f = [f1, f2, z];
    let cfg = EquivalenceConfig::default();
    for (i, row) in expected_m.iter().enumerate() {
        for (j, want) in row.iter().enumerate() {
            let v = ar.equivalent(eqs.mass_matrix[i][j], *want, &cfg).unwrap();
            assert_eq!(v, Equivalence::Proven, "M[{i}][{j}] = {}", ar.to_text(eqs.mass_matrix[i][j]));
        }
        let v = ar.equivalent(eqs.forcing[i], expected_f[i], &cfg).unwrap();
        assert_eq!(v, Equivalence::Proven, "f[{i}] = {}", ar.to_text(eqs.forcing[i]));
    }
}

/// Random state with a unit quaternion; returns symbol values including w'.
fn random_state(
    top: &HeavyTop,
    eqs_m: &[Vec<ExprId>],
    eqs_f: &[ExprId],
    rng: &mut impl Rng,
) -> Vec<(SymbolId, f64)> {
    let ar = &top.model.ar;
    let sym = |e: ExprId| ar.as_symbol(e).unwrap();
    let mut vals: Vec<(SymbolId, f64)> = Vec::new();
    for (c, v) in top.constants.iter().zip([1.0, 1.0, 1.0, 1.0]) {
        vals.push((sym(*c), v * rng.random_range(0.5..2.0)));
    }
    let q: Vec<f64> = (0..4).map(|_| rng.random_range(-1.0..1.0)).collect();
    let norm = q.iter().map(|x| x * x).sum::<f64>().sqrt();
    for (e, v) in top.e.iter().zip(&q) {
        vals.push((sym(*e), v / norm));
    }
    for w in top.w {
        vals.push((sym(w), rng.random_range(-5.0..5.0)));
    }
    let at = |e: ExprId, vals: &[(SymbolId, f64)]| {
        ar.eval(&[e], |s| vals.iter().find(|v| v.0 == s).map(|v| v.1)).unwrap()[0]
    };
    let mm = Matrix3::from_fn(|i, j| at(eqs_m[i][j], &vals));
    let ff = Vector3::from_fn(|i, _| at(eqs_f[i], &vals));
    let udot = mm.lu().solve(&ff).unwrap();
    for (i, w) in top.w.iter().enumerate() {
        let wd = ar.lookup(&format!("{}'", ar.symbol_info(sym(*w)).name)).unwrap();
        vals.push((wd, udot[i]));
    }
    vals
}

#[test]
fn energy_and_both_momentum_integrals_are_conserved() {
    let mut top = HeavyTop::new().unwrap();
    let eqs = top.model.kane().unwrap();
    let n = top.model.newtonian();
    let frame = top.model.body(top.rotor).frame;
    let o = top.support;
    let g = top.constants[1];
    let mg = top.model.ar.neg(g).unwrap();
    let gravity = top.model.scale(&top.model.unit(n, 3), mg).unwrap();
    let t = top.model.kinetic_energy().unwrap();
    let v = top.model.gravity_potential(&gravity, o).unwrap();
    let energy = top.model.ar.add(&[t, v]).unwrap();
    let h = top.model.angular_momentum(o, n).unwrap();
    let lz = top.model.dot(&h, &top.model.unit(n, 3)).unwrap();
    let l3 = top.model.dot(&h, &top.model.unit(frame, 3)).unwrap();
    let rates: Vec<ExprId> = [energy, lz, l3].iter().map(|q| top.model.dt(*q).unwrap()).collect();
    let mut rng = rand::rngs::StdRng::seed_from_u64(3);
    for _ in 0..100 {
        let vals = random_state(&top, &eqs.mass_matrix, &eqs.forcing, &mut rng);
        let ar = &top.model.ar;
        for (name, (q, rate)) in ["energy", "L_z", "L_3"].iter().zip([energy, lz, l3].iter().zip(&rates)) {
            let scale =
                ar.eval(&[*q], |s| vals.iter().find(|v| v.0 == s).map(|v| v.1)).unwrap()[0].abs().max(1.0);
            let r = ar.eval(&[*rate], |s| vals.iter().find(|v| v.0 == s).map(|v| v.1)).unwrap()[0];
            assert!(r.abs() < 1e-12 * scale * 25.0, "d({name})/dt = {r}");
        }
    }
}
