//! The foundation every layer stands on: keys and errors, the timer and the
//! modes, and the numerics (cancellation-free functions, the pulse-time
//! solver). Nothing here knows a curve.

pub(crate) mod error;
pub(crate) mod expf;
pub(crate) mod key;
pub(crate) mod math;
mod messages;
pub(crate) mod modes;
pub(crate) mod numbers;
pub(crate) mod solve;
pub(crate) mod timer;

/// The largest number of entries a table may have.
///
/// 65 536 entries are 128 KiB of `u16` flash, more than most microcontrollers
/// spend on one ramp; the limit keeps compile-time expansion bounded.
pub const MAX_LEN: u32 = 65_536;

/// The crate's unit tests' random numbers: xorshift64 from `state`
/// (not 0).
#[cfg(test)]
pub(crate) fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
    move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state
    }
}
