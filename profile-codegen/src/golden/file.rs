//! A golden file: the entries it holds, reading it back, comparing a table
//! with it and blessing it. Not API: `golden::check` and `check_file` are;
//! the repository's own tests reach these through `__private::golden`.

use std::format;
use std::fs;
use std::path::Path;
use std::string::{String, ToString};
use std::vec::Vec;

use super::Golden;
use super::lines;
use super::render::{edges, micros, render};
use crate::numbers::Fixed;
use crate::table::computed::expand;

/// A table as a golden file holds it.
#[derive(Clone, Debug, PartialEq)]
pub struct Entries {
    /// `# key = value` lines: parameters, then figures.
    pub header: Vec<(String, String)>,
    /// The entries.
    pub body: Body,
    /// The timer's tick rate, when known, for edge times in microseconds.
    pub timer_hz: Option<u32>,
    /// Timer reloads per step: 2 when each entry is a half period.
    pub ticks_per_step: u8,
}

/// A table's entries.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Body {
    /// One period per step, in ticks.
    Periods(Vec<u32>),
    /// `(period, count)` segments.
    Segments(Vec<(u32, u32)>),
    /// Runs, five words each (see [`runs`](profile_core::runs)).
    Runs(Vec<[u16; 5]>),
}

impl Body {
    /// Every step's period, segments expanded.
    pub(super) fn steps(&self) -> Vec<u32> {
        match self {
            Body::Periods(p) => p.clone(),
            Body::Segments(s) => expand(s),
            Body::Runs(r) => profile_core::runs::Expand::new(r).collect(),
        }
    }

    pub(super) fn len(&self) -> usize {
        match self {
            Body::Periods(p) => p.len(),
            Body::Segments(s) => s.len(),
            Body::Runs(r) => r.len(),
        }
    }
}

/// Whether golden files are being blessed: `UPDATE_GOLDEN=1`.
pub fn blessing() -> bool {
    std::env::var_os("UPDATE_GOLDEN").is_some_and(|v| v == "1")
}

/// [`check`](super::check), returning what changed instead of panicking; with
/// `UPDATE_GOLDEN=1`, writes the file and returns `Ok`.
pub fn compare<T: Golden + ?Sized>(path: impl AsRef<Path>, table: &T) -> Result<(), String> {
    compare_as(path.as_ref(), table, blessing())
}

/// [`compare`], blessing when `bless` says.
pub(super) fn compare_as<T: Golden + ?Sized>(
    path: &Path,
    table: &T,
    bless: bool,
) -> Result<(), String> {
    let actual = table.entries();
    let text = render(&actual);
    if bless {
        return write(path, &text);
    }
    let old = fs::read_to_string(path).map_err(|e| {
        format!(
            "{}: cannot read the golden file ({e}); run with UPDATE_GOLDEN=1 to write it",
            path.display()
        )
    })?;
    // Spacing is no change: an editor's tabs, trailing blanks, line endings.
    if old == text || lines::same_words(&old, &text) {
        return Ok(());
    }
    let bless = "if the change is intended, rerun with UPDATE_GOLDEN=1 and review the diff";
    let entries =
        parse(&old, &actual.body).map_err(|e| format!("{}:{e}; {bless}", path.display()))?;
    if entries == actual.body {
        let columns = match actual.body {
            Body::Periods(_) => lines::PER_STEP,
            Body::Segments(_) => lines::SEGMENTS,
            Body::Runs(_) => lines::RUNS,
        };
        let (line, what) = lines::first_difference(&old, &text, columns);
        return Err(format!(
            "{}:{line}: the entries are unchanged, but {what}; {bless}",
            path.display()
        ));
    }
    let old = entries;
    Err(format!(
        "{}: the table differs from its golden file: {}; {bless}",
        path.display(),
        difference(&old, &actual)
    ))
}

fn write(path: &Path, text: &str) -> Result<(), String> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        fs::create_dir_all(dir)
            .map_err(|e| format!("cannot create the folder {}: {e}", dir.display()))?;
    }
    // Beside, then renamed: a reader sees the old text or the new, never
    // half; and nothing is left beside when either fails.
    let partial = path.with_extension("partial");
    let written = fs::write(&partial, text).and_then(|()| fs::rename(&partial, path));
    if written.is_err() {
        let _ = fs::remove_file(&partial);
    }
    written.map_err(|e| format!("cannot write {}: {e}", path.display()))
}

