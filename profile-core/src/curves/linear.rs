//! Constant acceleration (the constant-acceleration article), in time, over
//! the index, and in the article's integer arithmetic.

use super::check::{len, positive, range};
use super::kind::{CurveKind, IndexEntry, Length, Modes, Unrounded};
use crate::base::error::Error;
use crate::base::key::Key;
use crate::base::modes::{Arithmetic, Discretization, Rounding};
use crate::base::solve::TimeCurve;

/// How long a linear ramp is: a step count or an acceleration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LinearExtent {
    /// Number of entries; the acceleration is solved for.
    Len(u32),
    /// Constant acceleration, in Hz/s; the table runs until `fmax` is reached.
    Accel(f64),
}

/// Constant acceleration, as in the constant-acceleration article ("Stepper
/// motor acceleration/deceleration control based on ARM chip S3C4510"): `f(t) = fmin + a t`, so after `i` steps
/// `f_i = sqrt(fmin² + 2 a i)`.
///
/// In time (`exact`, `left_endpoint`), `len` entries take the ramp from `fmin`
/// to `fmax`: `a = (fmax² - fmin²) / (2 len)`. Over the index (`index`, the
/// article's table), entry `i` is `1 / f_i` for `i = 0..=trans` with
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

impl Linear {
    /// Steps from `fmin` to `fmax` at acceleration `a`: `(fmax² - fmin²) / (2a)`.
    fn steps_at(&self, accel: f64) -> f64 {
        (self.fmax - self.fmin) * (self.fmax + self.fmin) / accel / 2.0
    }

    /// The acceleration in Hz/s: given, or `(fmax² - fmin²) / (2 steps)` where
    /// `steps` is `len` in time and `len - 1` (the article's `trans`) over the index:
    /// infinite over no steps (a `len` a [`Spec`](crate::Spec) refuses).
    pub fn accel(&self, index: bool) -> f64 {
        match self.extent {
            LinearExtent::Accel(a) => a,
            LinearExtent::Len(len) => {
                let steps = if index { len.saturating_sub(1) } else { len };
                (self.fmax - self.fmin) * (self.fmax + self.fmin) / (2.0 * steps as f64)
            }
        }
    }

    /// Frequency after `i` steps, `sqrt(fmin² + 2 a i)`, held at `fmax` once reached.
    pub fn freq_at_index(&self, i: u32) -> f64 {
        let a = self.accel(true);
        libm::sqrt(self.fmin * self.fmin + 2.0 * a * i as f64).min(self.fmax)
    }
}

/// Integer square root (floor), as the S3C4510 article's `sqrt_16`.
fn isqrt(n: u64) -> u64 {
    let mut x = libm::sqrt(n as f64) as u64;
    while x * x > n {
        x -= 1;
    }
    while (x + 1) * (x + 1) <= n {
        x += 1;
    }
    x
}

/// The S3C4510 article's `pulse()` in its own integer arithmetic: C `int` is 32-bit,
/// `REG16` and `UINT16` are 16-bit unsigned.
pub(crate) struct IntegerLinear {
    a: u64,
    f0: u64,
    ticks_per_step: u64,
    timer_hz: u64,
}

const INT_MAX: u64 = i32::MAX as u64;
const U16_MAX: u64 = u16::MAX as u64;

fn whole(key: Key, value: f64) -> Result<u64, Error> {
    if value != libm::trunc(value) {
        return Err(Error::NotWhole { key, value });
    }
    if value > U16_MAX as f64 {
        return Err(Error::IntegerOverflow {
            key,
            expression: "REG16",
            value: value as u128,
            max: U16_MAX,
        });
    }
    Ok(value as u64)
}

fn fits(key: Key, expression: &'static str, value: u64, max: u64) -> Result<(), Error> {
    if value > max {
        Err(Error::IntegerOverflow {
            key,
            expression,
            value: value as u128,
            max,
        })
    } else {
        Ok(())
    }
}

