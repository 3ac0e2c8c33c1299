//! Golden tables: the four seed curves, as `period_table!` expands them.
//!
//! For each of seed 000's example calls (yellow, orange, blue, gray) there are
//! two files under `tests/golden/`: the compatibility mode
//! (`discretization = index, rounding = truncate, arithmetic = f32`, what the
//! seed's C code computes) and the default mode (`exact`, `diffuse`, `f64`).
//! Each file starts with `# key = value` lines (the parameters, then the
//! table's figures) followed by the periods in ticks, ten per line.
//!
//! The tables come from `period_table!`, which is what users call, and must
//! equal [`Spec::table`] for the same parameters. Any change to a period or a
//! header line fails with the file, the index (or key), the golden value and
//! the actual one. After an intended change, bless the new tables with
//!
//! ```text
//! UPDATE_GOLDEN=1 cargo test --test golden
//! ```
//!
//! and review them with `git diff tests/golden`.

use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;

use stepper_profiles::{
    Arithmetic, Curve, Discretization, Figures, Rounding, Sigmoid, Spec, Timer, period_table,
};

/// Most mismatching entries listed per file.
const SHOWN_PER_FILE: usize = 20;

/// Values per line in a golden file.
const PER_LINE: usize = 10;

/// One golden table: its file, the macro's expansion, and the same parameters
/// as a [`Spec`].
struct Golden {
    file: &'static str,
    from_macro: &'static [u16],
    spec: Spec,
}

/// Seed 000's call `CalculateSModelLine(..., len, fmax, fmin, flexible)` at 10 MHz.
fn seed_spec(len: u32, fmax: f64, fmin: f64, flexible: f64) -> Spec {
    Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin,
            fmax,
            flexible,
            len,
        }),
        Timer::new(10_000_000),
    )
}

