//! A golden file against the table's text, line by line, once their
//! entries agree: spacing is no difference; the first line that differs
//! otherwise is named, with what it reads and what the table gives.

use std::format;
use std::string::String;
use std::vec::Vec;

/// The columns of a per-step table's entry lines, the first naming an
/// entry; then those of segments and of runs.
pub(super) const PER_STEP: &[&str] = &["entry", "period", "edge (ticks)", "edge (us)"];
pub(super) const SEGMENTS: &[&str] = &["segment", "period", "count", "end (ticks)", "end (us)"];
pub(super) const RUNS: &[&str] = &[
    "run",
    "count",
    "int_hi",
    "int_lo",
    "add_hi",
    "add_lo",
    "end (ticks)",
    "end (us)",
];

/// The lines of `text` that hold words, numbered from 1, each as its words.
fn worded(text: &str) -> impl Iterator<Item = (usize, Vec<&str>)> {
    text.lines()
        .enumerate()
        .map(|(n, line)| (n + 1, line.split_whitespace().collect::<Vec<_>>()))
        .filter(|(_, words)| !words.is_empty())
}

/// Whether `a` and `b` hold the same words line by line: they differ at
/// most in spacing (tabs, blanks at the ends of lines, blank lines, line
/// endings), which an editor may change without changing the table.
pub(super) fn same_words(a: &str, b: &str) -> bool {
    worded(a).map(|(_, w)| w).eq(worded(b).map(|(_, w)| w))
}

/// The first line of `file` whose words differ from the table's `text`,
/// numbered from 1, and how, in words. `columns` names the entry lines'
/// columns, the first naming an entry (`entry`, `segment`, `run`).
pub(super) fn first_difference(file: &str, text: &str, columns: &[&str]) -> (usize, String) {
    let mut old = worded(file);
    let mut new = worded(text);
    let end = file.lines().count() + 1;
    loop {
        match (old.next(), new.next()) {
            (Some((n, a)), Some((_, b))) if a != b => return (n, describe(&a, &b, columns)),
            (Some(_), Some(_)) => {}
            (Some((n, a)), None) => {
                let line = a.join(" ");
                return (
                    n,
                    format!("the file goes on after the table's last line with `{line}`"),
                );
            }
            (None, Some((_, b))) => {
                let line = b.join(" ");
                return (end, format!("the file ends where the table gives `{line}`"));
            }
            (None, None) => return (end, String::from("only the spacing differs")),
        }
    }
}

/// How line `a` of the file differs from the table's `b`: a figure's
/// value (`# key = value`), an entry's column, or the whole line.
fn describe(a: &[&str], b: &[&str], columns: &[&str]) -> String {
    let setting = |words: &[&str]| -> Option<(String, String)> {
        let line = words.join(" ");
        let (key, value) = line.strip_prefix('#')?.split_once('=')?;
        Some((key.trim().into(), value.trim().into()))
    };
    if let (Some((key, was)), Some((same, now))) = (setting(a), setting(b)) {
        if key == same {
            return format!("`{key}` reads {was}, the table gives {now}");
        }
    }
    let entry = !a[0].starts_with('#') && !b[0].starts_with('#');
    if entry && a.len() == b.len() && a.len() <= columns.len() {
        if let Some(c) = (0..a.len()).find(|&c| a[c] != b[c]) {
            let (noun, index) = (columns[0], b[0]);
            if c == 0 {
                return format!(
                    "the {noun}'s number reads {}, the table gives {index}",
                    a[0]
                );
            }
            return format!(
                "{noun} {index}'s {} reads {}, the table gives {}",
                columns[c], a[c], b[c]
            );
        }
    }
    format!(
        "the line reads `{}`, the table gives `{}`",
        a.join(" "),
        b.join(" ")
    )
}