impl IntegerLinear {
    /// Checks every intermediate of the article's code against its C type.
    pub(crate) fn new(
        l: &Linear,
        len: u32,
        ticks_per_step: u8,
        timer_hz: u32,
    ) -> Result<Self, Error> {
        let f0 = whole(Key::FMIN, l.fmin)?;
        let fmax = whole(Key::FMAX, l.fmax)?;
        let trans = (len - 1) as u64;
        // `for(i=0;i<=trans;i++)` with a 16-bit `i` never ends at trans = 65535.
        fits(
            Key::LEN,
            "REG16 i <= trans (the loop ends only below 65535)",
            trans,
            U16_MAX - 1,
        )?;
        let product = (fmax - f0) * (fmax + f0);
        fits(Key::FMAX, "(fmax-f0)*(fmax+f0)", product, INT_MAX)?;
        let a = product / (2 * trans);
        fits(
            Key::LEN,
            "UINT16 A = ((fmax-f0)*(fmax+f0))/(2*trans)",
            a,
            U16_MAX,
        )?;
        fits(Key::FMIN, "f0*f0", f0 * f0, INT_MAX)?;
        fits(Key::FMAX, "2*A*i+f0*f0", 2 * a * trans + f0 * f0, INT_MAX)?;
        let fastest = isqrt(2 * a * trans + f0 * f0);
        let tps = ticks_per_step as u64;
        fits(
            Key::FMAX,
            "REG16 f0 += f0 (ticks_per_step * f[i])",
            tps * fastest,
            U16_MAX,
        )?;
        Ok(IntegerLinear {
            a,
            f0,
            ticks_per_step: tps,
            timer_hz: timer_hz as u64,
        })
    }

    /// `f[i] = sqrt_16(2*A*i + f0*f0)`.
    pub(crate) fn freq(&self, i: u32) -> u64 {
        isqrt(2 * self.a * i as u64 + self.f0 * self.f0)
    }

    /// `timer_hz / (ticks_per_step * f[i])`, integer division.
    pub(crate) fn reload(&self, i: u32) -> u64 {
        self.timer_hz / (self.ticks_per_step * self.freq(i))
    }
}

/// `f(t) = fmin + a t` up to `fmax`, then `fmax`.
pub(crate) struct LinearInTime {
    pub(super) fmin: f64,
    fmax: f64,
    pub(super) accel: f64,
    rise: f64,
    pub(super) rise_steps: f64,
}

impl LinearInTime {
    pub(crate) fn new(l: &Linear) -> Self {
        let accel = l.accel(false);
        LinearInTime {
            fmin: l.fmin,
            fmax: l.fmax,
            accel,
            rise: (l.fmax - l.fmin) / accel,
            rise_steps: match l.extent {
                LinearExtent::Len(len) => len as f64,
                LinearExtent::Accel(a) => l.steps_at(a),
            },
        }
    }
}

impl TimeCurve for LinearInTime {
    fn freq(&self, t: f64) -> f64 {
        (self.fmin + self.accel * t).min(self.fmax)
    }

    fn steps(&self, t: f64) -> f64 {
        if t < self.rise {
            self.fmin * t + self.accel * t * t / 2.0
        } else {
            self.rise_steps + self.fmax * (t - self.rise)
        }
    }

    /// `t(k) = 2k / (fmin + sqrt(fmin² + 2 a k))`: the closed form, without cancellation.
    fn time_at(&self, k: f64) -> Option<f64> {
        Some(if k < self.rise_steps {
            2.0 * k / (self.fmin + libm::sqrt(self.fmin * self.fmin + 2.0 * self.accel * k))
        } else {
            self.rise + (k - self.rise_steps) / self.fmax
        })
    }

    fn ramp_end(&self) -> (f64, f64) {
        (self.rise, self.rise_steps)
    }

    fn end_freq(&self) -> f64 {
        self.fmax
    }
}

const INTEGER_APPLIES: &str =
    "to `curve = linear`, as the constant-acceleration article's integer `pulse()` code computes";

