//! The argument schema shared by `period_table!` and `profiles.toml`.
//!
//! Front ends turn their syntax into a list of [`Arg`]s, each carrying a
//! location of the front end's choice (a `Span` in the macro, a byte range in
//! TOML). [`spec_from_args`] checks keys, kinds and names, builds the [`Spec`]
//! and validates it; every problem comes back as a [`Diagnostic`] at the
//! location of the offending key or value. Parsing is written once, here.

use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

use crate::error::{Error, Key};
use crate::spec::{
    Arithmetic, Curve, Discretization, MAX_LEN, Rounding, Sigmoid, Spec, Timer, Word,
};

/// A value as written by the user.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// An integer literal (possibly negative).
    Int(i128),
    /// A floating-point literal (possibly negative).
    Float(f64),
    /// A bare name or a string: `sigmoid`, `"u16"`.
    Name(String),
}

impl core::fmt::Display for Value {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Value::Int(v) => write!(f, "{v}"),
            Value::Float(v) => write!(f, "{v:?}"),
            Value::Name(v) => f.write_str(v),
        }
    }
}

/// One `key = value` pair with the locations of its key and its value.
#[derive(Clone, Debug, PartialEq)]
pub struct Arg<L> {
    /// The key as written.
    pub key: String,
    /// Where the key is.
    pub key_loc: L,
    /// The value.
    pub value: Value,
    /// Where the value is.
    pub value_loc: L,
}

/// A message about the input and where it belongs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic<L> {
    /// Where the problem is.
    pub loc: L,
    /// What is wrong and what is expected: lowercase, no trailing period.
    pub message: String,
}

/// The curves a spec can name.
pub const CURVES: &[&str] = &["sigmoid"];

/// The curve a spec names, once its name is known to be valid.
#[derive(Clone, Copy)]
enum CurveKind {
    Sigmoid,
}

impl CurveKind {
    /// Only called with a name from [`CURVES`].
    fn from_name(_name: &str) -> Self {
        CurveKind::Sigmoid
    }
}

/// Keys every curve takes.
const COMMON: &[Key] = &[
    Key::Curve,
    Key::TimerHz,
    Key::Word,
    Key::TicksPerStep,
    Key::Discretization,
    Key::Rounding,
    Key::Arithmetic,
];

/// The keys `curve` takes besides the common ones, the required ones first.
fn curve_keys(curve: &str) -> &'static [Key] {
    match curve {
        "sigmoid" => &[Key::Len, Key::Fmin, Key::Fmax, Key::Flexible],
        _ => &[],
    }
}

/// Keys that must be given for `curve`.
fn required(curve: &str) -> Vec<Key> {
    let mut keys = curve_keys(curve).to_vec();
    keys.push(Key::TimerHz);
    keys
}

/// Every key `curve` accepts.
pub fn keys_for(curve: &str) -> Vec<Key> {
    let specific = curve_keys(curve);
    Key::ALL
        .iter()
        .copied()
        .filter(|k| COMMON.contains(k) || specific.contains(k))
        .collect()
}

fn quoted_list<I: IntoIterator<Item = S>, S: AsRef<str>>(items: I) -> String {
    items
        .into_iter()
        .map(|s| format!("`{}`", s.as_ref()))
        .collect::<Vec<_>>()
        .join(", ")
}

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

/// The closest of `candidates` to `word`, if close enough to be a typo.
pub fn suggest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    candidates
        .into_iter()
        .map(|c| (distance(word, c), c))
        .filter(|(d, c)| *d <= 2.max(c.len() / 3) && *d < c.len())
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}

struct Collector<'a, L> {
    args: &'a [Arg<L>],
    whole: &'a L,
    diagnostics: Vec<Diagnostic<L>>,
}

