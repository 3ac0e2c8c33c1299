//! An oracle for pulse-edge times that shares no code and no formula with
//! `profile-core`'s path from a curve to its edges.
//!
//! Each curve is written out here as its frequency `f(t)` only, from the
//! articles' definitions, with `std`'s `exp`, `exp_m1`
//! and `ln_1p` rather than `libm`. No closed-form step count `N(t)` appears:
//! `N` is integrated numerically (adaptive Gauss-Kronrod 7-15, split at every
//! joint of the curve), and parameters that production solves for in closed
//! form (the sigmoid's duration, the exponential's `tau` from a step budget,
//! the linear ramp's acceleration from `len`) are solved here from that
//! numeric integral.
//!
//! Edge `k` is found from edge `k - 1` by solving `∫ f = 1 - r` over the
//! step, where `r = N(t_(k-1)) - (k - 1)` is the residual carried from the
//! previous edge: no running sum of times or steps grows with `k`, so the
//! edges of a 65 536-entry table are as accurate as the first (each to a few
//! ulps of its time, and the residual to about 1e-13 step).

use stepper_profiles::{Curve, ExponentialExtent, LinearExtent};

/// Kronrod nodes on `[0, 1]` (the other half mirrored), QUADPACK's `qk15`.
const XGK: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
/// Kronrod weights for `XGK`.
const WGK: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_18,
    0.140_653_259_715_525_92,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_83,
];
/// Gauss weights for the 7-point rule on `XGK[1], XGK[3], XGK[5], XGK[7]`.
const WG: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// Deepest bisection of one quadrature interval.
const MAX_DEPTH: u32 = 30;

/// `∫a^b f` on a smooth piece, to about an ulp of the piece's integral.
///
/// The error of the Kronrod sum is estimated as QUADPACK's `qk15` does, from
/// its difference `δ` with the embedded Gauss sum: `|K| min(1, (200 δ/|K|)^1.5)`;
/// an interval whose estimate is above `2 ε |K|` is halved.
fn adaptive(f: &dyn Fn(f64) -> f64, a: f64, b: f64, depth: u32) -> f64 {
    let c = 0.5 * (a + b);
    let h = 0.5 * (b - a);
    let fc = f(c);
    let mut kronrod = WGK[7] * fc;
    let mut gauss = WG[3] * fc;
    for j in 0..7 {
        let pair = f(c - h * XGK[j]) + f(c + h * XGK[j]);
        kronrod += WGK[j] * pair;
        if j % 2 == 1 {
            gauss += WG[j / 2] * pair;
        }
    }
    let (kronrod, gauss) = (kronrod * h, gauss * h);
    let size = kronrod.abs();
    let estimate = size * (200.0 * (kronrod - gauss).abs() / size).powf(1.5).min(1.0);
    // A NaN estimate (a zero integral) counts as converged.
    let converged = estimate.is_nan() || estimate <= 2.0 * f64::EPSILON * size;
    if depth >= MAX_DEPTH || converged || c <= a || c >= b {
        kronrod
    } else {
        adaptive(f, a, c, depth + 1) + adaptive(f, c, b, depth + 1)
    }
}

/// A ramp as a function of time: `f(t)` rising from the start to `fmax` at
/// `t_ramp`, then held at `fmax`.
pub struct Model {
    f: Box<dyn Fn(f64) -> f64>,
    /// Times in `(0, t_ramp)` where a new formula takes over, sorted.
    joints: Vec<f64>,
    /// When the ramp reaches `fmax`, in s.
    pub t_ramp: f64,
    /// The frequency held after the ramp, in Hz.
    pub fmax: f64,
    /// For a ramp solved in frequency rather than time: its steps until
    /// `fmax`, and its edges.
    in_frequency: Option<(f64, EdgesFn)>,
}

/// The times of a ramp's edges `1..=n`.
type EdgesFn = Box<dyn Fn(usize) -> Vec<f64>>;

impl Model {
    /// A model from its frequency on `[0, t_ramp)` and its joints.
    pub fn new(
        f: impl Fn(f64) -> f64 + 'static,
        mut joints: Vec<f64>,
        t_ramp: f64,
        fmax: f64,
    ) -> Self {
        joints.retain(|&j| j > 0.0 && j < t_ramp);
        joints.sort_by(f64::total_cmp);
        Model {
            f: Box::new(f),
            joints,
            t_ramp,
            fmax,
            in_frequency: None,
        }
    }

    /// `f(t)` for any `t >= 0`.
    pub fn freq(&self, t: f64) -> f64 {
        if t < self.t_ramp {
            (self.f)(t)
        } else {
            self.fmax
        }
    }

