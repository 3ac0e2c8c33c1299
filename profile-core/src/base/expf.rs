//! Single-precision arithmetic of the articles' C, bit for bit, without
//! `f64`: `e^x` correctly rounded from integer arithmetic, and the period
//! a truncating `(unsigned short)(scale / f)` stores, by integer division.
//!
//! Where `f64` is software (every Cortex-M, the AVR) a `libm::exp` costs
//! thousands of instructions; the routes here cost about a hundred on a
//! 32-bit core, and give the same bits as the `f64` expressions they
//! stand for: the tests compare them on every input that can occur.

/// `ln 2 / 32` in units of `2^-56`.
const LN2_32: i64 = 1_560_828_692_041_340;
/// `32 / ln 2` in units of `2^-16`.
const INV_LN2_32: i64 = 3_025_551;
/// `1/2`, `1/6`, `1/24` and `1/120` in units of `2^-31`: the Taylor series of
/// `(e^r - 1 - r) / r^2`.
const C2: i32 = 1 << 30;
const C3: i32 = 357_913_941;
const C4: i32 = 89_478_485;
const C5: i32 = 17_895_697;

/// `2^(j/32)` in units of `2^-63`, rounded to nearest, `j = 0 .. 31`.
const EXP2_32: [u64; 32] = [
    9_223_372_036_854_775_808,
    9_425_337_585_438_007_767,
    9_631_725_603_661_576_981,
    9_842_632_931_000_616_231,
    10_058_158_527_438_640_871,
    10_278_403_519_900_636_096,
    10_503_471_249_702_896_438,
    10_733_467_321_041_881_441,
    10_968_499_650_544_839_023,
    11_208_678_517_905_446_201,
    11_454_116_617_628_225_966,
    11_704_929_111_906_019_353,
    11_961_233_684_655_323_370,
    12_223_150_596_734_848_760,
    12_490_802_742_373_206_726,
    12_764_315_706_832_201_104,
    13_043_817_825_332_782_212,
    13_329_440_243_271_311_081,
    13_621_316_977_754_388_159,
    13_919_584_980_481_119_318,
    14_224_384_202_002_324_189,
    14_535_857_657_386_837_923,
    14_854_151_493_325_717_732,
    15_179_415_056_705_840_218,
    15_511_800_964_685_064_948,
    15_851_465_176_301_844_309,
    16_198_567_065_652_879_633,
    16_553_269_496_673_159_336,
    16_915_738_899_553_466_671,
    17_286_145_348_831_213_003,
    17_664_662_643_191_237_676,
    18_051_468_387_014_017_850,
];

/// The bits of [`exp_fixed`]'s value below the result's 24 are 40; their
/// top ten count slices of `2^30` units, twice the error bound proven there.
/// A value in the slice below the tie (`2^39`) or the one above it may
/// stand for an exact value on the tie's other side: those two slices are
/// undecided.
const BELOW_TIE: u32 = (1 << 9) - 1;

/// `e^x` rounded to the nearest `f32`: the bits of `libm::exp(x as f64) as
/// f32`, the correctly rounded `expf` the articles' C libraries give,
/// without `f64` but where the fixed-point value lies within its error
/// bound of a tie (one input in 2000), or the result is not a normal
/// float; there the `f64` route decides.
pub(crate) fn exp_f32(x: f32) -> f32 {
    // Where single precision is hardware, its route first; both routes
    // give the `f64` route's bits wherever they decide.
    let single = if cfg!(target_abi = "eabihf") {
        exp_f32_single(x)
    } else {
        None
    };
    match single.or_else(|| exp_f32_fixed(x)) {
        Some(y) => y,
        None => libm::exp(x as f64) as f32,
    }
}

/// `32 / ln 2`, rounded to `f32`.
const INV_LN2_32_F32: f32 = f32::from_bits(0x4238_aa3b);
/// `1.5 · 2^23`: added to a float below `2^22` in magnitude, leaves the
/// nearest integer in the low bits of the sum.
const SHIFTER: f32 = 12_582_912.0;
/// `ln 2 / 32` in two parts: the first of 12 significant bits (so that `k`
/// times it, `|k| <= 4087`, is exact), the second the rest rounded.
const LN2_32_HIGH: f32 = f32::from_bits(0x3cb1_7000);
const LN2_32_LOW: f32 = f32::from_bits(0x3585_fdf4);

