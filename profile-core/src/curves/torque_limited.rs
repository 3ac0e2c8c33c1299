//! The fastest ramp a motor allows: at every speed the largest acceleration
//! its torque leaves, less a margin.

use super::check::{finite, positive, range};
use super::kind::{CurveKind, Length};
use crate::base::error::Error;
use crate::base::key::Key;
use crate::base::math::{exp_excess_ratio, exp_fraction};
use crate::base::solve::TimeCurve;

impl Key {
    /// `margin`: the share of the motor's pull-out torque (after `safety`)
    /// a `torque_limited` ramp plans on, above 0 and at most 0.99.
    pub const MARGIN: Key = Key("margin");
}

/// The largest `margin`: a motor's torque with nothing kept back (its
/// safety factor aside).
pub const MAX_MARGIN: f64 = 0.99;

/// The most points an [`AccelCurve`] holds: a torque curve's 32 and the
/// ramp's two ends.
pub const MAX_ACCEL_POINTS: usize = 34;

/// Acceleration against step frequency, `(Hz, Hz/s)` points with rising
/// frequencies and straight lines between them: what a motor's torque
/// leaves for accelerating at each speed
/// (`Motor::torque_limited` of the host crate, profile-codegen, makes
/// it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AccelCurve {
    points: [(f64, f64); MAX_ACCEL_POINTS],
    len: usize,
}

impl AccelCurve {
    /// No points.
    pub const EMPTY: AccelCurve = AccelCurve {
        points: [(0.0, 0.0); MAX_ACCEL_POINTS],
        len: 0,
    };

    /// The curve through `points`, `(step frequency in Hz, acceleration in
    /// Hz/s)`; `None` for no points or more than [`MAX_ACCEL_POINTS`]
    /// (their values are checked with the curve, [`TorqueLimited`]).
    pub fn new(points: &[(f64, f64)]) -> Option<AccelCurve> {
        if points.is_empty() || points.len() > MAX_ACCEL_POINTS {
            return None;
        }
        let mut curve = AccelCurve::EMPTY;
        curve.points[..points.len()].copy_from_slice(points);
        curve.len = points.len();
        Some(curve)
    }

    /// The points.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points[..self.len]
    }

    /// The acceleration at `hz`, in Hz/s, on the straight line between the
    /// points around it (the first or last point's beyond them).
    pub fn at(&self, hz: f64) -> f64 {
        let p = self.points();
        let Some(&(f0, a0)) = p.first() else {
            return 0.0;
        };
        if hz <= f0 {
            return a0;
        }
        for w in p.windows(2) {
            let ((fa, aa), (fb, ab)) = (w[0], w[1]);
            if hz <= fb {
                return aa + (ab - aa) * (hz - fa) / (fb - fa);
            }
        }
        p[p.len() - 1].1
    }
}

/// The fastest ramp a motor allows, with a margin: from `fmin` to `fmax`
/// the step frequency rises at `df/dt = a(f)`, the acceleration
/// [`AccelCurve`] gives at each frequency. From a motor
/// (`Motor::torque_limited` of the host crate, profile-codegen),
/// `a(f) = (s · margin · pull-out torque(f') / safety - friction - damping
/// · θ · f') / (J · θ)`, `θ` the angle of a table step, `J` the rotor's and
/// the load's inertia, `f'` one step's gain of speed ahead of `f` (where
/// the check judges the step) and `s` the largest share of the torque,
/// from 1 down to 0.8, with which the table on its timer passes: at every
/// speed all the torque the motor gives at `margin` times its own (the
/// same sums the motor check makes), so the table passes the check of the
/// motor with `safety / margin`, and no ramp that passes it is faster at
/// any speed.
///
/// Between two points of the acceleration curve, `a` is a straight line in
/// `f`, `a(f) = a_0 + s (f - f_0)`, and the ramp is solved in closed form:
/// `f(t) = f_0 + a_0 t (e^(st) - 1)/(st)`, an exponential towards where the
/// motor would have nothing left to spare (or a straight line where `s` is
/// 0).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TorqueLimited {
    /// Start frequency, in Hz.
    pub fmin: f64,
    /// End frequency, in Hz.
    pub fmax: f64,
    /// The share of the pull-out torque the ramp plans on, above 0 and at
    /// most [`MAX_MARGIN`] (as given; `accel` is already made with it).
    pub margin: f64,
    /// The acceleration at each frequency, covering `fmin` to `fmax`.
    pub accel: AccelCurve,
}

