//! Pulse times from the step count: solve `N(t) = k` for `t`.

use super::error::Error;

/// The iteration bound of [`pulse_time`]. Accepted Newton steps at least
/// halve from one iteration to the next, and each bisection halves the
/// floating-point numbers left in the bracket; on the brackets
/// [`edge_time`] builds the solver ends within a few dozen
/// iterations, usually 3 to 6.
pub(crate) const MAX_ITERATIONS: u32 = 200;

/// A curve defined in time: frequency and step count. After its ramp ends the
/// curve holds its end frequency.
pub(crate) trait TimeCurve {
    /// Step frequency at time `t`, in Hz. Positive and non-decreasing.
    fn freq(&self, t: f64) -> f64;
    /// Steps taken by time `t`: `N(t) = ∫0^t f`.
    fn steps(&self, t: f64) -> f64;
    /// Time and step count at which the ramp reaches its end frequency.
    fn ramp_end(&self) -> (f64, f64);
    /// The frequency held after the ramp.
    fn end_freq(&self) -> f64;
    /// The time of step `k` in closed form, where the curve has one.
    fn time_at(&self, _k: f64) -> Option<f64> {
        None
    }
}

/// The time at which `N` reaches `steps`, for `steps` at or past the ramp's end.
pub(crate) fn time_after_ramp<C: TimeCurve + ?Sized>(curve: &C, steps: f64) -> f64 {
    let (t, n) = curve.ramp_end();
    if steps <= n {
        t
    } else {
        t + (steps - n) / curve.end_freq()
    }
}

/// The midpoint of `[lo, hi]` (both `>= 0`) in floating-point numbers: as
/// many representable values on either side (near the geometric mean for a
/// wide bracket, the arithmetic one for a narrow one), so that bisection ends
/// within 64 halvings however wide the bracket is.
fn midpoint(lo: f64, hi: f64) -> f64 {
    let (a, b) = (lo.to_bits(), hi.to_bits());
    f64::from_bits(a + (b - a) / 2)
}

/// Solves `N(t) = target` for `t` in `[lo, hi]`, where `0 <= lo`,
/// `N(lo) <= target <= N(hi)`.
///
/// Newton's method on `N` (whose derivative is `f`), safeguarded as in
/// `rtsafe`: a Newton step that leaves the bracket, or that is not at most
/// half the step before it, gives way to bisection (over the floating-point
/// numbers in the bracket). The bracket shrinks every iteration; the root is
/// found to a few ulps or the bracket closes to adjacent numbers. Returns
/// `None` if `max_iterations` pass without convergence, the bracket is not a
/// finite interval of non-negative numbers, or the curve yields a non-finite
/// value: never loops without bound.
pub(crate) fn pulse_time<C: TimeCurve + ?Sized>(
    curve: &C,
    target: f64,
    mut lo: f64,
    mut hi: f64,
    max_iterations: u32,
) -> Option<f64> {
    if !(lo >= 0.0 && hi >= lo && hi.is_finite()) {
        return None;
    }
    let mut t = midpoint(lo, hi);
    // Start from the left end's Newton step: for the accelerating curves used
    // here it lands close to the root.
    let f_lo = curve.freq(lo);
    if f_lo > 0.0 {
        let guess = lo + (target - curve.steps(lo)) / f_lo;
        if guess > lo && guess < hi {
            t = guess;
        }
    }
    let mut last_step = hi - lo;
    for _ in 0..max_iterations {
        let g = curve.steps(t) - target;
        let slope = curve.freq(t);
        if !g.is_finite() || !slope.is_finite() {
            return None;
        }
        if g == 0.0 {
            return Some(t);
        }
        if g < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let newton = t - g / slope;
        let next = if newton > lo && newton < hi && libm::fabs(newton - t) <= 0.5 * last_step {
            newton
        } else {
            let mid = midpoint(lo, hi);
            if mid <= lo || mid >= hi {
                // Adjacent numbers: the root lies between them.
                return Some(if g < 0.0 { hi } else { lo });
            }
            mid
        };
        let step = libm::fabs(next - t);
        if step <= 4.0 * f64::EPSILON * libm::fabs(t) {
            return Some(next);
        }
        last_step = step;
        t = next;
    }
    None
}

/// The exact time of pulse edge `k` (when `N(t) = k`), in s.
pub(crate) fn edge_time(c: &dyn TimeCurve, k: u32) -> Result<f64, Error> {
    let steps = k as f64;
    if let Some(t) = c.time_at(steps) {
        return Ok(t);
    }
    let (ramp_time, ramp_steps) = c.ramp_end();
    if steps >= ramp_steps {
        return Ok(time_after_ramp(c, steps));
    }
    // f is non-decreasing from f(0) to the end frequency, so edge k is no
    // earlier than k / f_end and no later than k / f(0).
    let hi = ramp_time.min(steps / c.freq(0.0));
    let lo = (steps / c.end_freq()).min(hi);
    pulse_time(c, steps, lo, hi, MAX_ITERATIONS).ok_or(Error::NoConvergence {
        index: k,
        iterations: MAX_ITERATIONS,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `f(t) = 1 + t`, `N(t) = t + t²/2`.
    struct Ramp;
    impl TimeCurve for Ramp {
        fn freq(&self, t: f64) -> f64 {
            1.0 + t
        }
        fn steps(&self, t: f64) -> f64 {
            t + t * t / 2.0
        }
        fn ramp_end(&self) -> (f64, f64) {
            (2.0, 4.0)
        }
        fn end_freq(&self) -> f64 {
            3.0
        }
    }

    /// A curve whose step count is NaN: the solver must give up, not loop.
    struct Broken;
    impl TimeCurve for Broken {
        fn freq(&self, _: f64) -> f64 {
            1.0
        }
        fn steps(&self, _: f64) -> f64 {
            f64::NAN
        }
        fn ramp_end(&self) -> (f64, f64) {
            (1.0, 1.0)
        }
        fn end_freq(&self) -> f64 {
            1.0
        }
    }

    #[test]
    fn converges_to_the_closed_form() {
        // t + t²/2 = 3  =>  t = -1 + sqrt(7)
        let t = pulse_time(&Ramp, 3.0, 0.0, 4.0, MAX_ITERATIONS).unwrap();
        assert!((t - (-1.0 + 7f64.sqrt())).abs() < 1e-15, "{t}");
    }

    #[test]
    fn iteration_bound_is_enforced() {
        // One iteration cannot reach f64 precision from a wide bracket.
        assert_eq!(pulse_time(&Ramp, 3.0, 0.0, 4.0, 1), None);
        assert!(pulse_time(&Ramp, 3.0, 0.0, 4.0, 8).is_some());
    }

    #[test]
    fn non_finite_curve_is_an_error_not_a_hang() {
        assert_eq!(pulse_time(&Broken, 0.5, 0.0, 1.0, MAX_ITERATIONS), None);
    }
}
