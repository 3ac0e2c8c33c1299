//! The non-sigmoid curves against independent models of themselves.
//!
//! For the exponential (by `len` and by `tau`), linear (by `len` and by
//! `accel`), three-stage (convex and concave start) and jerk-limited
//! (trapezoidal and triangular acceleration) curves, the default mode
//! (`exact`, `diffuse`) promises every pulse edge within half a tick of the
//! exact pulse time `t(k)`, the solution of `N(t) = ∫0^t f = k`, scaled to ticks
//! by `timer_hz / ticks_per_step`.
//!
//! The exact times here owe nothing to `profile-core`: each `f(t)` is written
//! out from the articles (the jerk-limited ramp from its
//! acceleration, which rises at `jerk`, holds and falls symmetrically), with
//! `std`'s `exp` and `ln` rather than `libm`. Parameters that production
//! solves for (`tau` from a step budget, `accel` from `len`) are solved here
//! from the numeric integral, not from a closed form. `N` is integrated
//! numerically (composite 5-point Gauss-Legendre on panels that never cross a
//! joint of the curve, summed cumulatively), and `t(k)` is found by bisection
//! on that numeric `N` down to adjacent floating-point numbers. After the ramp
//! every curve holds `fmax`, so a table whose length follows from the
//! parameters has `ceil(N(T_ramp))` entries, the final fraction at `fmax`.
//!
//! Also checked: table lengths; `left_endpoint` entries against
//! `1 / f(t(k))` under `nearest`; the three-stage joints (value and slope
//! continuous, zero slope at `fc`) in the model and in the tables' own
//! frequencies; seed 001's figures (`tau` 18.545 ms, rise time 19.745 ms);
//! and segment tables (counts sum to the ramp's steps, none empty, flash
//! `2 * word_bytes * n`, each count and period as the model cuts the ramp).
//!
//! Three-stage shapes within 1e-12 of 0 are checked too: a closed form that
//! subtracts two terms of size `a t / B` would lose its digits there.

mod common;

use common::seeds::{SEED001_SEGMENTS, jerk_limited, seed001, seed004, zeng};
use stepper_profiles::{
    Curve, Discretization, Error, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, Rounding, SegmentFigures, Spec, ThreeStage, Timer, Word,
};

/// What a correct edge (or rounded entry) may miss its exact value by: half a
/// tick, plus room for floating-point error far below a tick.
const TOLERANCE_TICKS: f64 = 0.5 + 1e-6;

/// Panels per smooth piece of a curve. 5-point Gauss-Legendre is exact for
/// the polynomial pieces and, at this density, accurate to rounding for the
/// exponential ones (`(h / tau)^10` is below 1e-20).
const PANELS_PER_PIECE: usize = 400;

// ---------------------------------------------------------------------------
// The independent model: f(t), its numeric integral, and t(k).

/// A curve as a function of time, with the joints where it is not smooth.
struct Model {
    /// `f(t)` on `[0, t_ramp)`, in Hz.
    f: Box<dyn Fn(f64) -> f64>,
    /// Joints inside `(0, t_ramp)`, where a new formula takes over.
    joints: Vec<f64>,
    /// When the curve reaches `fmax`, in s.
    t_ramp: f64,
    /// The frequency held after the ramp, in Hz.
    fmax: f64,
}

impl Model {
    /// `f(t)` for any `t >= 0`: the curve, then `fmax`.
    fn freq(&self, t: f64) -> f64 {
        if t < self.t_ramp {
            (self.f)(t)
        } else {
            self.fmax
        }
    }
}

/// The nodes and weights of 5-point Gauss-Legendre on `[-1, 1]`.
fn gauss_legendre_5() -> [(f64, f64); 5] {
    let inner = (5.0 - 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
    let outer = (5.0 + 2.0 * (10.0f64 / 7.0).sqrt()).sqrt() / 3.0;
    let w_inner = (322.0 + 13.0 * 70.0f64.sqrt()) / 900.0;
    let w_outer = (322.0 - 13.0 * 70.0f64.sqrt()) / 900.0;
    [
        (-outer, w_outer),
        (-inner, w_inner),
        (0.0, 128.0 / 225.0),
        (inner, w_inner),
        (outer, w_outer),
    ]
}

/// `N(t)` of a model, integrated numerically on panels that end at every joint.
struct Numeric<'a> {
    model: &'a Model,
    rule: [(f64, f64); 5],
    /// Panel boundaries, from 0 to a little past the ramp.
    nodes: Vec<f64>,
    /// `N` at each node.
    cumulative: Vec<f64>,
    /// Index of the node at `t_ramp`.
    ramp_node: usize,
}