/// One stretch of the ramp, between two points of the acceleration curve.
#[derive(Clone, Copy, Debug, Default)]
struct Stretch {
    /// Frequency and acceleration at its start.
    f0: f64,
    a0: f64,
    /// The acceleration's slope in frequency, 1/s.
    slope: f64,
    /// When it starts, and the steps taken by then.
    t0: f64,
    n0: f64,
}

impl Stretch {
    /// Frequency `t` seconds into the stretch.
    fn freq(&self, t: f64) -> f64 {
        // (e^(st) - 1) / (st) = exp_fraction(-st).
        self.f0 + self.a0 * t * exp_fraction(-self.slope * t)
    }

    /// Steps taken `t` seconds into the stretch: `f_0 t + a_0 t² (e^(st) - 1
    /// - st)/(st)²`.
    fn steps(&self, t: f64) -> f64 {
        self.f0 * t + self.a0 * t * t * exp_excess_ratio(-self.slope * t)
    }
}

/// `ln(1 + y) / y` (1 at 0), without the cancellation of `ln(1 + y)` for
/// small `y`.
fn log1p_ratio(y: f64) -> f64 {
    if libm::fabs(y) < 1e-4 {
        1.0 - y / 2.0 + y * y / 3.0 - y * y * y / 4.0
    } else {
        libm::log1p(y) / y
    }
}

/// The ramp in time: its stretches.
pub(crate) struct TorqueLimitedInTime {
    stretches: [Stretch; MAX_ACCEL_POINTS],
    len: usize,
    fmax: f64,
    end: (f64, f64),
}

impl TorqueLimitedInTime {
    pub(crate) fn new(c: &TorqueLimited) -> Self {
        let mut out = TorqueLimitedInTime {
            stretches: [Stretch::default(); MAX_ACCEL_POINTS],
            len: 0,
            fmax: c.fmax,
            end: (0.0, 0.0),
        };
        let (mut t, mut n) = (0.0, 0.0);
        let mut f = c.fmin;
        let mut a = c.accel.at(f);
        for &(fb, ab) in c.accel.points() {
            if fb <= f {
                continue;
            }
            let to = fb.min(c.fmax);
            let slope = (ab - a) / (fb - f);
            let b = a + slope * (to - f);
            // a(f) = a_0 e^(st): the time to reach `to`, ln(b / a_0) / s.
            let span = (to - f) / a * log1p_ratio(slope * (to - f) / a);
            let s = Stretch {
                f0: f,
                a0: a,
                slope,
                t0: t,
                n0: n,
            };
            if out.len < MAX_ACCEL_POINTS {
                out.stretches[out.len] = s;
                out.len += 1;
            }
            n += s.steps(span);
            t += span;
            (f, a) = (to, b);
            if to >= c.fmax {
                break;
            }
        }
        out.end = (t, n);
        out
    }

    /// Steps until `fmax`.
    pub(crate) fn ramp_steps(&self) -> f64 {
        self.end.1
    }

    /// The stretch that holds time `t` (the last one past its end).
    fn at(&self, t: f64) -> Option<&Stretch> {
        let stretches = &self.stretches[..self.len];
        let i = stretches.partition_point(|s| s.t0 <= t);
        stretches.get(i.saturating_sub(1))
    }
}

impl TimeCurve for TorqueLimitedInTime {
    fn freq(&self, t: f64) -> f64 {
        if t >= self.end.0 {
            return self.fmax;
        }
        match self.at(t) {
            Some(s) => s.freq(t - s.t0).min(self.fmax),
            None => self.fmax,
        }
    }

    fn steps(&self, t: f64) -> f64 {
        if t >= self.end.0 {
            return self.end.1 + self.fmax * (t - self.end.0);
        }
        match self.at(t) {
            Some(s) => s.n0 + s.steps(t - s.t0),
            None => self.end.1,
        }
    }

    fn ramp_end(&self) -> (f64, f64) {
        self.end
    }

    fn end_freq(&self) -> f64 {
        self.fmax
    }
}

