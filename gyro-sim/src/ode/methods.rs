//! The methods by name. In: a name (a scene's `method`); out: its [`MethodInfo`] (tableau, order,
//! adaptive or fixed step), or None for a name the table does not have, which the caller reports.
//! Also [`Method`] and [`Tolerances`], what an integration is told to use. A new method is its
//! tableau's data in [`crate::ode::tableau`] and one row of [`METHODS`]; the row is checked at
//! compile time, and every row takes the unrolled steps. The Taylor method (`taylor`, no
//! tableau: the model's own Taylor coefficients, see [`super::taylor`]) is one more row.

use super::dense::DenseRounding;
use super::tableau::{Tableau, DOP853, DOPRI5, RK4, VERN7, VERN9};

/// Error tolerances in Autolev's sense: each component's local error is kept below
/// `atol + rtol * |y|` (RMS over components).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerances {
    /// Relative tolerance (Autolev's RELERR).
    pub rtol: f64,
    /// Absolute tolerance (Autolev's ABSERR).
    pub atol: f64,
}

/// How to integrate.
#[derive(Clone, Copy, Debug)]
pub enum Method {
    /// An embedded pair with error control.
    Adaptive(&'static Tableau, Tolerances),
    /// A fixed step no larger than the given one (shortened evenly to land on stop times).
    Fixed(&'static Tableau, f64),
    /// The Taylor method on the system's own Taylor coefficients: order and step from the
    /// tolerances.
    Taylor(Tolerances),
}

impl Method {
    /// The tableau of a Runge-Kutta method (None for the Taylor method).
    pub fn tableau(&self) -> Option<&'static Tableau> {
        match self {
            Method::Adaptive(tab, _) | Method::Fixed(tab, _) => Some(tab),
            Method::Taylor(_) => None,
        }
    }

    /// The same method at other tolerances (a fixed-step method unchanged).
    pub fn with_tolerances(&self, tol: Tolerances) -> Method {
        match *self {
            Method::Adaptive(tab, _) => Method::Adaptive(tab, tol),
            Method::Taylor(_) => Method::Taylor(tol),
            fixed @ Method::Fixed(..) => fixed,
        }
    }
}

/// The name scenes give the Taylor method.
pub const TAYLOR: &str = "taylor";

/// A method the scenes can name.
#[derive(Debug)]
pub struct MethodInfo {
    /// Its coefficients (name and order included); None for the Taylor method.
    pub tableau: Option<&'static Tableau>,
    /// Steps are chosen by error control (the tableau is an embedded pair); otherwise fixed.
    pub adaptive: bool,
}

impl MethodInfo {
    /// The name scenes use.
    pub fn name(&self) -> &'static str {
        self.tableau.map_or(TAYLOR, |t| t.name)
    }

    /// The order of the solution weights (None for the Taylor method: it follows the tolerance).
    pub fn order(&self) -> Option<u32> {
        self.tableau.map(|t| t.order)
    }

    /// Whether states between steps can be had (a continuous extension, or the Taylor series).
    pub fn dense_output(&self) -> bool {
        self.tableau.is_none_or(|t| t.dense.is_some())
    }

    /// The [`Method`]: `tol` for an adaptive one, `step` for a fixed-step one.
    pub fn method(&self, tol: Tolerances, step: f64) -> Method {
        match self.tableau {
            None => Method::Taylor(tol),
            Some(tab) if self.adaptive => Method::Adaptive(tab, tol),
            Some(tab) => Method::Fixed(tab, step),
        }
    }
}

/// Every method by name, in the order help texts list them.
pub static METHODS: &[MethodInfo] = &[
    MethodInfo { tableau: Some(&DOP853), adaptive: true },
    MethodInfo { tableau: Some(&DOPRI5), adaptive: true },
    MethodInfo { tableau: Some(&VERN7), adaptive: true },
    MethodInfo { tableau: Some(&VERN9), adaptive: true },
    MethodInfo { tableau: Some(&RK4), adaptive: false },
    MethodInfo { tableau: None, adaptive: true },
];

/// The name that picks the method by the tolerances ([`for_tolerances`]); a scene's default.
pub const AUTO: &str = "auto";

/// Below this tolerance (the larger of `rtol`, `atol`), [`for_tolerances`] picks vern9, at or
/// above it dop853: where vern9 starts to take less time at equal error in BENCHMARKS.md's
/// side-by-side table (Trial 3 and the top's cases).
pub const AUTO_TIGHT: f64 = 1e-7;

