//! `reload_offset`: every front end stores each period plus the offset
//! (per-step entries, segment periods, and every period compressed runs
//! play), while the figures, the motor check and golden files stay those of
//! the periods. Each is checked against the same table without the offset,
//! computed on its own.

use std::path::Path;

use profile_codegen::__private::golden::Body;
use profile_codegen::Generated;
use profile_codegen::golden::Golden;
use profile_codegen::profiles::Profiles;
use profile_core::player::{Player, Ramp};
use profile_core::{Curve, Sigmoid, Spec, Timer, runs};
use stepper_profiles::period_table;

mod arr {
    stepper_profiles::include_profiles!("tests/profiles/reload_offset.toml");
}

static PLAIN: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64kHz,
    flexible = 8,
    timer_hz = 10MHz,
);
static ARR: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64kHz,
    flexible = 8,
    timer_hz = 10MHz,
    reload_offset = -1,
);
static PLUS: [u32; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64kHz,
    flexible = 8,
    timer_hz = 10MHz,
    word = u32,
    reload_offset = 1000,
);
static SEGMENTS: [(u16, u16); 8] = period_table!(
    curve = exponential,
    len = 120,
    fmin = 500,
    fmax = 15_000,
    f_inf = 20_000,
    timer_hz = 10MHz,
    segments = 8,
);
static ARR_SEGMENTS: [(u16, u16); 8] = period_table!(
    curve = exponential,
    len = 120,
    fmin = 500,
    fmax = 15_000,
    f_inf = 20_000,
    timer_hz = 10MHz,
    segments = 8,
    reload_offset = -1,
);
static RUNS: &[[u16; 5]] = &period_table!(
    curve = linear,
    fmin = 1.6kHz,
    fmax = 48kHz,
    accel = 160_000,
    timer_hz = 10MHz,
    compress = 1,
);
static ARR_RUNS: &[[u16; 5]] = &period_table!(
    curve = linear,
    fmin = 1.6kHz,
    fmax = 48kHz,
    accel = 160_000,
    timer_hz = 10MHz,
    compress = 1,
    reload_offset = -1,
);

#[test]
fn the_macro_stores_each_period_plus_the_offset() {
    assert!(PLAIN.iter().zip(&ARR).all(|(&p, &a)| a == p - 1));
    assert!(
        PLAIN
            .iter()
            .zip(&PLUS)
            .all(|(&p, &a)| a == u32::from(p) + 1000)
    );
    for (&(p, c), &(a, d)) in SEGMENTS.iter().zip(&ARR_SEGMENTS) {
        assert_eq!((a, d), (p - 1, c));
    }
    // Runs: the same fit, every interval one tick less, so that every
    // period played is one less and the edges' remainders are the same.
    assert_eq!(RUNS.len(), ARR_RUNS.len());
    for (plain, arr) in RUNS.iter().zip(ARR_RUNS) {
        assert_eq!(runs::with_offset(plain, -1), *arr);
        assert_eq!((arr[0], arr[3], arr[4]), (plain[0], plain[3], plain[4]));
    }
    let played: Vec<u32> = runs::Expand::new(RUNS).collect();
    let stored: Vec<u32> = runs::Expand::new(ARR_RUNS).collect();
    assert_eq!(played.len(), 7192);
    assert!(played.iter().zip(&stored).all(|(&p, &s)| s == p - 1));
}

#[test]
fn run_time_generation_stores_the_same() {
    let spec = Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        }),
        Timer::new(10_000_000),
    );
    let mut table = [0u16; 1000];
    let plain = spec.generate(&mut table).unwrap();
    assert_eq!(table, PLAIN);
    let offset = spec.with_reload_offset(-1).generate(&mut table).unwrap();
    assert_eq!(table, ARR);
    // The figures are the periods'.
    assert_eq!(plain, offset);
    assert_eq!(
        offset.total_ticks,
        PLAIN.iter().map(|&p| u64::from(p)).sum::<u64>()
    );
}

#[test]
fn modules_store_the_offset_and_keep_the_periods_figures() {
    assert_eq!(arr::arr::RELOAD_OFFSET, -1);
    assert_eq!(arr::arr::PERIODS, ARR);
    assert_eq!(
        arr::arr::TOTAL_TICKS,
        PLAIN.iter().map(|&p| u64::from(p)).sum::<u64>()
    );
    assert_eq!(u32::from(arr::arr::PERIODS[0]), arr::arr::FIRST_TICKS - 1);
    assert_eq!(arr::arr_segments::SEGMENTS, ARR_SEGMENTS);
    let total: u64 = SEGMENTS
        .iter()
        .map(|&(p, c)| u64::from(p) * u64::from(c))
        .sum();
    assert_eq!(arr::arr_segments::TOTAL_TICKS, total);
    assert_eq!(&arr::arr_runs::RUNS[..], ARR_RUNS);
    let total: u64 = runs::Expand::new(RUNS).map(u64::from).sum();
    assert_eq!(arr::arr_runs::TOTAL_TICKS, total);
}

