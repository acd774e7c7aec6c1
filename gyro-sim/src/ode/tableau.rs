//! Butcher tableaux as data, each citing its source.

/// An explicit Runge-Kutta method: `c`, the strictly lower `a`, weights `b`, and for embedded
/// pairs the error weights `e = b - b_hat`.
#[derive(Debug)]
pub struct Tableau {
    /// Name.
    pub name: &'static str,
    /// Order of `b`.
    pub order: u32,
    /// Nodes.
    pub c: &'static [f64],
    /// Rows of `a` (row i has i entries).
    pub a: &'static [&'static [f64]],
    /// Weights of the solution.
    pub b: &'static [f64],
    /// Error weights `b - b_hat`, for embedded pairs.
    pub e: Option<&'static [f64]>,
    /// The last stage is `f(t + h, y_new)`, reusable as the next step's first.
    pub fsal: bool,
    /// Where the coefficients come from.
    pub source: &'static str,
}

/// Dormand and Prince's 5(4) pair.
pub const DOPRI5: Tableau = Tableau {
    name: "dopri5",
    order: 5,
    c: &[0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0],
    a: &[
        &[],
        &[1.0 / 5.0],
        &[3.0 / 40.0, 9.0 / 40.0],
        &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
        &[19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0],
        &[9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0],
        &[35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0],
    ],
    b: &[35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0, 0.0],
    e: Some(&[
        71.0 / 57600.0,
        0.0,
        -71.0 / 16695.0,
        71.0 / 1920.0,
        -17253.0 / 339200.0,
        22.0 / 525.0,
        -1.0 / 40.0,
    ]),
    fsal: true,
    source: "J. R. Dormand and P. J. Prince, A family of embedded Runge-Kutta formulae, J. Comput. Appl. Math. 6 (1980) 19-26; Hairer, Norsett, Wanner, Solving ODEs I, Table II.5.2",
};

/// The classical fourth-order Runge-Kutta method.
pub const RK4: Tableau = Tableau {
    name: "rk4",
    order: 4,
    c: &[0.0, 0.5, 0.5, 1.0],
    a: &[&[], &[0.5], &[0.0, 0.5], &[0.0, 0.0, 1.0]],
    b: &[1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
    e: None,
    fsal: false,
    source: "W. Kutta, Beitrag zur naeherungsweisen Integration totaler Differentialgleichungen, Z. Math. Phys. 46 (1901); Hairer, Norsett, Wanner, Solving ODEs I, Table II.1.2",
};
