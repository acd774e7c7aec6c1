//! `model!("path/to/model.al")`: expands a model file into its generated module items (`rhs`,
//! outputs, metadata); `model!("path/to/model.al", taylor, lanes, taylor_orders = [8, 12, 16])`
//! adds Taylor coefficients (straight-line at those orders) and `rhs_lanes`, and `drawing` the
//! outputs placing every frame and point (a default view's), each only where a run needs it.
//!
//! A thin shell: it reads the file (relative to the calling crate's manifest), asks
//! `kane_model` for the code, and turns any error into a compile error showing the model file's
//! line. The file is included with `include_str!`, so editing it triggers a rebuild.
//!
//! ```text
//! mod gimbal {
//!     kane_derive::model!("../kane-model/models/gimbal_gyroscope.al");
//! }
//! ```

use kane_model::codegen::CodeOptions;
use proc_macro::TokenStream;
use quote::quote;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{parse_macro_input, LitInt, LitStr, Token};

/// A macro's input: the model (a path or a name) and what to generate beyond `rhs`:
/// `taylor`, `lanes`, `drawing`, `taylor_orders = [..]`, comma-separated.
struct MacroInput {
    model: LitStr,
    options: CodeOptions,
}

impl Parse for MacroInput {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let model: LitStr = input.parse()?;
        let mut options = CodeOptions::default();
        while input.parse::<Option<Token![,]>>()?.is_some() && !input.is_empty() {
            let key: syn::Ident = input.parse()?;
            match key.to_string().as_str() {
                "taylor" => options.taylor = true,
                "lanes" => options.lanes = true,
                "drawing" => options.drawing = true,
                "taylor_orders" => {
                    input.parse::<Token![=]>()?;
                    let list;
                    syn::bracketed!(list in input);
                    let orders = Punctuated::<LitInt, Token![,]>::parse_terminated(&list)?;
                    options.taylor_orders =
                        orders.iter().map(LitInt::base10_parse).collect::<syn::Result<_>>()?;
                }
                _ => {
                    return Err(syn::Error::new(
                        key.span(),
                        "expected `taylor`, `lanes`, `drawing` or `taylor_orders = [..]`",
                    ))
                }
            }
        }
        Ok(MacroInput { model, options })
    }
}

/// Expands a model file into `Params`, `rhs`, `outputs`, state indices and a `Model` type.
#[proc_macro]
pub fn model(input: TokenStream) -> TokenStream {
    let input = parse_macro_input!(input as MacroInput);
    expand(&input.model, &input.options).unwrap_or_else(syn::Error::into_compile_error).into()
}

/// Expands a canonical system built through kane-model's Rust API (`kane_model::models`), by
/// name, into the same items as [`model!`].
#[proc_macro]
pub fn builtin_model(input: TokenStream) -> TokenStream {
    let MacroInput { model: name, options } = parse_macro_input!(input as MacroInput);
    kane_model::generate::generate_builtin(&name.value(), &options)
        .map(|e| e.tokens)
        .unwrap_or_else(|e| syn::Error::new(name.span(), e.to_string()).into_compile_error())
        .into()
}

fn expand(lit: &LitStr, options: &CodeOptions) -> syn::Result<proc_macro2::TokenStream> {
    let dir = std::env::var("CARGO_MANIFEST_DIR").unwrap_or_else(|_| ".".into());
    let path = std::path::Path::new(&dir).join(lit.value());
    let shown = lit.value();
    let src = std::fs::read_to_string(&path).map_err(|e| {
        syn::Error::new(lit.span(), format!("cannot read model file {}: {e}", path.display()))
    })?;
    let emitted = kane_model::generate::generate_file(std::path::Path::new(&shown), &src, options)
        .map_err(|e| syn::Error::new(lit.span(), e.to_string()))?;
    let tokens = emitted.tokens;
    let full = path.display().to_string();
    Ok(quote! {
        #tokens
        const _: &str = include_str!(#full);
    })
}

#[cfg(test)]
mod tests {
    use super::{expand, CodeOptions, MacroInput};
    use proc_macro2::Span;
    use syn::LitStr;

    #[test]
    fn a_model_file_error_becomes_a_compile_error_with_its_line() {
        let err = expand(&LitStr::new("tests/data/bad_model.al", Span::call_site()), &Default::default())
            .unwrap_err();
        let text = err.to_string();
        assert!(text.contains("tests/data/bad_model.al:3:18: error: `QQ` is not defined"), "{text}");
        let tokens = err.into_compile_error().to_string();
        assert!(tokens.contains("compile_error"), "{tokens}");
    }

    #[test]
    fn a_missing_file_is_a_compile_error_naming_it() {
        let err =
            expand(&LitStr::new("tests/data/nope.al", Span::call_site()), &Default::default()).unwrap_err();
        assert!(err.to_string().starts_with("cannot read model file"), "{err}");
    }

    #[test]
    fn a_good_model_expands_and_tracks_its_file() {
        let gimbal = LitStr::new("../kane-model/models/gimbal_gyroscope.al", Span::call_site());
        let tokens = expand(&gimbal, &Default::default()).unwrap().to_string();
        assert!(
            tokens.contains("pub fn rhs_with_constants") && tokens.contains("include_str"),
            "{}",
            &tokens[..200]
        );
    }

    #[test]
    fn straight_line_taylor_orders_are_asked_by_name() {
        let input: MacroInput = syn::parse_str(r#""m.al", taylor_orders = [8, 16], lanes"#).unwrap();
        assert_eq!(input.options.taylor_orders, vec![8, 16]);
        assert!(input.options.lanes && !input.options.taylor);
        let input: MacroInput = syn::parse_str(r#""m.al""#).unwrap();
        assert_eq!(input.options, CodeOptions::default());
        let input: MacroInput = syn::parse_str(r#""m.al", taylor,"#).unwrap();
        assert!(input.options.taylor);
        assert!(syn::parse_str::<MacroInput>(r#""m.al", orders = [8]"#).is_err());
    }

    #[test]
    fn straight_line_code_is_written_only_when_asked() {
        let gimbal = LitStr::new("../kane-model/models/gimbal_gyroscope.al", Span::call_site());
        let plain = expand(&gimbal, &Default::default()).unwrap().to_string();
        assert!(!plain.contains("taylor_with_constants") && !plain.contains("rhs_lanes"));
        let options = CodeOptions { taylor: true, ..Default::default() };
        let looped = expand(&gimbal, &options).unwrap().to_string();
        assert!(looped.contains("taylor_with_constants_loop") && !looped.contains("taylor_order_"));
        let options = CodeOptions { taylor_orders: vec![12], lanes: true, ..Default::default() };
        let asked = expand(&gimbal, &options).unwrap().to_string();
        assert!(asked.contains("taylor_order_12") && !asked.contains("taylor_order_16"));
        assert!(asked.contains("LaneModel for Model"));
    }
}
