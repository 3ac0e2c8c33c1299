//! Typed errors: each names the parameter at fault and says what is expected.

use core::fmt;

/// A parameter of a table spec, as spelled in macro arguments and TOML.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[non_exhaustive]
pub enum Key {
    /// `curve`
    Curve,
    /// `timer_hz`
    TimerHz,
    /// `word`
    Word,
    /// `ticks_per_step`
    TicksPerStep,
    /// `discretization`
    Discretization,
    /// `rounding`
    Rounding,
    /// `arithmetic`
    Arithmetic,
    /// `fmin`
    Fmin,
    /// `fmax`
    Fmax,
    /// `flexible`
    Flexible,
    /// `len`
    Len,
    /// `f_inf`
    FInf,
    /// `tau`
    Tau,
    /// `accel`
    Accel,
    /// `f1`
    F1,
    /// `f2`
    F2,
    /// `shape`
    Shape,
    /// `jerk`
    Jerk,
    /// `segments`
    Segments,
}

impl Key {
    /// Every key, in the order documentation lists them.
    pub const ALL: &'static [Key] = &[
        Key::Curve,
        Key::Len,
        Key::Fmin,
        Key::Fmax,
        Key::Flexible,
        Key::FInf,
        Key::Tau,
        Key::Accel,
        Key::F1,
        Key::F2,
        Key::Shape,
        Key::Jerk,
        Key::TimerHz,
        Key::Word,
        Key::TicksPerStep,
        Key::Discretization,
        Key::Rounding,
        Key::Arithmetic,
        Key::Segments,
    ];

    /// The key as written by users.
    pub const fn name(self) -> &'static str {
        match self {
            Key::Curve => "curve",
            Key::TimerHz => "timer_hz",
            Key::Word => "word",
            Key::TicksPerStep => "ticks_per_step",
            Key::Discretization => "discretization",
            Key::Rounding => "rounding",
            Key::Arithmetic => "arithmetic",
            Key::Fmin => "fmin",
            Key::Fmax => "fmax",
            Key::Flexible => "flexible",
            Key::Len => "len",
            Key::FInf => "f_inf",
            Key::Tau => "tau",
            Key::Accel => "accel",
            Key::F1 => "f1",
            Key::F2 => "f2",
            Key::Shape => "shape",
            Key::Jerk => "jerk",
            Key::Segments => "segments",
        }
    }

    /// The key spelled `name`, if there is one.
    pub fn from_name(name: &str) -> Option<Key> {
        Key::ALL.iter().copied().find(|k| k.name() == name)
    }
}

impl fmt::Display for Key {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

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
    /// A number that must be positive is zero or negative.
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
    /// An intermediate of seed 004's integer code would overflow its C type.
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
    /// A segment table needs a curve in time.
    SegmentsNeedTime {
        /// The discretization asked for.
        discretization: crate::Discretization,
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
        word: crate::Word,
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
        expected: crate::Word,
        /// The buffer's element type.
        got: crate::Word,
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
            | Error::Unsupported { key, .. } => Some(key),
            Error::LenZero | Error::LenTooLarge { .. } => Some(Key::Len),
            Error::TimerZero => Some(Key::TimerHz),
            Error::TicksPerStep { .. } => Some(Key::TicksPerStep),
            Error::PeriodOverflow { .. } => Some(Key::Fmin),
            Error::PeriodZero { .. } => Some(Key::Fmax),
            Error::EmptySegment { .. } | Error::SegmentsNeedTime { .. } => Some(Key::Segments),
            Error::BufferLength { .. } | Error::WordMismatch { .. } => None,
            Error::NoConvergence { .. } => Some(Key::Curve),
        }
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Error::NotFinite { key, value } => {
                write!(f, "`{key}` must be a finite number (got {value})")
            }
            Error::NotPositive { key, value } => {
                write!(f, "`{key}` must be greater than 0 (got {value})")
            }
            Error::TooLarge { key, value, max } => {
                write!(f, "`{key}` must be at most {max} (got {value})")
            }
            Error::NotGreater {
                key,
                value,
                other,
                other_value,
            } => write!(
                f,
                "`{key}` must be greater than `{other}` (got {value} <= {other_value})"
            ),
            Error::Zero { key } => write!(f, "`{key}` must not be 0"),
            Error::TooSmall {
                key,
                value,
                min,
                why,
            } => write!(f, "`{key}` must be greater than {min} {why} (got {value})"),
            Error::NotWhole { key, value } => write!(
                f,
                "`{key}` must be a whole number with `arithmetic = integer` (got {value})"
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
            Error::RampTooLong { key, steps, max } => write!(
                f,
                "`{key}` makes the ramp {steps:.0} steps long; at most {max} are allowed"
            ),
            Error::EmptySegment { index, steps } => write!(
                f,
                "segment {index} holds no step of the {steps}-step ramp; use fewer `segments`"
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
                "entry {index} is {ticks:.0} ticks, more than `word = {}` holds ({}); \
                 at `timer_hz = {timer_hz}` the lowest step frequency that fits is {lowest_hz:.2} Hz",
                word.name(),
                word.max(),
            ),
            Error::PeriodZero { index, highest_hz } => write!(
                f,
                "entry {index} rounds to 0 ticks; the timer resolves step frequencies up to {highest_hz:.0} Hz"
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
                "the pulse time of step {index} did not converge within {iterations} iterations"
            ),
        }
    }
}

#[cfg(feature = "std")]
impl std::error::Error for Error {}
