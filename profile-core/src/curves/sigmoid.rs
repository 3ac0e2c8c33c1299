//! The sigmoid S-curve of the S-curve articles, over the step index and over time.

use super::check::{len, positive, range};
use super::kind::{CurveKind, IndexEntry, Length, Modes, Unrounded};
use crate::base::error::Error;
use crate::base::expf::{WholeScale, exp_f32, reciprocal_of_one_plus};
use crate::base::key::Key;
use crate::base::math::{SoftplusRise, logistic};
use crate::base::modes::{Arithmetic, Discretization, Rounding};
use crate::base::solve::TimeCurve;

impl Key {
    /// `flexible`: the sigmoid's steepness.
    pub const FLEXIBLE: Key = Key("flexible");
}

/// The largest `flexible` accepted: the logistic then spans `[-500, 500]`,
/// already a step function at any table length, and `exp` stays finite.
pub const MAX_FLEXIBLE: f64 = 500.0;

/// The sigmoid S-curve of the S-curve articles ("Stepper Motor S-curve
/// Acceleration and Deceleration Algorithm and Implementation").
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

impl Sigmoid {
    /// Frequency at step index `i` (`discretization = index`), in Hz.
    pub fn freq_at_index(&self, i: u32) -> f64 {
        let half = self.len as f64 / 2.0;
        let x = self.flexible * (i as f64 - half) / half;
        (self.fmax - self.fmin) * logistic(x) + self.fmin
    }

    /// Frequency at step index `i` computed as the S-curve article's `CalculateSModelLine`
    /// does in C: single precision, a correctly rounded `expf`, and a
    /// double-precision `1.0 / ...`.
    pub fn freq_at_index_f32(&self, i: u32) -> f32 {
        SingleSigmoid::new(self).at(i)
    }

    /// Ramp duration in time: `len / (fmin + (fmax - fmin) / 2)`, in s.
    pub fn duration(&self) -> f64 {
        self.len as f64 / (self.fmin + (self.fmax - self.fmin) / 2.0)
    }
}

/// The sigmoid in the article's single precision, its parameters converted
/// once (a conversion from `f64` is software on most targets).
struct SingleSigmoid {
    half: f32,
    flexible: f32,
    fmin: f32,
    delt: f32,
}

impl SingleSigmoid {
    fn new(s: &Sigmoid) -> Self {
        let fmin = s.fmin as f32;
        SingleSigmoid {
            half: s.len as f32 / 2.0,
            flexible: s.flexible as f32,
            fmin,
            delt: s.fmax as f32 - fmin,
        }
    }

    /// The article's `fre[i]`.
    fn at(&self, i: u32) -> f32 {
        let melo = self.flexible * (i as f32 - self.half) / self.half;
        // C's `expf` is (nearly always) correctly rounded; `libm::expf` is off
        // by one ulp for about 1% of inputs, which can flip a truncated
        // period. `exp_f32` is correctly rounded but for rare double
        // roundings of `libm::exp`, whose bits it gives, and identical on
        // every target; and `1.0 / (1 + e)` in `double` rounded to `float`
        // is the `float` division.
        let e = exp_f32(-melo);
        let deno = reciprocal_of_one_plus(e);
        self.delt * deno + self.fmin
    }
}

/// Below this `flexible` the curve's step count is taken as its first-order
/// term: the next is 1e-100 of it.
const FLAT: f64 = 1e-100;

/// The sigmoid over `[0, T]`, with its closed-form step count.
pub(crate) struct SigmoidInTime {
    fmin: f64,
    delt: f64,
    flexible: f64,
    half: f64,
    duration: f64,
    len: f64,
    /// The softplus's rise from the curve's start, `s = -flexible`.
    rise: SoftplusRise,
}

impl SigmoidInTime {
    pub(crate) fn new(s: &Sigmoid) -> Self {
        let duration = s.duration();
        SigmoidInTime {
            fmin: s.fmin,
            delt: s.fmax - s.fmin,
            flexible: s.flexible,
            half: duration / 2.0,
            duration,
            len: s.len as f64,
            rise: SoftplusRise::new(-s.flexible),
        }
    }

    fn arg(&self, t: f64) -> f64 {
        self.flexible * (t - self.half) / self.half
    }
}

impl TimeCurve for SigmoidInTime {
    fn freq(&self, t: f64) -> f64 {
        self.fmin + self.delt * logistic(self.arg(t))
    }