impl<L: Clone> Collector<'_, L> {
    fn error(&mut self, loc: &L, message: String) {
        self.diagnostics.push(Diagnostic {
            loc: loc.clone(),
            message,
        });
    }

    fn find(&self, key: Key) -> Option<&Arg<L>> {
        self.args.iter().find(|a| a.key == key.name())
    }

    fn float(&mut self, key: Key) -> Option<f64> {
        let arg = self.find(key)?.clone();
        match arg.value {
            Value::Int(v) => Some(v as f64),
            Value::Float(v) => Some(v),
            Value::Name(ref n) => {
                self.error(
                    &arg.value_loc,
                    format!("`{key}` expects a number in {}, got `{n}`", unit(key)),
                );
                None
            }
        }
    }

    fn int(&mut self, key: Key, expected: &str) -> Option<i128> {
        let arg = self.find(key)?.clone();
        match arg.value {
            Value::Int(v) => Some(v),
            ref other => {
                self.error(
                    &arg.value_loc,
                    format!("`{key}` expects {expected}, got `{other}`"),
                );
                None
            }
        }
    }

    fn name<T: Copy>(&mut self, key: Key, choices: &[(&'static str, T)]) -> Option<T> {
        let arg = self.find(key)?.clone();
        let names = || quoted_list(choices.iter().map(|(n, _)| *n));
        match arg.value {
            Value::Name(ref n) => match choices.iter().find(|(c, _)| c == n) {
                Some((_, v)) => Some(*v),
                None => {
                    let hint = suggest(n, choices.iter().map(|(c, _)| *c))
                        .map(|s| format!("; did you mean `{s}`?"))
                        .unwrap_or_default();
                    self.error(
                        &arg.value_loc,
                        format!("`{key}` must be one of {} (got `{n}`){hint}", names()),
                    );
                    None
                }
            },
            ref other => {
                self.error(
                    &arg.value_loc,
                    format!("`{key}` expects one of {}, got `{other}`", names()),
                );
                None
            }
        }
    }
}

/// The unit a numeric key is given in, for messages.
pub fn unit(key: Key) -> &'static str {
    match key {
        Key::Fmin | Key::Fmax => "Hz (steps/s)",
        Key::TimerHz => "Hz",
        Key::Flexible => "units of the logistic's half-width",
        _ => "",
    }
}

