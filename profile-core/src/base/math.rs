//! Elementary functions written without cancellation, shared by the curves.
//!
//! Step counts of the exponential and three-stage curves subtract two nearly
//! equal terms where the curve is almost linear (`t / tau` small); these
//! functions return the difference itself, to full relative precision, from
//! a series where the direct formula would cancel.

/// `(x + expm1(-x)) / x² = 1/2 - x/6 + x²/24 - ...`, for any `x` (1/2 at 0).
///
/// Below `|x| = 1` the direct formula loses up to all its digits; there the
/// series (alternating for `x > 0`) is summed until its terms no longer
/// change the sum. Beyond, the two terms of the numerator differ by at least
/// a factor of 2.7.
pub(crate) fn exp_excess_ratio(x: f64) -> f64 {
    if libm::fabs(x) < 1.0 {
        // Σ_{n≥2} (-x)^(n-2) / n!
        let mut term = 0.5;
        let mut sum = term;
        let mut n = 2.0;
        while n < 40.0 {
            n += 1.0;
            term *= -x / n;
            let next = sum + term;
            if next == sum {
                break;
            }
            sum = next;
        }
        sum
    } else {
        (x + libm::expm1(-x)) / (x * x)
    }
}

/// `(1 - e^-x) / x = -expm1(-x) / x = 1 - x/2 + x²/6 - ...`, for any `x`
/// (1 at 0): the exponential's rise per unit of its argument, which stays
/// representable where `x` is so small that a product with it would not.
pub(crate) fn exp_fraction(x: f64) -> f64 {
    if libm::fabs(x) < 1e-8 {
        // The next term, x²/6, is below 2e-17.
        1.0 - x / 2.0
    } else {
        -libm::expm1(-x) / x
    }
}

/// `(-ln(1 - q) - q) / q = q/2 + q²/3 + q³/4 + ...`, for `0 < q < 1`.
///
/// Below `q = 1/2` the series is summed (the direct formula would cancel as
/// `2/q`); from `1/2` on the difference is at least a quarter of `-ln(1 - q)`.
/// Divided by `q` so that a tiny `q` does not underflow in `q²`.
pub(crate) fn log_excess_ratio(q: f64) -> f64 {
    if q < 0.5 {
        let mut power = q;
        let mut sum = power / 2.0;
        let mut n = 2.0;
        while n < 80.0 {
            n += 1.0;
            power *= q;
            let next = sum + power / n;
            if next == sum {
                break;
            }
            sum = next;
        }
        sum
    } else {
        (-libm::log1p(-q) - q) / q
    }
}

/// `ln(1 + e^x)` without overflow or loss for large `|x|`.
pub(crate) fn softplus(x: f64) -> f64 {
    if x > 0.0 {
        x + libm::log1p(libm::exp(-x))
    } else {
        libm::log1p(libm::exp(x))
    }
}

/// `1 / (1 + e^-x)`.
pub(crate) fn logistic(x: f64) -> f64 {
    1.0 / (1.0 + libm::exp(-x))
}

/// `(s, e)` with `s = x + y` rounded and `s + e = x + y` exactly (Knuth's
/// two-sum), for finite `x`, `y` whose sum does not overflow.
fn two_sum(x: f64, y: f64) -> (f64, f64) {
    let s = x + y;
    let v = s - x;
    (s, (x - (s - v)) + (y - v))
}

/// `(p, e)` with `p = x y` rounded and `p + e = x y` exactly (Dekker's
/// product, splitting each factor into two 26-bit halves: no fused
/// multiply-add, so every target computes the same bits), for factors well
/// inside the float range.
fn two_product(x: f64, y: f64) -> (f64, f64) {
    fn split(x: f64) -> (f64, f64) {
        let c = 134_217_729.0 * x; // 2^27 + 1
        let hi = c - (c - x);
        (hi, x - hi)
    }
    let p = x * y;
    let ((xh, xl), (yh, yl)) = (split(x), split(y));
    (p, ((xh * yh - p) + xh * yl + xl * yh) + xl * yl)
}

/// `a + b (x - y)` to within an ulp or two of the result itself, however
/// nearly `b (x - y)` cancels `a`: the difference and the product are
/// carried with their rounding errors, which the plain formula loses. Where
/// a factor is too large to split (beyond 1e290 or so) there is nothing
/// near enough to cancel, and the plain formula is returned.
pub(crate) fn gap_after(a: f64, b: f64, x: f64, y: f64) -> f64 {
    let plain = a + b * (x - y);
    let (d, d_err) = two_sum(x, -y);
    let (p, p_err) = two_product(b, d);
    let (s, s_err) = two_sum(a, p);
    let exact = s + (s_err + (p_err + b * d_err));
    if exact.is_finite() { exact } else { plain }
}

/// `softplus(s0 + d) - softplus(s0)` for `d >= 0`, `s0` fixed: the
/// integral of the logistic over `[s0, s0 + d]`.
///
/// Written as `ln(1 + logistic(s0) · expm1(d))`, which keeps full relative
/// precision when `d` is small (a flat sigmoid, or the first steps of any
/// sigmoid), where the difference of two softplus values would cancel. For
/// `d` large enough to overflow `expm1`, the two values differ by far more
/// than their rounding, and the difference is taken directly. `logistic(s0)`
/// is worked out once, for every `d` a pulse-time solve tries.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SoftplusRise {
    s0: f64,
    logistic_s0: f64,
    exp_s0: f64,
}

