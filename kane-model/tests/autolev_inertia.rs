//! INERTIA with a frame in parentheses (`INERTIA B(A), ...`: measure numbers in A's unit
//! vectors) and about a point (`INERTIA B_O, ...`), against the same inertia given by hand.

use kane_model::lang;

/// A body B turning freely about the fixed point O (three angles, B's mass centre at L along
/// B3>), with a frame A fixed in B turned 30 degrees about B2>, and B's inertia given by `inertia`.
fn top(inertia: &str) -> String {
    format!(
        "NEWTONIAN N\nFRAMES C, D, A\nBODIES B\nPOINTS O\nMOTIONVARIABLES' Q{{3}}', U{{3}}'\n\
         CONSTANTS L, G, M, I{{1:3}}, K{{1:3}}\nSIMPROT(N, C, 3, Q1)\nSIMPROT(C, D, 1, Q2)\n\
         SIMPROT(D, B, 2, Q3)\nSIMPROT(B, A, 2, 30)\nQ1' = U1\nQ2' = U2\nQ3' = U3\nV_O_N> = 0>\n\
         P_O_BO> = L*B3>\nV2PTS(N, B, O, BO)\nMASS B = M\n{inertia}\nGRAVITY(-G*N3>)\n\
         ZERO = FR() + FRSTAR()\nKANE()\n"
    )
}

/// Kane's mass matrix and forcing at one state and set of constants.
fn equations(inertia: &str) -> Vec<f64> {
    let src = top(inertia);
    let m = lang::load("top.al", &src).unwrap_or_else(|r| panic!("{}\n{src}", r.render()));
    let e = m.equations.as_ref().expect("KANE()");
    let at = |name: &str| match name {
        "Q1" => 0.3,
        "Q2" => -0.7,
        "Q3" => 1.1,
        "U1" => 0.4,
        "U2" => -1.3,
        "U3" => 0.9,
        "L" => 0.8,
        "G" => 9.81,
        "M" => 2.5,
        "I1" => 0.9,
        "I2" => 1.4,
        "I3" => 0.6,
        "K1" => 0.11,
        "K2" => -0.07,
        "K3" => 0.05,
        other => panic!("{other}"),
    };
    let mut all: Vec<_> = e.mass_matrix.iter().flatten().copied().collect();
    all.extend(e.forcing.iter().copied());
    m.model.ar.eval(&all, |s| Some(at(&m.model.ar.symbol_info(s).name))).unwrap()
}

fn same(a: &[f64], b: &[f64]) -> bool {
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12 * x.abs().max(1.0))
}

#[test]
fn a_frame_in_parentheses_measures_the_moments_in_its_unit_vectors() {
    let in_a = equations("INERTIA B(A), I1, I2, I3, K1, K2, K3");
    // The same dyadic written with A's unit vectors by hand.
    let by_hand = equations(
        "I_B_BO>> = I1*A1>*A1> + I2*A2>*A2> + I3*A3>*A3> + K1*(A1>*A2> + A2>*A1>) \
         + K2*(A2>*A3> + A3>*A2>) + K3*(A3>*A1> + A1>*A3>)",
    );
    assert!(same(&in_a, &by_hand), "{in_a:?}\n{by_hand:?}");
    // And rotated into B's unit vectors by hand: J = R I R^T with R = B_A, A turned 30 degrees
    // about B2>: A1> = c B1> - s B3>, A3> = s B1> + c B3>.
    let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    let r = [[c, 0.0, s], [0.0, 1.0, 0.0], [-s, 0.0, c]];
    let i = [[0.9, 0.11, 0.05], [0.11, 1.4, -0.07], [0.05, -0.07, 0.6]];
    let j: Vec<Vec<f64>> = (0..3)
        .map(|a| {
            (0..3)
                .map(|b| {
                    (0..3)
                        .flat_map(|k| (0..3).map(move |l| (k, l)))
                        .map(|(k, l)| r[a][k] * i[k][l] * r[b][l])
                        .sum()
                })
                .collect()
        })
        .collect();
    let in_b = equations(&format!(
        "INERTIA B, {}, {}, {}, {}, {}, {}",
        j[0][0], j[1][1], j[2][2], j[0][1], j[1][2], j[2][0]
    ));
    assert!(same(&in_a, &in_b), "{in_a:?}\n{in_b:?}");
    // The body's own frame in parentheses is the plain statement; another frame is not.
    let own = equations("INERTIA B(B), I1, I2, I3, K1, K2, K3");
    let plain = equations("INERTIA B, I1, I2, I3, K1, K2, K3");
    assert!(same(&own, &plain));
    assert!(!same(&in_a, &plain), "the frame changes the equations");
    // A shape's axes are A's too: a 1 x 2 x 3 box, M (b^2 + c^2) / 12, ...
    let boxed = equations("INERTIA B(A), CUBOID(1, 2, 3)");
    assert!(same(&boxed, &equations("INERTIA B(A), M*13/12, M*10/12, M*5/12")));
    assert!(!same(&boxed, &equations("INERTIA B, CUBOID(1, 2, 3)")));
}