    /// `∫a^b f`, split where the curve changes formula.
    pub fn integral(&self, a: f64, b: f64) -> f64 {
        let mut sum = 0.0;
        let mut from = a;
        for &cut in self.joints.iter().chain(std::iter::once(&self.t_ramp)) {
            if cut > from && cut < b {
                sum += self.piece(from, cut);
                from = cut;
            }
        }
        sum + self.piece(from, b)
    }

    fn piece(&self, a: f64, b: f64) -> f64 {
        if b <= a {
            0.0
        } else if a >= self.t_ramp {
            self.fmax * (b - a)
        } else {
            adaptive(&|t| self.freq(t), a, b, 0)
        }
    }

    /// Steps until the ramp reaches `fmax`: `N(t_ramp)`.
    pub fn ramp_steps(&self) -> f64 {
        match &self.in_frequency {
            Some((steps, _)) => *steps,
            None => self.integral(0.0, self.t_ramp),
        }
    }

    /// `N(t)`: the steps taken by time `t`.
    pub fn steps(&self, t: f64) -> f64 {
        self.integral(0.0, t)
    }

    /// Where the curve changes formula, in `(0, t_ramp)`, sorted.
    pub fn joints(&self) -> &[f64] {
        &self.joints
    }

    /// `t(0) = 0` and the times of pulse edges `1..=n`, in s.
    pub fn times(&self, n: usize) -> Vec<f64> {
        std::iter::once(0.0).chain(self.edges(n)).collect()
    }

    /// The times of pulse edges `1..=n`, in s: `t(k)` with `N(t(k)) = k`.
    pub fn edges(&self, n: usize) -> Vec<f64> {
        if let Some((_, edges)) = &self.in_frequency {
            return edges(n);
        }
        let mut out = Vec::with_capacity(n);
        let (mut t, mut residual) = (0.0f64, 0.0f64);
        for _ in 0..n {
            let need = 1.0 - residual;
            // f does not fall, so the edge is within need / f(t) of t.
            let mut lo = t;
            let mut hi = t + need / self.freq(t);
            while self.integral(t, hi) < need {
                hi = t + 2.0 * (hi - t);
            }
            let mut b = t + need / self.freq(t + 0.5 * (hi - t));
            if !(b > lo && b < hi) {
                b = 0.5 * (lo + hi);
            }
            for _ in 0..200 {
                let g = self.integral(t, b) - need;
                if g == 0.0 {
                    break;
                }
                if g < 0.0 {
                    lo = b;
                } else {
                    hi = b;
                }
                let newton = b - g / self.freq(b);
                let next = if newton > lo && newton < hi {
                    newton
                } else {
                    0.5 * (lo + hi)
                };
                if (next - b).abs() <= 2.0 * f64::EPSILON * b || hi - lo <= 2.0 * f64::EPSILON * b {
                    b = next;
                    break;
                }
                b = next;
            }
            residual = residual + self.integral(t, b) - 1.0;
            t = b;
            out.push(t);
        }
        out
    }
}

/// `Q = ∫0^1 g`, for the parameters that scale a fixed shape to `len` steps.
pub fn unit_integral(g: impl Fn(f64) -> f64 + 'static) -> f64 {
    Model::new(g, Vec::new(), 1.0, 0.0).integral(0.0, 1.0)
}

/// `1 / (1 + e^-x)`.
fn logistic(x: f64) -> f64 {
    1.0 / (1.0 + (-x).exp())
}

/// The sigmoid in time: `fmin + (fmax - fmin) · logistic(F (t - T/2) / (T/2))`
/// over `[0, T]`, with `T` such that the curve takes `len` steps.
pub fn sigmoid(fmin: f64, fmax: f64, flexible: f64, len: u32) -> Model {
    let delt = fmax - fmin;
    let q = unit_integral(move |s| fmin + delt * logistic(flexible * (2.0 * s - 1.0)));
    let t = len as f64 / q;
    let half = t / 2.0;
    Model::new(
        move |u| fmin + delt * logistic(flexible * (u - half) / half),
        vec![half],
        t,
        fmin + delt,
    )
}

/// How long an exponential ramp is.
pub enum Extent {
    /// `fmax` reached at the end of step `len`.
    Len(u32),
    /// The time constant, in s, or the acceleration, in Hz/s.
    Given(f64),
}

