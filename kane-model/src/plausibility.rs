//! Physical plausibility of parameter and initial values: masses that are not negative (zero is a
//! massless idealisation, whose mass matrix is checked at run time), principal moments of
//! inertia that are non-negative and, when none is zero (a zero moment is an idealisation: a
//! planar link, a rotor's spin axis alone), satisfy the triangle inequality, unit Euler
//! parameters.
//!
//! In: a [`Model`] and the values of its symbols by name. Out: the issues found, each naming the
//! parameter to blame; `kane check` prints them as warnings at the INPUT values, and a simulator
//! can call [`plausibility`] with the values of a run and refuse to start.

use nalgebra::{Matrix3, SymmetricEigen};

use crate::expr::ExprId;
use crate::mechanics::{Body, Dyadic, Model, Orientation};

/// Largest accepted `|norm - 1|` of a set of Euler parameters.
pub const EULER_NORM_TOLERANCE: f64 = 1e-9;

/// One implausible value, with the parameter to blame.
#[derive(Clone, Debug, PartialEq)]
pub struct PlausibilityIssue {
    /// The parameter to blame as declared (`M3`, `E1`), or the quantity (`I_D_DO>>`) when it
    /// depends on several parameters none of which is to blame alone.
    pub parameter: String,
    /// Every parameter the offending quantity depends on, as declared.
    pub involved: Vec<String>,
    /// What is wrong, with the values.
    pub message: String,
}

/// Checks masses, central inertias and Euler parameters at `values` (symbol name as declared to
/// value; a quantity depending on a name without a value is not checked).
pub fn plausibility(model: &Model, values: impl Fn(&str) -> Option<f64>) -> Vec<PlausibilityIssue> {
    let mut issues = Vec::new();
    for body in model.bodies() {
        if let Some(m) = body.mass {
            issues.extend(mass_issue(model, &body.name, m, &values));
        }
        issues.extend(inertia_issue(model, body, &values));
    }
    for p in &model.particles {
        if let Some(m) = p.mass {
            issues.extend(mass_issue(model, &p.name, m, &values));
        }
    }
    for f in &model.frames {
        if let Some(Orientation::EulerParameters(e)) = &f.orientation {
            issues.extend(euler_issue(model, &f.name, e, &values));
        }
    }
    issues
}

/// The value of `e`, when every symbol in it has one.
fn value_of(model: &Model, e: ExprId, values: &impl Fn(&str) -> Option<f64>) -> Option<f64> {
    let v = model.ar.eval(&[e], |s| values(&model.ar.symbol_info(s).name)).ok()?;
    v.first().copied().filter(|x| x.is_finite())
}

/// The names of the symbols in `roots`, as declared.
fn names(model: &Model, roots: &[ExprId]) -> Vec<String> {
    model.ar.free_symbols(roots).iter().map(|s| model.ar.symbol_info(*s).name.clone()).collect()
}

/// `A = 1, B = 2` for the names given.
fn listing(names: &[String], values: &impl Fn(&str) -> Option<f64>) -> String {
    let shown: Vec<String> =
        names.iter().map(|n| format!("{n} = {}", values(n).map_or("?".into(), |v| v.to_string()))).collect();
    shown.join(", ")
}

/// The symbol `e` is, if it is one.
fn symbol_name(model: &Model, e: ExprId) -> Option<String> {
    model.ar.as_symbol(e).map(|s| model.ar.symbol_info(s).name.clone())
}

fn mass_issue(
    model: &Model,
    owner: &str,
    m: ExprId,
    values: &impl Fn(&str) -> Option<f64>,
) -> Option<PlausibilityIssue> {
    let v = value_of(model, m, values)?;
    if v >= 0.0 {
        return None;
    }
    let involved = names(model, &[m]);
    let parameter = symbol_name(model, m).unwrap_or_else(|| owner.to_string());
    let given =
        if involved.is_empty() { String::new() } else { format!(" ({})", listing(&involved, values)) };
    let message = format!("the mass of {owner} is {v}{given}: a mass cannot be negative");
    Some(PlausibilityIssue { parameter, involved, message })
}

