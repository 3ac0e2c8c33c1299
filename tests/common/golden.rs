//! Golden files: the one bless mechanism (`UPDATE_GOLDEN=1` writes, otherwise
//! compare) for every golden file of the tests, and the format of tables.
//!
//! A golden file starts with `# key = value` lines (a table's parameters, then
//! its figures) followed by its entries: periods in ticks, right-aligned, ten
//! per line; or for a segment table one `period count` pair per line. Any
//! difference from the actual table is described with the file, the index (or
//! key), the golden value and the actual one.

use std::fmt::Write as _;
use std::fs;
use std::path::{Path, PathBuf};

use stepper_profiles::{Curve, ExponentialExtent, Figures, LinearExtent, Spec};

/// Whether golden files are being blessed: `UPDATE_GOLDEN=1`.
pub fn blessing() -> bool {
    std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1")
}

/// Writes a golden file, its folder created: beside, then renamed, so that
/// tests reading the file meanwhile see the old text or the new, never half.
pub fn write(path: &Path, text: &str) {
    fs::create_dir_all(path.parent().expect("a golden directory"))
        .unwrap_or_else(|e| panic!("cannot create the folder of {}: {e}", path.display()));
    let partial = path.with_extension("partial");
    fs::write(&partial, text)
        .and_then(|()| fs::rename(&partial, path))
        .unwrap_or_else(|e| panic!("cannot write {}: {e}", path.display()));
}

/// A golden text file: with `UPDATE_GOLDEN=1` written with `actual`;
/// otherwise compared with it, a difference described as the expected and
/// the actual text.
pub fn text(path: &Path, name: &str, actual: &str) -> Result<(), String> {
    if blessing() {
        write(path, actual);
        return Ok(());
    }
    match fs::read_to_string(path) {
        Ok(expected) if expected.replace("\r\n", "\n") == actual => Ok(()),
        Ok(expected) => Err(format!(
            "--- {name}: expected ({})\n{expected}--- {name}: actual\n{actual}",
            path.display()
        )),
        Err(_) => Err(format!(
            "--- {name}: no golden file {}; actual\n{actual}",
            path.display()
        )),
    }
}

/// Most mismatching entries listed per file.
const SHOWN_PER_FILE: usize = 20;

/// Values per line in a golden file of periods.
const PER_LINE: usize = 10;

/// The `# key = value` lines of a golden file, in order.
pub type Header = Vec<(String, String)>;

/// A table's entries: periods, or (period, count) segments.
#[derive(Debug, PartialEq, Eq)]
pub enum Body {
    Periods(Vec<u32>),
    Segments(Vec<(u32, u32)>),
}

/// A folder of golden files and the test that blesses them.
pub struct Folder {
    /// The folder, relative to the package and `/`-separated: `tests/golden`.
    pub dir: &'static str,
    /// The test target that checks and blesses the files: `golden`.
    pub test: &'static str,
    /// What each number of a file's body is, as parse errors name it.
    pub number: &'static str,
}

impl Folder {
    /// The path of `file` in this folder.
    pub fn path(&self, file: &str) -> PathBuf {
        let mut path = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        path.extend(self.dir.split('/'));
        path.push(file);
        path
    }

    /// `file` read back, its body shaped like `like`.
    pub fn read(&self, file: &str, like: &Body) -> Result<(Header, Body), String> {
        fs::read_to_string(self.path(file))
            .map_err(|e| format!("{file}: cannot read: {e}"))
            .and_then(|text| self.parse(file, &text, like))
    }

    /// With `UPDATE_GOLDEN=1`, writes each table to its file; otherwise
    /// compares each table with its file. Returns every difference described.
    pub fn bless_or_compare<'a>(
        &self,
        tables: impl IntoIterator<Item = (&'a str, Header, Body)>,
    ) -> Vec<String> {
        let mut problems = Vec::new();
        for (file, header, body) in tables {
            let path = self.path(file);
            if blessing() {
                write(&path, &render(&header, &body));
                continue;
            }
            let text = match fs::read_to_string(&path) {
                Ok(text) => text,
                Err(e) => {
                    problems.push(format!("{file}: cannot read {}: {e}", path.display()));
                    continue;
                }
            };
            match self.parse(file, &text, &body) {
                Ok(parsed) => problems.extend(differences(file, &parsed, &header, &body)),
                Err(problem) => problems.push(problem),
            }
        }
        problems
    }

