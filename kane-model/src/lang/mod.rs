//! The Autolev-compatible model language: lexer, parser (with spans), and lowering onto the
//! mechanics layer, with diagnostics that name file, line, column and what to do.
//!
//! # Example
//! ```
//! let src = "NEWTONIAN N\nBODIES B\nPOINT O\nVARIABLES Q', U'\nCONSTANTS M, L, G\n\
//!            SIMPROT(N, B, 3, Q)\nQ' = U\nW_B_N> = U*N3>\nV_O_N> = 0>\nP_O_BO> = L*B1>\n\
//!            V2PTS(N, B, O, BO)\nMASS B = M\nINERTIA B, 0, 0, 0\nGRAVITY(-G*N2>)\n\
//!            ZERO = FR() + FRSTAR()\nKANE()\n";
//! let loaded = kane_model::lang::load("pendulum.al", src).unwrap();
//! let eqs = loaded.equations.unwrap();
//! assert_eq!(eqs.speeds.len(), 1);
//! ```

pub mod algebraic;
mod ast;
mod check;
mod compare;
mod diagnostic;
mod eoms;
pub mod event;
mod file_search;
mod include;
mod interp;
mod parser;
mod present;
pub mod run_settings;
mod session;
mod show;
mod sum_tree;
mod to_spec;
mod token;
pub mod units;
mod user_functions;

pub use ast::{BinOp, Expr, ExprKind, Stmt, StmtKind};
pub use check::{bookkeeping_summary, check, check_for_generation, Checked, OVERRIDE_MARKER};
pub use compare::{compare, Comparison, Outcome, Relation};
pub use diagnostic::{line_column, Diagnostic, Report, Severity, SourcePart};
pub use eoms::{printed_eoms, EomsError, EomsText, PrintedEoms, Shown, COLLECT_BUDGET, COLLECT_TOTAL};
pub use interp::value::Value;
pub use interp::{language_words, nearest_word, Bookkeeping, CodeRequest, InputValue, LoadedModel};
pub use parser::parse_expression;
pub use present::Presenter;
pub use run_settings::{FileRun, RunSettings};
pub use show::show;
pub use to_spec::SpecError;
pub use token::Span;

/// Parses a program; every syntax error is reported.
pub fn parse(file: &str, source: &str) -> Result<Vec<Stmt>, Report> {
    let (stmts, errors) = parser::parse(source);
    if errors.is_empty() {
        Ok(stmts)
    } else {
        Err(Report::new(file, source, errors))
    }
}

/// Parses and runs a model file: declarations, kinematics, loads and, if the file asks for it,
/// Kane's equations. Every error found is reported, with its place in the file.
pub fn load(file: &str, source: &str) -> Result<LoadedModel, Report> {
    load_with(file, source, false)
}

/// As [`load`], for code generation: a large tree's Kane `M` and `f`, and assignments of FR()
/// and FRSTAR(), wait until something asks for them (its order-n form may need neither).
pub fn load_for_generation(file: &str, source: &str) -> Result<LoadedModel, Report> {
    load_with(file, source, true)
}

fn load_with(file: &str, source: &str, defer: bool) -> Result<LoadedModel, Report> {
    let (model, errors) = run_file(file, source, defer);
    if errors.is_empty() {
        Ok(model)
    } else {
        Err(model.report(file, errors))
    }
}

/// Runs a model file to its end whatever fails: the model as far as it was built, and every
/// error (in source order).
fn run_file(file: &str, source: &str, defer: bool) -> (LoadedModel, Vec<Diagnostic>) {
    let include::Expanded { source, stmts, mut errors, parts, .. } = include::expand(file, source);
    let mut it = interp::Interpreter::new();
    it.defer = defer;
    it.run(&stmts, &source, &errors);
    if errors.is_empty() && it.errors.is_empty() {
        it.put_specified_formulas();
    }
    errors.extend(std::mem::take(&mut it.errors));
    errors.sort_by_key(|d| d.span.start);
    (it.finish(source, parts), errors)
}
