//! The seeds' own curves and calls: as specs, in the modes that reproduce
//! their C code, and as `period_table!` expands them; and the jerk-limited
//! ramp that is pinned in `golden/curves/` and checked against its exact
//! edges.

use stepper_profiles::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, Rounding, Sigmoid, Spec, ThreeStage, Timer, period_table,
};

/// The timer frequency hard-wired into seed 000's C function.
pub const SEED000_TIMER_HZ: u32 = 10_000_000;

/// Seed 000's call `CalculateSModelLine(..., len, fmax, fmin, flexible)` at 10 MHz.
pub fn seed000(len: u32, fmax: f64, fmin: f64, flexible: f64) -> Spec {
    Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin,
            fmax,
            flexible,
            len,
        }),
        Timer::new(SEED000_TIMER_HZ),
    )
}

/// `spec` in seed 000's compatibility mode: what its `float` C code computes.
pub fn f32_compat(spec: Spec) -> Spec {
    spec.with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::F32)
}

/// Seed 000's orange call in its compatibility mode, checked against the C
/// code (`seed_c.rs`) and pinned in `golden/` (`golden.rs`).
pub static SEED000_ORANGE_COMPAT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64000,
    flexible = 8,
    timer_hz = 10_000_000,
    discretization = index,
    rounding = truncate,
    arithmetic = f32,
);

/// Seed 001's exponential ramp: 500 Hz to 10 000 Hz within 120 steps towards
/// an asymptote of 15 000 Hz.
pub fn seed001() -> Exponential {
    Exponential {
        fmin: 500.0,
        fmax: 10_000.0,
        f_inf: 15_000.0,
        extent: ExponentialExtent::Len(120),
    }
}

/// Seed 001's ramp at 1 MHz as its compact layout of 8 equal-time segments.
pub static SEED001_SEGMENTS: [(u16, u16); 8] = period_table!(
    curve = exponential,
    fmin = 500,
    fmax = 10000,
    f_inf = 15000,
    len = 120,
    timer_hz = 1_000_000,
    segments = 8,
);

/// Zeng, Hu and Hu's three-stage curve (seed 002), 100 Hz to 1200 Hz, with
/// the exponential stage's `shape`.
pub fn zeng(shape: f64) -> ThreeStage {
    ThreeStage {
        fmin: 100.0,
        fmax: 1200.0,
        accel: 4000.0,
        f1: 400.0,
        f2: 900.0,
        shape,
    }
}

/// Constant acceleration from `fmin` to `fmax` in `len` entries on seed
/// 004's timer: 50 MHz, two reloads per step.
pub fn seed004_ramp(fmin: f64, fmax: f64, len: u32) -> Spec {
    Spec::new(
        Curve::Linear(Linear {
            fmin,
            fmax,
            extent: LinearExtent::Len(len),
        }),
        Timer::new(50_000_000),
    )
    .with_ticks_per_step(2)
}

/// Seed 004's ramp, 500 Hz to 5000 Hz, in `len` entries (`len = 201` for its
/// 200 transition steps in its own arithmetic, 200 in the default mode).
pub fn seed004(len: u32) -> Spec {
    seed004_ramp(500.0, 5000.0, len)
}

/// `spec` in seed 004's compatibility mode: what its integer C code computes.
pub fn integer_compat(spec: Spec) -> Spec {
    spec.with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::Integer)
}

/// Seed 004's call in its compatibility mode, checked against the C code
/// (`seed004_c.rs`) and pinned in `golden/curves/` (`golden_curves.rs`).
pub static SEED004_INTEGER: [u16; 201] = period_table!(
    curve = linear,
    fmin = 500,
    fmax = 5000,
    len = 201,
    timer_hz = 50_000_000,
    ticks_per_step = 2,
    discretization = index,
    rounding = truncate,
    arithmetic = integer,
);

/// A jerk-limited ramp, 200 Hz to 5000 Hz, whose acceleration rises at
/// 400 000 Hz/s² to hold 20 000 Hz/s (a trapezoid). No seed has one.
pub fn jerk_limited() -> JerkLimited {
    JerkLimited {
        fmin: 200.0,
        fmax: 5000.0,
        accel: 20_000.0,
        jerk: 400_000.0,
    }
}
