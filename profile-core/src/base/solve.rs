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
    /// `(N(t), f(t))`, for curves whose two share their work. `N` is
    /// exact; `f` only steers the solver, and may be off in its last few
    /// digits.
    fn steps_and_freq(&self, t: f64) -> (f64, f64) {
        (self.steps(t), self.freq(t))
    }
    /// A bound on `|f'|` over the ramp, in Hz/s (infinite where the curve
    /// knows none): with `f >= f0` past an edge, a Newton step of `h` s on
    /// `N` there ends within `|f'| / 2 f0 · h²` of the root ([`Edges`]).
    fn max_slope(&self) -> f64 {
        f64::INFINITY
    }
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
/// `N(lo) <= target <= N(hi)`, from `start` (its left end's Newton step
/// when `start` is not inside the bracket).
///
/// Newton's method on `N` (whose derivative is `f`), safeguarded as in
/// `rtsafe`: a Newton step that leaves the bracket, or that is not at most
/// half the step before it, gives way to bisection (over the floating-point
/// numbers in the bracket). The bracket shrinks every iteration; the root is
/// found to a few ulps or the bracket closes to adjacent numbers. A Newton
/// step of at most `2^-32` of the bracket's first width `w` ends the solve
/// without another evaluation: Newton's error after a step `h` is
/// `|f'| h² / 2f`, at most `(|f'| w / f) w 2^-65`, below an ulp of the
/// result while `f` changes by less than a factor of a thousand over the
/// bracket (and it is never more than a step of `2^-32 w`). Returns `None`
/// if `max_iterations` pass without convergence, the bracket is not a
/// finite interval of non-negative numbers, the curve yields a
/// non-finite value, or `start` is the bracket's right end and `N` falls
/// short of `target` there (the bracket was wrong): never loops without
/// bound. With the root, `f` where the curve was last evaluated, a step or
/// less from it.
pub(crate) fn pulse_time<C: TimeCurve + ?Sized>(
    curve: &C,
    target: f64,
    (mut lo, mut hi): (f64, f64),
    start: Option<f64>,
    max_iterations: u32,
) -> Option<(f64, f64)> {
    if !(lo >= 0.0 && hi >= lo && hi.is_finite()) {
        return None;
    }
    let right = hi;
    let close = (hi - lo) * TWO_POW_MINUS_32;
    let mut t = match start {
        Some(start) if start > lo && start <= hi => start,
        _ => {
            // The left end's Newton step: for the accelerating curves used
            // here it lands close to the root.
            counted();
            let (n_lo, f_lo) = curve.steps_and_freq(lo);
            let guess = lo + (target - n_lo) / f_lo;
            if f_lo > 0.0 && guess > lo && guess < hi {
                guess
            } else {
                midpoint(lo, hi)
            }
        }
    };
    let mut last_step = hi - lo;
    for _ in 0..max_iterations {
        counted();
        let (n, slope) = curve.steps_and_freq(t);
        let g = n - target;
        if !g.is_finite() || !slope.is_finite() || (g < 0.0 && t == right) {
            return None;
        }
        if g == 0.0 {
            return Some((t, slope));
        }
        if g < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let newton = t - g / slope;
        if libm::fabs(newton - t) <= 4.0 * f64::EPSILON * libm::fabs(t) {
            // The step is lost in the last digits of `t`: a root.
            return Some((t, slope));
        }
        let next = if newton > lo && newton < hi && libm::fabs(newton - t) <= 0.5 * last_step {
            newton
        } else {
            let mid = midpoint(lo, hi);
            if mid <= lo || mid >= hi {
                // Adjacent numbers: the root lies between them.
                return Some((if g < 0.0 { hi } else { lo }, slope));
            }
            mid
        };
        let step = libm::fabs(next - t);
        if step <= 4.0 * f64::EPSILON * libm::fabs(t) || (next == newton && step <= close) {
            return Some((next, slope));
        }
        last_step = step;
        t = next;
    }
    None
}

#[cfg(test)]
std::thread_local! {
    /// The curve evaluations [`pulse_time`] has made on this thread.
    pub(crate) static EVALUATIONS: core::cell::Cell<u32> = const { core::cell::Cell::new(0) };
}

/// Counts an evaluation, in tests.
fn counted() {
    #[cfg(test)]
    EVALUATIONS.with(|n| n.set(n.get() + 1));
}

/// `2^-32`.
const TWO_POW_MINUS_32: f64 = 1.0 / 4_294_967_296.0;

/// The exact times of a curve's pulse edges in increasing order, each
/// solved from the one before.
///
/// `f` is non-decreasing, so the step from the edge before (`N = k0`) to
/// edge `k` takes no longer than `(k - k0) / f` at the edge before: the
/// bracket is that narrow (a hair wider, for `f` is known a step or less
/// from that edge). Newton's method, started at its right end, converges in
/// two or three evaluations; where the bracket proves wrong, or the solve
/// fails, the edge is solved on its own ([`edge_time`]).
///
/// Where the curve bounds its slope ([`TimeCurve::max_slope`], `S`), the
/// solve starts from the edge the last two steps predict (each step as
/// much longer or shorter than the one before as that one was than its
/// own), and one Newton step `h` from there is the edge when `K h²` is at
/// most `tolerance`, `K = S / 2 f0` with `f0` at most `f` at the edge
/// before (so on the whole bracket, `f` being non-decreasing): Newton's
/// error after a step of `h` on `N`, whose second derivative is `f'`, is
/// `|f'(ξ)| / 2 f(t) · e²` for the error `e` before it, at most `K e²`, and
/// `e <= h + K e²`, so within `K h² (1 + O(K h))`.
pub(crate) struct Edges<'c> {
    curve: &'c dyn TimeCurve,
    /// The edge before: its step count, its time and `f` there.
    steps: f64,
    time: f64,
    freq: f64,
    /// The two steps before, in s (0 for none).
    last: f64,
    before_last: f64,
    /// `S`, in Hz/s, and the largest error `K h²` taken, in s.
    slope: f64,
    tolerance: f64,
}

