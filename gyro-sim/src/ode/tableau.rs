//! Butcher tableaux as data, each citing its source. In: nothing; out: the coefficients of each
//! method (stages, weights, error weights, continuous extension) and its step-size control.

mod verner;

use super::dense::{DenseOutput, DenseRounding};
pub use verner::{VERN7, VERN9};

/// An explicit Runge-Kutta method: `c`, the strictly lower `a`, weights `b`, and for embedded
/// pairs the error weights `e = b - b_hat`.
#[derive(Debug)]
pub struct Tableau {
    /// The name scenes give it (`dop853`).
    pub name: &'static str,
    /// Order of `b`.
    pub order: u32,
    /// The nodes `c` (stage times as fractions of the step).
    pub c: &'static [f64],
    /// Rows of `a` (row i has i entries).
    pub a: &'static [&'static [f64]],
    /// Weights of the solution.
    pub b: &'static [f64],
    /// Error weights `b - b_hat`, for embedded pairs (for DOP853 the fifth-order estimate).
    pub e: Option<&'static [f64]>,
    /// DOP853's third-order error weights, combined with `e` as in Hairer's code.
    pub e3: Option<&'static [f64]>,
    /// The continuous extension used between steps; without one, steps land on output times.
    pub dense: Option<DenseOutput>,
    /// The last stage is `f(t + h, y_new)`, reusable as the next step's first.
    pub fsal: bool,
    /// Step-size control parameters (for embedded pairs).
    pub control: StepControl,
    /// Where the coefficients come from.
    pub source: &'static str,
}

impl Tableau {
    /// Stages a step computes before its error test: all, or all but a first-same-as-last stage
    /// the error estimate does not read (computed once the step is accepted, as in Hairer's
    /// DOP853, so a rejected step does not pay for it).
    pub const fn stages_before_error(&self) -> usize {
        let s = self.c.len();
        if !self.fsal {
            return s;
        }
        if reads_stage(self.e, s - 1) || reads_stage(self.e3, s - 1) {
            s
        } else {
            s - 1
        }
    }
}

/// True when the weights `w` give stage `j` a nonzero weight.
const fn reads_stage(w: Option<&[f64]>, j: usize) -> bool {
    match w {
        Some(w) => j < w.len() && w[j] != 0.0,
        None => false,
    }
}

/// Step-size control of an embedded pair: `h_new = h * 0.9 * err^-alpha * err_old^beta`,
/// `alpha = 1/order - 0.75 beta`, the ratio kept within `[min_factor, max_factor]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepControl {
    /// PI stabilisation exponent (0: the classical controller).
    pub beta: f64,
    /// Smallest ratio of a new step size to the last.
    pub min_factor: f64,
    /// Largest ratio.
    pub max_factor: f64,
}

/// Hairer's defaults for DOPRI5 (Solving ODEs I, section IV.2; dopri5.f: beta 0.04, 0.2..10).
const DOPRI5_CONTROL: StepControl = StepControl { beta: 0.04, min_factor: 0.2, max_factor: 10.0 };

/// Dormand and Prince's 5(4) pair.
pub static DOPRI5: Tableau = Tableau {
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
    e3: None,
    // Shampine's quartic extension: the weights `d` of Hairer's `contd5`.
    dense: Some(DenseOutput {
        c: &[],
        a: &[],
        d: &[&[
            -12715105075.0 / 11282082432.0,
            0.0,
            87487479700.0 / 32700410799.0,
            -10690763975.0 / 1880347072.0,
            701980252875.0 / 199316789632.0,
            -1453857185.0 / 822651844.0,
            69997945.0 / 29380423.0,
        ]],
        rounding: DenseRounding::SumTimesStep,
    }),
    fsal: true,
    control: DOPRI5_CONTROL,
    source: "J. R. Dormand and P. J. Prince, A family of embedded Runge-Kutta formulae, J. Comput. Appl. Math. 6 (1980) 19-26; Hairer, Norsett, Wanner, Solving ODEs I, Table II.5.2; dense output of L. F. Shampine (1986) as in Hairer's DOPRI5 (contd5)",
};

