//! Golden tables of the seeds' other curves, as `period_table!` expands them.
//!
//! Under `tests/golden/curves/`, one file per table:
//! - seed 001's exponential ramp, 500 Hz to 10 000 Hz within 120 steps towards
//!   an asymptote of 15 000 Hz, at 1 MHz and at 10 MHz, and the same ramp at
//!   1 MHz as seed 001's compact layout of 8 equal-time segments;
//! - seed 004's constant acceleration, 500 Hz to 5000 Hz in 200 transition
//!   steps at 50 MHz with two timer reloads per step, in the article's integer
//!   arithmetic (`len = 201, discretization = index, rounding = truncate,
//!   arithmetic = integer`) and in the default mode (`len = 200`);
//! - Zeng's three-stage curve (seed 002), 100 Hz to 1200 Hz at 1 MHz;
//! - a jerk-limited ramp, 200 Hz to 5000 Hz at 10 MHz;
//! - (pinned by `tests/torque_limited.rs`) the fastest ramp the shipped
//!   QSH4218-47-28-040 allows by its chart, with half its torque to spare,
//!   to 40 000 Hz at 10 MHz.
//!
//! The format is `stepper_profiles::golden`'s, as in `tests/golden.rs`:
//! `# key = value` lines (the parameters, then the table's figures), then one
//! entry per line with the time of its pulse edge; a segment table lists one
//! segment per line, its period, its count and where it ends.
//!
//! The tables come from `period_table!`, which is what users call, and must
//! equal [`Spec::table`] (or [`Spec::for_each_segment`]) for the same
//! parameters. Any change to an entry or a header line fails with the number
//! of entries that differ, the first of them and the largest shift of a pulse
//! edge. After an intended
//! change, bless the new tables with
//!
//! ```text
//! UPDATE_GOLDEN=1 cargo test --test golden_curves
//! ```
//!
//! and review them with `git diff tests/golden/curves`.

use test_support as common;

use std::path::PathBuf;

use common::golden::checked_periods;
use common::seeds::{
    self, SEED001_SEGMENTS, SEED004_INTEGER, integer_compat, jerk_limited, seed004, zeng,
};
use profile_codegen::__private::golden::{self, Body};
use profile_codegen::SpecTables;
use stepper_profiles::{Curve, Generated, Spec, Table, Timer, period_table};

/// The golden file `file`.
fn path(file: &str) -> PathBuf {
    [
        env!("CARGO_MANIFEST_DIR"),
        "tests",
        "golden",
        "curves",
        file,
    ]
    .iter()
    .collect()
}

