//! Edges proved rounded rather than solved: a linear ramp's, where only
//! the table's periods are asked for ([`CheckedSpec::generate_periods`](crate::CheckedSpec::generate_periods)).

use super::linear::LinearInTime;

/// The edges of a linear ramp in ticks, rounded to the nearest tick, each
/// proved equal to what rounding the closed form ([`TimeCurve::time_at`](crate::base::solve::TimeCurve::time_at)
/// times the scale) gives, in integer arithmetic: the closed form's `f64`
/// square root and division, software on a Cortex-M, cost some 2000
/// instructions an edge; a proof a few hundred.
///
/// Edge `k` at `y` ticks solves `H(y) = A·y² + B·y − k = 0` (`A = a / 2s²`
/// and `B = f0 / s` for the acceleration `a`, the start frequency `f0` and
/// `s` ticks a second; `N(t) = k` over ticks), and `H` rises with `y ≥ 0`.
/// The nearest tick is `R` when `H(R − h) < 0 < H(R + h)`, `h = ½ − δ`,
/// `δ = 2⁻¹⁴`: the root is then more than `δ` ticks from either half-tick,
/// farther than the closed form's `f64` strays from it (a few units of
/// 2⁻⁵³ of `y`, with `A` and `B` rounded to `f64`: under 2⁻¹⁶ ticks below
/// 2³² ticks), so that the closed form rounds to `R` too. `H` is read in
/// fixed point, units of 2⁻⁵² steps, from the exact mantissas of `A` and
/// `B`: `H(R)` and its slope at `R` (products of 117 bits at most), then
/// `H(R ± h) = H(R) ± h·H'(R) + A·h²`, each truncation a unit at most; a
/// sign is taken where `|H|` is above 16 units. `R` is guessed from the
/// edge before in `f32` and moved a tick at most twice. Where no sign is
/// sure (a root within `δ` of a half-tick: one edge in some 8000), the
/// ramp has ended, an edge is past 2³² ticks or a period past 2²², or `A`
/// or `B` is past what the fixed point holds (2 or more, in steps and
/// ticks), [`None`]: the edge is solved.
pub(crate) struct LinearEdges {
    /// `A` and `B`'s mantissas (53 bits), and the shifts from their
    /// products with `R²` and `R` to units of 2⁻⁵² steps.
    a: u64,
    a_shift: u32,
    b: u64,
    b_shift: u32,
    rise_steps: f64,
    /// `2A` and `B` in `f32`, for the guess.
    slope: f32,
    base: f32,
    /// The edge before, rounded, and `H` for it at its `R + h`, in units.
    before: u64,
    above: i128,
    /// `false` where `A` or `B` is out of the fixed point's reach.
    usable: bool,
}

/// `δ`: 2⁻¹⁴ ticks.
const MARGIN_BITS: u32 = 14;
/// Units of 2⁻⁵² steps a sign needs `|H|` above.
const SURE: i128 = 16;

/// A positive finite `x` as `(m, e)`, `x = m·2^e`, `m` its 53-bit
/// mantissa; `None` for anything else.
fn parts(x: f64) -> Option<(u64, i32)> {
    if !(x.is_normal() && x > 0.0) {
        return None;
    }
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    Some(((bits & ((1 << 52) - 1)) | (1 << 52), exponent - 1075))
}

/// `x >> shift` for a shift of any size (0 past 127).
fn shifted(x: u128, shift: u32) -> u128 {
    x.checked_shr(shift).unwrap_or(0)
}

impl LinearEdges {
    /// The edges of `curve` in ticks of `scale` a second, from its first.
    pub(crate) fn new(curve: &LinearInTime, scale: f64) -> Self {
        let big_a = curve.accel / (2.0 * (scale * scale));
        let big_b = curve.fmin / scale;
        let (a, ea) = parts(big_a).unwrap_or((0, 0));
        let (b, eb) = parts(big_b).unwrap_or((0, 0));
        // `A·R²` in units is `a·R²·2^(ea + 52)`: a right shift while `A`
        // is below 2.
        let usable = a > 0 && b > 0 && ea + 52 <= 0 && eb + 52 <= 0;
        LinearEdges {
            a,
            a_shift: (-(ea + 52)).max(0) as u32,
            b,
            b_shift: (-(eb + 52)).max(0) as u32,
            rise_steps: curve.rise_steps,
            slope: (2.0 * big_a) as f32,
            base: big_b as f32,
            before: 0,
            above: 0,
            usable,
        }
    }

