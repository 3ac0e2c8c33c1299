//! `key = value, ...` into the shared argument schema of `profile-core`.
//!
//! Locations are the offending tokens themselves, so an error can cover a
//! whole `-500` (a `Span` cannot be joined on stable Rust).

use proc_macro2::TokenStream;
use profile_codegen::__private::schema::units::{self, Quantity};
use profile_codegen::__private::schema::{self, Arg, MAX_DIGITS, Value};
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
        let (value, value_loc, parts) = parse_value(input, &key)?;
        if !input.is_empty() && !input.peek(Token![,]) {
            return Err(input.error(format!(
                "expected `,` after the value of `{key}`: a value is one literal or name, \
                 expressions are not evaluated"
            )));
        }
        Ok(Pair(Arg {
            key: key.to_string(),
            key_loc: key.into_token_stream(),
            value,
            value_loc,
            parts,
        }))
    }
}

/// A value, where it is, and where each of its elements is (a list's).
fn parse_value(input: ParseStream, key: &Ident) -> syn::Result<(Value, Loc, Vec<Loc>)> {
    if input.peek(syn::token::Bracket) && units::pair(&key.to_string()).is_some() {
        return parse_points(input, key);
    }
    let (value, loc) = parse_scalar(input, key)?;
    Ok((value, loc, Vec::new()))
}

fn parse_scalar(input: ParseStream, key: &Ident) -> syn::Result<(Value, Loc)> {
    let expected = || format!("`{key}` expects a number or a name");
    if input.peek(Ident) {
        let ident: Ident = input.parse()?;
        return Ok((Value::Name(ident.to_string()), ident.into_token_stream()));
    }
    if input.peek(syn::token::Bracket) {
        let group: proc_macro2::Group = input.parse()?;
        return Err(syn::Error::new_spanned(
            group,
            format!("{}, not a list (only `torque_curve` takes one)", expected()),
        ));
    }
    let minus: Option<Token![-]> = input.parse()?;
    if minus.is_some() && input.peek(Token![-]) {
        return Err(input.error(format!("`{key}` expects a number after `-`")));
    }
    // A literal token, never `syn::Lit`'s parse, which would take a second
    // `-` as part of the number.
    let lit = input
        .step(|cursor| match cursor.literal() {
            Some((lit, rest)) => Ok((lit, rest)),
            None => Err(cursor.error("not a literal")),
        })
        .map_err(|e| syn::Error::new(e.span(), expected()))?;
    let mut loc = minus.to_token_stream();
    lit.to_tokens(&mut loc);
    let sign = if minus.is_some() { "-" } else { "" };
    let written = format!("{sign}{lit}");
    let negative = minus.is_some();
    let (text, suffix) = match Lit::new(lit) {
        Lit::Int(i) => (i.base10_digits().to_string(), i.suffix().to_string()),
        Lit::Float(f) => (f.base10_digits().to_string(), f.suffix().to_string()),
        Lit::Str(s) if !negative => return Ok((Value::Name(s.value()), loc)),
        _ => return Err(syn::Error::new_spanned(loc, expected())),
    };
    digits(key, &text, &loc)?;
    let number = if negative {
        format!("-{text}")
    } else {
        text.clone()
    };
    if !suffix.is_empty() {
        return Ok((quantity(number, &suffix, written), loc));
    }
    // A unit after a space, `64 kHz`, reads as `64kHz`; a name followed by
    // `=` is the next key, its comma forgotten.
    if input.peek(Ident) && input.peek2(Token![=]) {
        let next: Ident = input.fork().parse()?;
        return Err(syn::Error::new(
            next.span(),
            format!("expected `,` between the value of `{key}` and the next key, `{next}`"),
        ));
    }
    if input.peek(Ident) {
        let unit: Ident = input.parse()?;
        unit.to_tokens(&mut loc);
        let written = format!("{written} {unit}");
        return Ok((quantity(number, &unit.to_string(), written), loc));
    }
    let integer = text.bytes().all(|b| b.is_ascii_digit());
    let value = match text.parse::<i128>() {
        Ok(v) if integer => Value::Int(if negative { -v } else { v }),
        _ => Value::Float(float(key, &text, negative, &loc)?),
    };
    Ok((value, loc))
}

/// A number with a unit or a suffix, which the schema reads for its key;
/// `written` as the source has it, for messages.
fn quantity(number: String, unit: &str, written: String) -> Value {
    Value::Quantity {
        number,
        unit: unit.to_string(),
        written,
    }
}

/// Refuses a literal of more than [`MAX_DIGITS`] digits.
fn digits(key: &Ident, text: &str, loc: &Loc) -> syn::Result<()> {
    let count = text.chars().filter(char::is_ascii_digit).count();
    if count > MAX_DIGITS {
        Err(syn::Error::new_spanned(
            loc,
            schema::too_many_digits(&key.to_string(), count),
        ))
    } else {
        Ok(())
    }
}

