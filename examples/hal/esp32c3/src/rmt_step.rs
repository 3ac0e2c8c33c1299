//! Periods as the RMT's symbols: shared by `bin/rmt.rs`, which sends them
//! on an ESP32-C3, and by the host test that plays them back
//! (`tests/rmt.rs` of the `stepper-profiles` repository).
//!
//! An RMT symbol is a 32-bit word of two halves, each a level and a length
//! of 1 to 32 767 ticks of the channel's clock (a length of 0 ends the
//! transmission): bits 0-14 the first length, bit 15 its level, bits 16-30
//! the second length, bit 31 its level. A step of `period` ticks is the
//! pin high for `pulse` ticks, then low for the rest: one symbol while the
//! rest fits a half, else the rest spread over more low halves, two a
//! symbol, as evenly as whole ticks allow, so that every half holds at
//! least a tick and the symbols' lengths add up to the period exactly.

use stepper_profiles::period_table;

/// 400 steps from 200 Hz to 20 kHz, S-shaped, in ticks of the RMT's
/// 10 MHz (80 MHz over a divider of 8): the slowest, 50 000 ticks, takes
/// two symbols.
pub static RAMP: [u16; 400] = period_table!(
    curve = sigmoid,
    len = 400,
    fmin = 200,
    fmax = 20kHz,
    flexible = 8,
    timer_hz = 10MHz,
);

/// Ticks the step pin stays high: 2.5 µs.
pub const PULSE: u32 = 25;

/// The longest half, in ticks.
pub const MAX_LEN: u32 = 0x7FFF;

/// A symbol: `(level, length)` twice.
pub const fn symbol(first: (bool, u32), second: (bool, u32)) -> u32 {
    (first.1 & MAX_LEN)
        | (first.0 as u32) << 15
        | (second.1 & MAX_LEN) << 16
        | (second.0 as u32) << 31
}

/// Why a period has no symbols.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepError {
    /// The period is not longer than the pulse: no low time is left.
    TooShort { period: u32, pulse: u32 },
    /// The pulse does not fit a half: 32 767 ticks at most.
    PulseTooLong { pulse: u32 },
}

/// Hands `emit` the symbols of a step of `period` ticks, high for `pulse`
/// of them; returns how many.
pub fn step(period: u32, pulse: u32, mut emit: impl FnMut(u32)) -> Result<usize, StepError> {
    if pulse == 0 || pulse > MAX_LEN {
        return Err(StepError::PulseTooLong { pulse });
    }
    let Some(low) = period.checked_sub(pulse).filter(|&l| l > 0) else {
        return Err(StepError::TooShort { period, pulse });
    };
    // Low halves: one beside the pulse, then two a symbol, so an odd
    // number, as few as hold `low`. With more than one, `low` passes
    // `MAX_LEN`, so each of them holds at least a tick; none holds more
    // than `MAX_LEN`.
    let halves = low.div_ceil(MAX_LEN) | 1;
    let (q, r) = (low / halves, low % halves);
    // Half `k` holds `q`, or `q + 1` for the first `r`.
    let half = |k: u32| q + u32::from(k < r);
    emit(symbol((true, pulse), (false, half(0))));
    let mut k = 1;
    while k < halves {
        emit(symbol((false, half(k)), (false, half(k + 1))));
        k += 2;
    }
    Ok(1 + (halves as usize - 1) / 2)
}

/// The end of a transmission: a symbol of length 0, the pin low.
pub const END: u32 = 0;