/// `2^(j/32)` as the sum of two `f32` (the nearest, then the nearest to
/// what remains), as bits.
const EXP2_32_PAIRS: [(u32, u32); 32] = [
    (0x3f800000, 0x00000000),
    (0x3f82cd87, 0xb34ea7a9),
    (0x3f85aac3, 0x334f9891),
    (0x3f88980f, 0xb37eda4b),
    (0x3f8b95c2, 0xb260aba1),
    (0x3f8ea43a, 0xb3697465),
    (0x3f91c3d3, 0x33675624),
    (0x3f94f4f0, 0xb32e0212),
    (0x3f9837f0, 0x33231b71),
    (0x3f9b8d3a, 0xb30c5563),
    (0x3f9ef532, 0x33412342),
    (0x3fa27043, 0x30c3125a),
    (0x3fa5fed7, 0xb32c9d5e),
    (0x3fa9a15b, 0xb3162b08),
    (0x3fad583f, 0xb22deaf6),
    (0x3fb123f6, 0xb37c5aa8),
    (0x3fb504f3, 0x32cfe77a),
    (0x3fb8fbaf, 0x330ec5f7),
    (0x3fbd08a4, 0xb3414fe8),
    (0x3fc12c4d, 0xb2d6663e),
    (0x3fc5672a, 0x320aa837),
    (0x3fc9b9be, 0xb37323a2),
    (0x3fce248c, 0x3228fc24),
    (0x3fd2a81e, 0xb35c1daa),
    (0x3fd744fd, 0xb2d4a58a),
    (0x3fdbfbb8, 0xb3504a1c),
    (0x3fe0ccdf, 0xb21eab59),
    (0x3fe5b907, 0xb2441be6),
    (0x3feac0c7, 0xb24116de),
    (0x3fefe4ba, 0xb348464a),
    (0x3ff5257d, 0x32292436),
    (0x3ffa83b3, 0xb2923758),
];

/// `e^x` rounded to the nearest `f32` from single-precision arithmetic, for
/// cores whose FPU computes it: `None` where it cannot prove the rounding
/// (one input in 30, then [`exp_f32_fixed`] decides), outside `-87 ..=
/// 88.5` and for NaN.
///
/// `x = k ln2/32 + r` (`k ln2/32`'s high part exact, so `r` is within
/// `2^-29.4` of its value), `e^r - 1 = p = r + r^2 (1/2 + r/6 + r^2/24)`,
/// then `e^x = 2^(k >> 5) (T + T p)` with `T = 2^((k & 31)/32)` a pair of
/// floats. The sum `y = T_high + c`, `c = T_high p + T_low`, is the one
/// rounding that matters: its error is computed exactly (`|T_high| >=
/// |c|`), and `c` is within `2^-28.8` of the exact correction relative to
/// the result (`r`'s error, `p`'s and `c`'s roundings, `r^5/120`), less
/// than an eighth of half an ulp (`2^-25` of the result at least): where
/// the rounding error lies within seven eighths of half an ulp, `y` is the
/// exact value rounded. The tests check every input.
pub(crate) fn exp_f32_single(x: f32) -> Option<f32> {
    if !(-87.0..=88.5).contains(&x) {
        return None;
    }
    if (x.to_bits() >> 23) & 0xff < 102 {
        // |x| < 2^-25: as in `exp_f32_fixed`.
        return Some(1.0);
    }
    let shifted = x * INV_LN2_32_F32 + SHIFTER;
    let k = shifted.to_bits() as i32 - SHIFTER.to_bits() as i32;
    let kf = shifted - SHIFTER;
    let r = (x - kf * LN2_32_HIGH) - kf * LN2_32_LOW;
    let p = r + r * r * (0.5 + r * (1.0 / 6.0 + r * (1.0 / 24.0)));
    let (high, low) = EXP2_32_PAIRS[(k & 31) as usize];
    let (high, low) = (f32::from_bits(high), f32::from_bits(low));
    let c = high * p + low;
    let y = high + c;
    let error = (high - y) + c;
    let bits = y.to_bits();
    // Seven eighths of half an ulp of y (y is in [0.98, 2), a normal
    // float): 1.75 times 2^-25 of y's power of two.
    let bound = f32::from_bits(((bits & 0x7f80_0000) - (25 << 23)) | 0x60_0000);
    if bits & 0x7f_ffff == 0 || error.abs() >= bound {
        // At a power of two the ulp below is half the one above.
        return None;
    }
    let exponent = ((bits >> 23) as i32) + (k >> 5);
    if !(1..255).contains(&exponent) {
        return None;
    }
    Some(f32::from_bits(bits.wrapping_add(((k >> 5) as u32) << 23)))
}

