//! The runtime metadata printed: in come a spec and its lowered program; out goes a
//! `ModelInfo` literal (names, units, outputs with their columns and the states they read).

use proc_macro2::TokenStream;
use quote::quote;

use crate::spec::ModelSpec;

use super::super::lower::Lowered;

/// The `ModelInfo` expression of a model.
pub fn info(spec: &ModelSpec, lowered: &Lowered) -> TokenStream {
    let name = &spec.name;
    let states: Vec<&str> = lowered.states.iter().map(|s| spec.symbol_name(*s)).collect();
    let state_units: Vec<&str> = states.iter().map(|s| spec.unit(s)).collect();
    let params: Vec<&str> = lowered.params.iter().map(|s| spec.symbol_name(*s)).collect();
    let param_units: Vec<&str> = params.iter().map(|s| spec.unit(s)).collect();
    let nq = lowered.program.n_coordinates;
    let cyclic = &lowered.program.cyclic;
    let (rhs_ops, out_ops) = lowered.program.op_counts();
    let outputs = spec.outputs.iter().zip(&lowered.program.outputs).map(|(o, code)| {
        let (oname, unit) = (&o.name, &o.unit);
        let kind = o.kind.label();
        let columns = o.columns();
        let reads = &code.reads;
        let needs_rates = code.needs_rates;
        quote! {
            ::kane_model::runtime::OutputInfo {
                name: #oname,
                unit: #unit,
                kind: #kind,
                columns: &[#(#columns),*],
                reads: &[#(#reads),*],
                needs_rates: #needs_rates,
            }
        }
    });
    quote! {
        ::kane_model::runtime::ModelInfo {
            name: #name,
            state_names: &[#(#states),*],
            state_units: &[#(#state_units),*],
            n_coordinates: #nq,
            param_names: &[#(#params),*],
            param_units: &[#(#param_units),*],
            outputs: &[#(#outputs),*],
            cyclic: &[#(#cyclic),*],
            op_counts: (#rhs_ops, #out_ops),
        }
    }
}
