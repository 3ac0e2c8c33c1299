//! Generation throughput per curve, in entries per second.
//!
//! ```text
//! cargo bench --bench generate
//! ```
//!
//! Each curve at 1000 entries and at the maximum length (65 536), in the
//! default mode (exact pulse times, diffused rounding), plus the sigmoid's
//! C-compatible mode over the index; each with its figures
//! (`Spec::generate`, `PERIODS = false`) and without (`generate_periods`,
//! `PERIODS = true`).

use divan::Bencher;
use divan::counter::ItemsCount;
use stepper_profiles::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, Rounding, Sigmoid, Spec, ThreeStage, Timer, Word,
};

fn main() {
    divan::main();
}

const LENS: [u32; 2] = [1000, 65_536];

/// A 32-bit timer at 100 MHz, so that every curve fits at either length.
fn timer() -> Timer {
    Timer {
        timer_hz: 100_000_000,
        word: Word::U32,
        ticks_per_step: 1,
    }
}

/// `Spec::generate` (`PERIODS` false: the table and its figures) or
/// `Spec::generate_periods` (true: the periods alone).
fn run<const PERIODS: bool>(bencher: Bencher, spec: Spec) {
    let len = spec.len();
    let mut buf = vec![0u32; len as usize];
    let bencher = bencher.counter(ItemsCount::new(len));
    if PERIODS {
        bencher.bench_local(|| spec.generate_periods(divan::black_box(&mut buf)).unwrap());
    } else {
        bencher.bench_local(|| {
            spec.generate(divan::black_box(&mut buf))
                .map(|_| ())
                .unwrap()
        });
    }
}

#[divan::bench(args = LENS, consts = [false, true])]
fn sigmoid_exact<const PERIODS: bool>(bencher: Bencher, len: u32) {
    let c = Curve::Sigmoid(Sigmoid {
        fmin: 500.0,
        fmax: 64_000.0,
        flexible: 8.0,
        len,
    });
    run::<PERIODS>(bencher, Spec::new(c, timer()));
}

#[divan::bench(args = LENS, consts = [false, true])]
fn sigmoid_index_f32<const PERIODS: bool>(bencher: Bencher, len: u32) {
    let c = Curve::Sigmoid(Sigmoid {
        fmin: 500.0,
        fmax: 64_000.0,
        flexible: 8.0,
        len,
    });
    let spec = Spec::new(c, timer())
        .with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::F32);
    run::<PERIODS>(bencher, spec);
}

#[divan::bench(args = LENS, consts = [false, true])]
fn exponential<const PERIODS: bool>(bencher: Bencher, len: u32) {
    let c = Curve::Exponential(Exponential {
        fmin: 500.0,
        fmax: 10_000.0,
        f_inf: 15_000.0,
        extent: ExponentialExtent::Len(len),
    });
    run::<PERIODS>(bencher, Spec::new(c, timer()));
}

#[divan::bench(args = LENS, consts = [false, true])]
fn linear<const PERIODS: bool>(bencher: Bencher, len: u32) {
    let c = Curve::Linear(Linear {
        fmin: 500.0,
        fmax: 50_000.0,
        extent: LinearExtent::Len(len),
    });
    run::<PERIODS>(bencher, Spec::new(c, timer()));
}

#[divan::bench(args = LENS, consts = [false, true])]
fn three_stage<const PERIODS: bool>(bencher: Bencher, len: u32) {
    // Scale the acceleration so the ramp takes about `len` steps.
    let accel = 4000.0 * 261.0 / len as f64;
    let c = Curve::ThreeStage(ThreeStage {
        fmin: 100.0,
        fmax: 1200.0,
        accel,
        f1: 400.0,
        f2: 900.0,
        shape: 12.0 * 261.0 / len as f64,
    });
    run::<PERIODS>(bencher, Spec::new(c, timer()));
}

#[divan::bench(args = LENS, consts = [false, true])]
fn jerk_limited<const PERIODS: bool>(bencher: Bencher, len: u32) {
    let scale = 754.0 / len as f64;
    let c = Curve::JerkLimited(JerkLimited {
        fmin: 200.0,
        fmax: 5000.0,
        accel: 20_000.0 * scale,
        jerk: 400_000.0 * scale * scale,
    });
    run::<PERIODS>(bencher, Spec::new(c, timer()));
}