/// The method fastest at equal error for tolerances `tol`, from the measurements in
/// BENCHMARKS.md ("Default method per tolerance").
pub fn for_tolerances(tol: Tolerances) -> &'static MethodInfo {
    let name = if tol.rtol.max(tol.atol) < AUTO_TIGHT { "vern9" } else { "dop853" };
    by_name(name).unwrap_or(&METHODS[0])
}

/// The method called `name` (any case); None when there is none.
pub fn by_name(name: &str) -> Option<&'static MethodInfo> {
    METHODS.iter().find(|m| m.name().eq_ignore_ascii_case(name))
}

/// The names for an error message: `methods: dop853, dopri5, vern7, vern9 (adaptive), rk4 (fixed step)`.
pub fn methods_help() -> String {
    let names = |adaptive: bool| {
        let names: Vec<&str> =
            METHODS.iter().filter(|m| m.adaptive == adaptive).map(MethodInfo::name).collect();
        names.join(", ")
    };
    let groups: Vec<String> = [(true, "adaptive"), (false, "fixed step")]
        .into_iter()
        .map(|(adaptive, kind)| (names(adaptive), kind))
        .filter(|(names, _)| !names.is_empty())
        .map(|(names, kind)| format!("{names} ({kind})"))
        .collect();
    format!("methods: {}", groups.join(", "))
}

/// Every row's tableau is well formed: checked when the crate compiles.
const _: () = {
    let mut i = 0;
    while i < METHODS.len() {
        check(&METHODS[i]);
        i += 1;
    }
};

/// Panics (at compile time) unless the row's shapes fit together: `a` strictly lower triangular
/// over `c`, weights over every stage, a first-same-as-last stage that is `f(t + h, y_new)`, the
/// continuous extension's rows over the stages and its extra stages, an error estimate for an
/// adaptive method.
const fn check(m: &MethodInfo) {
    let Some(tab) = m.tableau else { return };
    let s = tab.c.len();
    assert!(s > 0 && tab.a.len() == s && tab.b.len() == s, "a, b and c must have one entry per stage");
    let mut i = 0;
    while i < s {
        assert!(tab.a[i].len() == i, "row i of a has i entries");
        i += 1;
    }
    assert!(!m.adaptive || tab.e.is_some(), "an adaptive method needs error weights");
    if tab.fsal {
        // The last stage is f(t + h, y_new): node 1, its row of a the weights b.
        assert!(tab.c[s - 1] == 1.0 && tab.b[s - 1] == 0.0, "first-same-as-last: c ends in 1, b in 0");
        let mut j = 0;
        while j < s - 1 {
            assert!(tab.a[s - 1][j] == tab.b[j], "first-same-as-last: the last row of a is b");
            j += 1;
        }
    }
    if let Some(e) = tab.e {
        assert!(e.len() == s, "error weights over every stage");
    }
    if let Some(e3) = tab.e3 {
        assert!(e3.len() == s, "error weights over every stage");
    }
    if let Some(dense) = &tab.dense {
        let extra = dense.c.len();
        assert!(dense.a.len() == extra, "one row of a per extra stage");
        let mut i = 0;
        while i < extra {
            assert!(dense.a[i].len() == s + i, "an extra stage reads every stage before it");
            i += 1;
        }
        let mut r = 0;
        while r < dense.d.len() {
            assert!(dense.d[r].len() <= s + extra, "a row of d reads the stages and the extra ones");
            r += 1;
        }
        assert!(
            !matches!(dense.rounding, DenseRounding::SumTimesStep) || dense.d.len() == 1,
            "SumTimesStep takes one row of d"
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_find_their_rows() {
        assert_eq!(by_name("dop853").and_then(MethodInfo::order), Some(8));
        assert!(matches!(by_name("Taylor").map(|m| m.method(TOL, 0.1)), Some(Method::Taylor(_))));
        assert_eq!(by_name("DOPRI5").map(|m| m.adaptive), Some(true));
        assert!(std::ptr::eq(by_name("rk4").unwrap().tableau.unwrap(), &RK4));
        assert!(by_name("euler").is_none());
        assert_eq!(for_tolerances(TOL).name(), "vern9");
        assert_eq!(for_tolerances(Tolerances { rtol: 1e-6, atol: 1e-9 }).name(), "dop853");
        assert_eq!(
            methods_help(),
            "methods: dop853, dopri5, vern7, vern9, taylor (adaptive), rk4 (fixed step)"
        );
    }

    const TOL: Tolerances = Tolerances { rtol: 1e-9, atol: 1e-9 };
}
