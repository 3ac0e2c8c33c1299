//! `profiles.toml`: profiles declared in a file, for build scripts and the
//! `include_profiles!` macro.
//!
//! ```toml
//! [defaults]            # optional: any key, applied where a profile omits it
//! timer_hz = 10_000_000
//!
//! [profiles.orange]     # one table per profile; the name becomes a module
//! curve = "sigmoid"
//! len = 1000
//! fmin = 500
//! fmax = 64000
//! flexible = 8
//! ```
//!
//! A profile takes exactly the keys of `period_table!`; names (`curve`,
//! `rounding`, ...) are strings. A default that does not apply to a
//! profile's curve (`flexible` for a linear ramp) is ignored for it.
//!
//! In a build script:
//!
//! ```no_run
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! let out_dir = std::env::var("OUT_DIR")?;
//! profile_core::build::Profiles::load("profiles.toml")?.write_rust(&out_dir)?;
//! # Ok(()) }
//! ```
//!
//! and in the crate: `include!(concat!(env!("OUT_DIR"), "/profiles.rs"));`.
//! Every mistake in the file is reported as `profiles.toml:LINE:COL: message`
//! with the line and a caret under the offending text.

use std::collections::BTreeMap;
use std::fmt;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::string::{String, ToString};
use std::vec::Vec;
use std::{format, println};

use serde::Deserialize;
use toml::Spanned;

use crate::emit::{self, Generated, Profile};
use crate::error::Key;
use crate::params::{self, Arg, Diagnostic, Layout, Value};

type Table = BTreeMap<Spanned<String>, Spanned<toml::Value>>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    defaults: Option<Table>,
    motors: Option<BTreeMap<Spanned<String>, Spanned<Table>>>,
    profiles: Option<Spanned<BTreeMap<Spanned<String>, Spanned<Table>>>>,
}

/// Problems with a profiles file, each at its `file:line:col`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LoadError {
    text: String,
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
fn render(file: &str, source: &str, diagnostics: &[Diagnostic<Range<usize>>]) -> LoadError {
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
            text.push_str(&format!(
                "{pad} |\n{number} | {src_line}\n{pad} | {}{}\n",
                " ".repeat(col - 1),
                "^".repeat(width)
            ));
        }
    }
    LoadError { text }
}

const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut",
    "pub", "ref", "return", "self", "static", "struct", "super", "trait", "true", "try", "type",
    "unsafe", "use", "where", "while", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "typeof", "unsized", "virtual", "yield",
];

/// Why `name` cannot be a module name, if it cannot.
fn bad_name(name: &str) -> Option<String> {
    if name.is_empty() {
        return Some("a profile name must not be empty: it names a module".to_string());
    }
    // A leading `_` would make `_NAME_...` identifiers, reserved in C.
    let valid = name.chars().next().is_some_and(|c| c.is_ascii_lowercase())
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    if !valid {
        Some(format!(
            "profile name `{name}` must be a snake_case Rust identifier \
             (lowercase letters, digits and `_`, starting with a letter): it names a module"
        ))
    } else if name.starts_with('e') && name[1..].starts_with(|c: char| c.is_ascii_digit()) {
        Some(format!(
            "profile name `{name}` would make C names `{}_...`, which C reserves for error codes \
             (`E` followed by a digit): start it otherwise",
            name.to_uppercase()
        ))
    } else if KEYWORDS.contains(&name) {
        Some(format!(
            "profile name `{name}` is a Rust keyword and cannot name a module"
        ))
    } else {
        None
    }
}

/// A TOML value as an argument value; kinds no key takes are described, so
/// the schema can say what the key expects instead.
fn value(v: &Spanned<toml::Value>) -> Value {
    match v.get_ref() {
        toml::Value::Integer(i) => Value::Int(*i as i128),
        toml::Value::Float(f) => Value::Float(*f),
        toml::Value::String(s) => Value::Name(s.clone()),
        toml::Value::Boolean(_) => Value::Other("a boolean".into()),
        toml::Value::Datetime(_) => Value::Other("a date".into()),
        toml::Value::Array(items) => {
            points(items).map_or_else(|| Value::Other("an array".into()), Value::Points)
        }
        toml::Value::Table(_) => Value::Other("a table".into()),
    }
}

