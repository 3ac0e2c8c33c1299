//! `period_table!`: arguments through `profile-core`'s pipeline and emitter.

use proc_macro2::TokenStream;
use profile_codegen::__private::emit;
use profile_codegen::__private::pipeline::{self, Options};
use profile_codegen::__private::schema::Diagnostic;

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
    let compiled = pipeline::compile(&args, &whole, Options::default()).map_err(to_error)?;
    Ok(emit::rust::table_expr(&compiled.table))
}

#[cfg(test)]
mod tests {
    //! Fuzzing of the macro's front door without nightly: random token
    //! streams through `period_table!`'s expansion, called through
    //! `proc_macro2`. It must return tokens (a table or `compile_error!`s),
    //! never panic. `FUZZ_CASES` sets the number of cases (default 5000),
    //! `FUZZ_STATE` the generator's first state (a number other than 0).

    use super::*;

    /// Names, values and punctuation besides the keys (which come from the schema's list of keys).
    const PIECES: &[&str] = &[
        "speed",
        "sigmoid",
        "exponential",
        "linear",
        "three_stage",
        "jerk_limited",
        "index",
        "exact",
        "left_endpoint",
        "truncate",
        "nearest",
        "diffuse",
        "f32",
        "f64",
        "integer",
        "u16",
        "u32",
        "=",
        "=",
        "=",
        ",",
        ",",
        ",",
        "-",
        "0",
        "1",
        "2",
        "3",
        "8",
        "120",
        "200",
        "500",
        "1000",
        "64000",
        "5000",
        "15000",
        "10_000_000",
        "1_000_000",
        "65537",
        "4294967296",
        "1e999",
        "0.5",
        "-500",
        "1e-300",
        "\"u32\"",
        "\"x\"",
        "'c'",
        "true",
        "(1)",
        "[2]",
        "{}",
        "::",
        ";",
        "#",
        "b\"x\"",
        "340282366920938463463374607431768211456",
        "(0, 0.4)",
        "[(0, 0.4), (1000, 0.3)]",
        "[(1000, 0.3), (0, 0.4)]",
        "[]",
    ];

    /// Every key, and two that are not keys.
    fn keys() -> Vec<&'static str> {
        profile_codegen::__private::schema::all_keys()
            .into_iter()
            .map(|k| k.name())
            .chain(["fmni", "speed"])
            .collect()
    }

    const VALUES: &[&str] = &[
        "sigmoid",
        "exponential",
        "linear",
        "three_stage",
        "jerk_limited",
        "index",
        "exact",
        "left_endpoint",
        "truncate",
        "nearest",
        "diffuse",
        "f32",
        "integer",
        "u16",
        "u32",
        "0",
        "1",
        "2",
        "3",
        "8",
        "100",
        "120",
        "200",
        "500",
        "1000",
        "5000",
        "15000",
        "64000",
        "1e999",
        "-500",
        "0.5",
        "2.5",
        "65537",
        "1e-300",
        "\"u32\"",
        "1.8",
        "5.4e-6",
        "[(0, 0.4), (1000, 0.3)]",
        "[(0, 0.4)]",
        "64kHz",
        "\"5 kHz\"",
        "\"5\tkHz\"",
        "0kHz",
        "1e999kHz",
        "500u32",
        "500Hz",
        "1.8deg",
        "\"1.8°\"",
        "68gcm2",
        "40Ncm",
        "0.5ohm",
        "2mH",
        "2800mA",
        "24V",
        "[(0, 40Ncm), (1kHz, 33Ncm)]",
        "[(\"0 Hz\", \"0.4 N·m\")]",
        "1e-320",
        "-0.0",
        "4294967296",
        "18446744073709551616",
    ];

    struct Rng(u64);

    impl Rng {
        fn below(&mut self, n: usize) -> usize {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) % n as u64) as usize
        }
    }

    #[test]
    fn random_token_streams_never_panic() {
        let n: usize = std::env::var("FUZZ_CASES")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(5000);
        let state = std::env::var("FUZZ_STATE")
            .ok()
            .and_then(|v| v.parse().ok());
        let mut rng = Rng(state.unwrap_or(0x5eed_0003));
        let keys = keys();
        let pieces: Vec<&str> = keys.iter().chain(PIECES).copied().collect();
        let (mut tables, mut errors) = (0, 0);
        for case in 0..n {
            let text = if case % 2 == 0 {
                let words: Vec<&str> = (0..rng.below(24))
                    .map(|_| pieces[rng.below(pieces.len())])
                    .collect();
                words.join(" ")
            } else {
                // A valid call with a few random edits (a value replaced, a
                // key dropped or added), to reach validation and generation.
                let mut pairs: Vec<(String, String)> = [
                    ("curve", "linear"),
                    ("fmin", "500"),
                    ("fmax", "5000"),
                    ("len", "200"),
                    ("timer_hz", "1_000_000"),
                ]
                .iter()
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect();
                for _ in 0..rng.below(4) {
                    let value = VALUES[rng.below(VALUES.len())].to_string();
                    match rng.below(3) {
                        0 => {
                            let i = rng.below(pairs.len().max(1));
                            if let Some(p) = pairs.get_mut(i) {
                                p.1 = value;
                            }
                        }
                        1 if !pairs.is_empty() => {
                            pairs.remove(rng.below(pairs.len()));
                        }
                        _ => pairs.push((keys[rng.below(keys.len())].to_string(), value)),
                    }
                }
                let pairs: Vec<String> = pairs.iter().map(|(k, v)| format!("{k} = {v}")).collect();
                pairs.join(", ")
            };
            let Ok(tokens) = text.parse::<TokenStream>() else {
                continue;
            };
            let out = std::panic::catch_unwind(|| period_table(tokens))
                .unwrap_or_else(|_| panic!("case {case}: expansion panicked on `{text}`"));
            if out.to_string().contains("compile_error") {
                errors += 1;
            } else {
                tables += 1;
            }
        }
        println!("fuzz: {n} token streams, {tables} tables, {errors} compile errors");
    }

    #[test]
    fn a_valid_call_expands_to_an_array() {
        let tokens: TokenStream =
            "curve = linear, fmin = 500, fmax = 5000, len = 3, timer_hz = 1_000_000"
                .parse()
                .unwrap();
        // a = (5000² - 500²) / (2 * 3) = 4.125e6 Hz/s; edges at
        // t(k) = 2k / (500 + sqrt(500² + 2 a k)) = 585.6, 870.9, 1090.9 µs,
        // rounded to 586, 871, 1091 ticks.
        assert_eq!(period_table(tokens).to_string(), "[586u16 , 285 , 220]");
    }
}