impl<'a> Numeric<'a> {
    fn new(model: &'a Model) -> Self {
        let mut pieces = vec![0.0];
        let mut joints = model.joints.clone();
        joints.sort_by(f64::total_cmp);
        for j in joints {
            let last = *pieces.last().expect("starts with 0");
            if j > last + 1e-12 * model.t_ramp && j < model.t_ramp * (1.0 - 1e-12) {
                pieces.push(j);
            }
        }
        pieces.push(model.t_ramp);
        let mut nodes = vec![0.0];
        for w in pieces.windows(2) {
            for i in 1..=PANELS_PER_PIECE {
                nodes.push(if i == PANELS_PER_PIECE {
                    w[1]
                } else {
                    w[0] + (w[1] - w[0]) * i as f64 / PANELS_PER_PIECE as f64
                });
            }
        }
        let ramp_node = nodes.len() - 1;
        // After the ramp: a few steps at fmax, enough for the final fraction.
        for i in 1..=4 {
            nodes.push(model.t_ramp + i as f64 / model.fmax);
        }
        let mut numeric = Numeric {
            model,
            rule: gauss_legendre_5(),
            nodes,
            cumulative: vec![0.0],
            ramp_node,
        };
        for i in 0..numeric.nodes.len() - 1 {
            let (a, b) = (numeric.nodes[i], numeric.nodes[i + 1]);
            let next = numeric.cumulative[i] + numeric.integral(a, b);
            numeric.cumulative.push(next);
        }
        numeric
    }

    /// `∫a^b f` by one application of the rule (`[a, b]` inside one panel).
    fn integral(&self, a: f64, b: f64) -> f64 {
        let half = (b - a) / 2.0;
        let mid = (a + b) / 2.0;
        half * self
            .rule
            .iter()
            .map(|&(x, w)| w * self.model.freq(mid + half * x))
            .sum::<f64>()
    }

    /// Steps until the curve reaches `fmax`.
    fn ramp_steps(&self) -> f64 {
        self.cumulative[self.ramp_node]
    }

    /// `N(t)`, for `t` within the integrated span.
    fn steps(&self, t: f64) -> f64 {
        let panel = self.nodes.partition_point(|&n| n <= t).saturating_sub(1);
        let panel = panel.min(self.nodes.len() - 2);
        self.cumulative[panel] + self.integral(self.nodes[panel], t)
    }

