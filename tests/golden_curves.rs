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
//! The format is that of `tests/golden.rs`: `# key = value` lines (the
//! parameters, then the table's figures) followed by the periods in ticks,
//! ten per line; a segment table lists one `period count` pair per line.
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

use std::fmt::Write as _;
use std::fs;
use std::path::PathBuf;

use stepper_profiles::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, Rounding, Spec, ThreeStage, Timer, period_table,
};

/// Most mismatching entries listed per file.
const SHOWN_PER_FILE: usize = 20;

/// Values per line in a golden file of periods.
const PER_LINE: usize = 10;

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

/// A table's entries: periods, or (period, count) segments.
#[derive(Debug, PartialEq, Eq)]
enum Body {
    Periods(Vec<u32>),
    Segments(Vec<(u32, u32)>),
}

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
static SEED001_SEGMENTS: [(u16, u16); 8] = period_table!(
    curve = exponential,
    fmin = 500,
    fmax = 10000,
    f_inf = 15000,
    len = 120,
    timer_hz = 1_000_000,
    segments = 8,
);
static SEED004_INTEGER: [u16; 201] = period_table!(
    curve = linear,
    fmin = 500,
    fmax = 5000,
    len = 201,
    timer_hz = 50_000_000,
    ticks_per_step = 2,
    discretization = index,
    rounding = truncate,
    arithmetic = integer,
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
    let seed001 = Curve::Exponential(Exponential {
        fmin: 500.0,
        fmax: 10_000.0,
        f_inf: 15_000.0,
        extent: ExponentialExtent::Len(120),
    });
    let seed004 = |len| {
        Spec::new(
            Curve::Linear(Linear {
                fmin: 500.0,
                fmax: 5000.0,
                extent: LinearExtent::Len(len),
            }),
            Timer::new(50_000_000),
        )
        .with_ticks_per_step(2)
    };
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
            spec: seed004(201)
                .with_discretization(Discretization::Index)
                .with_rounding(Rounding::Truncate)
                .with_arithmetic(Arithmetic::Integer),
        },
        Golden {
            file: "seed004_linear_exact.txt",
            from_macro: FromMacro::Periods(&SEED004_EXACT),
            spec: seed004(200),
        },
        Golden {
            file: "seed002_three_stage.txt",
            from_macro: FromMacro::Periods(&ZENG),
            spec: Spec::new(
                Curve::ThreeStage(ThreeStage {
                    fmin: 100.0,
                    fmax: 1200.0,
                    accel: 4000.0,
                    f1: 400.0,
                    f2: 900.0,
                    shape: 12.0,
                }),
                Timer::new(1_000_000),
            ),
        },
        Golden {
            file: "jerk_limited.txt",
            from_macro: FromMacro::Periods(&JERK),
            spec: Spec::new(
                Curve::JerkLimited(JerkLimited {
                    fmin: 200.0,
                    fmax: 5000.0,
                    accel: 20_000.0,
                    jerk: 400_000.0,
                }),
                Timer::new(10_000_000),
            ),
        },
    ]
}

