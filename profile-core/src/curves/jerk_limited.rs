//! The jerk-limited (7-segment) S-curve: acceleration rises at `jerk`, holds
//! at `accel`, falls at `jerk` to zero at `fmax`.

use super::check::{positive, range};
use super::kind::{CurveKind, Length};
use crate::base::error::Error;
use crate::base::key::Key;
use crate::base::solve::TimeCurve;

impl Key {
    /// `jerk`: the jerk-limited ramp's jerk, in Hz/s².
    pub const JERK: Key = Key("jerk");
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

/// The ramp's three phases with their closed forms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct JerkInTime {
    f0: f64,
    fmax: f64,
    jerk: f64,
    /// Peak acceleration: `accel`, or lower when `accel` cannot be reached
    /// within the speed change (triangular acceleration).
    pub(crate) peak: f64,
    /// End of the rising-acceleration phase.
    pub(crate) t1: f64,
    /// End of the constant-acceleration phase.
    pub(crate) t2: f64,
    /// End of the ramp.
    pub(crate) t3: f64,
    fa: f64,
    fb: f64,
    na: f64,
    nb: f64,
    n3: f64,
}

impl JerkInTime {
    pub(crate) fn new(j: &JerkLimited) -> Self {
        let dv = j.fmax - j.fmin;
        let peak = j.accel.min(libm::sqrt(j.jerk * dv));
        let t_jerk = peak / j.jerk;
        let t_hold = ((dv - peak * peak / j.jerk) / peak).max(0.0);
        let fa = j.fmin + j.jerk * t_jerk * t_jerk / 2.0;
        let fb = fa + peak * t_hold;
        let mut c = JerkInTime {
            f0: j.fmin,
            fmax: j.fmax,
            jerk: j.jerk,
            peak,
            t1: t_jerk,
            t2: t_jerk + t_hold,
            t3: 2.0 * t_jerk + t_hold,
            fa,
            fb,
            na: 0.0,
            nb: 0.0,
            n3: 0.0,
        };
        let t_hold = c.t2 - c.t1;
        c.na = j.fmin * t_jerk + j.jerk * t_jerk * t_jerk * t_jerk / 6.0;
        c.nb = c.na + fa * t_hold + peak * t_hold * t_hold / 2.0;
        c.n3 = c.nb + fb * t_jerk + peak * t_jerk * t_jerk / 2.0
            - j.jerk * t_jerk * t_jerk * t_jerk / 6.0;
        c
    }

    /// Steps until `fmax`.
    pub(crate) fn ramp_steps(&self) -> f64 {
        self.n3
    }
}

impl TimeCurve for JerkInTime {
    /// `f'` is at most the peak acceleration.
    fn max_slope(&self) -> f64 {
        self.peak
    }

    fn freq(&self, t: f64) -> f64 {
        if t < self.t1 {
            self.f0 + self.jerk * t * t / 2.0
        } else if t < self.t2 {
            self.fa + self.peak * (t - self.t1)
        } else if t < self.t3 {
            let d = t - self.t2;
            (self.fb + self.peak * d - self.jerk * d * d / 2.0).min(self.fmax)
        } else {
            self.fmax
        }
    }

    fn steps(&self, t: f64) -> f64 {
        if t < self.t1 {
            self.f0 * t + self.jerk * t * t * t / 6.0
        } else if t < self.t2 {
            let d = t - self.t1;
            self.na + self.fa * d + self.peak * d * d / 2.0
        } else if t < self.t3 {
            let d = t - self.t2;
            self.nb + self.fb * d + self.peak * d * d / 2.0 - self.jerk * d * d * d / 6.0
        } else {
            self.n3 + self.fmax * (t - self.t3)
        }
    }

    fn ramp_end(&self) -> (f64, f64) {
        (self.t3, self.n3)
    }

    fn end_freq(&self) -> f64 {
        self.fmax
    }
}

impl CurveKind for JerkLimited {
    const NAME: &'static str = "jerk_limited";
    type Time = JerkInTime;

    fn time(&self) -> JerkInTime {
        JerkInTime::new(self)
    }

    fn frequencies(&self) -> (f64, f64) {
        (self.fmin, self.fmax)
    }

    fn length(&self, _index: bool) -> Length {
        Length::Derived {
            steps: JerkInTime::new(self).ramp_steps(),
            key: Key::JERK,
            extra: 0,
        }
    }

    fn check(&self, _index: bool) -> Result<(), Error> {
        range(self.fmin, self.fmax)?;
        positive(Key::ACCEL, self.accel)?;
        positive(Key::JERK, self.jerk)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trapezoidal_acceleration_reaches_fmax_with_zero_acceleration() {
        let c = JerkInTime::new(&JerkLimited {
            fmin: 200.0,
            fmax: 5000.0,
            accel: 20_000.0,
            jerk: 400_000.0,
        });
        assert_eq!(c.peak, 20_000.0);
        assert!(c.t2 > c.t1);
        assert!((c.freq(c.t3 - 1e-12) - 5000.0).abs() < 1e-6);
        assert!((c.freq(c.t1) - c.fa).abs() < 1e-9);
    }

    #[test]
    fn triangular_when_accel_is_out_of_reach() {
        let c = JerkInTime::new(&JerkLimited {
            fmin: 200.0,
            fmax: 1000.0,
            accel: 1e6,
            jerk: 1e6,
        });
        assert!((c.peak - (1e6f64 * 800.0).sqrt()).abs() < 1e-6);
        assert_eq!(c.t1, c.t2);
        assert!((c.freq(c.t3 - 1e-12) - 1000.0).abs() < 1e-6);
    }

    #[test]
    fn step_count_integrates_frequency() {
        let c = JerkInTime::new(&JerkLimited {
            fmin: 200.0,
            fmax: 5000.0,
            accel: 20_000.0,
            jerk: 400_000.0,
        });
        let n = 200_000;
        let h = c.t3 / n as f64;
        let sum: f64 = (0..n).map(|i| c.freq((i as f64 + 0.5) * h) * h).sum();
        assert!((sum - c.n3).abs() < 1e-6, "{sum} {}", c.n3);
    }
}
