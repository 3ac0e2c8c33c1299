//! `key = value, ...` into the shared argument schema of `profile-core`.
//!
//! Locations are the offending tokens themselves, so an error can cover a
//! whole `-500` (a `Span` cannot be joined on stable Rust).

use proc_macro2::TokenStream;
use profile_core::params::{Arg, Value};
use quote::ToTokens;
use syn::parse::{Parse, ParseStream, Parser};
use syn::punctuated::Punctuated;
use syn::{Ident, Lit, Token};

/// Where an argument is: the tokens to underline. Empty means the whole call.
pub(crate) type Loc = TokenStream;

struct Pair(Arg<Loc>);

impl Parse for Pair {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let key: Ident = input
            .parse()
            .map_err(|e| syn::Error::new(e.span(), "expected a key, as in `len = 1000`"))?;
        input
            .parse::<Token![=]>()
            .map_err(|e| syn::Error::new(e.span(), format!("expected `=` after `{key}`")))?;
        let (value, value_loc) = parse_value(input, &key)?;
        Ok(Pair(Arg {
            key: key.to_string(),
            key_loc: key.into_token_stream(),
            value,
            value_loc,
        }))
    }
}

fn parse_value(input: ParseStream, key: &Ident) -> syn::Result<(Value, Loc)> {
    let expected = || format!("`{key}` expects a number or a name");
    if input.peek(Ident) {
        let ident: Ident = input.parse()?;
        return Ok((Value::Name(ident.to_string()), ident.into_token_stream()));
    }
    if input.peek(syn::token::Bracket) {
        return parse_points(input, key);
    }
    let minus: Option<Token![-]> = input.parse()?;
    let lit: Lit = input
        .parse()
        .map_err(|e| syn::Error::new(e.span(), expected()))?;
    let mut loc = minus.to_token_stream();
    lit.to_tokens(&mut loc);
    let sign = if minus.is_some() { -1 } else { 1 };
    let value = match &lit {
        Lit::Int(i) => Value::Int(sign * i.base10_parse::<i128>()?),
        Lit::Float(f) => Value::Float(sign as f64 * f.base10_parse::<f64>()?),
        Lit::Str(s) if minus.is_none() => Value::Name(s.value()),
        _ => return Err(syn::Error::new_spanned(loc, expected())),
    };
    Ok((value, loc))
}

/// `[(x, y), ...]`: a list of number pairs, such as a torque curve.
fn parse_points(input: ParseStream, key: &Ident) -> syn::Result<(Value, Loc)> {
    let group: proc_macro2::Group = input.parse()?;
    let loc = group.to_token_stream();
    let expected =
        || format!("`{key}` expects a list of number pairs, such as `[(0, 0.4), (1000, 0.3)]`");
    let pairs = |content: ParseStream| -> syn::Result<Vec<(f64, f64)>> {
        let mut points = Vec::new();
        while !content.is_empty() {
            let inner;
            syn::parenthesized!(inner in content);
            let x = number(&inner)?;
            inner.parse::<Token![,]>()?;
            let y = number(&inner)?;
            let _: Option<Token![,]> = inner.parse()?;
            if !inner.is_empty() {
                return Err(inner.error("expected a pair"));
            }
            points.push((x, y));
            if content.is_empty() {
                break;
            }
            content.parse::<Token![,]>()?;
        }
        Ok(points)
    };
    let points = pairs
        .parse2(group.stream())
        .map_err(|_| syn::Error::new_spanned(&loc, expected()))?;
    Ok((Value::Points(points), loc))
}

/// A number literal, possibly negative, as `f64`.
fn number(input: ParseStream) -> syn::Result<f64> {
    let minus: Option<Token![-]> = input.parse()?;
    let sign = if minus.is_some() { -1.0 } else { 1.0 };
    let value = match input.parse::<Lit>()? {
        Lit::Int(i) => i.base10_parse::<f64>()?,
        Lit::Float(f) => f.base10_parse::<f64>()?,
        other => return Err(syn::Error::new(other.span(), "expected a number")),
    };
    Ok(sign * value)
}

/// Parses the macro's input into arguments, or a syntax error.
pub(crate) fn parse(input: TokenStream) -> syn::Result<Vec<Arg<Loc>>> {
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
        assert_eq!(args[1].value_loc.to_string(), "- 5");
        let curve = parse(quote::quote!(torque_curve = [(0, 0.4), (1000, -1e1),])).unwrap();
        assert_eq!(
            curve[0].value,
            Value::Points(vec![(0.0, 0.4), (1000.0, -10.0)])
        );
        assert!(parse(quote::quote!(torque_curve = [(0, 0.4, 1)])).is_err());
        assert!(parse(quote::quote!(torque_curve = [0, 0.4])).is_err());
    }

    #[test]
    fn syntax_errors_say_what_is_expected() {
        for (bad, message) in [
            ("curve", "expected `=` after `curve`"),
            ("curve =", "`curve` expects a number or a name"),
            ("= 5", "expected a key, as in `len = 1000`"),
            ("len = 5 6", "expected `,`"),
            ("len = true", "`len` expects a number or a name"),
            ("len = -x", "`len` expects a number or a name"),
            ("len = 'c'", "`len` expects a number or a name"),
            ("len = -\"x\"", "`len` expects a number or a name"),
        ] {
            let tokens: TokenStream = bad.parse().unwrap();
            let err = parse(tokens)
                .err()
                .unwrap_or_else(|| panic!("`{bad}` parsed"));
            assert_eq!(err.to_string(), message, "{bad}");
        }
    }
}
