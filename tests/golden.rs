//! Golden tables: the four seed curves, as `period_table!` expands them.
//!
//! For each of seed 000's example calls (yellow, orange, blue, gray) there are
//! two files under `tests/golden/`: the compatibility mode
//! (`discretization = index, rounding = truncate, arithmetic = f32`, what the
//! seed's C code computes) and the default mode (`exact`, `diffuse`, `f64`).
//! The files are `stepper_profiles::golden`'s, as users' golden tests write
//! them: `# key = value` lines (the parameters, then the table's figures),
//! then one entry per line with the time of its pulse edge.
//!
//! The tables come from `period_table!`, which is what users call, and must
//! equal [`Spec::table`] for the same parameters. Any change to a period or a
//! header line fails with the number of entries that differ, the first of
//! them and the largest shift of a pulse edge. After an intended change, bless the new tables with
//!
//! ```text
//! UPDATE_GOLDEN=1 cargo test --test golden
//! ```
//!
//! and review them with `git diff tests/golden`.

use test_support as common;

use std::path::PathBuf;

use common::golden::checked_periods;
use common::seeds::{SEED000_ORANGE_COMPAT, f32_compat, seed000};
use profile_codegen::__private::golden::{self, Body};
use stepper_profiles::{Figures, Generated, Spec, Table, period_table};

/// The golden file `file`.
fn path(file: &str) -> PathBuf {
    [env!("CARGO_MANIFEST_DIR"), "tests", "golden", file]
        .iter()
        .collect()
}

/// One golden table: its file, the macro's expansion, and the same parameters
/// as a [`Spec`].
struct Golden {
    file: &'static str,
    from_macro: &'static [u16],
    spec: Spec,
}

// The orange compatibility table, which `seed_c.rs` checks against the C
// code too, is `common::seeds::SEED000_ORANGE_COMPAT`.
static YELLOW_COMPAT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 16000,
    fmax = 56000,
    flexible = 4,
    timer_hz = 10_000_000,
    discretization = index,
    rounding = truncate,
    arithmetic = f32,
);
static BLUE_COMPAT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64000,
    flexible = 15,
    timer_hz = 10_000_000,
    discretization = index,
    rounding = truncate,
    arithmetic = f32,
);
static GRAY_COMPAT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 40000,
    flexible = 5,
    timer_hz = 10_000_000,
    discretization = index,
    rounding = truncate,
    arithmetic = f32,
);
static YELLOW_DEFAULT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 16000,
    fmax = 56000,
    flexible = 4,
    timer_hz = 10_000_000,
);
static ORANGE_DEFAULT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64000,
    flexible = 8,
    timer_hz = 10_000_000,
);
static BLUE_DEFAULT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64000,
    flexible = 15,
    timer_hz = 10_000_000,
);
static GRAY_DEFAULT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 40000,
    flexible = 5,
    timer_hz = 10_000_000,
);

fn goldens() -> [Golden; 8] {
    let yellow = seed000(1000, 56_000.0, 16_000.0, 4.0);
    let orange = seed000(1000, 64_000.0, 500.0, 8.0);
    let blue = seed000(1000, 64_000.0, 500.0, 15.0);
    let gray = seed000(1000, 40_000.0, 500.0, 5.0);
    [
        Golden {
            file: "seed000_yellow_compat.txt",
            from_macro: &YELLOW_COMPAT,
            spec: f32_compat(yellow),
        },
        Golden {
            file: "seed000_orange_compat.txt",
            from_macro: &SEED000_ORANGE_COMPAT,
            spec: f32_compat(orange),
        },
        Golden {
            file: "seed000_blue_compat.txt",
            from_macro: &BLUE_COMPAT,
            spec: f32_compat(blue),
        },
        Golden {
            file: "seed000_gray_compat.txt",
            from_macro: &GRAY_COMPAT,
            spec: f32_compat(gray),
        },
        Golden {
            file: "seed000_yellow_default.txt",
            from_macro: &YELLOW_DEFAULT,
            spec: yellow,
        },
        Golden {
            file: "seed000_orange_default.txt",
            from_macro: &ORANGE_DEFAULT,
            spec: orange,
        },
        Golden {
            file: "seed000_blue_default.txt",
            from_macro: &BLUE_DEFAULT,
            spec: blue,
        },
        Golden {
            file: "seed000_gray_default.txt",
            from_macro: &GRAY_DEFAULT,
            spec: gray,
        },
    ]
}

/// The table of `golden` as `Spec::table()` computes it, after checking that
/// `period_table!` expanded to the same periods.
fn checked_table(golden: &Golden) -> (Vec<u32>, Figures) {
    checked_periods(golden.file, &golden.spec, golden.from_macro)
}

#[test]
fn period_table_macro_equals_spec_table() {
    for golden in &goldens() {
        checked_table(golden);
    }
}

#[test]
fn tables_match_golden_files() {
    let mut problems: Vec<String> = goldens()
        .iter()
        .filter_map(|g| {
            let (periods, figures) = checked_table(g);
            let table = Generated::Steps(Table {
                spec: g.spec,
                periods,
                figures,
            });
            golden::compare(path(g.file), &table).err()
        })
        .collect();
    // Also after blessing: the new orange file must still show the seed's facts.
    problems.extend(orange_compat_seed_facts());
    assert!(
        problems.is_empty(),
        "expected the tables to match tests/golden/ (bless an intended change with \
         `UPDATE_GOLDEN=1 cargo test --test golden`):\n{}",
        problems.join("\n")
    );
}

/// Guards the blessed orange compatibility file itself, so that a table
/// blessed by mistake cannot become the reference. The orange call's known
/// figures: first 19183, last 156, about 0.412 s at 10 MHz.
fn orange_compat_seed_facts() -> Vec<String> {
    let file = "seed000_orange_compat.txt";
    let (header, periods) = match golden::read(path(file)) {
        Ok((header, Body::Periods(periods))) => (header, periods),
        Ok(_) => return vec![format!("{file}: expected a per-step table, got segments")],
        Err(problem) => return vec![problem],
    };
    let mut problems = Vec::new();
    if periods.len() != 1000 {
        problems.push(format!(
            "{file}: expected 1000 entries, got {}",
            periods.len()
        ));
    }
    let ends = (periods.first(), periods.last());
    if ends != (Some(&19183), Some(&156)) {
        problems.push(format!(
            "{file}: expected the seed's first and last periods 19183 and 156, got {ends:?}"
        ));
    }
    let total: u64 = periods.iter().map(|&p| u64::from(p)).sum();
    let seconds = total as f64 / 10_000_000.0;
    if (seconds - 0.412).abs() >= 0.0005 {
        problems.push(format!(
            "{file}: expected about 0.412 s at 10 MHz, got {seconds} s ({total} ticks)"
        ));
    }
    let stated = header.iter().find(|(k, _)| k == "total_ticks");
    if stated.map(|(_, v)| v.as_str()) != Some(total.to_string().as_str()) {
        problems.push(format!(
            "{file}: expected the header's total_ticks to be the sum of the entries, {total}, \
             got {stated:?}"
        ));
    }
    problems
}
