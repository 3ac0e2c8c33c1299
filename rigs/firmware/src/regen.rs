//! Every table of `profiles.toml` generated again, on the target, with
//! `Spec::generate` (soft-float `f64`/`f32` on the Cortex-M3) and compared bit
//! for bit with the table the macro computed on the host.

use cortex_m_semihosting::hprintln;
use stepper_profiles::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, Rounding, Sigmoid, Spec, ThreeStage, Timer,
};

use crate::Report;
use crate::profiles::{
    exponential, exponential_segments, jerk_limited, linear_exact, linear_integer, microstep,
    sigmoid_blue, sigmoid_exact, sigmoid_gray, sigmoid_orange, sigmoid_yellow, three_stage,
};

/// `[defaults]` of profiles.toml.
const TIMER: Timer = Timer::new(10_000_000);

fn sigmoid(fmin: f64, fmax: f64, flexible: f64) -> Spec {
    Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin,
            fmax,
            flexible,
            len: 1000,
        }),
        TIMER,
    )
}

/// The sigmoid article's C function: index, truncate, f32.
fn c_compatible(spec: Spec) -> Spec {
    spec.with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::F32)
}

fn exponential_spec() -> Spec {
    Spec::new(
        Curve::Exponential(Exponential {
            fmin: 500.0,
            fmax: 10_000.0,
            f_inf: 15_000.0,
            extent: ExponentialExtent::Len(120),
        }),
        Timer::new(1_000_000),
    )
}

/// `microstep` and `microstep_runs`: 1600 Hz to 48 kHz at 160 000 Hz/s on
/// the 10 MHz timer of `[defaults]`.
pub fn microstep_spec() -> Spec {
    Spec::new(
        Curve::Linear(Linear {
            fmin: 1600.0,
            fmax: 48_000.0,
            extent: LinearExtent::Accel(160_000.0),
        }),
        TIMER,
    )
}

fn linear(len: u32) -> Spec {
    Spec::new(
        Curve::Linear(Linear {
            fmin: 500.0,
            fmax: 5000.0,
            extent: LinearExtent::Len(len),
        }),
        Timer::new(50_000_000),
    )
    .with_ticks_per_step(2)
}

/// Generates `spec` into a buffer on the stack and compares it with `flash`.
fn same<const N: usize>(report: &mut Report, name: &str, spec: &Spec, flash: &[u16; N]) {
    let mut table = [0u16; N];
    match spec.generate(&mut table) {
        Ok(_) => {
            let differ = table.iter().zip(flash).filter(|(a, b)| a != b).count();
            if let Some(i) = table.iter().zip(flash).position(|(a, b)| a != b) {
                hprintln!(
                    "FAIL {}: entry {}: target {}, host {}",
                    name,
                    i,
                    table[i],
                    flash[i]
                );
            }
            hprintln!(
                "  {:<22} {:>5} entries, {}",
                name,
                N,
                if differ == 0 {
                    "identical"
                } else {
                    "DIFFERENT"
                }
            );
            report.equal(name, differ as u64, 0);
        }
        Err(e) => {
            hprintln!("FAIL {}: {}", name, e);
            report.equal(name, 1, 0);
        }
    }
}

/// Regenerates every profile and compares.
pub fn run(report: &mut Report) {
    hprintln!("run-time Spec::generate vs compile-time tables:");
    same(
        report,
        "sigmoid_yellow",
        &c_compatible(sigmoid(16_000.0, 56_000.0, 4.0)),
        &sigmoid_yellow::PERIODS,
    );
    same(
        report,
        "sigmoid_orange",
        &c_compatible(sigmoid(500.0, 64_000.0, 8.0)),
        &sigmoid_orange::PERIODS,
    );
    same(
        report,
        "sigmoid_blue",
        &c_compatible(sigmoid(500.0, 64_000.0, 15.0)),
        &sigmoid_blue::PERIODS,
    );
    same(
        report,
        "sigmoid_gray",
        &c_compatible(sigmoid(500.0, 40_000.0, 5.0)),
        &sigmoid_gray::PERIODS,
    );
    same(
        report,
        "sigmoid_exact",
        &sigmoid(500.0, 64_000.0, 8.0),
        &sigmoid_exact::PERIODS,
    );
    same(
        report,
        "exponential",
        &exponential_spec(),
        &exponential::PERIODS,
    );
    same(
        report,
        "linear_integer",
        &linear(201)
            .with_discretization(Discretization::Index)
            .with_rounding(Rounding::Truncate)
            .with_arithmetic(Arithmetic::Integer),
        &linear_integer::PERIODS,
    );
    same(report, "linear_exact", &linear(200), &linear_exact::PERIODS);
    same(report, "microstep", &microstep_spec(), &microstep::PERIODS);
    same(
        report,
        "three_stage",
        &Spec::new(
            Curve::ThreeStage(ThreeStage {
                fmin: 100.0,
                fmax: 1200.0,
                accel: 4000.0,
                f1: 400.0,
                f2: 900.0,
                shape: 12.0,
            }),
            Timer::new(1_000_000),
        ),
        &three_stage::PERIODS,
    );
    same(
        report,
        "jerk_limited",
        &Spec::new(
            Curve::JerkLimited(JerkLimited {
                fmin: 200.0,
                fmax: 5000.0,
                accel: 20_000.0,
                jerk: 400_000.0,
            }),
            TIMER,
        ),
        &jerk_limited::PERIODS,
    );

    // The segment layout.
    let mut pairs = [(0u16, 0u16); exponential_segments::SEGMENT_COUNT];
    let name = "exponential_segments";
    match exponential_spec().generate_segments(&mut pairs) {
        Ok(_) => {
            let same = pairs == exponential_segments::SEGMENTS;
            hprintln!(
                "  {:<22} {:>5} segments, {}",
                name,
                pairs.len(),
                if same { "identical" } else { "DIFFERENT" }
            );
            report.equal(name, same.into(), 1);
        }
        Err(e) => {
            hprintln!("FAIL {}: {}", name, e);
            report.equal(name, 0, 1);
        }
    }
}
