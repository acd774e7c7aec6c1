//! The model module printed: in come a spec and its lowered program; out go the items of a Rust
//! module (`Params`, `param_constants`, `rhs_with_constants`, `rhs`, `output`, `jacobian`,
//! `INFO` and a `Model` implementing [`crate::runtime::GeneratedModel`]; `taylor_with_constants` and
//! `rhs_lanes` with [`crate::runtime::LaneModel`] where asked).

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use crate::spec::ModelSpec;

use super::super::names::{const_ident, rust_ident};
use super::metadata;
use super::section::{self, Scalar, SectionStyle};
use crate::program::ir::{Input, Program};
use crate::program::taylor::TaylorProgram;
use crate::program::Lowered;

/// What the module holds beyond `rhs` and the outputs.
pub struct Extras<'a> {
    /// Taylor coefficients (`taylor_with_constants` and its loop).
    pub taylor: bool,
    /// Orders with straight-line Taylor code (see
    /// [`crate::program::taylor::TaylorProgram::straight_line_orders`]).
    pub taylor_orders: &'a [usize],
    /// `rhs_lanes` and the `LaneModel` implementation.
    pub lanes: bool,
}

/// The module's items.
pub fn module(spec: &ModelSpec, lowered: &Lowered, extras: &Extras) -> TokenStream {
    let program = &lowered.program;
    let param_idents: Vec<Ident> =
        lowered.params.iter().map(|s| rust_ident(&spec.model.ar.symbol_info(*s).name)).collect();
    let state_names: Vec<String> = lowered.states.iter().map(|s| spec.symbol_name(*s).to_string()).collect();
    let state_consts: Vec<Ident> = state_names.iter().map(|s| const_ident(s)).collect();
    let state_idx: Vec<usize> = (0..state_names.len()).collect();
    let (ns, no) = (state_names.len(), spec.outputs.len());
    let n_columns: usize = spec.outputs.iter().map(|o| o.components.len()).sum();
    let n_constants = program.param_constants.results.len();
    let params_items = params_items(spec, lowered, &param_idents);
    let quaternion: Vec<bool> = spec.outputs.iter().map(|o| o.kind.is_quaternion()).collect();
    let compute = functions(program, &param_idents, &quaternion);
    let lanes = extras.lanes.then(|| rhs_lanes_fn(program));
    // A right-hand side whose every operation has a recurrence (all do) gets Taylor coefficients.
    let taylor = if extras.taylor { TaylorProgram::new(&program.rhs, ns).ok() } else { None };
    let orders = if taylor.is_some() { extras.taylor_orders } else { &[] };
    let taylor_fn =
        taylor.as_ref().map(|t| super::taylor::taylor_fn(t, &input_tokens(&param_idents, true), orders));
    let mut meta = crate::program::Meta::of(spec, lowered);
    meta.taylor_straight_line = orders.to_vec();
    let info = metadata::info(&meta);
    let model_impl = model_impl(spec, lowered, &param_idents, taylor.is_some());
    quote! {
        /// Number of states: coordinates, then speeds.
        pub const N_STATES: usize = #ns;
        /// Number of outputs.
        pub const N_OUTPUTS: usize = #no;
        /// Number of values `outputs` writes: every output's columns.
        pub const N_OUTPUT_COLUMNS: usize = #n_columns;
        #(
            /// Index of a state in `y`.
            pub const #state_consts: usize = #state_idx;
        )*
        #params_items
        /// Quantities of the parameters alone, computed once per parameter set by [`param_constants`].
        #[derive(Clone, Debug, PartialEq)]
        pub struct ParamConstants {
            /// The values, in the order `rhs_with_constants` reads them.
            pub v: [f64; #n_constants],
        }
        #compute
        #lanes
        #taylor_fn
        /// The model's metadata: names, units, outputs.
        pub const INFO: ::kane_model::runtime::ModelInfo = #info;
        #model_impl
    }
}

/// `Params` with its defaults.
fn params_items(spec: &ModelSpec, lowered: &Lowered, idents: &[Ident]) -> TokenStream {
    let defaults = lowered.params.iter().map(|s| nan_or(spec.default_of(spec.symbol_name(*s))));
    quote! {
        /// The model's parameters (defaults from the model's INPUT; NaN where none).
        #[derive(Clone, Debug, PartialEq)]
        pub struct Params {
            #(
                /// A constant of the model.
                pub #idents: f64,
            )*
        }
        impl Default for Params {
            fn default() -> Self {
                Params { #( #idents: #defaults, )* }
            }
        }
    }
}

