//! Equations of motion a file forms itself: `ZERO = FR() + FRSTAR()` then
//! `SOLVE(ZERO, U1', ...)` for every independent speed's rate, without KANE(). Unchanged, they
//! are KANE()'s equations (constraints included, solved numerically); changed by hand, their
//! coefficients are read off; KANE with arguments is refused with its reason.

use kane_model::lang;

/// A rod of mass M hinged at O, its mass centre at L along A1>, with `ending` after GRAVITY.
fn rod(ending: &str) -> String {
    format!(
        "NEWTONIAN N\nBODIES A\nPOINTS O\nCONSTANTS L, M, G, K\nVARIABLES Q', U'\nSIMPROT(N, A, 3, Q)\n\
         Q' = U\nP_O_AO> = L*A1>\nV_O_N> = 0>\nV_AO_N> = DT(P_O_AO>, N)\nMASS A = M\n\
         INERTIA A, 0, M*L^2/12, M*L^2/12\nGRAVITY(-G*N2>)\n{ending}\n"
    )
}

/// `U'` of a loaded file at L = 1, M = 3, G = 9.81, K = 2, Q = 0.1, U = 0.
fn rate(m: &lang::LoadedModel) -> f64 {
    let eqs = m.equations.as_ref().expect("equations of motion");
    let value = |s: kane_model::expr::SymbolId| match m.model.ar.symbol_info(s).name.as_str() {
        "L" => Some(1.0),
        "M" => Some(3.0),
        "G" => Some(9.81),
        "K" => Some(2.0),
        "Q" => Some(0.1),
        _ => Some(0.0),
    };
    eqs.rates_at(&m.model.ar, &value).unwrap().speeds[0]
}

#[test]
fn solve_of_fr_plus_frstar_gives_kanes_equations() {
    let solved = lang::load("s.al", &rod("ZERO = FR() + FRSTAR()\nSOLVE(ZERO, U')")).unwrap();
    let kane = lang::load("k.al", &rod("ZERO = FR() + FRSTAR()\nKANE()")).unwrap();
    // (M L^2 / 12 + M L^2) U' = -M G L cos(Q).
    let want = -3.0 * 9.81 * 0.1_f64.cos() / (3.0 / 12.0 + 3.0);
    assert!((rate(&solved) - want).abs() < 1e-13 && rate(&solved) == rate(&kane), "{} {want}", rate(&solved));
}

#[test]
fn equations_changed_by_hand_are_read_off_their_coefficients() {
    let m =
        lang::load("h.al", &rod("ZERO = FR() + FRSTAR()\nZERO[1] = ZERO[1] - K*Q\nSOLVE(ZERO, U')")).unwrap();
    let want = (-3.0 * 9.81 * 0.1_f64.cos() - 2.0 * 0.1) / (3.0 / 12.0 + 3.0);
    assert!((rate(&m) - want).abs() < 1e-13, "{} vs {want}", rate(&m));
}

#[test]
fn a_constrained_file_solved_without_kane_equals_kane() {
    let kane = include_str!("data/rolling_disc.al");
    let solved = kane.replace("KANE()", "SOLVE(ZERO, U3', U1', U2')");
    let (a, b) = (lang::load("k.al", kane).unwrap(), lang::load("s.al", &solved).unwrap());
    let value = |m: &lang::LoadedModel| {
        let inputs: Vec<(String, f64)> =
            m.inputs.iter().map(|i| (i.name.to_ascii_uppercase(), i.value)).collect();
        let eqs = m.equations.as_ref().unwrap();
        let by = |s: kane_model::expr::SymbolId| {
            let n = m.model.ar.symbol_info(s).name.to_ascii_uppercase();
            inputs.iter().find(|i| i.0 == n).map(|i| i.1)
        };
        eqs.rates_at(&m.model.ar, &by).unwrap().speeds
    };
    assert_eq!(value(&a), value(&b));
    // Changed by hand, a constrained file's equations are refused with the way out.
    let changed = solved.replace("ZERO = FR() + FRSTAR()", "ZERO = FR() + FRSTAR()\nZERO[1] = ZERO[1] + 0");
    let e = lang::load("c.al", &changed).err().unwrap().to_string();
    assert!(e.contains("motion constraints is not supported") && e.contains("help:"), "{e}");
}

#[test]
fn solving_for_some_rates_only_stays_an_algebraic_solve() {
    let m =
        lang::load("p.al", &rod("ZERO = FR() + FRSTAR()\nZERO[1] = ZERO[1] - K*Q\nSOLVE(ZERO, K)")).unwrap();
    assert!(m.equations.is_none(), "K is not a speed's rate: no equations of motion");
}

#[test]
fn kane_with_arguments_needs_as_many_auxiliary_speeds() {
    let e =
        lang::load("t.al", &rod("SPECIFIED T\nZERO = FR() + FRSTAR()\nKANE(T)")).err().unwrap().to_string();
    assert!(e.contains("KANE names 1 loads but CONSTRAIN(AUXILIARY[...]) declared 0"), "{e}");
}

#[test]
fn solve_takes_a_bracketed_list_and_rhs_reads_solved_assigned_and_kinematic_quantities() {
    let bracketed =
        lang::load("b.al", &rod("ZERO = FR() + FRSTAR()\nSOLVE(ZERO, [U'])\nUD = RHS(U')")).unwrap();
    let want = -3.0 * 9.81 * 0.1_f64.cos() / (3.0 / 12.0 + 3.0);
    assert!((rate(&bracketed) - want).abs() < 1e-13, "{}", rate(&bracketed));
    // RHS(U') of the equations of motion: U' solved symbolically (one speed).
    let Some(lang::Value::Scalar(ud)) = bracketed.value("UD") else { panic!("UD") };
    let at = |s: kane_model::expr::SymbolId| match bracketed.model.ar.symbol_info(s).name.as_str() {
        "L" => Some(1.0),
        "M" => Some(3.0),
        "G" => Some(9.81),
        "Q" => Some(0.1),
        _ => Some(0.0),
    };
    let ud = bracketed.model.ar.eval(&[ud], at).unwrap()[0];
    assert!((ud - want).abs() < 1e-13, "{ud} vs {want}");
    let src = "VARIABLES X, Y, Q', U'\nQ' = 2*U\nZ = 5*X\nEQN[1] = X + Y - 3\nEQN[2] = X - Y - 1\n\
               SOLVE(EQN, [X, Y])\nA = RHS(X)\nB = RHS(Y)\nC = RHS(Z)\nD = RHS(Q')\n";
    let m = lang::load("r.al", src).unwrap();
    let text = |name: &str| match m.value(name) {
        Some(lang::Value::Scalar(x)) => m.model.ar.to_text(x),
        other => panic!("{name}: {other:?}"),
    };
    assert_eq!(
        (text("A"), text("B"), text("C"), text("D")),
        ("2".into(), "1".into(), "5*X".into(), "2*U".into())
    );
    let e = lang::load("n.al", "VARIABLES X\nA = RHS(X)\n").err().unwrap().to_string();
    assert!(e.contains("`X` has not been solved for or assigned"), "{e}");
}