/// The classical fourth-order Runge-Kutta method.
pub static RK4: Tableau = Tableau {
    name: "rk4",
    order: 4,
    c: &[0.0, 0.5, 0.5, 1.0],
    a: &[&[], &[0.5], &[0.0, 0.5], &[0.0, 0.0, 1.0]],
    b: &[1.0 / 6.0, 1.0 / 3.0, 1.0 / 3.0, 1.0 / 6.0],
    e: None,
    e3: None,
    dense: None,
    fsal: false,
    control: DOPRI5_CONTROL,
    source: "W. Kutta, Beitrag zur naeherungsweisen Integration totaler Differentialgleichungen, Z. Math. Phys. 46 (1901); Hairer, Norsett, Wanner, Solving ODEs I, Table II.1.2",
};

/// Hairer's DOP853: Dormand and Prince's 8(5,3) pair (12 stages plus the first-same-as-last).
pub static DOP853: Tableau = Tableau {
    name: "dop853",
    order: 8,
    c: &[0.0, 0.05260015195876773, 0.0789002279381516, 0.1183503419072274, 0.2816496580927726, 0.3333333333333333, 0.25, 0.3076923076923077, 0.6512820512820513, 0.6, 0.8571428571428571, 1.0, 1.0],
    a: &[
        &[],
        &[0.05260015195876773],
        &[0.0197250569845379, 0.0591751709536137],
        &[0.02958758547680685, 0.0, 0.08876275643042054],
        &[0.2413651341592667, 0.0, -0.8845494793282861, 0.924834003261792],
        &[0.037037037037037035, 0.0, 0.0, 0.17082860872947386, 0.12546768756682242],
        &[0.037109375, 0.0, 0.0, 0.17025221101954405, 0.06021653898045596, -0.017578125],
        &[0.03709200011850479, 0.0, 0.0, 0.17038392571223998, 0.10726203044637328, -0.015319437748624402, 0.008273789163814023],
        &[0.6241109587160757, 0.0, 0.0, -3.3608926294469414, -0.868219346841726, 27.59209969944671, 20.154067550477894, -43.48988418106996],
        &[0.47766253643826434, 0.0, 0.0, -2.4881146199716677, -0.590290826836843, 21.230051448181193, 15.279233632882423, -33.28821096898486, -0.020331201708508627],
        &[-0.9371424300859873, 0.0, 0.0, 5.186372428844064, 1.0914373489967295, -8.149787010746927, -18.52006565999696, 22.739487099350505, 2.4936055526796523, -3.0467644718982196],
        &[2.273310147516538, 0.0, 0.0, -10.53449546673725, -2.0008720582248625, -17.9589318631188, 27.94888452941996, -2.8589982771350235, -8.87285693353063, 12.360567175794303, 0.6433927460157636],
        &[0.054293734116568765, 0.0, 0.0, 0.0, 0.0, 4.450312892752409, 1.8915178993145003, -5.801203960010585, 0.3111643669578199, -0.1521609496625161, 0.20136540080403034, 0.04471061572777259],
    ],
    b: &[0.054293734116568765, 0.0, 0.0, 0.0, 0.0, 4.450312892752409, 1.8915178993145003, -5.801203960010585, 0.3111643669578199, -0.1521609496625161, 0.20136540080403034, 0.04471061572777259, 0.0],
    e: Some(&[0.01312004499419488, 0.0, 0.0, 0.0, 0.0, -1.2251564463762044, -0.4957589496572502, 1.6643771824549864, -0.35032884874997366, 0.3341791187130175, 0.08192320648511571, -0.022355307863886294, 0.0]),
    dense: Some(DOP853_DENSE),
    e3: Some(&[-0.18980075407240762, 0.0, 0.0, 0.0, 0.0, 4.450312892752409, 1.8915178993145003, -5.801203960010585, -0.4226823213237919, -0.1521609496625161, 0.20136540080403034, 0.02265179219836082, 0.0]),
    fsal: true,
    // The stabilised PI control of DOPRI5, not dop853.f's defaults (beta 0, ratio within
    // 0.333..6): on the gimbal's Trial 3 at 1e-9 those took 6 % more evaluations for a 6x
    // larger error (measured with `cargo bench -p gyro-sim --bench gimbal`).
    control: DOPRI5_CONTROL,
    source: "E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential Equations I, 2nd ed., section II.10 and the DOP853 code (coefficients of J. R. Dormand and P. J. Prince, 1980, as published with it)",
};

