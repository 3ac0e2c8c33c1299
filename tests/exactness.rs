//! Default-mode tables put every pulse edge within half a tick of the curve.
//!
//! With `discretization = exact` and `rounding = diffuse` (the defaults), the
//! prefix sums of a table are the pulse edges as the timer plays them. That
//! mode promises each edge within 0.5 tick of the exact pulse time `t(k)`, the
//! solution of `N(t) = ∫0^t f = k`, scaled to ticks by `timer_hz / ticks_per_step`.
//!
//! The exact times come from `common::oracle`, which shares no code with
//! `profile-core`: the time-domain sigmoid, `f(t) = fmin + (fmax - fmin) / (1
//! + exp(-flexible (t - T/2) / (T/2)))` over `[0, T]`, is written out there
//! with `T` solved from the numeric integral so that `len` steps fit, and each
//! `t(k)` is found on that numeric `N`. The closed-form softplus expression
//! that production uses appears nowhere. The oracle's accuracy is checked, not
//! assumed: the sigmoid is symmetric, so `T` must be `len` over the mean of
//! `fmin` and `fmax`, and the last edge, found step by step, must land on `T`.
//!
//! Also checked: `left_endpoint` entries against `1 / f(t(k))` under `nearest`
//! and `truncate`, and that plain truncation (the seed's C cast) drifts by about
//! -500 ticks over the orange ramp while diffusion does not drift at all.

use test_support as common;

use common::oracle::{self, Model};
use profile_codegen::SpecTables;
use stepper_profiles::{Arithmetic, Curve, Discretization, Rounding, Sigmoid, Spec, Timer, Word};

/// What a correct edge may miss its exact time by: half a tick, plus room
/// for floating-point error far below anything a timer could show.
const EDGE_TOLERANCE_TICKS: f64 = 0.5 + 1e-6;

/// Numerical slack on one exact period, for the `left_endpoint` checks.
const SLACK_TICKS: f64 = 1e-6;

/// How far the oracle's own figures may disagree with each other, in ticks.
/// Well under [`SLACK_TICKS`], so that the slack covers the oracle's error.
const ORACLE_AGREEMENT_TICKS: f64 = 1e-7;

/// One table to check.
#[derive(Clone, Copy, Debug)]
struct Case {
    name: &'static str,
    len: u32,
    fmin: f64,
    fmax: f64,
    flexible: f64,
    timer_hz: u32,
    word: Word,
    ticks_per_step: u8,
}

impl Case {
    const fn seed(name: &'static str, len: u32, fmax: f64, fmin: f64, flexible: f64) -> Self {
        Case {
            name,
            len,
            fmin,
            fmax,
            flexible,
            timer_hz: 10_000_000,
            word: Word::U16,
            ticks_per_step: 1,
        }
    }

    /// The spec in the default mode (exact, diffuse, f64).
    fn spec(&self) -> Spec {
        Spec::new(
            Curve::Sigmoid(Sigmoid {
                fmin: self.fmin,
                fmax: self.fmax,
                flexible: self.flexible,
                len: self.len,
            }),
            Timer {
                timer_hz: self.timer_hz,
                word: self.word,
                ticks_per_step: self.ticks_per_step,
            },
        )
    }

    /// Timer ticks per second of step period.
    fn scale(&self) -> f64 {
        self.timer_hz as f64 / self.ticks_per_step as f64
    }
}

/// The four example calls of seed 000 (argument order len, fmax, fmin, flexible).
const SEEDS: [Case; 4] = [
    Case::seed("yellow", 1000, 56_000.0, 16_000.0, 4.0),
    Case::seed("orange", 1000, 64_000.0, 500.0, 8.0),
    Case::seed("blue", 1000, 64_000.0, 500.0, 15.0),
    Case::seed("gray", 1000, 40_000.0, 500.0, 5.0),
];

