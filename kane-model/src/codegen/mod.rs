//! Code generation: in comes a [`ModelSpec`] (built from mechanics, never from the language);
//! out goes a Rust module with a straight-line `rhs` generic over `num_traits::Float`, one
//! function per output, and the model's runtime metadata.
//!
//! The crate's layers, in the order data flows through them: `expr` -> `mechanics` -> `spec` ->
//! `codegen` (this module) -> [`crate::runtime`]. Each uses only the layers before it and
//! `runtime`, what generated code reaches: a leaf that uses nothing else in the crate (this
//! module's evaluators run its recurrences; its metadata are runtime types). The model
//! language, `lang`, sits above them all and is never read here: event expressions arrive as
//! expressions ([`event::lower`]), specs as specs.
//!
//! The stages are modules: [`lower`] turns the spec into one [`ir::Program`] (SSA sections for
//! `param_constants`, `rhs` with `M u' = f` solved inside it, and each output); `print` spells
//! that program in Rust; [`taylor`] turns `rhs` into Taylor-coefficient recurrences, printed
//! beside it; `jit` (feature `jit`) compiles the same sections to machine code in process.
//! The same spec gives byte-identical code.

pub mod event;
pub mod fault;
pub mod ir;
#[cfg(feature = "jit")]
pub mod jit;
pub mod linearize;
mod lower;
mod meta;
mod names;
mod print;
mod program_model;
pub mod taylor;

use proc_macro2::TokenStream;
use thiserror::Error;

use crate::spec::ModelSpec;

pub use lower::{lower, Lowered};
pub use meta::{Meta, OutputMeta};
pub use names::rust_ident;
pub use print::{print_section, Extras, Scalar, SectionStyle};
pub use program_model::ProgramModel;

/// Why a model cannot be turned into code.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum CodegenError {
    /// A symbol the equations need is neither a state, a parameter nor time.
    #[error("`{0}` is a time-dependent quantity that is not a state and has no formula: give it one in the file (`{0} = ...`, after KANE() too) or in a gyro-sim scene's [specified] table; tables of values in time are not supported")]
    UnsupportedSymbol(String),
    /// An expression operation failed.
    #[error(transparent)]
    Expr(#[from] crate::expr::ExprError),
    /// A mechanics operation failed.
    #[error(transparent)]
    Mechanics(#[from] crate::mechanics::MechanicsError),
}

/// What to generate beyond `rhs`, `jacobian` and the outputs: only what the runs ask for.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CodeOptions {
    /// Taylor coefficients, for the Taylor method (`taylor_with_constants`, a loop over the order).
    pub taylor: bool,
    /// Orders whose Taylor coefficients are also written out straight-line (faster); an order
    /// whose code would pass [`taylor::STRAIGHT_LINE_BUDGET`] keeps the loop (see
    /// [`taylor::TaylorProgram::straight_line_orders`]). Implies `taylor`.
    pub taylor_orders: Vec<usize>,
    /// `rhs_lanes` ([`crate::runtime::LaneModel`]), for batches of members in lock step.
    pub lanes: bool,
    /// The operation counts of `M` and `f` as `kane check` counts them
    /// ([`Emitted::equation_ops`]), for `kane gen --stats`: a tape of each, not built otherwise.
    pub equation_counts: bool,
    /// The outputs of the model's default drawing ([`crate::spec::Drawing`]): where each
    /// frame and point is, for a view drawn without a hand-written scene.
    pub drawing: bool,
}

impl CodeOptions {
    /// Everything: Taylor coefficients with straight-line code at
    /// [`crate::runtime::TAYLOR_UNROLLED_ORDERS`], and lanes.
    pub fn everything() -> CodeOptions {
        let taylor_orders = crate::runtime::TAYLOR_UNROLLED_ORDERS.to_vec();
        CodeOptions { taylor: true, taylor_orders, lanes: true, equation_counts: false, drawing: false }
    }
}

/// Generated code and what it costs.
#[derive(Clone, Debug)]
pub struct Emitted {
    /// The module's items.
    pub tokens: TokenStream,
    /// Arithmetic operations per `rhs` call (equations and solve) and per evaluation of every
    /// output, counted on the lowered program.
    pub op_counts: crate::runtime::OpCounts,
    /// The sizes of `M` and `f` as derived (before simplification), counted as `kane check`
    /// counts them; None unless asked ([`CodeOptions::equation_counts`]) or when the chosen form
    /// never formed them.
    pub equation_ops: Option<crate::mechanics::EquationOps>,
    /// Values computed by one `rhs` call (named intermediates and results).
    pub rhs_values: usize,
    /// Whether the module has Taylor coefficients.
    pub taylor: bool,
    /// The orders with straight-line Taylor code.
    pub taylor_straight_line: Vec<usize>,
    /// Whether the module has `rhs_lanes`.
    pub lanes: bool,
    /// A one-line description for the module's documentation.
    pub doc: String,
}

impl Emitted {
    /// The module's report: what one `rhs` call and the outputs cost, and the Taylor code.
    pub fn report(&self) -> String {
        let orders: Vec<String> = self.taylor_straight_line.iter().map(|o| o.to_string()).collect();
        let taylor = match (self.taylor, orders.is_empty()) {
            (false, _) => "none".to_string(),
            (true, true) => "a loop over the order".to_string(),
            (true, false) => format!("straight-line at orders {}, a loop at the others", orders.join(", ")),
        };
        format!(
            "rhs: {} operations, {} values per call; outputs: {} operations for all of them; Taylor coefficients: {taylor}; lanes: {}",
            self.op_counts.rhs,
            self.rhs_values,
            self.op_counts.outputs,
            if self.lanes { "yes" } else { "no" },
        )
    }
}

/// Generates the items of the model module of `spec`.
pub fn generate(spec: &mut ModelSpec, options: &CodeOptions) -> Result<Emitted, CodegenError> {
    let lowered = lower(spec)?;
    let n_states = lowered.states.len();
    let taylor = options.taylor || !options.taylor_orders.is_empty();
    let orders = match taylor::TaylorProgram::new(&lowered.program.rhs, n_states) {
        Ok(t) if taylor => t.straight_line_orders(&options.taylor_orders),
        _ => Vec::new(),
    };
    let extras = print::Extras { taylor, taylor_orders: &orders, lanes: options.lanes };
    let tokens = print::module(spec, &lowered, &extras);
    let doc = format!("Generated by kane-model from the model `{}`: do not edit by hand.", spec.name);
    let rhs_values = lowered.program.rhs.ops.len();
    Ok(Emitted {
        tokens,
        op_counts: lowered.program.op_counts(),
        equation_ops: (options.equation_counts && spec.equations.formed)
            .then(|| spec.equations.op_counts(&spec.model.ar)),
        rhs_values,
        taylor,
        taylor_straight_line: orders,
        lanes: options.lanes,
        doc,
    })
}

/// The generated module as formatted source text (for `kane gen` and snapshots), its report in
/// the header.
pub fn to_source(emitted: &Emitted) -> Result<String, syn::Error> {
    let file: syn::File = syn::parse2(emitted.tokens.clone())?;
    Ok(format!("//! {}\n//!\n//! {}\n\n{}", emitted.doc, emitted.report(), prettyplease::unparse(&file)))
}

/// The generated module's items as formatted text without an inner doc comment (for
/// `include!` inside a module).
pub fn to_items(emitted: &Emitted) -> Result<String, syn::Error> {
    let file: syn::File = syn::parse2(emitted.tokens.clone())?;
    Ok(prettyplease::unparse(&file))
}