/// The shipped profiles with `reload_offset = -1` in `[defaults]`: every
/// table stores its periods less one, its figures, its motor check and its
/// golden file's entries are those of the shipped table.
#[test]
fn every_shipped_profile_with_an_offset() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("profiles.toml");
    let source = std::fs::read_to_string(&path).unwrap();
    let shifted = source.replacen("[defaults]\n", "[defaults]\nreload_offset = -1\n", 1);
    let plain = Profiles::parse("profiles.toml", &source).unwrap_or_else(|e| panic!("{e}"));
    let offset = Profiles::parse("profiles.toml", &shifted).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(plain.profiles().len(), offset.profiles().len());
    let mut motors = 0;
    for (p, q) in plain.profiles().iter().zip(offset.profiles()) {
        let name = &p.name;
        assert_eq!(q.table.spec().reload_offset, -1, "{name}");
        assert_eq!(p.table.step_periods(), q.table.step_periods(), "{name}");
        assert_eq!(p.torque, q.torque, "{name}: the motor check");
        motors += usize::from(p.torque.is_some());
        match (&p.table, &q.table) {
            (Generated::Steps(a), Generated::Steps(b)) => {
                assert_eq!(a.figures, b.figures, "{name}");
                let less: Vec<u32> = a.periods.iter().map(|p| p - 1).collect();
                assert_eq!(b.stored_periods(), less, "{name}");
            }
            (Generated::Segments(a), Generated::Segments(b)) => {
                assert_eq!(a.figures, b.figures, "{name}");
                let less: Vec<(u32, u32)> = a.pairs.iter().map(|&(p, c)| (p - 1, c)).collect();
                assert_eq!(b.stored_pairs(), less, "{name}");
            }
            (Generated::Runs(a), Generated::Runs(b)) => {
                assert_eq!(a.figures, b.figures, "{name}");
                let stored: Vec<u32> = runs::Expand::new(&b.stored_runs()).collect();
                let less: Vec<u32> = p.table.step_periods().iter().map(|p| p - 1).collect();
                assert_eq!(stored, less, "{name}");
            }
            _ => panic!("{name}: another layout"),
        }
        // A golden file pins the periods; its header says the offset.
        let (a, b) = (p.table.entries(), q.table.entries());
        assert_eq!(a.body, b.body, "{name}");
        assert!(matches!(
            b.body,
            Body::Periods(_) | Body::Segments(_) | Body::Runs(_)
        ));
        let with: Vec<_> = b
            .header
            .iter()
            .filter(|(k, _)| k != "reload_offset")
            .cloned()
            .collect();
        assert_eq!(a.header, with, "{name}");
        assert!(
            b.header
                .contains(&("reload_offset".to_string(), "-1".to_string()))
        );
        // The Rust printed for a build script says it.
        assert!(
            offset
                .rust_source()
                .contains("pub const RELOAD_OFFSET: i32 = -1;")
        );
    }
    assert!(motors >= 2, "the shipped profiles that check a motor");
}

/// The player plays a table that holds register values as it plays the
/// periods, each value the period plus the offset: a stop, a cruise change
/// and a short move included.
#[test]
fn the_player_hands_out_register_values() {
    let moves: [(u32, Option<u32>, Option<u32>); 4] = [
        (5000, None, None),
        (700, None, None),
        (5000, Some(1300), None),
        (5000, None, Some(1500)),
    ];
    for (steps, stop_at, cruise_at) in moves {
        for (plain, arr) in [
            (Ramp::steps(&PLAIN), Ramp::steps(&ARR)),
            (Ramp::runs(RUNS), Ramp::runs(ARR_RUNS)),
            (Ramp::segments(&SEGMENTS), Ramp::segments(&ARR_SEGMENTS)),
        ] {
            let (mut a, mut b) = (Player::new(plain), Player::new(arr));
            a.start(steps);
            b.start(steps);
            let mut k = 0;
            loop {
                if Some(k) == stop_at {
                    a.stop();
                    b.stop();
                }
                if Some(k) == cruise_at {
                    a.set_cruise(400);
                    b.set_cruise(400);
                }
                match (a.next_period(), b.next_period()) {
                    (Some(p), Some(r)) => assert_eq!(r + 1, p, "step {k}"),
                    (None, None) => break,
                    other => panic!("step {k}: {other:?}"),
                }
                k += 1;
            }
        }
    }
}
