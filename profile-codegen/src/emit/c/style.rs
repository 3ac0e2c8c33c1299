//! What a user places around the C arrays, checked before it is pasted
//! into their declarations: words that qualify the element type before it,
//! attributes after the array's name, nothing that ends the declaration,
//! opens a comment or a block, or reaches the preprocessor.

use core::fmt;
use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

/// How the C is written: text placed around every array, so that it lands
/// in the memory the target reads constants from, and the header's name.
///
/// Both are written as given, in the declarations and the definitions,
/// once [`check`](Self::check) accepts them. The players' pointers carry
/// the storage words too; with `PROGMEM` in the attribute the header
/// includes `<avr/pgmspace.h>` and the players read with `pgm_read_word`
/// (`pgm_read_dword` for `uint32_t` periods).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct CStyle {
    /// Words before the element type that qualify it: `__code` (SDCC, 8051
    /// code memory), `__flash` (AVR GCC's named address space), `__far`.
    pub storage: Option<String>,
    /// After the array's name: `PROGMEM` (avr-libc), or
    /// `__attribute__((section(".ramps")))` for a linker section.
    pub attribute: Option<String>,
    /// The header's name in C, a C identifier: its include guard
    /// (`STEPPER_PROFILES_<PREFIX>_H`), its players (`<prefix>_runs_t`,
    /// `<prefix>_runs_start`, ...) and their macros. Without it, the name
    /// of the file the header is written to (`x_axis` for `x_axis.h`).
    pub prefix: Option<String>,
}

/// A [`CStyle`] text that would not make a declaration: which one, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CStyleError {
    /// The field at fault, `storage`, `attribute` or `prefix` (the command
    /// line's `--storage`, `--attribute` and `--prefix`).
    pub field: &'static str,
    /// What is wrong and what is expected, to follow the field's name.
    pub problem: String,
}

impl fmt::Display for CStyleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}` {}", self.field, self.problem)
    }
}

impl std::error::Error for CStyleError {}

impl CStyle {
    /// Checks that each text is what a declaration holds there. The
    /// storage: words that qualify the element type (any identifier but a C
    /// keyword, `volatile` aside). The attribute: words, each optionally
    /// followed by parentheses (`__attribute__((...))`, `__ALIGNED(4)`),
    /// balanced, holding only words, numbers, strings and commas.
    /// Everything else is refused: `;`, `=`, braces, comments, `#`, `\`,
    /// line breaks, and `const` or `static`, which the header writes itself.
    /// The prefix: a C identifier that starts with a letter.
    pub fn check(&self) -> Result<(), CStyleError> {
        if let Some(text) = &self.storage {
            storage(text).map_err(|problem| CStyleError {
                field: "storage",
                problem,
            })?;
        }
        if let Some(text) = &self.attribute {
            attribute(text).map_err(|problem| CStyleError {
                field: "attribute",
                problem,
            })?;
        }
        if let Some(text) = &self.prefix {
            prefix(text).map_err(|problem| CStyleError {
                field: "prefix",
                problem,
            })?;
        }
        Ok(())
    }
}

const STORAGE: &str = "give words that qualify the element type, such as `__code` or `__flash`";
const ATTRIBUTE: &str =
    "give words such as `PROGMEM`, or `__attribute__((...))` with balanced parentheses";

/// Storage classes: the header writes its own.
const STORAGE_CLASSES: &[&str] = &[
    "static",
    "extern",
    "auto",
    "register",
    "typedef",
    "_Thread_local",
    "thread_local",
    "constexpr",
];

/// Words of a type: the element type is the table's word.
const TYPES: &[&str] = &[
    "void",
    "char",
    "short",
    "int",
    "long",
    "float",
    "double",
    "signed",
    "unsigned",
    "_Bool",
    "bool",
    "_Complex",
    "_Imaginary",
    "_BitInt",
    "struct",
    "union",
    "enum",
];

/// C's other keywords, C89 to C23.
const KEYWORDS: &[&str] = &[
    "const",
    "volatile",
    "restrict",
    "_Atomic",
    "inline",
    "_Noreturn",
    "_Alignas",
    "alignas",
    "_Alignof",
    "alignof",
    "_Generic",
    "_Static_assert",
    "static_assert",
    "sizeof",
    "typeof",
    "typeof_unqual",
    "break",
    "case",
    "continue",
    "default",
    "do",
    "else",
    "for",
    "goto",
    "if",
    "return",
    "switch",
    "while",
    "true",
    "false",
    "nullptr",
    "_Decimal32",
    "_Decimal64",
    "_Decimal128",
];

fn is_keyword(word: &str) -> bool {
    [STORAGE_CLASSES, TYPES, KEYWORDS]
        .iter()
        .any(|list| list.contains(&word))
}

/// A piece of the text, at its byte offset.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Token<'a> {
    Word(&'a str),
    Open,
    Close,
    Comma,
    /// A number or a string.
    Literal,
}