/// Checks `args` and builds the spec they describe.
///
/// `whole` locates the entire argument list, for missing keys. All problems
/// found in keys, kinds and names are reported together; then the spec's own
/// validation runs.
pub fn spec_from_args<L: Clone>(args: &[Arg<L>], whole: &L) -> Result<Spec, Vec<Diagnostic<L>>> {
    let mut c = Collector {
        args,
        whole,
        diagnostics: Vec::new(),
    };

    // Which curve, so that its keys are known.
    let curve_name = match c.find(Key::Curve).cloned() {
        None => {
            c.error(
                whole,
                format!(
                    "missing key `curve`: expected one of {}",
                    quoted_list(CURVES)
                ),
            );
            None
        }
        Some(arg) => match &arg.value {
            Value::Name(n) if CURVES.contains(&n.as_str()) => Some(n.clone()),
            other => {
                let hint = match other {
                    Value::Name(n) => suggest(n, CURVES.iter().copied())
                        .map(|s| format!("; did you mean `{s}`?"))
                        .unwrap_or_default(),
                    _ => String::new(),
                };
                c.error(
                    &arg.value_loc,
                    format!(
                        "`curve` must be one of {} (got `{other}`){hint}",
                        quoted_list(CURVES)
                    ),
                );
                None
            }
        },
    };

    // Unknown, inapplicable and duplicate keys.
    for (i, arg) in args.iter().enumerate() {
        match Key::from_name(&arg.key) {
            None => {
                let valid = match &curve_name {
                    Some(n) => keys_for(n),
                    None => Key::ALL.to_vec(),
                };
                let hint = suggest(&arg.key, valid.iter().map(|k| k.name()))
                    .map(|s| format!("did you mean `{s}`? "))
                    .unwrap_or_default();
                c.error(
                    &arg.key_loc,
                    format!(
                        "unknown key `{}`; {hint}expected one of {}",
                        arg.key,
                        quoted_list(valid.iter().map(|k| k.name()))
                    ),
                );
            }
            Some(key) => {
                if let Some(n) = &curve_name {
                    if !keys_for(n).contains(&key) {
                        c.error(
                            &arg.key_loc,
                            format!(
                                "`{key}` does not apply to `curve = {n}`, which takes {}",
                                quoted_list(keys_for(n).iter().map(|k| k.name()))
                            ),
                        );
                    }
                }
                if args[..i].iter().any(|a| a.key == arg.key) {
                    c.error(&arg.key_loc, format!("duplicate key `{key}`"));
                }
            }
        }
    }

    let Some(curve_name) = curve_name else {
        return Err(c.diagnostics);
    };
    let missing: Vec<Key> = required(&curve_name)
        .into_iter()
        .filter(|k| c.find(*k).is_none())
        .collect();
    if !missing.is_empty() {
        let keys = quoted_list(missing.iter().map(|k| k.name()));
        let plural = if missing.len() == 1 { "key" } else { "keys" };
        c.error(
            c.whole,
            format!(
                "missing {plural} {keys}: `curve = {curve_name}` needs {}",
                quoted_list(required(&curve_name).iter().map(|k| k.name()))
            ),
        );
    }

    let timer_hz = c.int(Key::TimerHz, "an integer number of Hz");
    let word = c.name(Key::Word, &[("u16", Word::U16), ("u32", Word::U32)]);
    let ticks_per_step = c.int(Key::TicksPerStep, "1 or 2");
    let discretization = c.name(
        Key::Discretization,
        &[
            ("exact", Discretization::Exact),
            ("left_endpoint", Discretization::LeftEndpoint),
            ("index", Discretization::Index),
        ],
    );
    let rounding = c.name(
        Key::Rounding,
        &[
            ("truncate", Rounding::Truncate),
            ("nearest", Rounding::Nearest),
            ("diffuse", Rounding::Diffuse),
        ],
    );
    let arithmetic = c.name(
        Key::Arithmetic,
        &[("f64", Arithmetic::F64), ("f32", Arithmetic::F32)],
    );

    let curve = match CurveKind::from_name(&curve_name) {
        CurveKind::Sigmoid => {
            let len = c.int(Key::Len, "an integer number of entries");
            let fmin = c.float(Key::Fmin);
            let fmax = c.float(Key::Fmax);
            let flexible = c.float(Key::Flexible);
            Curve::Sigmoid(Sigmoid {
                fmin: fmin.unwrap_or(f64::NAN),
                fmax: fmax.unwrap_or(f64::NAN),
                flexible: flexible.unwrap_or(f64::NAN),
                len: len.map(|l| int_len(&mut c, l)).unwrap_or(0),
            })
        }
    };
    let timer_hz = timer_hz.map(|v| match u32::try_from(v) {
        Ok(hz) => hz,
        Err(_) => {
            let loc = c.find(Key::TimerHz).map(|a| a.value_loc.clone());
            let message = if v < 0 {
                format!("`timer_hz` must be greater than 0 (got {v})")
            } else {
                format!("`timer_hz` must be at most {} (got {v})", u32::MAX)
            };
            c.error(loc.as_ref().unwrap_or(whole), message);
            0
        }
    });
    let ticks_per_step = ticks_per_step.map(|v| match v {
        1 | 2 => v as u8,
        _ => {
            let loc = c.find(Key::TicksPerStep).map(|a| a.value_loc.clone());
            c.error(
                loc.as_ref().unwrap_or(whole),
                format!("`ticks_per_step` must be 1 or 2 (got {v})"),
            );
            1
        }
    });

    if !c.diagnostics.is_empty() {
        return Err(c.diagnostics);
    }
    let spec = Spec {
        curve,
        timer: Timer {
            timer_hz: timer_hz.unwrap_or(0),
            word: word.unwrap_or(Word::U16),
            ticks_per_step: ticks_per_step.unwrap_or(1),
        },
        discretization: discretization.unwrap_or_default(),
        rounding: rounding.unwrap_or_default(),
        arithmetic: arithmetic.unwrap_or_default(),
    };
    spec.validate()
        .map_err(|e| std::vec![locate(&e, args, whole)])?;
    Ok(spec)
}

fn int_len<L: Clone>(c: &mut Collector<'_, L>, len: i128) -> u32 {
    if (1..=MAX_LEN as i128).contains(&len) {
        return len as u32;
    }
    let loc = c.find(Key::Len).map(|a| a.value_loc.clone());
    let message = if len < 1 {
        format!("`len` must be at least 1 (got {len})")
    } else {
        Error::LenTooLarge {
            len: u64::try_from(len).unwrap_or(u64::MAX),
            max: MAX_LEN,
        }
        .to_string()
    };
    c.error(loc.as_ref().unwrap_or(c.whole), message);
    0
}