    /// `N(t) = fmin t + (fmax - fmin) (T / 2 flexible) (softplus(s(t)) - softplus(-flexible))`,
    /// the difference taken as one rise of the softplus over `s(t) + flexible
    /// = flexible t / (T/2)`, so that a flat curve (small `flexible`) keeps
    /// its digits.
    fn steps(&self, t: f64) -> f64 {
        // Flatter than a float tells from a constant: the rise is
        // `logistic(-flexible) · flexible t / (T/2)` to 1e-100 of itself,
        // and `T / 2 flexible` alone would overflow below 1e-306.
        if self.flexible < FLAT {
            return self.fmin * t + self.delt * logistic(-self.flexible) * t;
        }
        let rise = self.rise.over(self.flexible * t / self.half);
        self.fmin * t + self.delt * (self.half / self.flexible) * rise
    }

    /// `f' <= (fmax - fmin) flexible / 4 (T/2)`: the logistic's slope is at
    /// most a quarter.
    fn max_slope(&self) -> f64 {
        self.delt * self.flexible / (4.0 * self.half)
    }

    /// One exponential for both: the logistic from the rise's `expm1`.
    fn steps_and_freq(&self, t: f64) -> (f64, f64) {
        if self.flexible < FLAT {
            return (self.steps(t), self.freq(t));
        }
        let (rise, logistic) = self.rise.over_with_logistic(self.flexible * t / self.half);
        (
            self.fmin * t + self.delt * (self.half / self.flexible) * rise,
            self.fmin + self.delt * logistic,
        )
    }

    fn ramp_end(&self) -> (f64, f64) {
        (self.duration, self.len)
    }

    fn end_freq(&self) -> f64 {
        self.fmin + self.delt
    }
}

impl CurveKind for Sigmoid {
    const NAME: &'static str = "sigmoid";
    const ARITHMETIC: &'static [(Arithmetic, &'static str)] = &[(
        Arithmetic::F32,
        "to `curve = sigmoid` with `discretization = index`, as the S-curve article's C function `CalculateSModelLine` computes",
    )];
    const INDEX: bool = true;
    type Time = SigmoidInTime;

    fn time(&self) -> SigmoidInTime {
        SigmoidInTime::new(self)
    }

    fn frequencies(&self) -> (f64, f64) {
        (self.fmin, self.fmax)
    }

    fn length(&self, _index: bool) -> Length {
        Length::Given(self.len)
    }

    fn check(&self, _index: bool) -> Result<(), Error> {
        len(self.len)?;
        range(self.fmin, self.fmax)?;
        positive(Key::FLEXIBLE, self.flexible)?;
        if self.flexible > MAX_FLEXIBLE {
            return Err(Error::TooLarge {
                key: Key::FLEXIBLE,
                value: self.flexible,
                max: MAX_FLEXIBLE,
            });
        }
        Ok(())
    }

    fn check_modes(&self, modes: &Modes) -> Result<(), Error> {
        if modes.arithmetic == Arithmetic::F32 && modes.discretization != Discretization::Index {
            return Err(Error::Unsupported {
                key: Key::ARITHMETIC,
                value: "f32",
                applies: Self::ARITHMETIC[0].1,
            });
        }
        Ok(())
    }

    fn index_entries(
        &self,
        modes: &Modes,
        sink: &mut dyn FnMut(IndexEntry) -> Result<(), Error>,
    ) -> Result<(), Error> {
        let scale = modes.scale();
        if modes.arithmetic == Arithmetic::F32 {
            let single = SingleSigmoid::new(self);
            // The article's truncation, by integer division where the
            // timer's rate is whole.
            let whole = match modes.rounding {
                Rounding::Truncate => WholeScale::new(scale),
                _ => None,
            };
            for k in 0..self.len {
                let freq = single.at(k);
                sink(IndexEntry {
                    exact: Unrounded::Over { scale, freq },
                    rounded: whole.and_then(|w| w.truncated_period(freq)),
                })?;
            }
            return Ok(());
        }
        for k in 0..self.len {
            sink(IndexEntry::exact(scale / self.freq_at_index(k)))?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn step_count_reaches_len_at_the_end() {
        let s = Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        };
        let c = SigmoidInTime::new(&s);
        assert!((c.steps(c.ramp_end().0) - 1000.0).abs() < 1e-9);
        assert_eq!(c.steps(0.0), 0.0);
        // In time, 1000 steps at an average of (500 + 64000) / 2 Hz.
        assert!((c.ramp_end().0 - 1000.0 / 32_250.0).abs() < 1e-15);
    }

    #[test]
    fn index_curve_matches_the_seed_first_and_last() {
        let s = Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        };
        // f[0] = 521.29 Hz: the curve never reaches fmin.
        assert!((s.freq_at_index(0) - 521.29).abs() < 0.01);
        assert_eq!((1e7 / s.freq_at_index(0)) as u32, 19183);
        assert_eq!((1e7 / s.freq_at_index(999)) as u32, 156);
        assert_eq!((1e7 / s.freq_at_index_f32(0) as f64) as u32, 19183);
    }
}