/// A golden file read back: its `# key = value` lines (the table's kind,
/// size, parameters and figures) and its entries.
pub fn read(path: impl AsRef<Path>) -> Result<(Vec<(String, String)>, Body), String> {
    let path = path.as_ref();
    let text = fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let header: Vec<(String, String)> = text
        .lines()
        .filter_map(|l| l.strip_prefix('#')?.split_once('='))
        .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
        .collect();
    let like = match header.iter().find(|(k, _)| k == "table") {
        Some((_, kind)) if kind == "segments" => Body::Segments(Vec::new()),
        Some((_, kind)) if kind == "runs" => Body::Runs(Vec::new()),
        _ => Body::Periods(Vec::new()),
    };
    let body = parse(&text, &like).map_err(|e| format!("{}:{e}", path.display()))?;
    Ok((header, body))
}

/// A golden file's entries, read back like `like`.
pub(super) fn parse(text: &str, like: &Body) -> Result<Body, String> {
    let mut periods = Vec::new();
    let mut segments = Vec::new();
    let mut runs = Vec::new();
    for (n, line) in text.lines().enumerate() {
        if line.starts_with('#') || line.trim().is_empty() {
            continue;
        }
        let cell = |i: usize| -> Result<u32, String> {
            line.split_whitespace()
                .nth(i)
                .and_then(|w| w.parse().ok())
                .ok_or_else(|| format!("{}: expected an entry line, got {line:?}", n + 1))
        };
        match like {
            Body::Periods(_) => periods.push(cell(1)?),
            Body::Segments(_) => segments.push((cell(1)?, cell(2)?)),
            Body::Runs(_) => {
                let mut words = [0u16; 5];
                for (k, w) in words.iter_mut().enumerate() {
                    *w = u16::try_from(cell(k + 1)?)
                        .map_err(|_| format!("{}: a run word above 65535", n + 1))?;
                }
                runs.push(words);
            }
        }
    }
    Ok(match like {
        Body::Periods(_) => Body::Periods(periods),
        Body::Segments(_) => Body::Segments(segments),
        Body::Runs(_) => Body::Runs(runs),
    })
}

/// What changed from `old` to `new`, in a sentence.
pub(super) fn difference(old: &Body, new: &Entries) -> String {
    let mut parts = Vec::new();
    let (name, first, differing) = match (old, &new.body) {
        (Body::Periods(o), Body::Periods(n)) => {
            let first = o
                .iter()
                .zip(n)
                .position(|(a, b)| a != b)
                .map(|i| format!("the first at entry {i}: was {} ticks, now {}", o[i], n[i]));
            let differing = o.iter().zip(n).filter(|(a, b)| a != b).count();
            ("entries", first, differing)
        }
        (Body::Segments(o), Body::Segments(n)) => {
            let first = o.iter().zip(n).position(|(a, b)| a != b).map(|i| {
                format!(
                    "the first at segment {i}: was {} ticks x {}, now {} ticks x {}",
                    o[i].0, o[i].1, n[i].0, n[i].1
                )
            });
            let differing = o.iter().zip(n).filter(|(a, b)| a != b).count();
            ("segments", first, differing)
        }
        (Body::Runs(o), Body::Runs(n)) => {
            let first = o
                .iter()
                .zip(n)
                .position(|(a, b)| a != b)
                .map(|i| format!("the first at run {i}: was {:?}, now {:?}", o[i], n[i]));
            let differing = o.iter().zip(n).filter(|(a, b)| a != b).count();
            ("runs", first, differing)
        }
        _ => return "its layout changed".to_string(),
    };
    if old.len() != new.body.len() {
        parts.push(format!("{} {name}, was {}", new.body.len(), old.len()));
    }
    if differing > 0 {
        let of = old.len().min(new.body.len());
        let first = first.unwrap_or_default();
        parts.push(format!("{differing} of {of} {name} differ, {first}"));
    }
    let (o, n) = (
        edges(old, new.ticks_per_step),
        edges(&new.body, new.ticks_per_step),
    );
    let shift = o
        .iter()
        .zip(&n)
        .map(|(a, b)| a.abs_diff(*b))
        .max()
        .unwrap_or(0);
    let at = new
        .timer_hz
        .map(|hz| format!(" ({} us)", Fixed(micros(shift, hz), 3)))
        .unwrap_or_default();
    parts.push(format!(
        "the largest shift of a pulse edge is {shift} ticks{at}"
    ));
    parts.join("; ")
}
