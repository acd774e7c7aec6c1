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
mod interp;
mod parser;
mod present;
mod session;
mod show;
mod sum_tree;
mod to_spec;
mod token;
pub mod units;

pub use ast::{BinOp, Expr, ExprKind, Stmt, StmtKind};
pub use check::{bookkeeping_summary, check, check_for_generation, Checked, OVERRIDE_MARKER};
pub use compare::{compare, Comparison, Outcome, Relation};
pub use diagnostic::{line_column, Diagnostic, Report, Severity};
pub use eoms::{printed_eoms, EomsError, EomsText, PrintedEoms, Shown, COLLECT_BUDGET, COLLECT_TOTAL};
pub use interp::value::Value;
pub use interp::{Bookkeeping, CodeRequest, InputValue, LoadedModel};
pub use parser::parse_expression;
pub use present::Presenter;
pub use show::show;
pub use to_spec::SpecError;
pub use token::Span;

/// Parses a program; every syntax error is reported.
pub fn parse(file: &str, source: &str) -> Result<Vec<Stmt>, Report> {
    let (stmts, errors) = parser::parse(source);
    if errors.is_empty() {
        Ok(stmts)
    } else {
        Err(Report { file: file.to_string(), source: source.to_string(), diagnostics: errors })
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
    let (stmts, mut errors) = parser::parse(source);
    let mut it = interp::Interpreter::new();
    it.defer = defer;
    it.run(&stmts, source, &errors);
    if errors.is_empty() && it.errors.is_empty() {
        it.put_specified_formulas();
    }
    errors.extend(std::mem::take(&mut it.errors));
    if errors.is_empty() {
        Ok(it.finish())
    } else {
        errors.sort_by_key(|d| d.span.start);
        Err(Report { file: file.to_string(), source: source.to_string(), diagnostics: errors })
    }
}
