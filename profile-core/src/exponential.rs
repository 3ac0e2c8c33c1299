//! The exponential ramp of seed 001.

use crate::solve::TimeCurve;
use crate::spec::{Exponential, ExponentialExtent};

impl Exponential {
    /// `ln((f_inf - fmin) / (f_inf - fmax))`: rise time in units of `tau`.
    fn rise_in_tau(&self) -> f64 {
        libm::log1p((self.fmax - self.fmin) / (self.f_inf - self.fmax))
    }

    /// The time constant, in s: given, or solved so that `fmax` is reached at
    /// the end of step `len`: `tau = len / (f_inf ln((f_inf - fmin)/(f_inf - fmax)) - (fmax - fmin))`.
    pub fn tau(&self) -> f64 {
        match self.extent {
            ExponentialExtent::Tau(tau) => tau,
            ExponentialExtent::Len(len) => {
                len as f64 / (self.f_inf * self.rise_in_tau() - (self.fmax - self.fmin))
            }
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
    f_inf: f64,
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
            f_inf: e.f_inf,
            tau,
            rise: e.rise_time(),
            rise_steps: match e.extent {
                // Exactly `len` by construction, without rounding noise.
                ExponentialExtent::Len(len) => len as f64,
                ExponentialExtent::Tau(_) => tau * (e.f_inf * e.rise_in_tau() - (e.fmax - e.fmin)),
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
            self.fmin - (self.f_inf - self.fmin) * libm::expm1(-t / self.tau)
        } else {
            self.fmax
        }
    }

    fn steps(&self, t: f64) -> f64 {
        if t < self.rise {
            self.f_inf * t + (self.f_inf - self.fmin) * self.tau * libm::expm1(-t / self.tau)
        } else {
            self.rise_steps + self.fmax * (t - self.rise)
        }
    }

    fn ramp_end(&self) -> (f64, f64) {
        (self.rise, self.rise_steps)
    }

    fn end_freq(&self) -> f64 {
        self.fmax
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Seed 001: 500 Hz to 10 000 Hz within 120 steps, asymptote 15 000 Hz.
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