    /// `t(k)`: bisection on the numeric `N` inside the panel that brackets `k`.
    fn time_of(&self, k: f64) -> f64 {
        if k <= 0.0 {
            return 0.0;
        }
        let end = *self.cumulative.last().expect("integrated");
        assert!(
            k <= end,
            "expected step {k} within the integrated span ({end})"
        );
        let panel = self.cumulative.partition_point(|&c| c < k) - 1;
        let (mut lo, mut hi) = (self.nodes[panel], self.nodes[panel + 1]);
        let base = self.cumulative[panel];
        loop {
            let mid = lo + (hi - lo) / 2.0;
            if mid <= lo || mid >= hi {
                return mid;
            }
            if base + self.integral(self.nodes[panel], mid) < k {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
}

/// Seed 001: `f(t) = f0 + (f_inf - f0)(1 - exp(-t/tau))` up to `fmax`.
fn exponential_model(e: &Exponential) -> Model {
    let (f0, fmax, f_inf) = (e.fmin, e.fmax, e.f_inf);
    // f(T) = fmax at T = tau * rise, whatever tau is.
    let rise = ((f_inf - f0) / (f_inf - fmax)).ln();
    let tau = match e.extent {
        ExponentialExtent::Tau(tau) => tau,
        ExponentialExtent::Len(len) => {
            // N scales with tau: integrate the ramp at tau = 1 and scale it to `len` steps.
            let unit = Model {
                f: Box::new(move |s: f64| f0 + (f_inf - f0) * (1.0 - (-s).exp())),
                joints: Vec::new(),
                t_ramp: rise,
                fmax,
            };
            len as f64 / Numeric::new(&unit).ramp_steps()
        }
    };
    Model {
        f: Box::new(move |t: f64| f0 + (f_inf - f0) * (1.0 - (-t / tau).exp())),
        joints: Vec::new(),
        t_ramp: tau * rise,
        fmax,
    }
}

/// Seed 004 in time: `f(t) = f0 + a t` up to `fmax`.
fn linear_model(l: &Linear) -> Model {
    let (f0, fmax) = (l.fmin, l.fmax);
    let accel = match l.extent {
        LinearExtent::Accel(a) => a,
        LinearExtent::Len(len) => {
            // N scales with 1/a: integrate the ramp at a = 1 and scale it to `len` steps.
            let unit = Model {
                f: Box::new(move |s: f64| f0 + s),
                joints: Vec::new(),
                t_ramp: fmax - f0,
                fmax,
            };
            Numeric::new(&unit).ramp_steps() / len as f64
        }
    };
    Model {
        f: Box::new(move |t: f64| f0 + accel * t),
        joints: Vec::new(),
        t_ramp: (fmax - f0) / accel,
        fmax,
    }
}

/// Zeng, Hu and Hu's three stages (seed 002, equation (5)), value and slope
/// continuous at the joints: `t1 = ln(1 + B (f1 - f0) / a) / B`,
/// `t2 = t1 + (f2 - f1) / a`, `tc = t2 + 2 (fc - f2) / a` (the paper's
/// `tc = t2 + a / 4b` breaks the slope's continuity; `a / 2b` keeps it).
#[derive(Clone, Copy, Debug)]
struct Zeng {
    f0: f64,
    fc: f64,
    a: f64,
    shape: f64,
    c: f64,
    d: f64,
    b: f64,
    t1: f64,
    t2: f64,
    tc: f64,
}

impl Zeng {
    fn new(z: &ThreeStage) -> Self {
        let (f0, f1, f2, fc, a, shape) = (z.fmin, z.f1, z.f2, z.fmax, z.accel, z.shape);
        let c = f1 - f0 + a / shape;
        let t1 = (shape * (f1 - f0) / a).ln_1p() / shape;
        let d = f1 - a * t1;
        let t2 = t1 + (f2 - f1) / a;
        let b = a * a / (4.0 * (fc - f2));
        let tc = t2 + 2.0 * (fc - f2) / a;
        Zeng {
            f0,
            fc,
            a,
            shape,
            c,
            d,
            b,
            t1,
            t2,
            tc,
        }
    }

    /// The exponential stage, `f0 + C (1 - exp(-B t))`, for any `t` (with
    /// `exp_m1`, so that a nearly linear start, `B` near 0, stays exact).
    fn stage1(&self, t: f64) -> f64 {
        self.f0 - self.c * (-self.shape * t).exp_m1()
    }

    /// The linear stage, `a t + d`, for any `t`.
    fn stage2(&self, t: f64) -> f64 {
        self.a * t + self.d
    }

    /// The parabolic stage, `-b (t - tc)² + fc`, for any `t`.
    fn stage3(&self, t: f64) -> f64 {
        -self.b * (t - self.tc) * (t - self.tc) + self.fc
    }

    fn freq(&self, t: f64) -> f64 {
        if t < self.t1 {
            self.stage1(t)
        } else if t < self.t2 {
            self.stage2(t)
        } else if t < self.tc {
            self.stage3(t)
        } else {
            self.fc
        }
    }

    fn model(self) -> Model {
        Model {
            f: Box::new(move |t| self.freq(t)),
            joints: vec![self.t1, self.t2],
            t_ramp: self.tc,
            fmax: self.fc,
        }
    }
}

/// The jerk-limited ramp from its acceleration: `a(s) = min(J s, A, J (T - s))`,
/// with the peak `A` lowered to `sqrt(J (fmax - f0))` when `accel` is out of
/// reach. `a` is symmetric about `T / 2`, so with `G(u) = ∫0^u min(J s, A) ds`,
/// `f(t) = f0 + G(t)` on the first half and `fmax - G(T - t)` on the second.
fn jerk_model(j: &JerkLimited) -> Model {
    let (f0, fmax, jerk) = (j.fmin, j.fmax, j.jerk);
    let dv = fmax - f0;
    let peak = j.accel.min((jerk * dv).sqrt());
    let t_jerk = peak / jerk;
    // The area under a(s) is peak * (T - t_jerk) = dv.
    let t_ramp = dv / peak + t_jerk;
    let g = move |u: f64| {
        if u <= t_jerk {
            jerk * u * u / 2.0
        } else {
            jerk * t_jerk * t_jerk / 2.0 + peak * (u - t_jerk)
        }
    };
    Model {
        f: Box::new(move |t| {
            if t <= t_ramp / 2.0 {
                f0 + g(t)
            } else {
                fmax - g(t_ramp - t)
            }
        }),
        joints: vec![t_jerk, t_ramp / 2.0, t_ramp - t_jerk],
        t_ramp,
        fmax,
    }
}

fn model_of(curve: &Curve) -> Model {
    match curve {
        Curve::Exponential(e) => exponential_model(e),
        Curve::Linear(l) => linear_model(l),
        Curve::ThreeStage(z) => Zeng::new(z).model(),
        Curve::JerkLimited(j) => jerk_model(j),
        other => panic!("expected a non-sigmoid curve, got {other:?}"),
    }
}

// ---------------------------------------------------------------------------
// The cases.

struct Case {
    name: &'static str,
    spec: Spec,
    /// Whether the length follows from the parameters (not `len`).
    derived_len: bool,
}

fn cases() -> Vec<Case> {
    let case = |name, curve, timer: Timer, derived_len| Case {
        name,
        spec: Spec::new(curve, timer),
        derived_len,
    };
    let timer_2 = |hz| Timer {
        ticks_per_step: 2,
        ..Timer::new(hz)
    };
    vec![
        case(
            "exponential, seed 001 by len (120 steps), 1 MHz",
            Curve::Exponential(seed001()),
            Timer::new(1_000_000),
            false,
        ),
        case(
            "exponential, seed 001 by len (120 steps), 10 MHz",
            Curve::Exponential(seed001()),
            Timer::new(10_000_000),
            false,
        ),
        case(
            "exponential by tau (30 ms), 1 MHz",
            Curve::Exponential(Exponential {
                fmin: 400.0,
                fmax: 8000.0,
                f_inf: 9000.0,
                extent: ExponentialExtent::Tau(0.03),
            }),
            Timer::new(1_000_000),
            true,
        ),
        case(
            "exponential by tau (5 ms), 16 MHz, u32, 2 ticks per step",
            Curve::Exponential(Exponential {
                fmin: 150.0,
                fmax: 20_000.0,
                f_inf: 20_500.0,
                extent: ExponentialExtent::Tau(0.005),
            }),
            Timer {
                word: Word::U32,
                ..timer_2(16_000_000)
            },
            true,
        ),
        Case {
            name: "linear, seed 004 by len (200 steps), 50 MHz, 2 ticks per step",
            spec: seed004(200),
            derived_len: false,
        },
        case(
            "linear by accel (50 000 Hz/s), 2 MHz",
            Curve::Linear(Linear {
                fmin: 300.0,
                fmax: 6000.0,
                extent: LinearExtent::Accel(50_000.0),
            }),
            Timer::new(2_000_000),
            true,
        ),
        case(
            "three_stage, Zeng 100 -> 1200 Hz, shape 12, 1 MHz",
            Curve::ThreeStage(zeng(12.0)),
            Timer::new(1_000_000),
            true,
        ),
        case(
            "three_stage, Zeng 100 -> 1200 Hz, shape -5, 1 MHz",
            Curve::ThreeStage(zeng(-5.0)),
            Timer::new(1_000_000),
            true,
        ),
        case(
            "three_stage, shape 40, f1 = f2, 8 MHz",
            Curve::ThreeStage(ThreeStage {
                fmin: 250.0,
                fmax: 9000.0,
                accel: 60_000.0,
                f1: 3000.0,
                f2: 3000.0,
                shape: 40.0,
            }),
            Timer::new(8_000_000),
            true,
        ),
        case(
            "jerk_limited, trapezoidal acceleration, 10 MHz",
            Curve::JerkLimited(jerk_limited()),
            Timer::new(10_000_000),
            true,
        ),
        case(
            "jerk_limited, triangular acceleration, 1 MHz",
            Curve::JerkLimited(JerkLimited {
                fmin: 200.0,
                fmax: 1000.0,
                accel: 1e6,
                jerk: 200_000.0,
            }),
            Timer::new(1_000_000),
            true,
        ),
    ]
}

fn scale(spec: &Spec) -> f64 {
    spec.timer.timer_hz as f64 / spec.timer.ticks_per_step as f64
}

fn table(name: &str, spec: &Spec) -> Vec<u32> {
    spec.table()
        .unwrap_or_else(|e| panic!("{name}: expected a valid table, got the error {e}"))
        .periods
}

/// The independent length: `len`, or `ceil(N(T_ramp))`.
fn expected_len(case: &Case, numeric: &Numeric) -> u32 {
    let steps = numeric.ramp_steps();
    if !case.derived_len {
        let given = case.spec.len();
        assert!(
            (steps - given as f64).abs() < 1e-9 * steps,
            "{}: expected the model's ramp to take the given {given} steps, got {steps}",
            case.name
        );
        return given;
    }
    // A ramp of a whole number of steps (a symmetric jerk-limited ramp takes
    // exactly (fmin + fmax) / 2 * T) has that many entries, with no fraction
    // to add; rounding noise in the last bits must not add an entry. Near but
    // not at a whole number, `ceil` would hinge on the last bits: avoid.
    let whole = steps.round();
    if (steps - whole).abs() <= 1e-9 * steps {
        return whole as u32;
    }
    assert!(
        (steps - whole).abs() > 1e-6,
        "{}: choose parameters whose ramp is not within 1e-6 of a whole number of steps \
         (got {steps})",
        case.name
    );
    steps.ceil() as u32
}

// ---------------------------------------------------------------------------
// The tests.

/// Checks a default-mode table against the model: its length, and every
/// prefix sum within half a tick of the exact edge. Returns the length and
/// the worst edge error, with the edge where it occurs.
fn check_edges(case: &Case) -> (u32, f64, usize) {
    let model = model_of(&case.spec.curve);
    let numeric = Numeric::new(&model);
    let len = expected_len(case, &numeric);
    let periods = table(case.name, &case.spec);
    assert_eq!(
        periods.len(),
        len as usize,
        "{}: expected {len} entries (the model's ramp takes {} steps), got {}",
        case.name,
        numeric.ramp_steps(),
        periods.len()
    );
    assert_eq!(case.spec.len(), len, "{}: Spec::len()", case.name);
    let scale = scale(&case.spec);
    let mut edge = 0u64;
    let mut worst = (0.0f64, 0usize);
    for (k, &p) in periods.iter().enumerate() {
        edge += u64::from(p);
        let exact = numeric.time_of((k + 1) as f64) * scale;
        let error = edge as f64 - exact;
        assert!(
            error.abs() <= TOLERANCE_TICKS,
            "{}: expected edge {} within 0.5 tick of its exact time {exact:.6} ticks, \
             got {edge} (off by {error:.6}; entry {k} = {p})",
            case.name,
            k + 1,
        );
        if error.abs() > worst.0 {
            worst = (error.abs(), k + 1);
        }
    }
    (len, worst.0, worst.1)
}

#[test]
fn default_tables_put_every_edge_within_half_a_tick() {
    let mut report = Vec::new();
    for case in &cases() {
        let (len, worst, at) = check_edges(case);
        report.push(format!(
            "{}: {len} entries, worst edge {worst:.4} tick at edge {at}",
            case.name
        ));
    }
    eprintln!("{}", report.join("\n"));
}

/// A three-stage case near Zeng's parameters (`accel` 4100, so that the ramp
/// is not a whole number of steps as `shape` approaches 0) with another shape.
fn zeng_case(name: &'static str, shape: f64, timer_hz: u32) -> Case {
    let curve = ThreeStage {
        accel: 4100.0,
        ..zeng(shape)
    };
    Case {
        name,
        spec: Spec::new(Curve::ThreeStage(curve), Timer::new(timer_hz)),
        derived_len: true,
    }
}

/// As the shape `B` approaches 0 the exponential stage becomes linear
/// (`C = f1 - f0 + a/B` grows as `1/B`); the tables must stay exact.
#[test]
fn three_stage_with_a_nearly_linear_start() {
    for case in [
        zeng_case("three_stage shape 1e-3, 6 MHz", 1e-3, 6_000_000),
        zeng_case("three_stage shape 1e-6, 6 MHz", 1e-6, 6_000_000),
        zeng_case("three_stage shape -1e-3, 6 MHz", -1e-3, 6_000_000),
        zeng_case("three_stage shape -1e-6, 6 MHz", -1e-6, 6_000_000),
    ] {
        let (len, worst, at) = check_edges(&case);
        eprintln!(
            "{}: {len} entries, worst edge {worst:.4} tick at edge {at}",
            case.name
        );
    }
}

/// The same for shapes closer to 0. The textbook step count of the
/// exponential stage, `(f0 + C) t + C expm1(-B t) / B`, subtracts two terms
/// of size `C t` (about `a t / B`) to leave one of size `f t`; written that
/// way it was 0.517 tick off at `B = 1e-8`, 7.4 at `1e-10` and 1333 at
/// `-1e-12` with these parameters at 6 MHz.
#[test]
fn three_stage_with_an_almost_zero_shape() {
    for case in [
        zeng_case("three_stage shape 1e-8, 6 MHz", 1e-8, 6_000_000),
        zeng_case("three_stage shape -1e-8, 6 MHz", -1e-8, 6_000_000),
        zeng_case("three_stage shape 1e-10, 6 MHz", 1e-10, 6_000_000),
        zeng_case("three_stage shape 1e-12, 6 MHz", 1e-12, 6_000_000),
        zeng_case("three_stage shape -1e-12, 6 MHz", -1e-12, 6_000_000),
    ] {
        check_edges(&case);
    }
}

#[test]
fn left_endpoint_entries_are_the_rounded_frequency_at_each_edge() {
    for case in &cases() {
        let spec = case
            .spec
            .with_discretization(Discretization::LeftEndpoint)
            .with_rounding(Rounding::Nearest);
        let model = model_of(&spec.curve);
        let numeric = Numeric::new(&model);
        let periods = table(case.name, &spec);
        assert_eq!(
            periods.len(),
            expected_len(case, &numeric) as usize,
            "{}: left_endpoint length",
            case.name
        );
        let scale = scale(&spec);
        for (k, &p) in periods.iter().enumerate() {
            let exact = scale / model.freq(numeric.time_of(k as f64));
            assert!(
                (p as f64 - exact).abs() <= TOLERANCE_TICKS,
                "{}: expected left_endpoint entry {k} to be {exact:.6} ticks rounded, got {p}",
                case.name
            );
        }
    }
}

/// The slope of `f` just left and just right of `t`, from each side's own formula.
fn one_sided_slopes(left: impl Fn(f64) -> f64, right: impl Fn(f64) -> f64, t: f64) -> (f64, f64) {
    let h = 1e-6 * t.max(1e-3);
    (
        (left(t + h) - left(t - h)) / (2.0 * h),
        (right(t + h) - right(t - h)) / (2.0 * h),
    )
}

#[test]
fn three_stage_joints_are_smooth_in_the_model_and_in_the_tables() {
    for shape in [12.0, -5.0, 2.0, -13.0] {
        let z = Zeng::new(&zeng(shape));
        let name = format!("three_stage shape {shape}");
        // Value continuity at the joints, and the frequencies they name.
        for (t, left, right) in [
            (z.t1, z.stage1(z.t1), z.stage2(z.t1)),
            (z.t2, z.stage2(z.t2), z.stage3(z.t2)),
        ] {
            assert!(
                (left - right).abs() < 1e-9 * z.fc,
                "{name}: expected f continuous at t = {t}, got {left} and {right}"
            );
        }
        assert!((z.stage1(z.t1) - 400.0).abs() < 1e-9, "{name}: f(t1) = f1");
        assert!((z.stage2(z.t2) - 900.0).abs() < 1e-9, "{name}: f(t2) = f2");
        assert!((z.stage3(z.tc) - 1200.0).abs() < 1e-9, "{name}: f(tc) = fc");
        // Slope continuity: both sides equal `a` at t1 and t2, and 0 at tc.
        let (l1, r1) = one_sided_slopes(|t| z.stage1(t), |t| z.stage2(t), z.t1);
        let (l2, r2) = one_sided_slopes(|t| z.stage2(t), |t| z.stage3(t), z.t2);
        let (l3, _) = one_sided_slopes(|t| z.stage3(t), |_| z.fc, z.tc);
        for (what, slope, expected) in [
            ("left of t1", l1, z.a),
            ("right of t1", r1, z.a),
            ("left of t2", l2, z.a),
            ("right of t2", r2, z.a),
            ("at tc", l3, 0.0),
        ] {
            assert!(
                (slope - expected).abs() < 1e-4 * z.a,
                "{name}: expected df/dt {what} to be {expected}, got {slope}"
            );
        }
        // Approaching fc, the slope falls linearly to 0 (the paper's a/4b would
        // leave it at a/2 with a jump in f).
        for fraction in [0.5, 0.1, 0.01] {
            let t = z.tc - fraction * (z.tc - z.t2);
            let (slope, _) = one_sided_slopes(|t| z.freq(t), |t| z.freq(t), t);
            assert!(
                (slope - fraction * z.a).abs() < 1e-4 * z.a,
                "{name}: expected df/dt = {} at {fraction} of the parabola before tc, got {slope}",
                fraction * z.a
            );
        }

        // The tables: their frequencies and accelerations near each joint
        // follow the model.
        let spec = Spec::new(Curve::ThreeStage(zeng(shape)), Timer::new(1_000_000));
        let periods = table(&name, &spec);
        let scale = scale(&spec);
        let model = z.model();
        let numeric = Numeric::new(&model);
        let edges: Vec<f64> = std::iter::once(0.0)
            .chain(periods.iter().scan(0u64, |s, &p| {
                *s += u64::from(p);
                Some(*s as f64)
            }))
            .collect();
        let exact: Vec<f64> = (0..=periods.len())
            .map(|k| numeric.time_of(k as f64) * scale)
            .collect();
        let len = periods.len();
        let mut linear_windows = 0;
        for (joint, t) in [("t1", z.t1), ("t2", z.t2), ("tc", z.tc)] {
            // The step in which the joint falls.
            let k = exact.partition_point(|&e| e <= t * scale).saturating_sub(1);
            for i in k.saturating_sub(3)..(k + 4).min(len) {
                let table_hz = scale / periods[i] as f64;
                let mid = (exact[i] + exact[i + 1]) / 2.0 / scale;
                let model_hz = model.freq(mid);
                // One tick of rounding in a period of `p` ticks is 1/p of the frequency.
                let allowed = model_hz * (1.0 / periods[i] as f64 + 1e-6);
                assert!(
                    (table_hz - model_hz).abs() <= allowed,
                    "{name}: near {joint}, expected entry {i} at {model_hz:.3} Hz, got \
                     {table_hz:.3} Hz ({} ticks)",
                    periods[i]
                );
            }
            // Acceleration over windows of m steps either side of the joint,
            // from the table's edges and from the exact ones.
            let m = 4;
            let window_hz = |e: &[f64], i: usize| m as f64 * scale / (e[i + m] - e[i]);
            let window_t = |e: &[f64], i: usize| (e[i] + e[i + m]) / 2.0 / scale;
            let first = k.saturating_sub(2 * m);
            let last = (k + 2 * m).min(len - m);
            for i in (first..last.saturating_sub(m)).step_by(m) {
                let slope = |e: &[f64]| {
                    (window_hz(e, i + m) - window_hz(e, i)) / (window_t(e, i + m) - window_t(e, i))
                };
                let (from_table, from_model) = (slope(&edges), slope(&exact));
                // Each edge within half a tick: a window's frequency is good to
                // one tick in its length.
                let error_hz = |i: usize| window_hz(&exact, i) / (exact[i + m] - exact[i]);
                let allowed = 1.5 * (error_hz(i) + error_hz(i + m))
                    / (window_t(&exact, i + m) - window_t(&exact, i));
                assert!(
                    (from_table - from_model).abs() <= allowed,
                    "{name}: near {joint}, expected the table's acceleration over steps {i}..{} \
                     to be {from_model:.1} Hz/s (within {allowed:.1}), got {from_table:.1}",
                    i + 2 * m
                );
                if joint == "tc" {
                    assert!(
                        from_table.abs() < 0.1 * z.a,
                        "{name}: expected the acceleration to vanish near fc, got {from_table:.1} \
                         Hz/s over steps {i}..{}",
                        i + 2 * m
                    );
                }
                // Both windows inside the linear stage: the acceleration is `a`.
                let inside = |t: f64| t >= z.t1 * scale && t <= z.t2 * scale;
                if inside(exact[i]) && inside(exact[i + 2 * m]) {
                    assert!(
                        (from_table - z.a).abs() <= allowed + 1e-6 * z.a,
                        "{name}: expected {} Hz/s in the linear stage (within {allowed:.1}), \
                         got {from_table:.1} over steps {i}..{}",
                        z.a,
                        i + 2 * m
                    );
                    linear_windows += 1;
                }
            }
        }
        assert!(
            linear_windows > 0,
            "{name}: expected some windows inside the linear stage"
        );
    }
}

#[test]
fn seed_001_figures() {
    let e = seed001();
    let model = exponential_model(&e);
    let numeric = Numeric::new(&model);
    let rise = model.t_ramp;
    let tau = rise / ((15_000.0f64 - 500.0) / (15_000.0 - 10_000.0)).ln();
    // The seed's figures, to the digits it gives.
    assert_eq!(format!("{:.3}", tau * 1e3), "18.545", "tau in ms: {tau}");
    assert_eq!(
        format!("{:.3}", rise * 1e3),
        "19.745",
        "rise time in ms: {rise}"
    );
    assert!((numeric.ramp_steps() - 120.0).abs() < 1e-9);
    // Production's figures agree with the independent ones.
    assert!(
        (e.tau() - tau).abs() < 1e-12 * tau,
        "expected Exponential::tau() = {tau}, got {}",
        e.tau()
    );
    assert!(
        (e.rise_time() - rise).abs() < 1e-12 * rise,
        "expected Exponential::rise_time() = {rise}, got {}",
        e.rise_time()
    );
    // The table at 1 MHz plays the rise time to half a tick.
    let spec = Spec::new(Curve::Exponential(e), Timer::new(1_000_000));
    let figures = spec.figures().expect("seed 001 is valid");
    let exact = rise * 1e6;
    assert!(
        (19_745.0..19_746.0).contains(&exact),
        "rise time {exact} ticks"
    );
    assert!(
        (figures.total_ticks as f64 - exact).abs() <= 0.5,
        "expected the table's total within 0.5 of {exact:.3} ticks, got {}",
        figures.total_ticks
    );
    assert_eq!(figures.len, 120);
    assert!(
        figures.max_edge_error_ticks <= 0.5,
        "{}",
        figures.max_edge_error_ticks
    );
    // The same ramp given by its time constant is the same table.
    let by_tau = Spec::new(
        Curve::Exponential(Exponential {
            extent: ExponentialExtent::Tau(e.tau()),
            ..e
        }),
        Timer::new(1_000_000),
    );
    assert_eq!(
        table("seed 001 by tau", &by_tau),
        table("seed 001", &spec),
        "expected seed 001 by its tau to equal seed 001 by its 120 steps"
    );
}

fn word_bytes(word: Word) -> u32 {
    match word {
        Word::U16 => 2,
        Word::U32 => 4,
    }
}

/// Checks one segment table against its ramp and the independent model.
fn check_segments(name: &str, spec: &Spec, pairs: &[(u32, u32)], figures: &SegmentFigures) {
    let n = pairs.len() as u32;
    let len = spec.len();
    let counts: u64 = pairs.iter().map(|&(_, c)| u64::from(c)).sum();
    assert_eq!(
        counts,
        u64::from(len),
        "{name}, {n} segments: expected the counts to sum to the ramp's {len} steps"
    );
    assert!(
        pairs.iter().all(|&(_, c)| c >= 1),
        "{name}, {n} segments: expected every count >= 1, got {pairs:?}"
    );
    assert_eq!(figures.segments, n, "{name}: figures.segments");
    assert_eq!(figures.steps, len, "{name}: figures.steps");
    let wb = word_bytes(spec.timer.word);
    assert_eq!(
        figures.flash_bytes,
        2 * wb * n,
        "{name}, {n} segments: flash_bytes"
    );
    assert_eq!(
        figures.per_step_flash_bytes,
        wb * len,
        "{name}: per_step_flash_bytes"
    );
    let played: u64 = pairs
        .iter()
        .map(|&(p, c)| u64::from(p) * u64::from(c))
        .sum();
    assert_eq!(figures.total_ticks, played, "{name}: total_ticks");

    // Independently: segment i spans [i T/n, (i+1) T/n] of the ramp's duration
    // T = t(len); its count is the step count at its end, rounded, minus the
    // one at its start; its period is its duration over its count.
    let model = model_of(&spec.curve);
    let numeric = Numeric::new(&model);
    let duration = numeric.time_of(len as f64);
    let dt = duration / n as f64;
    let scale = scale(spec);
    let (mut before, mut played_end) = (0u32, 0u64);
    for (i, &(period, count)) in pairs.iter().enumerate() {
        let after = if i + 1 == pairs.len() {
            len
        } else {
            numeric.steps((i + 1) as f64 * dt).round() as u32
        };
        assert_eq!(
            count,
            after - before,
            "{name}, {n} segments: segment {i}'s count"
        );
        let exact = dt * scale / count as f64;
        played_end += u64::from(period) * u64::from(count);
        if spec.rounding == Rounding::Diffuse {
            // Diffused: the segment's last step ends as near its exact edge
            // as a whole period repeated `count` times allows.
            let end = numeric.time_of(after as f64) * scale;
            assert!(
                (played_end as f64 - end).abs() <= count as f64 / 2.0 + 1e-6,
                "{name}, {n} segments: expected segment {i} to end within {} ticks of \
                 {end:.4}, got {played_end}",
                count as f64 / 2.0
            );
        } else {
            assert!(
                (period as f64 - exact).abs() <= TOLERANCE_TICKS,
                "{name}, {n} segments: expected segment {i}'s period {exact:.4} rounded, \
                 got {period}"
            );
        }
        before = after;
    }
}

#[test]
fn segment_tables_cover_the_ramp() {
    // The macro's table is the library's.
    let spec = Spec::new(Curve::Exponential(seed001()), Timer::new(1_000_000));
    let mut pairs = Vec::new();
    let figures = spec
        .for_each_segment(8, |_, p, c| pairs.push((p, c)))
        .expect("seed 001 in 8 segments");
    let from_macro: Vec<(u32, u32)> = SEED001_SEGMENTS
        .iter()
        .map(|&(p, c)| (u32::from(p), u32::from(c)))
        .collect();
    assert_eq!(
        from_macro, pairs,
        "expected period_table!(segments = 8) to equal Spec::for_each_segment"
    );
    check_segments("seed 001", &spec, &pairs, &figures);
    let mut buffer = [(0u16, 0u16); 8];
    assert_eq!(spec.generate_segments(&mut buffer), Ok(figures));
    assert_eq!(buffer, SEED001_SEGMENTS);

    let mut tables = 0;
    for case in &cases() {
        for n in [1, 2, 3, 5, 8, 16, 32] {
            let mut pairs = Vec::new();
            match case.spec.for_each_segment(n, |_, p, c| pairs.push((p, c))) {
                Ok(figures) => {
                    check_segments(case.name, &case.spec, &pairs, &figures);
                    tables += 1;
                }
                // Equal-time segments starve the slow start first; only a
                // finer cut may run out of steps.
                Err(Error::EmptySegment { index, steps }) if n > 8 => {
                    assert_eq!(steps, case.spec.len(), "{}", case.name);
                    assert!(index < n, "{}", case.name);
                }
                Err(e) => panic!(
                    "{}: expected {n} segments to work, got the error {e}",
                    case.name
                ),
            }
        }
        // More segments than steps: some segment would be empty, which is
        // refused before any work (or allocation) for the segments.
        let len = case.spec.len();
        let result = case.spec.for_each_segment(2 * len, |_, _, _| {});
        assert!(
            matches!(
                result,
                Err(Error::TooLarge {
                    key: stepper_profiles::Key::SEGMENTS,
                    ..
                })
            ),
            "{}: expected {} segments for {len} steps to be refused, got {result:?}",
            case.name,
            2 * len
        );
    }
    assert!(tables >= 60, "only {tables} segment tables checked");
    eprintln!("{tables} segment tables checked");
}
