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
use crate::motor::{MAX_CURVE_POINTS, Motor, MotorError, TorqueCurve};
use crate::spec::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, MAX_LEN, Rounding, Sigmoid, Spec, ThreeStage, Timer, Word,
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
    /// A list of `(x, y)` number pairs: `[(0, 0.4), (1000, 0.3)]`.
    Points(Vec<(f64, f64)>),
    /// A value of a kind no key takes, described: `a boolean`, `an array`.
    Other(String),
}

impl Value {
    /// The value as quoted in messages: `` `1000.5` ``, `` `slow` ``, `a boolean`.
    /// A name that reads as a number says it is a string.
    pub fn quoted(&self) -> String {
        match self {
            Value::Name(n)
                if n.trim()
                    .starts_with(|c: char| c.is_ascii_digit() || "+-.".contains(c))
                    && n.trim().parse::<f64>().is_ok() =>
            {
                format!("the string `\"{n}\"` (write numbers without quotes)")
            }
            Value::Other(kind) => kind.clone(),
            Value::Points(_) => "a list of points".to_string(),
            other => format!("`{other}`"),
        }
    }
}

impl core::fmt::Display for Value {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Value::Int(v) => write!(f, "{v}"),
            Value::Float(v) => write!(f, "{v:?}"),
            Value::Name(v) | Value::Other(v) => f.write_str(v),
            Value::Points(points) => {
                f.write_str("[")?;
                for (i, (x, y)) in points.iter().enumerate() {
                    let sep = if i == 0 { "" } else { ", " };
                    write!(f, "{sep}({x}, {y})")?;
                }
                f.write_str("]")
            }
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
pub const CURVES: &[&str] = &[
    "sigmoid",
    "exponential",
    "linear",
    "three_stage",
    "jerk_limited",
];

/// Keys every curve takes, besides the motor's ([`Key::MOTOR`]).
const COMMON: &[Key] = &[
    Key::Curve,
    Key::TimerHz,
    Key::Word,
    Key::TicksPerStep,
    Key::Discretization,
    Key::Rounding,
    Key::Arithmetic,
    Key::Segments,
    Key::Motor,
];

/// A curve's own keys: those it requires, and pairs of which exactly one is given.
struct CurveKeys {
    required: &'static [Key],
    one_of: Option<[Key; 2]>,
}

fn curve_keys(curve: &str) -> CurveKeys {
    let (required, one_of): (&'static [Key], _) = match curve {
        "sigmoid" => (&[Key::Len, Key::Fmin, Key::Fmax, Key::Flexible], None),
        "exponential" => (
            &[Key::Fmin, Key::Fmax, Key::FInf],
            Some([Key::Len, Key::Tau]),
        ),
        "linear" => (&[Key::Fmin, Key::Fmax], Some([Key::Len, Key::Accel])),
        "three_stage" => (
            &[
                Key::Fmin,
                Key::Fmax,
                Key::Accel,
                Key::F1,
                Key::F2,
                Key::Shape,
            ],
            None,
        ),
        "jerk_limited" => (&[Key::Fmin, Key::Fmax, Key::Accel, Key::Jerk], None),
        _ => (&[], None),
    };
    CurveKeys { required, one_of }
}

/// Every key `curve` accepts, in documentation order.
pub fn keys_for(curve: &str) -> Vec<Key> {
    let own = curve_keys(curve);
    Key::ALL
        .iter()
        .copied()
        .filter(|k| {
            COMMON.contains(k)
                || Key::MOTOR.contains(k)
                || own.required.contains(k)
                || own.one_of.is_some_and(|pair| pair.contains(k))
        })
        .collect()
}

/// Keys to list in messages: a curve's and the common ones, not the motor's.
pub(crate) fn listed(keys: &[Key]) -> impl Iterator<Item = &'static str> + '_ {
    keys.iter()
        .filter(|k| !Key::MOTOR.contains(k) && **k != Key::Motor)
        .map(|k| k.name())
}

/// Items in backticks, separated by commas: `` `a`, `b` ``.
pub fn quoted<I: IntoIterator<Item = S>, S: AsRef<str>>(items: I) -> String {
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

/// The most digits a number may be written with: more than any key needs
/// (an `f64` holds 17 significant digits), few enough that no number is
/// parsed at length.
pub const MAX_DIGITS: usize = 40;

/// The message for a number written with more than [`MAX_DIGITS`] digits.
pub fn too_many_digits(key: &str, digits: usize) -> String {
    format!(
        "`{key}` has a number of {digits} digits, more than the {MAX_DIGITS} any key takes: \
         write it with an exponent, as in `1.5e9`"
    )
}

/// The unit a numeric key is given in, for messages.
pub fn unit(key: Key) -> &'static str {
    match key {
        Key::Fmin | Key::Fmax | Key::FInf | Key::F1 | Key::F2 => "Hz (steps/s)",
        Key::TimerHz => "Hz",
        Key::Accel => "Hz/s",
        Key::Jerk => "Hz/s²",
        Key::Tau => "s",
        Key::Shape => "1/s",
        _ => "",
    }
}

/// A table's layout: one entry per step, or seed 001's segments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Layout {
    /// One period per step: `[u16; len]`.
    Steps,
    /// `n` equal-time segments of (period, step count): `[(u16, u16); n]`.
    Segments(u32),
}