/// The fixed-point route of [`exp_f32`]: `None` where it cannot prove the
/// rounding.
pub(crate) fn exp_f32_fixed(x: f32) -> Option<f32> {
    let bits = x.to_bits();
    // |x| < 2^-25: e^x lies within half an ulp of 1 (above 1 the ulp is
    // 2^-23, below it 2^-24).
    if (bits >> 23) & 0xff < 102 {
        return Some(1.0);
    }
    let (v, exponent) = exp_fixed(x)?;
    let (high, low) = ((v >> 32) as u32, v as u32);
    let slice = ((high & 0xff) << 2) | (low >> 30);
    if slice.wrapping_sub(BELOW_TIE) < 2 || exponent < 1 {
        return None;
    }
    // The 24 bits of the significand, rounded: a carry out of them moves the
    // exponent field up by one, as the sum below does.
    let significand = (high >> 8) + u32::from(slice > BELOW_TIE);
    let out = ((exponent as u32) << 23) + (significand - (1 << 23));
    if out >> 23 >= 255 {
        return None;
    }
    Some(f32::from_bits(out))
}

/// `e^x` for `-87 <= x <= 88.5` and `|x| >= 2^-25`, as `v · 2^(exponent -
/// 127 - 63)` with `2^63 <= v < 2^64` (so `exponent` is the biased exponent
/// of the result); `None` outside that range and for NaN.
///
/// `x = k ln2/32 + r` with `|r| <= ln2/64` (plus 2^-40), then `e^x = 2^(k >>
/// 5) · 2^((k & 31)/32) · (1 + p)` with `p = r + r^2 (1/2 + r/6 + r^2/24 +
/// r^3/120)`. The error of `v`, relative to the result, is below `2^-34`,
/// that is `2^29` units of `v`:
/// - `x` is exact in units of `2^-56` (its last bit is at least `2^-48`);
/// - `ln2/32` rounded in units of `2^-56`, times `|k| <= 4087`: `2^-45`;
/// - the series' remainder, `r^6/720` and beyond: below `2^-49`;
/// - `r` cut to units of `2^-37` in the series, the series' three
///   products and `r^2` cut to `2^-31` and `2^-42`, times `r^2 <= 2^-13`:
///   below `2^-42` in all;
/// - `p` cut to units of `2^-37` and multiplied by `2^(j/32) < 2`: `2^-36`;
///   `2^(j/32)` cut to 32 bits in that product (`2^-31`), times `|p| <=
///   2^-6.5`: `2^-37.5`; the table and the last shift: `2^-62`;
/// - doubling `v` when it lies below `2^63` doubles the error in its units.
///
/// Their sum is below `2^-35.2` before doubling, `2^-34.2` after: 2^29
/// units of `v`, half a slice of [`BELOW_TIE`]'s. The tests measure the largest error over
/// every input against `libm::exp` (within `2^-52`) and hold it below that
/// (it is `1.7 · 10^8`, `2^27.3` units).
pub(crate) fn exp_fixed(x: f32) -> Option<(u64, i32)> {
    if !(-87.0..=88.5).contains(&x) {
        return None;
    }
    let bits = x.to_bits();
    let biased = ((bits >> 23) & 0xff) as i32;
    if biased < 102 {
        return None;
    }
    // x in units of 2^-56: the significand shifted by 8 ..= 39 places.
    let magnitude = i64::from((bits & 0x7f_ffff) | 0x80_0000) << (biased - 94);
    let x56 = if bits >> 31 == 0 {
        magnitude
    } else {
        -magnitude
    };
    // k = round(x 32/ln2), from x's top bits (units of 2^-24); |k| <= 4087.
    let k = ((i64::from((x56 >> 32) as i32) * INV_LN2_32 + (1 << 39)) >> 40) as i32;
    let r = x56 - i64::from(k) * LN2_32;
    // |r| <= ln2/64 + 2^-40 < 2^31 units of 2^-37.
    let r37 = (r >> 19) as i32;
    let q = C4 + (wide(C5, r37) >> 37) as i32;
    let q = C3 + (wide(q, r37) >> 37) as i32;
    let q = C2 + (wide(q, r37) >> 37) as i32;
    let r2 = (wide(r37, r37) >> 32) as i32;
    let p = r + (wide(r2, q) >> 17);
    let t = EXP2_32[(k & 31) as usize];
    let correction = (i64::from((t >> 32) as u32) * i64::from((p >> 19) as i32)) >> 5;
    let v = t.wrapping_add(correction as u64);
    let exponent = (k >> 5) + 127;
    Some(if v >> 63 == 0 {
        (v << 1, exponent - 1)
    } else {
        (v, exponent)
    })
}