fn is_word_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// The tokens of `text`, or the offset of the first character that is none.
/// Spaces and tabs separate them; a string holds printable ASCII but `"` and
/// `\`.
fn tokens(text: &str) -> Result<Vec<(usize, Token<'_>)>, usize> {
    let mut out = Vec::new();
    let mut chars = text.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        let token = match c {
            ' ' | '\t' => continue,
            '(' => Token::Open,
            ')' => Token::Close,
            ',' => Token::Comma,
            '"' => loop {
                match chars.next() {
                    Some((_, '"')) => break Token::Literal,
                    Some((_, c)) if c.is_ascii() && !c.is_ascii_control() && c != '\\' => {}
                    Some((j, _)) => return Err(j),
                    None => return Err(i),
                }
            },
            c if is_word_char(c) => {
                let mut end = i + c.len_utf8();
                while let Some(&(j, c)) = chars.peek() {
                    if !is_word_char(c) {
                        break;
                    }
                    end = j + c.len_utf8();
                    chars.next();
                }
                let word = &text[i..end];
                if c.is_ascii_digit() {
                    Token::Literal
                } else {
                    Token::Word(word)
                }
            }
            _ => return Err(i),
        };
        out.push((i, token));
    }
    Ok(out)
}

/// `text` as a message shows it: control characters escaped.
fn shown(text: &str) -> String {
    text.chars()
        .map(|c| {
            if c.is_control() {
                c.escape_debug().to_string()
            } else {
                c.to_string()
            }
        })
        .collect()
}

/// "cannot hold" the text from `at` to the next space, and what is expected.
fn cannot_hold(text: &str, at: usize, expected: &str) -> String {
    let rest = &text[at..];
    let piece = rest.split([' ', '\t']).next().unwrap_or(rest);
    format!(
        "cannot hold `{}`: {expected}{}",
        shown(piece),
        got(text, piece)
    )
}

/// ` (got `text`)`, unless the text is the piece a message quotes already.
fn got(text: &str, piece: &str) -> String {
    if text.trim() == piece {
        String::new()
    } else {
        format!(" (got `{}`)", shown(text))
    }
}

fn storage(text: &str) -> Result<(), String> {
    if text.trim().is_empty() {
        return Err(
            "is blank: give a word that qualifies the element type, such as `__code` or `__flash`"
                .to_string(),
        );
    }
    for (at, token) in tokens(text).map_err(|at| cannot_hold(text, at, STORAGE))? {
        let Token::Word(word) = token else {
            return Err(cannot_hold(text, at, STORAGE));
        };
        let why = match word {
            "volatile" => continue,
            "const" => "the tables are `const` already; ".to_string() + STORAGE,
            "__attribute__" => "an attribute goes after the array's name; ".to_string() + STORAGE,
            w if STORAGE_CLASSES.contains(&w) => "the header gives the tables their storage \
                 class (`static const` in one header, `extern const` in a split one)"
                .to_string(),
            w if TYPES.contains(&w) => {
                "the element type is the table's word (`uint16_t` or `uint32_t`)".to_string()
            }
            w if KEYWORDS.contains(&w) => {
                "a C keyword that does not qualify the element type; ".to_string() + STORAGE
            }
            _ => continue,
        };
        return Err(format!("cannot hold `{word}`: {why}"));
    }
    Ok(())
}

fn attribute(text: &str) -> Result<(), String> {
    if text.trim().is_empty() {
        return Err(
            "is blank: give a word such as `PROGMEM`, or `__attribute__((...))`".to_string(),
        );
    }
    let unbalanced = || {
        format!(
            "has unbalanced parentheses: {ATTRIBUTE} (got `{}`)",
            shown(text)
        )
    };
    let (mut depth, mut after_word) = (0u32, false);
    for (at, token) in tokens(text).map_err(|at| cannot_hold(text, at, ATTRIBUTE))? {
        match token {
            Token::Word(word) if depth == 0 && is_keyword(word) => {
                return Err(format!(
                    "cannot hold `{word}`: a C keyword cannot follow the array's name; {ATTRIBUTE}"
                ));
            }
            Token::Word(_) => {}
            Token::Open if depth == 0 && !after_word => {
                return Err(cannot_hold(text, at, ATTRIBUTE));
            }
            Token::Open => depth += 1,
            Token::Close if depth == 0 => return Err(unbalanced()),
            Token::Close => depth -= 1,
            Token::Comma | Token::Literal if depth == 0 => {
                return Err(cannot_hold(text, at, ATTRIBUTE));
            }
            Token::Comma | Token::Literal => {}
        }
        after_word = matches!(token, Token::Word(_));
    }
    if depth != 0 {
        return Err(unbalanced());
    }
    Ok(())
}

fn prefix(text: &str) -> Result<(), String> {
    if text.trim().is_empty() {
        return Err("is blank: give a C identifier such as `x_axis`".to_string());
    }
    let mut chars = text.chars();
    let starts = chars.next().is_some_and(|c| c.is_ascii_alphabetic());
    if starts && chars.all(is_word_char) {
        return Ok(());
    }
    Err(format!(
        "must be a C identifier, a letter, then letters, digits or `_`, such as `x_axis` \
         (got `{}`)",
        shown(text)
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_parentheses_and_strings() {
        assert_eq!(
            tokens("a (\"x\", 4)"),
            Ok(std::vec![
                (0, Token::Word("a")),
                (2, Token::Open),
                (3, Token::Literal),
                (6, Token::Comma),
                (8, Token::Literal),
                (9, Token::Close),
            ])
        );
        assert_eq!(tokens("a\"b"), Err(1));
        assert_eq!(tokens("\"a\\b\""), Err(2));
        assert_eq!(tokens("é"), Err(0));
    }

    #[test]
    fn keywords_are_words_of_c() {
        assert!(is_keyword("const") && is_keyword("static") && is_keyword("int"));
        assert!(!is_keyword("__code") && !is_keyword("PROGMEM"));
    }
}
