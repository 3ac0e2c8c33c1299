//! A profiles file as arguments: the TOML read with locations, `[defaults]`
//! and `[motors.NAME]` merged into each profile, names checked.

use std::collections::BTreeMap;
use std::format;
use std::ops::Range;
use std::string::{String, ToString};
use std::vec::Vec;

use serde::Deserialize;
use toml::Spanned;

use crate::schema::curves::CurveSchema;
use crate::schema::units::{self, Quantity};
use crate::schema::{self, Arg, Diagnostic, Hint, Value, did_you_mean};
use profile_core::Key;

type Table = BTreeMap<Spanned<String>, Spanned<toml::Value>>;

/// A profile's key that names another profile of the file, its emergency
/// ramp: the file's, not `period_table!`'s.
pub(crate) const EMERGENCY: &str = "emergency";

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    defaults: Option<Table>,
    motors: Option<BTreeMap<Spanned<String>, Spanned<Table>>>,
    profiles: Option<Spanned<BTreeMap<Spanned<String>, Spanned<Table>>>>,
}

const KEYWORDS: &[&str] = &[
    "as", "async", "await", "break", "const", "continue", "crate", "dyn", "else", "enum", "extern",
    "false", "fn", "for", "gen", "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut",
    "pub", "ref", "return", "self", "static", "struct", "super", "trait", "true", "try", "type",
    "unsafe", "use", "where", "while", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "typeof", "unsized", "virtual", "yield",
];

/// Crates a firmware crate that includes the profiles has in scope: a
/// module named like one of them makes its paths ambiguous (E0659).
const CRATES: [&str; 6] = [
    "stepper_profiles",
    "profile_core",
    "profile_macros",
    "core",
    "std",
    "alloc",
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
    } else if CRATES.contains(&name) {
        Some(format!(
            "profile name `{name}` is the name of a crate: a module of that name beside it makes \
             every `{name}::` path ambiguous"
        ))
    } else {
        None
    }
}

/// A TOML value as an argument value; kinds no key takes are described, so
/// the schema can say what the key expects instead.
fn value(key: &str, v: &Spanned<toml::Value>) -> Value {
    match v.get_ref() {
        toml::Value::Integer(i) => Value::Int(*i as i128),
        toml::Value::Float(f) => Value::Float(*f),
        toml::Value::String(s) => Value::Name(s.clone()),
        toml::Value::Boolean(_) => Value::Other("a boolean".into()),
        toml::Value::Datetime(_) => Value::Other("a date".into()),
        toml::Value::Array(items) => match points(key, items) {
            Ok(Some(points)) => Value::Points(points),
            Ok(None) => Value::Other("an array".into()),
            Err((part, message)) => Value::Refused { message, part },
        },
        toml::Value::Table(_) => Value::Other("a table".into()),
    }
}

/// What is wrong with an array's element: its index and the message.
type AtElement = (usize, String);

/// `[[x, y], ...]` as number pairs, if that is what the array holds; a
/// frequency or a torque may be a string with a unit, `"1.5 kHz"`, `"40
/// N·cm"`, as `key` takes them ([`units::pair`]). A pair holding what is
/// not a number (`["fast", 0.3]`), or a unit it does not take, is an error
/// at its element.
fn points(key: &str, items: &[toml::Value]) -> Result<Option<Vec<(f64, f64)>>, AtElement> {
    let (qx, qy) = units::pair(key).unwrap_or((Quantity::Frequency, Quantity::Torque));
    let number = |v: &toml::Value, q: Quantity| match v {
        toml::Value::Integer(i) => Ok(*i as f64),
        toml::Value::Float(f) => Ok(*f),
        toml::Value::String(s) => match units::split(s) {
            Some((n, unit)) => units::curve_point(key, q, &n.replace('_', ""), unit, s.trim()),
            None => Err(units::not_a_point(key, q, &format!("`{s:?}`"))),
        },
        toml::Value::Boolean(b) => Err(units::not_a_point(key, q, &format!("`{b}`"))),
        toml::Value::Datetime(d) => Err(units::not_a_point(key, q, &format!("`{d}`"))),
        toml::Value::Array(_) => Err(units::not_a_point(key, q, "an array")),
        toml::Value::Table(_) => Err(units::not_a_point(key, q, "a table")),
    };
    let mut points = Vec::new();
    for (part, item) in items.iter().enumerate() {
        let Some([x, y]) = item.as_array().map(|a| a.as_slice()) else {
            return Ok(None);
        };
        let x = number(x, qx).map_err(|m| (part, m))?;
        let y = number(y, qy).map_err(|m| (part, m))?;
        points.push((x, y));
    }
    Ok(Some(points))
}