/// What `period_table!` expanded to.
enum FromMacro {
    Periods(&'static [u16]),
    Segments(&'static [(u16, u16)]),
}

/// One golden table: its file, the macro's expansion, and the same
/// parameters as a [`Spec`].
struct Golden {
    file: &'static str,
    from_macro: FromMacro,
    spec: Spec,
}

// Seed 001's segments and seed 004's integer table, which `curves_exact.rs`
// and `seed004_c.rs` check too, are in `common::seeds`.
static SEED001_1MHZ: [u16; 120] = period_table!(
    curve = exponential,
    fmin = 500,
    fmax = 10000,
    f_inf = 15000,
    len = 120,
    timer_hz = 1_000_000,
);
static SEED001_10MHZ: [u16; 120] = period_table!(
    curve = exponential,
    fmin = 500,
    fmax = 10000,
    f_inf = 15000,
    len = 120,
    timer_hz = 10_000_000,
);
static SEED004_EXACT: [u16; 200] = period_table!(
    curve = linear,
    fmin = 500,
    fmax = 5000,
    len = 200,
    timer_hz = 50_000_000,
    ticks_per_step = 2,
);
static ZENG: [u16; 261] = period_table!(
    curve = three_stage,
    fmin = 100,
    fmax = 1200,
    accel = 4000,
    f1 = 400,
    f2 = 900,
    shape = 12,
    timer_hz = 1_000_000,
);
static JERK: [u16; 754] = period_table!(
    curve = jerk_limited,
    fmin = 200,
    fmax = 5000,
    accel = 20000,
    jerk = 400000,
    timer_hz = 10_000_000,
);

fn goldens() -> Vec<Golden> {
    let seed001 = Curve::Exponential(seeds::seed001());
    vec![
        Golden {
            file: "seed001_exponential_1mhz.txt",
            from_macro: FromMacro::Periods(&SEED001_1MHZ),
            spec: Spec::new(seed001, Timer::new(1_000_000)),
        },
        Golden {
            file: "seed001_exponential_10mhz.txt",
            from_macro: FromMacro::Periods(&SEED001_10MHZ),
            spec: Spec::new(seed001, Timer::new(10_000_000)),
        },
        Golden {
            file: "seed001_exponential_8_segments_1mhz.txt",
            from_macro: FromMacro::Segments(&SEED001_SEGMENTS),
            spec: Spec::new(seed001, Timer::new(1_000_000)),
        },
        Golden {
            file: "seed004_linear_integer.txt",
            from_macro: FromMacro::Periods(&SEED004_INTEGER),
            spec: integer_compat(seed004(201)),
        },
        Golden {
            file: "seed004_linear_exact.txt",
            from_macro: FromMacro::Periods(&SEED004_EXACT),
            spec: seed004(200),
        },
        Golden {
            file: "seed002_three_stage.txt",
            from_macro: FromMacro::Periods(&ZENG),
            spec: Spec::new(Curve::ThreeStage(zeng(12.0)), Timer::new(1_000_000)),
        },
        Golden {
            file: "jerk_limited.txt",
            from_macro: FromMacro::Periods(&JERK),
            spec: Spec::new(Curve::JerkLimited(jerk_limited()), Timer::new(10_000_000)),
        },
    ]
}

/// The table as `period_table!` and the library compute it (after checking
/// that the two agree).
fn checked(golden: &Golden) -> Generated {
    let spec = &golden.spec;
    let file = golden.file;
    match golden.from_macro {
        FromMacro::Periods(from_macro) => {
            let (periods, figures) = checked_periods(file, spec, from_macro);
            Generated::Steps(Table {
                spec: *spec,
                periods,
                figures,
            })
        }
        FromMacro::Segments(from_macro) => {
            let n = from_macro.len() as u32;
            let table = spec
                .check()
                .and_then(|c| c.segment_table(n))
                .unwrap_or_else(|e| panic!("{file}: expected {n} segments, got the error {e}"));
            let from_macro: Vec<(u32, u32)> = from_macro
                .iter()
                .map(|&(p, c)| (u32::from(p), u32::from(c)))
                .collect();
            assert_eq!(
                from_macro, table.pairs,
                "{file}: expected period_table!(segments = {n}) to equal the segment table"
            );
            Generated::Segments(table)
        }
    }
}

#[test]
fn period_table_macro_equals_spec_table() {
    for golden in &goldens() {
        checked(golden);
    }
}

#[test]
fn tables_match_golden_files() {
    let mut problems: Vec<String> = goldens()
        .iter()
        .filter_map(|g| golden::compare(path(g.file), &checked(g)).err())
        .collect();
    // Also after blessing: the files must still show the seeds' facts.
    problems.extend(seed_facts());
    assert!(
        problems.is_empty(),
        "expected the tables to match tests/golden/curves/ (bless an intended change with \
         `UPDATE_GOLDEN=1 cargo test --test golden_curves`):\n{}",
        problems.join("\n")
    );
}

/// Guards the blessed files themselves, so that a table blessed by mistake
/// cannot become the reference: seed 001 rises in 19.745 ms (tau 18.545 ms)
/// within 120 steps, split into 8 segments whose counts sum to 120; seed
/// 004's integer table runs from 50 000 to 5000 ticks (500 Hz to 5000 Hz at
/// 50 MHz, two reloads per step) over 201 entries.
fn seed_facts() -> Vec<String> {
    let mut problems = Vec::new();
    let mut check = |ok: bool, what: String| {
        if !ok {
            problems.push(what);
        }
    };
    match golden::read(path("seed001_exponential_1mhz.txt")) {
        Ok((_, Body::Periods(p))) => {
            let total: u64 = p.iter().map(|&t| u64::from(t)).sum();
            check(
                p.len() == 120,
                format!("seed 001: expected 120 entries, got {}", p.len()),
            );
            check(
                (19_745..=19_746).contains(&total),
                format!(
                    "seed 001: expected 19 745 or 19 746 ticks (19.745 ms) at 1 MHz, got {total}"
                ),
            );
        }
        Ok(_) => check(false, "seed 001: expected a per-step table".into()),
        Err(e) => check(false, e),
    }
    match golden::read(path("seed001_exponential_8_segments_1mhz.txt")) {
        Ok((_, Body::Segments(s))) => {
            let steps: u32 = s.iter().map(|&(_, c)| c).sum();
            check(
                s.len() == 8 && steps == 120 && s.iter().all(|&(_, c)| c >= 1),
                format!("seed 001 segments: expected 8 non-empty segments of 120 steps, got {s:?}"),
            );
        }
        Ok(_) => check(false, "seed 001 segments: expected a segment table".into()),
        Err(e) => check(false, e),
    }
    match golden::read(path("seed004_linear_integer.txt")) {
        Ok((_, Body::Periods(p))) => check(
            p.len() == 201 && p.first() == Some(&50_000) && p.last() == Some(&5000),
            format!(
                "seed 004: expected 201 entries from 50000 to 5000 ticks, got {} from {:?} to {:?}",
                p.len(),
                p.first(),
                p.last()
            ),
        ),
        Ok(_) => check(false, "seed 004: expected a per-step table".into()),
        Err(e) => check(false, e),
    }
    problems
}
