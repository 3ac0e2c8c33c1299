//! Parameters at the ends of what a float holds: a table or an error that
//! says what is wrong with which key, never an error about the arithmetic.

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
    assert_eq!(
        three_stage(1e-300).table().unwrap_err().to_string(),
        "`accel` makes the ramp 9.849999999999998e305 steps long; at most 65536 are allowed"
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