impl CurveKind for TorqueLimited {
    const NAME: &'static str = "torque_limited";
    type Time = TorqueLimitedInTime;

    fn time(&self) -> TorqueLimitedInTime {
        TorqueLimitedInTime::new(self)
    }

    fn frequencies(&self) -> (f64, f64) {
        (self.fmin, self.fmax)
    }

    fn length(&self, _index: bool) -> Length {
        Length::Derived {
            steps: TorqueLimitedInTime::new(self).ramp_steps(),
            key: Key::FMAX,
            extra: 0,
        }
    }

    fn check(&self, _index: bool) -> Result<(), Error> {
        range(self.fmin, self.fmax)?;
        positive(Key::MARGIN, self.margin)?;
        if self.margin > MAX_MARGIN {
            return Err(Error::TooLarge {
                key: Key::MARGIN,
                value: self.margin,
                max: MAX_MARGIN,
            });
        }
        let points = self.accel.points();
        let covers = points.first().is_some_and(|p| p.0 <= self.fmin)
            && points.last().is_some_and(|p| p.0 >= self.fmax);
        let rising = points.windows(2).all(|w| w[1].0 > w[0].0);
        if !covers || !rising {
            return Err(Error::AccelCurve {
                hz: points.first().map_or(f64::NAN, |p| p.0),
                accel: f64::NAN,
            });
        }
        for &(hz, accel) in points {
            finite(Key::FMAX, hz)?;
            if !(accel.is_finite() && accel > 0.0) {
                return Err(Error::AccelCurve { hz, accel });
            }
        }
        // An acceleration so small against the frequency that the ramp
        // would take forever to pass it.
        let (t, n) = TorqueLimitedInTime::new(self).ramp_end();
        if !(t.is_finite() && n.is_finite()) {
            let slowest = points
                .iter()
                .copied()
                .fold(
                    (self.fmax, f64::INFINITY),
                    |a, p| if p.1 < a.1 { p } else { a },
                );
            return Err(Error::AccelCurve {
                hz: slowest.0,
                accel: slowest.1,
            });
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ramp(points: &[(f64, f64)], fmin: f64, fmax: f64) -> TorqueLimitedInTime {
        TorqueLimitedInTime::new(&TorqueLimited {
            fmin,
            fmax,
            margin: 0.5,
            accel: AccelCurve::new(points).unwrap(),
        })
    }

    /// A constant acceleration is a linear ramp: `f = fmin + a t`,
    /// `N = fmin t + a t²/2`.
    #[test]
    fn a_flat_acceleration_is_a_linear_ramp() {
        let c = ramp(&[(100.0, 2000.0), (1100.0, 2000.0)], 100.0, 1100.0);
        let (t, n) = c.ramp_end();
        assert!((t - 0.5).abs() < 1e-15, "{t}");
        assert!((n - (100.0 * 0.5 + 1000.0 * 0.25)).abs() < 1e-9, "{n}");
        assert!((c.freq(0.25) - 600.0).abs() < 1e-12);
        assert!((c.steps(0.25) - (25.0 + 62.5)).abs() < 1e-12);
    }

    /// A falling acceleration, `a = a_0 - k (f - f_0)`: `f` approaches
    /// `f_0 + a_0 / k` as `1 - e^(-kt)`, and the time to `f` is
    /// `ln(a_0 / a(f)) / k`.
    #[test]
    fn a_falling_acceleration_is_an_exponential_approach() {
        // a = 4000 - 2 (f - 200): nothing left at 2200 Hz.
        let c = ramp(&[(200.0, 4000.0), (2200.0, 0.0)], 200.0, 1200.0);
        let k = 2.0;
        let t_end = (4000.0f64 / 2000.0).ln() / k;
        assert!((c.ramp_end().0 - t_end).abs() < 1e-15);
        for t in [0.01, 0.1, 0.3] {
            let f = 200.0 + 2000.0 * (1.0 - (-k * t).exp());
            assert!((c.freq(t) - f).abs() < 1e-9, "{t}");
            let n = 200.0 * t + 2000.0 * (t - (1.0 - (-k * t).exp()) / k);
            assert!((c.steps(t) - n).abs() < 1e-9, "{t}");
        }
    }
}