/// A decimal literal's digits as a finite `f64`.
fn float(key: &Ident, text: &str, negative: bool, loc: &Loc) -> syn::Result<f64> {
    let v: f64 = text
        .parse()
        .map_err(|_| syn::Error::new_spanned(loc, format!("`{key}` expects a number")))?;
    if !v.is_finite() {
        return Err(syn::Error::new_spanned(
            loc,
            format!("`{key}` is too large for a 64-bit float (at most about 1.8e308)"),
        ));
    }
    Ok(if negative { -v } else { v })
}

/// Number pairs, and where each is.
type Located = (Vec<(f64, f64)>, Vec<Loc>);

/// `[(x, y), ...]`: a list of number pairs, such as a torque curve, and
/// where each pair is.
fn parse_points(input: ParseStream, key: &Ident) -> syn::Result<(Value, Loc, Vec<Loc>)> {
    let group: proc_macro2::Group = input.parse()?;
    let loc = group.to_token_stream();
    let expected =
        || format!("`{key}` expects a list of number pairs, such as `[(0, 0.4), (1000, 0.3)]`");
    let name = key.to_string();
    let (qx, qy) = units::pair(&name).unwrap_or((Quantity::Frequency, Quantity::Torque));
    let pair = |inner: ParseStream| -> syn::Result<(f64, f64)> {
        let x = number(inner, &name, qx)?;
        inner.parse::<Token![,]>()?;
        let y = number(inner, &name, qy)?;
        let _: Option<Token![,]> = inner.parse()?;
        if !inner.is_empty() {
            return Err(inner.error("expected a pair"));
        }
        Ok((x, y))
    };
    let pairs = |content: ParseStream| -> syn::Result<Located> {
        let (mut points, mut parts) = (Vec::new(), Vec::new());
        while !content.is_empty() {
            let inner: proc_macro2::Group = content.parse()?;
            if inner.delimiter() != proc_macro2::Delimiter::Parenthesis {
                return Err(syn::Error::new_spanned(&inner, "expected a pair"));
            }
            points.push(pair.parse2(inner.stream())?);
            parts.push(inner.to_token_stream());
            if content.is_empty() {
                break;
            }
            content.parse::<Token![,]>()?;
        }
        Ok((points, parts))
    };
    let (points, parts) = pairs.parse2(group.stream()).map_err(|e| {
        // A unit's error names the key and stands at the literal; any
        // other mistake is the list's.
        if e.to_string().starts_with(&format!("`{key}`")) {
            e
        } else {
            syn::Error::new_spanned(&loc, expected())
        }
    })?;
    Ok((Value::Points(points), loc, parts))
}

/// A number literal, possibly negative, as `f64`, in the base unit of `q`
/// (a frequency or a torque), which it may carry, with or without a space
/// (`1kHz`, `40 Ncm`), or a string of both, as in a profiles file
/// (`"40 N·cm"`). A word or a literal that is no number is an error at it.
fn number(input: ParseStream, key: &str, q: Quantity) -> syn::Result<f64> {
    if input.peek(Ident) {
        let word: Ident = input.parse()?;
        return Err(syn::Error::new(
            word.span(),
            units::not_a_point(key, q, &format!("`{word}`")),
        ));
    }
    let minus: Option<Token![-]> = input.parse()?;
    let sign = if minus.is_some() { "-" } else { "" };
    let lit = input.step(|cursor| match cursor.literal() {
        Some((lit, rest)) => Ok((lit, rest)),
        None => Err(cursor.error("expected a number")),
    })?;
    let mut loc = minus.to_token_stream();
    lit.to_tokens(&mut loc);
    let (text, suffix) = match Lit::new(lit.clone()) {
        Lit::Int(i) => (i.base10_digits().to_string(), i.suffix().to_string()),
        Lit::Float(f) => (f.base10_digits().to_string(), f.suffix().to_string()),
        Lit::Str(s) if minus.is_none() => return quoted_point(key, q, &s, loc),
        _ => {
            let got = format!("`{sign}{lit}`");
            return Err(syn::Error::new_spanned(
                loc,
                units::not_a_point(key, q, &got),
            ));
        }
    };
    let count = text.chars().filter(char::is_ascii_digit).count();
    if count > MAX_DIGITS {
        let message = schema::too_many_digits(key, count);
        return Err(syn::Error::new_spanned(loc, message));
    }
    let number = format!("{sign}{text}");
    let (unit, written) = if !suffix.is_empty() {
        (suffix.clone(), format!("{number}{suffix}"))
    } else if input.peek(Ident) {
        let unit: Ident = input.parse()?;
        unit.to_tokens(&mut loc);
        (unit.to_string(), format!("{number} {unit}"))
    } else {
        (q.units()[0].0.to_string(), number.clone())
    };
    units::curve_point(key, q, &number, &unit, &written)
        .map_err(|m| syn::Error::new_spanned(loc, m))
}

