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
//! - a jerk-limited ramp, 200 Hz to 5000 Hz at 10 MHz.
//!
//! The format is that of `tests/golden.rs` (`common::golden`): `# key =
//! value` lines (the parameters, then the table's figures) followed by the
//! periods in ticks, ten per line; a segment table lists one `period count`
//! pair per line.
//!
//! The tables come from `period_table!`, which is what users call, and must
//! equal [`Spec::table`] (or [`Spec::for_each_segment`]) for the same
//! parameters. Any change to an entry or a header line fails with the file,
//! the index (or key), the golden value and the actual one. After an intended
//! change, bless the new tables with
//!
//! ```text
//! UPDATE_GOLDEN=1 cargo test --test golden_curves
//! ```
//!
//! and review them with `git diff tests/golden/curves`.

mod common;

use common::golden::{self, Body, Folder, Header};
use common::seeds::{
    self, SEED001_SEGMENTS, SEED004_INTEGER, integer_compat, jerk_limited, seed004, zeng,
};
use stepper_profiles::{Curve, SegmentFigures, Spec, Timer, period_table};

/// The golden files of this test.
const GOLDEN: Folder = Folder {
    dir: "tests/golden/curves",
    test: "golden_curves",
    number: "a number of ticks",
};

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

/// The `# key = value` header and the entries, as `period_table!` and the
/// library compute them (after checking that the two agree).
fn checked(golden: &Golden) -> (Header, Body) {
    let spec = &golden.spec;
    let file = golden.file;
    let mut header = golden::spec_header(spec);
    if let Curve::Exponential(e) = spec.curve {
        header.extend(golden::header(&[
            ("tau_s", format!("{:.9}", e.tau())),
            ("rise_time_s", format!("{:.9}", e.rise_time())),
        ]));
    }
    match golden.from_macro {
        FromMacro::Periods(from_macro) => {
            let (periods, figures) = golden::checked_periods(file, spec, from_macro);
            header.extend(golden::header(&[("entries", figures.len.to_string())]));
            header.extend(golden::figures_header(&figures));
            (header, Body::Periods(periods))
        }
        FromMacro::Segments(from_macro) => {
            let n = from_macro.len() as u32;
            let mut pairs = Vec::new();
            let f = spec
                .for_each_segment(n, |_, p, c| pairs.push((p, c)))
                .unwrap_or_else(|e| panic!("{file}: expected {n} segments, got the error {e}"));
            let from_macro: Vec<(u32, u32)> = from_macro
                .iter()
                .map(|&(p, c)| (u32::from(p), u32::from(c)))
                .collect();
            assert_eq!(
                from_macro, pairs,
                "{file}: expected period_table!(segments = {n}) to equal Spec::for_each_segment()"
            );
            header.extend(segment_figures_header(&f));
            (header, Body::Segments(pairs))
        }
    }
}

/// The header lines of a segment table's figures.
fn segment_figures_header(f: &SegmentFigures) -> Header {
    let mut header = golden::header(&[
        ("segments", f.segments.to_string()),
        ("steps", f.steps.to_string()),
        ("flash_bytes", f.flash_bytes.to_string()),
        ("per_step_flash_bytes", f.per_step_flash_bytes.to_string()),
    ]);
    header.extend(golden::timing(
        f.total_ticks,
        f.duration_s,
        f.max_edge_error_ticks,
        f.total_error_ticks,
    ));
    header
}

#[test]
fn period_table_macro_equals_spec_table() {
    for golden in &goldens() {
        checked(golden);
    }
}

#[test]
fn tables_match_golden_files() {
    let mut problems = GOLDEN.bless_or_compare(goldens().iter().map(|golden| {
        let (header, body) = checked(golden);
        (golden.file, header, body)
    }));
    // Also after blessing: the files must still show the seeds' facts.
    problems.extend(seed_facts());
    GOLDEN.assert_no_problems(&problems);
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
    let value = |header: &[(String, String)], key: &str| {
        header
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.clone())
            .unwrap_or_default()
    };
    match GOLDEN.read("seed001_exponential_1mhz.txt", &Body::Periods(Vec::new())) {
        Ok((header, Body::Periods(p))) => {
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
            check(
                value(&header, "tau_s").starts_with("0.018545"),
                format!(
                    "seed 001: expected tau 18.545 ms, got {}",
                    value(&header, "tau_s")
                ),
            );
            check(
                value(&header, "rise_time_s").starts_with("0.019745"),
                format!(
                    "seed 001: expected rise time 19.745 ms, got {}",
                    value(&header, "rise_time_s")
                ),
            );
        }
        Ok(_) => unreachable!("parsed as periods"),
        Err(e) => check(false, e),
    }
    match GOLDEN.read(
        "seed001_exponential_8_segments_1mhz.txt",
        &Body::Segments(Vec::new()),
    ) {
        Ok((_, Body::Segments(s))) => {
            let steps: u32 = s.iter().map(|&(_, c)| c).sum();
            check(
                s.len() == 8 && steps == 120 && s.iter().all(|&(_, c)| c >= 1),
                format!("seed 001 segments: expected 8 non-empty segments of 120 steps, got {s:?}"),
            );
        }
        Ok(_) => unreachable!("parsed as segments"),
        Err(e) => check(false, e),
    }
    match GOLDEN.read("seed004_linear_integer.txt", &Body::Periods(Vec::new())) {
        Ok((_, Body::Periods(p))) => check(
            p.len() == 201 && p.first() == Some(&50_000) && p.last() == Some(&5000),
            format!(
                "seed 004: expected 201 entries from 50000 to 5000 ticks, got {} from {:?} to {:?}",
                p.len(),
                p.first(),
                p.last()
            ),
        ),
        Ok(_) => unreachable!("parsed as periods"),
        Err(e) => check(false, e),
    }
    problems
}
