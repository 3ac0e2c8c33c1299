//! Every table against an oracle that shares no code with production.
//!
//! Random valid profiles of every curve, extreme ones included (an
//! exponential's asymptote from 1e-15 to 1e12 times `fmax` above it, a
//! three-stage `shape` within 1e-15 of its bound, a sigmoid's `flexible`
//! from 0.01 to 50, tables up to `MAX_LEN` entries, u16 and u32 words, one
//! or two reloads per step), are generated with `profile-core` and checked
//! against `common::oracle`, which integrates each curve's frequency
//! numerically:
//!
//! - the table's length is the oracle's;
//! - every pulse edge (a prefix sum of the table) is within the printed
//!   `max_edge_error_ticks` of the oracle's exact edge, and that figure is
//!   the largest distance (to `TOLERANCE`): a figure computed from a wrong
//!   formula cannot agree with a table computed from the same formula;
//! - in the default mode, every edge is within half a tick;
//! - segment tables' printed edge error is the played edges' true distance;
//! - compressed tables (`compress = E`, runs played by `runs::Expand`) keep
//!   every edge within `E` ticks of the oracle's, and print that distance;
//! - no valid profile fails with a solver error; the only errors allowed
//!   are periods that do not fit the word or ramps longer than `MAX_LEN`,
//!   and most profiles must give a table.
//!
//! `ORACLE_CASES` sets the profiles per curve (default 40; CI runs 10 000
//! per curve from an optimised build).

use test_support as common;

use common::lcg::Lcg;
use common::oracle::{self, Model};
use profile_codegen::SpecTables;
use stepper_profiles::{
    AccelCurve, Curve, Discretization, Error, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, MAX_LEN, Rounding, Sigmoid, Spec, ThreeStage, Timer, TorqueLimited, Word, runs,
};

/// What the oracle and production may differ by on an edge `e` ticks from
/// the start: a millionth of a tick, plus a few ulps of the edge itself.
fn tolerance(edge_ticks: f64) -> f64 {
    1e-6 + 64.0 * f64::EPSILON * edge_ticks
}