/// How each input is read in generated functions.
fn input_tokens(params: &[Ident], generic: bool) -> impl Fn(Input) -> TokenStream + '_ {
    move |input| match input {
        Input::Time => quote!(t),
        Input::State(i) => quote!(y[#i]),
        Input::Param(i) if generic => {
            let p = &params[i];
            quote!(::kane_model::__private::cast::<T>(p.#p))
        }
        Input::Param(i) => {
            let p = &params[i];
            quote!(p.#p)
        }
        Input::ParamConstant(i) => quote!(::kane_model::__private::cast::<T>(__constants.v[#i])),
        Input::Rate(i) => quote!(rates[#i]),
        Input::Slot(i) => quote!(slots[#i]),
    }
}

/// How each input is read in `rhs_lanes`: parameters and parameter constants from slices of the
/// number type (one value per lane).
fn lane_input_tokens(input: Input) -> TokenStream {
    match input {
        Input::Time => quote!(t),
        Input::State(i) => quote!(y[#i]),
        Input::Param(i) => quote!(p[#i]),
        Input::ParamConstant(i) => quote!(d[#i]),
        Input::Rate(i) => quote!(rates[#i]),
        Input::Slot(i) => quote!(slots[#i]),
    }
}

/// `rhs_lanes`: the right-hand side with parameters and parameter constants in the number type.
fn rhs_lanes_fn(program: &Program) -> TokenStream {
    let style = SectionStyle {
        scalar: Scalar::Generic(format_ident!("T")),
        input: &lane_input_tokens,
        prefix: "__v",
    };
    let (body, values) = section::print(&program.rhs, &style);
    let idx: Vec<usize> = (0..values.len()).collect();
    quote! {
        /// `dy = f(t, y)` with the parameters `p` (in `INFO.param_names` order) and the parameter
        /// constants `d` (`param_constants(p).v`) in the number type: one member per lane of a batch.
        #[allow(unused_variables, clippy::all)]
        #[inline]
        pub fn rhs_lanes<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &[T], d: &[T], dy: &mut [T]) {
            #body
            #( dy[#idx] = #values; )*
        }

        impl ::kane_model::runtime::LaneModel for Model {
            #[inline]
            fn rhs_lanes<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &[T], d: &[T], dy: &mut [T]) {
                rhs_lanes(t, y, p, d, dy)
            }
        }
    }
}

/// `param_constants`, `rhs_with_constants`, `rhs`, `output`, `outputs` and `jacobian`.
fn functions(program: &Program, params: &[Ident], quaternion: &[bool]) -> TokenStream {
    let t = format_ident!("T");
    let (generic_in, f64_in) = (input_tokens(params, true), input_tokens(params, false));
    let generic = SectionStyle { scalar: Scalar::Generic(t.clone()), input: &generic_in, prefix: "__v" };
    let plain = SectionStyle { scalar: Scalar::F64, input: &f64_in, prefix: "__v" };
    let (constants_body, constants_values) = section::print(&program.param_constants, &plain);
    let (rhs_body, rhs_values) = section::print(&program.rhs, &generic);
    let rhs_idx: Vec<usize> = (0..rhs_values.len()).collect();
    let outputs = super::outputs::output_fns(program, quaternion, &generic);
    let ns = rhs_values.len();
    quote! {
        /// The parameter-only subexpressions of `rhs`.
        #[allow(unused_variables, clippy::all)]
        pub fn param_constants(p: &Params) -> ParamConstants {
            #constants_body
            ParamConstants { v: [#(#constants_values),*] }
        }

        /// `dy = f(t, y)` with the parameter-only quantities `d = param_constants(p)` precomputed.
        #[allow(unused_variables, clippy::all)]
        #[inline]
        pub fn rhs_with_constants<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &Params, __constants: &ParamConstants, dy: &mut [T]) {
            #rhs_body
            #( dy[#rhs_idx] = #rhs_values; )*
        }

        /// `dy = f(t, y)`: the kinematic equations and `M u' = f` solved for `u'`.
        pub fn rhs<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &Params, dy: &mut [T]) {
            rhs_with_constants(t, y, p, &param_constants(p), dy)
        }

        #outputs

        /// The Jacobian `d(y')/dy` at `(t, y)`, row-major, exact to round-off: one pass of `rhs`
        /// in dual numbers per column.
        pub fn jacobian(t: f64, y: &[f64], p: &Params, jac: &mut [f64]) {
            use ::kane_model::runtime::dual::Dual;
            let mut yd = [Dual::new(0.0, 0.0); #ns];
            let mut dyd = [Dual::new(0.0, 0.0); #ns];
            for col in 0..#ns {
                for (k, v) in yd.iter_mut().enumerate() {
                    *v = Dual::new(y[k], if k == col { 1.0 } else { 0.0 });
                }
                rhs(Dual::new(t, 0.0), &yd, p, &mut dyd);
                for row in 0..#ns {
                    jac[row * #ns + col] = dyd[row].eps;
                }
            }
        }
    }
}

/// The `Model` type and its `GeneratedModel` implementation.
fn model_impl(spec: &ModelSpec, lowered: &Lowered, idents: &[Ident], taylor: bool) -> TokenStream {
    let taylor_method = taylor.then(|| {
        quote! {
            fn taylor(t: f64, y: &[f64], p: &Params, d: &ParamConstants, order: usize, out: &mut [f64], work: &mut ::kane_model::runtime::TaylorWork) -> bool {
                taylor_with_constants(t, y, p, d, order, out, work)
            }
        }
    });
    let initial = lowered.states.iter().map(|s| nan_or(spec.default_of(spec.symbol_name(*s))));
    let names: Vec<String> =
        lowered.params.iter().map(|s| spec.symbol_name(*s).to_ascii_uppercase()).collect();
    let ns = lowered.states.len();
    // The widest output's columns (a quaternion writes four).
    let width = spec
        .outputs
        .iter()
        .map(|o| if o.kind.is_quaternion() { 4 } else { o.components.len() })
        .max()
        .unwrap_or(0);
    quote! {
        /// The model as a [`::kane_model::runtime::GeneratedModel`].
        #[derive(Clone, Copy, Debug, Default)]
        pub struct Model;

        impl ::kane_model::runtime::GeneratedModel for Model {
            type Params = Params;
            type ParamConstants = ParamConstants;
            const INFO: ::kane_model::runtime::ModelInfo = INFO;
            fn initial_state() -> Vec<f64> {
                vec![#(#initial),*]
            }
            fn set_param(p: &mut Params, name: &str, value: f64) -> bool {
                match name.to_ascii_uppercase().as_str() {
                    #( #names => { p.#idents = value; true } )*
                    _ => false,
                }
            }
            fn param(p: &Params, name: &str) -> Option<f64> {
                match name.to_ascii_uppercase().as_str() {
                    #( #names => Some(p.#idents), )*
                    _ => None,
                }
            }
            fn param_constants(p: &Params) -> ParamConstants {
                param_constants(p)
            }
            #[inline]
            fn rhs_with_constants(t: f64, y: &[f64], p: &Params, d: &ParamConstants, dy: &mut [f64]) {
                rhs_with_constants(t, y, p, d, dy)
            }
            fn output(k: usize, t: f64, y: &[f64], rates: &[f64], p: &Params, out: &mut [f64]) {
                output(k, t, y, rates, p, out)
            }
            fn constant_values(d: &ParamConstants) -> &[f64] {
                &d.v
            }
            fn output_rate(k: usize, t: f64, y: &[f64], dy: &[f64], p: &Params, out: &mut [f64], rate: &mut [f64]) {
                use ::kane_model::runtime::dual::Dual;
                let mut yd = [Dual::new(0.0, 0.0); #ns];
                for ((v, a), b) in yd.iter_mut().zip(y).zip(dy) {
                    *v = Dual::new(*a, *b);
                }
                let mut od = [Dual::new(0.0, 0.0); #width];
                let w = out.len().min(#width);
                output(k, Dual::new(t, 1.0), &yd, &[], p, &mut od[..w]);
                for ((o, r), d) in out.iter_mut().zip(rate.iter_mut()).zip(&od[..w]) {
                    *o = d.re;
                    *r = d.eps;
                }
            }
            #taylor_method
        }
    }
}

/// `f64::NAN` as tokens for a missing value, else the literal.
fn nan_or(v: Option<f64>) -> TokenStream {
    match v {
        Some(v) if v.is_finite() => {
            let lit = proc_macro2::Literal::f64_suffixed(v);
            quote!(#lit)
        }
        _ => quote!(f64::NAN),
    }
}