/// Seed 001: `f(t) = fmin + (f_inf - fmin)(1 - e^(-t/tau))`, up to `fmax`.
pub fn exponential(fmin: f64, fmax: f64, f_inf: f64, extent: Extent) -> Model {
    let span = f_inf - fmin;
    // f reaches fmax where 1 - e^-x = q = (fmax - fmin) / span, that is
    // x = ln(span / (f_inf - fmax)): from `ln(1 - q)` while `q` is small,
    // from the ratio near the asymptote, where `1 - q` has lost the gap.
    let q = (fmax - fmin) / span;
    let rise = if q < 0.5 {
        -(-q).ln_1p()
    } else {
        (span / (f_inf - fmax)).ln()
    };
    let tau = match extent {
        Extent::Given(tau) => tau,
        Extent::Len(len) => {
            // N scales with tau: the ramp at tau = 1 over x = t / tau in [0, rise].
            let q = unit_integral(move |s| fmin - span * (-s * rise).exp_m1()) * rise;
            len as f64 / q
        }
    };
    Model::new(
        move |t| fmin - span * (-t / tau).exp_m1(),
        Vec::new(),
        tau * rise,
        fmax,
    )
}

/// Seed 004 in time: `f(t) = fmin + a t`, up to `fmax`.
pub fn linear(fmin: f64, fmax: f64, extent: Extent) -> Model {
    let accel = match extent {
        Extent::Given(a) => a,
        Extent::Len(len) => {
            // The ramp takes T = (fmax - fmin) / a and T · ∫0^1 (fmin + (fmax - fmin) s) ds steps.
            let q = unit_integral(move |s| fmin + (fmax - fmin) * s);
            (fmax - fmin) * q / len as f64
        }
    };
    Model::new(
        move |t| fmin + accel * t,
        Vec::new(),
        (fmax - fmin) / accel,
        fmax,
    )
}

/// Zeng, Hu and Hu's three stages (seed 002, equation (5)), value and slope
/// continuous at both joints: `f0 + C (1 - e^(-B t))`, `a t + d`,
/// `fc - b (t - tc)²`.
///
/// The acceleration at the start, `B C = a + B (f1 - f0)`, vanishes as `B`
/// nears `-a / (f1 - f0)`; it is summed here in integers (`exact_sum`), and
/// `C` and `t1` follow from it.
pub fn three_stage(f0: f64, fc: f64, a: f64, f1: f64, f2: f64, shape: f64) -> Model {
    let start = exact_sum(a, shape, f1, f0).unwrap_or(a + shape * (f1 - f0));
    let c = start / shape;
    let t1 = if start < 0.5 * a {
        (start / a).ln() / shape
    } else {
        (shape * (f1 - f0) / a).ln_1p() / shape
    };
    let d = f1 - a * t1;
    let t2 = t1 + (f2 - f1) / a;
    let b = a * a / (4.0 * (fc - f2));
    let tc = t2 + 2.0 * (fc - f2) / a;
    Model::new(
        move |t| {
            if t < t1 {
                f0 - c * (-shape * t).exp_m1()
            } else if t < t2 {
                a * t + d
            } else {
                fc - b * (t - tc) * (t - tc)
            }
        },
        vec![t1, t2],
        tc,
        fc,
    )
}

/// `x = m 2^e` with an integer `m`.
fn integer_and_exponent(x: f64) -> (i128, i32) {
    let bits = x.to_bits();
    let exponent = ((bits >> 52) & 0x7ff) as i32;
    let fraction = (bits & ((1 << 52) - 1)) as i128;
    let (m, e) = if exponent == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), exponent - 1075)
    };
    (if x < 0.0 { -m } else { m }, e)
}

/// `m 2^e` for integers `m` and `e`, on the common scale `2^e` of `terms`:
/// `None` where a term would not fit 120 bits.
fn on_common_scale(terms: &[(i128, i32)]) -> Option<(Vec<i128>, i32)> {
    let e = terms.iter().map(|t| t.1).min()?;
    let scaled = terms
        .iter()
        .map(|&(m, k)| {
            let shift = u32::try_from(k - e).ok()?;
            let bits = 128 - m.unsigned_abs().leading_zeros();
            (bits + shift <= 120).then(|| m << shift)
        })
        .collect::<Option<Vec<_>>>()?;
    Some((scaled, e))
}

/// `a + b (x - y)`, computed exactly in integers and rounded once; `None`
/// where the operands' exponents are too far apart for 128 bits (then no
/// term is near enough to another to cancel, and floats do).
pub fn exact_sum(a: f64, b: f64, x: f64, y: f64) -> Option<f64> {
    let (diff, e_d) = on_common_scale(&[integer_and_exponent(x), integer_and_exponent(y)])?;
    let d = diff[0] - diff[1];
    let (mb, e_b) = integer_and_exponent(b);
    let d_bits = 128 - d.unsigned_abs().leading_zeros();
    if d_bits + 53 > 120 {
        return None;
    }
    let product = (mb * d, e_b + e_d);
    let (sum, e) = on_common_scale(&[integer_and_exponent(a), product])?;
    // The integer sum rounds once to a float; 2^e in two halves, each a
    // power of two a float holds.
    let half = e / 2;
    Some((sum[0] + sum[1]) as f64 * 2f64.powi(half) * 2f64.powi(e - half))
}