/// `[[x, y], ...]` as number pairs, if that is what the array holds.
fn points(items: &[toml::Value]) -> Option<Vec<(f64, f64)>> {
    let number = |v: &toml::Value| match v {
        toml::Value::Integer(i) => Some(*i as f64),
        toml::Value::Float(f) => Some(*f),
        _ => None,
    };
    items
        .iter()
        .map(|item| match item.as_array().map(|a| a.as_slice()) {
            Some([x, y]) => Some((number(x)?, number(y)?)),
            _ => None,
        })
        .collect()
}

fn arg(key: &Spanned<String>, v: &Spanned<toml::Value>) -> Arg<Range<usize>> {
    Arg {
        key: key.get_ref().clone(),
        key_loc: key.span(),
        value: value(v),
        value_loc: v.span(),
    }
}

/// The TOML parser's message in this project's words.
fn toml_message(message: &str, source: &str, span: &Range<usize>) -> String {
    let text = source.get(span.clone()).unwrap_or("").trim();
    if message == "duplicate key" && !text.is_empty() {
        return format!(
            "duplicate key `{}`",
            text.trim_matches(|c| c == '[' || c == ']')
        );
    }
    if let Some(rest) = message.strip_prefix("unknown field `") {
        let field = rest.split('`').next().unwrap_or("");
        let hint = params::suggest(field, ["defaults", "motors", "profiles"])
            .map(|s| format!("did you mean `[{s}]`? "))
            .unwrap_or_default();
        return format!(
            "unknown table `{field}`; {hint}expected `[defaults]`, `[motors.NAME]` or \
             `[profiles.NAME]` tables"
        );
    }
    // A number too large for the parser: name the key it is the value of.
    if message.contains("overflowed") || message.contains(" as i128") {
        let line_start = source
            .get(..span.start)
            .and_then(|s| s.rfind('\n'))
            .map_or(0, |i| i + 1);
        let key = source
            .get(line_start..span.start)
            .unwrap_or("")
            .trim_end()
            .trim_end_matches('=')
            .trim();
        return if message.contains("overflowed") {
            format!("`{key}` is too large for a 64-bit float (at most about 1.8e308)")
        } else {
            format!(
                "`{key}` is too large for a TOML integer (at most {})",
                i64::MAX
            )
        };
    }
    if message.contains("expected a map") {
        return format!(
            "`{text}` must be a table: `[profiles.NAME]` or `[defaults]` followed by `key = value` lines"
        );
    }
    message.to_string()
}

fn sorted(table: &Table) -> Vec<(&Spanned<String>, &Spanned<toml::Value>)> {
    let mut entries: Vec<_> = table.iter().collect();
    entries.sort_by_key(|(k, _)| k.span().start);
    entries
}

/// The most entries (steps, summed over every profile) one profiles file may
/// generate: four tables of [`MAX_LEN`](crate::MAX_LEN), 512 KiB of `u16`
/// flash. It bounds the work and memory of one `include_profiles!` or build
/// script; a file above it is refused before its tables are computed.
pub const MAX_FILE_ENTRIES: u32 = 4 * crate::MAX_LEN;

/// The most motor names an "unknown motor" message lists.
const LISTED_MOTORS: usize = 8;

/// "unknown motor": the declared names (a few, in order), and the nearest.
fn unknown_motor(value: &Value, declared: &[&str]) -> String {
    let hint = match value {
        Value::Name(n) => params::suggest(n, declared.iter().copied())
            .map(|s| format!("did you mean `{s}`? "))
            .unwrap_or_default(),
        _ => String::new(),
    };
    let list = match declared.len() {
        0 => "the file declares no `[motors.NAME]` table".to_string(),
        n if n <= LISTED_MOTORS => {
            format!(
                "the file declares {}",
                params::quoted(declared.iter().copied())
            )
        }
        n => format!(
            "the file declares {} and {} more",
            params::quoted(declared[..LISTED_MOTORS].iter().copied()),
            n - LISTED_MOTORS
        ),
    };
    format!("unknown motor {}; {hint}{list}", value.quoted())
}