    /// Fails with every problem listed, and how to bless an intended change.
    #[track_caller]
    pub fn assert_no_problems(&self, problems: &[String]) {
        assert!(
            problems.is_empty(),
            "expected the tables to match their golden files ({}/); after an intended change \
             run `UPDATE_GOLDEN=1 cargo test --test {}` and review `git diff`:\n{}",
            self.dir,
            self.test,
            problems.join("\n")
        );
    }

    /// A golden file's text read back: its header and its entries, shaped
    /// like `like`.
    fn parse(&self, file: &str, text: &str, like: &Body) -> Result<(Header, Body), String> {
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
                values
                    .push(word.parse().map_err(|_| {
                        format!("{}: expected {}, got {word:?}", at(), self.number)
                    })?);
            }
        }
        let body = match like {
            Body::Periods(_) => Body::Periods(values),
            Body::Segments(_) => Body::Segments(values.chunks(2).map(|c| (c[0], c[1])).collect()),
        };
        Ok((header, body))
    }
}

/// Header lines from their keys and values.
pub fn header(entries: &[(&str, String)]) -> Header {
    entries
        .iter()
        .map(|(k, v)| ((*k).to_owned(), v.clone()))
        .collect()
}

/// The header's first lines: the curve's own parameters, as the macro's
/// keys, then the timer and the mode.
pub fn spec_header(spec: &Spec) -> Header {
    let s = |v: f64| v.to_string();
    let curve = &spec.curve;
    let mut out = vec![("curve", curve.name().to_owned())];
    match *curve {
        Curve::Sigmoid(g) => out.extend([
            ("len", g.len.to_string()),
            ("fmin", s(g.fmin)),
            ("fmax", s(g.fmax)),
            ("flexible", s(g.flexible)),
        ]),
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
        ref other => panic!("expected a curve the golden files know, got {other:?}"),
    }
    out.extend([
        ("timer_hz", spec.timer.timer_hz.to_string()),
        ("word", spec.timer.word.name().to_owned()),
        ("ticks_per_step", spec.timer.ticks_per_step.to_string()),
        ("discretization", spec.discretization.name().to_owned()),
        ("rounding", spec.rounding.name().to_owned()),
        ("arithmetic", spec.arithmetic.name().to_owned()),
    ]);
    header(&out)
}

/// The header lines of a table's figures: its first and last periods, then
/// [`timing`].
pub fn figures_header(f: &Figures) -> Header {
    let mut lines = header(&[
        ("first", f.first_ticks.to_string()),
        ("last", f.last_ticks.to_string()),
    ]);
    lines.extend(timing(
        f.total_ticks,
        f.duration_s,
        f.max_edge_error_ticks,
        f.total_error_ticks,
    ));
    lines
}

/// The header lines of how a table plays: its total and duration, and how
/// far its edges are from the exact ones.
pub fn timing(
    total_ticks: u64,
    duration_s: f64,
    max_edge_error_ticks: f64,
    total_error_ticks: f64,
) -> Header {
    header(&[
        ("total_ticks", total_ticks.to_string()),
        ("duration_s", format!("{duration_s:.9}")),
        ("max_edge_error_ticks", format!("{max_edge_error_ticks:.6}")),
        ("total_error_ticks", format!("{total_error_ticks:.6}")),
    ])
}

/// `spec`'s table as `Spec::table()` computes it, its periods and figures,
/// after checking that `period_table!` expanded to the same periods.
#[track_caller]
pub fn checked_periods(file: &str, spec: &Spec, from_macro: &[u16]) -> (Vec<u32>, Figures) {
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
        "{file}: expected period_table! to equal Spec::table(); lengths {} and {}, first \
         difference at index {first_difference:?}",
        from_macro.len(),
        table.periods.len()
    );
    (table.periods, table.figures)
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

/// Every difference between a golden file and the actual table, described.
fn differences(
    file: &str,
    golden: &(Header, Body),
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