impl<'c> Edges<'c> {
    /// The edges of `curve`, from its start, each within `tolerance` s of
    /// the root where one Newton step ends the solve (a few ulps of it
    /// otherwise).
    pub(crate) fn new(curve: &'c dyn TimeCurve, tolerance: f64) -> Self {
        Edges {
            curve,
            steps: 0.0,
            time: 0.0,
            freq: curve.freq(0.0),
            last: 0.0,
            before_last: 0.0,
            slope: curve.max_slope(),
            tolerance,
        }
    }

    /// Edge `steps` in the bracket `(lo, hi]` by one Newton step from the
    /// predicted edge, when that step is short enough to end the solve;
    /// else where the step landed, to start the safeguarded solve from.
    fn predicted(&self, steps: f64, (lo, hi): (f64, f64)) -> Result<(f64, f64), Option<f64>> {
        if !(self.slope.is_finite() && self.before_last > 0.0) {
            return Err(None);
        }
        let step = self.last * (self.last / self.before_last) * (steps - self.steps);
        let start = self.time + step;
        if !(start > lo && start < hi) {
            return Err(None);
        }
        counted();
        let (n, f) = self.curve.steps_and_freq(start);
        let h = (n - steps) / f;
        let next = start - h;
        if !(next > lo && next <= hi) {
            return Err(None);
        }
        if self.slope / (2.0 * self.freq) * h * h <= self.tolerance {
            // `f` at the edge is at least `f(start) - S |start - edge|`,
            // and at least `f` at the edge before: the next bracket's
            // right end must not fall short of the next edge.
            let floor = f - self.slope * (libm::fabs(h) + self.tolerance);
            Ok((next, floor.max(self.freq)))
        } else {
            Err(Some(next))
        }
    }

    /// The time of edge `k`, in s, `k` past the edge before.
    pub(crate) fn time(&mut self, k: u32) -> Result<f64, Error> {
        let c = self.curve;
        let steps = k as f64;
        let (ramp_time, ramp_steps) = c.ramp_end();
        let t = if let Some(t) = c.time_at(steps) {
            self.freq = f64::NAN;
            t
        } else if steps >= ramp_steps {
            self.freq = f64::NAN;
            time_after_ramp(c, steps)
        } else {
            if self.freq.is_nan() {
                self.freq = c.freq(self.time);
            }
            let longest = (steps - self.steps) / self.freq;
            let hi = ramp_time.min(self.time + longest * (1.0 + TWO_POW_MINUS_20));
            let lo = (steps / c.end_freq()).max(self.time).min(hi);
            let solved = match self.predicted(steps, (lo, hi)) {
                Ok(solved) => Some(solved),
                Err(start) => (longest > 0.0 && hi.is_finite())
                    .then(|| pulse_time(c, steps, (lo, hi), start.or(Some(hi)), MAX_ITERATIONS))
                    .flatten(),
            };
            let (t, freq) = match solved {
                Some(solved) => solved,
                None => {
                    let t = edge_time(c, k)?;
                    (t, c.freq(t))
                }
            };
            self.freq = freq;
            t
        };
        (self.before_last, self.last) = (self.last, t - self.time);
        (self.steps, self.time) = (steps, t);
        Ok(t)
    }
}

/// How far from its root an edge may be where one Newton step ends its
/// solve ([`Edges`]), in timer ticks: `2^-30`, a billionth of a tick. An
/// edge rounds otherwise than at its root only within that of a half tick.
pub(crate) const EDGE_TOLERANCE_TICKS: f64 = 1.0 / 1_073_741_824.0;

/// `2^-20`.
const TWO_POW_MINUS_20: f64 = 1.0 / 1_048_576.0;

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
    pulse_time(c, steps, (lo, hi), None, MAX_ITERATIONS)
        .map(|(t, _)| t)
        .ok_or(Error::NoConvergence {
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
        let (t, _) = pulse_time(&Ramp, 3.0, (0.0, 4.0), None, MAX_ITERATIONS).unwrap();
        assert!((t - (-1.0 + 7f64.sqrt())).abs() < 1e-15, "{t}");
    }

    #[test]
    fn iteration_bound_is_enforced() {
        // One iteration cannot reach f64 precision from a wide bracket.
        assert_eq!(pulse_time(&Ramp, 3.0, (0.0, 4.0), None, 1), None);
        assert!(pulse_time(&Ramp, 3.0, (0.0, 4.0), None, 8).is_some());
    }

    #[test]
    fn non_finite_curve_is_an_error_not_a_hang() {
        assert_eq!(
            pulse_time(&Broken, 0.5, (0.0, 1.0), None, MAX_ITERATIONS),
            None
        );
    }
}
