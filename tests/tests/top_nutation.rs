//! Linearization: the heavy top's nutation frequency about steady precession, from the A matrix
//! of Kane's equations, against Routh's effective potential and the fast-top formula.

use kane_model::expr::{ExprId, SymbolId};
use kane_model::mechanics::{KaneEquations, Model, Orientation, Shape};

/// The EJS top in body-fixed 3-1-3 Euler angles (precession, nutation, spin), `q' = u`.
fn euler_angle_top() -> (Model, KaneEquations, [ExprId; 3], [ExprId; 3]) {
    let mut m = Model::new("N");
    let n = m.newtonian();
    let [mass, g, r, d] = ["M", "g", "R", "d"].map(|s| m.ar.constant(s).unwrap());
    let q = ["phi", "theta", "psi"].map(|s| m.ar.variable(s).unwrap());
    let u = ["u1", "u2", "u3"].map(|s| m.ar.variable(s).unwrap());
    let body = m.add_body("B").unwrap();
    let f = m.body(body).frame;
    m.orient(f, n, Orientation::BodyFixed { axes: [3, 1, 3], angles: q }).unwrap();
    m.set_coordinates(&q).unwrap();
    m.set_speeds(&u).unwrap();
    for i in 0..3 {
        m.set_kinematics(q[i], u[i]).unwrap();
    }
    let fifth = m.ar.rational(1, 5).unwrap();
    let c = m.ar.mul(&[fifth, r]).unwrap();
    let inertia = m.shape_inertia(Shape::SolidEllipsoid { a: r, b: r, c }, mass, f).unwrap();
    m.set_mass(body, mass);
    m.set_inertia(body, inertia);
    let o = m.add_point("O").unwrap();
    m.fix_point(o, n);
    let cm = m.body(body).mass_center;
    let arm = m.scale(&m.unit(f, 3), d).unwrap();
    m.set_position(cm, o, arm).unwrap();
    let mg = m.ar.neg(g).unwrap();
    let grav = m.scale(&m.unit(n, 3), mg).unwrap();
    m.add_gravity(&grav).unwrap();
    let eqs = m.kane().unwrap();
    (m, eqs, q, u)
}

/// Nutation frequency at `theta0` with spin component `w3` (M = g = R = d = 1).
fn frequencies(theta0: f64, w3: f64) -> (f64, f64, f64) {
    let (i1, i3, mgd) = (26.0 / 125.0 + 1.0, 0.4, 1.0);
    // Steady precession: M g d = W (I3 w3 - I1 W cos theta0), slow root.
    let c = theta0.cos();
    let prec = (i3 * w3 - ((i3 * w3).powi(2) - 4.0 * i1 * c * mgd).sqrt()) / (2.0 * i1 * c);
    let spin = w3 - prec * c;

    let (mut model, eqs, q, u) = euler_angle_top();
    let values: Vec<(SymbolId, f64)> = {
        let ar = &model.ar;
        let mut v: Vec<(SymbolId, f64)> =
            ["M", "g", "R", "d"].iter().map(|n| (ar.lookup(n).unwrap(), 1.0)).collect();
        for (e, x) in q.iter().zip([0.3, theta0, 0.7]) {
            v.push((ar.as_symbol(*e).unwrap(), x));
        }
        for (e, x) in u.iter().zip([prec, 0.0, spin]) {
            v.push((ar.as_symbol(*e).unwrap(), x));
        }
        v
    };
    let a = model.linearize(&eqs, &|s| values.iter().find(|v| v.0 == s).map(|v| v.1)).unwrap();
    let kane = a.complex_eigenvalues().iter().map(|z| z.im.abs()).fold(0.0, f64::max);

    // Routh: V_eff = (p_phi - p_psi cos th)^2 / (2 I1 sin^2 th) + M g d cos th, w^2 = V_eff'' / I1.
    let p_psi = i3 * w3;
    let p_phi = i1 * prec * theta0.sin().powi(2) + p_psi * c;
    let v_eff = |th: f64| (p_phi - p_psi * th.cos()).powi(2) / (2.0 * i1 * th.sin().powi(2)) + mgd * th.cos();
    let h = 1e-4;
    let v2 = (v_eff(theta0 + h) - 2.0 * v_eff(theta0) + v_eff(theta0 - h)) / (h * h);
    (kane, (v2 / i1).sqrt(), i3 * w3 / i1)
}

#[test]
fn nutation_frequency_matches_the_effective_potential() {
    for (theta0, w3) in [(std::f64::consts::FRAC_PI_3, 10.0), (0.5, 25.0), (1.2, 6.0)] {
        let (kane, routh, _) = frequencies(theta0, w3);
        assert!((kane - routh).abs() < 1e-6 * routh, "theta0 {theta0}, w3 {w3}: {kane} vs {routh}");
    }
}

#[test]
fn fast_top_nutation_approaches_i3_w3_over_i1() {
    let (slow, _, slow_formula) = frequencies(std::f64::consts::FRAC_PI_3, 10.0);
    let (fast, _, fast_formula) = frequencies(std::f64::consts::FRAC_PI_3, 200.0);
    let slow_err = (slow - slow_formula).abs() / slow_formula;
    let fast_err = (fast - fast_formula).abs() / fast_formula;
    assert!(fast_err < 1e-3, "fast top: {fast} vs {fast_formula}");
    assert!(fast_err < slow_err / 10.0, "the formula improves with spin: {slow_err} then {fast_err}");
}
