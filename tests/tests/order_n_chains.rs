//! The order-n form of chains of links pinned end to end (relative angles): its `u'` equals the
//! mass-matrix solve's at random states (planar and spatial chains, rigid links with inertia and
//! particles, gravity and applied loads), it is the form generated for longer chains, and its
//! operation count grows linearly with the number of links.

use kane_model::program::taylor::TaylorProgram;
use kane_model::program::{lower, Lowered};
use kane_model::spec::ModelSpec;
use kane_tests::{interpreted_rhs, lowered_rhs as run, normwise};
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rustc_hash::FxHashMap;

/// What a generated chain has.
#[derive(Clone, Copy)]
struct Chain {
    links: usize,
    /// Axes cycling through 3, 1, 2, -2 (else all about 3: planar).
    spatial: bool,
    /// A particle on every other link and an applied torque and force.
    extras: bool,
}

/// The model file of `c`: rigid links `B{i}` turning by `Q{i}` relative to the previous link,
/// pinned at `J{i-1}` (the fixed `O` for the first), mass centres and next pins fixed in them.
fn chain_file(c: Chain) -> String {
    let n = c.links;
    let names = |p: &str| (1..=n).map(|i| format!("{p}{i}")).collect::<Vec<_>>().join(", ");
    let mut s = vec![
        "NEWTONIAN N".to_string(),
        format!("BODIES {}", names("B")),
        format!("POINTS O, {}", names("J")),
        format!("CONSTANTS L{{{n}}}, H{{{n}}}, A{{{n}}}, C{{{n}}}, M{{{n}}}, IX{{{n}}}, IY{{{n}}}, IZ{{{n}}}, MP{{{n}}}, G, T, K, F"),
        format!("VARIABLES Q{{{n}}}', U{{{n}}}'"),
    ];
    if c.extras {
        s.push(format!(
            "PARTICLES {}",
            (1..=n).step_by(2).map(|i| format!("P{i}")).collect::<Vec<_>>().join(", ")
        ));
    }
    let axes = [3, 1, 2, -2];
    for i in 1..=n {
        let parent = if i == 1 { "N".to_string() } else { format!("B{}", i - 1) };
        let axis = if c.spatial { axes[(i - 1) % 4] } else { 3 };
        s.push(format!("SIMPROT({parent}, B{i}, {axis}, Q{i})"));
        s.push(format!("Q{i}' = U{i}"));
    }
    s.push("V_O_N> = 0>".to_string());
    for i in 1..=n {
        let pin = if i == 1 { "O".to_string() } else { format!("J{}", i - 1) };
        let (centre, next) = if c.spatial {
            (format!("A{i}*B{i}1> + C{i}*B{i}2> + H{i}*B{i}3>/2"), format!("L{i}*B{i}1> + H{i}*B{i}3>"))
        } else {
            (format!("L{i}/2*B{i}1>"), format!("L{i}*B{i}1>"))
        };
        s.push(format!("P_{pin}_B{i}O> = {centre}"));
        s.push(format!("P_{pin}_J{i}> = {next}"));
        s.push(format!("V2PTS(N, B{i}, {pin}, B{i}O)"));
        s.push(format!("V2PTS(N, B{i}, {pin}, J{i})"));
        s.push(format!("MASS B{i} = M{i}"));
        if c.spatial {
            s.push(format!("INERTIA B{i}, IX{i}, IY{i}, IZ{i}, IX{i}/10, IY{i}/10, IZ{i}/10"));
        } else {
            s.push(format!("INERTIA B{i}, 0, 0, IZ{i}"));
        }
        if c.extras && i % 2 == 1 {
            s.push(format!("P_{pin}_P{i}> = L{i}/3*B{i}2>"));
            s.push(format!("V2PTS(N, B{i}, {pin}, P{i})"));
            s.push(format!("MASS P{i} = MP{i}"));
        }
    }
    s.push("GRAVITY(-G*N2>)".to_string());
    if c.extras {
        let m = n.div_ceil(2);
        s.push(format!("TORQUE_B{m}> = T*B{m}3> - K*Q{m}*N1>"));
        s.push(format!("FORCE_J{n}> = -F*U{n}*B{n}2>"));
    }
    s.push("ZERO = FR() + FRSTAR()".to_string());
    s.push("KANE()".to_string());
    s.join("\n") + "\n"
}

/// The spec of `c`.
fn spec(c: Chain) -> ModelSpec {
    let loaded =
        kane_model::lang::load("chain.al", &chain_file(c)).unwrap_or_else(|r| panic!("{}", r.render()));
    loaded.into_spec("chain").unwrap()
}

/// Random parameters (by upper-case name) and states.
fn sample(spec: &ModelSpec, rng: &mut StdRng) -> (FxHashMap<String, f64>, Vec<f64>) {
    let mut values = FxHashMap::default();
    for (_, info) in spec.model.ar.symbols() {
        values.insert(info.name.to_ascii_uppercase(), rng.random_range(0.5..1.5));
    }
    let states = spec.states();
    let y: Vec<f64> = (0..states.len()).map(|_| rng.random_range(-1.5..1.5)).collect();
    for (s, v) in states.iter().zip(&y) {
        values.insert(spec.symbol_name(*s).to_ascii_uppercase(), *v);
    }
    (values, y)
}