/// The jerk-limited ramp from its acceleration `a(s) = min(J s, A, J (T - s))`,
/// with the peak `A` lowered to `sqrt(J (fmax - f0))` when `accel` is out of
/// reach. `a` is symmetric about `T / 2`, so with `G(u) = ∫0^u min(J s, A) ds`,
/// `f(t) = f0 + G(t)` on the first half and `fmax - G(T - t)` on the second.
pub fn jerk_limited(f0: f64, fmax: f64, accel: f64, jerk: f64) -> Model {
    let dv = fmax - f0;
    let peak = accel.min((jerk * dv).sqrt());
    let t_jerk = peak / jerk;
    // The area under a(s) is peak · (T - t_jerk) = dv.
    let t_ramp = dv / peak + t_jerk;
    let g = move |u: f64| {
        if u <= t_jerk {
            jerk * u * u / 2.0
        } else {
            jerk * t_jerk * t_jerk / 2.0 + peak * (u - t_jerk)
        }
    };
    Model::new(
        move |t| {
            if t <= t_ramp / 2.0 {
                f0 + g(t)
            } else {
                fmax - g(t_ramp - t)
            }
        },
        vec![t_jerk, t_ramp / 2.0, t_ramp - t_jerk],
        t_ramp,
        fmax,
    )
}

/// The fastest ramp a motor allows: `df/dt = a(f)`, the acceleration `a`
/// straight between its points `(f, a)`. Solved here the other way round
/// from production's closed form in time: the time to reach `f` is the
/// integral `∫ df / a(f)` (adaptive quadrature), and `f(t)` inverts it by
/// Newton's method on `f` (its derivative `a`), safeguarded by bisection.
pub fn torque_limited(fmin: f64, fmax: f64, points: &[(f64, f64)]) -> Model {
    // The frequencies where `a` changes slope, from `fmin` to `fmax`.
    let mut at: Vec<f64> = vec![fmin];
    at.extend(points.iter().map(|p| p.0).filter(|&f| f > fmin && f < fmax));
    at.push(fmax);
    let points = points.to_vec();
    let at_for_steps = at.clone();
    let inverse = move |f: f64| -> f64 {
        let i = points.partition_point(|p| p.0 <= f);
        let a = if i == 0 {
            points[0].1
        } else if i == points.len() {
            points[i - 1].1
        } else {
            let ((f0, a0), (f1, a1)) = (points[i - 1], points[i]);
            a0 + (a1 - a0) * ((f - f0) / (f1 - f0))
        };
        1.0 / a
    };
    let inverse_for_steps = inverse.clone();
    // When each of those frequencies is reached.
    let mut times = vec![0.0];
    for w in at.windows(2) {
        let last = times[times.len() - 1];
        times.push(last + adaptive(&inverse, w[0], w[1], 0));
    }
    let t_ramp = times[times.len() - 1];
    let joints = times[1..times.len() - 1].to_vec();
    let f = move |t: f64| -> f64 {
        let i = times.partition_point(|&x| x <= t).clamp(1, times.len() - 1);
        let (from, to, t0) = (at[i - 1], at[i], times[i - 1]);
        // Newton on the time from the stretch's start to `f`.
        let (mut lo, mut hi) = (from, to);
        let mut f = (from + (t - t0) / inverse(from)).clamp(lo, hi);
        for _ in 0..100 {
            let g = t0 + adaptive(&inverse, from, f, 0) - t;
            if g == 0.0 {
                break;
            }
            if g < 0.0 {
                lo = f;
            } else {
                hi = f;
            }
            let newton = f - g / inverse(f);
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let done =
                (next - f).abs() <= 2.0 * f64::EPSILON * f || hi - lo <= 2.0 * f64::EPSILON * f;
            f = next;
            if done {
                break;
            }
        }
        f
    };
    let mut model = Model::new(f, joints, t_ramp, fmax);
    model.in_frequency = Some(in_frequency(at_for_steps, inverse_for_steps, t_ramp, fmax));
    model
}