/// The profiles of one file, checked and computed.
#[derive(Clone, Debug, PartialEq)]
pub struct Profiles {
    file: String,
    path: Option<PathBuf>,
    profiles: Vec<Profile>,
}

impl Profiles {
    /// Reads, checks and computes every profile of the file at `path`.
    pub fn load(path: impl AsRef<Path>) -> Result<Self, LoadError> {
        let path = path.as_ref();
        let source = std::fs::read_to_string(path).map_err(|e| LoadError {
            text: format!("cannot read `{}`: {e}", path.display()),
        })?;
        let mut profiles = Self::parse(&path.display().to_string(), &source)?;
        profiles.path = Some(path.to_path_buf());
        Ok(profiles)
    }

    /// Checks and computes the profiles in `source`; `file` names it in messages.
    pub fn parse(file: &str, source: &str) -> Result<Self, LoadError> {
        let parsed: File = toml::from_str(source).map_err(|e| {
            let loc = e.span().unwrap_or(0..0);
            let message = toml_message(e.message(), source, &loc);
            render(file, source, &[Diagnostic { loc, message }])
        })?;
        let mut diagnostics = Vec::new();

        let mut defaults = Vec::new();
        // Keys a misspelt default was probably meant to be: not missing too.
        let mut meant = Vec::new();
        for (key, v) in parsed.defaults.as_ref().map(sorted).unwrap_or_default() {
            if Key::from_name(key.get_ref()).is_none() {
                let names = Key::ALL.iter().map(|k| k.name());
                let near = params::suggest(key.get_ref(), names.clone());
                meant.extend(near.and_then(Key::from_name));
                let hint = near
                    .map(|s| format!("did you mean `{s}`? "))
                    .unwrap_or_default();
                let list: Vec<String> =
                    params::listed(Key::ALL).map(|n| format!("`{n}`")).collect();
                diagnostics.push(Diagnostic {
                    loc: key.span(),
                    message: format!(
                        "unknown key `{}` in `[defaults]`; {hint}expected one of {}, or a motor's keys",
                        key.get_ref(),
                        list.join(", ")
                    ),
                });
                continue;
            }
            defaults.push(arg(key, v));
        }

        let Some(profiles_table) = parsed.profiles else {
            diagnostics.push(Diagnostic {
                loc: 0..0,
                message: "no profiles: declare at least one `[profiles.NAME]` table".to_string(),
            });
            return Err(render(file, source, &diagnostics));
        };
        let mut names: Vec<_> = profiles_table.get_ref().iter().collect();
        names.sort_by_key(|(k, _)| k.span().start);
        if names.is_empty() {
            diagnostics.push(Diagnostic {
                loc: profiles_table.span(),
                message: "no profiles: declare at least one `[profiles.NAME]` table".to_string(),
            });
        }

        // A motor table holds a motor's keys only; checked once per motor.
        let motors: Vec<_> = parsed.motors.iter().flatten().collect();
        for (_, table) in &motors {
            for (key, _) in sorted(table.get_ref()) {
                if Key::from_name(key.get_ref()).is_some_and(|k| Key::MOTOR.contains(&k)) {
                    continue;
                }
                let motor_keys = Key::MOTOR.iter().map(|k| k.name());
                let hint = params::suggest(key.get_ref(), motor_keys.clone())
                    .map(|s| format!("did you mean `{s}`? "))
                    .unwrap_or_default();
                diagnostics.push(Diagnostic {
                    loc: key.span(),
                    message: format!(
                        "`{}` is not a motor key; {hint}a `[motors.NAME]` table takes {} \
                         (a profile's keys go in `[profiles.NAME]` or `[defaults]`)",
                        key.get_ref(),
                        params::quoted(motor_keys)
                    ),
                });
            }
        }
        let mut motor_names: Vec<&str> = motors.iter().map(|(k, _)| k.get_ref().as_str()).collect();
        motor_names.sort_unstable();

        let mut profiles = Vec::new();
        // Profiles whose arguments are right, and the entries they ask for.
        let mut checked = Vec::new();
        let mut entries: u64 = 0;
        for (name, table) in names {
            if let Some(message) = bad_name(name.get_ref()) {
                diagnostics.push(Diagnostic {
                    loc: name.span(),
                    message,
                });
                continue;
            }
            let mut args: Vec<_> = sorted(table.get_ref())
                .into_iter()
                .map(|(key, v)| arg(key, v))
                .collect();
            let long = args.iter().find_map(|a| {
                let digits = source
                    .get(a.value_loc.clone())?
                    .chars()
                    .filter(char::is_ascii_digit)
                    .count();
                let number = matches!(a.value, Value::Int(_) | Value::Float(_));
                (number && digits > params::MAX_DIGITS).then(|| Diagnostic {
                    loc: a.value_loc.clone(),
                    message: params::too_many_digits(&a.key, digits),
                })
            });
            if let Some(d) = long {
                diagnostics.push(d);
                continue;
            }
            // The motor the profile names, itself or through `[defaults]`:
            // its keys fill what the profile omits.
            let named = args
                .iter()
                .chain(&defaults)
                .find(|a| a.key == Key::Motor.name())
                .cloned();
            if let Some(m) = &named {
                let found = match &m.value {
                    Value::Name(n) => motors.iter().find(|(k, _)| k.get_ref() == n),
                    _ => None,
                };
                match found {
                    Some((_, table)) => {
                        for (key, v) in sorted(table.get_ref()) {
                            let motor_key = Key::from_name(key.get_ref())
                                .is_some_and(|k| Key::MOTOR.contains(&k));
                            if motor_key && !args.iter().any(|a| &a.key == key.get_ref()) {
                                args.push(arg(key, v));
                            }
                        }
                    }
                    None => {
                        diagnostics.push(Diagnostic {
                            loc: m.value_loc.clone(),
                            message: unknown_motor(&m.value, &motor_names),
                        });
                        continue;
                    }
                }
            }
            // Defaults fill what the profile omits, where its curve takes
            // them; a motor's keys only where the profile has a motor.
            let curve = args
                .iter()
                .chain(&defaults)
                .find(|a| a.key == "curve")
                .and_then(|a| match &a.value {
                    Value::Name(n) if params::CURVES.contains(&n.as_str()) => Some(n.clone()),
                    _ => None,
                });
            let has_motor = named.is_some()
                || args
                    .iter()
                    .any(|a| Key::from_name(&a.key).is_some_and(|k| Key::MOTOR.contains(&k)));
            for d in &defaults {
                let key = Key::from_name(&d.key);
                let applies = if key.is_some_and(|k| Key::MOTOR.contains(&k)) {
                    has_motor
                } else {
                    match &curve {
                        Some(c) => params::keys_for(c).iter().any(|k| k.name() == d.key),
                        None => true,
                    }
                };
                if applies && !args.iter().any(|a| a.key == d.key) {
                    args.push(d.clone());
                }
            }
            let whole = name.span();
            match params::spec_from_args_assuming(&args, &whole, &meant) {
                Ok(p) => {
                    entries += p.spec.len() as u64;
                    checked.push((name, args, p));
                }
                Err(mut d) => diagnostics.append(&mut d),
            }
        }
        // The file's total, checked before any table is computed.
        if entries > MAX_FILE_ENTRIES as u64 {
            let mut sum = 0u64;
            let over = checked.iter().find(|(_, _, p)| {
                sum += p.spec.len() as u64;
                sum > MAX_FILE_ENTRIES as u64
            });
            if let Some((name, _, _)) = over {
                diagnostics.push(Diagnostic {
                    loc: name.span(),
                    message: format!(
                        "profile `{}` brings the file to {sum} entries, more than the \
                         {MAX_FILE_ENTRIES} one file may hold; split the profiles over several files",
                        name.get_ref()
                    ),
                });
            }
            checked.clear();
        }
        for (name, args, parsed) in checked {
            let whole = name.span();
            let spec = parsed.spec;
            let table = match parsed.layout {
                Layout::Steps => spec.table().map(Generated::Steps),
                Layout::Segments(n) => spec.segment_table(n).map(Generated::Segments),
            };
            let table = match table {
                Ok(table) => table,
                Err(e) => {
                    diagnostics.push(params::locate(&e, &args, &whole));
                    continue;
                }
            };
            let torque = match &parsed.motor {
                None => None,
                Some(motor) => match motor.check(&spec, &table.step_periods()) {
                    Ok(figures) => Some(figures),
                    Err(e) => {
                        let mut d = params::locate_motor(&e, &args, &whole);
                        d.message = format!("profile `{}`: {}", name.get_ref(), d.message);
                        diagnostics.push(d);
                        continue;
                    }
                },
            };
            profiles.push(Profile {
                name: name.get_ref().clone(),
                table,
                torque,
                motor: parsed.motor,
            });
        }
        if !diagnostics.is_empty() {
            // In source order, and once: a mistake in `[defaults]` reaches
            // every profile that uses it.
            diagnostics.sort_by_key(|d| (d.loc.start, d.loc.end));
            diagnostics.dedup();
            return Err(render(file, source, &diagnostics));
        }
        Ok(Profiles {
            file: file.to_string(),
            path: None,
            profiles,
        })
    }