fn golden_path(file: &str) -> PathBuf {
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

fn owned(entries: &[(&str, String)]) -> Vec<(String, String)> {
    entries
        .iter()
        .map(|(k, v)| ((*k).to_owned(), v.clone()))
        .collect()
}

/// The curve's own parameters, as the macro's keys.
fn curve_parameters(curve: &Curve) -> Vec<(String, String)> {
    let s = |v: f64| v.to_string();
    let mut out = vec![("curve", curve.name().to_owned())];
    match *curve {
        Curve::Exponential(e) => {
            out.extend([
                ("fmin", s(e.fmin)),
                ("fmax", s(e.fmax)),
                ("f_inf", s(e.f_inf)),
            ]);
            out.push(match e.extent {
                ExponentialExtent::Len(len) => ("len", len.to_string()),
                ExponentialExtent::Tau(tau) => ("tau", s(tau)),
            });
        }
        Curve::Linear(l) => {
            out.extend([("fmin", s(l.fmin)), ("fmax", s(l.fmax))]);
            out.push(match l.extent {
                LinearExtent::Len(len) => ("len", len.to_string()),
                LinearExtent::Accel(a) => ("accel", s(a)),
            });
        }
        Curve::ThreeStage(z) => out.extend([
            ("fmin", s(z.fmin)),
            ("fmax", s(z.fmax)),
            ("accel", s(z.accel)),
            ("f1", s(z.f1)),
            ("f2", s(z.f2)),
            ("shape", s(z.shape)),
        ]),
        Curve::JerkLimited(j) => out.extend([
            ("fmin", s(j.fmin)),
            ("fmax", s(j.fmax)),
            ("accel", s(j.accel)),
            ("jerk", s(j.jerk)),
        ]),
        ref other => panic!("expected a non-sigmoid golden curve, got {other:?}"),
    }
    owned(&out)
}

/// The `# key = value` header and the entries, as `period_table!` and the
/// library compute them (after checking that the two agree).
fn checked(golden: &Golden) -> (Vec<(String, String)>, Body) {
    let spec = &golden.spec;
    let file = golden.file;
    let mut header = curve_parameters(&spec.curve);
    header.extend(owned(&[
        ("timer_hz", spec.timer.timer_hz.to_string()),
        ("word", spec.timer.word.name().to_owned()),
        ("ticks_per_step", spec.timer.ticks_per_step.to_string()),
        ("discretization", spec.discretization.name().to_owned()),
        ("rounding", spec.rounding.name().to_owned()),
        ("arithmetic", spec.arithmetic.name().to_owned()),
    ]));
    if let Curve::Exponential(e) = spec.curve {
        header.extend(owned(&[
            ("tau_s", format!("{:.9}", e.tau())),
            ("rise_time_s", format!("{:.9}", e.rise_time())),
        ]));
    }
    match golden.from_macro {
        FromMacro::Periods(from_macro) => {
            let table = spec
                .table()
                .unwrap_or_else(|e| panic!("{file}: expected a valid table, got the error {e}"));
            let from_macro: Vec<u32> = from_macro.iter().map(|&p| u32::from(p)).collect();
            let first_difference = from_macro
                .iter()
                .zip(&table.periods)
                .position(|(m, t)| m != t);
            assert!(
                from_macro.len() == table.periods.len() && first_difference.is_none(),
                "{file}: expected period_table! to equal Spec::table(); lengths {} and {}, \
                 first difference at index {first_difference:?}",
                from_macro.len(),
                table.periods.len()
            );
            let f = table.figures;
            header.extend(owned(&[
                ("entries", f.len.to_string()),
                ("first", f.first_ticks.to_string()),
                ("last", f.last_ticks.to_string()),
                ("total_ticks", f.total_ticks.to_string()),
                ("duration_s", format!("{:.9}", f.duration_s)),
                (
                    "max_edge_error_ticks",
                    format!("{:.6}", f.max_edge_error_ticks),
                ),
                ("total_error_ticks", format!("{:.6}", f.total_error_ticks)),
            ]));
            (header, Body::Periods(table.periods))
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
            header.extend(owned(&[
                ("segments", f.segments.to_string()),
                ("steps", f.steps.to_string()),
                ("flash_bytes", f.flash_bytes.to_string()),
                ("per_step_flash_bytes", f.per_step_flash_bytes.to_string()),
                ("total_ticks", f.total_ticks.to_string()),
                ("duration_s", format!("{:.9}", f.duration_s)),
                (
                    "max_edge_error_ticks",
                    format!("{:.6}", f.max_edge_error_ticks),
                ),
                ("total_error_ticks", format!("{:.6}", f.total_error_ticks)),
            ]));
            (header, Body::Segments(pairs))
        }
    }
}

/// A golden file's text: header lines, then the entries right-aligned.
fn render(header: &[(String, String)], body: &Body) -> String {
    let mut out = String::new();
    for (key, value) in header {
        let _ = writeln!(out, "# {key} = {value}");
    }
    match body {
        Body::Periods(periods) => {
            let width = periods
                .iter()
                .map(|p| p.to_string().len())
                .max()
                .unwrap_or(1);
            for line in periods.chunks(PER_LINE) {
                let cells: Vec<String> = line.iter().map(|p| format!("{p:>width$}")).collect();
                let _ = writeln!(out, "{}", cells.join(" "));
            }
        }
        Body::Segments(pairs) => {
            let width = pairs
                .iter()
                .map(|(p, c)| p.to_string().len().max(c.to_string().len()))
                .max()
                .unwrap_or(1);
            for (period, count) in pairs {
                let _ = writeln!(out, "{period:>width$} {count:>width$}");
            }
        }
    }
    out
}

/// A golden file read back: its header and its entries, shaped like `like`.
fn parse(file: &str, text: &str, like: &Body) -> Result<(Vec<(String, String)>, Body), String> {
    let mut header = Vec::new();
    let mut values: Vec<u32> = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let at = || format!("{file}:{}", number + 1);
        if let Some(rest) = line.strip_prefix('#') {
            let (key, value) = rest
                .split_once('=')
                .ok_or_else(|| format!("{}: expected `# key = value`, got {line:?}", at()))?;
            header.push((key.trim().to_owned(), value.trim().to_owned()));
            continue;
        }
        let words: Vec<&str> = line.split_whitespace().collect();
        if matches!(like, Body::Segments(_)) && words.len() != 2 {
            return Err(format!(
                "{}: expected one `period count` pair, got {line:?}",
                at()
            ));
        }
        for word in words {
            values.push(
                word.parse()
                    .map_err(|_| format!("{}: expected a number of ticks, got {word:?}", at()))?,
            );
        }
    }
    let body = match like {
        Body::Periods(_) => Body::Periods(values),
        Body::Segments(_) => Body::Segments(values.chunks(2).map(|c| (c[0], c[1])).collect()),
    };
    Ok((header, body))
}