/// The inertia matrix of `d` when all its terms are in one frame.
fn one_frame_entries(d: &Dyadic) -> Option<[[ExprId; 3]; 3]> {
    let first = d.terms().first()?;
    if d.terms().len() != 1 || first.0 != first.1 {
        return None;
    }
    Some(first.2)
}

fn inertia_issue(
    model: &Model,
    body: &Body,
    values: &impl Fn(&str) -> Option<f64>,
) -> Option<PlausibilityIssue> {
    let entries = one_frame_entries(body.inertia.as_ref()?)?;
    let mut m = Matrix3::zeros();
    for i in 0..3 {
        for j in 0..3 {
            m[(i, j)] = value_of(model, entries[i][j], values)?;
        }
    }
    let m = (m + m.transpose()) * 0.5;
    let mut moments: Vec<f64> = SymmetricEigen::new(m).eigenvalues.iter().copied().collect();
    moments.sort_by(f64::total_cmp);
    let tol = 1e-12 * moments.iter().fold(f64::MIN_POSITIVE, |a, b| a.max(b.abs()));
    let (lo, mid, hi) = (moments[0], moments[1], moments[2]);
    let (offender, what) = if lo < -tol {
        (lo, format!("has a negative principal moment {lo}; principal moments must be non-negative"))
    } else if lo > tol && lo + mid < hi - tol {
        // A zero moment is an idealisation (a planar link, a rotor's spin axis alone): no rigid
        // body has it, but the file means it; only three non-zero moments must form a triangle.
        (
            hi,
            format!(
                "violates the triangle inequality: principal moments {lo} + {mid} < {hi}; a rigid body's \
                 moments satisfy I1 + I2 >= I3"
            ),
        )
    } else {
        return None;
    };
    let flat: Vec<ExprId> = entries.iter().flatten().copied().collect();
    let involved = names(model, &flat);
    // Blame the diagonal entry equal to the offending moment, when it is one parameter.
    let diagonal =
        (0..3).min_by(|a, b| (m[(*a, *a)] - offender).abs().total_cmp(&(m[(*b, *b)] - offender).abs()));
    let blamed = diagonal.filter(|k| (m[(*k, *k)] - offender).abs() <= tol.max(1e-300));
    let cm = model.point_name(body.mass_center);
    let parameter = blamed
        .and_then(|k| symbol_name(model, entries[k][k]))
        .unwrap_or_else(|| format!("I_{}_{cm}>>", body.name));
    let message = format!("the central inertia of {} {what} ({})", body.name, listing(&involved, values));
    Some(PlausibilityIssue { parameter, involved, message })
}