/// Other timers, words and shapes.
const OTHERS: [Case; 7] = [
    Case {
        ticks_per_step: 2,
        ..Case::seed("orange, two reloads per step", 1000, 64_000.0, 500.0, 8.0)
    },
    Case {
        word: Word::U32,
        ..Case::seed("long u32 table", 20_000, 20_000.0, 20.0, 6.0)
    },
    Case {
        timer_hz: 72_000_000,
        word: Word::U32,
        ticks_per_step: 2,
        ..Case::seed("72 MHz, u32, two reloads", 5000, 300_000.0, 200.0, 10.0)
    },
    Case::seed("one entry", 1, 2000.0, 1000.0, 4.0),
    Case::seed("two entries", 2, 64_000.0, 500.0, 8.0),
    Case::seed("flat and odd", 3001, 2000.0, 153.0, 0.5),
    Case {
        timer_hz: 1_000_000,
        ..Case::seed("steep at 1 MHz", 4096, 100_000.0, 20.0, 60.0)
    },
];

/// The oracle's model of `case`'s curve.
fn model(case: &Case) -> Model {
    oracle::sigmoid(case.fmin, case.fmax, case.flexible, case.len)
}

/// Exact pulse times `t(0..=len)` of `case`, after checking the oracle that
/// gives them.
fn exact_times(case: &Case) -> Vec<f64> {
    let model = model(case);
    let scale = case.scale();
    let symmetric = case.len as f64 / (case.fmin + (case.fmax - case.fmin) / 2.0);
    let off = ((model.t_ramp - symmetric) * scale).abs();
    assert!(
        off <= ORACLE_AGREEMENT_TICKS,
        "{}: expected the oracle's duration {} s to be len over the mean frequency, \
         {symmetric} s, within {ORACLE_AGREEMENT_TICKS} tick, off by {off} tick",
        case.name,
        model.t_ramp
    );
    let times = model.times(case.len as usize);
    let last = ((times[case.len as usize] - model.t_ramp) * scale).abs();
    assert!(
        last <= ORACLE_AGREEMENT_TICKS,
        "{}: expected the oracle's last edge on its duration within \
         {ORACLE_AGREEMENT_TICKS} tick, off by {last} tick",
        case.name
    );
    times
}

/// Checks that every prefix sum of the default-mode table of `case` is within
/// half a tick of its exact time, and returns the largest miss.
fn check_edges(case: &Case) -> f64 {
    let times = exact_times(case);
    let table = case
        .spec()
        .table()
        .unwrap_or_else(|e| panic!("{}: expected a valid table, got the error {e}", case.name));
    assert_eq!(
        table.periods.len(),
        case.len as usize,
        "{}: expected one entry per step",
        case.name
    );
    let scale = case.scale();
    let max = case.word.max();
    let mut edge = 0u64;
    let mut worst = 0.0f64;
    let mut misses = Vec::new();
    for (k, &period) in table.periods.iter().enumerate() {
        assert!(
            (1..=max).contains(&period),
            "{}: expected entry {k} to fit {} and be at least 1 tick, got {period}",
            case.name,
            case.word.name()
        );
        edge += period as u64;
        let exact = times[k + 1] * scale;
        let error = edge as f64 - exact;
        worst = worst.max(error.abs());
        if error.abs() > EDGE_TOLERANCE_TICKS && misses.len() < 20 {
            misses.push(format!(
                "  edge {} (after entry {k} = {period}): table {edge} ticks, exact {exact:.6}, \
                 off by {error:+.6}",
                k + 1
            ));
        }
    }
    assert!(
        misses.is_empty(),
        "{} {:?}: expected every pulse edge within {EDGE_TOLERANCE_TICKS} tick of its exact \
         time, worst {worst:.6}:\n{}",
        case.name,
        case,
        misses.join("\n")
    );
    // The figure is the step edges' error in timer ticks: with two reloads
    // per step, twice the entries' running sum's.
    let repeat = f64::from(case.spec().timer.ticks_per_step);
    let reported = table.figures.max_edge_error_ticks;
    assert!(
        (reported - worst * repeat).abs() <= 1e-6,
        "{}: expected figures.max_edge_error_ticks to be the measured {:.9}, got {reported:.9}",
        case.name,
        worst * repeat
    );
    let total_exact = case.len as f64 / (case.fmin + (case.fmax - case.fmin) / 2.0) * scale;
    assert!(
        (table.figures.total_ticks as f64 - total_exact).abs() <= EDGE_TOLERANCE_TICKS,
        "{}: expected total_ticks within half a tick of T = {total_exact:.6} ticks, got {}",
        case.name,
        table.figures.total_ticks
    );
    worst
}