impl CurveKind for Linear {
    const NAME: &'static str = "linear";
    const ARITHMETIC: &'static [(Arithmetic, &'static str)] =
        &[(Arithmetic::Integer, INTEGER_APPLIES)];
    const INDEX: bool = true;
    type Time = LinearInTime;

    fn time(&self) -> LinearInTime {
        LinearInTime::new(self)
    }

    fn frequencies(&self) -> (f64, f64) {
        (self.fmin, self.fmax)
    }

    /// `len`, or over the index the steps to `fmax` and one more entry at
    /// `fmax` (`trans + 1` entries).
    fn length(&self, index: bool) -> Length {
        match self.extent {
            LinearExtent::Len(len) => Length::Given(len),
            LinearExtent::Accel(a) => Length::Derived {
                steps: self.steps_at(a),
                key: Key::ACCEL,
                extra: u32::from(index),
            },
        }
    }

    fn check(&self, index: bool) -> Result<(), Error> {
        range(self.fmin, self.fmax)?;
        match self.extent {
            LinearExtent::Len(n) => {
                len(n)?;
                if n < 2 && index {
                    return Err(Error::TooSmall {
                        key: Key::LEN,
                        value: n as f64,
                        min: 1.0,
                        why: " for a linear ramp over the index: its `len` entries span trans = len - 1 steps",
                    });
                }
                Ok(())
            }
            LinearExtent::Accel(a) => positive(Key::ACCEL, a),
        }
    }

    /// The article's integer code: over the index, truncated, from `len`,
    /// and with every intermediate within its C type.
    fn check_modes(&self, modes: &Modes) -> Result<(), Error> {
        if modes.arithmetic != Arithmetic::Integer {
            return Ok(());
        }
        let unsupported = |applies| Error::Unsupported {
            key: Key::ARITHMETIC,
            value: "integer",
            applies,
        };
        if modes.discretization != Discretization::Index {
            return Err(unsupported(
                "with `discretization = index`, as the article's `f[i]` table is built",
            ));
        }
        if modes.rounding != Rounding::Truncate {
            return Err(unsupported(
                "with `rounding = truncate`: the article's code rounds by integer division",
            ));
        }
        if let LinearExtent::Accel(_) = self.extent {
            return Err(unsupported(
                "with `len`: the article's integer code takes the step count (trans + 1), not `accel`",
            ));
        }
        let t = modes.timer;
        IntegerLinear::new(self, modes.len, t.ticks_per_step, t.timer_hz).map(|_| ())
    }

    fn index_entries(
        &self,
        modes: &Modes,
        sink: &mut dyn FnMut(IndexEntry) -> Result<(), Error>,
    ) -> Result<(), Error> {
        let scale = modes.scale();
        if modes.arithmetic == Arithmetic::Integer {
            // The article's integer division is the rounding; the exact
            // value is the same ratio before truncation.
            let t = modes.timer;
            let int = IntegerLinear::new(self, modes.len, t.ticks_per_step, t.timer_hz)?;
            for k in 0..modes.len {
                sink(IndexEntry {
                    exact: Unrounded::Ticks(scale / int.freq(k) as f64),
                    rounded: Some(int.reload(k)),
                })?;
            }
        } else {
            for k in 0..modes.len {
                sink(IndexEntry::exact(scale / self.freq_at_index(k)))?;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integer_square_root_is_the_floor() {
        for n in [
            0u64,
            1,
            2,
            3,
            4,
            15,
            16,
            17,
            24_999_999,
            25_000_000,
            u32::MAX as u64,
        ] {
            let r = isqrt(n);
            assert!(r * r <= n && (r + 1) * (r + 1) > n, "{n}");
        }
    }

    /// A ramp of no steps (`len` 0, or 1 over the index) has no finite
    /// acceleration: infinite, and the frequency at its top.
    #[test]
    fn no_steps_accelerate_infinitely() {
        for (len, index) in [(0, true), (1, true), (0, false)] {
            let l = Linear {
                fmin: 100.0,
                fmax: 200.0,
                extent: LinearExtent::Len(len),
            };
            assert_eq!(l.accel(index), f64::INFINITY, "{len} {index}");
        }
        let l = Linear {
            fmin: 100.0,
            fmax: 200.0,
            extent: LinearExtent::Len(0),
        };
        assert_eq!(l.freq_at_index(0), 200.0);
    }

    /// The S3C4510 article: f0 500, fmax 5000, trans 200 at 50 MHz, two reloads per step.
    #[test]
    fn seed_004_integer_table() {
        let l = Linear {
            fmin: 500.0,
            fmax: 5000.0,
            extent: LinearExtent::Len(201),
        };
        let t = IntegerLinear::new(&l, 201, 2, 50_000_000).unwrap();
        assert_eq!(t.a, 61_875);
        assert_eq!(t.freq(0), 500);
        assert_eq!(t.freq(200), 5000);
        assert_eq!(t.reload(0), 50_000);
        assert_eq!(t.reload(200), 5000);
    }

    #[test]
    fn closed_form_edges_agree_with_the_step_count() {
        let c = LinearInTime::new(&Linear {
            fmin: 500.0,
            fmax: 5000.0,
            extent: LinearExtent::Len(200),
        });
        for k in [0.0, 1.0, 50.0, 199.0, 200.0] {
            let t = c.time_at(k).unwrap();
            assert!((c.steps(t) - k).abs() < 1e-9, "{k}");
        }
    }
}
