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
mod warnings;
mod zero;

use super::diagnostic::{Report, Severity};
use super::interp::LoadedModel;

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
/// ends in a `% override` comment); implausible INPUT values are warnings.
pub fn check(file: &str, source: &str) -> Result<Checked, Report> {
    checked(file, source, super::load(file, source)?)
}

/// As [`check`], loaded by [`super::load_for_generation`]: a large tree's `M` and `f` may be
/// left unformed.
pub fn check_for_generation(file: &str, source: &str) -> Result<Checked, Report> {
    checked(file, source, super::load_for_generation(file, source)?)
}

fn checked(file: &str, source: &str, mut model: super::LoadedModel) -> Result<Checked, Report> {
    let mut diagnostics = consistency::consistency(&mut model, source);
    diagnostics.extend(coordinates::coordinates_without_kinematics(&model));
    diagnostics.extend(loads::repeated_loads(&model, source));
    diagnostics.extend(warnings::input_warnings(&model));
    diagnostics.extend(implicit::implicit_constants_without_values(&model));
    diagnostics.extend(dimensions::units_against_use(&model, source));
    diagnostics.sort_by_key(|d| d.span.start);
    let report = Report { file: file.to_string(), source: source.to_string(), diagnostics };
    if report.diagnostics.iter().any(|d| d.severity == Severity::Error) {
        Err(report)
    } else {
        Ok(Checked { model, warnings: report })
    }
}
