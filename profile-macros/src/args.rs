//! `key = value, ...` into the shared argument schema of `profile-core`.

use proc_macro2::{Span, TokenStream};
use profile_core::params::{Arg, Value};
use syn::parse::{Parse, ParseStream, Parser};
use syn::punctuated::Punctuated;
use syn::{Ident, Lit, Token};

struct Pair(Arg<Span>);

impl Parse for Pair {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let key: Ident = input.parse()?;
        input.parse::<Token![=]>()?;
        let (value, value_loc) = parse_value(input)?;
        Ok(Pair(Arg {
            key: key.to_string(),
            key_loc: key.span(),
            value,
            value_loc,
        }))
    }
}

fn parse_value(input: ParseStream) -> syn::Result<(Value, Span)> {
    if input.peek(Ident) {
        let ident: Ident = input.parse()?;
        return Ok((Value::Name(ident.to_string()), ident.span()));
    }
    let minus: Option<Token![-]> = input.parse()?;
    let lit: Lit = input
        .parse()
        .map_err(|e| syn::Error::new(e.span(), "expected a number or a name"))?;
    let span = match minus {
        Some(ref m) => m.span.join(lit.span()).unwrap_or(lit.span()),
        None => lit.span(),
    };
    let sign = if minus.is_some() { -1 } else { 1 };
    let value = match &lit {
        Lit::Int(i) => Value::Int(sign * i.base10_parse::<i128>()?),
        Lit::Float(f) => Value::Float(sign as f64 * f.base10_parse::<f64>()?),
        Lit::Str(s) if minus.is_none() => Value::Name(s.value()),
        _ => return Err(syn::Error::new(span, "expected a number or a name")),
    };
    Ok((value, span))
}

/// Parses the macro's input into arguments, or a syntax error.
pub(crate) fn parse(input: TokenStream) -> syn::Result<Vec<Arg<Span>>> {
    let pairs = Punctuated::<Pair, Token![,]>::parse_terminated.parse2(input)?;
    Ok(pairs.into_iter().map(|p| p.0).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_names_numbers_and_signs() {
        let args = parse(quote::quote!(
            curve = sigmoid,
            fmin = -5,
            fmax = 1e3,
            word = "u32",
        ))
        .unwrap();
        let values: Vec<_> = args
            .iter()
            .map(|a| (a.key.as_str(), a.value.clone()))
            .collect();
        assert_eq!(
            values,
            vec![
                ("curve", Value::Name("sigmoid".into())),
                ("fmin", Value::Int(-5)),
                ("fmax", Value::Float(1000.0)),
                ("word", Value::Name("u32".into())),
            ]
        );
    }

    #[test]
    fn syntax_errors_are_errors() {
        for bad in [
            "curve",
            "curve =",
            "= 5",
            "len = 5 6",
            "len = true",
            "len = -x",
            "len = 'c'",
        ] {
            let tokens: TokenStream = bad.parse().unwrap();
            assert!(parse(tokens).is_err(), "{bad}");
        }
    }
}
