//! Code generation: Kane's equations become a Rust module with a straight-line `rhs`, generic
//! over `num_traits::Float`, and an `outputs` function evaluated only at output times.
//!
//! `rhs` computes the CSE'd entries of `M` and `f`, solves `M u' = f` with an `LDL^T`
//! factorisation unrolled at generation time (structural zeros of `M` skipped), and writes
//! `y' = (q', u')`. The same model gives byte-identical code.
// Symmetric-matrix code reads clearest with two indices (M[i][j] and M[j][i]).
#![allow(clippy::needless_range_loop)]

mod hoist;
mod ldlt;
mod names;
mod solve;

use proc_macro2::{Ident, Span, TokenStream};
use quote::{format_ident, quote};
use rustc_hash::FxHashMap;
use thiserror::Error;

use crate::expr::{Cse, ExprId, RustStyle, Scalar, SymbolId, SymbolKind, Tape};
use crate::lang::{LoadedModel, Value};

pub use names::rust_ident;

/// Why a model cannot be turned into code.
#[derive(Clone, Debug, PartialEq, Error)]
pub enum CodegenError {
    /// The model file does not call KANE().
    #[error("the model derives no equations: call KANE() in the model file")]
    NoEquations,
    /// A symbol the equations need is neither a state, a parameter nor time.
    #[error("`{0}` is a time-dependent quantity that is not a state; specified functions are not supported in generated code")]
    UnsupportedSymbol(String),
    /// An OUTPUT name that is not a scalar the model defines.
    #[error("OUTPUT `{0}` is not a state or a scalar defined in the model")]
    UnknownOutput(String),
    /// An expression operation failed.
    #[error(transparent)]
    Expr(#[from] crate::expr::ExprError),
    /// A mechanics operation failed.
    #[error(transparent)]
    Mechanics(#[from] crate::mechanics::MechanicsError),
}

/// Generated code and what it costs.
#[derive(Clone, Debug)]
pub struct Emitted {
    /// The module's items.
    pub tokens: TokenStream,
    /// Arithmetic operations in `rhs` (equations and solve) and in `outputs` (beyond `rhs`).
    pub op_counts: (usize, usize),
    /// A one-line description for the module's documentation.
    pub doc: String,
}

/// Generates the items of a model module named `name` from a loaded model file.
pub fn emit(loaded: &mut LoadedModel, name: &str) -> Result<Emitted, CodegenError> {
    let mut eqs = loaded.equations.clone().ok_or(CodegenError::NoEquations)?;
    // Generated code runs many times: the collected form (terms grouped by state monomial) is
    // worth its derivation cost.
    loaded.model.simplify_equations(&mut eqs)?;
    let states: Vec<SymbolId> = eqs.coordinates.iter().chain(&eqs.speeds).copied().collect();
    let (nq, n) = (eqs.coordinates.len(), eqs.speeds.len());

    // Outputs: OUTPUT names other than T and the states, each a scalar of the model.
    let mut outputs: Vec<(String, ExprId, String)> = Vec::new();
    let mut output_reads: Vec<ExprId> = Vec::new();
    for (oname, _) in &loaded.outputs {
        let upper = oname.to_ascii_uppercase();
        if upper == "T"
            || states.iter().any(|s| loaded.model.ar.symbol_info(*s).name.eq_ignore_ascii_case(oname))
        {
            continue;
        }
        match loaded.value(oname) {
            Some(Value::Scalar(e)) => {
                let unit = loaded.units.get(&upper).cloned().unwrap_or_default();
                // Which states an output depends on is read from its collected form, where
                // coordinates that cancel (|a_P| does not depend on the gimbal's q1) are gone; the
                // code evaluates the original form, which is better conditioned (the expanded
                // one cancels large terms when the gimbals spin fast).
                let c = loaded.model.collected_form(e)?;
                let reads =
                    if loaded.model.ar.free_symbols(&[c]).len() < loaded.model.ar.free_symbols(&[e]).len() {
                        c
                    } else {
                        e
                    };
                outputs.push((oname.clone(), e, unit));
                output_reads.push(reads);
            }
            _ => return Err(CodegenError::UnknownOutput(oname.clone())),
        }
    }

    // Kinetic energy in terms of the states (for run summaries); q' eliminated like velocities.
    let ke = loaded.model.kinetic_energy()?;
    let ke = {
        let mut map = FxHashMap::default();
        for (q, rhs) in eqs.coordinates.iter().zip(&eqs.kinematics) {
            let name = format!("{}'", loaded.model.ar.symbol_info(*q).name);
            if let Some(d) = loaded.model.ar.lookup(&name) {
                map.insert(loaded.model.ar.symbol_expr(d), *rhs);
            }
        }
        for (u, e) in &eqs.dependent_speeds {
            map.insert(loaded.model.ar.symbol_expr(*u), *e);
        }
        loaded.model.ar.subs(ke, &map)?
    };
    let ar = &mut loaded.model.ar;
    let mut rhs_roots: Vec<ExprId> = Vec::new();
    for i in 0..n {
        for j in i..n {
            rhs_roots.push(eqs.mass_matrix[i][j]);
        }
    }
    rhs_roots.extend(&eqs.forcing);
    rhs_roots.extend(&eqs.kinematics);
    let out_roots: Vec<ExprId> = outputs.iter().map(|o| o.1).collect();

    // Parameters: the constants the code reads, in declaration order.
    let mut all = rhs_roots.clone();
    all.extend(&out_roots);
    all.push(ke);
    let udot: Vec<SymbolId> = eqs.speed_derivatives.clone();
    let mut params: Vec<SymbolId> = Vec::new();
    for s in ar.free_symbols(&all) {
        match ar.symbol_info(s).kind {
            SymbolKind::Constant => params.push(s),
            SymbolKind::Time => {}
            _ if states.contains(&s) || udot.contains(&s) => {}
            _ => return Err(CodegenError::UnsupportedSymbol(ar.symbol_info(s).name.clone())),
        }
    }
    // Parameter-only parts (whole subexpressions, the parameter terms of sums and factors of
    // products, reciprocals of constant pivots) become constants computed once per parameter
    // set by `derive` and read by `rhs_derived`.
    let is_param = |s: SymbolId| params.contains(&s);
    let mut hoisted = hoist::Hoisted::default();
    let mut roots = Vec::with_capacity(rhs_roots.len());
    for &r in &rhs_roots {
        roots.push(hoisted.rewrite(ar, r, &is_param)?);
    }
    // The determinant of each 2x2 block of M, collected by state monomial, so that its
    // parameter parts are constants too (the gimbal's is A + B cos^2 q2): appended to the roots.
    let pairs: Vec<(usize, usize)> = solve::blocks(n, |i, j| !ar.is_zero(eqs.mass_matrix[i][j]))
        .into_iter()
        .filter_map(|b| if let [a, c] = b[..] { Some((a, c)) } else { None })
        .collect();
    let mut det_roots: Vec<((usize, usize), usize)> = Vec::new();
    for &(a, c) in &pairs {
        let mm = &eqs.mass_matrix;
        let diag = ar.mul(&[mm[a][a], mm[c][c]])?;
        let off = ar.powi(mm[a][c], 2)?;
        let det = ar.sub(diag, off)?;
        let det = ar.collect_state(det, is_param)?;
        roots.push(hoisted.rewrite(ar, det, &is_param)?);
        det_roots.push(((a, c), roots.len() - 1));
    }
    // A pivot without fill-in is M's diagonal entry itself: a constant one is inverted once
    // (2x2 blocks use their determinant instead).
    let mut pivot_recips: Vec<Option<ExprId>> = vec![None; n];
    for j in (0..n).filter(|j| !pairs.iter().any(|(a, c)| a == j || c == j)) {
        let row_empty = (0..j).all(|k| ar.is_zero(eqs.mass_matrix[k][j]));
        let mjj = eqs.mass_matrix[j][j];
        if row_empty && !ar.is_zero(mjj) && ar.free_symbols(&[mjj]).iter().all(|s| is_param(*s)) {
            let minus_one = ar.minus_one();
            let recip = ar.pow(mjj, minus_one)?;
            pivot_recips[j] = Some(hoisted.constant(ar, recip)?);
        }
    }
    let ident_of = |s: SymbolId| -> Ident { rust_ident(&ar.symbol_info(s).name) };
    let state_idents: Vec<Ident> = states.iter().map(|s| ident_of(*s)).collect();
    let param_idents: Vec<Ident> = params.iter().map(|s| ident_of(*s)).collect();
    let udot_idents: Vec<Ident> = udot.iter().map(|s| ident_of(*s)).collect();

    let t_ident = format_ident!("T");
    let symbol_tokens = |s: SymbolId| -> TokenStream {
        match ar.symbol_info(s).kind {
            SymbolKind::Time => quote!(t),
            _ => {
                let id = ident_of(s);
                quote!(#id)
            }
        }
    };

    // rhs: parameters and states as locals, shared subexpressions, M and f, the solve, y'.
    let (rhs_body, derive_body, n_hoisted, rhs_ops) = {
        let hoisted_ident = |s: SymbolId| hoisted.index_of(s).map(|i| format_ident!("__h{}", i));
        let local_tokens = |s: SymbolId| -> TokenStream {
            match hoisted_ident(s) {
                Some(h) => quote!(#h),
                None => symbol_tokens(s),
            }
        };
        // derive: f64 arithmetic on the parameters, shared parts computed once.
        let defs: Vec<ExprId> = hoisted.defs.iter().map(|d| d.1).collect();
        let mut derive = TokenStream::new();
        let (body, values) = straight_line(ar, &defs, &symbol_tokens, Scalar::F64);
        derive.extend(body);
        let hs: Vec<Ident> = (0..defs.len()).map(|i| format_ident!("__h{}", i)).collect();
        derive.extend(quote!(Derived { v: [#(#values),*] }));

        let cse = Cse::new(ar, &roots);
        let mut names: FxHashMap<ExprId, TokenStream> = FxHashMap::default();
        let temps: Vec<ExprId> = cse.temps.clone();
        for (i, e) in temps.iter().enumerate() {
            let x = format_ident!("__x{}", i);
            names.insert(*e, quote!(#x));
        }
        // Speeds arrive last in an integrator's stage (they come from the previous stage's u'):
        // products multiply the factors without speeds first.
        let late_memo = std::cell::RefCell::new(FxHashMap::<ExprId, bool>::default());
        let is_late = |e: ExprId| -> bool {
            if let Some(v) = late_memo.borrow().get(&e) {
                return *v;
            }
            let v = ar.free_symbols(&[e]).iter().any(|s| eqs.speeds.contains(s));
            late_memo.borrow_mut().insert(e, v);
            v
        };
        let style = RustStyle {
            scalar: Scalar::Generic(t_ident.clone()),
            symbol: &local_tokens,
            names: Some(&names),
            late: Some(&is_late),
        };
        let mut body = TokenStream::new();
        for (i, h) in hs.iter().enumerate() {
            body.extend(
                quote!(let #h: #t_ident = ::kane_model::__private::cast::<#t_ident>(__derived.v[#i]);),
            );
        }
        // sin and cos of the same argument come from one sin_cos call.
        let partner = |ar: &crate::expr::Arena, e: ExprId| -> Option<(crate::expr::Func, ExprId)> {
            match *ar.node(e) {
                crate::expr::Node::Func(f @ (crate::expr::Func::Sin | crate::expr::Func::Cos), x) => {
                    Some((f, x))
                }
                _ => None,
            }
        };
        let mut emitted_pair: Vec<ExprId> = Vec::new();
        for (i, e) in temps.iter().enumerate() {
            if emitted_pair.contains(e) {
                continue;
            }
            let x = format_ident!("__x{}", i);
            if let Some((f, arg)) = partner(ar, *e) {
                let other =
                    temps.iter().position(|o| partner(ar, *o).is_some_and(|(g, a)| a == arg && g != f));
                if let Some(j) = other {
                    let y = format_ident!("__x{}", j);
                    let a = names.get(&arg).cloned().unwrap_or_else(|| {
                        let t = ar.to_rust(arg, &style);
                        quote!((#t))
                    });
                    let (s_id, c_id) = if f == crate::expr::Func::Sin { (x, y) } else { (y, x) };
                    body.extend(quote!(let (#s_id, #c_id): (#t_ident, #t_ident) = #a.sin_cos();));
                    emitted_pair.push(temps[j]);
                    continue;
                }
            }
            let v = ar.to_rust(*e, &style);
            body.extend(quote!(let #x: #t_ident = #v;));
        }
        let mut k = 0;
        let mut m_tokens: Vec<Vec<Option<TokenStream>>> = vec![vec![None; n]; n];
        for i in 0..n {
            for j in i..n {
                let e = roots[k];
                k += 1;
                if ar.is_zero(e) {
                    continue;
                }
                let id = format_ident!("__m{}_{}", i, j);
                let v = names.get(&e).cloned().unwrap_or_else(|| ar.to_rust(e, &style));
                body.extend(quote!(let #id: #t_ident = #v;));
                m_tokens[i][j] = Some(quote!(#id));
                m_tokens[j][i] = Some(quote!(#id));
            }
        }
        let mut f_tokens = Vec::with_capacity(n);
        for i in 0..n {
            let e = roots[k];
            k += 1;
            let id = format_ident!("__f{}", i);
            let v = names.get(&e).cloned().unwrap_or_else(|| ar.to_rust(e, &style));
            body.extend(quote!(let #id: #t_ident = #v;));
            f_tokens.push(quote!(#id));
        }
        let recips: Vec<Option<TokenStream>> =
            pivot_recips.iter().map(|r| r.map(|e| ar.to_rust(e, &style))).collect();
        let mut dets: Vec<((usize, usize), TokenStream)> = Vec::new();
        for ((a, c), k) in &det_roots {
            let id = format_ident!("__det{}_{}", a, c);
            let v = names.get(&roots[*k]).cloned().unwrap_or_else(|| ar.to_rust(roots[*k], &style));
            body.extend(quote!(let #id: #t_ident = #v;));
            dets.push(((*a, *c), quote!(#id)));
        }
        let (solve, x, solve_ops) = solve::emit(&m_tokens, &f_tokens, &recips, &dets, &t_ident);
        body.extend(solve);
        for i in 0..nq {
            let e = roots[k];
            k += 1;
            let v = names.get(&e).cloned().unwrap_or_else(|| ar.to_rust(e, &style));
            body.extend(quote!(dy[#i] = #v;));
        }
        for (i, xi) in x.iter().enumerate() {
            let idx = nq + i;
            body.extend(quote!(dy[#idx] = #xi;));
        }
        // Per-call operations: the rewritten equations and the solve.
        let mut inputs: Vec<SymbolId> = states.clone();
        inputs.extend(&params);
        inputs.extend(hoisted.defs.iter().map(|d| d.0));
        inputs.push(crate::expr::TIME);
        let eq_ops = Tape::compile(ar, &roots, &inputs).map(|t| t.op_count()).unwrap_or(0);
        (body, derive, defs.len(), eq_ops + solve_ops)
    };

    // outputs: y' from rhs, then the output expressions.
    let (out_body, out_ops) = {
        let (mut body, values) =
            straight_line(ar, &out_roots, &symbol_tokens, Scalar::Generic(t_ident.clone()));
        for (i, v) in values.iter().enumerate() {
            body.extend(quote!(out[#i] = #v;));
        }
        let mut inputs: Vec<SymbolId> = states.clone();
        inputs.extend(&params);
        inputs.extend(&udot);
        inputs.push(crate::expr::TIME);
        let ops = Tape::compile(ar, &out_roots, &inputs).map(|t| t.op_count()).unwrap_or(0);
        (body, ops)
    };

    // Kinetic energy as one expression, its shared parts named.
    let ke_body = {
        let (mut body, values) = straight_line(ar, &[ke], &symbol_tokens, Scalar::Generic(t_ident.clone()));
        let v = &values[0];
        body.extend(quote!(#v));
        body
    };

    // Coordinates no equation reads (cyclic), and the states each output reads.
    let rhs_free = ar.free_symbols(&rhs_roots);
    let cyclic: Vec<usize> = (0..nq).filter(|i| !rhs_free.contains(&states[*i])).collect();
    let output_states: Vec<Vec<usize>> = output_reads
        .iter()
        .map(|e| {
            let free = ar.free_symbols(&[*e]);
            (0..states.len()).filter(|i| free.contains(&states[*i])).collect()
        })
        .collect();
    let output_states_tokens = output_states.iter().map(|v| quote!(&[#(#v),*]));
    let ns = states.len();
    let no = outputs.len();
    let np = params.len();
    let state_names: Vec<String> = states.iter().map(|s| ar.symbol_info(*s).name.clone()).collect();
    let state_units: Vec<String> = state_names
        .iter()
        .map(|s| loaded.units.get(&s.to_ascii_uppercase()).cloned().unwrap_or_default())
        .collect();
    let state_consts: Vec<Ident> = state_names.iter().map(|s| names::const_ident(s)).collect();
    let state_idx: Vec<usize> = (0..ns).collect();
    let param_names: Vec<String> =
        params.iter().map(|s| loaded.model.ar.symbol_info(*s).name.clone()).collect();
    let param_defaults: Vec<f64> = param_names.iter().map(|p| loaded.input(p).unwrap_or(f64::NAN)).collect();
    let initial: Vec<f64> = state_names.iter().map(|s| loaded.input(s).unwrap_or(f64::NAN)).collect();
    let output_names: Vec<&String> = outputs.iter().map(|o| &o.0).collect();
    let output_units: Vec<&String> = outputs.iter().map(|o| &o.2).collect();
    let udot_idx: Vec<usize> = (nq..ns).collect();
    let param_match: Vec<String> = param_names.iter().map(|p| p.to_ascii_uppercase()).collect();
    let (rhs_ops_lit, out_ops_lit) = (rhs_ops, out_ops);
    let doc = format!("Generated by kane-model from the model `{name}`: do not edit by hand.");
    let defaults = param_defaults.iter().map(|v| nan_or(*v));
    let initial_tokens = initial.iter().map(|v| nan_or(*v));
    let name_lit = name.to_string();
    let _ = Span::call_site();

    let tokens = quote! {

        /// Number of states: coordinates, then speeds.
        pub const N_STATES: usize = #ns;
        /// Number of outputs.
        pub const N_OUTPUTS: usize = #no;
        #(
            /// Index of a state in `y`.
            pub const #state_consts: usize = #state_idx;
        )*

        /// The model's parameters (defaults from the model file's INPUT; NaN where none).
        #[derive(Clone, Debug, PartialEq)]
        pub struct Params {
            #(
                /// A constant of the model.
                pub #param_idents: f64,
            )*
        }

        impl Default for Params {
            fn default() -> Self {
                Params { #( #param_idents: #defaults, )* }
            }
        }

        /// Quantities of the parameters alone, computed once per parameter set by [`derive`].
        #[derive(Clone, Debug, PartialEq)]
        pub struct Derived {
            /// The values, in the order `rhs_derived` reads them.
            pub v: [f64; #n_hoisted],
        }

        /// The parameter-only subexpressions of `rhs`.
        #[allow(unused_variables, clippy::all)]
        pub fn derive(p: &Params) -> Derived {
            #( let #param_idents: f64 = p.#param_idents; )*
            #derive_body
        }

        /// `dy = f(t, y)` with the parameter-only quantities `d = derive(p)` precomputed.
        #[allow(unused_variables, clippy::all)]
        #[inline]
        pub fn rhs_derived<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &Params, __derived: &Derived, dy: &mut [T]) {
            #( let #param_idents: T = ::kane_model::__private::cast::<T>(p.#param_idents); )*
            #( let #state_idents: T = y[#state_idx]; )*
            #rhs_body
        }

        /// `dy = f(t, y)`: the kinematic equations and `M u' = f` solved for `u'`.
        pub fn rhs<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &Params, dy: &mut [T]) {
            rhs_derived(t, y, p, &derive(p), dy)
        }

        /// The model's outputs at `(t, y)`.
        #[allow(unused_variables, clippy::all)]
        pub fn outputs<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &Params, out: &mut [T]) {
            let mut dy = [T::zero(); #ns];
            rhs(t, y, p, &mut dy);
            #( let #param_idents: T = ::kane_model::__private::cast::<T>(p.#param_idents); )*
            #( let #state_idents: T = y[#state_idx]; )*
            #( let #udot_idents: T = dy[#udot_idx]; )*
            #out_body
        }

        /// The kinetic energy at `(t, y)`.
        #[allow(unused_variables, clippy::all)]
        pub fn kinetic_energy<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &Params) -> T {
            #( let #param_idents: T = ::kane_model::__private::cast::<T>(p.#param_idents); )*
            #( let #state_idents: T = y[#state_idx]; )*
            #ke_body
        }

        /// The Jacobian `d(y')/dy` at `(t, y)`, row-major, exact to round-off: one pass of `rhs`
        /// in dual numbers per column.
        pub fn jacobian(t: f64, y: &[f64], p: &Params, jac: &mut [f64]) {
            use ::kane_model::dual::Dual;
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

        /// The model as a [`::kane_model::runtime::GeneratedModel`].
        #[derive(Clone, Copy, Debug, Default)]
        pub struct Model;

        impl ::kane_model::runtime::GeneratedModel for Model {
            type Params = Params;
            type Derived = Derived;
            const NAME: &'static str = #name_lit;
            const STATE_NAMES: &'static [&'static str] = &[#(#state_names),*];
            const STATE_UNITS: &'static [&'static str] = &[#(#state_units),*];
            const OUTPUT_NAMES: &'static [&'static str] = &[#(#output_names),*];
            const OUTPUT_UNITS: &'static [&'static str] = &[#(#output_units),*];
            const PARAM_NAMES: &'static [&'static str] = &[#(#param_names),*];
            const OP_COUNTS: (usize, usize) = (#rhs_ops_lit, #out_ops_lit);
            const CYCLIC: &'static [usize] = &[#(#cyclic),*];
            const OUTPUT_STATES: &'static [&'static [usize]] = &[#(#output_states_tokens),*];
            fn initial_state() -> Vec<f64> {
                vec![#(#initial_tokens),*]
            }
            fn set_param(p: &mut Params, name: &str, value: f64) -> bool {
                match name.to_ascii_uppercase().as_str() {
                    #( #param_match => { p.#param_idents = value; true } )*
                    _ => false,
                }
            }
            fn param(p: &Params, name: &str) -> Option<f64> {
                match name.to_ascii_uppercase().as_str() {
                    #( #param_match => Some(p.#param_idents), )*
                    _ => None,
                }
            }
            fn rhs(t: f64, y: &[f64], p: &Params, dy: &mut [f64]) {
                rhs(t, y, p, dy)
            }
            fn derive(p: &Params) -> Derived {
                derive(p)
            }
            #[inline]
            fn rhs_derived(t: f64, y: &[f64], p: &Params, d: &Derived, dy: &mut [f64]) {
                rhs_derived(t, y, p, d, dy)
            }
            fn outputs(t: f64, y: &[f64], p: &Params, out: &mut [f64]) {
                outputs(t, y, p, out)
            }
            fn kinetic_energy(t: f64, y: &[f64], p: &Params) -> f64 {
                kinetic_energy(t, y, p)
            }
        }

        const _: usize = #np;
    };
    Ok(Emitted { tokens, op_counts: (rhs_ops, out_ops), doc })
}

/// The shared subexpressions of `roots` as `let __xi: T = ...;` statements, and each root's
/// value written in them.
fn straight_line(
    ar: &crate::expr::Arena,
    roots: &[ExprId],
    symbol_tokens: &dyn Fn(SymbolId) -> TokenStream,
    scalar: Scalar,
) -> (TokenStream, Vec<TokenStream>) {
    let cse = Cse::new(ar, roots);
    let names: FxHashMap<ExprId, TokenStream> = cse
        .temps
        .iter()
        .enumerate()
        .map(|(i, e)| {
            let x = format_ident!("__x{}", i);
            (*e, quote!(#x))
        })
        .collect();
    let ty = match &scalar {
        Scalar::F64 => quote!(f64),
        Scalar::Generic(t) => quote!(#t),
    };
    let style = RustStyle { scalar, symbol: symbol_tokens, names: Some(&names), late: None };
    let mut body = TokenStream::new();
    for (i, e) in cse.temps.iter().enumerate() {
        let x = format_ident!("__x{}", i);
        let v = ar.to_rust(*e, &style);
        body.extend(quote!(let #x: #ty = #v;));
    }
    let values =
        roots.iter().map(|e| names.get(e).cloned().unwrap_or_else(|| ar.to_rust(*e, &style))).collect();
    (body, values)
}

/// `f64::NAN` as tokens for NaN, else the literal.
fn nan_or(v: f64) -> TokenStream {
    if v.is_nan() {
        quote!(f64::NAN)
    } else {
        let lit = proc_macro2::Literal::f64_suffixed(v);
        quote!(#lit)
    }
}

/// For `build.rs`: reads `model` (a model file), writes its generated module to `out` (for
/// `include!`), and asks cargo to rerun when the model file changes.
///
/// ```text
/// // build.rs
/// fn main() {
///     let out = std::path::Path::new(&std::env::var("OUT_DIR").unwrap()).join("gimbal.rs");
///     kane_model::codegen::build_script("models/gimbal_gyroscope.al", &out).unwrap();
/// }
/// // src/lib.rs: pub mod gimbal { include!(concat!(env!("OUT_DIR"), "/gimbal.rs")); }
/// ```
pub fn build_script(model: &str, out: &std::path::Path) -> Result<(), String> {
    println!("cargo:rerun-if-changed={model}");
    let src = std::fs::read_to_string(model).map_err(|e| format!("{model}: {e}"))?;
    let mut loaded = crate::lang::load(model, &src).map_err(|r| r.to_string())?;
    let name =
        std::path::Path::new(model).file_stem().and_then(|s| s.to_str()).unwrap_or("model").to_string();
    let emitted = emit(&mut loaded, &name).map_err(|e| format!("{model}: {e}"))?;
    // No inner doc comment: the file is include!d inside a module.
    let file: syn::File = syn::parse2(emitted.tokens).map_err(|e| e.to_string())?;
    let text = prettyplease::unparse(&file);
    let tmp = out.with_extension("rs.partial");
    std::fs::write(&tmp, text).map_err(|e| format!("{}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, out).map_err(|e| format!("{}: {e}", out.display()))
}

/// The generated module as formatted source text (for `kane gen` and snapshots).
pub fn to_source(emitted: &Emitted) -> Result<String, String> {
    let file: syn::File = syn::parse2(emitted.tokens.clone()).map_err(|e| e.to_string())?;
    Ok(format!("//! {}\n\n{}", emitted.doc, prettyplease::unparse(&file)))
}