/// The same spec in the seed's compatibility mode.
fn compat(spec: Spec) -> Spec {
    spec.with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::F32)
}

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
static ORANGE_COMPAT: [u16; 1000] = period_table!(
    curve = sigmoid,
    len = 1000,
    fmin = 500,
    fmax = 64000,
    flexible = 8,
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
    let yellow = seed_spec(1000, 56_000.0, 16_000.0, 4.0);
    let orange = seed_spec(1000, 64_000.0, 500.0, 8.0);
    let blue = seed_spec(1000, 64_000.0, 500.0, 15.0);
    let gray = seed_spec(1000, 40_000.0, 500.0, 5.0);
    [
        Golden {
            file: "seed000_yellow_compat.txt",
            from_macro: &YELLOW_COMPAT,
            spec: compat(yellow),
        },
        Golden {
            file: "seed000_orange_compat.txt",
            from_macro: &ORANGE_COMPAT,
            spec: compat(orange),
        },
        Golden {
            file: "seed000_blue_compat.txt",
            from_macro: &BLUE_COMPAT,
            spec: compat(blue),
        },
        Golden {
            file: "seed000_gray_compat.txt",
            from_macro: &GRAY_COMPAT,
            spec: compat(gray),
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

fn golden_path(file: &str) -> PathBuf {
    [env!("CARGO_MANIFEST_DIR"), "tests", "golden", file]
        .iter()
        .collect()
}

/// The `# key = value` header: parameters first, then figures.
fn header(spec: &Spec, figures: &Figures) -> Vec<(String, String)> {
    let Curve::Sigmoid(s) = spec.curve else {
        panic!(
            "expected the golden specs to be sigmoids, got {:?}",
            spec.curve
        )
    };
    let entries: [(&str, String); 17] = [
        ("curve", spec.curve.name().to_owned()),
        ("len", s.len.to_string()),
        ("fmin", s.fmin.to_string()),
        ("fmax", s.fmax.to_string()),
        ("flexible", s.flexible.to_string()),
        ("timer_hz", spec.timer.timer_hz.to_string()),
        ("word", spec.timer.word.name().to_owned()),
        ("ticks_per_step", spec.timer.ticks_per_step.to_string()),
        ("discretization", spec.discretization.name().to_owned()),
        ("rounding", spec.rounding.name().to_owned()),
        ("arithmetic", spec.arithmetic.name().to_owned()),
        ("first", figures.first_ticks.to_string()),
        ("last", figures.last_ticks.to_string()),
        ("total_ticks", figures.total_ticks.to_string()),
        ("duration_s", format!("{:.9}", figures.duration_s)),
        (
            "max_edge_error_ticks",
            format!("{:.6}", figures.max_edge_error_ticks),
        ),
        (
            "total_error_ticks",
            format!("{:.6}", figures.total_error_ticks),
        ),
    ];
    entries
        .into_iter()
        .map(|(k, v)| (k.to_owned(), v))
        .collect()
}

/// A golden file's text: header lines, then the periods right-aligned, ten per line.
fn render(header: &[(String, String)], periods: &[u32]) -> String {
    let mut out = String::new();
    for (key, value) in header {
        let _ = writeln!(out, "# {key} = {value}");
    }
    let width = periods
        .iter()
        .map(|p| p.to_string().len())
        .max()
        .unwrap_or(1);
    for line in periods.chunks(PER_LINE) {
        let cells: Vec<String> = line.iter().map(|p| format!("{p:>width$}")).collect();
        let _ = writeln!(out, "{}", cells.join(" "));
    }
    out
}

/// A golden file read back: its header and its periods.
struct Parsed {
    header: Vec<(String, String)>,
    periods: Vec<u32>,
}

fn parse(file: &str, text: &str) -> Result<Parsed, String> {
    let mut parsed = Parsed {
        header: Vec::new(),
        periods: Vec::new(),
    };
    for (number, line) in text.lines().enumerate() {
        if let Some(rest) = line.strip_prefix('#') {
            let (key, value) = rest.split_once('=').ok_or_else(|| {
                format!(
                    "{file}:{}: expected `# key = value`, got {line:?}",
                    number + 1
                )
            })?;
            parsed
                .header
                .push((key.trim().to_owned(), value.trim().to_owned()));
        } else {
            for word in line.split_whitespace() {
                let ticks = word.parse().map_err(|_| {
                    format!(
                        "{file}:{}: expected a period in ticks, got {word:?}",
                        number + 1
                    )
                })?;
                parsed.periods.push(ticks);
            }
        }
    }
    Ok(parsed)
}

/// Every difference between a golden file and the actual table, described.
fn differences(
    file: &str,
    golden: &Parsed,
    header: &[(String, String)],
    periods: &[u32],
) -> Vec<String> {
    let mut problems = Vec::new();
    let keys = |h: &[(String, String)]| h.iter().map(|(k, _)| k.clone()).collect::<Vec<_>>();
    if keys(&golden.header) != keys(header) {
        problems.push(format!(
            "{file}: header keys differ: golden {:?}, actual {:?}",
            keys(&golden.header),
            keys(header)
        ));
    }
    for (key, actual) in header {
        match golden.header.iter().find(|(k, _)| k == key) {
            Some((_, expected)) if expected == actual => {}
            Some((_, expected)) => problems.push(format!(
                "{file}: header `{key}`: golden {expected}, actual {actual}"
            )),
            None => problems.push(format!("{file}: header `{key}` missing, actual {actual}")),
        }
    }
    if golden.periods.len() != periods.len() {
        problems.push(format!(
            "{file}: golden has {} entries, actual table {}",
            golden.periods.len(),
            periods.len()
        ));
    }
    let mismatched: Vec<(usize, u32, u32)> = golden
        .periods
        .iter()
        .zip(periods)
        .enumerate()
        .filter(|(_, (g, a))| g != a)
        .map(|(i, (&g, &a))| (i, g, a))
        .collect();
    for &(index, expected, actual) in mismatched.iter().take(SHOWN_PER_FILE) {
        problems.push(format!(
            "{file}: index {index}: golden {expected} ticks, actual {actual} ticks"
        ));
    }
    if mismatched.len() > SHOWN_PER_FILE {
        problems.push(format!(
            "{file}: ... {} more mismatched entries ({} in all)",
            mismatched.len() - SHOWN_PER_FILE,
            mismatched.len()
        ));
    }
    problems
}

/// The table of `golden` as `Spec::table()` computes it, after checking that
/// `period_table!` expanded to the same periods.
fn checked_table(golden: &Golden) -> (Vec<u32>, Figures) {
    let table = golden
        .spec
        .table()
        .unwrap_or_else(|e| panic!("{}: expected a valid table, got the error {e}", golden.file));
    let from_macro: Vec<u32> = golden.from_macro.iter().map(|&p| u32::from(p)).collect();
    let first_difference = from_macro
        .iter()
        .zip(&table.periods)
        .position(|(m, t)| m != t);
    assert!(
        from_macro.len() == table.periods.len() && first_difference.is_none(),
        "{}: expected period_table! to equal Spec::table(); lengths {} and {}, first difference \
         at index {first_difference:?}",
        golden.file,
        from_macro.len(),
        table.periods.len()
    );
    (table.periods, table.figures)
}

#[test]
fn period_table_macro_equals_spec_table() {
    for golden in &goldens() {
        checked_table(golden);
    }
}

#[test]
fn tables_match_golden_files() {
    let update = std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1");
    let mut problems = Vec::new();
    for golden in &goldens() {
        let (periods, figures) = checked_table(golden);
        let header = header(&golden.spec, &figures);
        let path = golden_path(golden.file);
        if update {
            fs::create_dir_all(path.parent().expect("a golden directory"))
                .expect("can create tests/golden");
            // Write beside, then rename: tests reading the file meanwhile see
            // the old table or the new one, never half of one.
            let partial = path.with_extension("txt.partial");
            fs::write(&partial, render(&header, &periods))
                .and_then(|()| fs::rename(&partial, &path))
                .unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
            continue;
        }
        let text = match fs::read_to_string(&path) {
            Ok(text) => text,
            Err(e) => {
                problems.push(format!(
                    "{}: cannot read {}: {e}",
                    golden.file,
                    path.display()
                ));
                continue;
            }
        };
        match parse(golden.file, &text) {
            Ok(parsed) => problems.extend(differences(golden.file, &parsed, &header, &periods)),
            Err(problem) => problems.push(problem),
        }
    }
    // Also after blessing: the new orange file must still show the seed's facts.
    problems.extend(orange_compat_seed_facts());
    assert!(
        problems.is_empty(),
        "expected the tables to match their golden files (tests/golden/); after an intended \
         change run `UPDATE_GOLDEN=1 cargo test --test golden` and review `git diff`:\n{}",
        problems.join("\n")
    );
}

/// Guards the blessed orange compatibility file itself, so that a table
/// blessed by mistake cannot become the reference. DESIGN.md: first 19183,
/// last 156, about 0.412 s at 10 MHz.
fn orange_compat_seed_facts() -> Vec<String> {
    let file = "seed000_orange_compat.txt";
    let parsed = match fs::read_to_string(golden_path(file))
        .map_err(|e| format!("{file}: cannot read: {e}"))
        .and_then(|text| parse(file, &text))
    {
        Ok(parsed) => parsed,
        Err(problem) => return vec![problem],
    };
    let mut problems = Vec::new();
    if parsed.periods.len() != 1000 {
        problems.push(format!(
            "{file}: expected 1000 entries, got {}",
            parsed.periods.len()
        ));
    }
    let ends = (parsed.periods.first(), parsed.periods.last());
    if ends != (Some(&19183), Some(&156)) {
        problems.push(format!(
            "{file}: expected the seed's first and last periods 19183 and 156, got {ends:?}"
        ));
    }
    let total: u64 = parsed.periods.iter().map(|&p| u64::from(p)).sum();
    let seconds = total as f64 / 10_000_000.0;
    if (seconds - 0.412).abs() >= 0.0005 {
        problems.push(format!(
            "{file}: expected about 0.412 s at 10 MHz, got {seconds} s ({total} ticks)"
        ));
    }
    let stated = parsed.header.iter().find(|(k, _)| k == "total_ticks");
    if stated.map(|(_, v)| v.as_str()) != Some(total.to_string().as_str()) {
        problems.push(format!(
            "{file}: expected the header's total_ticks to be the sum of the entries, {total}, \
             got {stated:?}"
        ));
    }
    problems
}
