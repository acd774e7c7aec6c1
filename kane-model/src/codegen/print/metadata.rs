//! The runtime metadata printed: in comes a model's [`Meta`]; out goes a `ModelInfo` literal
//! (names, units, outputs with their columns and the states they read).

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use crate::program::Meta;

/// The `ModelInfo` expression of a model.
pub fn info(meta: &Meta) -> TokenStream {
    let Meta {
        name,
        states,
        state_units,
        n_coordinates,
        params,
        param_units,
        cyclic,
        dependent_coordinates,
        taylor_straight_line,
        inputs,
        open_inputs,
        ..
    } = meta;
    let (rhs_ops, out_ops) = (meta.op_counts.rhs, meta.op_counts.outputs);
    let outputs = meta.outputs.iter().map(|o| {
        let (oname, unit, kind, columns, reads) = (&o.name, &o.unit, &o.kind, &o.columns, &o.reads);
        let needs_rates = o.needs_rates;
        let kind = format_ident!("{kind:?}");
        quote! {
            ::kane_model::runtime::OutputInfo {
                name: #oname,
                unit: #unit,
                kind: ::kane_model::runtime::OutputKind::#kind,
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
            n_coordinates: #n_coordinates,
            param_names: &[#(#params),*],
            param_units: &[#(#param_units),*],
            inputs: &[#(#inputs),*],
            open_inputs: &[#(#open_inputs),*],
            outputs: &[#(#outputs),*],
            cyclic: &[#(#cyclic),*],
            dependent_coordinates: &[#(#dependent_coordinates),*],
            op_counts: ::kane_model::runtime::OpCounts { rhs: #rhs_ops, outputs: #out_ops },
            taylor_straight_line: &[#(#taylor_straight_line),*],
        }
    }
}
