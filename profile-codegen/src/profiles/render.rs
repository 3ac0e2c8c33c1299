//! Diagnostics in a file: `file:line:col: message`, the line and a caret.

use std::fmt;
use std::format;
use std::ops::Range;
use std::string::{String, ToString};
use std::vec::Vec;

use crate::schema::Diagnostic;

/// Problems with a profiles file, each at its `file:line:col`.
///
/// Its `Debug` form is its text, so that `fn main() -> Result<(), Box<dyn
/// Error>>` prints the lines and carets as they are.
#[derive(Clone, PartialEq, Eq)]
pub struct LoadError {
    pub(crate) text: String,
}

impl LoadError {
    /// Every problem, rendered with its location, source line and caret.
    pub fn message(&self) -> &str {
        &self.text
    }
}

impl fmt::Display for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

impl fmt::Debug for LoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

impl std::error::Error for LoadError {}

/// Where each line of a source starts, for locating many diagnostics in
/// one pass over the text.
struct Lines<'a> {
    source: &'a str,
    starts: Vec<usize>,
}

impl<'a> Lines<'a> {
    fn new(source: &'a str) -> Self {
        let starts = std::iter::once(0)
            .chain(source.match_indices('\n').map(|(i, _)| i + 1))
            .collect();
        Lines { source, starts }
    }

    /// 1-based line and column (in characters) of byte `offset`.
    fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.source.len());
        let line = self.starts.partition_point(|&s| s <= offset);
        let start = self.starts[line - 1];
        let col = self
            .source
            .get(start..offset)
            .map_or(0, |s| s.chars().count())
            + 1;
        (line, col)
    }

    /// Line `line` (1-based), without its end.
    fn line(&self, line: usize) -> Option<&'a str> {
        let start = *self.starts.get(line - 1)?;
        if start >= self.source.len() {
            return None;
        }
        let end = self.starts.get(line).map_or(self.source.len(), |&e| e - 1);
        self.source
            .get(start..end)
            .map(|l| l.trim_end_matches('\r'))
    }
}

/// Renders diagnostics as `file:line:col: message`, the line, and a caret:
/// in time linear in the source and the diagnostics.
pub(crate) fn render(
    file: &str,
    source: &str,
    diagnostics: &[Diagnostic<Range<usize>>],
) -> LoadError {
    let lines = Lines::new(source);
    let mut text = String::new();
    for (i, d) in diagnostics.iter().enumerate() {
        if i > 0 {
            text.push('\n');
        }
        let (line, col) = lines.line_col(d.loc.start);
        text.push_str(&format!("{file}:{line}:{col}: {}\n", d.message));
        if let Some(src_line) = lines.line(line) {
            let number = line.to_string();
            let pad = " ".repeat(number.len());
            let width = source
                .get(d.loc.clone())
                .map_or(1, |s| s.lines().next().unwrap_or("").chars().count().max(1));
            let width = width.min(src_line.chars().count().saturating_sub(col - 1).max(1));
            // Under the line's own tabs a tab, so that the caret stays
            // under its token however wide a tab is shown.
            let under: String = src_line
                .chars()
                .take(col - 1)
                .map(|c| if c == '\t' { '\t' } else { ' ' })
                .collect();
            text.push_str(&format!(
                "{pad} |\n{number} | {src_line}\n{pad} | {under}{}\n",
                "^".repeat(width)
            ));
        }
    }
    LoadError { text }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_caret_keeps_the_lines_tabs() {
        let src = "[profiles.a]\n\t\tfmx = 64000\n";
        let start = src.find("fmx").unwrap();
        let d = Diagnostic {
            loc: start..start + 3,
            message: "unknown key".to_string(),
        };
        assert_eq!(
            render("p.toml", src, &[d]).text,
            "p.toml:2:3: unknown key\n  |\n2 | \t\tfmx = 64000\n  | \t\t^^^\n"
        );
    }

    #[test]
    fn line_and_column_count_characters() {
        let src = "a = 1\nbé = 2\n";
        let lines = Lines::new(src);
        assert_eq!(lines.line_col(0), (1, 1));
        assert_eq!(lines.line_col(6), (2, 1));
        assert_eq!(lines.line_col(src.find('=').unwrap()), (1, 3));
        assert_eq!(lines.line_col(src.rfind('2').unwrap()), (2, 6));
        assert_eq!(lines.line_col(src.len()), (3, 1));
        // As `str::lines`: no line after the final newline.
        assert_eq!(
            (lines.line(1), lines.line(2), lines.line(3)),
            (Some("a = 1"), Some("bé = 2"), None)
        );
    }
}
