//! The program of a `CODE ALGEBRAIC(EQN, X, ...)` or `CODE NONLINEAR(EQN, X, ...)` statement:
//! in come the equations and unknowns (in the file's arena) and the file's INPUT values; out
//! goes a [`SystemPlan`], one straight-line section computing the residuals, then the Jacobian
//! row by row, that each language's program wraps in the Newton iteration `kane solve` runs.

mod c;
mod fortran;
mod matlab;
mod python;

use rustc_hash::FxHashMap;

use crate::expr::{Arena, Compiler, ExprError, ExprId, SymbolId, TIME};
use crate::lang::algebraic::{AlgebraicSystem, SystemKind, MAX_ITERATIONS};
use crate::lang::units::column_name;
use crate::program::ir::{Input, Section};

use super::{Language, Program, StandaloneError};

/// A system's section and values: the unknowns are read as states, every other name as a
/// parameter.
#[derive(Clone, Debug)]
pub struct SystemPlan {
    /// Linear (one step and one of refinement) or Newton's method.
    pub kind: SystemKind,
    /// Results: the `n` residuals, then the `n * n` Jacobian entries, row by row; for an
    /// evaluation, the `n` values.
    pub section: Section,
    /// The unknowns' names.
    pub unknowns: Vec<String>,
    /// Where the iteration starts: the INPUT values (NaN where none) or, for a linear system, 0.
    pub start: Vec<f64>,
    /// The names the equations read besides the unknowns.
    pub names: Vec<String>,
    /// Their INPUT values (NaN where the file gives none).
    pub values: Vec<f64>,
    /// Whether the unknowns are OUTPUT quantities evaluated, not solved for.
    pub evaluation: bool,
}

impl SystemPlan {
    /// The plan of `system`, `value_of` giving every other name's value (and, for a nonlinear
    /// system, the unknowns' starting values).
    pub fn new(
        ar: &mut Arena,
        system: &AlgebraicSystem,
        value_of: &dyn Fn(SymbolId) -> Option<f64>,
    ) -> Result<SystemPlan, ExprError> {
        let mut roots = system.equations.clone();
        for &e in &system.equations {
            for &u in &system.unknowns {
                roots.push(ar.diff(e, u)?);
            }
        }
        let mut inputs: FxHashMap<SymbolId, Input> = FxHashMap::default();
        for (k, &u) in system.unknowns.iter().enumerate() {
            inputs.insert(u, Input::State(k));
        }
        let (section, names, values) = lowered(ar, &roots, inputs, value_of);
        let start = match system.kind {
            SystemKind::Linear => vec![0.0; system.unknowns.len()],
            SystemKind::Nonlinear => {
                system.unknowns.iter().map(|u| value_of(*u).unwrap_or(f64::NAN)).collect()
            }
        };
        Ok(SystemPlan {
            kind: system.kind,
            section,
            unknowns: system.names.clone(),
            start,
            names,
            values,
            evaluation: false,
        })
    }

    /// The plan that evaluates `quantities` (names and values) once, at the values `value_of`
    /// gives every name they read: its section's results are the values.
    pub fn evaluation(
        ar: &Arena,
        quantities: &[(String, ExprId)],
        value_of: &dyn Fn(SymbolId) -> Option<f64>,
    ) -> SystemPlan {
        let roots: Vec<ExprId> = quantities.iter().map(|(_, e)| *e).collect();
        let (section, names, values) = lowered(ar, &roots, FxHashMap::default(), value_of);
        SystemPlan {
            kind: SystemKind::Linear,
            section,
            unknowns: quantities.iter().map(|(n, _)| n.clone()).collect(),
            start: Vec::new(),
            names,
            values,
            evaluation: true,
        }
    }

    /// The CSV header: the unknowns' names, as the simulator writes a name without a unit.
    pub fn header(&self) -> String {
        self.unknowns.iter().map(|n| column_name(n, "")).collect::<Vec<_>>().join(",")
    }

