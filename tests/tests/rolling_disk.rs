//! The rolling disk: SymPy's closed-form right-hand side, and the same equations whether the
//! contact point is taken as fixed or tracked with two nonholonomic constraints.

use kane_model::expr::{Arena, SymbolId};
use kane_model::mechanics::{KaneEquations, Rates};
use kane_model::models::RollingDisk;
use rand::{Rng, SeedableRng};

/// `q'` and `u'` at a state given by symbol (constraints solved numerically).
fn rates(ar: &Arena, eqs: &KaneEquations, values: &[(SymbolId, f64)]) -> Rates {
    eqs.rates_at(ar, &|s| values.iter().find(|v| v.0 == s).map(|v| v.1)).unwrap()
}

/// `u'` at a state given by symbol.
fn udot(ar: &Arena, eqs: &KaneEquations, values: &[(SymbolId, f64)]) -> Vec<f64> {
    rates(ar, eqs, values).speeds
}

fn state(ar: &Arena, rng: &mut impl Rng) -> Vec<(SymbolId, f64)> {
    ["q1", "q2", "q3", "x", "y", "u1", "u2", "u3", "r", "m", "g"]
        .iter()
        .filter_map(|n| ar.lookup(n))
        .map(|s| {
            let name = ar.symbol_info(s).name.clone();
            let v = match name.as_str() {
                "q2" => rng.random_range(-1.2..1.2),
                "r" | "m" | "g" => rng.random_range(0.5..2.0),
                _ => rng.random_range(-2.0..2.0),
            };
            (s, v)
        })
        .collect()
}

fn value(ar: &Arena, values: &[(SymbolId, f64)], name: &str) -> f64 {
    let s = ar.lookup(name).unwrap();
    values.iter().find(|v| v.0 == s).unwrap().1
}

#[test]
fn contact_fixed_disk_matches_sympys_closed_form() {
    // SymPy 1.14, sympy/physics/mechanics rolling-disc example, simplify(M^-1 f):
    //   u1' = (4 g sin q2 + 6 r u2 u3 - r u3^2 tan q2) / (5 r)
    //   u2' = -2 u1 u3 / 3
    //   u3' = (-2 u2 + u3 tan q2) u1
    let mut disk = RollingDisk::contact_fixed().unwrap();
    let eqs = disk.model.kane().unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(5);
    for _ in 0..50 {
        let vals = state(&disk.model.ar, &mut rng);
        let got = udot(&disk.model.ar, &eqs, &vals);
        let v = |n: &str| value(&disk.model.ar, &vals, n);
        let (q2, u1, u2, u3, r, g) = (v("q2"), v("u1"), v("u2"), v("u3"), v("r"), v("g"));
        let want = [
            (4.0 * g * q2.sin() + 6.0 * r * u2 * u3 - r * u3 * u3 * q2.tan()) / (5.0 * r),
            -2.0 * u1 * u3 / 3.0,
            (-2.0 * u2 + u3 * q2.tan()) * u1,
        ];
        assert_speed_rates_agree(&got, &want);
    }
}

#[test]
fn nonholonomic_disk_equals_the_contact_fixed_disk() {
    let mut fixed = RollingDisk::contact_fixed().unwrap();
    let fixed_eqs = fixed.model.kane().unwrap();
    let mut tracked = RollingDisk::nonholonomic().unwrap();
    let eqs = tracked.model.kane().unwrap();
    assert_eq!(eqs.speeds.len(), 3);
    assert_eq!(eqs.constraints.as_ref().map(|c| c.dependent.len()), Some(2));
    assert_eq!(eqs.kinematics.len(), 5);
    let mut rng = rand::rngs::StdRng::seed_from_u64(6);
    for _ in 0..50 {
        let vals = state(&tracked.model.ar, &mut rng);
        let got = udot(&tracked.model.ar, &eqs, &vals);
        let by_name: Vec<(SymbolId, f64)> = vals
            .iter()
            .filter_map(|(s, v)| {
                fixed.model.ar.lookup(&tracked.model.ar.symbol_info(*s).name).map(|t| (t, *v))
            })
            .collect();
        let want = udot(&fixed.model.ar, &fixed_eqs, &by_name);
        assert_speed_rates_agree(&got, &want);
        // The contact point moves as the rolling constraint says: x' = r (u2 - u3 tan q2) cos q1.
        let v = |n: &str| value(&tracked.model.ar, &vals, n);
        let xdot = rates(&tracked.model.ar, &eqs, &vals).coordinates[3];
        let want_x = v("r") * (v("u2") - v("u3") * v("q2").tan()) * v("q1").cos();
        assert!((xdot - want_x).abs() < 1e-12 * want_x.abs().max(1.0), "x' {xdot} vs {want_x}");
    }
}

/// The three speed derivatives agree to 1e-11 relative.
fn assert_speed_rates_agree(got: &[f64], want: &[f64]) {
    for i in 0..3 {
        assert!(
            (got[i] - want[i]).abs() < 1e-11 * want[i].abs().max(1.0),
            "u{}' {} vs {}",
            i + 1,
            got[i],
            want[i]
        );
    }
}

#[test]
fn the_generated_constrained_rhs_equals_the_numeric_reduction_upright_included() {
    let mut tracked = RollingDisk::nonholonomic().unwrap();
    let eqs = tracked.model.kane().unwrap();
    let mut spec = kane_model::spec::ModelSpec::new("disk", tracked.model, eqs.clone());
    let lowered = kane_model::program::lower(&mut spec).unwrap();
    let mut rng = rand::rngs::StdRng::seed_from_u64(7);
    for k in 0..40 {
        let mut vals = state(&spec.model.ar, &mut rng);
        if k % 4 == 0 {
            // Exactly upright, a symmetric state of the disc.
            let q2 = spec.model.ar.lookup("q2").unwrap();
            vals.iter_mut().filter(|v| v.0 == q2).for_each(|v| v.1 = 0.0);
        }
        let want = rates(&spec.model.ar, &eqs, &vals);
        let by_name: rustc_hash::FxHashMap<String, f64> =
            vals.iter().map(|(s, v)| (spec.model.ar.symbol_info(*s).name.to_ascii_uppercase(), *v)).collect();
        let y: Vec<f64> =
            spec.states().iter().map(|s| by_name[&spec.symbol_name(*s).to_ascii_uppercase()]).collect();
        let got = kane_tests::lowered_rhs(&spec, &lowered, &by_name, &y);
        let mut expected = want.coordinates.clone();
        expected.extend(&want.speeds);
        assert!(got.iter().all(|v| v.is_finite()), "{got:?}");
        assert!(kane_tests::normwise(&got, &expected) < 1e-12, "{got:?} vs {expected:?}");
    }
}
