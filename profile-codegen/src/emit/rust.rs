//! Rust: a table as an array expression, a profile as a module, as tokens.
//!
//! `period_table!` and `include_profiles!` return these tokens; the build
//! script writes the same tokens as text. Nothing is printed to be parsed
//! again.

use proc_macro2::{Ident, Literal, Span, TokenStream};
use quote::quote;
use std::format;
use std::string::String;
use std::vec::Vec;

use super::{Constant, Number, Profile, avoid_periods, constants, doc_lines};
use crate::numbers::Fixed;
use crate::table::computed::Generated;
use core::mem::size_of;
use profile_core::Word;
use profile_core::runs::{IndexedRun, RunIndex};

/// A period as a literal: the first of an array carries the word's suffix,
/// which gives the array its type.
fn period(word: Word, ticks: u32, first: bool) -> Literal {
    match (first, word) {
        (false, _) => Literal::u32_unsuffixed(ticks),
        (true, Word::U16) => Literal::u16_suffixed(ticks as u16),
        (true, Word::U32) => Literal::u32_suffixed(ticks),
    }
}

/// The word's type: `u16` or `u32`.
fn word_type(word: Word) -> Ident {
    Ident::new(word.name(), Span::call_site())
}

/// An array expression holding the table as it is stored (each period plus
/// `reload_offset`): `[19183u16, 18866, ...]`, `[(9533u16, 3u16), (4750,
/// 9), ...]` for a segment table, or `[[2u16, 2442u16, ...], [5, 1303,
/// ...], ...]` for runs (see [`runs`](profile_core::runs)).
pub fn table_expr(table: &Generated) -> TokenStream {
    let word = table.spec().timer.word;
    match table {
        Generated::Steps(t) => {
            let items = t
                .stored_periods()
                .into_iter()
                .enumerate()
                .map(|(i, p)| period(word, p, i == 0));
            quote!([#(#items),*])
        }
        Generated::Segments(t) => {
            let items = t.stored_pairs().into_iter().enumerate().map(|(i, (p, c))| {
                let (p, c) = (period(word, p, i == 0), period(word, c, i == 0));
                quote!((#p, #c))
            });
            quote!([#(#items),*])
        }
        Generated::Runs(t) => {
            let items = t.stored_runs().into_iter().enumerate().map(|(i, words)| {
                let w = words.map(|w| period(Word::U16, u32::from(w), i == 0));
                quote!([#(#w),*])
            });
            quote!([#(#items),*])
        }
    }
}

/// A constant's value as a literal of its type.
fn value(value: Number) -> (Ident, Literal) {
    let (ty, literal) = match value {
        Number::U8(v) => ("u8", Literal::u8_unsuffixed(v)),
        Number::I32(v) => ("i32", Literal::i32_unsuffixed(v)),
        Number::U32(v) => ("u32", Literal::u32_unsuffixed(v)),
        Number::U64(v) => ("u64", Literal::u64_unsuffixed(v)),
        Number::Usize(v) => ("usize", Literal::u64_unsuffixed(v)),
        Number::F64(v) => ("f64", Literal::f64_unsuffixed(v)),
    };
    (Ident::new(ty, Span::call_site()), literal)
}

/// A doc attribute's text: a space, as `///` writes it, then the line.
fn doc(line: &str) -> String {
    format!(" {line}")
}

/// The lines of `RUN_INDEX`'s docs that state its sizes, as the types have
/// them: a run indexed, the buckets and what an index holds besides, and a
/// run of `RUNS`.
fn run_index_sizes() -> [String; 3] {
    let (indexed, buckets, run) = (
        size_of::<IndexedRun>(),
        size_of::<RunIndex<0>>(),
        size_of::<[u16; 5]>(),
    );
    [
        format!(
            " them and plans its moves finding a step's run by its bucket of steps ({indexed} bytes of"
        ),
        format!(
            " flash a run and {buckets} for the buckets, in place of `RUNS`' {run} a run when `RUNS` is"
        ),
        String::from(" not played itself)."),
    ]
}

/// A module named after the profile, holding the table and its figures,
/// documented with its parameters.
pub fn module(profile: &Profile) -> TokenStream {
    let spec = profile.table.spec();
    let word = spec.timer.word;
    let mut docs = std::vec![
        doc(&format!(
            "Profile `{}` ({}).",
            profile.name,
            spec.curve.name()
        )),
        String::new(),
    ];
    docs.extend(doc_lines(&profile.table).iter().map(|l| doc(l)));
    if let Some(t) = &profile.torque {
        docs.push(String::new());
        docs.push(doc(&format!(
            "Motor: the smallest torque margin is {} N·m at step {} ({} Hz): {} N·m \
             needed of {} N·m available.",
            Fixed(t.min_margin_nm, 4),
            t.step,
            Fixed(t.hz, 1),
            Fixed(t.needed_nm, 4),
            Fixed(t.available_nm, 4)
        )));
    }
    let name = Ident::new(&profile.name, Span::call_site());
    let ty = word_type(word);
    let array = table_expr(&profile.table);
    let table = match &profile.table {
        Generated::Steps(t) => {
            let len = Literal::usize_unsuffixed(t.periods.len());
            quote! {
                #[doc = " Timer periods, one per step, in ticks of `TIMER_HZ`, each plus `RELOAD_OFFSET`."]
                pub static PERIODS: [#ty; #len] = #array;
            }
        }
        Generated::Segments(t) => {
            let len = Literal::usize_unsuffixed(t.pairs.len());
            quote! {
                #[doc = " `(period in ticks plus `RELOAD_OFFSET`, steps)` per equal-time segment."]
                pub static SEGMENTS: [(#ty, #ty); #len] = #array;
            }
        }
        Generated::Runs(t) => {
            let len = Literal::usize_unsuffixed(t.runs.len());
            let sizes = run_index_sizes();
            quote! {
                #[doc = " Runs of fixed-point periods, `[count, interval_hi, interval_lo, add_hi, add_lo]`:"]
                #[doc = " play them with `runs::Expand` (see the `runs` module); each period plus `RELOAD_OFFSET`."]
                pub static RUNS: [[u16; 5]; #len] = #array;
                #[doc = " `RUNS` with where each run begins: `Player::new(&RUN_INDEX)` plays"]
                #(#[doc = #sizes])*
                pub static RUN_INDEX: ::stepper_profiles::runs::RunIndex<#len> =
                    ::stepper_profiles::runs::RunIndex::new(&RUNS);
            }
        }
    };
    // The table with its rate as a type and its offset, for `player::Timed`.
    let hz = Literal::u32_unsuffixed(spec.timer.timer_hz);
    let (array_name, ramp) = match &profile.table {
        Generated::Steps(_) => (quote!(PERIODS), quote!(steps)),
        Generated::Segments(_) => (quote!(SEGMENTS), quote!(segments)),
        Generated::Runs(_) => (quote!(RUNS), quote!(runs)),
    };
    let rated = quote! {
        #[doc = " The table as a ramp of a timer of `TIMER_HZ` ticks per second, as a type, storing each"]
        #[doc = " period plus `RELOAD_OFFSET`: `player::Timed::new(RAMP)` hands out durations of that timer."]
        pub const RAMP: ::stepper_profiles::player::Rated<'static, #ty, #hz> =
            ::stepper_profiles::player::Rated::new(
                ::stepper_profiles::player::Ramp::#ramp(&#array_name),
                RELOAD_OFFSET
            );
    };
    let constants = constants(profile).into_iter().map(|c: Constant| {
        let name = Ident::new(c.name, Span::call_site());
        let (ty, literal) = value(c.value);
        let doc = doc(c.doc);
        quote! {
            #[doc = #doc]
            pub const #name: #ty = #literal;
        }
    });
    let avoid = avoid(profile);
    let stop_steps = stop_steps(profile);
    // Unused figures are no reason for warnings in the user's crate.
    quote! {
        #(#[doc = #docs])*
        #[allow(dead_code)]
        pub mod #name {
            #table
            #(#constants)*
            #stop_steps
            #avoid
            #rated
        }
    }
}

/// A profile's bands as the periods that play in them (`AVOID`), when it
/// names bands.
fn avoid(profile: &Profile) -> Option<TokenStream> {
    let pairs = avoid_periods(profile)?;
    let len = Literal::usize_unsuffixed(pairs.len());
    let pairs = pairs.iter().map(|&(shortest, longest)| {
        let (shortest, longest) = (
            Literal::u32_unsuffixed(shortest),
            Literal::u32_unsuffixed(longest),
        );
        quote!((#shortest, #longest))
    });
    Some(quote! {
        #[doc = " The bands of `avoid` as the periods that play in them, `(shortest, longest)` in ticks"]
        #[doc = " plus `RELOAD_OFFSET`, inclusive: `Player::new(..).avoiding(&AVOID)` keeps a cruise out."]
        pub static AVOID: [(u32, u32); #len] = [#(#pairs),*];
    })
}

/// The steps an abort plays after each step of the table (`STOP_STEPS`),
/// when the profile names an emergency ramp.
fn stop_steps(profile: &Profile) -> Option<TokenStream> {
    let emergency = profile.emergency.as_ref()?;
    let steps = &emergency.stop_steps;
    let len = Literal::usize_unsuffixed(steps.len());
    let wide = steps.iter().any(|&s| s > u32::from(u16::MAX));
    let (ty, items) = match wide {
        false => (
            quote!(u16),
            steps
                .iter()
                .map(|&s| Literal::u16_unsuffixed(s as u16))
                .collect::<Vec<_>>(),
        ),
        true => (
            quote!(u32),
            steps.iter().map(|&s| Literal::u32_unsuffixed(s)).collect(),
        ),
    };
    let first = std::format!(
        " Steps an abort along `{}` plays after each step of the table: `Player::abort` on a",
        emergency.profile
    );
    let second = std::format!(
        " player made with `.with_emergency(..)` of `{}`'s table enters it at its last entry not",
        emergency.profile
    );
    Some(quote! {
        #[doc = #first]
        #[doc = #second]
        #[doc = " shorter than the step's period and plays down to rest (0: the motor stops at once)."]
        pub static STOP_STEPS: [#ty; #len] = [#(#items),*];
    })
}

/// One module per profile.
pub fn modules(profiles: &[Profile]) -> TokenStream {
    let modules: Vec<TokenStream> = profiles.iter().map(module).collect();
    quote!(#(#modules)*)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_literal_is_suffixed() {
        use std::string::ToString;
        let lits = |word, ps: &[u32]| -> String {
            let items = ps.iter().enumerate().map(|(i, &p)| period(word, p, i == 0));
            quote!([#(#items),*]).to_string()
        };
        assert_eq!(lits(Word::U16, &[3, 2, 1]), "[3u16 , 2 , 1]");
        assert_eq!(lits(Word::U32, &[70000]), "[70000u32]");
    }
}