    /// Newton steps at most (2 for a linear system: one step and one of refinement).
    pub fn steps(&self) -> usize {
        match self.kind {
            SystemKind::Linear => 2,
            SystemKind::Nonlinear => MAX_ITERATIONS,
        }
    }

    /// Whether the iteration halves a step that does not lower the residual.
    fn damped(&self) -> bool {
        self.kind == SystemKind::Nonlinear
    }

    /// Whether the program checks that every starting value is given (a nonlinear system's).
    fn checked_start(&self) -> bool {
        self.kind == SystemKind::Nonlinear
    }
}

/// `roots` lowered to one section, `inputs` naming what they read besides the other names (time,
/// then parameters); those names and their values (NaN where `value_of` gives none).
fn lowered(
    ar: &Arena,
    roots: &[ExprId],
    mut inputs: FxHashMap<SymbolId, Input>,
    value_of: &dyn Fn(SymbolId) -> Option<f64>,
) -> (Section, Vec<String>, Vec<f64>) {
    let (mut names, mut values) = (Vec::new(), Vec::new());
    for s in ar.free_symbols(roots) {
        if s == TIME {
            inputs.insert(s, Input::Time);
        } else if let std::collections::hash_map::Entry::Vacant(slot) = inputs.entry(s) {
            slot.insert(Input::Param(names.len()));
            names.push(ar.symbol_info(s).name.clone());
            values.push(value_of(s).unwrap_or(f64::NAN));
        }
    }
    let mut lowering = Compiler::new(ar, |s| inputs.get(&s).copied(), None);
    let results = lowering.lower_all(roots);
    (lowering.builder.finish(results), names, values)
}

/// Converged when the largest residual is below this times 1 + |J| max(|x|, 1) at the start.
pub const TOLERANCE: f64 = crate::lang::algebraic::TOLERANCE;
/// A pivot below this times the largest entry of the Jacobian is singular.
pub const SINGULAR_PIVOT: f64 = 1e-14;

/// The text of `plan`'s program in `language`, its file's stem `stem`.
pub fn write_system(
    plan: &SystemPlan,
    language: Language,
    stem: &str,
    about: &Program,
) -> Result<String, StandaloneError> {
    super::check_file_name(language, stem)?;
    Ok(match language {
        Language::C => c::program(plan, stem, about),
        Language::Matlab => matlab::program(plan, stem, about),
        Language::Python => python::program(plan, stem, about),
        Language::Fortran => fortran::program(plan, stem, about),
    })
}

impl Program {
    /// The header comment of a system's program; `build` says how to build or run it.
    fn system_header_lines(&self, plan: &SystemPlan, build: &str) -> Vec<String> {
        if plan.evaluation {
            return vec![
                format!(
                    "Generated by kane from {}: do not edit by hand (edit the model file and regenerate).",
                    self.model_file
                ),
                format!("Evaluates {} at the file's INPUT values", listed(&plan.unknowns)),
                "(CODE ALGEBRAIC() of a file without equations of motion) and writes them as CSV".into(),
                "(internal units: angles in radians).".into(),
                format!("Run: {build}"),
            ];
        }
        let how = match plan.kind {
            SystemKind::Linear => "as a linear system (Gaussian elimination, one step of refinement)",
            SystemKind::Nonlinear => "by Newton's method from the file's INPUT values",
        };
        vec![
            format!(
                "Generated by kane from {}: do not edit by hand (edit the model file and regenerate).",
                self.model_file
            ),
            format!("Solves the equations for {} {how},", listed(&plan.unknowns)),
            "as `kane solve` does, and writes the solution as CSV (internal units: angles in".into(),
            "radians).".into(),
            format!("Run: {build}"),
        ]
    }
}

/// `names` joined by commas, or, when there are more than eight, the first three, the count and
/// the last.
fn listed(names: &[String]) -> String {
    match names {
        [first, second, third, .., last] if names.len() > 8 => {
            format!("{first}, {second}, {third}, ... {last} ({} quantities)", names.len())
        }
        _ => names.join(", "),
    }
}
