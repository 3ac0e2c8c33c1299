//! The exponential ramp of the exponential-ramp article.

use super::check::{greater, len, positive, range};
use super::kind::{CurveKind, Length};
use crate::base::error::Error;
use crate::base::key::Key;
use crate::base::solve::TimeCurve;

impl Key {
    /// `f_inf`: the exponential's asymptote, in Hz.
    pub const F_INF: Key = Key("f_inf");
    /// `tau`: the exponential's time constant, in s.
    pub const TAU: Key = Key("tau");
}

/// How long an exponential ramp is: a step budget or a time constant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ExponentialExtent {
    /// `fmax` is reached exactly at the end of step `len`; `tau` is solved for.
    Len(u32),
    /// The time constant `tau`, in s; the table runs until `fmax` is reached.
    Tau(f64),
}

/// The exponential ramp of the exponential-ramp article ("Design and
/// implementation of speed increase/decrease in stepper motor control"): `f(t) = fmin + (f_inf - fmin)(1 - exp(-t/tau))`,
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

impl Exponential {
    /// `q = (fmax - fmin) / (f_inf - fmin)`: the part of the way to the
    /// asymptote the ramp covers.
    fn reach(&self) -> f64 {
        (self.fmax - self.fmin) / (self.f_inf - self.fmin)
    }

    /// `ln((f_inf - fmin) / (f_inf - fmax)) = -ln(1 - q)`: rise time in units
    /// of `tau`. Near the asymptote (`q` from 1/2 on) from the ratio itself:
    /// `f_inf - fmax` is exact there, where `1 - q` has lost the digits that
    /// the gap between `fmax` and `f_inf` holds.
    fn rise_in_tau(&self) -> f64 {
        let q = self.reach();
        if q < 0.5 {
            -libm::log1p(-q)
        } else {
            libm::log((self.f_inf - self.fmin) / (self.f_inf - self.fmax))
        }
    }

    /// Steps until `fmax` per second of `tau`:
    /// `N(t_r) / tau = f_inf u - (fmax - fmin) = fmin u + (fmax - fmin)(u - q)/q`
    /// with `u` the rise in `tau`. The second form has no cancellation: with
    /// a distant asymptote (`q` small) `(u - q)/q` is summed as a series.
    fn steps_per_tau(&self) -> f64 {
        let q = self.reach();
        let u = self.rise_in_tau();
        let excess = if q < 0.5 {
            crate::base::math::log_excess_ratio(q)
        } else {
            (u - q) / q
        };
        self.fmin * u + (self.fmax - self.fmin) * excess
    }

    /// The time constant, in s: given, or solved so that `fmax` is reached at
    /// the end of step `len`: `tau = len / (f_inf ln((f_inf - fmin)/(f_inf - fmax)) - (fmax - fmin))`.
    pub fn tau(&self) -> f64 {
        match self.extent {
            ExponentialExtent::Tau(tau) => tau,
            ExponentialExtent::Len(len) => len as f64 / self.steps_per_tau(),
        }
    }

    /// The time at which the ramp reaches `fmax`, in s.
    pub fn rise_time(&self) -> f64 {
        self.tau() * self.rise_in_tau()
    }
}

/// `f(t) = fmin + (f_inf - fmin)(1 - exp(-t/tau))` up to the rise time, `fmax` after.
pub(crate) struct ExponentialInTime {
    fmin: f64,
    fmax: f64,
    /// The initial acceleration `(f_inf - fmin) / tau`, in Hz/s.
    accel: f64,
    tau: f64,
    rise: f64,
    rise_steps: f64,
}

impl ExponentialInTime {
    pub(crate) fn new(e: &Exponential) -> Self {
        let tau = e.tau();
        ExponentialInTime {
            fmin: e.fmin,
            fmax: e.fmax,
            accel: (e.f_inf - e.fmin) / tau,
            tau,
            rise: e.rise_time(),
            rise_steps: match e.extent {
                // Exactly `len` by construction, without rounding noise.
                ExponentialExtent::Len(len) => len as f64,
                ExponentialExtent::Tau(_) => tau * e.steps_per_tau(),
            },
        }
    }

