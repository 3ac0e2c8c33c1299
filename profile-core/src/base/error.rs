//! Typed errors: each names the parameter at fault and says what is expected.

use core::fmt;

use super::key::Key;
use super::modes::Discretization;
use super::numbers::Hundredths;
pub(crate) use super::numbers::{Fixed, Num, Significant};
use super::timer::Word;

/// Why a spec cannot become a table.
///
/// [`Error::key`] names the parameter to blame, so front ends can point at it.
/// Messages are lowercase, quote keys in backticks and say what is expected.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// A number is NaN or infinite.
    NotFinite {
        /// The parameter.
        key: Key,
        /// Its value.
        value: f64,
    },
    /// A number that must be positive is zero or negative, or so small a
    /// float holds it only without its precision (subnormal).
    NotPositive {
        /// The parameter.
        key: Key,
        /// Its value.
        value: f64,
    },
    /// A number is above the largest value the curve handles.
    TooLarge {
        /// The parameter.
        key: Key,
        /// Its value.
        value: f64,
        /// The largest accepted value.
        max: f64,
    },
    /// `key` must be at least `other`.
    NotAtLeast {
        /// The parameter that must not be the smaller one.
        key: Key,
        /// Its value.
        value: f64,
        /// The parameter it is compared with.
        other: Key,
        /// That parameter's value.
        other_value: f64,
    },
    /// `key` must be greater than `other`.
    NotGreater {
        /// The parameter that must be the larger one.
        key: Key,
        /// Its value.
        value: f64,
        /// The parameter it is compared with.
        other: Key,
        /// That parameter's value.
        other_value: f64,
    },
    /// A number must differ from 0.
    Zero {
        /// The parameter.
        key: Key,
    },
    /// A number must be greater than a bound derived from other parameters.
    TooSmall {
        /// The parameter.
        key: Key,
        /// Its value.
        value: f64,
        /// The bound it must exceed.
        min: f64,
        /// Why, in words.
        why: &'static str,
    },
    /// A number must be a whole number (integer arithmetic).
    NotWhole {
        /// The parameter.
        key: Key,
        /// Its value.
        value: f64,
    },
    /// An intermediate of the S3C4510 article's integer code would overflow
    /// its C type.
    IntegerOverflow {
        /// The parameter to blame.
        key: Key,
        /// The C expression.
        expression: &'static str,
        /// Its value.
        value: u128,
        /// The C type's maximum.
        max: u64,
    },
    /// The curve's parameters make the ramp longer than [`MAX_LEN`](crate::MAX_LEN).
    RampTooLong {
        /// The parameter that sets the length.
        key: Key,
        /// The steps the ramp would take.
        steps: f64,
        /// The maximum.
        max: u32,
    },
    /// A segment of a segment table holds no step.
    EmptySegment {
        /// The segment's index.
        index: u32,
        /// The number of steps in the ramp.
        steps: u32,
    },
    /// A segment holds more steps than its count's word holds.
    SegmentTooLong {
        /// The segment's index.
        index: u32,
        /// Its step count.
        count: u32,
        /// The word of the counts.
        word: Word,
    },
    /// `compress` below the nearest a step edge can land to every curve
    /// edge: half a tick, or a whole tick with `ticks_per_step = 2` (each
    /// entry played twice puts step edges on even ticks).
    CompressTooSmall {
        /// The value given.
        value: f64,
        /// The timer's reloads per step.
        ticks_per_step: u8,
    },
    /// `compress` above [`MAX_COMPRESS_TICKS`](crate::MAX_COMPRESS_TICKS).
    CompressTooLarge {
        /// The value given.
        value: f64,
    },
    /// No run keeps an edge within `compress` ticks of the curve.
    CompressUnreachable {
        /// The edge (1-based step).
        step: u32,
        /// The tolerance, in ticks.
        tolerance: f64,
    },
    /// A segment table needs a curve in time.
    SegmentsNeedTime {
        /// The discretization asked for.
        discretization: Discretization,
    },
    /// `len` is 0.
    LenZero,
    /// `len` is above [`MAX_LEN`](crate::MAX_LEN).
    LenTooLarge {
        /// The requested length.
        len: u64,
        /// The maximum.
        max: u32,
    },
    /// `timer_hz` is 0.
    TimerZero,
    /// `ticks_per_step` is neither 1 nor 2.
    TicksPerStep {
        /// The value given.
        value: u64,
    },
    /// `reload_offset` outside what any period of the word leaves room for:
    /// from `1 - max` to `max - 1`, `max` the word's largest value.
    ReloadOffsetRange {
        /// The offset given.
        offset: i32,
        /// The word.
        word: Word,
    },
    /// A stored value, a period plus `reload_offset`, is 0 or less, or more
    /// than the word holds.
    ReloadOffset {
        /// What holds it: `"entry"`, `"segment"` or `"step"` (of runs).
        what: &'static str,
        /// Its index, from 0.
        index: u32,
        /// Its period, in ticks.
        ticks: u32,
        /// The offset.
        offset: i32,
        /// The word.
        word: Word,
    },
    /// A valid option that does not apply to this curve or combination.
    Unsupported {
        /// The parameter whose value does not apply.
        key: Key,
        /// Its value, as written.
        value: &'static str,
        /// Where it does apply.
        applies: &'static str,
    },
    /// An entry is too long for the table word.
    PeriodOverflow {
        /// Index of the first offending entry.
        index: u32,
        /// Its period in ticks.
        ticks: f64,
        /// The word.
        word: Word,
        /// `timer_hz`.
        timer_hz: u32,
        /// The lowest step frequency whose period fits, in Hz.
        lowest_hz: f64,
    },
    /// An entry rounds to zero ticks: the timer cannot produce that frequency.
    PeriodZero {
        /// Index of the first offending entry.
        index: u32,
        /// The highest step frequency the timer resolves (one tick per period), in Hz.
        highest_hz: f64,
    },
    /// The buffer passed to [`Spec::generate`](crate::Spec::generate) has the wrong length.
    BufferLength {
        /// The table length.
        expected: u32,
        /// The buffer length.
        got: usize,
    },
    /// The buffer's element type is not the spec's word.
    WordMismatch {
        /// The spec's word.
        expected: Word,
        /// The buffer's element type.
        got: Word,
    },
    /// The pulse-time solver did not converge within its iteration bound.
    NoConvergence {
        /// The step whose time was being solved.
        index: u32,
        /// The iteration bound.
        iterations: u32,
    },
}

