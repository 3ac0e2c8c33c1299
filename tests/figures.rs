//! The acceleration figures mean what they say: the integer table's
//! windowed acceleration is the curve's, not its rounding jitter, and the
//! curve's own peak is the continuous curve's. The continuous peak comes
//! from `support/src/oracle.rs`, which writes each curve's frequency on its own,
//! differentiated numerically over a fine grid.

use test_support as common;

use common::oracle::{self, Model};
use profile_codegen::SpecTables;
use stepper_profiles::period_table;
use stepper_profiles::profiles::Profiles;
use stepper_profiles::{
    Curve, Discretization, Generated, JerkLimited, Linear, LinearExtent, Rounding, Sigmoid, Spec,
    Timer, Word,
};

fn timer(timer_hz: u32) -> Timer {
    Timer {
        timer_hz,
        word: Word::U16,
        ticks_per_step: 1,
    }
}

/// The largest acceleration of the curve between the mean frequencies of
/// consecutive steps of its first `len` (the oracle's edges), over the time
/// between their centres: what any table of the curve's steps can show.
fn stepwise_peak(model: &Model, len: usize) -> f64 {
    let mut edges = vec![0.0];
    edges.extend(model.edges(len));
    let periods: Vec<f64> = edges.windows(2).map(|w| w[1] - w[0]).collect();
    periods
        .windows(2)
        .map(|p| ((1.0 / p[1] - 1.0 / p[0]) / ((p[0] + p[1]) / 2.0)).abs())
        .fold(0.0, f64::max)
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

/// A short table still reads its acceleration between windows no longer
/// than a quarter of it; a table of one entry reads none.
#[test]
fn a_short_table_reads_between_short_windows() {
    let spec = |len| {
        Spec::new(
            Curve::Linear(Linear {
                fmin: 500.0,
                fmax: 5_000.0,
                extent: LinearExtent::Len(len),
            }),
            timer(1_000_000),
        )
    };
    let f = spec(10).table().unwrap().figures;
    let peak = stepwise_peak(&oracle::linear(500.0, 5_000.0, oracle::Extent::Len(10)), 10);
    assert!(
        relative(f.max_accel_hz_s, peak) < 0.10,
        "{} against {peak}",
        f.max_accel_hz_s
    );
    assert_eq!(spec(1).table().unwrap().figures.max_accel_hz_s, 0.0);
}

/// Where the table follows the curve within half a tick (`exact`,
/// `diffuse`), its acceleration figure follows the curve's peak between
/// steps (the oracle's edges) within 10 %: every such shipped profile, and ramps of 1/256 microsteps on a
/// 10 MHz timer, where one tick is 8 % of a period and entry by entry (or
/// over windows of a few entries) the rounding reads many times the ramp.
#[test]
fn the_table_acceleration_follows_the_curve_for_every_shipped_profile() {
    let text = std::fs::read_to_string("profiles.toml").unwrap();
    let profiles = Profiles::parse("profiles.toml", &text).unwrap();
    let mut checked = 0;
    for p in profiles.profiles() {
        let Generated::Steps(t) = &p.table else {
            continue;
        };
        let s = &t.spec;
        if s.discretization != Discretization::Exact || s.rounding != Rounding::Diffuse {
            continue;
        }
        let peak = stepwise_peak(&oracle::model(&s.curve), t.periods.len());
        let f = &t.figures;
        println!(
            "{}: table {:.4e}, curve {peak:.4e}",
            p.name, f.max_accel_hz_s
        );
        assert!(
            relative(f.max_accel_hz_s, peak) < 0.10,
            "{}: the table reads {:.4e} Hz/s, the curve peaks at {peak:.4e}",
            p.name,
            f.max_accel_hz_s
        );
        checked += 1;
    }
    assert!(checked >= 6, "{checked} profiles");
    // 1/256 microsteps of a 1.8° motor: 50 to 3000 full steps/s at 30 000
    // full steps/s², constant and jerk-limited, on 10 MHz.
    let k = 256.0;
    for curve in [
        Curve::Linear(Linear {
            fmin: 50.0 * k,
            fmax: 3000.0 * k,
            extent: LinearExtent::Accel(30_000.0 * k),
        }),
        Curve::JerkLimited(JerkLimited {
            fmin: 50.0 * k,
            fmax: 3000.0 * k,
            accel: 30_000.0 * k,
            jerk: 600_000.0 * k,
        }),
    ] {
        let t = Spec::new(curve, timer(10_000_000)).table().unwrap();
        let (f, len) = (t.figures, t.periods.len());
        let peak = stepwise_peak(&oracle::model(&curve), len);
        println!(
            "1/256 {}: table {:.4e}, curve {peak:.4e}",
            curve.name(),
            f.max_accel_hz_s
        );
        assert!(
            relative(f.max_accel_hz_s, peak) < 0.10,
            "1/256 {}: the table reads {:.4e} Hz/s, the curve peaks at {peak:.4e}",
            curve.name(),
            f.max_accel_hz_s
        );
    }
}