fn arg(source: &str, key: &Spanned<String>, v: &Spanned<toml::Value>) -> Arg<Range<usize>> {
    let value = value(key.get_ref(), v);
    // Each point's place, where the reading finds one for each.
    let count = match (&value, v.get_ref()) {
        (Value::Points(points), _) => points.len(),
        (Value::Refused { .. }, toml::Value::Array(items)) => items.len(),
        _ => 0,
    };
    let parts = Some(elements(source, v.span()))
        .filter(|parts| count > 0 && parts.len() == count)
        .unwrap_or_default();
    Arg {
        key: key.get_ref().clone(),
        key_loc: key.span(),
        value,
        value_loc: v.span(),
        parts,
    }
}

/// Where each `[...]` element of the array at `span` is in `source`, in
/// order: the array's text read bracket by bracket, past strings and
/// comments (the TOML parser gives spans to top-level values only).
fn elements(source: &str, span: Range<usize>) -> Vec<Range<usize>> {
    let Some(text) = source.get(span.clone()) else {
        return Vec::new();
    };
    let bytes = text.as_bytes();
    let (mut out, mut depth, mut start) = (Vec::new(), 0usize, 0usize);
    let mut i = 1; // past the array's own `[`
    while i < bytes.len() {
        match bytes[i] {
            b'#' => {
                while i < bytes.len() && bytes[i] != b'\n' {
                    i += 1;
                }
            }
            quote @ (b'"' | b'\'') => {
                i += 1;
                while i < bytes.len() && bytes[i] != quote {
                    // A basic string's escape skips the character it escapes.
                    i += if quote == b'"' && bytes[i] == b'\\' {
                        2
                    } else {
                        1
                    };
                }
            }
            b'[' | b'{' => {
                if depth == 0 {
                    start = i;
                }
                depth += 1;
            }
            b']' | b'}' if depth > 0 => {
                depth -= 1;
                if depth == 0 {
                    out.push(span.start + start..span.start + i + 1);
                }
            }
            b']' => break,
            _ => {}
        }
        i += 1;
    }
    out
}

