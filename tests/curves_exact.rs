//! The non-sigmoid curves against independent models of themselves.
//!
//! For the exponential (by `len` and by `tau`), linear (by `len` and by
//! `accel`), three-stage (convex and concave start) and jerk-limited
//! (trapezoidal and triangular acceleration) curves, the default mode
//! (`exact`, `diffuse`) promises every pulse edge within half a tick of the
//! exact pulse time `t(k)`, the solution of `N(t) = ∫0^t f = k`, scaled to ticks
//! by `timer_hz / ticks_per_step`.
//!
//! The exact times come from `common::oracle`, which owes nothing to
//! `profile-core`: each `f(t)` is written out from the articles (the
//! jerk-limited ramp from its acceleration, which rises at `jerk`, holds and
//! falls symmetrically) with `std`'s `exp` and `ln` rather than `libm`,
//! parameters that production solves for (`tau` from a step budget, `accel`
//! from `len`) are solved from the numeric integral, and each `t(k)` is
//! found on that numeric `N`. After the ramp every curve holds `fmax`, so a
//! table whose length follows from the parameters has `ceil(N(T_ramp))`
//! entries, the final fraction at `fmax`.
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

use test_support as common;

use common::oracle::{self, Model};
use common::seeds::{SEED001_SEGMENTS, jerk_limited, seed001, seed004, zeng};
use profile_codegen::SpecTables;
use stepper_profiles::{
    CompactFigures, Curve, Discretization, Error, Exponential, ExponentialExtent, JerkLimited,
    Linear, LinearExtent, Rounding, Spec, ThreeStage, Timer, Word,
};

/// What a correct edge (or rounded entry) may miss its exact value by: half a
/// tick, plus room for floating-point error far below a tick.
const TOLERANCE_TICKS: f64 = 0.5 + 1e-6;

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
fn expected_len(case: &Case, model: &Model) -> u32 {
    let steps = model.ramp_steps();
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
    let model = oracle::model(&case.spec.curve);
    let len = expected_len(case, &model);
    let periods = table(case.name, &case.spec);
    assert_eq!(
        periods.len(),
        len as usize,
        "{}: expected {len} entries (the model's ramp takes {} steps), got {}",
        case.name,
        model.ramp_steps(),
        periods.len()
    );
    assert_eq!(case.spec.len(), len, "{}: Spec::len()", case.name);
    let scale = scale(&case.spec);
    let mut edge = 0u64;
    let mut worst = (0.0f64, 0usize);
    let times = model.times(periods.len());
    for (k, &p) in periods.iter().enumerate() {
        edge += u64::from(p);
        let exact = times[k + 1] * scale;
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
        let model = oracle::model(&spec.curve);
        let periods = table(case.name, &spec);
        assert_eq!(
            periods.len(),
            expected_len(case, &model) as usize,
            "{}: left_endpoint length",
            case.name
        );
        let scale = scale(&spec);
        let times = model.times(periods.len());
        for (k, &p) in periods.iter().enumerate() {
            let exact = scale / model.freq(times[k]);
            assert!(
                (p as f64 - exact).abs() <= TOLERANCE_TICKS,
                "{}: expected left_endpoint entry {k} to be {exact:.6} ticks rounded, got {p}",
                case.name
            );
        }
    }
}

/// The slope of `f` just left and just right of `t`, by one-sided differences.
fn one_sided_slopes(f: impl Fn(f64) -> f64, t: f64) -> (f64, f64) {
    let h = 1e-7 * t.max(1e-3);
    ((f(t) - f(t - h)) / h, (f(t + h) - f(t)) / h)
}

