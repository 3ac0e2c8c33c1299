//! Square roots and a reciprocal in fixed point, for the figures of
//! queued lines ([`Axes::queue`](crate::player::Axes::queue)): integer
//! multiplications only (a core without an FPU does single precision in
//! software, at tens of instructions an operation), the same bits on every
//! core.
//!
//! Each is Newton's method from a guess, and each result is *below* the
//! exact value, by less than 2⁻²⁷ of it. Newton's steps for `1/√t`,
//! `y' = y·(3 − t·y²)/2`, and for `1/m`, `y' = y·(2 − m·y)`, square the
//! error (to `−1.5e²` and `−e²`): from the guesses' (under 3.1 % and
//! 5.9 %), three steps bring it under 2⁻³⁰, where the truncations in the
//! steps leave the result within a unit or two of 2⁻³⁰ of the root, on
//! either side; taking [`SLACK`] units off puts it below. The module's
//! tests check the bound against `f64` on every guess's interval and on
//! random inputs.

/// Units of 2⁻³⁰ taken off a result of Newton's steps, more than their
/// truncations can leave it above the root.
const SLACK: u32 = 4;

/// `2³³ / √(2i + 17)`: `1/√t` at the middle of `t`'s 24 intervals of
/// width 1/32 in `[1/4, 1)`, Q30.
const GUESS: [u32; 24] = {
    let mut guess = [0u32; 24];
    let mut i = 0;
    while i < 24 {
        // √(2⁶⁶ / (2i + 17)), to the integer below.
        let square = (1u128 << 66) / (2 * i as u128 + 17);
        let (mut lo, mut hi) = (0u128, 1u128 << 34);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if mid * mid <= square {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        guess[i] = lo as u32;
        i += 1;
    }
    guess
};

/// `1/√x` for `x > 0`, as `(y, h)` with `1/√x ≈ y · 2^(h − 62)`, `y` in
/// Q30 in `(2³⁰, 2³¹]` and below the exact by less than 2⁻²⁷ of it.
#[inline]
pub(crate) fn rsqrt(x: u64) -> (u32, u32) {
    debug_assert!(x > 0);
    // x·4^h in [2⁶², 2⁶⁴): its top word is t/2³² in [1/4, 1).
    let h = x.leading_zeros() / 2;
    let t = ((x << (2 * h)) >> 32) as u32;
    let mut y = GUESS[(t >> 27) as usize - 8];
    for _ in 0..3 {
        let y2 = (u64::from(y) * u64::from(y)) >> 30;
        let ty2 = (u64::from(t) * y2) >> 32;
        y = ((u64::from(y) * ((3u64 << 30) - ty2)) >> 31) as u32;
    }
    (y - SLACK, h)
}

/// `√x`, below the exact by less than 2⁻²⁷ of it (0 for 0).
#[inline]
pub(crate) fn sqrt(x: u64) -> u32 {
    if x == 0 {
        return 0;
    }
    let (y, h) = rsqrt(x);
    let t = ((x << (2 * h)) >> 32) as u32;
    // √x = t·y / 2³⁰ / 2^h: t/2³² times 1/√(t/2³²), scaled back.
    ((u64::from(t) * u64::from(y)) >> (30 + h)) as u32
}

/// `2⁵⁸ / r` (`1/r` in Q28 for `r` in Q30) for `r > 0`, below the exact
/// by less than 2⁻²⁷ of it, `u32::MAX` where it does not fit.
#[inline]
pub(crate) fn recip_q28(r: u32) -> u32 {
    debug_assert!(r > 0);
    // m = r·2^c in [2³¹, 2³²): m/2³² in [1/2, 1), its reciprocal in
    // (1, 2] guessed by the line through both ends' midpoints.
    let c = r.leading_zeros();
    let m = r << c;
    let mut y = ((48u64 << 30) / 17 - ((u64::from(m) * ((32u64 << 30) / 17)) >> 32)) as u32;
    for _ in 0..3 {
        let my = (u64::from(m) * u64::from(y)) >> 32;
        y = ((u64::from(y) * ((2u64 << 30) - my)) >> 30) as u32;
    }
    let y = y - SLACK;
    // 1/r = (1/(m/2³²)) · 2^(c − 2), and Q28 from Q30: y · 2^(c − 4).
    let k = if c >= 4 {
        u64::from(y) << (c - 4)
    } else {
        u64::from(y) >> (4 - c)
    };
    u32::try_from(k).unwrap_or(u32::MAX)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::format;

    /// Below the exact, by less than 2⁻²⁷ of it.
    fn within(got: f64, exact: f64, what: &str) {
        assert!(got <= exact, "{what}: {got} above {exact}");
        assert!(
            exact - got < exact / f64::from(1u32 << 27),
            "{what}: {got} for {exact}"
        );
    }

    fn inputs() -> impl Iterator<Item = u64> {
        let mut next = crate::base::xorshift(0x9E37_79B9_7F4A_7C15);
        // Every magnitude: the random bits shifted down at random.
        let random = core::iter::from_fn(move || {
            let s = next();
            Some(s >> (s % 64))
        });
        // Each guess's interval's ends and middle, at every even shift.
        let edges = (0..31u32).flat_map(|h| {
            (8u64..=32).flat_map(move |i| {
                [i << 59, (i << 59) | (1 << 58), (i << 59).wrapping_sub(1)].map(|t| t >> (2 * h))
            })
        });
        edges.chain(random.take(200_000)).filter(|&x| x > 0)
    }

    #[test]
    fn inverse_roots_are_below_and_near() {
        for x in inputs() {
            let (y, h) = rsqrt(x);
            let got = f64::from(y) * 2f64.powi(h as i32 - 62);
            within(got, 1.0 / (x as f64).sqrt(), &format!("rsqrt({x})"));
        }
    }

    #[test]
    fn roots_are_below_and_near() {
        assert_eq!(sqrt(0), 0);
        for x in inputs() {
            let exact = (x as f64).sqrt();
            let got = f64::from(sqrt(x));
            // Below, by the 2⁻²⁷ and the integer part's truncation.
            assert!(got <= exact, "sqrt({x}): {got} above {exact}");
            assert!(
                exact - got < exact / f64::from(1u32 << 27) + 1.0,
                "sqrt({x}): {got}"
            );
        }
    }

    #[test]
    fn reciprocals_are_below_and_near() {
        let mut r = 1u32;
        while r < u32::MAX / 3 {
            let exact = (1u64 << 58) as f64 / f64::from(r);
            let got = recip_q28(r);
            if exact < f64::from(u32::MAX) {
                within(f64::from(got), exact, &format!("recip({r})"));
            } else {
                assert_eq!(got, u32::MAX, "recip({r})");
            }
            r += 1 + r / 4099;
        }
    }
}
