//! The one emitter: Rust source for a table, used by the macro and build scripts.

use core::fmt::Write;
use std::string::String;

use crate::spec::Word;

/// Rust source of an array expression holding `periods` as `word`s:
/// `[19183u16, 18866, ...]`. Only the first literal carries the suffix;
/// the array's type follows from it.
pub fn rust_array(word: Word, periods: &[u32]) -> String {
    let mut out = String::with_capacity(periods.len() * 7 + 2);
    out.push('[');
    for (i, p) in periods.iter().enumerate() {
        if i == 0 {
            let _ = write!(out, "{p}{}", word.name());
        } else {
            let _ = write!(out, ", {p}");
        }
    }
    out.push(']');
    out
}

/// Rust source of an array of `(period, count)` pairs, as `word`s:
/// `[(9533u16, 3u16), (4750, 9), ...]`.
pub fn rust_pairs(word: Word, pairs: &[(u32, u32)]) -> String {
    let mut out = String::with_capacity(pairs.len() * 14 + 2);
    out.push('[');
    for (i, (period, count)) in pairs.iter().enumerate() {
        if i == 0 {
            let w = word.name();
            let _ = write!(out, "({period}{w}, {count}{w})");
        } else {
            let _ = write!(out, ", ({period}, {count})");
        }
    }
    out.push(']');
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_literal_is_suffixed() {
        assert_eq!(rust_array(Word::U16, &[3, 2, 1]), "[3u16, 2, 1]");
        assert_eq!(rust_array(Word::U32, &[70000]), "[70000u32]");
        assert_eq!(
            rust_pairs(Word::U16, &[(9, 3), (4, 9)]),
            "[(9u16, 3u16), (4, 9)]"
        );
    }
}