    /// `H(R ± h)` for edge `k`, in units of 2⁻⁵² steps: below, above.
    fn around(&self, r: u64, k: u32) -> (i128, i128) {
        let square = u128::from(r * r);
        let at = shifted(u128::from(self.a) * square, self.a_shift)
            + shifted(u128::from(self.b) * u128::from(r), self.b_shift);
        let at = at as i128 - (i128::from(k) << 52);
        // The slope at R, 2A·R + B, and A·h², in units.
        let slope = shifted(2 * u128::from(self.a) * u128::from(r), self.a_shift)
            + shifted(u128::from(self.b), self.b_shift);
        let h = (1u128 << (MARGIN_BITS - 1)) - 1;
        let step = (slope * h) >> MARGIN_BITS;
        let bend = shifted(u128::from(self.a) * h * h, self.a_shift + 2 * MARGIN_BITS);
        let (step, bend) = (step as i128, bend as i128);
        (at - step + bend, at + step + bend)
    }

    /// Edge `k` (edges asked for in order, one after another), rounded to
    /// the nearest tick, where it is proved; `None` to solve it.
    pub(crate) fn edge(&mut self, k: u32) -> Option<u64> {
        if !(self.usable && (k as f64) < self.rise_steps) {
            return None;
        }
        // The guess: from the edge before's `R + h`, where `H` for this
        // edge is `above` less a step.
        let left = 1.0 - (self.above >> 20) as i64 as f32 * (1.0 / 4_294_967_296.0);
        let slope = self.slope * (self.before as f32 + 0.5) + self.base;
        let ahead = 2.0 * left / (slope + libm::sqrtf(slope * slope + 2.0 * self.slope * left));
        if !(0.0..4_194_304.0).contains(&ahead) {
            return None;
        }
        let mut r = self.before + libm::roundf(0.5 + ahead) as u64;
        if r == 0 || r >= 1 << 32 {
            return None;
        }
        for _ in 0..3 {
            let (below, above) = self.around(r, k);
            if below > SURE {
                r -= 1;
            } else if above < -SURE {
                r += 1;
            } else if below < -SURE && above > SURE {
                self.before = r;
                self.above = above;
                return Some(r);
            } else {
                return None;
            }
            if r == 0 {
                return None;
            }
        }
        None
    }

    /// After edge `k` was solved at `edge` ticks, rounded: the next guess
    /// starts there.
    pub(crate) fn solved(&mut self, k: u32, edge: u64) {
        self.before = edge;
        self.above = match self.usable && edge > 0 && edge < 1 << 32 {
            true => self.around(edge, k).1,
            false => 0,
        };
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::solve::TimeCurve;
    use crate::{Linear, LinearExtent};

    /// Edges proved by [`LinearEdges`] on random ramps and timers, each
    /// against the closed form rounded as the quantizer rounds it; the
    /// edges it leaves to the solver are few.
    #[test]
    fn proved_edges_are_the_closed_forms_rounded() {
        let mut next = crate::base::xorshift(0x0DDB_A11C_AFE5_EED5);
        let (mut proved, mut solved) = (0u64, 0u64);
        for case in 0..400 {
            let timers = [1e5, 1e6, 8e6, 1e7, 16e6, 72e6, 1.6e8];
            let scale = timers[(next() % 7) as usize] / (1 + next() % 2) as f64;
            // First periods of 8 to 2²¹ ticks, the last at least 2.
            let fmin = scale / (8.0 + (next() % (1 << 21)) as f64);
            let fmax = (fmin * (1.01 + (next() % 400) as f64 / 10.0)).min(scale / 2.0);
            let len = 1 + (next() % 4000) as u32;
            let ramp = Linear {
                fmin,
                fmax,
                extent: match case % 5 {
                    0 => LinearExtent::Accel(fmax * fmax / (1 + next() % 3000) as f64),
                    _ => LinearExtent::Len(len),
                },
            };
            let time = LinearInTime::new(&ramp);
            let mut edges = LinearEdges::new(&time, scale);
            let last = (time.rise_steps as u32).min(5000);
            for k in 1..=last {
                let exact = libm::round(time.time_at(f64::from(k)).unwrap() * scale);
                match edges.edge(k) {
                    Some(edge) => {
                        assert_eq!(edge as f64, exact, "{ramp:?} at {scale}: edge {k}");
                        proved += 1;
                    }
                    None => {
                        edges.solved(k, exact as u64);
                        // (The ramp's end, and edges past 2³² ticks, are
                        // always solved.)
                        let within = f64::from(k) < time.rise_steps && exact < 4_294_967_296.0;
                        solved += u64::from(within);
                    }
                }
            }
        }
        // A root within 2⁻¹⁴ of a half-tick: one edge in some 8000.
        assert!(solved * 2000 < proved, "{solved} solved, {proved} proved");
    }
}
