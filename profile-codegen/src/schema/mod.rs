//! The argument schema shared by `period_table!` and `profiles.toml`.
//!
//! Front ends turn their syntax into a list of [`Arg`]s, each carrying a
//! location of the front end's choice (a `Span` in the macro, a byte range in
//! TOML). [`read`] checks keys, kinds and names and says what the arguments
//! ask for; every problem comes back as a [`Diagnostic`] at the location of
//! the offending key or value. The keys a curve takes come from its schema
//! (`curves/`); this module knows the common keys, the motor's, and how to
//! say what is wrong.

use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

use crate::numbers::Num;
use crate::schema::curves::{CURVE_SCHEMAS, CurveSchema};
use profile_core::Key;

pub(crate) mod curves;
mod describe;
pub(crate) mod keys;
mod request;
mod suggest;
pub mod units;
mod values;

pub(crate) use curves::curve_keys;
pub(crate) use describe::at_value;
pub use describe::{describe, describe_motor, locate, locate_motor};
pub(crate) use request::value_problems;
pub use request::{Request, read};
pub use suggest::{Hint, did_you_mean, suggest};

/// A value as written by the user.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// An integer literal (possibly negative).
    Int(i128),
    /// A floating-point literal (possibly negative).
    Float(f64),
    /// A bare name or a string: `sigmoid`, `"u16"`.
    Name(String),
    /// A number written with a unit or a suffix: `64kHz` is `number` `"64"`
    /// and `unit` `"kHz"`. Keys read it through [`units`].
    Quantity {
        /// The number: sign, digits, point and exponent, without `_`.
        number: String,
        /// The unit or suffix.
        unit: String,
        /// The value as written, for messages: `64_000 Hz`, `10 khz`.
        written: String,
    },
    /// A list of `(x, y)` number pairs: `[(0, 0.4), (1000, 0.3)]`.
    Points(Vec<(f64, f64)>),
    /// A list of pairs whose element `part` (counted from 0) the front end
    /// could not read, and why: a unit a torque curve's point does not
    /// take (`[[0, "40 Ncn"]]` in a profiles file).
    Refused {
        /// The message, naming the key.
        message: String,
        /// The element at fault.
        part: usize,
    },
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
            Value::Refused { .. } => "an array".to_string(),
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
            Value::Refused { .. } => f.write_str("an array"),
            Value::Quantity { written, .. } => f.write_str(written),
            Value::Points(points) => {
                f.write_str("[")?;
                for (i, (x, y)) in points.iter().enumerate() {
                    let sep = if i == 0 { "" } else { ", " };
                    write!(f, "{sep}({}, {})", Num(*x), Num(*y))?;
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
    /// Where each element of a list value is (a torque curve's points), in
    /// order; empty for other values, or where the front door does not
    /// know.
    pub parts: Vec<L>,
}

/// A message about the input and where it belongs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Diagnostic<L> {
    /// Where the problem is.
    pub loc: L,
    /// What is wrong and what is expected: lowercase, no trailing period.
    pub message: String,
}

/// The curves a spec can name, in documentation order.
pub fn curve_names() -> impl Iterator<Item = &'static str> + Clone {
    CURVE_SCHEMAS.iter().map(|r| r.name)
}

/// Every key `curve` accepts, in documentation order: its own, the common
/// ones, the motor's.
pub fn keys_for(curve: &str) -> Vec<Key> {
    let own = CurveSchema::named(curve).map_or(&[][..], |r| r.keys);
    crate::schema::keys::all()
        .into_iter()
        .filter(|k| {
            *k == Key::CURVE
                || own.contains(k)
                || crate::schema::keys::COMMON.contains(k)
                || crate::schema::keys::is_motor(*k)
        })
        .collect()
}

/// Keys to list in messages: a curve's and the common ones, not the
/// motor's, the driver's nor the step interrupt's (suggestions still find
/// them).
pub(crate) fn listed(keys: &[Key]) -> impl Iterator<Item = &'static str> + '_ {
    keys.iter()
        .filter(|k| {
            !crate::schema::keys::is_motor(**k)
                && **k != Key::MOTOR
                && **k != Key::DRIVER
                && !crate::schema::keys::DRIVER_TIMING.contains(k)
                && !crate::schema::keys::BUDGET.contains(k)
                && **k != Key::AVOID
        })
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
        Key::FMIN | Key::FMAX => "Hz (steps/s)",
        Key::TIMER_HZ => "Hz",
        Key::ACCEL => "Hz/s",
        Key::MAX_START_HZ => "Hz",
        Key::STEP_ANGLE => "degrees",
        Key::ROTOR_INERTIA | Key::LOAD_INERTIA => "kg·m²",
        Key::FRICTION | Key::HOLDING_TORQUE | Key::DETENT_TORQUE | Key::IRON_LOSS => "N·m",
        Key::DAMPING => "N·m·s/rad",
        Key::RESISTANCE => "Ω",
        Key::INDUCTANCE => "H",
        Key::RATED_CURRENT | Key::DRIVER_CURRENT => "A",
        Key::SUPPLY_VOLTAGE => "V",
        Key::STEP_PULSE | Key::STEP_SPACE | Key::DIR_SETUP => "s",
        Key::CPU_HZ => "Hz",
        Key::AVOID => "full steps/s",
        _ => CURVE_SCHEMAS
            .iter()
            .flat_map(|r| r.units)
            .find(|(k, _)| *k == key)
            .map_or("", |(_, unit)| unit),
    }
}

/// A table's layout: one entry per step, equal-time segments, or runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TableLayout {
    /// One period per step: `[u16; len]`.
    Steps,
    /// `n` equal-time segments of (period, step count): `[(u16, u16); n]`.
    Segments(u32),
    /// Runs of fixed-point periods, each pulse edge within this many ticks
    /// of the curve: `[[u16; 5]; runs]`.
    Runs(f64),
}
