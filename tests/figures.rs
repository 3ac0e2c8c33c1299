//! The acceleration figures mean what they say: the integer table's
//! windowed acceleration is the curve's, not its rounding jitter, and the
//! curve's own peak is the continuous curve's. The continuous peak comes
//! from `common/oracle.rs`, which writes each curve's frequency on its own,
//! differentiated numerically over a fine grid.

mod common;

use common::oracle::{self, Model};
use stepper_profiles::period_table;
use stepper_profiles::{
    ACCEL_WINDOW, Curve, JerkLimited, Linear, LinearExtent, Sigmoid, Spec, Timer, Word,
};

fn timer(timer_hz: u32) -> Timer {
    Timer {
        timer_hz,
        word: Word::U16,
        ticks_per_step: 1,
    }
}

/// The largest `|df/dt|` of the continuous curve over its ramp.
fn continuous_peak(model: &Model) -> f64 {
    let n = 200_000;
    let h = model.t_ramp / n as f64;
    (1..n)
        .map(|i| {
            let t = i as f64 * h;
            ((model.freq(t + h / 4.0) - model.freq(t - h / 4.0)) / (h / 2.0)).abs()
        })
        .fold(0.0, f64::max)
}

fn relative(a: f64, b: f64) -> f64 {
    (a - b).abs() / b
}

/// The shipped `sigmoid_exact`: per entry, one tick of rounding read as
/// 2.96e7 Hz/s; the curve peaks near 8.2e6.
#[test]
fn the_exact_sigmoid_reports_the_curves_acceleration_not_its_jitter() {
    const T: [u16; 1000] = period_table!(
        curve = sigmoid,
        len = 1000,
        fmin = 500,
        fmax = 64000,
        flexible = 8,
        timer_hz = 10_000_000,
    );
    let spec = Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        }),
        timer(10_000_000),
    );
    let table = spec.table().unwrap();
    assert_eq!(
        table.periods.iter().map(|&p| p as u16).collect::<Vec<_>>(),
        T
    );
    let f = table.figures;
    let peak = continuous_peak(&oracle::sigmoid(500.0, 64_000.0, 8.0, 1000));
    assert_eq!(f.accel_window, ACCEL_WINDOW);
    assert!(
        relative(f.max_accel_hz_s, peak) < 0.10,
        "table {:.4e} against the curve's {peak:.4e}",
        f.max_accel_hz_s
    );
    assert!(
        relative(f.curve_max_accel_hz_s, peak) < 0.02,
        "curve {:.4e} against {peak:.4e}",
        f.curve_max_accel_hz_s
    );
    // Entry by entry the same table reads more than three times the peak.
    let tps = 10_000_000.0;
    let per_entry = T
        .windows(2)
        .map(|w| {
            let (a, b) = (f64::from(w[0]), f64::from(w[1]));
            ((tps / b - tps / a) / ((a + b) / 2.0 / tps)).abs()
        })
        .fold(0.0, f64::max);
    assert!(per_entry > 3.0 * peak, "{per_entry:.4e}");
}

/// A jerk-limited ramp's acceleration is its `accel` key, and its jerk its
/// `jerk` key: on the table (windowed) and on the curve.
#[test]
fn a_jerk_limited_ramp_reports_its_own_limits() {
    let spec = Spec::new(
        Curve::JerkLimited(JerkLimited {
            fmin: 200.0,
            fmax: 5_000.0,
            accel: 20_000.0,
            jerk: 400_000.0,
        }),
        timer(10_000_000),
    );
    let f = spec.table().unwrap().figures;
    let peak = continuous_peak(&oracle::jerk_limited(200.0, 5_000.0, 20_000.0, 400_000.0));
    assert!(relative(peak, 20_000.0) < 1e-3, "{peak}");
    assert!(
        relative(f.max_accel_hz_s, 20_000.0) < 0.10,
        "{}",
        f.max_accel_hz_s
    );
    assert!(
        relative(f.curve_max_accel_hz_s, 20_000.0) < 0.01,
        "{}",
        f.curve_max_accel_hz_s
    );
    assert!(
        relative(f.curve_max_jerk_hz_s2, 400_000.0) < 0.05,
        "{}",
        f.curve_max_jerk_hz_s2
    );
}

/// Fewer entries than two windows: the figure is entry by entry and says so.
#[test]
fn a_short_table_measures_entry_by_entry() {
    let spec = Spec::new(
        Curve::Linear(Linear {
            fmin: 500.0,
            fmax: 5_000.0,
            extent: LinearExtent::Len(10),
        }),
        timer(1_000_000),
    );
    let f = spec.table().unwrap().figures;
    assert_eq!(f.accel_window, 1);
    assert!(f.max_accel_hz_s > 0.0);
}
