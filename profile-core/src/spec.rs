//! The validated description of a table: curve, timer and discretization.

use crate::error::Error;

/// The largest number of entries a table may have.
///
/// 65 536 entries are 128 KiB of `u16` flash, more than most microcontrollers
/// spend on one ramp; the limit keeps compile-time expansion bounded.
pub const MAX_LEN: u32 = 65_536;

/// The width of one table entry, which is the width of the timer's reload register.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Word {
    /// 16-bit timer (the default): periods from 1 to 65 535 ticks.
    U16,
    /// 32-bit timer: periods from 1 to 4 294 967 295 ticks.
    U32,
}

impl Word {
    /// The largest period this word holds, in ticks.
    pub const fn max(self) -> u32 {
        match self {
            Word::U16 => u16::MAX as u32,
            Word::U32 => u32::MAX,
        }
    }

    /// Bytes of flash one entry takes.
    pub const fn bytes(self) -> u32 {
        match self {
            Word::U16 => 2,
            Word::U32 => 4,
        }
    }

    /// The Rust (and TOML) name: `u16` or `u32`.
    pub const fn name(self) -> &'static str {
        match self {
            Word::U16 => "u16",
            Word::U32 => "u32",
        }
    }
}

/// How the timer turns ticks into step pulses.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timer {
    /// Tick rate of the timer after its prescaler, in Hz. Must not be 0.
    pub timer_hz: u32,
    /// Width of the reload register, and so of each table entry.
    pub word: Word,
    /// Timer reloads per step: 1 for compare/PWM output, 2 where the timer toggles
    /// the pin and overflows twice per pulse (each entry is then a half period).
    pub ticks_per_step: u8,
}

impl Timer {
    /// A timer at `timer_hz` with the defaults: `u16` word, one reload per step.
    pub const fn new(timer_hz: u32) -> Self {
        Timer {
            timer_hz,
            word: Word::U16,
            ticks_per_step: 1,
        }
    }

    /// Ticks per second of step period: `timer_hz / ticks_per_step`.
    pub(crate) fn ticks_per_second(&self) -> f64 {
        self.timer_hz as f64 / self.ticks_per_step as f64
    }

    /// The lowest step frequency whose period still fits the word, in Hz.
    pub fn lowest_frequency(&self) -> f64 {
        self.ticks_per_second() / self.word.max() as f64
    }
}

/// How a continuous curve becomes one entry per step (DESIGN section 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Discretization {
    /// Entry `k` is `t(k+1) - t(k)` where `N(t(k)) = k`: pulse edges land where
    /// the continuous curve puts them. The default.
    #[default]
    Exact,
    /// Entry `k` is `1 / f(t(k))`: the frequency at the start of the step
    /// (too long while accelerating).
    LeftEndpoint,
    /// Entry `k` is `1 / f(x = k)`: the curve's x axis is the step index
    /// (seeds 000, 003 and 004).
    Index,
}

impl Discretization {
    /// The name used in macro arguments and TOML.
    pub const fn name(self) -> &'static str {
        match self {
            Discretization::Exact => "exact",
            Discretization::LeftEndpoint => "left_endpoint",
            Discretization::Index => "index",
        }
    }
}

/// How exact periods (in fractional ticks) become integers.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Rounding {
    /// Drop the fraction, as C's `(unsigned short)` cast does. Drifts short.
    Truncate,
    /// Round each entry to the nearest tick (halves away from zero).
    Nearest,
    /// Round the running sum of exact times and emit the differences: every
    /// pulse edge within 0.5 tick of its exact time. The default.
    #[default]
    Diffuse,
}

impl Rounding {
    /// The name used in macro arguments and TOML.
    pub const fn name(self) -> &'static str {
        match self {
            Rounding::Truncate => "truncate",
            Rounding::Nearest => "nearest",
            Rounding::Diffuse => "diffuse",
        }
    }
}

/// The floating-point arithmetic the curve is evaluated in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum Arithmetic {
    /// Double precision (the default).
    #[default]
    F64,
    /// Single precision, operation for operation as the C function of seed 000
    /// (`CalculateSModelLine`), so tables migrated from C keep their bits.
    /// Applies to `curve = sigmoid` with `discretization = index`.
    F32,
    /// Integer arithmetic, operation for operation as seed 004's `pulse()`:
    /// `A = (fmax - fmin)(fmax + fmin) / (2 trans)`, `f[i] = isqrt(2 A i + fmin²)`,
    /// `reload = timer_hz / (ticks_per_step f[i])`, all integer divisions. Applies
    /// to `curve = linear` with `discretization = index` and `rounding = truncate`;
    /// where the article's 16-bit variables would overflow, an error.
    Integer,
}

