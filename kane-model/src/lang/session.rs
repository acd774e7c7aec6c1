//! A model file run and kept open, so that more text can be evaluated in its names: the
//! quantities `kane show` prints and the hand-derived equations `kane compare` checks.

use rustc_hash::FxHashMap;

use crate::expr::{EquivalenceConfig, SampleAround, SymbolId, SymbolKind};

use super::diagnostic::{Diagnostic, Report};
use super::interp::Interpreter;
use super::present::Presenter;

/// A model file after its run, with the interpreter that ran it.
pub(crate) struct Session {
    pub(crate) it: Interpreter,
}

/// A report on `file` holding `diagnostics`.
pub(crate) fn report(file: &str, source: &str, diagnostics: Vec<Diagnostic>) -> Report {
    Report::new(file, source, diagnostics)
}

impl Session {
    /// Parses and runs `source`; every error is reported, with its place in `file`.
    pub(crate) fn open(file: &str, source: &str) -> Result<Session, Report> {
        let super::include::Expanded { source, stmts, mut errors, parts, .. } =
            super::include::expand(file, source);
        let mut it = Interpreter::new();
        if errors.is_empty() {
            it.run(&stmts, &source, &[]);
            errors = std::mem::take(&mut it.errors);
        }
        if !errors.is_empty() {
            errors.sort_by_key(|d| d.span.start);
            return Err(Report { file: file.to_string(), source, diagnostics: errors, parts });
        }
        Ok(Session { it })
    }

    /// The presenter of the file's named parameter expressions, leaving out `exclude`.
    pub(crate) fn presenter(&mut self, exclude: Option<&str>) -> Result<Presenter, crate::expr::ExprError> {
        Presenter::new(&mut self.it.model.ar, &self.it.bindings, exclude)
    }

    /// Sampling at physical values: the first point at the file's INPUT values, later points
    /// around them (parameters within 20 %, so masses and lengths stay positive; states within
    /// 1). Parameters with no INPUT value (or 0 for a mass) are sampled in 0.5..1.5.
    pub(crate) fn physical_sampling(&self) -> EquivalenceConfig {
        let ar = &self.it.model.ar;
        let inputs: FxHashMap<String, f64> =
            self.it.inputs.iter().map(|i| (i.name.to_ascii_uppercase(), i.value)).collect();
        let masses: Vec<SymbolId> = self
            .it
            .model
            .bodies
            .iter()
            .filter_map(|b| b.mass)
            .chain(self.it.model.particles.iter().filter_map(|p| p.mass))
            .filter_map(|m| ar.as_symbol(m))
            .collect();
        let mut cfg = EquivalenceConfig::default();
        for (s, info) in ar.symbols() {
            let input = inputs.get(&info.name.to_ascii_uppercase()).copied();
            let around = match (info.kind, input) {
                (SymbolKind::Constant, Some(v)) if v != 0.0 && !(masses.contains(&s) && v < 0.0) => {
                    SampleAround { centre: v, spread: 0.2, relative: true }
                }
                (SymbolKind::Constant, Some(0.0)) if !masses.contains(&s) => {
                    SampleAround { centre: 0.0, spread: 1.0, relative: false }
                }
                (SymbolKind::Constant, _) => SampleAround { centre: 1.0, spread: 0.5, relative: true },
                (_, v) => SampleAround { centre: v.unwrap_or(0.0), spread: 1.0, relative: false },
            };
            cfg.around.insert(s, around);
        }
        cfg
    }
}
