//! `include_profiles!("profiles.toml")`: one module per profile of a file.

use std::path::Path;

use proc_macro2::{Literal, TokenStream};
use profile_codegen::profiles::Profiles;
use syn::LitStr;

/// Expands `include_profiles!(path)`; errors become a `compile_error!` on the path.
pub(crate) fn include_profiles(input: TokenStream) -> TokenStream {
    match try_include(input) {
        Ok(tokens) => tokens,
        Err(e) => e.to_compile_error(),
    }
}

/// The path, with a trailing comma allowed as `include_str!` allows it.
struct PathArg(LitStr);

impl syn::parse::Parse for PathArg {
    fn parse(input: syn::parse::ParseStream) -> syn::Result<Self> {
        let lit = input.parse()?;
        if input.peek(syn::Token![,]) {
            input.parse::<syn::Token![,]>()?;
        }
        Ok(PathArg(lit))
    }
}

fn try_include(input: TokenStream) -> syn::Result<TokenStream> {
    let PathArg(lit) = syn::parse2(input).map_err(|e| {
        syn::Error::new(
            e.span(),
            "expected the path of a profiles file, relative to the crate's Cargo.toml: \
             `include_profiles!(\"profiles.toml\")`",
        )
    })?;
    let dir = std::env::var("CARGO_MANIFEST_DIR").map_err(|_| {
        syn::Error::new(
            lit.span(),
            "`CARGO_MANIFEST_DIR` is not set: build with Cargo to resolve the path",
        )
    })?;
    let relative = lit.value();
    let path = Path::new(&dir).join(&relative);
    let bytes = std::fs::read(&path).map_err(|e| {
        syn::Error::new(
            lit.span(),
            format!(
                "cannot read `{}`: {e} (the path is relative to the crate's root, the folder \
                 of its Cargo.toml: `{dir}`)",
                path.display()
            ),
        )
    })?;
    let profiles = Profiles::parse_bytes(&relative, &bytes)
        .map_err(|e| syn::Error::new(lit.span(), e.message()))?;
    let items = profiles.rust_tokens();
    // Make Cargo rebuild when the file changes.
    let tracked = Literal::string(&path.to_string_lossy());
    Ok(quote::quote! {
        #items
        const _: &[u8] = include_bytes!(#tracked);
    })
}
