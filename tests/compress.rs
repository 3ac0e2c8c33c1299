//! Compressed tables through the front doors: `period_table!` with
//! `compress`, a profiles file, and a golden file of the runs. The runs
//! are the fitter's (`Spec::run_table`), and every edge they play is within
//! `compress` ticks of an independent computation of the curve
//! (`tests/oracle.rs` checks random profiles the same way).

use test_support as common;

use common::oracle;
use profile_codegen::SpecTables;
use profile_codegen::profiles::Profiles;
use stepper_profiles::{Curve, Generated, Linear, LinearExtent, Spec, Timer, Word};
use stepper_profiles::{golden, period_table, runs};

/// 1/16 microsteps, 100 to 3000 full steps/s at 10 000 full steps/s²:
/// 7 192 steps, 14 384 bytes per step.
static MICROSTEP: &[[u16; 5]] = &period_table!(
    curve = linear,
    fmin = 1.6kHz,
    fmax = 48kHz,
    accel = 160_000,
    timer_hz = 10MHz,
    compress = 1,
);

fn microstep_spec() -> Spec {
    Spec::new(
        Curve::Linear(Linear {
            fmin: 1_600.0,
            fmax: 48_000.0,
            extent: LinearExtent::Accel(160_000.0),
        }),
        Timer {
            timer_hz: 10_000_000,
            word: Word::U16,
            ticks_per_step: 1,
        },
    )
}

#[test]
fn the_macro_emits_the_fitters_runs() {
    let table = microstep_spec().run_table(1.0).unwrap();
    assert_eq!(MICROSTEP, &table.runs[..]);
    assert!(table.figures.per_step_flash_bytes >= 10 * table.figures.flash_bytes);
}

#[test]
fn every_played_edge_is_within_a_tick_of_the_curve() {
    let model = oracle::linear(1_600.0, 48_000.0, oracle::Extent::Given(160_000.0));
    let played: Vec<u32> = runs::Expand::new(MICROSTEP).collect();
    let exact = model.edges(played.len());
    let mut edge = 0u64;
    for (k, (p, t)) in played.iter().zip(&exact).enumerate() {
        edge += u64::from(*p);
        let error = edge as f64 - t * 1e7;
        assert!(error.abs() <= 1.0 + 1e-6, "edge {}: {error} ticks", k + 1);
    }
    assert_eq!(played.len(), 7192);
}

#[test]
fn a_profiles_file_gives_the_same_runs() {
    let profiles = Profiles::parse(
        "profiles.toml",
        "[profiles.microstep]\ncurve = \"linear\"\nfmin = \"1.6 kHz\"\nfmax = \"48 kHz\"\n\
         accel = 160_000\ntimer_hz = \"10 MHz\"\ncompress = 1\n",
    )
    .unwrap_or_else(|e| panic!("{e}"));
    let Generated::Runs(t) = &profiles.profiles()[0].table else {
        panic!("a compressed table");
    };
    assert_eq!(&t.runs[..], MICROSTEP);
    let source = profiles.rust_source();
    assert!(source.contains("pub static RUNS: [[u16; 5]; "), "{source}");
    assert!(source.contains("pub const RUN_COUNT: usize = "), "{source}");
}

#[test]
fn the_runs_are_pinned() {
    golden::check(
        "tests/golden/curves/microstep_compressed.txt",
        &golden::timed(MICROSTEP, 10_000_000),
    );
}

/// The player plays the runs as their expansion: up, cruise, down, and a
/// stop mid-ramp.
#[test]
fn the_player_plays_runs_as_their_expansion() {
    use stepper_profiles::player::{Player, Ramp};
    let expanded: Vec<u16> = runs::Expand::new(MICROSTEP).map(|p| p as u16).collect();
    let len = expanded.len() as u32;
    for (steps, stop_at) in [(2 * len + 500, None), (len, None), (3 * len, Some(5000))] {
        let mut compressed = Player::new(Ramp::runs(MICROSTEP));
        let mut per_step = Player::new(Ramp::steps(&expanded));
        compressed.start(steps);
        per_step.start(steps);
        let mut k = 0;
        loop {
            if Some(k) == stop_at {
                compressed.stop();
                per_step.stop();
            }
            let (a, b) = (compressed.next_period(), per_step.next_period());
            assert_eq!(a, b, "step {k} of a move of {steps}");
            if a.is_none() {
                break;
            }
            k += 1;
        }
    }
}