/// Places a core error at the value of the key it blames (or on `whole`).
pub fn locate<L: Clone>(error: &Error, args: &[Arg<L>], whole: &L) -> Diagnostic<L> {
    let loc = error
        .key()
        .and_then(|k| args.iter().find(|a| a.key == k.name()))
        .map(|a| a.value_loc.clone())
        .unwrap_or_else(|| whole.clone());
    Diagnostic {
        loc,
        message: error.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(list: &[(&str, Value)]) -> Vec<Arg<usize>> {
        list.iter()
            .enumerate()
            .map(|(i, (k, v))| Arg {
                key: k.to_string(),
                key_loc: 2 * i,
                value: v.clone(),
                value_loc: 2 * i + 1,
            })
            .collect()
    }

    fn name(s: &str) -> Value {
        Value::Name(s.to_string())
    }

    fn orange() -> Vec<(&'static str, Value)> {
        std::vec![
            ("curve", name("sigmoid")),
            ("len", Value::Int(1000)),
            ("fmin", Value::Int(500)),
            ("fmax", Value::Float(64000.0)),
            ("flexible", Value::Int(8)),
            ("timer_hz", Value::Int(10_000_000)),
        ]
    }

    fn errors(list: &[(&str, Value)]) -> Vec<(usize, String)> {
        spec_from_args(&args(list), &999)
            .unwrap_err()
            .into_iter()
            .map(|d| (d.loc, d.message))
            .collect()
    }

    #[test]
    fn builds_the_orange_spec_with_defaults() {
        let spec = spec_from_args(&args(&orange()), &999).unwrap();
        assert_eq!(spec.discretization, Discretization::Exact);
        assert_eq!(spec.rounding, Rounding::Diffuse);
        assert_eq!(spec.timer, Timer::new(10_000_000));
        assert_eq!(spec.len(), 1000);
    }

    #[test]
    fn typo_gets_a_suggestion_on_the_key() {
        let mut list = orange();
        list[4].0 = "flexibel";
        assert_eq!(
            errors(&list),
            std::vec![
                (
                    8,
                    "unknown key `flexibel`; did you mean `flexible`? expected one of `curve`, \
                     `len`, `fmin`, `fmax`, `flexible`, `timer_hz`, `word`, `ticks_per_step`, \
                     `discretization`, `rounding`, `arithmetic`"
                        .to_string()
                ),
                (
                    999,
                    "missing key `flexible`: `curve = sigmoid` needs `len`, `fmin`, `fmax`, \
                     `flexible`, `timer_hz`"
                        .to_string()
                ),
            ]
        );
    }

    #[test]
    fn duplicate_is_reported_on_the_second() {
        let mut list = orange();
        list.push(("fmin", Value::Int(600)));
        assert_eq!(
            errors(&list),
            std::vec![(12, "duplicate key `fmin`".to_string())]
        );
    }

    #[test]
    fn validation_points_at_the_value() {
        let mut list = orange();
        list[3].1 = Value::Int(400);
        assert_eq!(
            errors(&list),
            std::vec![(
                7,
                "`fmax` must be greater than `fmin` (got 400 <= 500)".to_string()
            )]
        );
    }

    #[test]
    fn wrong_kinds() {
        let mut list = orange();
        list[1].1 = Value::Float(1000.5);
        list[2].1 = name("slow");
        list.push(("rounding", name("round")));
        assert_eq!(
            errors(&list),
            std::vec![
                (
                    13,
                    "`rounding` must be one of `truncate`, `nearest`, `diffuse` (got `round`)"
                        .to_string()
                ),
                (
                    3,
                    "`len` expects an integer number of entries, got `1000.5`".to_string()
                ),
                (
                    5,
                    "`fmin` expects a number in Hz (steps/s), got `slow`".to_string()
                ),
            ]
        );
    }

    #[test]
    fn suggestions_are_only_for_near_misses() {
        assert_eq!(suggest("fmn", ["fmin", "fmax"]), Some("fmin"));
        assert_eq!(suggest("speed", ["fmin", "fmax"]), None);
    }
}