fn cases() -> usize {
    std::env::var("ORACLE_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(40)
}

fn scale(spec: &Spec) -> f64 {
    spec.timer.timer_hz as f64 / spec.timer.ticks_per_step as f64
}

/// A random timer and a frequency range whose periods fit it: `fmin` at
/// least 1% above the lowest frequency the word holds, `fmax` at most half
/// the tick rate, their ratio up to `max_ratio`.
fn timer_and_range(rng: &mut Lcg, max_ratio: f64) -> (Timer, f64, f64) {
    let timer_hz = rng.log_uniform(2e4, 1e8) as u32;
    let word = if rng.next_unit() < 0.25 {
        Word::U32
    } else {
        Word::U16
    };
    let ticks_per_step = if rng.next_unit() < 0.2 { 2 } else { 1 };
    let timer = Timer {
        timer_hz,
        word,
        ticks_per_step,
    };
    let per_second = timer_hz as f64 / ticks_per_step as f64;
    let lowest = 1.01 * per_second / word.max() as f64;
    let highest = per_second / 2.0;
    let fmin = rng.log_uniform(lowest, highest / 1.01);
    let top = (highest / fmin).min(max_ratio);
    let fmax = fmin * rng.log_uniform(1.001, top);
    (timer, fmin, fmax)
}

/// A step count, log-uniform from 1 to `MAX_LEN`, weighted to short tables.
fn steps(rng: &mut Lcg) -> f64 {
    if rng.next_unit() < 0.02 {
        rng.log_uniform(16_384.0, MAX_LEN as f64)
    } else {
        rng.log_uniform(1.0, 4096.0)
    }
}

fn len(rng: &mut Lcg) -> u32 {
    (steps(rng) as u32).clamp(1, MAX_LEN)
}

/// A discretization and rounding: mostly the default, the others often
/// enough to be covered.
fn modes(rng: &mut Lcg, index: bool) -> (Discretization, Rounding) {
    let d = match rng.next_unit() {
        u if u < 0.7 => Discretization::Exact,
        u if u < 0.85 || !index => Discretization::LeftEndpoint,
        _ => Discretization::Index,
    };
    let r = match rng.next_unit() {
        u if u < 0.7 => Rounding::Diffuse,
        u if u < 0.85 => Rounding::Nearest,
        _ => Rounding::Truncate,
    };
    (d, r)
}

fn spec(curve: Curve, timer: Timer, rng: &mut Lcg, index: bool) -> Spec {
    let (d, r) = modes(rng, index);
    Spec::new(curve, timer)
        .with_discretization(d)
        .with_rounding(r)
}

fn random_sigmoid(rng: &mut Lcg) -> Spec {
    let (timer, fmin, fmax) = timer_and_range(rng, 1e4);
    let flexible = if rng.next_unit() < 0.05 {
        rng.log_uniform(50.0, 500.0)
    } else {
        rng.log_uniform(0.01, 50.0)
    };
    let curve = Curve::Sigmoid(Sigmoid {
        fmin,
        fmax,
        flexible,
        len: len(rng),
    });
    spec(curve, timer, rng, true)
}

fn random_exponential(rng: &mut Lcg) -> Spec {
    let (timer, fmin, fmax) = timer_and_range(rng, 1e4);
    // Now and then an asymptote within 1e-15 to 1e-6 of `fmax`.
    let gap = if rng.next_unit() < 0.9 {
        rng.log_uniform(1e-6, 1e12)
    } else {
        rng.log_uniform(1e-15, 1e-6)
    };
    let f_inf = fmax * (1.0 + gap);
    let extent = if rng.next_unit() < 0.5 {
        ExponentialExtent::Len(len(rng))
    } else {
        // A time constant that makes the ramp about `steps` long.
        let rise = ((f_inf - fmin) / (f_inf - fmax)).ln();
        ExponentialExtent::Tau(steps(rng) / ((fmin + fmax) / 2.0) / rise)
    };
    let curve = Curve::Exponential(Exponential {
        fmin,
        fmax,
        f_inf,
        extent,
    });
    spec(curve, timer, rng, false)
}

fn random_linear(rng: &mut Lcg) -> Spec {
    let (timer, fmin, fmax) = timer_and_range(rng, 1e4);
    let extent = if rng.next_unit() < 0.5 {
        LinearExtent::Len(len(rng).max(2))
    } else {
        LinearExtent::Accel((fmax - fmin) * (fmax + fmin) / (2.0 * steps(rng)))
    };
    spec(
        Curve::Linear(Linear { fmin, fmax, extent }),
        timer,
        rng,
        true,
    )
}

fn random_three_stage(rng: &mut Lcg) -> Spec {
    let (timer, fmin, fmax) = timer_and_range(rng, 1e4);
    let f1 = fmin + (fmax - fmin) * rng.log_uniform(1e-3, 0.9);
    let f2 = if rng.next_unit() < 0.1 {
        f1
    } else {
        f1 + (fmax - f1) * rng.log_uniform(1e-3, 0.9)
    };
    let accel = (fmax - fmin) * (fmax + fmin) / steps(rng);
    // |shape| relative to the bound accel / (f1 - fmin) of a concave start.
    let bound = accel / (f1 - fmin);
    let shape = match rng.next_unit() {
        u if u < 0.5 => bound * rng.log_uniform(1e-12, 1e3),
        u if u < 0.9 => -bound * rng.log_uniform(1e-12, 0.999),
        // Within 1e-15 to 1e-3 of the bound, where the start's acceleration
        // is all but cancelled.
        _ => -bound * (1.0 - rng.log_uniform(1e-15, 1e-3)),
    };
    let curve = Curve::ThreeStage(ThreeStage {
        fmin,
        fmax,
        accel,
        f1,
        f2,
        shape,
    });
    spec(curve, timer, rng, false)
}

fn random_jerk_limited(rng: &mut Lcg) -> Spec {
    let (timer, fmin, fmax) = timer_and_range(rng, 1e4);
    let accel = (fmax - fmin) * (fmax + fmin) / (2.0 * steps(rng));
    let jerk = accel * accel / (fmax - fmin) * rng.log_uniform(0.05, 100.0);
    let curve = Curve::JerkLimited(JerkLimited {
        fmin,
        fmax,
        accel,
        jerk,
    });
    spec(curve, timer, rng, false)
}

/// A torque-limited ramp: an acceleration curve of 2 to 8 points over
/// `fmin` to `fmax` (and sometimes beyond), falling or rising between
/// them, scaled so that the ramp takes about a random step count.
fn random_torque_limited(rng: &mut Lcg) -> Spec {
    let (timer, fmin, fmax) = timer_and_range(rng, 1e3);
    let n = 2 + (rng.next_unit() * 7.0) as usize;
    let (lo, hi) = (
        fmin * (1.0 - 0.5 * rng.next_unit()),
        fmax * (1.0 + rng.next_unit()),
    );
    let mut freqs: Vec<f64> = (0..n.saturating_sub(2))
        .map(|_| lo + (hi - lo) * rng.next_unit())
        .collect();
    freqs.push(lo);
    freqs.push(hi);
    freqs.sort_by(f64::total_cmp);
    freqs.dedup();
    // About `steps` steps at the mean acceleration.
    let mean = (fmax - fmin) * (fmax + fmin) / (2.0 * steps(rng));
    let points: Vec<(f64, f64)> = freqs
        .iter()
        .map(|&f| (f, mean * rng.log_uniform(0.05, 3.0)))
        .collect();
    let curve = Curve::TorqueLimited(TorqueLimited {
        fmin,
        fmax,
        margin: 0.5,
        accel: AccelCurve::new(&points).expect("at most 8 points"),
    });
    spec(curve, timer, rng, false)
}

/// The oracle's length of a table, when not decided by rounding.
fn oracle_len(spec: &Spec, model: &Model) -> Option<u64> {
    match spec.curve {
        Curve::Sigmoid(s) => Some(s.len as u64),
        Curve::Exponential(Exponential {
            extent: ExponentialExtent::Len(n),
            ..
        }) => Some(n as u64),
        Curve::Linear(Linear {
            extent: LinearExtent::Len(n),
            ..
        }) => Some(n as u64),
        Curve::Linear(Linear {
            fmin,
            fmax,
            extent: LinearExtent::Accel(a),
        }) if spec.discretization == Discretization::Index => {
            // Entries i = 0, 1, ... while sqrt(fmin² + 2 a i) < fmax, then one at fmax.
            let below = ((fmax * fmax - fmin * fmin) / (2.0 * a)).max(0.0);
            oracle::entries(below).map(|n| n + 1)
        }
        _ => oracle::entries(model.ramp_steps()),
    }
}

/// The unrounded entries over the step index, in ticks.
fn index_entries(spec: &Spec, len: usize) -> Vec<f64> {
    let scale = scale(spec);
    match spec.curve {
        Curve::Sigmoid(s) => {
            let half = s.len as f64 / 2.0;
            (0..len)
                .map(|i| {
                    let x = s.flexible * (i as f64 - half) / half;
                    scale / (s.fmin + (s.fmax - s.fmin) / (1.0 + (-x).exp()))
                })
                .collect()
        }
        Curve::Linear(l) => {
            let a = match l.extent {
                LinearExtent::Accel(a) => a,
                LinearExtent::Len(n) => {
                    (l.fmax * l.fmax - l.fmin * l.fmin) / (2.0 * (n - 1) as f64)
                }
            };
            (0..len)
                .map(|i| scale / (l.fmin * l.fmin + 2.0 * a * i as f64).sqrt().min(l.fmax))
                .collect()
        }
        _ => unreachable!("index applies to the sigmoid and the linear ramp"),
    }
}

/// The exact step edges a table of `spec` is measured against, in timer
/// ticks: with `ticks_per_step = 2` the timer plays each entry twice, and a
/// step edge is twice the entries' running sum.
fn reference_edges(spec: &Spec, model: &Model, len: usize) -> Vec<f64> {
    let repeat = f64::from(spec.timer.ticks_per_step);
    entry_edges(spec, model, len)
        .into_iter()
        .map(|t| t * repeat)
        .collect()
}

/// The exact running sums of the entries, in ticks of the entries.
fn entry_edges(spec: &Spec, model: &Model, len: usize) -> Vec<f64> {
    let scale = scale(spec);
    match spec.discretization {
        Discretization::Exact => model.edges(len).into_iter().map(|t| t * scale).collect(),
        Discretization::LeftEndpoint => {
            let starts = std::iter::once(0.0).chain(model.edges(len - 1));
            starts
                .scan(0.0, |edge, t| {
                    *edge += scale / model.freq(t);
                    Some(*edge)
                })
                .collect()
        }
        Discretization::Index => index_entries(spec, len)
            .into_iter()
            .scan(0.0, |edge, e| {
                *edge += e;
                Some(*edge)
            })
            .collect(),
    }
}

/// Step-edge errors of a played table against the reference, in timer
/// ticks (each period played `repeat` times): the largest distance, the last
/// edge's error, and the largest amount by which any edge exceeds `bound`
/// (beyond its tolerance), with that edge.
struct EdgeErrors {
    worst: f64,
    /// The largest distance among edges within 2^32 ticks of the start,
    /// where an `f64` resolves a millionth of a tick.
    worst_near: f64,
    last: f64,
    tolerance: f64,
    over: Option<(usize, f64, f64)>,
}

fn edge_errors(
    periods: impl IntoIterator<Item = u32>,
    repeat: u8,
    reference: &[f64],
    bound: f64,
) -> EdgeErrors {
    let mut e = EdgeErrors {
        worst: 0.0,
        worst_near: 0.0,
        last: 0.0,
        tolerance: 0.0,
        over: None,
    };
    let mut played = 0u64;
    for (k, (p, exact)) in periods.into_iter().zip(reference).enumerate() {
        played += u64::from(p) * u64::from(repeat);
        let error = played as f64 - exact;
        // Both edges are f64s: a few ulps of the larger of the two.
        let tol = tolerance(exact.max(played as f64));
        if error.abs() > e.worst {
            e.worst = error.abs();
            e.tolerance = tol;
        }
        if *exact < 4_294_967_296.0 {
            e.worst_near = e.worst_near.max(error.abs());
        }
        if error.abs() > bound + tol && e.over.is_none() {
            e.over = Some((k + 1, played as f64, *exact));
        }
        e.last = error;
    }
    e
}

#[derive(Default, Debug)]
struct Tally {
    tables: usize,
    segment_tables: usize,
    compressed_tables: usize,
    compressed_runs: u64,
    compressed_steps: u64,
    unreachable: usize,
    entries: u64,
    overflow: usize,
    too_long: usize,
    worst_default: f64,
    worst_default_near: f64,
}

fn check(spec: &Spec, rng: &mut Lcg, tally: &mut Tally) {
    let table = match spec.table() {
        Ok(t) => t,
        Err(Error::PeriodOverflow { .. } | Error::PeriodZero { .. }) => {
            tally.overflow += 1;
            return;
        }
        Err(Error::RampTooLong { .. }) => {
            tally.too_long += 1;
            return;
        }
        Err(e) => panic!("{spec:?}: a valid profile must give a table, got the error {e}"),
    };
    let model = oracle::model(&spec.curve);
    let len = table.periods.len();
    if let Some(expected) = oracle_len(spec, &model) {
        assert_eq!(len as u64, expected, "{spec:?}: table length");
    }
    let reference = reference_edges(spec, &model, len);
    let f = &table.figures;
    let default =
        spec.discretization == Discretization::Exact && spec.rounding == Rounding::Diffuse;
    let repeat = spec.timer.ticks_per_step;
    let bound = if default {
        0.5 * f64::from(repeat)
    } else {
        f.max_edge_error_ticks
    };
    let e = edge_errors(table.periods.iter().copied(), repeat, &reference, bound);
    if let Some((k, played, exact)) = e.over {
        panic!(
            "{spec:?}: edge {k} is at {played} ticks, {} from the oracle's {exact}, more than \
             the bound of {bound} (the figures say every edge is within {})",
            played - exact,
            f.max_edge_error_ticks
        );
    }
    assert!(
        (e.worst - f.max_edge_error_ticks).abs() <= e.tolerance,
        "{spec:?}: the table's edges are up to {} ticks from the oracle's, the figures say {}",
        e.worst,
        f.max_edge_error_ticks
    );
    assert!(
        (e.last - f.total_error_ticks).abs() <= tolerance(reference[len - 1]),
        "{spec:?}: the last edge is {} ticks off, the figures say {}",
        e.last,
        f.total_error_ticks
    );
    if default {
        let repeat = f64::from(repeat);
        tally.worst_default = tally.worst_default.max(e.worst / repeat);
        tally.worst_default_near = tally.worst_default_near.max(e.worst_near / repeat);
    }
    tally.tables += 1;
    tally.entries += len as u64;

    // Now and then the same ramp as a segment table: its printed edge error
    // is the played edges' true distance from the curve.
    if spec.discretization == Discretization::Exact && rng.next_unit() < 0.2 {
        let n = 1 + (rng.next_unit() * len.min(64) as f64) as u32;
        if let Ok(segments) = spec.segment_table(n) {
            let played = segments
                .pairs
                .iter()
                .flat_map(|&(p, c)| std::iter::repeat_n(p, c as usize));
            let e = edge_errors(played, repeat, &reference, f64::INFINITY);
            // The worst edge may be another one in each computation, with
            // errors equal to their ulps: a few ulps of the largest edge.
            let largest = reference[len - 1].max(segments.figures.total_ticks as f64);
            assert!(
                (e.worst - segments.figures.max_edge_error_ticks).abs() <= tolerance(largest),
                "{spec:?} in {n} segments: the edges are up to {} ticks from the oracle's, \
                 the figures say {}",
                e.worst,
                segments.figures.max_edge_error_ticks
            );
            tally.segment_tables += 1;
        }
    }

    // Now and then the same ramp compressed into runs, within a random
    // tolerance: every edge the runs play within it.
    if spec.timer.word == Word::U16
        && spec.discretization != Discretization::LeftEndpoint
        && len <= 20_000
        && rng.next_unit() < 0.3
    {
        let compress = (0.5 + 2.5 * rng.next_unit()) * f64::from(spec.timer.ticks_per_step);
        let spec = spec.with_rounding(Rounding::Diffuse);
        check_compressed(&spec, compress, &reference, tally);
    }
}

fn check_compressed(spec: &Spec, compress: f64, reference: &[f64], tally: &mut Tally) {
    let table = match spec.run_table(compress) {
        Ok(t) => t,
        Err(e @ Error::CompressUnreachable { .. }) => {
            println!("{spec:?} with compress = {compress}: {e}");
            tally.unreachable += 1;
            return;
        }
        Err(e) => panic!("{spec:?} with compress = {compress}: {e}"),
    };
    let played: Vec<u32> = runs::Expand::new(&table.runs).collect();
    assert_eq!(played.len(), reference.len(), "{spec:?}: compressed steps");
    let e = edge_errors(played, spec.timer.ticks_per_step, reference, compress);
    if let Some((k, played, exact)) = e.over {
        panic!(
            "{spec:?} with compress = {compress}: edge {k} is at {played} ticks, {} from the \
             oracle's {exact}",
            played - exact
        );
    }
    let largest = reference[reference.len() - 1];
    assert!(
        (e.worst - table.figures.max_edge_error_ticks).abs() <= tolerance(largest),
        "{spec:?} with compress = {compress}: the edges are up to {} ticks from the oracle's, \
         the figures say {}",
        e.worst,
        table.figures.max_edge_error_ticks
    );
    tally.compressed_tables += 1;
    tally.compressed_runs += table.runs.len() as u64;
    tally.compressed_steps += reference.len() as u64;
}

fn run(name: &str, seed: u64, generate: fn(&mut Lcg) -> Spec) {
    run_share(name, seed, generate, cases());
}

/// `n` of a curve's random profiles from `seed` (a share of them, where a
/// curve's profiles are split between tests that run side by side).
fn run_share(name: &str, seed: u64, generate: fn(&mut Lcg) -> Spec, n: usize) {
    let mut rng = Lcg(seed);
    let mut tally = Tally::default();
    for _ in 0..n {
        let spec = generate(&mut rng);
        match spec.validate() {
            Ok(()) => {}
            Err(Error::RampTooLong { .. }) => {
                tally.too_long += 1;
                continue;
            }
            Err(e) => panic!("the generator made an invalid {spec:?}: {e}"),
        }
        check(&spec, &mut rng, &mut tally);
    }
    println!(
        "{name}: {n} profiles, {} tables ({} entries; worst default-mode step edge, over its \
         reloads per step, {:.6} tick within \
         2^32 ticks of the start, {:.6} over all edges, where an f64 edge is coarser), \
         {} segment tables, {} compressed tables ({} runs for {} steps, {} unreachable), \
         {} periods beyond the word, {} ramps beyond MAX_LEN",
        tally.tables,
        tally.entries,
        tally.worst_default_near,
        tally.worst_default,
        tally.segment_tables,
        tally.compressed_tables,
        tally.compressed_runs,
        tally.compressed_steps,
        tally.unreachable,
        tally.overflow,
        tally.too_long
    );
    assert!(
        tally.tables * 10 >= n * 8,
        "{name}: expected most random profiles to give tables, got {tally:?}"
    );
}

#[test]
fn sigmoid_tables_agree_with_the_oracle() {
    run("sigmoid", 0x51_6d01, random_sigmoid);
}

#[test]
fn exponential_tables_agree_with_the_oracle() {
    run("exponential", 0xe4_9001, random_exponential);
}

#[test]
fn linear_tables_agree_with_the_oracle() {
    run("linear", 0x11_7ea7, random_linear);
}

#[test]
fn three_stage_tables_agree_with_the_oracle() {
    run("three_stage", 0x3_57a9e, random_three_stage);
}

#[test]
fn jerk_limited_tables_agree_with_the_oracle() {
    run("jerk_limited", 0x1e_4c, random_jerk_limited);
}

/// The slowest curve to check: its profiles in two halves, each from a
/// seed of its own, so that the two run side by side.
#[test]
fn torque_limited_tables_agree_with_the_oracle() {
    run_share(
        "torque_limited",
        0x70_2c,
        random_torque_limited,
        cases() / 2,
    );
}

#[test]
fn torque_limited_tables_agree_with_the_oracle_second_half() {
    let n = cases();
    run_share("torque_limited", 0x70_2d, random_torque_limited, n - n / 2);
}

/// Profiles at the edges of the domain that once gave wrong tables (an
/// exponential whose asymptote is far above `fmax`: its step count cancelled)
/// or solver errors (flat sigmoids, long or not: their step count cancelled).
#[test]
fn extreme_profiles_agree_with_the_oracle() {
    let exponential = |f_inf, len| {
        Spec::new(
            Curve::Exponential(Exponential {
                fmin: 100.0,
                fmax: 10_000.0,
                f_inf,
                extent: ExponentialExtent::Len(len),
            }),
            Timer::new(1_000_000),
        )
    };
    let sigmoid = |flexible, len| {
        Spec::new(
            Curve::Sigmoid(Sigmoid {
                fmin: 500.0,
                fmax: 64_000.0,
                flexible,
                len,
            }),
            Timer::new(10_000_000),
        )
    };
    let mut specs = vec![exponential(1e16, 120), exponential(1e16, 2000)];
    specs.extend([1e12, 1e17, 1e18, 1e20, 1e100, 1e300].map(|f_inf| exponential(f_inf, 120)));
    specs.extend(
        [
            (0.01, 1000),
            (0.5, 30_000),
            (0.01, 65_536),
            (50.0, 65_536),
            (500.0, 1000),
        ]
        .map(|(flexible, len)| sigmoid(flexible, len)),
    );
    let zeng = |shape| {
        Spec::new(
            Curve::ThreeStage(ThreeStage {
                fmin: 100.0,
                fmax: 1200.0,
                accel: 4000.0,
                f1: 400.0,
                f2: 900.0,
                shape,
            }),
            Timer::new(1_000_000),
        )
    };
    specs.extend([1e-300, -1e-300, 1e-9, -1e-9, 13.3].map(zeng));
    let mut rng = Lcg(1);
    let mut tally = Tally::default();
    for spec in &specs {
        check(spec, &mut rng, &mut tally);
    }
    assert_eq!(tally.tables, specs.len(), "{tally:?}");
    // 100 -> 10 000 Hz in 120 steps with the asymptote at 1e16 Hz: a
    // constant acceleration, so periods fall, but for the one-tick steps of
    // diffused rounding (a wrong step count once made them rise by 4).
    let table = exponential(1e16, 120).table().expect("valid");
    assert!(
        table.periods.windows(2).all(|w| w[1] <= w[0] + 1),
        "{:?}",
        table.periods
    );
}

/// The oracle itself, on a curve whose edges are known in closed form.
#[test]
fn the_oracle_integrates_what_it_should() {
    let m = Model::new(|t| 1.0 + t, vec![], 2.0, 3.0);
    // ∫0^2 (1 + t) = 4, then 3 per second.
    assert!((m.ramp_steps() - 4.0).abs() < 1e-14);
    assert!((m.integral(1.0, 3.0) - 5.5).abs() < 1e-14);
    // t + t²/2 = 1 at t = sqrt(3) - 1.
    let e = m.edges(5);
    assert!((e[0] - (3f64.sqrt() - 1.0)).abs() < 1e-15);
    assert!((e[3] - 2.0).abs() < 1e-15);
    assert!((e[4] - 7.0 / 3.0).abs() < 4e-15, "{}", e[4] - 7.0 / 3.0);
}