impl Arithmetic {
    /// The name used in macro arguments and TOML.
    pub const fn name(self) -> &'static str {
        match self {
            Arithmetic::F64 => "f64",
            Arithmetic::F32 => "f32",
            Arithmetic::Integer => "integer",
        }
    }
}

/// The sigmoid S-curve of seeds 000 and 003.
///
/// `f(x) = fmin + (fmax - fmin) / (1 + exp(-flexible * (x - len/2) / (len/2)))`.
/// With `discretization = index`, `x` is the step index `0..len`. In time, the same
/// shape spans `[0, T]` with `T = len / (fmin + (fmax - fmin) / 2)`, so exactly
/// `len` steps fit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sigmoid {
    /// Frequency the curve starts from (its lower asymptote), in Hz (steps/s).
    pub fmin: f64,
    /// Frequency the curve rises to (its upper asymptote), in Hz (steps/s).
    pub fmax: f64,
    /// Steepness: the logistic runs over `[-flexible, flexible]`. Larger is
    /// steeper in the middle; small values approach constant acceleration.
    pub flexible: f64,
    /// Number of entries (steps) in the table.
    pub len: u32,
}

/// How long an exponential ramp is: a step budget or a time constant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ExponentialExtent {
    /// `fmax` is reached exactly at the end of step `len`; `tau` is solved for.
    Len(u32),
    /// The time constant `tau`, in s; the table runs until `fmax` is reached.
    Tau(f64),
}

/// The exponential ramp of seed 001: `f(t) = fmin + (f_inf - fmin)(1 - exp(-t/tau))`,
/// cut where it reaches `fmax`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Exponential {
    /// Start frequency `f0`, in Hz.
    pub fmin: f64,
    /// Frequency at the end of the ramp, in Hz. Below `f_inf`.
    pub fmax: f64,
    /// The asymptote the exponential approaches, in Hz.
    pub f_inf: f64,
    /// Step budget or time constant.
    pub extent: ExponentialExtent,
}

/// How long a linear ramp is: a step count or an acceleration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LinearExtent {
    /// Number of entries; the acceleration is solved for.
    Len(u32),
    /// Constant acceleration, in Hz/s; the table runs until `fmax` is reached.
    Accel(f64),
}

/// Constant acceleration (seed 004): `f(t) = fmin + a t`, so after `i` steps
/// `f_i = sqrt(fmin² + 2 a i)`.
///
/// In time (`exact`, `left_endpoint`), `len` entries take the ramp from `fmin`
/// to `fmax`: `a = (fmax² - fmin²) / (2 len)`. Over the index (`index`, the
/// seed's table), entry `i` is `1 / f_i` for `i = 0..=trans` with
/// `trans = len - 1`, so the last entry is at `fmax`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Linear {
    /// Start frequency, in Hz.
    pub fmin: f64,
    /// End frequency, in Hz.
    pub fmax: f64,
    /// Step count or acceleration.
    pub extent: LinearExtent,
}

/// The three-stage curve of Zeng, Hu and Hu (seed 002): exponential up to `f1`,
/// linear at `accel` up to `f2`, parabolic up to `fmax`, with frequency and
/// acceleration continuous at both joints. The table runs until `fmax`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ThreeStage {
    /// Start frequency `f0`, in Hz.
    pub fmin: f64,
    /// Final frequency `fc`, reached with zero acceleration, in Hz.
    pub fmax: f64,
    /// Acceleration `a` of the linear stage (the peak), in Hz/s.
    pub accel: f64,
    /// Frequency where the exponential stage hands over to the linear one, in Hz.
    pub f1: f64,
    /// Frequency where the linear stage hands over to the parabola, in Hz.
    pub f2: f64,
    /// Shape `B` of the exponential stage, in 1/s: positive is convex
    /// (acceleration falls towards `a`), negative concave. Not 0.
    pub shape: f64,
}

/// The jerk-limited (7-segment) S-curve: acceleration rises at `jerk` up to
/// `accel`, holds, and falls back to zero at `fmax`. When `accel` cannot be
/// reached within the speed change, the peak acceleration is lower
/// (triangular acceleration). The table runs until `fmax`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JerkLimited {
    /// Start frequency, in Hz.
    pub fmin: f64,
    /// Final frequency, in Hz.
    pub fmax: f64,
    /// Largest acceleration, in Hz/s.
    pub accel: f64,
    /// Jerk, in Hz/s².
    pub jerk: f64,
}