#[test]
fn three_stage_joints_are_smooth_in_the_model_and_in_the_tables() {
    for shape in [12.0, -5.0, 2.0, -13.0] {
        let curve = zeng(shape);
        let model = oracle::model(&Curve::ThreeStage(curve));
        let name = format!("three_stage shape {shape}");
        let &[t1, t2] = model.joints() else {
            panic!("{name}: expected two joints, got {:?}", model.joints());
        };
        let (tc, a) = (model.t_ramp, curve.accel);
        let f = |t: f64| model.freq(t);
        // Value continuity at the joints, and the frequencies they name.
        for (t, named) in [(t1, curve.f1), (t2, curve.f2), (tc, curve.fmax)] {
            let h = 1e-9 * t;
            for (side, value) in [("left", f(t - h)), ("right", f(t))] {
                assert!(
                    (value - named).abs() < 1e-9 * curve.fmax + a * h,
                    "{name}: expected f = {named} at t = {t} from the {side}, got {value}"
                );
            }
        }
        // Slope continuity: both sides equal `a` at t1 and t2, and 0 at tc.
        let (l1, r1) = one_sided_slopes(f, t1);
        let (l2, r2) = one_sided_slopes(f, t2);
        let (l3, _) = one_sided_slopes(f, tc);
        for (what, slope, expected) in [
            ("left of t1", l1, a),
            ("right of t1", r1, a),
            ("left of t2", l2, a),
            ("right of t2", r2, a),
            ("at tc", l3, 0.0),
        ] {
            assert!(
                (slope - expected).abs() < 1e-4 * a,
                "{name}: expected df/dt {what} to be {expected}, got {slope}"
            );
        }
        // Approaching fc, the slope falls linearly to 0 (the paper's a/4b would
        // leave it at a/2 with a jump in f).
        for fraction in [0.5, 0.1, 0.01] {
            let t = tc - fraction * (tc - t2);
            let (left, right) = one_sided_slopes(f, t);
            let slope = (left + right) / 2.0;
            assert!(
                (slope - fraction * a).abs() < 1e-4 * a,
                "{name}: expected df/dt = {} at {fraction} of the parabola before tc, got {slope}",
                fraction * a
            );
        }

        // The tables: their frequencies and accelerations near each joint
        // follow the model.
        let spec = Spec::new(Curve::ThreeStage(zeng(shape)), Timer::new(1_000_000));
        let periods = table(&name, &spec);
        let scale = scale(&spec);
        let edges: Vec<f64> = std::iter::once(0.0)
            .chain(periods.iter().scan(0u64, |s, &p| {
                *s += u64::from(p);
                Some(*s as f64)
            }))
            .collect();
        let exact: Vec<f64> = model
            .times(periods.len())
            .into_iter()
            .map(|t| t * scale)
            .collect();
        let len = periods.len();
        let mut linear_windows = 0;
        for (joint, t) in [("t1", t1), ("t2", t2), ("tc", tc)] {
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
                        from_table.abs() < 0.1 * a,
                        "{name}: expected the acceleration to vanish near fc, got {from_table:.1} \
                         Hz/s over steps {i}..{}",
                        i + 2 * m
                    );
                }
                // Both windows inside the linear stage: the acceleration is `a`.
                let inside = |t: f64| t >= t1 * scale && t <= t2 * scale;
                if inside(exact[i]) && inside(exact[i + 2 * m]) {
                    assert!(
                        (from_table - a).abs() <= allowed + 1e-6 * a,
                        "{name}: expected {} Hz/s in the linear stage (within {allowed:.1}), \
                         got {from_table:.1} over steps {i}..{}",
                        a,
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
    let model = oracle::model(&Curve::Exponential(e));
    let rise = model.t_ramp;
    let tau = rise / ((15_000.0f64 - 500.0) / (15_000.0 - 10_000.0)).ln();
    // The seed's figures, to the digits it gives.
    assert_eq!(format!("{:.3}", tau * 1e3), "18.545", "tau in ms: {tau}");
    assert_eq!(
        format!("{:.3}", rise * 1e3),
        "19.745",
        "rise time in ms: {rise}"
    );
    assert!((model.ramp_steps() - 120.0).abs() < 1e-9);
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
fn check_segments(name: &str, spec: &Spec, pairs: &[(u32, u32)], figures: &CompactFigures) {
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
    assert_eq!(figures.entries, n, "{name}: figures.entries");
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
    let model = oracle::model(&spec.curve);
    let times = model.times(len as usize);
    let duration = times[len as usize];
    let dt = duration / n as f64;
    let scale = scale(spec);
    let (mut before, mut played_end) = (0u32, 0u64);
    for (i, &(period, count)) in pairs.iter().enumerate() {
        let after = if i + 1 == pairs.len() {
            len
        } else {
            model.steps((i + 1) as f64 * dt).round() as u32
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
            let end = times[after as usize] * scale;
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
