//! Compile-time stepper-motor period tables.
//!
//! Use these macros through the `stepper-profiles` crate, which re-exports them
//! with the run-time API of `profile-core`.
#![forbid(unsafe_code)]

mod args;
mod expand;
mod include;

/// Computes a period table at compile time and expands to an array expression.
///
/// ```
/// # extern crate profile_macros as stepper_profiles;
/// use stepper_profiles::period_table;
///
/// // Seed 000's orange curve, bit for bit as its C code computes it.
/// static PERIOD: [u16; 1000] = period_table!(
///     curve = sigmoid, len = 1000, fmin = 500, fmax = 64000, flexible = 8,
///     timer_hz = 10_000_000,
///     discretization = index, rounding = truncate, arithmetic = f32,
/// );
/// assert_eq!((PERIOD[0], PERIOD[999]), (19183, 156));
///
/// // The default mode: exact pulse times, diffused rounding.
/// const EXACT: [u16; 1000] = period_table!(
///     curve = sigmoid, len = 1000, fmin = 500, fmax = 64000, flexible = 8,
///     timer_hz = 10_000_000,
/// );
/// assert_eq!(EXACT.iter().map(|&p| p as u32).sum::<u32>(), 310_078);
/// ```
///
/// Keys (frequencies in Hz = steps/s):
///
/// | key | value | default |
/// | --- | --- | --- |
/// | `curve` | `sigmoid` | required |
/// | `len` | entries (steps), 1 to 65 536 | required |
/// | `fmin`, `fmax` | the curve's lower and upper frequency | required |
/// | `flexible` | sigmoid steepness, over 0 up to 500 | required |
/// | `timer_hz` | timer tick rate after the prescaler | required |
/// | `word` | `u16`, `u32` | `u16` |
/// | `ticks_per_step` | `1`, or `2` when each entry is a half period | `1` |
/// | `discretization` | `exact`, `left_endpoint`, `index` | `exact` |
/// | `rounding` | `truncate`, `nearest`, `diffuse` | `diffuse` |
/// | `arithmetic` | `f64`, `f32` (seed 000's C code, with `index`) | `f64` |
///
/// Integer literals are accepted where a number is expected. A frequency may
/// carry a unit, `Hz`, `kHz` or `MHz`, and a time `s`, `ms` or `us`, with or
/// without a space (`fmax = 64kHz`, `timer_hz = 10 MHz`, `tau = 5ms`): the
/// number is scaled in decimal, so `64kHz` gives the table of `64_000`. Any
/// other suffix, a type suffix such as `500u32` included, is an error. Every
/// mistake is a compile error at the offending key or value, saying what is
/// expected.
#[proc_macro]
pub fn period_table(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    expand::period_table(input.into()).into()
}

/// Declares one module per profile of a TOML file, at compile time.
///
/// The path is relative to the crate's `Cargo.toml` (`CARGO_MANIFEST_DIR`).
/// Each `[profiles.NAME]` becomes `pub mod NAME` with `PERIODS` (or
/// `SEGMENTS`), `LEN`, `TIMER_HZ`, `TICKS_PER_STEP`, `TOTAL_TICKS` and the
/// other figures as constants, documented with the profile's parameters.
/// Cargo rebuilds the crate when the file changes.
///
/// ```ignore
/// stepper_profiles::include_profiles!("profiles.toml");
///
/// fn first_period() -> u16 {
///     orange::PERIODS[0]
/// }
/// ```
///
/// A mistake in the file is a compile error on the path, reading
/// `profiles.toml:LINE:COL: message` with the line and a caret.
#[proc_macro]
pub fn include_profiles(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    include::include_profiles(input.into()).into()
}
