//! Arguments to a table, through `profile-core` and its emitter.

use proc_macro2::TokenStream;
use profile_core::emit;
use profile_core::params::{self, Diagnostic, Layout};

use crate::args::Loc;

fn to_error(diagnostics: Vec<Diagnostic<Loc>>) -> syn::Error {
    let mut errors = diagnostics
        .into_iter()
        .map(|d| syn::Error::new_spanned(d.loc, d.message));
    let mut first = errors
        .next()
        .unwrap_or_else(|| syn::Error::new(proc_macro2::Span::call_site(), "invalid arguments"));
    for e in errors {
        first.combine(e);
    }
    first
}

/// Expands `period_table!(...)`; errors become `compile_error!`s.
///
/// Several errors expand to several `compile_error!` statements, so they are
/// wrapped in a block to stay one expression.
pub(crate) fn period_table(input: TokenStream) -> TokenStream {
    match try_period_table(input) {
        Ok(tokens) => tokens,
        Err(e) => {
            let errors = e.to_compile_error();
            quote::quote!({ #errors })
        }
    }
}

fn try_period_table(input: TokenStream) -> syn::Result<TokenStream> {
    let whole = TokenStream::new();
    let args = crate::args::parse(input)?;
    let parsed = params::spec_from_args(&args, &whole).map_err(to_error)?;
    let spec = parsed.spec;
    let locate = |e| to_error(vec![params::locate(&e, &args, &whole)]);
    let source = match parsed.layout {
        Layout::Steps => {
            let table = spec.table().map_err(locate)?;
            emit::rust_array(spec.timer.word, &table.periods)
        }
        Layout::Segments(n) => {
            let mut pairs = Vec::with_capacity(n as usize);
            spec.for_each_segment(n, |_, period, count| pairs.push((period, count)))
                .map_err(locate)?;
            emit::rust_pairs(spec.timer.word, &pairs)
        }
    };
    source.parse().map_err(|e| {
        syn::Error::new(
            proc_macro2::Span::call_site(),
            format!("internal error: emitted source does not parse: {e}"),
        )
    })
}
