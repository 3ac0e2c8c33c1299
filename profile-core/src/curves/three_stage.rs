//! The exponential-linear-parabolic curve of Zeng, Hu and Hu.

use super::check::{finite, greater, positive};
use super::kind::{CurveKind, Length};
use crate::base::error::Error;
use crate::base::key::Key;
use crate::base::solve::TimeCurve;

impl Key {
    /// `f1`: where the three-stage curve's exponential stage ends, in Hz.
    pub const F1: Key = Key("f1");
    /// `f2`: where its linear stage ends, in Hz.
    pub const F2: Key = Key("f2");
    /// `shape`: its exponential stage's shape `B`, in 1/s.
    pub const SHAPE: Key = Key("shape");
}

/// The three-stage curve of Zeng, Hu and Hu ("Control Algorithm of
/// Acceleration Curve for Stepper Motor", 2016): exponential up to `f1`,
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

impl ThreeStage {
    /// `a + B (f1 - f0)`, the acceleration at the start, in Hz/s, to its
    /// own precision: near the bound of `B` the plain formula leaves only
    /// the rounding of `B (f1 - f0)` (at 1e-12 from the bound an edge moved
    /// 3 ticks, at 1e-14 over 500).
    fn start_gap(&self) -> f64 {
        crate::base::math::gap_after(self.accel, self.shape, self.f1, self.fmin)
    }
}

/// The curve with its joints solved (DESIGN section 2):
/// `C = f1 - f0 + a/B`, `t1 = ln(1 + B (f1 - f0)/a) / B`, `t2 = t1 + (f2 - f1)/a`,
/// `b = a² / (4 (fc - f2))`, `tc = t2 + 2 (fc - f2)/a` (the paper's `a/4b`
/// would break slope continuity; `a/2b` is right).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct ThreeStageInTime {
    f0: f64,
    f1: f64,
    f2: f64,
    fc: f64,
    a: f64,
    shape: f64,
    start: f64,
    c: f64,
    b: f64,
    pub(crate) t1: f64,
    pub(crate) t2: f64,
    pub(crate) tc: f64,
    n1: f64,
    n2: f64,
    nc: f64,
}

impl ThreeStageInTime {
    pub(crate) fn new(s: &ThreeStage) -> Self {
        let (f0, f1, f2, fc, a, shape) = (s.fmin, s.f1, s.f2, s.fmax, s.accel, s.shape);
        // `B C = a + B (f1 - f0)`, the acceleration at the start, vanishes
        // as `B` nears its bound `-a/(f1 - f0)`: it is kept to its own
        // digits, since `C`, `t1` and the stage's steps all follow from it.
        let start = s.start_gap();
        let c = start / shape;
        let t1 = if start < 0.5 * a {
            libm::log(start / a) / shape
        } else {
            libm::log1p(shape * (f1 - f0) / a) / shape
        };
        let t2 = t1 + (f2 - f1) / a;
        let b = a * a / (4.0 * (fc - f2));
        let tc = t2 + 2.0 * (fc - f2) / a;
        let mut curve = ThreeStageInTime {
            f0,
            f1,
            f2,
            fc,
            a,
            shape,
            start,
            c,
            b,
            t1,
            t2,
            tc,
            n1: 0.0,
            n2: 0.0,
            nc: 0.0,
        };
        // Each stage's count starts where the previous one ends.
        curve.n1 = curve.stage1_steps(t1);
        let d = t2 - t1;
        curve.n2 = curve.n1 + f1 * d + a * d * d / 2.0;
        curve.nc = curve.n2 + curve.parabola_steps(tc - t2);
        curve
    }

    /// `N1(t) = (f0 + C) t + C (exp(-Bt) - 1)/B`, written without the
    /// cancellation of two huge terms when `B` is small (`C ~ a/B`):
    /// `N1 = f0 t + (a + B (f1 - f0)) t² h(Bt)` with `h(x) = (x + expm1(-x))/x²`.
    fn stage1_steps(&self, t: f64) -> f64 {
        let h = crate::base::math::exp_excess_ratio(self.shape * t);
        self.f0 * t + self.start * t * t * h
    }

