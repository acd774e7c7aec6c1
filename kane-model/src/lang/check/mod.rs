//! `kane check`: a model file loaded, then checked for contradictions between the kinematics it
//! assigns and the kinematics its positions and orientations imply (errors), for coordinates
//! without a kinematic equation (errors), and for loads given twice and physically implausible
//! INPUT values (warnings).
//!
//! In: a file name and its source. Out: the loaded model with its warnings, or a report of every
//! error (with the warnings).

mod bookkeeping;
mod consistency;
mod coordinates;
mod dimensions;
mod implicit;
mod loads;
mod marker;
mod point_motion;
mod rotor;
mod warnings;
mod zero;

use super::diagnostic::{Report, Severity};
use super::interp::LoadedModel;
use consistency::Contradiction;

pub use bookkeeping::bookkeeping_summary;
pub use marker::MARKER as OVERRIDE_MARKER;

/// A model file that loaded and passed the checks.
pub struct Checked {
    /// The model.
    pub model: LoadedModel,
    /// Warnings (implausible INPUT values), in source order.
    pub warnings: Report,
}

/// Loads and checks a model file: a velocity, acceleration or angular velocity set in the file
/// that contradicts the one its positions and orientations imply is an error (unless its line
/// ends in a `% override` comment); implausible INPUT values are warnings. A file that fails
/// to load is checked as far as it loaded, so one report holds every independent problem.
pub fn check(file: &str, source: &str) -> Result<Checked, Report> {
    checked(file, super::run_file(file, source, false))
}

/// As [`check`], loaded by [`super::load_for_generation`]: a large tree's `M` and `f` may be
/// left unformed.
pub fn check_for_generation(file: &str, source: &str) -> Result<Checked, Report> {
    checked(file, super::run_file(file, source, true))
}

fn checked(
    file: &str,
    (mut model, errors): (super::LoadedModel, Vec<super::Diagnostic>),
) -> Result<Checked, Report> {
    let text = std::mem::take(&mut model.text);
    let mut found = std::mem::take(&mut model.warnings);
    found.extend(consistency::consistency(&mut model, &text));
    found.extend(coordinates::coordinates_without_kinematics(&model));
    found.extend(loads::repeated_loads(&model, &text));
    found.extend(warnings::input_warnings(&model));
    found.extend(implicit::implicit_constants_without_values(&model));
    found.extend(dimensions::units_against_use(&model, &text));
    model.text = text;
    // What a failed statement would have set up is not checked again.
    found.retain(|d| errors.is_empty() || !model.tainted.explains(&d.message));
    let mut diagnostics = errors;
    diagnostics.extend(found);
    diagnostics.sort_by_key(|d| d.span.start);
    let report = model.report(file, diagnostics);
    if report.diagnostics.iter().any(|d| d.severity == Severity::Error) {
        Err(report)
    } else {
        Ok(Checked { model, warnings: report })
    }
}