    /// Steps until `fmax`: `N(t_r) = tau (f_inf ln(...) - (fmax - fmin))`.
    pub(crate) fn ramp_steps(&self) -> f64 {
        self.rise_steps
    }
}

impl TimeCurve for ExponentialInTime {
    fn freq(&self, t: f64) -> f64 {
        if t < self.rise {
            self.fmin + self.accel * t * crate::base::math::exp_fraction(t / self.tau)
        } else {
            self.fmax
        }
    }

    /// `N(t) = fmin t + (f_inf - fmin) tau (t/tau - (1 - e^(-t/tau)))`
    /// `= fmin t + a t² h(t/tau)` with `a = (f_inf - fmin)/tau` and
    /// `h(x) = (x - (1 - e^-x))/x²`, summed as a series where `t/tau` is small:
    /// no cancellation, and no underflow however distant the asymptote.
    fn steps(&self, t: f64) -> f64 {
        if t < self.rise {
            self.fmin * t + self.accel * t * t * crate::base::math::exp_excess_ratio(t / self.tau)
        } else {
            self.rise_steps + self.fmax * (t - self.rise)
        }
    }

    /// `f'` is largest at the start, `(f_inf - fmin) / tau`.
    fn max_slope(&self) -> f64 {
        self.accel
    }

    /// One excess ratio for both: `(1 - e^-x) / x = 1 - x h(x)`.
    fn steps_and_freq(&self, t: f64) -> (f64, f64) {
        if t < self.rise {
            let x = t / self.tau;
            let h = crate::base::math::exp_excess_ratio(x);
            (
                self.fmin * t + self.accel * t * t * h,
                self.fmin + self.accel * t * (1.0 - x * h),
            )
        } else {
            (self.steps(t), self.fmax)
        }
    }

    fn ramp_end(&self) -> (f64, f64) {
        (self.rise, self.rise_steps)
    }

    fn end_freq(&self) -> f64 {
        self.fmax
    }
}

impl CurveKind for Exponential {
    const NAME: &'static str = "exponential";
    type Time = ExponentialInTime;

    fn time(&self) -> ExponentialInTime {
        ExponentialInTime::new(self)
    }

    fn frequencies(&self) -> (f64, f64) {
        (self.fmin, self.fmax)
    }

    fn length(&self, _index: bool) -> Length {
        match self.extent {
            ExponentialExtent::Len(len) => Length::Given(len),
            ExponentialExtent::Tau(_) => Length::Derived {
                steps: ExponentialInTime::new(self).ramp_steps(),
                key: Key::TAU,
                extra: 0,
            },
        }
    }

    fn check(&self, _index: bool) -> Result<(), Error> {
        range(self.fmin, self.fmax)?;
        greater(Key::F_INF, self.f_inf, Key::FMAX, self.fmax)?;
        match self.extent {
            ExponentialExtent::Len(n) => len(n),
            ExponentialExtent::Tau(tau) => positive(Key::TAU, tau),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exponential-ramp article (C8051F040): 500 Hz to 10 000 Hz within 120 steps, asymptote 15 000 Hz.
    #[test]
    fn seed_001_time_constant_and_rise_time() {
        let e = Exponential {
            fmin: 500.0,
            fmax: 10_000.0,
            f_inf: 15_000.0,
            extent: ExponentialExtent::Len(120),
        };
        assert!((e.tau() * 1e3 - 18.545).abs() < 5e-4, "{}", e.tau());
        assert!(
            (e.rise_time() * 1e3 - 19.745).abs() < 5e-4,
            "{}",
            e.rise_time()
        );
        let c = ExponentialInTime::new(&e);
        assert!((c.steps(e.rise_time() * (1.0 - 1e-15)) - 120.0).abs() < 1e-9);
        // The same ramp from its time constant: 120 steps again.
        let by_tau = Exponential {
            extent: ExponentialExtent::Tau(e.tau()),
            ..e
        };
        assert!((ExponentialInTime::new(&by_tau).ramp_steps() - 120.0).abs() < 1e-9);
        assert!((c.freq(e.rise_time() * (1.0 - 1e-12)) - 10_000.0).abs() < 1e-6);
    }
}