/// DOP853's seventh-degree dense output: three extra stages (`c`, rows of `a` over all earlier
/// stages including `f(t + h, y_new)`) and the four rows `d` over all 16 stages of Hairer's DOP853
/// code (`contd8`), as published with it and tabulated in SciPy's `dop853_coefficients.py`
/// (digits as published).
#[allow(clippy::excessive_precision)]
const DOP853_DENSE: DenseOutput = DenseOutput {
    c: &[0.1, 0.2, 0.777777777777777777777777777778],
    a: &[
        &[
            5.61675022830479523392909219681e-2,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            2.53500210216624811088794765333e-1,
            -2.46239037470802489917441475441e-1,
            -1.24191423263816360469010140626e-1,
            1.5329179827876569731206322685e-1,
            8.20105229563468988491666602057e-3,
            7.56789766054569976138603589584e-3,
            -8.298e-3,
        ],
        &[
            3.18346481635021405060768473261e-2,
            0.0,
            0.0,
            0.0,
            0.0,
            2.83009096723667755288322961402e-2,
            5.35419883074385676223797384372e-2,
            -5.49237485713909884646569340306e-2,
            0.0,
            0.0,
            -1.08347328697249322858509316994e-4,
            3.82571090835658412954920192323e-4,
            -3.40465008687404560802977114492e-4,
            1.41312443674632500278074618366e-1,
        ],
        &[
            -4.28896301583791923408573538692e-1,
            0.0,
            0.0,
            0.0,
            0.0,
            -4.69762141536116384314449447206,
            7.68342119606259904184240953878,
            4.06898981839711007970213554331,
            3.56727187455281109270669543021e-1,
            0.0,
            0.0,
            0.0,
            -1.39902416515901462129418009734e-3,
            2.9475147891527723389556272149,
            -9.15095847217987001081870187138,
        ],
    ],
    d: &[
        &[
            -0.84289382761090128651353491142e1,
            0.0,
            0.0,
            0.0,
            0.0,
            0.56671495351937776962531783590,
            -0.30689499459498916912797304727e1,
            0.23846676565120698287728149680e1,
            0.21170345824450282767155149946e1,
            -0.87139158377797299206789907490,
            0.22404374302607882758541771650e1,
            0.63157877876946881815570249290,
            -0.88990336451333310820698117400e-1,
            0.18148505520854727256656404962e2,
            -0.91946323924783554000451984436e1,
            -0.44360363875948939664310572000e1,
        ],
        &[
            0.10427508642579134603413151009e2,
            0.0,
            0.0,
            0.0,
            0.0,
            0.24228349177525818288430175319e3,
            0.16520045171727028198505394887e3,
            -0.37454675472269020279518312152e3,
            -0.22113666853125306036270938578e2,
            0.77334326684722638389603898808e1,
            -0.30674084731089398182061213626e2,
            -0.93321305264302278729567221706e1,
            0.15697238121770843886131091075e2,
            -0.31139403219565177677282850411e2,
            -0.93529243588444783865713862664e1,
            0.35816841486394083752465898540e2,
        ],
        &[
            0.19985053242002433820987653617e2,
            0.0,
            0.0,
            0.0,
            0.0,
            -0.38703730874935176555105901742e3,
            -0.18917813819516756882830838328e3,
            0.52780815920542364900561016686e3,
            -0.11573902539959630126141871134e2,
            0.68812326946963000169666922661e1,
            -0.10006050966910838403183860980e1,
            0.77771377980534432092869265740,
            -0.27782057523535084065932004339e1,
            -0.60196695231264120758267380846e2,
            0.84320405506677161018159903784e2,
            0.11992291136182789328035130030e2,
        ],
        &[
            -0.25693933462703749003312586129e2,
            0.0,
            0.0,
            0.0,
            0.0,
            -0.15418974869023643374053993627e3,
            -0.23152937917604549567536039109e3,
            0.35763911791061412378285349910e3,
            0.93405324183624310003907691704e2,
            -0.37458323136451633156875139351e2,
            0.10409964950896230045147246184e3,
            0.29840293426660503123344363579e2,
            -0.43533456590011143754432175058e2,
            0.96324553959188282948394950600e2,
            -0.39177261675615439165231486172e2,
            -0.14972683625798562581422125276e3,
        ],
    ],
    rounding: DenseRounding::WeightsTimesStep,
};
