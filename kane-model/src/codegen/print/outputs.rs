//! The outputs printed: in come the lowered output sections; out go `output(k, ..)` (one output,
//! nothing else computed) and `outputs(..)` (every column in order).

use proc_macro2::TokenStream;
use quote::quote;

use super::section::{self, SectionStyle};
use crate::program::ir::Program;

/// `output` and `outputs`; `quaternion[k]` says output `k`'s nine direction cosines are written
/// as a quaternion.
pub fn output_fns(program: &Program, quaternion: &[bool], style: &SectionStyle<'_>) -> TokenStream {
    let mut arms = TokenStream::new();
    let mut widths = Vec::new();
    for (k, code) in program.outputs.iter().enumerate() {
        let (body, values) = section::print(&code.section, style);
        let writes = if quaternion[k] {
            widths.push(4usize);
            quote! {
                let q = ::kane_model::runtime::quaternion_from_dcm(&[#(#values),*]);
                out[..4].copy_from_slice(&q);
            }
        } else {
            widths.push(values.len());
            let idx = 0..values.len();
            quote!(#( out[#idx] = #values; )*)
        };
        arms.extend(quote!(#k => { #body #writes }));
    }
    let needs_rates = program.outputs.iter().any(|o| o.needs_rates);
    let ns = program.rhs.results.len();
    let nq = program.n_coordinates;
    let rates = if needs_rates {
        quote! {
            let mut dy = [T::zero(); #ns];
            rhs(t, y, p, &mut dy);
            let rates = &dy[#nq..];
        }
    } else {
        quote!(let rates: &[T] = &[];)
    };
    let starts: Vec<usize> = widths
        .iter()
        .scan(0, |acc, w| {
            let s = *acc;
            *acc += w;
            Some(s)
        })
        .collect();
    let ends: Vec<usize> = starts.iter().zip(&widths).map(|(s, w)| s + w).collect();
    let ks = 0..program.outputs.len();
    quote! {
        /// Output `k` at `(t, y)` into `out`; `rates` are `u'` when the output reads them.
        #[allow(unused_variables, clippy::all)]
        pub fn output<T: ::kane_model::__private::num_traits::Float>(k: usize, t: T, y: &[T], rates: &[T], p: &Params, out: &mut [T]) {
            match k {
                #arms
                _ => {}
            }
        }

        /// Every output at `(t, y)`, their columns one after another.
        #[allow(unused_variables, clippy::all)]
        pub fn outputs<T: ::kane_model::__private::num_traits::Float>(t: T, y: &[T], p: &Params, out: &mut [T]) {
            #rates
            #( output(#ks, t, y, rates, p, &mut out[#starts..#ends]); )*
        }
    }
}