/// `a b` in 64 bits: one `smull` on a 32-bit Arm core.
fn wide(a: i32, b: i32) -> i64 {
    i64::from(a) * i64::from(b)
}

/// `1 / (1 + e)` in single precision: the bits of C's `1.0 / (1 + e)`
/// (a `double` division rounded to `float`). A division rounded to 53 bits
/// and then to 24 is the division rounded to 24 (53 >= 2 · 24 + 2), so the
/// `f32` division gives the same bits; the tests check every `e >= 0`.
pub(crate) fn reciprocal_of_one_plus(e: f32) -> f32 {
    1.0 / (1.0 + e)
}

/// A timer's rate in steps per second (`Timer::frequency_scale`) that is a
/// whole number below `2^32`: the periods C's truncating `(unsigned)
/// (scale / f)` stores are then integer divisions.
#[derive(Clone, Copy, Debug)]
pub(crate) struct WholeScale(u32);

impl WholeScale {
    /// `None` where `scale` is not a whole number from 1 to `2^32 - 1`.
    pub(crate) fn new(scale: f64) -> Option<Self> {
        ((1.0..4_294_967_296.0).contains(&scale) && libm::floor(scale) == scale)
            .then_some(WholeScale(scale as u32))
    }

    /// `floor(scale / f)` for `f > 0`: what truncating the `double` quotient
    /// gives when it is below `2^29`. An `f32` `f` is `m 2^e`, so the quotient
    /// lies at least `1/m >= 2^-24` from every integer it is not; below
    /// `2^29` that is more than its rounding to 53 bits moves it
    /// (`2^29 · 2^-53`), so the rounded quotient is on the same side of
    /// every integer, and truncating it is the floor. `None` from `2^29` up
    /// and where `f` is not a positive normal float.
    pub(crate) fn truncated_period(self, f: f32) -> Option<u64> {
        let n = self.0;
        let bits = f.to_bits();
        let biased = (bits >> 23) as i32;
        if !(1..255).contains(&biased) {
            // Negative (the sign bit makes `biased` >= 256), zero,
            // subnormal, infinite or NaN.
            return None;
        }
        // f = m 2^shift.
        let m = (bits & 0x7f_ffff) | 0x80_0000;
        let shift = biased - 150;
        let quotient = if shift >= 32 {
            0
        } else if shift >= 0 {
            u64::from(n) / (u64::from(m) << shift)
        } else {
            // floor(n 2^s / m), s = -shift: long division eight bits at a
            // time, every step a 32-bit division (the remainder stays below
            // m < 2^24).
            let mut s = -shift;
            let mut q = u64::from(n / m);
            let mut rem = n % m;
            while s > 0 && q < 1 << 29 {
                let b = s.min(8);
                let wide = rem << b;
                q = (q << b) | u64::from(wide / m);
                rem = wide % m;
                s -= b;
            }
            if s > 0 {
                return None;
            }
            q
        };
        (quotient < 1 << 29).then_some(quotient)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every input in debug builds would take minutes: a stride there,
    /// every input in optimised ones (CI runs the crate's tests optimised).
    fn stride() -> usize {
        if cfg!(debug_assertions) { 997 } else { 1 }
    }

    #[test]
    fn the_table_is_two_to_the_thirty_seconds() {
        for (j, &t) in EXP2_32.iter().enumerate() {
            // Against f64 (53 bits): within 2^11 units.
            let want = libm::exp2(j as f64 / 32.0) * 9_223_372_036_854_775_808.0;
            assert!((t as f64 - want).abs() <= 2048.0, "{j}");
            // 2^(j/32) 2^((32-j)/32) = 2: the products within the two
            // roundings of 2^64.
            if j > 0 {
                let product = u128::from(t) * u128::from(EXP2_32[32 - j]);
                let two = 1u128 << 127;
                assert!(product.abs_diff(two) < 1 << 65, "{j}");
            }
        }
    }

    #[test]
    fn the_constants_are_their_values() {
        let ln2_32 = core::f64::consts::LN_2 / 32.0;
        assert!((LN2_32 as f64 - ln2_32 * 2f64.powi(56)).abs() <= 16.0);
        assert!((INV_LN2_32 as f64 - 2f64.powi(16) / ln2_32).abs() <= 0.5);
        for (c, n) in [(C2, 2.0), (C3, 6.0), (C4, 24.0), (C5, 120.0)] {
            assert!((c as f64 - 2f64.powi(31) / n).abs() <= 0.5, "1/{n}");
        }
    }

    /// Every `f32` from -87 to 88.5 (those whose result is a normal float):
    /// the fixed-point value within 2^29 units (2^-34) of `libm::exp`, and
    /// where it decides, the bits of `libm::exp(x as f64) as f32`.
    #[test]
    fn exp_agrees_with_the_double_route_on_every_input() {
        let (mut worst, mut undecided, mut inputs) = (0.0f64, 0u64, 0u64);
        let ranges = [
            (0u32, 88.5f32.to_bits()),
            (1u32 << 31, (-87.0f32).to_bits()),
        ];
        for (from, to) in ranges {
            for bits in (from..=to).step_by(stride()) {
                let x = f32::from_bits(bits);
                let want = libm::exp(x as f64) as f32;
                inputs += 1;
                if let Some((v, exponent)) = exp_fixed(x) {
                    let exact = libm::exp(x as f64) * libm::exp2(f64::from(190 - exponent));
                    let error = (v as f64 - exact).abs();
                    worst = worst.max(error);
                }
                match exp_f32_fixed(x) {
                    Some(y) => assert_eq!(y.to_bits(), want.to_bits(), "e^{x:e}"),
                    None => undecided += 1,
                }
                assert_eq!(exp_f32(x).to_bits(), want.to_bits(), "e^{x:e}");
            }
        }
        assert!(worst < (1u64 << 29) as f64, "largest error {worst} units");
        // 2^31 / 2^40 of the inputs would be undecided were the values
        // spread evenly; 1 in 2088 of them are.
        assert!(
            undecided * 1000 < inputs,
            "{undecided} of {inputs} undecided"
        );
    }

    /// The single-precision route, on every input from -87 to 88.5: where
    /// it decides, the bits of the `f64` route.
    #[test]
    fn the_single_precision_route_agrees_on_every_input() {
        let (mut undecided, mut inputs) = (0u64, 0u64);
        for (from, to) in [
            (0u32, 88.5f32.to_bits()),
            (1u32 << 31, (-87.0f32).to_bits()),
        ] {
            for bits in (from..=to).step_by(stride()) {
                let x = f32::from_bits(bits);
                inputs += 1;
                match exp_f32_single(x) {
                    Some(y) => {
                        let want = libm::exp(x as f64) as f32;
                        assert_eq!(y.to_bits(), want.to_bits(), "e^{x:e}");
                    }
                    None => undecided += 1,
                }
            }
        }
        // One in 25 undecided at most (the bound's margin against half an
        // ulp, on either side of a tie).
        assert!(undecided * 25 < inputs, "{undecided} of {inputs} undecided");
    }

    #[test]
    fn the_pairs_are_two_to_the_thirty_seconds() {
        for (j, &(high, low)) in EXP2_32_PAIRS.iter().enumerate() {
            let (high, low) = (f32::from_bits(high), f32::from_bits(low));
            // The fixed-point table, in units of 2^-63: within 2^-47.
            let sum = high as f64 + low as f64;
            let fixed = EXP2_32[j] as f64 / 9_223_372_036_854_775_808.0;
            assert!((sum - fixed).abs() < 2f64.powi(-47), "{j}");
            assert_eq!(high, (libm::exp2(j as f64 / 32.0)) as f32, "{j}");
        }
        assert_eq!(LN2_32_HIGH.to_bits() & 0xfff, 0);
        let ln2_32 = core::f64::consts::LN_2 / 32.0;
        assert!((LN2_32_HIGH as f64 + LN2_32_LOW as f64 - ln2_32).abs() < 1e-13);
        assert!((INV_LN2_32_F32 as f64 - 1.0 / ln2_32).abs() < 4e-6);
    }

    #[test]
    fn exp_outside_the_fixed_range_takes_the_double_route() {
        for x in [
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            -500.0,
            -104.0,
            -87.5,
            88.7,
            88.8,
            500.0,
            0.0,
            -0.0,
            1e-30,
            -1e-30,
            2.9e-8,
            -2.9e-8,
        ] {
            let want = libm::exp(x as f64) as f32;
            assert_eq!(exp_f32(x).to_bits(), want.to_bits(), "e^{x:e}");
        }
    }

    /// Every `e` from 0 to infinity.
    #[test]
    fn the_reciprocal_is_the_double_division_rounded() {
        for bits in (0..=f32::INFINITY.to_bits()).step_by(stride()) {
            let e = f32::from_bits(bits);
            let want = (1.0f64 / (1.0f32 + e) as f64) as f32;
            assert_eq!(reciprocal_of_one_plus(e).to_bits(), want.to_bits(), "{e:e}");
        }
    }

    #[test]
    fn truncated_periods_are_the_double_quotient_truncated() {
        // Exact quotients, quotients an ulp either side of an integer, and
        // a sweep of frequencies at common timer rates.
        for scale in [
            10_000_000.0,
            16_000_000.0,
            1_000_000.0,
            62_500.0,
            4_294_967_295.0,
            3.0,
        ] {
            let mut f = 0.05f32;
            while f < 1e7 {
                for g in [
                    f,
                    f32::from_bits(f.to_bits() + 1),
                    f32::from_bits(f.to_bits() - 1),
                ] {
                    let want = scale / g as f64;
                    match WholeScale::new(scale).unwrap().truncated_period(g) {
                        Some(q) => assert_eq!(q, want as u64, "{scale} / {g:e}"),
                        None => assert!(want >= (1 << 29) as f64, "{scale} / {g:e}"),
                    }
                }
                f *= 1.000_37;
            }
            for q in [1u32, 2, 3, 156, 19_183, 65_535, 1 << 20] {
                let g = (scale / q as f64) as f32;
                let want = scale / g as f64;
                let period = WholeScale::new(scale).unwrap().truncated_period(g);
                assert_eq!(period, Some(want as u64), "{scale} / {g:e}");
            }
        }
        let ten = WholeScale::new(10_000_000.0).unwrap();
        for f in [0.0, -0.0, -5.0, f32::NAN, f32::INFINITY, 1e-3, 1e-40] {
            assert_eq!(ten.truncated_period(f), None, "{f:e}");
        }
        assert_eq!(ten.truncated_period(3e38), Some(0));
        for scale in [
            2.5,
            0.0,
            0.5,
            -3.0,
            4_294_967_296.0,
            f64::NAN,
            f64::INFINITY,
        ] {
            assert!(WholeScale::new(scale).is_none(), "{scale}");
        }
    }
}