    /// The parabola's steps `d` after `t2`: `∫ fc - b (u - tc)² du` over
    /// `[t2, t2 + d]`, as `d (f2 + a d / 2 - b d² / 3)` (with `fc - b (t2 -
    /// tc)² = f2` and `2 b (tc - t2) = a`), and `b d²` as `(a d)² / 4 (fc -
    /// f2)`: no cancellation of the two cubes `b (t - tc)³ / 3` where `fc`
    /// is far above the ramp, and finite wherever the ramp is.
    fn parabola_steps(&self, d: f64) -> f64 {
        let ad = self.a * d;
        d * (self.f2 + ad / 2.0 - ad * ad / (12.0 * (self.fc - self.f2)))
    }

    /// Steps until `fmax`.
    pub(crate) fn ramp_steps(&self) -> f64 {
        // A ramp that never ends (an acceleration so small the time to
        // `fmax` is not a float) has no count: as long as a float counts.
        if self.tc.is_finite() {
            self.nc
        } else {
            f64::INFINITY
        }
    }

    /// Acceleration `df/dt` at `t`, in Hz/s.
    #[cfg(test)]
    pub(crate) fn accel(&self, t: f64) -> f64 {
        if t < self.t1 {
            self.shape * self.c * libm::exp(-self.shape * t)
        } else if t < self.t2 {
            self.a
        } else if t < self.tc {
            -2.0 * self.b * (t - self.tc)
        } else {
            0.0
        }
    }
}

impl TimeCurve for ThreeStageInTime {
    /// `f'` runs from `start` (the exponential's slope at 0) to `a` over the
    /// first stage, holds `a`, then falls to 0: at most the larger of the
    /// two.
    fn max_slope(&self) -> f64 {
        self.start.max(self.a)
    }

    fn freq(&self, t: f64) -> f64 {
        if t < self.t1 {
            self.f0 - self.c * libm::expm1(-self.shape * t)
        } else if t < self.t2 {
            self.f1 + self.a * (t - self.t1)
        } else if t < self.tc {
            // `b d²` as `(a d)² / 4 (fc - f2)`: `b` overflows for a huge `a`
            // while `a d` stays within `2 (fc - f2)`. In the stage's first
            // half from `f2` up (`f2 + a d - b d²`, `d` after `t2`), in its
            // second from `fc` down: neither cancels where `fc` is far from
            // `f`.
            let four_gap = 4.0 * (self.fc - self.f2);
            if t - self.t2 < self.tc - t {
                let ad = self.a * (t - self.t2);
                self.f2 + ad - ad * ad / four_gap
            } else {
                let ad = self.a * (t - self.tc);
                self.fc - ad * ad / four_gap
            }
        } else {
            self.fc
        }
    }

    fn steps(&self, t: f64) -> f64 {
        if t < self.t1 {
            self.stage1_steps(t)
        } else if t < self.t2 {
            let d = t - self.t1;
            self.n1 + self.f1 * d + self.a * d * d / 2.0
        } else if t < self.tc {
            self.n2 + self.parabola_steps(t - self.t2)
        } else {
            self.nc + self.fc * (t - self.tc)
        }
    }

    fn ramp_end(&self) -> (f64, f64) {
        (self.tc, self.nc)
    }

    fn end_freq(&self) -> f64 {
        self.fc
    }
}

impl CurveKind for ThreeStage {
    const NAME: &'static str = "three_stage";
    type Time = ThreeStageInTime;

    fn time(&self) -> ThreeStageInTime {
        ThreeStageInTime::new(self)
    }

    fn frequencies(&self) -> (f64, f64) {
        (self.fmin, self.fmax)
    }

    fn length(&self, _index: bool) -> Length {
        Length::Derived {
            steps: ThreeStageInTime::new(self).ramp_steps(),
            key: Key::ACCEL,
            extra: 0,
        }
    }

