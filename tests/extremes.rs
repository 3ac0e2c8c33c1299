//! Parameters at the ends of what a float holds: a table or an error that
//! says what is wrong with which key, never an error about the arithmetic.

use profile_codegen::SpecTables;
use profile_core::{Curve, Error, Key, Linear, LinearExtent, Sigmoid, Spec, ThreeStage, Timer};

fn timer() -> Timer {
    Timer::new(10_000_000)
}

/// An acceleration too large to double still reaches `fmax` at once: one
/// entry, as `accel = 1e200` gives, not "no length (got 0)".
#[test]
fn the_largest_acceleration_gives_one_entry() {
    for accel in [1e200, 1e308, f64::MAX] {
        let spec = Spec::new(
            Curve::Linear(Linear {
                fmin: 500.0,
                fmax: 64_000.0,
                extent: LinearExtent::Accel(accel),
            }),
            timer(),
        );
        let table = spec.table().unwrap_or_else(|e| panic!("{accel}: {e}"));
        assert_eq!(table.periods.len(), 1, "{accel}");
    }
}

fn three_stage(accel: f64) -> Spec {
    Spec::new(
        Curve::ThreeStage(ThreeStage {
            fmin: 100.0,
            fmax: 1200.0,
            accel,
            f1: 400.0,
            f2: 900.0,
            shape: 12.0,
        }),
        Timer::new(1_000_000),
    )
}

/// An acceleration so small the ramp never ends is too long, and a
/// subnormal one is refused at `accel` as such: not "no length (got NaN)".
#[test]
fn the_smallest_acceleration_is_too_long_or_too_small() {
    // (f2² - f1²) / 2a + 2 (fc - f2) (2 fc + f2) / 3a and a first stage
    // of some 15 000 steps: 9.85e305 to the float (the stage-three steps
    // summed without the cancellation of two cubes).
    assert_eq!(
        three_stage(1e-300).table().unwrap_err().to_string(),
        "`accel` makes the ramp 9.85e305 steps long; at most 65536 are allowed"
    );
    assert_eq!(
        three_stage(1e-307).table().unwrap_err().to_string(),
        "`accel` makes the ramp longer than a float counts (1.8e308 steps); at most 65536 are \
         allowed"
    );
    let e = three_stage(1e-310).table().unwrap_err();
    assert_eq!(
        e.to_string(),
        "`accel` must be at least 2.2250738585072014e-308, the smallest normal float (got 1e-310)"
    );
    assert_eq!(e.key(), Some(Key::ACCEL));
}

/// A subnormal `flexible` is refused at `flexible`, not left to a solver
/// that cannot converge on it.
#[test]
fn a_subnormal_flexible_is_refused_at_its_key() {
    let spec = |flexible: f64| {
        Spec::new(
            Curve::Sigmoid(Sigmoid {
                fmin: 476.3177,
                fmax: 10_906.0,
                flexible,
                len: 3,
            }),
            timer(),
        )
    };
    let e = spec(1e-308).table().unwrap_err();
    assert!(
        matches!(
            e,
            Error::NotPositive {
                key: Key::FLEXIBLE,
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(spec(3e-308).table().unwrap().periods.len(), 3);
}

fn near_asymptote(
    f_inf: f64,
    extent: profile_core::ExponentialExtent,
) -> profile_core::Exponential {
    profile_core::Exponential {
        fmin: 500.0,
        fmax: 10_000.0,
        f_inf,
        extent,
    }
}

/// An asymptote a hair above `fmax`: the rise time still takes the ramp to
/// `fmax`, checked through the inverse function (the gap left to the
/// asymptote at the rise, `(f_inf - fmin) e^(-t/tau)`, is `f_inf - fmax`),
/// and a ramp of given `tau` has the steps the frequency's integral counts
/// (Simpson's rule over the rise). `1 - q` once lost the gap: the next
/// float above 10 000 Hz gave an edge 114 ticks off, 5 steps short.
#[test]
fn an_asymptote_just_above_fmax_keeps_its_gap() {
    use profile_core::ExponentialExtent;
    let next_up = f64::from_bits(10_000f64.to_bits() + 1);
    for f_inf in [10_000.001, 10_000.000_000_1, 10_000.000_000_001, next_up] {
        let e = near_asymptote(f_inf, ExponentialExtent::Len(1000));
        let (tau, rise) = (e.tau(), e.rise_time());
        let gap = (f_inf - 500.0) * (-rise / tau).exp();
        assert!(
            (gap / (f_inf - 10_000.0) - 1.0).abs() < 1e-9,
            "{f_inf}: gap {gap} against {}",
            f_inf - 10_000.0
        );
        let e = near_asymptote(f_inf, ExponentialExtent::Tau(0.003));
        let (tau, rise) = (e.tau(), e.rise_time());
        let f = |t: f64| 500.0 - (f_inf - 500.0) * (-t / tau).exp_m1();
        let n = 200_000;
        let h = rise / n as f64;
        let simpson = (0..=n)
            .map(|k| {
                let w = if k == 0 || k == n {
                    1.0
                } else if k % 2 == 1 {
                    4.0
                } else {
                    2.0
                };
                w * f(k as f64 * h)
            })
            .sum::<f64>()
            * h
            / 3.0;
        let spec = Spec::new(Curve::Exponential(e), Timer::new(10_000_000));
        let len = spec.table().unwrap().periods.len();
        assert_eq!(len as f64, simpson.ceil(), "{f_inf}: {simpson} steps");
    }
}

/// A sigmoid flatter than a float tells from a constant, down to the
/// smallest normal `flexible`: the table of the constant frequency
/// `(fmin + fmax) / 2`, every edge within half a tick of `k` periods of it.
/// Below 1e-306 its step count once overflowed ("did not converge").
#[test]
fn the_flattest_sigmoid_is_its_middle_frequency() {
    for flexible in [1e-20, 1e-100, 1e-200, 1e-306, 1e-307, 2.3e-308] {
        let spec = Spec::new(
            Curve::Sigmoid(Sigmoid {
                fmin: 500.0,
                fmax: 64_000.0,
                flexible,
                len: 1000,
            }),
            timer(),
        );
        let table = spec.table().unwrap_or_else(|e| panic!("{flexible}: {e}"));
        assert_eq!(table.periods.len(), 1000);
        let period = 10_000_000.0 / 32_250.0;
        let mut edge = 0u64;
        for (k, &p) in table.periods.iter().enumerate() {
            edge += u64::from(p);
            let exact = (k + 1) as f64 * period;
            assert!(
                (edge as f64 - exact).abs() <= 0.5 + 1e-9,
                "{flexible}: edge {} at {edge}, exactly {exact}",
                k + 1
            );
        }
    }
}