/// Every difference between a golden file and the actual table, described.
fn differences(
    file: &str,
    golden: &(Vec<(String, String)>, Body),
    header: &[(String, String)],
    body: &Body,
) -> Vec<String> {
    let mut problems = Vec::new();
    let keys = |h: &[(String, String)]| h.iter().map(|(k, _)| k.clone()).collect::<Vec<_>>();
    if keys(&golden.0) != keys(header) {
        problems.push(format!(
            "{file}: header keys differ: golden {:?}, actual {:?}",
            keys(&golden.0),
            keys(header)
        ));
    }
    for (key, actual) in header {
        match golden.0.iter().find(|(k, _)| k == key) {
            Some((_, expected)) if expected == actual => {}
            Some((_, expected)) => problems.push(format!(
                "{file}: header `{key}`: golden {expected}, actual {actual}"
            )),
            None => problems.push(format!("{file}: header `{key}` missing, actual {actual}")),
        }
    }
    let (golden_cells, actual_cells, unit): (Vec<String>, Vec<String>, &str) =
        match (&golden.1, body) {
            (Body::Periods(g), Body::Periods(a)) => (
                g.iter().map(|p| format!("{p} ticks")).collect(),
                a.iter().map(|p| format!("{p} ticks")).collect(),
                "index",
            ),
            (Body::Segments(g), Body::Segments(a)) => (
                g.iter()
                    .map(|(p, c)| format!("{p} ticks x {c} steps"))
                    .collect(),
                a.iter()
                    .map(|(p, c)| format!("{p} ticks x {c} steps"))
                    .collect(),
                "segment",
            ),
            _ => unreachable!("parsed like the actual body"),
        };
    if golden_cells.len() != actual_cells.len() {
        problems.push(format!(
            "{file}: golden has {} entries, actual table {}",
            golden_cells.len(),
            actual_cells.len()
        ));
    }
    let mismatched: Vec<(usize, &String, &String)> = golden_cells
        .iter()
        .zip(&actual_cells)
        .enumerate()
        .filter(|(_, (g, a))| g != a)
        .map(|(i, (g, a))| (i, g, a))
        .collect();
    for &(index, expected, actual) in mismatched.iter().take(SHOWN_PER_FILE) {
        problems.push(format!(
            "{file}: {unit} {index}: golden {expected}, actual {actual}"
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

#[test]
fn period_table_macro_equals_spec_table() {
    for golden in &goldens() {
        checked(golden);
    }
}

#[test]
fn tables_match_golden_files() {
    let update = std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1");
    let mut problems = Vec::new();
    for golden in &goldens() {
        let (header, body) = checked(golden);
        let path = golden_path(golden.file);
        if update {
            fs::create_dir_all(path.parent().expect("a golden directory"))
                .expect("can create tests/golden/curves");
            // Write beside, then rename: tests reading the file meanwhile see
            // the old table or the new one, never half of one.
            let partial = path.with_extension("txt.partial");
            fs::write(&partial, render(&header, &body))
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
        match parse(golden.file, &text, &body) {
            Ok(parsed) => problems.extend(differences(golden.file, &parsed, &header, &body)),
            Err(problem) => problems.push(problem),
        }
    }
    // Also after blessing: the files must still show the seeds' facts.
    problems.extend(seed_facts());
    assert!(
        problems.is_empty(),
        "expected the tables to match their golden files (tests/golden/curves/); after an \
         intended change run `UPDATE_GOLDEN=1 cargo test --test golden_curves` and review \
         `git diff`:\n{}",
        problems.join("\n")
    );
}

/// Guards the blessed files themselves, so that a table blessed by mistake
/// cannot become the reference: seed 001 rises in 19.745 ms (tau 18.545 ms)
/// within 120 steps, split into 8 segments whose counts sum to 120; seed
/// 004's integer table runs from 50 000 to 5000 ticks (500 Hz to 5000 Hz at
/// 50 MHz, two reloads per step) over 201 entries.
fn seed_facts() -> Vec<String> {
    let read = |file: &str, like: &Body| {
        fs::read_to_string(golden_path(file))
            .map_err(|e| format!("{file}: cannot read: {e}"))
            .and_then(|text| parse(file, &text, like))
    };
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
    match read("seed001_exponential_1mhz.txt", &Body::Periods(Vec::new())) {
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
    match read(
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
    match read("seed004_linear_integer.txt", &Body::Periods(Vec::new())) {
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
