//! `model!("path/to/model.al")`: expands a model file into its generated module items.
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

use proc_macro::TokenStream;
use quote::quote;
use syn::{parse_macro_input, LitStr};

/// Expands a model file into `Params`, `rhs`, `outputs`, state indices and a `Model` type.
#[proc_macro]
pub fn model(input: TokenStream) -> TokenStream {
    let path = parse_macro_input!(input as LitStr);
    expand(&path).unwrap_or_else(syn::Error::into_compile_error).into()
}

/// Expands a canonical system built through kane-model's Rust API (`kane_model::models`), by
/// name, into the same items as [`model!`].
#[proc_macro]
pub fn builtin_model(input: TokenStream) -> TokenStream {
    let name = parse_macro_input!(input as LitStr);
    kane_model::build::generate_builtin(&name.value())
        .map(|e| e.tokens)
        .unwrap_or_else(|e| syn::Error::new(name.span(), e.to_string()).into_compile_error())
        .into()
}

fn expand(lit: &LitStr) -> syn::Result<proc_macro2::TokenStream> {
    let dir = std::env::var("CARGO_MANIFEST_DIR").unwrap_or_else(|_| ".".into());
    let path = std::path::Path::new(&dir).join(lit.value());
    let shown = lit.value();
    let src = std::fs::read_to_string(&path).map_err(|e| {
        syn::Error::new(lit.span(), format!("cannot read model file {}: {e}", path.display()))
    })?;
    let emitted = kane_model::build::generate_file(std::path::Path::new(&shown), &src)
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
    use super::expand;
    use proc_macro2::Span;
    use syn::LitStr;

    #[test]
    fn a_model_file_error_becomes_a_compile_error_with_its_line() {
        let err = expand(&LitStr::new("tests/data/bad_model.al", Span::call_site())).unwrap_err();
        let text = err.to_string();
        assert!(text.contains("tests/data/bad_model.al:3:18: error: `QQ` is not defined"), "{text}");
        let tokens = err.into_compile_error().to_string();
        assert!(tokens.contains("compile_error"), "{tokens}");
    }

    #[test]
    fn a_missing_file_is_a_compile_error_naming_it() {
        let err = expand(&LitStr::new("tests/data/nope.al", Span::call_site())).unwrap_err();
        assert!(err.to_string().starts_with("cannot read model file"), "{err}");
    }

    #[test]
    fn a_good_model_expands_and_tracks_its_file() {
        let tokens = expand(&LitStr::new("../kane-model/models/gimbal_gyroscope.al", Span::call_site()))
            .unwrap()
            .to_string();
        assert!(
            tokens.contains("pub fn rhs_derived") && tokens.contains("include_str"),
            "{}",
            &tokens[..200]
        );
    }
}