#[test]
fn seed_calls_default_mode_edges_within_half_a_tick() {
    for case in &SEEDS {
        let worst = check_edges(case);
        // Integer edges against real-valued exact times: over 1000 edges the
        // worst miss comes close to half a tick. A much smaller one would mean
        // the comparison is no longer against the true, unrounded times.
        assert!(
            worst > 0.4,
            "{}: expected the worst edge near half a tick over 1000 edges, got {worst}",
            case.name
        );
    }
}

#[test]
fn other_timers_and_shapes_edges_within_half_a_tick() {
    for case in &OTHERS {
        check_edges(case);
    }
}

/// Checks the `left_endpoint` table of `case` under `rounding` against
/// `scale / f(t(k))` with `accept(entry, exact)`.
fn check_left_endpoint(case: &Case, rounding: Rounding, accept: fn(f64, f64) -> bool) {
    let model = model(case);
    let times = exact_times(case);
    let spec = case
        .spec()
        .with_discretization(Discretization::LeftEndpoint)
        .with_rounding(rounding);
    let table = spec
        .table()
        .unwrap_or_else(|e| panic!("{}: expected a valid table, got the error {e}", case.name));
    let scale = case.scale();
    let misses: Vec<String> = table
        .periods
        .iter()
        .enumerate()
        .filter_map(|(k, &entry)| {
            let exact = scale / model.freq(times[k]);
            (!accept(entry as f64, exact))
                .then(|| format!("  entry {k}: table {entry}, exact 1/f(t(k)) = {exact:.6} ticks"))
        })
        .take(20)
        .collect();
    assert!(
        misses.is_empty(),
        "{} left_endpoint/{}: expected entries to be 1/f(t(k)) rounded this way:\n{}",
        case.name,
        rounding.name(),
        misses.join("\n")
    );
}

#[test]
fn left_endpoint_entries_are_the_rounded_start_frequency() {
    for case in SEEDS.iter().chain(&OTHERS[..1]) {
        check_left_endpoint(case, Rounding::Nearest, |entry, exact| {
            (entry - exact).abs() <= 0.5 + SLACK_TICKS
        });
        check_left_endpoint(case, Rounding::Truncate, |entry, exact| {
            entry <= exact + SLACK_TICKS && exact - entry < 1.0 + SLACK_TICKS
        });
    }
}

#[test]
fn truncation_drifts_about_500_ticks_on_the_orange_call() {
    let orange = &SEEDS[1];
    let compat = orange
        .spec()
        .with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::F32)
        .table()
        .expect("the orange call in compatibility mode is valid");
    // The unrounded index-domain periods: the article's sigmoid at index `i`,
    // `f = fmin + (fmax - fmin) / (1 + exp(-flexible (i - len/2) / (len/2)))`.
    let half = orange.len as f64 / 2.0;
    let exact: f64 = (0..orange.len)
        .map(|i| {
            let x = orange.flexible * (i as f64 - half) / half;
            let f = orange.fmin + (orange.fmax - orange.fmin) / (1.0 + (-x).exp());
            orange.scale() / f
        })
        .sum();
    let total: u64 = compat.periods.iter().map(|&p| p as u64).sum();
    let drift = total as f64 - exact;
    assert!(
        (-600.0..=-400.0).contains(&drift),
        "expected the truncated orange table to drift between -600 and -400 ticks \
         (about -500), got {drift:.3} ({total} ticks against {exact:.3})"
    );
    let reported = compat.figures.total_error_ticks;
    assert!(
        (reported - drift).abs() <= 1.0,
        "expected figures.total_error_ticks to be the measured drift {drift:.3} within a tick \
         (the f32 curve differs from f64 in the last bits), got {reported:.3}"
    );
    // The default mode on the same curve does not drift.
    let default = orange.spec().table().expect("the orange call is valid");
    assert!(
        default.figures.total_error_ticks.abs() <= 0.5,
        "expected the default mode to end within half a tick of the exact total, got {}",
        default.figures.total_error_ticks
    );
}