/// What a list of arguments asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parsed {
    /// The table's spec.
    pub spec: Spec,
    /// Its layout.
    pub layout: Layout,
    /// The motor it drives, when described: the table must be checked
    /// against it with [`Motor::check`].
    pub motor: Option<Motor>,
}

struct Collector<'a, L> {
    args: &'a [Arg<L>],
    whole: &'a L,
    /// Diagnostics with the index of the argument they concern, for source order.
    diagnostics: Vec<(usize, Diagnostic<L>)>,
}

impl<L: Clone> Collector<'_, L> {
    fn at_arg(&mut self, index: usize, key: bool, message: String) {
        let arg = &self.args[index];
        let loc = if key { &arg.key_loc } else { &arg.value_loc };
        self.diagnostics.push((
            index,
            Diagnostic {
                loc: loc.clone(),
                message,
            },
        ));
    }

    fn at_whole(&mut self, message: String) {
        self.diagnostics.push((
            usize::MAX,
            Diagnostic {
                loc: self.whole.clone(),
                message,
            },
        ));
    }

    fn find(&self, key: Key) -> Option<(usize, &Arg<L>)> {
        self.args
            .iter()
            .enumerate()
            .find(|(_, a)| a.key == key.name())
    }

    fn float(&mut self, key: Key) -> Option<f64> {
        let (i, arg) = self.find(key)?;
        match &arg.value {
            Value::Int(v) => Some(*v as f64),
            Value::Float(v) => Some(*v),
            other => {
                let unit = match unit(key) {
                    "" => String::new(),
                    unit => format!(" in {unit}"),
                };
                let message = format!("`{key}` expects a number{unit}, got {}", other.quoted());
                self.at_arg(i, false, message);
                None
            }
        }
    }

    fn int(&mut self, key: Key, expected: &str) -> Option<i128> {
        let (i, arg) = self.find(key)?;
        match &arg.value {
            Value::Int(v) => Some(*v),
            other => {
                let message = format!("`{key}` expects {expected}, got {}", other.quoted());
                self.at_arg(i, false, message);
                None
            }
        }
    }

    /// An integer key with a range; `check` says what is wrong with a value.
    fn ranged<T>(
        &mut self,
        key: Key,
        expected: &str,
        check: impl Fn(i128) -> Result<T, String>,
    ) -> Option<T> {
        let v = self.int(key, expected)?;
        match check(v) {
            Ok(t) => Some(t),
            Err(message) => {
                let (i, _) = self.find(key)?;
                self.at_arg(i, false, message);
                None
            }
        }
    }

    fn name<T: Copy>(&mut self, key: Key, choices: &[(&'static str, T)]) -> Option<T> {
        let (i, arg) = self.find(key)?;
        let names = quoted(choices.iter().map(|(n, _)| *n));
        let message = match &arg.value {
            Value::Name(n) => match choices.iter().find(|(c, _)| c == n) {
                Some((_, v)) => return Some(*v),
                None => {
                    let hint = suggest(n, choices.iter().map(|(c, _)| *c))
                        .map(|s| format!("; did you mean `{s}`?"))
                        .unwrap_or_default();
                    format!("`{key}` must be one of {names} (got `{n}`){hint}")
                }
            },
            other => format!("`{key}` expects one of {names}, got {}", other.quoted()),
        };
        self.at_arg(i, false, message);
        None
    }

    fn finish(mut self) -> Vec<Diagnostic<L>> {
        self.diagnostics.sort_by_key(|(i, _)| *i);
        self.diagnostics.into_iter().map(|(_, d)| d).collect()
    }
}

fn len_check(len: i128) -> Result<u32, String> {
    if len < 1 {
        Err(format!("`len` must be at least 1 (got {len})"))
    } else if len > MAX_LEN as i128 {
        Err(Error::LenTooLarge {
            len: u64::try_from(len).unwrap_or(u64::MAX),
            max: MAX_LEN,
        }
        .to_string())
    } else {
        Ok(len as u32)
    }
}

/// Checks `args` and builds the table they describe.
///
/// `whole` locates the entire argument list, for missing keys. All problems
/// found in keys, kinds and names are reported together, in source order;
/// then the spec's own validation runs.
pub fn spec_from_args<L: Clone>(args: &[Arg<L>], whole: &L) -> Result<Parsed, Vec<Diagnostic<L>>> {
    spec_from_args_assuming(args, whole, &[])
}

/// [`spec_from_args`], not reporting `assumed` keys as missing: keys another
/// diagnostic already covers, such as the target of a misspelt default. When
/// such a key is all that is wrong, the error holds no diagnostic of its own.
pub fn spec_from_args_assuming<L: Clone>(
    args: &[Arg<L>],
    whole: &L,
    assumed: &[Key],
) -> Result<Parsed, Vec<Diagnostic<L>>> {
    let mut c = Collector {
        args,
        whole,
        diagnostics: Vec::new(),
    };

    // Which curve, so that its keys are known.
    let curve_name: Option<&str> = match c.find(Key::Curve) {
        None => {
            c.at_whole(format!(
                "missing key `curve`: expected one of {}",
                quoted(CURVES)
            ));
            None
        }
        Some((i, arg)) => match &arg.value {
            Value::Name(n) if CURVES.contains(&n.as_str()) => {
                CURVES.iter().copied().find(|c| c == n)
            }
            other => {
                let hint = match other {
                    Value::Name(n) => suggest(n, CURVES.iter().copied())
                        .map(|s| format!("; did you mean `{s}`?"))
                        .unwrap_or_default(),
                    _ => String::new(),
                };
                let message = match other {
                    Value::Name(_) => format!(
                        "`curve` must be one of {} (got `{other}`){hint}",
                        quoted(CURVES)
                    ),
                    _ => format!(
                        "`curve` expects one of {}, got {}",
                        quoted(CURVES),
                        other.quoted()
                    ),
                };
                c.at_arg(i, false, message);
                None
            }
        },
    };
    let valid = match curve_name {
        Some(n) => keys_for(n),
        None => Key::ALL.to_vec(),
    };

    // Unknown, inapplicable and duplicate keys.
    let mut suggested = assumed.to_vec();
    for (i, arg) in args.iter().enumerate() {
        match Key::from_name(&arg.key) {
            None => {
                let near = suggest(&arg.key, valid.iter().map(|k| k.name()));
                suggested.extend(near.and_then(Key::from_name));
                let hint = near
                    .map(|s| format!("did you mean `{s}`? "))
                    .unwrap_or_default();
                let message = format!(
                    "unknown key `{}`; {hint}expected one of {}, or a motor's keys",
                    arg.key,
                    quoted(listed(&valid))
                );
                c.at_arg(i, true, message);
            }
            Some(key) => {
                if let Some(n) = curve_name {
                    if !valid.contains(&key) {
                        let message = format!(
                            "`{key}` does not apply to `curve = {n}`, which takes {}",
                            quoted(listed(&valid))
                        );
                        c.at_arg(i, true, message);
                    }
                }
                if args[..i].iter().any(|a| a.key == arg.key) {
                    c.at_arg(i, true, format!("duplicate key `{key}`"));
                }
            }
        }
    }

    let Some(curve_name) = curve_name else {
        return Err(c.finish());
    };
    let own = curve_keys(curve_name);
    let mut required = own.required.to_vec();
    required.push(Key::TimerHz);
    let missing: Vec<Key> = required
        .iter()
        .copied()
        .filter(|k| c.find(*k).is_none() && !suggested.contains(k))
        .collect();
    // A required key covered by another diagnostic (a near-miss spelling) is
    // still absent: the spec cannot be built, whatever else is right.
    let incomplete = required.iter().any(|k| c.find(*k).is_none());
    if !missing.is_empty() {
        let plural = if missing.len() == 1 { "key" } else { "keys" };
        c.at_whole(format!(
            "missing {plural} {}: `curve = {curve_name}` needs {}",
            quoted(missing.iter().map(|k| k.name())),
            quoted(required.iter().map(|k| k.name()))
        ));
    }
    if let Some([a, b]) = own.one_of {
        match (c.find(a).map(|(i, _)| i), c.find(b).map(|(i, _)| i)) {
            (Some(i), Some(j)) => c.at_arg(
                i.max(j),
                true,
                format!("give one of `{a}` and `{b}`, not both: each sets the ramp's length"),
            ),
            (None, None) if !suggested.contains(&a) && !suggested.contains(&b) => c.at_whole(
                format!("missing key: `curve = {curve_name}` needs one of `{a}` and `{b}`"),
            ),
            _ => {}
        }
    }

    let timer_hz = c.ranged(Key::TimerHz, "an integer number of Hz", |v| {
        if v < 1 {
            Err(format!("`timer_hz` must be greater than 0 (got {v})"))
        } else {
            u32::try_from(v)
                .map_err(|_| format!("`timer_hz` must be at most {} (got {v})", u32::MAX))
        }
    });
    let word = c.name(Key::Word, &[("u16", Word::U16), ("u32", Word::U32)]);
    let ticks_per_step = c.ranged(Key::TicksPerStep, "1 or 2", |v| match v {
        1 | 2 => Ok(v as u8),
        _ => Err(format!("`ticks_per_step` must be 1 or 2 (got {v})")),
    });
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
        &[
            ("f64", Arithmetic::F64),
            ("f32", Arithmetic::F32),
            ("integer", Arithmetic::Integer),
        ],
    );
    let segments = c.ranged(Key::Segments, "an integer number of segments", |v| {
        if v < 1 {
            Err(format!("`segments` must be at least 1 (got {v})"))
        } else if v > MAX_LEN as i128 {
            Err(format!("`segments` must be at most {MAX_LEN} (got {v})"))
        } else {
            Ok(v as u32)
        }
    });

    let nan = f64::NAN;
    let float = |c: &mut Collector<'_, L>, key| c.float(key).unwrap_or(nan);
    let len = c.ranged(Key::Len, "an integer number of entries", len_check);
    let fmin = float(&mut c, Key::Fmin);
    let fmax = float(&mut c, Key::Fmax);
    let curve = match curve_name {
        "sigmoid" => Curve::Sigmoid(Sigmoid {
            fmin,
            fmax,
            flexible: float(&mut c, Key::Flexible),
            len: len.unwrap_or(0),
        }),
        "exponential" => Curve::Exponential(Exponential {
            fmin,
            fmax,
            f_inf: float(&mut c, Key::FInf),
            extent: match len {
                Some(n) => ExponentialExtent::Len(n),
                None => ExponentialExtent::Tau(float(&mut c, Key::Tau)),
            },
        }),
        "linear" => Curve::Linear(Linear {
            fmin,
            fmax,
            extent: match len {
                Some(n) => LinearExtent::Len(n),
                None => LinearExtent::Accel(float(&mut c, Key::Accel)),
            },
        }),
        "three_stage" => Curve::ThreeStage(ThreeStage {
            fmin,
            fmax,
            accel: float(&mut c, Key::Accel),
            f1: float(&mut c, Key::F1),
            f2: float(&mut c, Key::F2),
            shape: float(&mut c, Key::Shape),
        }),
        _ => Curve::JerkLimited(JerkLimited {
            fmin,
            fmax,
            accel: float(&mut c, Key::Accel),
            jerk: float(&mut c, Key::Jerk),
        }),
    };

    let motor = motor_from_args(&mut c);

    if incomplete || !c.diagnostics.is_empty() {
        return Err(c.finish());
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
    let layout = match segments {
        Some(n) => {
            spec.check_segments(n)
                .map_err(|e| std::vec![locate(&e, args, whole)])?;
            Layout::Segments(n)
        }
        None => Layout::Steps,
    };
    if let Some(m) = &motor {
        m.validate()
            .map_err(|e| std::vec![locate_motor(&e, args, whole)])?;
    }
    Ok(Parsed {
        spec,
        layout,
        motor,
    })
}

/// The spec's parameters as `(key, value)` pairs, in documentation order, as
/// a user would write them (defaults included): for docs, headers, reports.
pub fn describe(spec: &Spec) -> Vec<(Key, String)> {
    let mut out = std::vec![(Key::Curve, spec.curve.name().to_string())];
    let num = |v: f64| format!("{v}");
    match spec.curve {
        Curve::Sigmoid(c) => out.extend([
            (Key::Len, c.len.to_string()),
            (Key::Fmin, num(c.fmin)),
            (Key::Fmax, num(c.fmax)),
            (Key::Flexible, num(c.flexible)),
        ]),
        Curve::Exponential(c) => {
            out.extend([
                (Key::Fmin, num(c.fmin)),
                (Key::Fmax, num(c.fmax)),
                (Key::FInf, num(c.f_inf)),
            ]);
            out.push(match c.extent {
                ExponentialExtent::Len(n) => (Key::Len, n.to_string()),
                ExponentialExtent::Tau(t) => (Key::Tau, num(t)),
            });
        }
        Curve::Linear(c) => {
            out.extend([(Key::Fmin, num(c.fmin)), (Key::Fmax, num(c.fmax))]);
            out.push(match c.extent {
                LinearExtent::Len(n) => (Key::Len, n.to_string()),
                LinearExtent::Accel(a) => (Key::Accel, num(a)),
            });
        }
        Curve::ThreeStage(c) => out.extend([
            (Key::Fmin, num(c.fmin)),
            (Key::Fmax, num(c.fmax)),
            (Key::Accel, num(c.accel)),
            (Key::F1, num(c.f1)),
            (Key::F2, num(c.f2)),
            (Key::Shape, num(c.shape)),
        ]),
        Curve::JerkLimited(c) => out.extend([
            (Key::Fmin, num(c.fmin)),
            (Key::Fmax, num(c.fmax)),
            (Key::Accel, num(c.accel)),
            (Key::Jerk, num(c.jerk)),
        ]),
    }
    out.extend([
        (Key::TimerHz, spec.timer.timer_hz.to_string()),
        (Key::Word, spec.timer.word.name().to_string()),
        (Key::TicksPerStep, spec.timer.ticks_per_step.to_string()),
        (Key::Discretization, spec.discretization.name().to_string()),
        (Key::Rounding, spec.rounding.name().to_string()),
        (Key::Arithmetic, spec.arithmetic.name().to_string()),
    ]);
    out
}

/// The motor the arguments describe, if any; problems go to the collector.
fn motor_from_args<L: Clone>(c: &mut Collector<'_, L>) -> Option<Motor> {
    let described = Key::MOTOR.iter().any(|k| c.find(*k).is_some());
    if !described {
        if let Some((i, arg)) = c.find(Key::Motor) {
            let message = format!(
                "`motor = {}` names no motor description: declare `[motors.{}]` in the \
                 profiles file, or give the motor's keys (`step_angle`, `rotor_inertia`, \
                 `torque_curve`, ...)",
                arg.value, arg.value
            );
            c.at_arg(i, false, message);
        }
        return None;
    }
    let required = [Key::StepAngle, Key::RotorInertia, Key::TorqueCurve];
    let missing: Vec<Key> = required
        .iter()
        .copied()
        .filter(|k| c.find(*k).is_none())
        .collect();
    if !missing.is_empty() {
        c.at_whole(format!(
            "missing motor {} {}: a motor needs {}",
            if missing.len() == 1 { "key" } else { "keys" },
            quoted(missing.iter().map(|k| k.name())),
            quoted(required.iter().map(|k| k.name()))
        ));
    }
    let step_angle = c.float(Key::StepAngle);
    let microsteps = c.ranged(
        Key::Microsteps,
        "an integer number of microsteps per full step",
        |v| {
            u32::try_from(v)
                .ok()
                .filter(|m| (1..=1024).contains(m))
                .ok_or_else(|| format!("`microsteps` must be from 1 to 1024 (got {v})"))
        },
    );
    let rotor_inertia = c.float(Key::RotorInertia);
    let load_inertia = c.float(Key::LoadInertia);
    let friction = c.float(Key::Friction);
    let damping = c.float(Key::Damping);
    let safety = c.float(Key::Safety);
    let max_start_hz = c.float(Key::MaxStartHz);
    let curve = match c.find(Key::TorqueCurve) {
        None => None,
        Some((i, arg)) => match &arg.value {
            Value::Points(points) => match TorqueCurve::new(points) {
                Some(curve) => Some(curve),
                None => {
                    let message = format!(
                        "`torque_curve` must have from 1 to {MAX_CURVE_POINTS} points (got {})",
                        points.len()
                    );
                    c.at_arg(i, false, message);
                    None
                }
            },
            other => {
                let message = format!(
                    "`torque_curve` expects a list of (step frequency in Hz, torque in N·m) \
                     points such as `[(0, 0.4), (1000, 0.3)]`, got {}",
                    other.quoted()
                );
                c.at_arg(i, false, message);
                None
            }
        },
    };
    Some(Motor {
        step_angle: step_angle?,
        microsteps: microsteps.unwrap_or(1),
        rotor_inertia: rotor_inertia?,
        load_inertia: load_inertia.unwrap_or(0.0),
        torque_curve: curve?,
        friction: friction.unwrap_or(0.0),
        damping: damping.unwrap_or(0.0),
        safety: safety.unwrap_or(1.0),
        max_start_hz,
    })
}

/// Places a motor error: at the value of its key, at `motor` for a table the
/// motor cannot follow (when no `motor` names it: at `max_start_hz` for a
/// start too fast, else at `torque_curve`), or on `whole`.
pub fn locate_motor<L: Clone>(error: &MotorError, args: &[Arg<L>], whole: &L) -> Diagnostic<L> {
    let find = |k: Key| {
        args.iter()
            .find(|a| a.key == k.name())
            .map(|a| a.value_loc.clone())
    };
    let inline = match error {
        MotorError::Start { .. } => Key::MaxStartHz,
        _ => Key::TorqueCurve,
    };
    let loc = find(error.key())
        .or_else(|| find(inline))
        .or_else(|| find(Key::TorqueCurve))
        .unwrap_or_else(|| whole.clone());
    Diagnostic {
        loc,
        message: error.to_string(),
    }
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
        let spec = spec_from_args(&args(&orange()), &999).unwrap().spec;
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
            std::vec![(
                8,
                "unknown key `flexibel`; did you mean `flexible`? expected one of `curve`, \
                     `len`, `fmin`, `fmax`, `flexible`, `timer_hz`, `word`, `ticks_per_step`, \
                     `discretization`, `rounding`, `arithmetic`, `segments`, or a motor's keys"
                    .to_string()
            )]
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
        // Reported together, in source order.
        assert_eq!(
            errors(&list),
            std::vec![
                (
                    3,
                    "`len` expects an integer number of entries, got `1000.5`".to_string()
                ),
                (
                    5,
                    "`fmin` expects a number in Hz (steps/s), got `slow`".to_string()
                ),
                (
                    13,
                    "`rounding` must be one of `truncate`, `nearest`, `diffuse` (got `round`)"
                        .to_string()
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