fn euler_issue(
    model: &Model,
    frame: &str,
    e: &[ExprId; 4],
    values: &impl Fn(&str) -> Option<f64>,
) -> Option<PlausibilityIssue> {
    // Stored scalar first; the file names them vector part first (Autolev's E1, E2, E3, E4).
    let in_file_order = [e[1], e[2], e[3], e[0]];
    let involved: Vec<String> =
        in_file_order.iter().map(|x| symbol_name(model, *x)).collect::<Option<_>>()?;
    let v: Vec<f64> = in_file_order.iter().map(|x| value_of(model, *x, values)).collect::<Option<_>>()?;
    let norm = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    if (norm - 1.0).abs() <= EULER_NORM_TOLERANCE {
        return None;
    }
    let message = format!(
        "the Euler parameters of {frame} have norm {norm} ({}); they must have norm 1 (within {EULER_NORM_TOLERANCE:e})",
        listing(&involved, values)
    );
    Some(PlausibilityIssue { parameter: involved[0].clone(), involved, message })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn model(src: &str) -> Model {
        crate::lang::load("t.al", src).unwrap().model
    }

    const BODY: &str = "NEWTONIAN N\nBODIES B\nCONSTANTS M, I1, I2, I3\nMASS B = M\nINERTIA B, I1, I2, I3\n";

    fn at<'a>(pairs: &'a [(&'a str, f64)]) -> impl Fn(&str) -> Option<f64> + 'a {
        move |n| pairs.iter().find(|(k, _)| k.eq_ignore_ascii_case(n)).map(|(_, v)| *v)
    }

    #[test]
    fn a_plausible_body_has_no_issue() {
        let m = model(BODY);
        assert!(plausibility(&m, at(&[("M", 1.0), ("I1", 1.0), ("I2", 2.0), ("I3", 3.0)])).is_empty());
    }

    #[test]
    fn negative_mass_names_its_parameter_and_zero_mass_is_allowed() {
        let m = model(BODY);
        for mass in [-1.0, -1e-300] {
            let issues = plausibility(&m, at(&[("M", mass), ("I1", 1.0), ("I2", 1.0), ("I3", 1.0)]));
            assert_eq!(issues.len(), 1, "{issues:?}");
            assert_eq!(issues[0].parameter, "M");
            assert!(issues[0].message.contains("cannot be negative"), "{}", issues[0].message);
        }
        assert!(plausibility(&m, at(&[("M", 0.0), ("I1", 1.0), ("I2", 1.0), ("I3", 1.0)])).is_empty());
    }

    #[test]
    fn triangle_inequality_blames_the_largest_moment() {
        let m = model(BODY);
        let issues = plausibility(&m, at(&[("M", 1.0), ("I1", 1.0), ("I2", 1.0), ("I3", 2.5)]));
        assert_eq!(issues.len(), 1, "{issues:?}");
        assert_eq!(issues[0].parameter, "I3");
        assert_eq!(issues[0].involved, ["I1", "I2", "I3"]);
        assert!(issues[0].message.contains("triangle inequality"), "{}", issues[0].message);
    }

    #[test]
    fn a_zero_moment_is_an_idealisation_not_an_implausible_body() {
        let m = model(BODY);
        // A planar link (only the moment about its hinge) and a rotor's spin axis alone.
        assert!(plausibility(&m, at(&[("M", 1.0), ("I1", 0.0), ("I2", 0.0), ("I3", 2.5)])).is_empty());
        assert!(plausibility(&m, at(&[("M", 1.0), ("I1", 3.0), ("I2", 0.0), ("I3", 0.0)])).is_empty());
        let negative = plausibility(&m, at(&[("M", 1.0), ("I1", 0.0), ("I2", -1.0), ("I3", 2.5)]));
        assert!(negative[0].message.contains("negative principal moment"), "{negative:?}");
    }

    #[test]
    fn unknown_values_are_not_checked() {
        let m = model(BODY);
        assert!(plausibility(&m, at(&[("I1", 1.0), ("I2", 1.0), ("I3", 9.0)])).len() == 1);
        assert!(plausibility(&m, at(&[])).is_empty());
    }

    #[test]
    fn euler_parameters_off_the_unit_sphere() {
        let src = "NEWTONIAN N\nBODIES B\nVARIABLES E{4}'\nDIRCOS(N, B, EULER, E1, E2, E3, E4)\n";
        let m = model(src);
        let unit = [("E1", 0.5), ("E2", 0.5), ("E3", 0.5), ("E4", 0.5)];
        assert!(plausibility(&m, at(&unit)).is_empty());
        let issues = plausibility(&m, at(&[("E1", 0.5), ("E2", 0.0), ("E3", 0.0), ("E4", 0.9)]));
        assert_eq!(issues.len(), 1, "{issues:?}");
        assert_eq!(issues[0].parameter, "E1");
        assert_eq!(issues[0].involved, ["E1", "E2", "E3", "E4"]);
    }
}