    fn check(&self, _index: bool) -> Result<(), Error> {
        positive(Key::FMIN, self.fmin)?;
        greater(Key::F1, self.f1, Key::FMIN, self.fmin)?;
        finite(Key::F2, self.f2)?;
        if self.f2 < self.f1 {
            return Err(Error::NotAtLeast {
                key: Key::F2,
                value: self.f2,
                other: Key::F1,
                other_value: self.f1,
            });
        }
        greater(Key::FMAX, self.fmax, Key::F2, self.f2)?;
        positive(Key::ACCEL, self.accel)?;
        finite(Key::SHAPE, self.shape)?;
        if self.shape == 0.0 {
            return Err(Error::Zero { key: Key::SHAPE });
        }
        let min_shape = -self.accel / (self.f1 - self.fmin);
        if self.shape <= min_shape || self.start_gap() <= 0.0 {
            return Err(Error::TooSmall {
                key: Key::SHAPE,
                value: self.shape,
                min: min_shape,
                why: ", that is -accel / (f1 - fmin), for a concave start",
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn zeng(shape: f64) -> ThreeStageInTime {
        ThreeStageInTime::new(&ThreeStage {
            fmin: 100.0,
            fmax: 1200.0,
            accel: 4000.0,
            f1: 400.0,
            f2: 900.0,
            shape,
        })
    }

    /// Value and slope continuous at both joints; zero acceleration at `fc`.
    #[test]
    fn joints_are_smooth() {
        for shape in [12.0, -5.0] {
            let c = zeng(shape);
            for t in [c.t1, c.t2] {
                let h = 1e-9;
                assert!((c.freq(t - h) - c.freq(t + h)).abs() < 1e-4, "f at {t}");
                let slope_left = (c.freq(t - h) - c.freq(t - 2.0 * h)) / h;
                let slope_right = (c.freq(t + 2.0 * h) - c.freq(t + h)) / h;
                assert!(
                    (slope_left - slope_right).abs() < 1.0,
                    "{slope_left} {slope_right}"
                );
                assert!((c.accel(t - 1e-12) - c.accel(t + 1e-12)).abs() < 1e-3);
            }
            assert!((c.freq(c.t1) - 400.0).abs() < 1e-9);
            assert!((c.freq(c.t2) - 900.0).abs() < 1e-9);
            assert!(c.accel(c.tc - 1e-12).abs() < 1e-6);
            assert!((c.freq(c.tc) - 1200.0).abs() < 1e-9);
        }
    }

    /// The closed-form step count is the integral of the frequency.
    #[test]
    fn step_count_integrates_frequency() {
        let c = zeng(12.0);
        let n = 200_000;
        let h = c.tc / n as f64;
        let mut sum = 0.0;
        for i in 0..n {
            sum += c.freq((i as f64 + 0.5) * h) * h;
        }
        assert!(
            (sum - c.steps(c.tc)).abs() < 1e-6,
            "{sum} {}",
            c.steps(c.tc)
        );
    }

    /// An acceleration whose square overflows still gives a finite ramp:
    /// the stages take next to no time, the steps are those of the first
    /// stage's instant rise, and the frequency stays within `fmin..=fmax`.
    #[test]
    fn a_huge_acceleration_keeps_the_ramp_finite() {
        for accel in [1e10, 1e160, 1e200, 1e300] {
            let c = ThreeStageInTime::new(&ThreeStage {
                fmin: 100.0,
                fmax: 5000.0,
                accel,
                f1: 1000.0,
                f2: 3000.0,
                shape: 5.0,
            });
            let n = c.ramp_steps();
            assert!(n.is_finite() && (0.0..1e-2).contains(&n), "{accel}: {n}");
            for t in [c.t1, (c.t2 + c.tc) / 2.0, c.tc, 2.0 * c.tc] {
                let f = c.freq(t);
                assert!((100.0..=5000.0).contains(&f), "{accel}: f({t}) = {f}");
            }
        }
    }
}