    /// The profiles, in file order.
    pub fn profiles(&self) -> &[Profile] {
        &self.profiles
    }

    /// The file's name as used in messages.
    pub fn file(&self) -> &str {
        &self.file
    }

    /// Rust source with one module per profile (what `include_profiles!` expands to).
    pub fn rust_source(&self) -> String {
        emit::rust_modules(&self.profiles)
    }

    /// A C99 header with every profile's table and figures.
    pub fn c_header(&self) -> String {
        let stem = Path::new(&self.file)
            .file_stem()
            .map_or("profiles".into(), |s| s.to_string_lossy().into_owned());
        let guard: String = stem
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() {
                    c.to_ascii_uppercase()
                } else {
                    '_'
                }
            })
            .collect();
        let source = Path::new(&self.file)
            .file_name()
            .map_or(self.file.clone(), |s| s.to_string_lossy().into_owned());
        emit::c_header(
            &format!("STEPPER_PROFILES_{guard}_H"),
            &source,
            &self.profiles,
        )
    }

    /// Writes `profiles.rs` into `out_dir` (to `include!`) and, for a file
    /// read with [`Profiles::load`], prints `cargo::rerun-if-changed` for it.
    pub fn write_rust(&self, out_dir: impl AsRef<Path>) -> Result<PathBuf, LoadError> {
        let target = out_dir.as_ref().join("profiles.rs");
        write(&target, &self.rust_source())?;
        if let Some(path) = &self.path {
            println!("cargo::rerun-if-changed={}", path.display());
        }
        Ok(target)
    }

    /// Writes the C header to `path`.
    pub fn write_c_header(&self, path: impl AsRef<Path>) -> Result<(), LoadError> {
        write(path.as_ref(), &self.c_header())
    }
}

fn write(path: &Path, contents: &str) -> Result<(), LoadError> {
    std::fs::write(path, contents).map_err(|e| LoadError {
        text: format!("cannot write `{}`: {e}", path.display()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn names_must_be_module_names() {
        assert!(bad_name("orange").is_none());
        assert!(bad_name("seed_004_exact").is_none());
        assert!(bad_name("Orange").is_some());
        assert!(bad_name("4th").is_some());
        assert!(bad_name("my profile").is_some());
        assert!(bad_name("type").is_some());
        assert!(bad_name("_hidden").is_some());
        assert!(bad_name("").is_some());
        assert!(bad_name("e1").is_some());
        assert!(bad_name("e2_fast").is_some());
        assert!(bad_name("exponential").is_none());
        assert!(bad_name("e").is_none());
    }
}