#[test]
fn a_point_after_the_body_gives_the_inertia_about_it() {
    // About O, at L B3> from BO: the central moments plus M L^2 about B1> and B2>.
    let about_o = equations("INERTIA B_O, I1 + M*L^2, I2 + M*L^2, I3, K1, K2, K3");
    let central = equations("INERTIA B, I1, I2, I3, K1, K2, K3");
    assert!(same(&about_o, &central), "{about_o:?}\n{central:?}");
    // About O in A's unit vectors: r = L B3> is L (-s A1> + c A3>); I + M (r.r 1 - r r).
    let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    let (m, l) = (2.5, 0.8);
    let r = [-s * l, 0.0, c * l];
    let i = [[0.9, 0.11, 0.05], [0.11, 1.4, -0.07], [0.05, -0.07, 0.6]];
    let o = |a: usize, b: usize| i[a][b] + m * (if a == b { l * l } else { 0.0 } - r[a] * r[b]);
    let about_o_in_a = equations(&format!(
        "INERTIA B_O(A), {}, {}, {}, {}, {}, {}",
        o(0, 0),
        o(1, 1),
        o(2, 2),
        o(0, 1),
        o(1, 2),
        o(2, 0)
    ));
    let central_in_a = equations("INERTIA B(A), I1, I2, I3, K1, K2, K3");
    assert!(same(&about_o_in_a, &central_in_a), "{about_o_in_a:?}\n{central_in_a:?}");
    // About the mass centre by name is the plain statement.
    assert!(same(&equations("INERTIA B_BO, I1, I2, I3, K1, K2, K3"), &central));
}

#[test]
fn inertia_about_a_point_needs_the_mass_and_the_point_fixed_in_the_body() {
    let err = |src: &str| lang::load("e.al", src).err().expect("an error").to_string();
    let head = "NEWTONIAN N\nBODIES B\nPOINTS O, P\nVARIABLES Q'\nCONSTANTS L\n";
    let e = err(&format!("{head}P_O_BO> = L*B3>\nINERTIA B_O, 1, 2, 3\n"));
    assert!(e.contains("B has no mass yet") && e.contains("give MASS B = ... before INERTIA B_O"), "{e}");
    let e = err(&format!("{head}MASS B = 1\nINERTIA B_O, 1, 2, 3\n"));
    assert!(e.contains("INERTIA B_O needs where BO is from O"), "{e}");
    let e = err(&format!("{head}MASS B = 1\nP_P_BO> = Q*B3>\nINERTIA B_P, 1, 2, 3\n"));
    assert!(e.contains("P moves in B"), "{e}");
    let e = err(&format!("{head}INERTIA B(O), 1, 2, 3\n"));
    assert!(e.contains("`O` is not a frame") && e.contains("INERTIA B_O, ..."), "{e}");
    let e = err(&format!("{head}MASS B = 1\nINERTIA B_O, CUBOID(1, 2, 3)\n"));
    assert!(e.contains("INERTIA by shape gives the inertia about the mass centre"), "{e}");
    let e = err(&format!("{head}INERTIA C_O, 1, 2, 3\n"));
    assert!(e.contains("`C_O` is not a body"), "{e}");
}
