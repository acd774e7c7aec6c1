//! Printing a model's expressions for reading: simplified, collected by state monomial, and in
//! the names the model file gave to parameter expressions (`I1 = 2/3*M1*(H1*W - W^2)`).

use rustc_hash::FxHashMap;

use crate::expr::{Abbreviations, Arena, Collected, ExprError, ExprId, SymbolKind, MAX_EXPANDED_TERMS};

use super::interp::value::Value;
use super::interp::{Binding, LoadedModel};

/// The named parameter expressions of a model file, ready to print expressions in them.
#[derive(Clone, Debug, Default)]
pub struct Presenter {
    names: Abbreviations,
    /// Each name (upper-cased, as the file binds it) with its value.
    pub defined: Vec<(String, ExprId)>,
}

impl LoadedModel {
    /// The presenter of the file's named parameter expressions (`I1 = ...`), for printing
    /// expressions simplified and in those names.
    pub fn presenter(&mut self) -> Result<Presenter, ExprError> {
        Presenter::new(&mut self.model.ar, &self.bindings, None)
    }
}

/// True when `e` holds parameters only, and at least one.
fn parameter_only(ar: &Arena, e: ExprId) -> bool {
    let free = ar.free_symbols(&[e]);
    !free.is_empty() && free.iter().all(|s| ar.symbol_info(*s).kind == SymbolKind::Constant)
}

impl Presenter {
    /// The presenter for `bindings`, leaving out the name `exclude` (so that a quantity is not
    /// printed as its own name). Each name becomes a constant of that name in `ar`, used only
    /// for printing.
    pub(crate) fn new(
        ar: &mut Arena,
        bindings: &FxHashMap<String, Binding>,
        exclude: Option<&str>,
    ) -> Result<Presenter, ExprError> {
        let mut defined: Vec<(String, ExprId)> = bindings
            .iter()
            .filter_map(|(k, b)| match b {
                Binding::Value(Value::Scalar(x)) => Some((k.clone(), *x)),
                _ => None,
            })
            .filter(|(k, x)| {
                exclude.is_none_or(|n| !n.eq_ignore_ascii_case(k))
                    && ar.as_symbol(*x).is_none()
                    && parameter_only(ar, *x)
            })
            .collect();
        defined.sort();
        let mut defs = Vec::with_capacity(defined.len());
        for (name, value) in &defined {
            if let Ok(s) = ar.constant(name) {
                defs.push((s, *value));
            }
        }
        Ok(Presenter { names: Abbreviations::new(ar, &defs)?, defined })
    }

    /// `e` simplified and collected, parameters in the file's names; `e` as it is when
    /// expanding it would give too many terms.
    pub fn tidy(&self, ar: &mut Arena, e: ExprId) -> Result<Collected, ExprError> {
        let budget = u64::try_from(MAX_EXPANDED_TERMS).unwrap_or(u64::MAX);
        Ok(self.tidy_within(ar, e, budget)?.unwrap_or_else(|| Collected::whole(ar, e)))
    }

    /// [`Presenter::tidy`], or `None` when expanding `e` may build a sum of more than `budget`
    /// terms (judged before expanding, see [`Arena::expansion_bounds`]).
    pub fn tidy_within(
        &self,
        ar: &mut Arena,
        e: ExprId,
        budget: u64,
    ) -> Result<Option<Collected>, ExprError> {
        if ar.expansion_bounds(&[e])[0] > budget {
            return Ok(None);
        }
        let params: Vec<bool> = ar.symbols().map(|(_, s)| s.kind == SymbolKind::Constant).collect();
        match ar.tidy(e, |s| params.get(s.index()).copied().unwrap_or(false), &self.names) {
            Err(ExprError::TooLarge(_)) => Ok(None),
            other => other.map(Some),
        }
    }

    /// `e` simplified, as plain text.
    pub fn text(&self, ar: &mut Arena, e: ExprId) -> Result<String, ExprError> {
        let c = self.tidy(ar, e)?;
        Ok(ar.collected_text(&c))
    }

    /// `e` simplified, as LaTeX.
    pub fn latex(&self, ar: &mut Arena, e: ExprId) -> Result<String, ExprError> {
        let c = self.tidy(ar, e)?;
        Ok(ar.collected_latex(&c))
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn prints_in_the_files_names() {
        let src = "NEWTONIAN N\nCONSTANTS M, L, H\nVARIABLES Q'\nK1 = 1/2*M*L^2\n\
                   K2 = 1/4*M*L^2 + 1/12*M*H^2\nX = (K2 - K1)*SIN(Q)^2\n";
        let mut m = super::super::load("t.al", src).unwrap();
        let p = m.presenter().unwrap();
        let Some(super::Value::Scalar(x)) = m.value("X") else { panic!("X is a scalar") };
        assert_eq!(p.text(&mut m.model.ar, x).unwrap(), "(K2 - K1)*sin(Q)^2");
        assert_eq!(p.defined.iter().map(|d| d.0.as_str()).collect::<Vec<_>>(), ["K1", "K2"]);
    }

    #[test]
    fn tidy_within_declines_what_would_swell() {
        let src = "NEWTONIAN N\nCONSTANTS K\nVARIABLES Q{12}'\n\
                   X = (SIN(Q1) + COS(Q1))*(SIN(Q2) + COS(Q2))*(SIN(Q3) + COS(Q3))*(SIN(Q4) + COS(Q4))*\
                   (SIN(Q5) + COS(Q5))*(SIN(Q6) + COS(Q6))*(SIN(Q7) + COS(Q7))*(SIN(Q8) + COS(Q8))\n";
        let mut m = super::super::load("t.al", src).unwrap();
        let p = m.presenter().unwrap();
        let Some(super::Value::Scalar(x)) = m.value("X") else { panic!("X is a scalar") };
        assert_eq!(p.tidy_within(&mut m.model.ar, x, 255).unwrap(), None);
        assert!(p.tidy_within(&mut m.model.ar, x, 256).unwrap().is_some());
    }
}
