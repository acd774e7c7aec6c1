//! The four-bar loop of `kane-model/models/four_bar.al`: two configuration constraints whose
//! derivatives are the motion constraints. Its start is assembled by Newton onto the closed
//! loop; its lowered right-hand side equals the interpreted equations at assembled states;
//! a parallelogram linkage (crank and rocker equal, coupler equal to the ground link) moves as
//! a hand derivation says it must.

use kane_model::program::{lower, ProgramModel};
use kane_model::spec::ModelSpec;
use rustc_hash::FxHashMap;

const FOUR_BAR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/../kane-model/models/four_bar.al");

struct Loop {
    spec: ModelSpec,
    model: ProgramModel,
    values: FxHashMap<String, f64>,
}

fn four_bar(sets: &[(&str, f64)]) -> Loop {
    let source = std::fs::read_to_string(FOUR_BAR).unwrap();
    let loaded = kane_model::lang::check_for_generation(FOUR_BAR, &source)
        .unwrap_or_else(|r| panic!("{}", r.render()))
        .model;
    let mut values: FxHashMap<String, f64> =
        loaded.inputs.iter().map(|i| (i.name.to_ascii_uppercase(), i.value)).collect();
    values.extend(sets.iter().map(|(k, v)| (k.to_string(), *v)));
    let mut spec = loaded.into_spec("four_bar").unwrap();
    let model = ProgramModel::new(&mut spec).unwrap();
    Loop { spec, model, values }
}

impl Loop {
    fn params(&self) -> Vec<f64> {
        self.model.info().param_names.iter().map(|n| self.values[*n]).collect()
    }

    /// The state with the file's values, its dependent coordinates assembled.
    fn assembled(&self) -> Vec<f64> {
        let mut y: Vec<f64> = self.model.info().state_names.iter().map(|n| self.values[*n]).collect();
        let a = self.model.assemble(&self.params(), &mut y).expect("configuration constraints").unwrap();
        assert!(a.residual < 1e-14, "{a:?}");
        y
    }

    /// `y'` from the lowered program and from the interpreted equations (pivoted LU).
    fn rates(&mut self, y: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let mut values = self.values.clone();
        for (n, v) in self.model.info().state_names.iter().zip(y) {
            values.insert(n.to_string(), *v);
        }
        let lowered = lower(&mut self.spec).unwrap();
        let generated = kane_tests::lowered_rhs(&self.spec, &lowered, &values, y);
        let by_name = |n: &str| values.get(n).copied();
        let (qdot, udot) = kane_tests::interpreted_rhs(&self.spec.model.ar, &self.spec.equations, &by_name);
        (generated, qdot.into_iter().chain(udot).collect())
    }
}

#[test]
fn assembled_states_give_the_same_rates_lowered_and_interpreted() {
    for crank in [-2.5, -1.0, 0.2, 1.2, 2.9] {
        let mut l = four_bar(&[("Q1", crank), ("U1", 1.5)]);
        let y = l.assembled();
        let (generated, interpreted) = l.rates(&y);
        assert!(generated.iter().all(|x| x.is_finite()), "crank {crank}: {generated:?}");
        let d = kane_tests::normwise(&generated, &interpreted);
        assert!(d < 1e-12, "crank {crank}: lowered vs interpreted {d:e}");
    }
}

#[test]
fn a_parallelogram_moves_as_the_hand_derivation_says() {
    // LA = LC = 1, LB = LD = 2.5: the coupler translates (Q2 = 0, U2 = 0) and the rocker
    // follows the crank (Q3 = Q1, U3 = U1). Energy: KE = (MA + MC) LA^2 U1^2 / 6 +
    // MB LA^2 U1^2 / 2, PE = G LA sin(Q1) (MA / 2 + MC / 2 + MB), so
    // U1' = -G cos(Q1) (MA + MC + 2 MB) / (LA (2 (MA + MC) / 3 + 2 MB)).
    let (ma, mb, mc, g, q1, u1) = (1.0, 2.0, 1.5, 9.81, 1.0_f64, 0.7);
    let mut l = four_bar(&[("LC", 1.0), ("Q1", q1), ("Q2", 0.1), ("Q3", 0.9), ("U1", u1)]);
    let y = l.assembled();
    assert!(y[1].abs() < 1e-14 && (y[2] - q1).abs() < 1e-14, "assembled {y:?}");
    let (generated, interpreted) = l.rates(&y);
    let want = -g * q1.cos() * (ma + mc + 2.0 * mb) / (2.0 * (ma + mc) / 3.0 + 2.0 * mb);
    for rates in [&generated, &interpreted] {
        // y' = (Q1', Q2', Q3', U1'): U2 and U3 are the dependent speeds.
        assert!((rates[0] - u1).abs() < 1e-14 && rates[1].abs() < 1e-14 && (rates[2] - u1).abs() < 1e-14);
        assert!((rates[3] - want).abs() < 1e-13 * want.abs(), "U1' = {} vs {want}", rates[3]);
    }
}
