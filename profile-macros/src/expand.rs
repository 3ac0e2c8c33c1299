//! Arguments to a table, through `profile-core` and its emitter.

use proc_macro2::{Span, TokenStream};
use profile_core::emit;
use profile_core::params::{self, Diagnostic};

fn to_error(diagnostics: Vec<Diagnostic<Span>>) -> syn::Error {
    let mut errors = diagnostics
        .into_iter()
        .map(|d| syn::Error::new(d.loc, d.message));
    let mut first = errors
        .next()
        .unwrap_or_else(|| syn::Error::new(Span::call_site(), "invalid arguments"));
    for e in errors {
        first.combine(e);
    }
    first
}

/// Expands `period_table!(...)`; errors become `compile_error!`s.
pub(crate) fn period_table(input: TokenStream) -> TokenStream {
    match try_period_table(input) {
        Ok(tokens) => tokens,
        Err(e) => e.to_compile_error(),
    }
}

fn try_period_table(input: TokenStream) -> syn::Result<TokenStream> {
    let whole = Span::call_site();
    let args = crate::args::parse(input)?;
    let spec = params::spec_from_args(&args, &whole).map_err(to_error)?;
    let table = spec
        .table()
        .map_err(|e| to_error(vec![params::locate(&e, &args, &whole)]))?;
    let source = emit::rust_array(spec.timer.word, &table.periods);
    source.parse().map_err(|e| {
        syn::Error::new(
            whole,
            format!("internal error: emitted source does not parse: {e}"),
        )
    })
}