/// A torque curve's frequency or torque written as a string with its unit,
/// `"1 kHz"`, `"40 N·cm"`, read as a profiles file reads it.
fn quoted_point(key: &str, q: Quantity, s: &syn::LitStr, loc: Loc) -> syn::Result<f64> {
    let text = s.value();
    let point = match units::split(&text) {
        Some((number, unit)) => {
            units::curve_point(key, q, &number.replace('_', ""), unit, text.trim())
        }
        None => Err(units::not_a_point(key, q, &format!("`{}`", s.token()))),
    };
    point.map_err(|m| syn::Error::new_spanned(loc, m))
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
        let curve = parse(quote::quote!(torque_curve = [(0.5kHz, 0.4), (2MHz, 0.1)])).unwrap();
        assert_eq!(
            curve[0].value,
            Value::Points(vec![(500.0, 0.4), (2e6, 0.1)])
        );
        // Units after a space, and on the torques.
        let curve = parse(quote::quote!(
            torque_curve = [(0.5 kHz, 40Ncm), (2 MHz, 100 mNm), (3MHz, 0.05 Nm)]
        ))
        .unwrap();
        assert_eq!(
            curve[0].value,
            Value::Points(vec![(500.0, 0.4), (2e6, 0.1), (3e6, 0.05)])
        );
        let units = parse(quote::quote!(
            fmax = 64_000Hz, tau = 5 ms, fmin = -1.5e3Hz, len = 10u32, fmax = 10 khz
        ))
        .unwrap();
        let quantity = |n: &str, u: &str, w: &str| Value::Quantity {
            number: n.into(),
            unit: u.into(),
            written: w.into(),
        };
        let values: Vec<_> = units.iter().map(|a| a.value.clone()).collect();
        assert_eq!(
            values,
            vec![
                quantity("64000", "Hz", "64_000Hz"),
                quantity("5", "ms", "5 ms"),
                quantity("-1.5e3", "Hz", "-1.5e3Hz"),
                quantity("10", "u32", "10u32"),
                quantity("10", "khz", "10 khz"),
            ]
        );
        assert_eq!(units[1].value_loc.to_string(), "5 ms");
        assert!(parse(quote::quote!(torque_curve = [0, 0.4])).is_err());
        // A string with a unit, as in a profiles file.
        let curve = parse(quote::quote!(
            torque_curve = [(0, "40 N·cm"), ("1 kHz", 0.3)]
        ))
        .unwrap();
        assert_eq!(
            curve[0].value,
            Value::Points(vec![(0.0, 0.4), (1000.0, 0.3)])
        );
        assert_eq!(curve[0].parts.len(), 2);
    }

    #[test]
    fn syntax_errors_say_what_is_expected() {
        for (bad, message) in [
            ("curve", "expected `=` after `curve`"),
            ("curve =", "`curve` expects a number or a name"),
            ("= 5", "expected a key, as in `len = 1000`"),
            (
                "len = 5 6",
                "expected `,` after the value of `len`: a value is one literal or name, \
                 expressions are not evaluated",
            ),
            (
                "len = 1000 fmin = 500",
                "expected `,` between the value of `len` and the next key, `fmin`",
            ),
            (
                "len = 100 + 100",
                "expected `,` after the value of `len`: a value is one literal or name, \
                 expressions are not evaluated",
            ),
            ("fmin = --500", "`fmin` expects a number after `-`"),
            (
                "torque_curve = [(1kHz2, 0.4)]",
                "`torque_curve` frequencies accept the units `Hz`, `kHz`, `MHz` (got `1kHz2`); \
                 did you mean `kHz`?",
            ),
            (
                "torque_curve = [(1, 0.4 A)]",
                "`torque_curve` torques accept the units `Nm` (`N·m`), `Ncm` (`N·cm`), `mNm` (`mN·m`) \
                 (got `0.4 A`)",
            ),
            (
                "torque_curve = [(1, 0.4, Nm)]",
                "`torque_curve` expects a list of number pairs, such as `[(0, 0.4), (1000, 0.3)]`",
            ),
            (
                "torque_curve = [(0, 0.4), (\"fast\", 0.3)]",
                "`torque_curve` frequencies are numbers, with or without a unit (`1000`, \
                 `\"1 kHz\"`), got `\"fast\"`",
            ),
            (
                "torque_curve = [(0, 0.4), (1000, inf)]",
                "`torque_curve` torques are numbers, with or without a unit (`0.4`, \
                 `\"40 N·cm\"`), got `inf`",
            ),
            (
                "torque_curve = [(0, 0.4), (12345678901234567890123456789012345678901234, 0.3)]",
                "`torque_curve` has a number of 44 digits, more than the 40 any key takes: write \
                 it with an exponent, as in `1.5e9`",
            ),
            (
                "fmax = 1e999",
                "`fmax` is too large for a 64-bit float (at most about 1.8e308)",
            ),
            (
                "resistance = [1, 2]",
                "`resistance` expects a number or a name, not a list (only `torque_curve` \
                 takes one)",
            ),
            (
                "fmin = [(0, 1)]",
                "`fmin` expects a number or a name, not a list (only `torque_curve` takes one)",
            ),
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
        let long = format!("fmax = 1{}", "0".repeat(300));
        let err = parse(long.parse().unwrap()).expect_err("a 301-digit literal");
        assert_eq!(
            err.to_string(),
            "`fmax` has a number of 301 digits, more than the 40 any key takes: write it with \
             an exponent, as in `1.5e9`"
        );
    }
}