/// A ramp whose acceleration `1 / inverse(f)` is smooth between the
/// frequencies `at` (from its start to its end): its steps until the end,
/// `∫ f / a df`, and its edges. Edge `k` is at the frequency `f_k` where
/// `N_i + ∫ f / a df` from the start `f_i` of its stretch reaches `k`
/// (Newton's method on `f`, whose derivative is `f / a`), at the time
/// `t_i + ∫ df / a` from there: every integral is taken from a stretch's
/// start, so no running sum grows with `k`. Past the end, the end
/// frequency held.
fn in_frequency(
    at: Vec<f64>,
    inverse: impl Fn(f64) -> f64 + Clone + 'static,
    t_ramp: f64,
    fmax: f64,
) -> (f64, EdgesFn) {
    let steps_over = {
        let inverse = inverse.clone();
        move |from: f64, to: f64| adaptive(&|f| f * inverse(f), from, to, 0)
    };
    // Steps and time at each stretch's start.
    let mut starts = vec![(0.0f64, 0.0f64)];
    for w in at.windows(2) {
        let (n, t) = starts[starts.len() - 1];
        starts.push((
            n + steps_over(w[0], w[1]),
            t + adaptive(&|x| inverse(x), w[0], w[1], 0),
        ));
    }
    let total = starts[starts.len() - 1].0;
    let edges = move |n: usize| {
        let mut out = Vec::with_capacity(n);
        let mut f = at[0];
        for k in 1..=n {
            let k = k as f64;
            // The stretch that holds edge `k`, if the ramp does.
            let Some(i) = (0..at.len() - 1).find(|&i| starts[i + 1].0 > k) else {
                out.push(t_ramp + (k - total) / fmax);
                continue;
            };
            let (from, (n_i, t_i)) = (at[i], starts[i]);
            let need = k - n_i;
            let (mut lo, mut hi) = (from.max(f.min(at[i + 1])), at[i + 1]);
            if lo < from || lo > hi {
                lo = from;
            }
            let mut next = 0.5 * (lo + hi);
            for _ in 0..200 {
                let g = steps_over(from, next) - need;
                if g == 0.0 {
                    break;
                }
                if g < 0.0 {
                    lo = next;
                } else {
                    hi = next;
                }
                // d/df ∫ f / a = f / a.
                let newton = next - g / (next * inverse(next));
                let x = if newton > lo && newton < hi {
                    newton
                } else {
                    0.5 * (lo + hi)
                };
                let done = (x - next).abs() <= 2.0 * f64::EPSILON * next
                    || hi - lo <= 2.0 * f64::EPSILON * next;
                next = x;
                if done {
                    break;
                }
            }
            f = next;
            // `f_k` holds the edge to an ulp of a frequency, which where
            // the ramp is slow is far more than an ulp of its time: the
            // steps it misses by, over `f`, are the time it misses by.
            let missed = steps_over(from, next) - need;
            out.push(t_i + adaptive(&|x| inverse(x), from, next, 0) - missed / next);
        }
        out
    };
    (total, Box::new(edges))
}

/// Entries of a table whose ramp takes `steps` steps (a real number): `None`
/// when `steps` is so near a whole number that rounding decides.
pub fn entries(steps: f64) -> Option<u64> {
    let whole = steps.round();
    if (steps - whole).abs() <= 1e-9 * steps.max(1.0) {
        Some(whole.max(1.0) as u64)
    } else if (steps - whole).abs() <= 1e-6 * steps.max(1.0) {
        None
    } else {
        Some(steps.ceil() as u64)
    }
}

/// The oracle's model of a curve in time, from a production curve's parameters (the parameters only: every
/// formula is this file's own).
pub fn model(curve: &Curve) -> Model {
    match *curve {
        Curve::Sigmoid(s) => sigmoid(s.fmin, s.fmax, s.flexible, s.len),
        Curve::Exponential(e) => exponential(
            e.fmin,
            e.fmax,
            e.f_inf,
            match e.extent {
                ExponentialExtent::Len(n) => Extent::Len(n),
                ExponentialExtent::Tau(tau) => Extent::Given(tau),
            },
        ),
        Curve::Linear(l) => linear(
            l.fmin,
            l.fmax,
            match l.extent {
                LinearExtent::Len(n) => Extent::Len(n),
                LinearExtent::Accel(a) => Extent::Given(a),
            },
        ),
        Curve::ThreeStage(z) => three_stage(z.fmin, z.fmax, z.accel, z.f1, z.f2, z.shape),
        Curve::JerkLimited(j) => jerk_limited(j.fmin, j.fmax, j.accel, j.jerk),
        Curve::TorqueLimited(t) => torque_limited(t.fmin, t.fmax, t.accel.points()),
        _ => unreachable!("every curve has a model"),
    }
}