/// The worst normwise relative difference of `u'`, between the order-n expressions and the
/// generated program each against `M u' = f`, over `samples` random states.
fn worst(c: Chain, samples: usize) -> (f64, f64, Lowered) {
    let mut spec = spec(c);
    let eqs = spec.equations.clone();
    let rates = spec.model.order_n_rates(&eqs).unwrap().expect("the chain is a tree");
    let lowered = lower(&mut spec).unwrap();
    let mut rng = StdRng::seed_from_u64(11);
    let (mut expr_worst, mut code_worst) = (0.0f64, 0.0f64);
    let nq = eqs.coordinates.len();
    for _ in 0..samples {
        let (values, y) = sample(&spec, &mut rng);
        let by_name = |name: &str| values.get(name).copied();
        let (_, want) = interpreted_rhs(&spec.model.ar, &eqs, &by_name);
        let got: Vec<f64> =
            rates.iter().map(|e| kane_tests::value_of(&spec.model.ar, *e, &by_name)).collect();
        expr_worst = expr_worst.max(normwise(&got, &want));
        let code = run(&spec, &lowered, &values, &y);
        code_worst = code_worst.max(normwise(&code[nq..], &want));
    }
    (expr_worst, code_worst, lowered)
}

fn check(c: Chain) {
    let (expr, code, lowered) = worst(c, 20);
    assert!(expr < 1e-12, "{} links: order-n expressions differ by {expr:e}", c.links);
    assert!(code < 1e-12, "{} links: generated rhs differs by {code:e}", c.links);
    if c.links >= 5 {
        assert!(lowered.order_n, "{} links: the order-n form is generated", c.links);
    }
    // Every operation of the order-n form (quotients and integer powers too) has a Taylor
    // recurrence.
    let states = 2 * c.links;
    assert!(TaylorProgram::new(&lowered.program.rhs, states).is_ok());
}

#[test]
fn planar_rigid_chains_agree_with_the_mass_matrix_solve() {
    for links in [2, 5, 8] {
        check(Chain { links, spatial: false, extras: false });
    }
}

#[test]
fn planar_chains_with_particles_and_loads_agree() {
    for links in [2, 5, 8] {
        check(Chain { links, spatial: false, extras: true });
    }
}

#[test]
fn spatial_chains_with_particles_and_loads_agree() {
    for links in [2, 5, 8] {
        check(Chain { links, spatial: true, extras: true });
    }
}

#[test]
fn the_planar_chain_costs_linear_operations() {
    let count = |links| {
        let mut s = spec(Chain { links, spatial: false, extras: false });
        let lowered = lower(&mut s).unwrap();
        assert!(lowered.order_n);
        lowered.program.rhs.op_count()
    };
    let (c10, c20, c40) = (count(10), count(20), count(40));
    // SD/FAST's order-n planar chain: 2,374 / 10,354 operations at 10 / 40 links.
    assert!(c40 <= 10_354, "{c10} {c20} {c40}");
    let (per_link_low, per_link_high) = ((c20 - c10) as f64 / 10.0, (c40 - c20) as f64 / 20.0);
    assert!(per_link_high <= 1.05 * per_link_low, "{c10} {c20} {c40}");
}

/// A spec loaded for generation: a large tree's `M` and `f` may be left unformed.
fn spec_for_generation(file: &str) -> ModelSpec {
    let loaded =
        kane_model::lang::load_for_generation("chain.al", file).unwrap_or_else(|r| panic!("{}", r.render()));
    loaded.into_spec("chain").unwrap()
}

#[test]
fn a_long_chain_is_generated_without_forming_its_mass_matrix() {
    let c = Chain { links: 40, spatial: false, extras: true };
    let mut deferred = spec_for_generation(&chain_file(c));
    assert!(!deferred.equations.formed, "M and f wait for the mass-matrix form");
    let lowered = lower(&mut deferred).unwrap();
    assert!(lowered.order_n);
    assert!(!deferred.equations.formed, "the order-n form needs no M");
    let eager = spec(c);
    let mut rng = StdRng::seed_from_u64(5);
    let nq = c.links;
    for _ in 0..5 {
        let (values, y) = sample(&eager, &mut rng);
        let by_name = |name: &str| values.get(name).copied();
        let (_, want) = interpreted_rhs(&eager.model.ar, &eager.equations, &by_name);
        let code = run(&deferred, &lowered, &values, &y);
        // The reference solves a 40-link M, whose conditioning costs it digits (about 3e-12 here).
        let d = normwise(&code[nq..], &want);
        assert!(d < 1e-10, "{d:e}");
    }
}

#[test]
fn a_statement_that_changes_the_model_after_kane_forms_the_equations_first() {
    let c = Chain { links: 20, spatial: false, extras: false };
    let file = chain_file(c) + "MASS B1 = 5*M1\n";
    let deferred = spec_for_generation(&file);
    assert!(deferred.equations.formed);
    let eager = kane_model::lang::load("chain.al", &file).unwrap().into_spec("chain").unwrap();
    let mut rng = StdRng::seed_from_u64(6);
    let (values, _) = sample(&eager, &mut rng);
    let by_name = |name: &str| values.get(name).copied();
    let (_, want) = interpreted_rhs(&eager.model.ar, &eager.equations, &by_name);
    let (_, got) = interpreted_rhs(&deferred.model.ar, &deferred.equations, &by_name);
    assert!(normwise(&got, &want) < 1e-12, "the equations use the mass at KANE()");
    assert!(lower(&mut { deferred }).unwrap().order_n);
}
