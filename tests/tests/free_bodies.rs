//! Torque-free bodies: Euler's equations, the intermediate-axis instability, Feynman's plate;
//! a spring; the gimbal's partial velocity table (the paper's Table 1).

use kane_model::expr::{Equivalence, EquivalenceConfig, SymbolId};
use kane_model::mechanics::{Model, Vector};
use kane_model::models::{FreeBody, GimbalGyroscope};

fn values(body: &FreeBody, i: [f64; 3], w: [f64; 3]) -> Vec<(SymbolId, f64)> {
    let ar = &body.model.ar;
    let mut v = Vec::new();
    for (name, x) in ["I1", "I2", "I3"].iter().zip(i) {
        if let Some(s) = ar.lookup(name) {
            v.push((s, x));
        }
    }
    for (name, x) in [("m", 1.0), ("r", 1.0)] {
        if let Some(s) = ar.lookup(name) {
            v.push((s, x));
        }
    }
    for (e, x) in body.e.iter().zip([1.0, 0.0, 0.0, 0.0]) {
        v.push((ar.as_symbol(*e).unwrap(), x));
    }
    for (e, x) in body.w.iter().zip(w) {
        v.push((ar.as_symbol(*e).unwrap(), x));
    }
    v
}

#[test]
fn torque_free_body_follows_eulers_equations() {
    let mut b = FreeBody::asymmetric().unwrap();
    let eqs = b.model.kane().unwrap();
    let ar = &mut b.model.ar;
    let i = ["I1", "I2", "I3"].map(|n| ar.constant(n).unwrap());
    let [w1, w2, w3] = b.w;
    let cfg = EquivalenceConfig::default();
    // I1 w1' = (I2 - I3) w2 w3, cyclically.
    for (k, (a, bb)) in [(0, (1, 2)), (1, (2, 0)), (2, (0, 1))] {
        let d = ar.sub(i[a], i[bb]).unwrap();
        let (x, y) = match k {
            0 => (w2, w3),
            1 => (w3, w1),
            _ => (w1, w2),
        };
        let want = ar.mul(&[d, x, y]).unwrap();
        assert_eq!(ar.equivalent(eqs.forcing[k], want, &cfg).unwrap(), Equivalence::Proven, "f[{k}]");
        assert_eq!(ar.equivalent(eqs.mass_matrix[k][k], i[k], &cfg).unwrap(), Equivalence::Proven);
    }
}

#[test]
fn rotation_about_the_intermediate_axis_is_unstable() {
    let mut b = FreeBody::asymmetric().unwrap();
    let eqs = b.model.kane().unwrap();
    let max_growth = |b: &mut FreeBody, w: [f64; 3]| {
        let v = values(b, [1.0, 2.0, 3.0], w);
        let a = b.model.linearize(&eqs, &|s| v.iter().find(|x| x.0 == s).map(|x| x.1)).unwrap();
        a.complex_eigenvalues().iter().map(|z| z.re).fold(f64::MIN, f64::max)
    };
    // About axis 2 the growth rate is w sqrt((I2 - I1)(I3 - I2) / (I1 I3)) = sqrt(1/3).
    let growth = max_growth(&mut b, [0.0, 1.0, 0.0]);
    assert!((growth - (1.0f64 / 3.0).sqrt()).abs() < 1e-9, "{growth}");
    assert!(max_growth(&mut b, [1.0, 0.0, 0.0]).abs() < 1e-9);
    assert!(max_growth(&mut b, [0.0, 0.0, 1.0]).abs() < 1e-9);
}

#[test]
fn feynmans_plate_wobbles_twice_as_fast_as_it_spins() {
    let mut b = FreeBody::feynman_plate().unwrap();
    let eqs = b.model.kane().unwrap();
    let spin = 3.0;
    let v = values(&b, [0.0; 3], [0.0, 0.0, spin]);
    let a = b.model.linearize(&eqs, &|s| v.iter().find(|x| x.0 == s).map(|x| x.1)).unwrap();
    // In the body, the transverse rate turns at (I3 - I1)/I1 w3 = w3 for a thin disk.
    let body_rate = a.complex_eigenvalues().iter().map(|z| z.im.abs()).fold(0.0, f64::max);
    assert!((body_rate - spin).abs() < 1e-9, "{body_rate}");
    // In space, the symmetry axis precesses about H at |H| / I1 = 2 w3 for a small wobble.
    let n = b.model.newtonian();
    let o = b.model.point("O").unwrap();
    let h = b.model.angular_momentum(o, n).unwrap();
    let h_mag = b.model.magnitude(&h).unwrap();
    let ar = &b.model.ar;
    let at = |e| ar.eval(&[e], |s| v.iter().find(|x| x.0 == s).map(|x| x.1)).unwrap()[0];
    let i1 = at(eqs.mass_matrix[0][0]);
    assert!((at(h_mag) / i1 / spin - 2.0).abs() < 1e-12);
}