impl Error {
    /// The parameter a front end should point at, if one is to blame.
    pub fn key(&self) -> Option<Key> {
        match *self {
            Error::NotFinite { key, .. }
            | Error::NotPositive { key, .. }
            | Error::TooLarge { key, .. }
            | Error::Zero { key }
            | Error::TooSmall { key, .. }
            | Error::NotWhole { key, .. }
            | Error::IntegerOverflow { key, .. }
            | Error::RampTooLong { key, .. }
            | Error::NotGreater { key, .. }
            | Error::NotAtLeast { key, .. }
            | Error::Unsupported { key, .. } => Some(key),
            Error::LenZero | Error::LenTooLarge { .. } => Some(Key::LEN),
            Error::TimerZero => Some(Key::TIMER_HZ),
            Error::TicksPerStep { .. } => Some(Key::TICKS_PER_STEP),
            Error::ReloadOffsetRange { .. } | Error::ReloadOffset { .. } => {
                Some(Key::RELOAD_OFFSET)
            }
            Error::PeriodOverflow { .. } => Some(Key::FMIN),
            Error::PeriodZero { .. } => Some(Key::FMAX),
            Error::EmptySegment { .. }
            | Error::SegmentTooLong { .. }
            | Error::SegmentsNeedTime { .. } => Some(Key::SEGMENTS),
            Error::CompressTooSmall { .. }
            | Error::CompressTooLarge { .. }
            | Error::CompressUnreachable { .. } => Some(Key::COMPRESS),
            Error::BufferLength { .. } | Error::WordMismatch { .. } => None,
            Error::NoConvergence { .. } => None,
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::NotFinite { key, value } => {
                write!(f, "`{key}` must be a finite number (got {})", Num(value))
            }
            Error::NotPositive { key, value } if value > 0.0 => write!(
                f,
                "`{key}` must be at least 2.2250738585072014e-308, the smallest normal float \
                 (got {})",
                Num(value)
            ),
            Error::NotPositive { key, value } => {
                write!(f, "`{key}` must be greater than 0 (got {})", Num(value))
            }
            Error::TooLarge { key, value, max } => {
                write!(
                    f,
                    "`{key}` must be at most {} (got {})",
                    Num(max),
                    Num(value)
                )
            }
            Error::NotGreater {
                key,
                value,
                other,
                other_value,
            } => write!(
                f,
                "`{key}` must be greater than `{other}` (got {} <= {})",
                Num(value),
                Num(other_value)
            ),
            Error::Zero { key } => write!(f, "`{key}` must not be 0"),
            Error::TooSmall {
                key,
                value,
                min,
                why,
            } => write!(
                f,
                "`{key}` must be greater than {}{why} (got {})",
                Significant(min),
                Num(value)
            ),
            Error::NotAtLeast {
                key,
                value,
                other,
                other_value,
            } => write!(
                f,
                "`{key}` must be at least `{other}` (got {} < {})",
                Num(value),
                Num(other_value)
            ),
            Error::NotWhole { key, value } => write!(
                f,
                "`{key}` must be a whole number with `arithmetic = integer` (got {})",
                Num(value)
            ),
            Error::IntegerOverflow {
                key,
                expression,
                value,
                max,
            } => write!(
                f,
                "`{key}` overflows the integer `pulse()` code: `{expression}` is {value}, more than {max}"
            ),
            _ => self.fmt_table(f),
        }
    }
}

