//! "Did you mean": the one place a near miss is found and phrased.

use std::format;
use std::string::String;
use std::vec::Vec;

/// Edit distance, for "did you mean".
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(ca != *cb);
            let next = (row[j + 1] + 1).min(row[j] + 1).min(prev + cost);
            prev = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// The closest of `candidates` to `word`, if close enough to be a typo: one
/// that differs only in case first (`KHz` is `kHz`, not `Hz`).
pub fn suggest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let candidates: Vec<&'a str> = candidates.into_iter().collect();
    if let Some(same) = candidates.iter().find(|c| c.eq_ignore_ascii_case(word)) {
        return Some(same);
    }
    let len = word.chars().count();
    candidates
        .into_iter()
        // The distance is at least the difference in length: skip the far.
        .filter(|c| c.chars().count().abs_diff(len) <= 2.max(c.len() / 3))
        .map(|c| (distance(word, c), c))
        .filter(|(d, c)| *d <= 2.max(c.len() / 3) && *d < c.len())
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

/// "did you mean `x`?" for the closest of `candidates`, placed as `hint`
/// says; empty when nothing is close.
pub fn did_you_mean<'a>(
    word: &str,
    candidates: impl IntoIterator<Item = &'a str>,
    hint: Hint,
) -> String {
    suggest(word, candidates).map_or_else(String::new, |near| phrase(near, hint))
}

/// "did you mean `near`?", placed as `hint` says.
pub fn phrase(near: &str, hint: Hint) -> String {
    match hint {
        Hint::Before => format!("did you mean `{near}`? "),
        Hint::After => format!("; did you mean `{near}`?"),
        Hint::Table => format!("did you mean `[{near}]`? "),
    }
}

/// Where a hint stands in its message.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hint {
    /// Before what is expected: "unknown key `x`; did you mean `y`? expected ...".
    Before,
    /// At the end: "... (got `x`); did you mean `y`?".
    After,
    /// A TOML table, before what is expected: "did you mean `[y]`? ".
    Table,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggestions_are_only_for_near_misses() {
        assert_eq!(suggest("fmn", ["fmin", "fmax"]), Some("fmin"));
        assert_eq!(suggest("speed", ["fmin", "fmax"]), None);
        assert_eq!(
            did_you_mean("fmn", ["fmin"], Hint::After),
            "; did you mean `fmin`?"
        );
        assert_eq!(
            did_you_mean("profile", ["profiles"], Hint::Table),
            "did you mean `[profiles]`? "
        );
        assert_eq!(did_you_mean("speed", ["fmin"], Hint::Before), "");
    }

    #[test]
    fn a_word_in_the_wrong_case_is_the_word() {
        // `Hz` is as near to `KHz` by edits as `kHz` is.
        assert_eq!(suggest("KHz", ["Hz", "kHz", "MHz"]), Some("kHz"));
        assert_eq!(suggest("mhz", ["Hz", "kHz", "MHz"]), Some("MHz"));
        assert_eq!(suggest("FMAX", ["fmin", "fmax"]), Some("fmax"));
    }
}