/// A curve and its parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Curve {
    /// The sigmoid S-curve (seeds 000, 003).
    Sigmoid(Sigmoid),
    /// The exponential ramp (seed 001).
    Exponential(Exponential),
    /// Constant acceleration (seed 004).
    Linear(Linear),
    /// Exponential, linear, parabolic (seed 002).
    ThreeStage(ThreeStage),
    /// Jerk-limited S-curve.
    JerkLimited(JerkLimited),
}

impl Curve {
    /// The name used in macro arguments and TOML.
    pub const fn name(&self) -> &'static str {
        match self {
            Curve::Sigmoid(_) => "sigmoid",
            Curve::Exponential(_) => "exponential",
            Curve::Linear(_) => "linear",
            Curve::ThreeStage(_) => "three_stage",
            Curve::JerkLimited(_) => "jerk_limited",
        }
    }

    /// The start and end frequencies, in Hz.
    pub fn frequencies(&self) -> (f64, f64) {
        match *self {
            Curve::Sigmoid(c) => (c.fmin, c.fmax),
            Curve::Exponential(c) => (c.fmin, c.fmax),
            Curve::Linear(c) => (c.fmin, c.fmax),
            Curve::ThreeStage(c) => (c.fmin, c.fmax),
            Curve::JerkLimited(c) => (c.fmin, c.fmax),
        }
    }
}

/// Everything needed to compute one period table.
///
/// Build one with [`Spec::new`] and the `with_*` methods, then call
/// [`Spec::generate`] (into a buffer) or [`Spec::validate`].
///
/// ```
/// use profile_core::{Curve, Sigmoid, Spec, Timer};
///
/// let spec = Spec::new(
///     Curve::Sigmoid(Sigmoid { fmin: 500.0, fmax: 64_000.0, flexible: 8.0, len: 1000 }),
///     Timer::new(10_000_000),
/// );
/// let mut table = [0u16; 1000];
/// let figures = spec.generate(&mut table).unwrap();
/// assert_eq!(figures.len, 1000);
/// assert!(table[0] > table[999]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spec {
    /// The curve and its parameters.
    pub curve: Curve,
    /// The timer the table is for.
    pub timer: Timer,
    /// Curve to entries.
    pub discretization: Discretization,
    /// Fractional ticks to integers.
    pub rounding: Rounding,
    /// Floating-point arithmetic.
    pub arithmetic: Arithmetic,
}

impl Spec {
    /// A spec with the default discretization (`exact`), rounding (`diffuse`)
    /// and arithmetic (`f64`).
    pub const fn new(curve: Curve, timer: Timer) -> Self {
        Spec {
            curve,
            timer,
            discretization: Discretization::Exact,
            rounding: Rounding::Diffuse,
            arithmetic: Arithmetic::F64,
        }
    }

    /// The same spec with another discretization.
    pub const fn with_discretization(mut self, discretization: Discretization) -> Self {
        self.discretization = discretization;
        self
    }

    /// The same spec with another rounding.
    pub const fn with_rounding(mut self, rounding: Rounding) -> Self {
        self.rounding = rounding;
        self
    }

    /// The same spec with another arithmetic.
    pub const fn with_arithmetic(mut self, arithmetic: Arithmetic) -> Self {
        self.arithmetic = arithmetic;
        self
    }

    /// The same spec with another table word.
    pub const fn with_word(mut self, word: Word) -> Self {
        self.timer.word = word;
        self
    }

    /// The same spec with another number of timer reloads per step.
    pub const fn with_ticks_per_step(mut self, ticks_per_step: u8) -> Self {
        self.timer.ticks_per_step = ticks_per_step;
        self
    }

    /// The number of entries the table has: `len` where given, otherwise the
    /// steps until the curve reaches `fmax`, rounded up (the final fraction of
    /// a step is taken at `fmax`). 0 for an invalid spec.
    pub fn len(&self) -> u32 {
        let index = self.discretization == Discretization::Index;
        let (steps, given) = crate::curves::ramp_steps(&self.curve, index);
        crate::curves::entries(
            steps,
            given,
            index && matches!(self.curve, Curve::Linear(_)),
        )
    }

    /// `true` when the table has no entries (never for a valid spec).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Checks every parameter and combination without computing the table.
    ///
    /// A period that does not fit the word is found only by [`Spec::generate`].
    pub fn validate(&self) -> Result<(), Error> {
        crate::validate::validate(self)
    }
}
