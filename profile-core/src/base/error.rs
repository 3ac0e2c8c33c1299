//! Typed errors: each names the parameter at fault and says what is expected.

use core::fmt;

use super::key::Key;
use super::messages::*;
use super::modes::Discretization;
pub(crate) use super::numbers::Num;
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
    /// `compress` above 65 535 ticks (`MAX_COMPRESS_TICKS`, with the `std`
    /// feature).
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
    /// A `torque_limited` ramp's acceleration curve does not cover
    /// `fmin` to `fmax` with rising frequencies, or holds an acceleration
    /// that is not above 0 (at `hz`).
    AccelCurve {
        /// The point's frequency, Hz.
        hz: f64,
        /// Its acceleration, Hz/s (NaN where the curve's frequencies are at
        /// fault).
        accel: f64,
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
            Error::AccelCurve { .. } => Some(Key::FMAX),
        }
    }
}

impl fmt::Display for Error {
    /// Every variant by name, without a wildcard: a new variant does not
    /// compile until it has a message. The longer messages are written in
    /// `messages.rs`, by theme: a parameter's value, the ramp's length and
    /// layouts, the table's entries and words.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::NotFinite { key, value } => {
                write!(f, "`{key}` must be a finite number (got {})", Num(value))
            }
            Error::NotPositive { key, value } => not_positive(f, key, value),
            Error::TooLarge { key, value, max } => {
                let (max, value) = (Num(max), Num(value));
                write!(f, "`{key}` must be at most {max} (got {value})")
            }
            Error::NotGreater {
                key,
                value,
                other,
                other_value,
            } => compared(f, (key, value), "greater than", "<=", (other, other_value)),
            Error::NotAtLeast {
                key,
                value,
                other,
                other_value,
            } => compared(f, (key, value), "at least", "<", (other, other_value)),
            Error::Zero { key } => write!(f, "`{key}` must not be 0"),
            Error::TooSmall {
                key,
                value,
                min,
                why,
            } => too_small(f, key, value, min, why),
            Error::NotWhole { key, value } => not_whole(f, key, value),
            Error::IntegerOverflow {
                key,
                expression,
                value,
                max,
            } => integer_overflow(f, key, expression, value, max),
            Error::RampTooLong { key, steps, max } => ramp_too_long(f, key, steps, max),
            Error::EmptySegment { index, steps } => empty_segment(f, index, steps),
            Error::SegmentTooLong { index, count, word } => segment_too_long(f, index, count, word),
            Error::CompressTooSmall {
                value,
                ticks_per_step,
            } => compress_too_small(f, value, ticks_per_step),
            Error::CompressTooLarge { value } => compress_too_large(f, value),
            Error::CompressUnreachable { step, tolerance } => {
                compress_unreachable(f, step, tolerance)
            }
            Error::SegmentsNeedTime { discretization } => segments_need_time(f, discretization),
            Error::LenZero => f.write_str("`len` must be at least 1 (got 0)"),
            Error::LenTooLarge { len, max } => {
                write!(f, "`len` must be at most {max} (got {len})")
            }
            Error::TimerZero => f.write_str("`timer_hz` must be greater than 0 (got 0)"),
            Error::TicksPerStep { value } => {
                write!(f, "`ticks_per_step` must be 1 or 2 (got {value})")
            }
            Error::ReloadOffsetRange { offset, word } => reload_offset_range(f, offset, word),
            Error::ReloadOffset {
                what,
                index,
                ticks,
                offset,
                word,
            } => reload_offset(f, (what, index, ticks), offset, word),
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
            } => period_overflow(f, (index, ticks), word, timer_hz, lowest_hz),
            Error::PeriodZero { index, highest_hz } => period_zero(f, index, highest_hz),
            Error::BufferLength { expected, got } => write!(
                f,
                "the buffer holds {got} entries but the table has `len = {expected}`"
            ),
            Error::WordMismatch { expected, got } => word_mismatch(f, expected, got),
            Error::NoConvergence { index, iterations } => no_convergence(f, index, iterations),
            Error::AccelCurve { hz, accel } if accel.is_nan() => write!(
                f,
                "the acceleration curve must have rising frequencies from `fmin` or below to \
                 `fmax` or above (its first point is at {} Hz)",
                Num(hz)
            ),
            Error::AccelCurve { hz, accel } => write!(
                f,
                "the acceleration at {} Hz must be above 0 (got {} Hz/s): the motor has no \
                 torque to spare there",
                Num(hz),
                Num(accel)
            ),
        }
    }
}

// Beside the error it returns: the one check of a stored value.
impl Word {
    /// What a table of this word stores for a period of `ticks`, offset by
    /// `reload_offset` = `offset`: from 1 to [`max`](Self::max), or the
    /// error that says which period (`what` `index`: `entry 3`, `step 12`)
    /// and why. The one check of a stored value, for every layout.
    ///
    /// ```
    /// use profile_core::Word;
    ///
    /// assert_eq!(Word::U16.stored(1000, -1, "entry", 0), Ok(999));
    /// assert!(Word::U16.stored(65_535, 1, "entry", 7).is_err());
    /// ```
    pub fn stored(
        self,
        ticks: u32,
        offset: i32,
        what: &'static str,
        index: u32,
    ) -> Result<u32, Error> {
        let value = i64::from(ticks) + i64::from(offset);
        if value < 1 || value > i64::from(self.max()) {
            return Err(Error::ReloadOffset {
                what,
                index,
                ticks,
                offset,
                word: self,
            });
        }
        Ok(value as u32)
    }
}

impl core::error::Error for Error {}

#[cfg(test)]
#[path = "error_tests.rs"]
mod tests;
