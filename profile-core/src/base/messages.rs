//! The messages of `Error`'s longer variants, one function each, by
//! theme: a parameter's value, the ramp's length and layouts, the table's
//! entries and words. `Error`'s `Display` names every variant and calls
//! these (`base/error.rs`).

use core::fmt;

use super::key::Key;
use super::modes::Discretization;
use super::numbers::{Fixed, Hundredths, Num, Significant};
use super::timer::Word;

// A parameter's value.

/// `Error::NotPositive`'s message: a subnormal is positive but refused.
pub(super) fn not_positive(f: &mut fmt::Formatter<'_>, key: Key, value: f64) -> fmt::Result {
    if value > 0.0 {
        write!(
            f,
            "`{key}` must be at least 2.2250738585072014e-308, the smallest normal float \
             (got {})",
            Num(value)
        )
    } else {
        write!(f, "`{key}` must be greater than 0 (got {})", Num(value))
    }
}

/// `Error::NotGreater`'s and `Error::NotAtLeast`'s message: `key` must be
/// `relation` `other`, and was `shown` it.
pub(super) fn compared(
    f: &mut fmt::Formatter<'_>,
    (key, value): (Key, f64),
    relation: &str,
    shown: &str,
    (other, other_value): (Key, f64),
) -> fmt::Result {
    write!(
        f,
        "`{key}` must be {relation} `{other}` (got {} {shown} {})",
        Num(value),
        Num(other_value)
    )
}

/// `Error::TooSmall`'s message.
pub(super) fn too_small(
    f: &mut fmt::Formatter<'_>,
    key: Key,
    value: f64,
    min: f64,
    why: &str,
) -> fmt::Result {
    write!(
        f,
        "`{key}` must be greater than {}{why} (got {})",
        Significant(min),
        Num(value)
    )
}

/// `Error::NotWhole`'s message.
pub(super) fn not_whole(f: &mut fmt::Formatter<'_>, key: Key, value: f64) -> fmt::Result {
    write!(
        f,
        "`{key}` must be a whole number with `arithmetic = integer` (got {})",
        Num(value)
    )
}

/// `Error::IntegerOverflow`'s message.
pub(super) fn integer_overflow(
    f: &mut fmt::Formatter<'_>,
    key: Key,
    expression: &str,
    value: u128,
    max: u64,
) -> fmt::Result {
    write!(
        f,
        "`{key}` overflows the integer `pulse()` code: `{expression}` is {value}, more than {max}"
    )
}

// The ramp's length and its layouts.

/// `Error::RampTooLong`'s message: the length in exponent form beyond
/// 1e16 steps, and said so where it is no length at all.
pub(super) fn ramp_too_long(
    f: &mut fmt::Formatter<'_>,
    key: Key,
    steps: f64,
    max: u32,
) -> fmt::Result {
    if steps == f64::INFINITY {
        write!(
            f,
            "`{key}` makes the ramp longer than a float counts (1.8e308 steps); at most {max} \
             are allowed"
        )
    } else if steps.is_nan() || steps <= 0.0 {
        write!(
            f,
            "`{key}` gives the ramp no length in steps (got {steps}); from 1 to {max} are allowed"
        )
    } else {
        write!(
            f,
            "`{key}` makes the ramp {} steps long; at most {max} are allowed",
            Num(libm::round(steps))
        )
    }
}

/// `Error::EmptySegment`'s message.
pub(super) fn empty_segment(f: &mut fmt::Formatter<'_>, index: u32, steps: u32) -> fmt::Result {
    write!(
        f,
        "segment {index} holds no step of the {steps}-step ramp; use fewer `segments`"
    )
}

/// `Error::SegmentTooLong`'s message.
pub(super) fn segment_too_long(
    f: &mut fmt::Formatter<'_>,
    index: u32,
    count: u32,
    word: Word,
) -> fmt::Result {
    write!(
        f,
        "segment {index} holds {count} steps, more than a `word = {}` count holds ({}); \
         use more `segments`",
        word.name(),
        word.max()
    )
}

/// `Error::SegmentsNeedTime`'s message.
pub(super) fn segments_need_time(
    f: &mut fmt::Formatter<'_>,
    discretization: Discretization,
) -> fmt::Result {
    write!(
        f,
        "`segments` cuts the curve into equal-time pieces and needs `discretization = exact` (got `{}`)",
        discretization.name()
    )
}