/// The TOML parser's message in this project's words.
pub(crate) fn toml_message(message: &str, source: &str, span: &Range<usize>) -> String {
    let text = source.get(span.clone()).unwrap_or("").trim();
    if message == "duplicate key" && !text.is_empty() {
        return format!(
            "duplicate key `{}`",
            text.trim_matches(|c| c == '[' || c == ']')
        );
    }
    if let Some(rest) = message.strip_prefix("unknown field `") {
        let field = rest.split('`').next().unwrap_or("");
        let hint = did_you_mean(field, ["defaults", "motors", "profiles"], Hint::Table);
        return format!(
            "unknown table `{field}`; {hint}expected `[defaults]`, `[motors.NAME]` or \
             `[profiles.NAME]` tables"
        );
    }
    // `8 000`: digits split by spaces read as a bare string.
    let spaced = text.starts_with(|c: char| c.is_ascii_digit())
        && text.contains(' ')
        && text
            .chars()
            .all(|c| c.is_ascii_digit() || " _.".contains(c));
    if message.starts_with("string values must be quoted") && spaced {
        let joined: String = text.split_whitespace().collect::<Vec<_>>().join("_");
        return format!(
            "a number cannot contain spaces: write `{joined}` (or, with a unit, a string such \
             as `\"64 kHz\"`)"
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

/// The most motor names an "unknown motor" message lists.
const LISTED_MOTORS: usize = 8;

/// "unknown motor": the declared names (a few, in order), and the nearest.
fn unknown_motor(value: &Value, declared: &[&str]) -> String {
    let hint = match value {
        Value::Name(n) => did_you_mean(n, declared.iter().copied(), Hint::Before),
        _ => String::new(),
    };
    let list = match declared.len() {
        0 => "the file declares no `[motors.NAME]` table".to_string(),
        n if n <= LISTED_MOTORS => {
            format!(
                "the file declares {}",
                schema::quoted(declared.iter().copied())
            )
        }
        n => format!(
            "the file declares {} and {} more",
            schema::quoted(declared[..LISTED_MOTORS].iter().copied()),
            n - LISTED_MOTORS
        ),
    };
    format!("unknown motor {}; {hint}{list}", value.quoted())
}

/// One profile's arguments: its own keys, then its motor's, then the
/// defaults that apply to it.
pub(crate) struct ProfileArgs {
    /// The profile's name.
    pub(crate) name: String,
    /// Where the name is: where problems with the whole profile are shown.
    pub(crate) whole: Range<usize>,
    /// Its arguments.
    pub(crate) args: Vec<Arg<Range<usize>>>,
    /// Its `emergency`, the name of another profile, read by the file
    /// once every profile is computed.
    pub(crate) emergency: Option<Arg<Range<usize>>>,
}

/// A file read into profiles' arguments, and what is wrong with it so far.
pub(crate) struct FileArgs {
    pub(crate) profiles: Vec<ProfileArgs>,
    /// Keys a misspelt default or motor key was probably meant to be: not
    /// missing too.
    pub(crate) meant: Vec<Key>,
    pub(crate) diagnostics: Vec<Diagnostic<Range<usize>>>,
}

/// Reads `source` into each profile's arguments. A TOML syntax error is the
/// only problem reported alone.
pub(crate) fn read(source: &str) -> Result<FileArgs, Diagnostic<Range<usize>>> {
    let parsed: File = toml::from_str(source).map_err(|e| {
        let loc = e.span().unwrap_or(0..0);
        let message = toml_message(e.message(), source, &loc);
        Diagnostic { loc, message }
    })?;
    let mut file = FileArgs {
        profiles: Vec::new(),
        meant: Vec::new(),
        diagnostics: Vec::new(),
    };
    let defaults = defaults(source, parsed.defaults.as_ref(), &mut file);
    let motors: Vec<_> = parsed.motors.iter().flatten().collect();
    let motor_args = check_motors(source, &motors, &mut file);
    let mut declared: Vec<&str> = motors.iter().map(|(k, _)| k.get_ref().as_str()).collect();
    declared.sort_unstable();
    let Some(profiles) = parsed.profiles else {
        file.diagnostics.push(no_profiles(0..0));
        return Ok(file);
    };
    let mut names: Vec<_> = profiles.get_ref().iter().collect();
    names.sort_by_key(|(k, _)| k.span().start);
    if names.is_empty() {
        file.diagnostics.push(no_profiles(profiles.span()));
    }
    for (name, table) in names {
        if let Some(message) = bad_name(name.get_ref()) {
            file.diagnostics.push(Diagnostic {
                loc: name.span(),
                message,
            });
            continue;
        }
        match profile(source, table.get_ref(), &defaults, &motors, &declared) {
            Ok(mut args) => {
                let emergency = args.iter().position(|a| a.key == EMERGENCY);
                let emergency = emergency.map(|i| args.remove(i));
                file.profiles.push(ProfileArgs {
                    name: name.get_ref().clone(),
                    whole: name.span(),
                    args,
                    emergency,
                })
            }
            Err(d) => file.diagnostics.push(d),
        }
    }
    // A default or a motor's key no profile takes is still read: a mistake
    // in it is one.
    let taken: Vec<&Range<usize>> = file
        .profiles
        .iter()
        .flat_map(|p| p.args.iter().map(|a| &a.key_loc))
        .collect();
    let nowhere = usize::MAX..usize::MAX;
    for d in defaults.iter().chain(&motor_args) {
        if !taken.contains(&&d.key_loc) {
            file.diagnostics.extend(schema::value_problems(d, &nowhere));
        }
    }
    Ok(file)
}

fn no_profiles(loc: Range<usize>) -> Diagnostic<Range<usize>> {
    Diagnostic {
        loc,
        message: "no profiles: declare at least one `[profiles.NAME]` table".to_string(),
    }
}

/// The `[defaults]` table as arguments; an unknown key is reported, and the
/// key it probably meant is not reported missing.
fn defaults(source: &str, table: Option<&Table>, file: &mut FileArgs) -> Vec<Arg<Range<usize>>> {
    let mut defaults = Vec::new();
    for (key, v) in table.map(sorted).unwrap_or_default() {
        if crate::schema::keys::from_name(key.get_ref()).is_some() {
            defaults.push(arg(source, key, v));
            continue;
        }
        let all: Vec<Key> = crate::schema::keys::all().into_iter().collect();
        let names = all.iter().map(|k| k.name());
        file.meant.extend(
            schema::suggest(key.get_ref(), names.clone()).and_then(crate::schema::keys::from_name),
        );
        file.diagnostics.push(Diagnostic {
            loc: key.span(),
            message: format!(
                "unknown key `{}` in `[defaults]`; {}expected one of {}, or a motor's keys",
                key.get_ref(),
                did_you_mean(key.get_ref(), names, Hint::Before),
                schema::quoted(schema::listed(&all))
            ),
        });
    }
    defaults
}

/// A motor table holds a motor's keys only; checked once per motor.
/// The key a misspelt one probably meant goes to `file.meant`: not missing
/// too. Returns the motor keys as arguments, so that those no profile takes
/// are read too.
fn check_motors(
    source: &str,
    motors: &[(&Spanned<String>, &Spanned<Table>)],
    file: &mut FileArgs,
) -> Vec<Arg<Range<usize>>> {
    let mut args = Vec::new();
    for (_, table) in motors {
        for (key, v) in sorted(table.get_ref()) {
            if crate::schema::keys::from_name(key.get_ref())
                .is_some_and(crate::schema::keys::is_motor)
            {
                args.push(arg(source, key, v));
                continue;
            }
            let motor_keys = crate::schema::keys::MOTOR_KEYS.iter().map(|k| k.name());
            file.meant.extend(
                schema::suggest(key.get_ref(), motor_keys.clone())
                    .and_then(crate::schema::keys::from_name),
            );
            file.diagnostics.push(Diagnostic {
                loc: key.span(),
                message: format!(
                    "`{}` is not a motor key; {}a `[motors.NAME]` table takes {} \
                     (a profile's keys go in `[profiles.NAME]` or `[defaults]`)",
                    key.get_ref(),
                    did_you_mean(key.get_ref(), motor_keys.clone(), Hint::Before),
                    schema::quoted(motor_keys)
                ),
            });
        }
    }
    args
}

/// A profile's arguments: its own keys, then the keys of the motor it names
/// (itself or through `[defaults]`), then the defaults that apply to it:
/// those its curve takes, and a motor's keys where it has a motor.
fn profile(
    source: &str,
    table: &Table,
    defaults: &[Arg<Range<usize>>],
    motors: &[(&Spanned<String>, &Spanned<Table>)],
    declared: &[&str],
) -> Result<Vec<Arg<Range<usize>>>, Diagnostic<Range<usize>>> {
    let mut args: Vec<_> = sorted(table)
        .into_iter()
        .map(|(key, v)| arg(source, key, v))
        .collect();
    for a in &args {
        let digits = source
            .get(a.value_loc.clone())
            .map_or(0, |text| text.chars().filter(char::is_ascii_digit).count());
        if matches!(a.value, Value::Int(_) | Value::Float(_)) && digits > schema::MAX_DIGITS {
            return Err(Diagnostic {
                loc: a.value_loc.clone(),
                message: schema::too_many_digits(&a.key, digits),
            });
        }
    }
    let named = args
        .iter()
        .chain(defaults)
        .find(|a| a.key == Key::MOTOR.name())
        .cloned();
    if let Some(m) = &named {
        let found = match &m.value {
            Value::Name(n) => motors.iter().find(|(k, _)| k.get_ref() == n),
            _ => None,
        };
        let Some((_, motor)) = found else {
            return Err(Diagnostic {
                loc: m.value_loc.clone(),
                message: unknown_motor(&m.value, declared),
            });
        };
        for (key, v) in sorted(motor.get_ref()) {
            let motor_key = crate::schema::keys::from_name(key.get_ref())
                .is_some_and(crate::schema::keys::is_motor);
            if motor_key && !args.iter().any(|a| &a.key == key.get_ref()) {
                args.push(arg(source, key, v));
            }
        }
    }
    let curve = args
        .iter()
        .chain(defaults)
        .find(|a| a.key == Key::CURVE.name())
        .and_then(|a| match &a.value {
            Value::Name(n) => CurveSchema::named(n),
            _ => None,
        });
    let curve_keys = curve.map(|r| schema::keys_for(r.name));
    let has_motor = named.is_some()
        || args.iter().any(|a| {
            crate::schema::keys::from_name(&a.key).is_some_and(crate::schema::keys::is_motor)
        });
    let own: Vec<String> = args.iter().map(|a| a.key.clone()).collect();
    let given = |key: Key| own.iter().any(|k| k == key.name());
    for d in defaults {
        let applies = match crate::schema::keys::from_name(&d.key) {
            Some(k) if crate::schema::keys::is_motor(k) => has_motor,
            Some(k) => {
                curve_keys.as_ref().is_none_or(|keys| keys.contains(&k))
                    && !displaced(k, curve).any(given)
            }
            None => curve.is_none(),
        };
        if applies && !own.contains(&d.key) {
            args.push(d.clone());
        }
    }
    Ok(args)
}

/// The keys that, given in a profile, displace a default `key`: the other
/// of the curve's pair that sets the ramp's length (`len` or `accel`, `len`
/// or `tau`), the other layout (`segments` or `compress`).
fn displaced(key: Key, curve: Option<&CurveSchema>) -> impl Iterator<Item = Key> {
    let pairs = curve
        .and_then(|r| r.one_of)
        .into_iter()
        .chain([[Key::SEGMENTS, Key::COMPRESS]]);
    pairs.filter_map(move |[a, b]| match key {
        k if k == a => Some(b),
        k if k == b => Some(a),
        _ => None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
        assert!(bad_name("stepper_profiles").is_some());
        assert!(bad_name("core").is_some());
        assert!(bad_name("stepper_profiles_fast").is_none());
    }
}
