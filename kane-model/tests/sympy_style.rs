//! Files written as SymPy's documentation writes its models: the rolling disc with
//! its speeds chosen as the disc's angular velocity in the lean frame after a SIMPROT chain
//! (`W_R_N> = U1*L1> + U2*L2> + U3*L3>`, the kinematic equations solved from it) and its
//! contact as the disc's material point at rest (`V2PTS(N, R, C, RO)`, Autolev's rolling
//! contact: accepted without a comment).

use kane_model::lang;
use rand::{Rng, SeedableRng};

const DISC: &str = include_str!("data/rolling_disc_sympy.al");
const TRACKED: &str = include_str!("data/rolling_disc_sympy_tracked.al");

#[test]
fn the_rolling_disc_equals_sympys_closed_form() {
    let checked = lang::check("disc.al", DISC).unwrap_or_else(|r| panic!("{}", r.render()));
    assert!(checked.warnings.diagnostics.is_empty(), "{}", checked.warnings.render());
    equals_the_closed_form(&checked.model);
}

#[test]
fn the_tracked_disc_with_its_no_slip_constraints_equals_it_too() {
    // No false contradiction for V_RO_N> = DT(P_O_RO>, N) under CONSTRAIN.
    let checked = lang::check("tracked.al", TRACKED).unwrap_or_else(|r| panic!("{}", r.render()));
    assert!(checked.warnings.diagnostics.is_empty(), "{}", checked.warnings.render());
    assert_eq!(checked.model.outputs.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>(), ["U4", "U5"]);
    equals_the_closed_form(&checked.model);
}

/// SymPy's closed form of the disc's rates at 50 random states.
fn equals_the_closed_form(m: &lang::LoadedModel) {
    let eqs = m.equations.as_ref().unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(24);
    for _ in 0..50 {
        let (q2, u1, u2, u3) = (
            rng.random_range(-1.2..1.2),
            rng.random_range(-2.0..2.0),
            rng.random_range(-2.0..2.0),
            rng.random_range(-2.0..2.0),
        );
        let (r, g) = (rng.random_range(0.5..2.0), rng.random_range(0.5..2.0));
        let value = |s: kane_model::expr::SymbolId| match m.model.ar.symbol_info(s).name.as_str() {
            "Q2" => Some(q2),
            "U1" => Some(u1),
            "U2" => Some(u2),
            "U3" => Some(u3),
            "RAD" => Some(r),
            "G" => Some(g),
            "M" => Some(1.3),
            _ => Some(0.4),
        };
        let rates = eqs.rates_at(&m.model.ar, &value).unwrap();
        // SymPy: q1' = u3 / cos q2, q2' = u1, q3' = u2 - u3 tan q2, and simplify(M^-1 f):
        //   u1' = (4 g sin q2 + 6 r u2 u3 - r u3^2 tan q2) / (5 r)
        //   u2' = -2 u1 u3 / 3
        //   u3' = (-2 u2 + u3 tan q2) u1
        let want_q = [u3 / q2.cos(), u1, u2 - u3 * q2.tan()];
        let want_u = [
            (4.0 * g * q2.sin() + 6.0 * r * u2 * u3 - r * u3 * u3 * q2.tan()) / (5.0 * r),
            -2.0 * u1 * u3 / 3.0,
            (-2.0 * u2 + u3 * q2.tan()) * u1,
        ];
        for (got, want) in
            rates.coordinates[..3].iter().chain(&rates.speeds).zip(want_q.iter().chain(&want_u))
        {
            assert!((got - want).abs() < 1e-12 * want.abs().max(1.0), "{got} vs {want} at q2 = {q2}");
        }
    }
}

#[test]
fn an_angular_velocity_that_leaves_rates_undetermined_is_named() {
    let partial = DISC.replace("SIMPROT(L, R, 2, Q3)", "SIMPROT(L, R, 2, Q3)\nQ3' = U2");
    let e = lang::load("d.al", &partial).err().unwrap().to_string();
    assert!(e.contains("W_R_N> given in speeds") && e.contains("2 of them"), "{e}");
}