/// [`Error::RampTooLong`]'s message: the length in exponent form beyond
/// 1e16 steps, and said so where it is no length at all.
fn ramp_too_long(f: &mut fmt::Formatter<'_>, key: Key, steps: f64, max: u32) -> fmt::Result {
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

impl Error {
    /// The messages of the errors about lengths, layouts, the timer and the
    /// table itself.
    fn fmt_table(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::RampTooLong { key, steps, max } => ramp_too_long(f, key, steps, max),
            Error::EmptySegment { index, steps } => write!(
                f,
                "segment {index} holds no step of the {steps}-step ramp; use fewer `segments`"
            ),
            Error::SegmentTooLong { index, count, word } => write!(
                f,
                "segment {index} holds {count} steps, more than a `word = {}` count holds ({}); \
                 use more `segments`",
                word.name(),
                word.max()
            ),
            Error::CompressTooSmall {
                value,
                ticks_per_step: 2,
            } => write!(
                f,
                "`compress` is the largest step-edge error allowed, in timer ticks, and must be \
                 at least 1 with `ticks_per_step = 2`: each entry is played twice, so step edges \
                 fall on every other tick (got {})",
                Num(value)
            ),
            Error::CompressTooSmall { value, .. } => write!(
                f,
                "`compress` is the largest pulse-edge error allowed, in ticks, and must be at \
                 least 0.5: a whole tick cannot land nearer to every edge (got {})",
                Num(value)
            ),
            Error::CompressTooLarge { value } => write!(
                f,
                "`compress` is the largest pulse-edge error allowed, in ticks, and must be at \
                 most 65535, the longest period a run's 16-bit word holds (got {})",
                Num(value)
            ),
            Error::CompressUnreachable { step, tolerance } => write!(
                f,
                "no run of 16-bit periods keeps pulse edge {step} within {} ticks of the \
                 curve; raise `compress`",
                Num(tolerance)
            ),
            Error::SegmentsNeedTime { discretization } => write!(
                f,
                "`segments` cuts the curve into equal-time pieces and needs `discretization = exact` (got `{}`)",
                discretization.name()
            ),
            Error::LenZero => f.write_str("`len` must be at least 1 (got 0)"),
            Error::LenTooLarge { len, max } => {
                write!(f, "`len` must be at most {max} (got {len})")
            }
            Error::TimerZero => f.write_str("`timer_hz` must be greater than 0 (got 0)"),
            Error::TicksPerStep { value } => {
                write!(f, "`ticks_per_step` must be 1 or 2 (got {value})")
            }
            Error::ReloadOffsetRange { .. } | Error::ReloadOffset { .. } => self.fmt_offset(f),
            Error::Unsupported {
                key,
                value,
                applies,
            } => write!(f, "`{key} = {value}` applies only {applies}"),
            Error::PeriodOverflow {
                index,
                ticks,
                word,
                timer_hz,
                lowest_hz,
            } => write!(
                f,
                "entry {index} is {} ticks, more than `word = {}` holds ({}); \
                 at `timer_hz = {timer_hz}` the lowest step frequency that fits is {} Hz",
                Num(libm::round(ticks)),
                word.name(),
                word.max(),
                Hundredths(lowest_hz),
            ),
            Error::PeriodZero { index, highest_hz } => write!(
                f,
                "entry {index} rounds to 0 ticks; the timer resolves step frequencies up to {} Hz",
                Fixed(highest_hz, 0)
            ),
            Error::BufferLength { expected, got } => write!(
                f,
                "the buffer holds {got} entries but the table has `len = {expected}`"
            ),
            Error::WordMismatch { expected, got } => write!(
                f,
                "the buffer holds `{}` entries but the spec has `word = {}`",
                got.name(),
                expected.name()
            ),
            Error::NoConvergence { index, iterations } => write!(
                f,
                "the pulse time of step {index} did not converge within {iterations} iterations: \
                 the curve's step count is not a finite number there"
            ),
            // Written by `fmt`; every variant's message is pinned in the tests.
            _ => Ok(()),
        }
    }

    /// The messages of `reload_offset`: its range, and a stored value it
    /// takes out of the word.
    fn fmt_offset(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::ReloadOffsetRange { offset, word } => write!(
                f,
                "`reload_offset` must be from -{max} to {max} with `word = {}`: a period of 1 to \
             {} ticks plus the offset must fit the word (got {offset})",
                word.name(),
                word.max(),
                max = word.max() - 1,
            ),
            Error::ReloadOffset {
                what,
                index,
                ticks,
                offset,
                word,
            } => write!(
                f,
                "`reload_offset = {offset}` makes {what} {index} ({ticks} tick{}) {}: a stored \
             value, the period plus the offset, must be from 1 to {} (`word = {}`)",
                if ticks == 1 { "" } else { "s" },
                i64::from(ticks) + i64::from(offset),
                word.max(),
                word.name()
            ),
            _ => Ok(()),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Error {}

#[cfg(test)]
#[path = "error_tests.rs"]
mod tests;