impl SoftplusRise {
    pub(crate) fn new(s0: f64) -> Self {
        SoftplusRise {
            s0,
            logistic_s0: logistic(s0),
            exp_s0: libm::exp(s0),
        }
    }

    /// The rise over `[s0, s0 + d]`.
    pub(crate) fn over(&self, d: f64) -> f64 {
        self.over_with_logistic(d).0
    }

    /// The rise over `[s0, s0 + d]` and the logistic at `s0 + d` (the
    /// softplus's slope there), from one exponential: the rise exact, the
    /// logistic within a few ulps.
    pub(crate) fn over_with_logistic(&self, d: f64) -> (f64, f64) {
        if d < 700.0 {
            let rise = libm::expm1(d);
            // e^(s0 + d) = e^s0 (1 + expm1(d)): finite below d = 700 for
            // the s0 >= -500 of the curves.
            let e = self.exp_s0 * (1.0 + rise);
            (libm::log1p(self.logistic_s0 * rise), e / (1.0 + e))
        } else {
            (
                softplus(self.s0 + d) - softplus(self.s0),
                logistic(self.s0 + d),
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn excesses_match_their_series_and_direct_forms() {
        // Small arguments: the leading terms dominate, and nothing underflows.
        assert_eq!(exp_excess_ratio(0.0), 0.5);
        for x in [1e-8, -1e-8, 1e-300] {
            assert!((exp_excess_ratio(x) / (0.5 - x / 6.0) - 1.0).abs() < 1e-15);
        }
        assert_eq!(exp_fraction(0.0), 1.0);
        assert_eq!(exp_fraction(1e-300), 1.0);
        for q in [1e-9, 1e-300] {
            assert!((log_excess_ratio(q) / (q / 2.0) - 1.0).abs() < 1e-8);
        }
        // Both sides of each switch agree with the direct formula where it is good.
        for x in [0.999_999, 1.0, -0.999_999, -1.0] {
            let direct = (x + libm::expm1(-x)) / (x * x);
            assert!((exp_excess_ratio(x) / direct - 1.0).abs() < 1e-14, "{x}");
        }
        for x in [0.999e-8, 1.001e-8] {
            assert!(
                (exp_fraction(x) / (-libm::expm1(-x) / x) - 1.0).abs() < 1e-15,
                "{x}"
            );
        }
        for q in [0.499_999, 0.5, 0.9] {
            let direct = (-libm::log1p(-q) - q) / q;
            assert!((log_excess_ratio(q) / direct - 1.0).abs() < 1e-14, "{q}");
        }
    }

    /// Against exact integer arithmetic: `a + b (x - y)` with
    /// `b = -a / (x - y) (1 - 2^-k)`, whose value is an integer combination
    /// of the operands' mantissas.
    #[test]
    fn gap_after_keeps_the_digits_of_a_cancelling_sum() {
        // 7777 + b 914 with b a float near -7777/914: every operand and the
        // result are multiples of 2^-49, and the sum fits an i128 in those
        // units.
        let exact = |a: f64, b: f64, x: f64, y: f64| -> f64 {
            let unit = 2f64.powi(49);
            let (a, b, x, y) = (a * unit, b * unit, x, y);
            assert!([a, b, x, y].iter().all(|v| v.fract() == 0.0));
            let s = a as i128 + (b as i128) * (x as i128 - y as i128);
            s as f64 / unit
        };
        for k in [10, 30, 40, 45, 50] {
            let b = -7777.0 / 914.0 * (1.0 - 2f64.powi(-k));
            let got = gap_after(7777.0, b, 1231.0, 317.0);
            let want = exact(7777.0, b, 1231.0, 317.0);
            assert!((got / want - 1.0).abs() < 1e-15, "2^-{k}: {got} {want}");
        }
        // The plain formula is off by a large part of the smallest ones.
        let b = -7777.0 / 914.0 * (1.0 - 2f64.powi(-45));
        let plain = 7777.0 + b * (1231.0 - 317.0);
        assert!((plain / exact(7777.0, b, 1231.0, 317.0) - 1.0).abs() > 1e-4);
        // A factor too large to split: the plain formula.
        assert_eq!(gap_after(1.0, 1e300, 1e-5, 0.0), 1.0 + 1e300 * 1e-5);
    }

    #[test]
    fn softplus_rise_is_the_difference_of_softplus() {
        for (s0, d) in [(-8.0, 16.0), (-500.0, 1000.0), (-0.01, 0.02), (-3.0, 1e-9)] {
            let direct = softplus(s0 + d) - softplus(s0);
            let rise = SoftplusRise::new(s0).over(d);
            assert!(
                (rise / direct - 1.0).abs() < 1e-6,
                "{s0} {d}: {rise} {direct}"
            );
        }
        // Where the direct difference cancels, the rise keeps its digits:
        // logistic(-0.01) · 1e-12 to first order.
        let rise = SoftplusRise::new(-0.01).over(1e-12);
        assert!((rise / (logistic(-0.01) * 1e-12) - 1.0).abs() < 1e-11);
    }
}