#[test]
fn spring_force_on_a_particle() {
    // A particle on a spring of natural length L to a fixed point: m x'' = -k (|r| - L) x/|r|.
    let mut m = Model::new("N");
    let n = m.newtonian();
    let [mass, k, l] = ["m", "k", "L"].map(|s| m.ar.constant(s).unwrap());
    let q = [m.ar.variable("x").unwrap(), m.ar.variable("y").unwrap()];
    let u = [m.ar.variable("vx").unwrap(), m.ar.variable("vy").unwrap()];
    let o = m.add_point("O").unwrap();
    m.fix_point(o, n);
    let p = m.add_particle("P").unwrap();
    let pt = m.particle(p).point;
    let z = m.ar.zero();
    m.set_position(pt, o, Vector::new(n, [q[0], q[1], z])).unwrap();
    m.set_particle_mass(p, mass);
    m.set_coordinates(&q).unwrap();
    m.set_speeds(&u).unwrap();
    m.set_kinematics(q[0], u[0]).unwrap();
    m.set_kinematics(q[1], u[1]).unwrap();
    m.add_spring(pt, o, k, l).unwrap();
    let c = m.ar.constant("c").unwrap();
    m.add_damper(pt, o, c).unwrap();
    let eqs = m.kane().unwrap();
    let (x, y, vx, vy, kk, ll, cc): (f64, f64, f64, f64, f64, f64, f64) =
        (0.7, -1.1, 0.3, 0.5, 2.0, 0.4, 0.25);
    let vals = [("x", x), ("y", y), ("vx", vx), ("vy", vy), ("k", kk), ("L", ll), ("m", 1.5), ("c", cc)];
    let r = (x * x + y * y).sqrt();
    let rdot = (x * vx + y * vy) / r;
    let fx = -kk * (r - ll) * x / r - cc * rdot * x / r;
    let got = m.ar.eval_named(eqs.forcing[0], &vals).unwrap();
    assert!((got - fx).abs() < 1e-14, "{got} vs {fx}");
    assert_eq!(m.ar.eval_named(eqs.mass_matrix[0][0], &vals).unwrap(), 1.5);
}

#[test]
fn gimbal_partial_angular_velocity_table() {
    let mut g = GimbalGyroscope::new().unwrap();
    let frames = g.bodies.map(|b| g.model.body(b).frame);
    let table = g.model.partial_velocity_table(&frames, &[g.points[1]]).unwrap();
    // B's axis a2 = b2 is kept in A, where its measure numbers are the same.
    let expected = "\
W_B_A> / u1 = -A2>
W_B_A> / u2 = 0>
W_B_A> / u3 = 0>
W_C_A> / u1 = -A2>
W_C_A> / u2 = -B1>
W_C_A> / u3 = 0>
W_D_A> / u1 = -A2>
W_D_A> / u2 = -B1>
W_D_A> / u3 = -C2>
V_P_A> / u1 = ";
    assert!(table.starts_with(expected), "{table}");
}

#[test]
fn quaternion_norm_as_a_configuration_constraint() {
    // The unit-norm condition of Euler parameters is a configuration constraint; its residual
    // stays an output, and its rate vanishes along the kinematic equations.
    let mut b = FreeBody::asymmetric().unwrap();
    let ar = &mut b.model.ar;
    let sq: Vec<_> = b.e.iter().map(|e| ar.powi(*e, 2).unwrap()).collect();
    let norm = ar.add(&sq).unwrap();
    let one = ar.one();
    let residual = ar.sub(norm, one).unwrap();
    b.model.add_configuration_constraint(residual);
    assert_eq!(b.model.configuration_residuals(), &[residual]);
    let rate = b.model.dt(residual).unwrap();
    assert_eq!(b.model.ar.simplify(rate).unwrap(), b.model.ar.zero());
}