/// `Error::CompressTooSmall`'s message: with `ticks_per_step = 2` the
/// bound is a whole tick.
pub(super) fn compress_too_small(
    f: &mut fmt::Formatter<'_>,
    value: f64,
    ticks_per_step: u8,
) -> fmt::Result {
    if ticks_per_step == 2 {
        write!(
            f,
            "`compress` is the largest step-edge error allowed, in timer ticks, and must be \
             at least 1 with `ticks_per_step = 2`: each entry is played twice, so step edges \
             fall on every other tick (got {})",
            Num(value)
        )
    } else {
        write!(
            f,
            "`compress` is the largest pulse-edge error allowed, in ticks, and must be at \
             least 0.5: a whole tick cannot land nearer to every edge (got {})",
            Num(value)
        )
    }
}

/// `Error::CompressTooLarge`'s message.
pub(super) fn compress_too_large(f: &mut fmt::Formatter<'_>, value: f64) -> fmt::Result {
    write!(
        f,
        "`compress` is the largest pulse-edge error allowed, in ticks, and must be at \
         most 65535, the longest period a run's 16-bit word holds (got {})",
        Num(value)
    )
}

/// `Error::CompressUnreachable`'s message.
pub(super) fn compress_unreachable(
    f: &mut fmt::Formatter<'_>,
    step: u32,
    tolerance: f64,
) -> fmt::Result {
    write!(
        f,
        "no run of 16-bit periods keeps pulse edge {step} within {} ticks of the \
         curve; raise `compress`",
        Num(tolerance)
    )
}

// The table's entries and its word.

/// `Error::ReloadOffsetRange`'s message.
pub(super) fn reload_offset_range(
    f: &mut fmt::Formatter<'_>,
    offset: i32,
    word: Word,
) -> fmt::Result {
    write!(
        f,
        "`reload_offset` must be from -{max} to {max} with `word = {}`: a period of 1 to \
         {} ticks plus the offset must fit the word (got {offset})",
        word.name(),
        word.max(),
        max = word.max() - 1,
    )
}

/// `Error::ReloadOffset`'s message: `what` `index` of `ticks` ticks.
pub(super) fn reload_offset(
    f: &mut fmt::Formatter<'_>,
    (what, index, ticks): (&str, u32, u32),
    offset: i32,
    word: Word,
) -> fmt::Result {
    write!(
        f,
        "`reload_offset = {offset}` makes {what} {index} ({ticks} tick{}) {}: a stored \
         value, the period plus the offset, must be from 1 to {} (`word = {}`)",
        if ticks == 1 { "" } else { "s" },
        i64::from(ticks) + i64::from(offset),
        word.max(),
        word.name()
    )
}

/// `Error::PeriodOverflow`'s message: entry `index` of `ticks` ticks.
pub(super) fn period_overflow(
    f: &mut fmt::Formatter<'_>,
    (index, ticks): (u32, f64),
    word: Word,
    timer_hz: u32,
    lowest_hz: f64,
) -> fmt::Result {
    write!(
        f,
        "entry {index} is {} ticks, more than `word = {}` holds ({}); \
         at `timer_hz = {timer_hz}` the lowest step frequency that fits is {} Hz",
        Num(libm::round(ticks)),
        word.name(),
        word.max(),
        Hundredths(lowest_hz),
    )
}

/// `Error::PeriodZero`'s message.
pub(super) fn period_zero(f: &mut fmt::Formatter<'_>, index: u32, highest_hz: f64) -> fmt::Result {
    write!(
        f,
        "entry {index} rounds to 0 ticks; the timer resolves step frequencies up to {} Hz",
        Fixed(highest_hz, 0)
    )
}

/// `Error::WordMismatch`'s message.
pub(super) fn word_mismatch(f: &mut fmt::Formatter<'_>, expected: Word, got: Word) -> fmt::Result {
    write!(
        f,
        "the buffer holds `{}` entries but the spec has `word = {}`",
        got.name(),
        expected.name()
    )
}

/// `Error::NoConvergence`'s message.
pub(super) fn no_convergence(
    f: &mut fmt::Formatter<'_>,
    index: u32,
    iterations: u32,
) -> fmt::Result {
    write!(
        f,
        "the pulse time of step {index} did not converge within {iterations} iterations: \
         the curve's step count is not a finite number there"
    )
}
