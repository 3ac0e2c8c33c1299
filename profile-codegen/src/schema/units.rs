//! Units: which keys take a frequency, a time or one of a motor's
//! quantities, the units each accepts, and numbers written with one
//! (`64kHz`, `"5 ms"`, `3.4mH`, `"68 g·cm²"`) read exactly.
//!
//! A unit scales the number as written, in decimal, before it becomes a
//! float: `64kHz` is the integer 64000, `0.1MHz` the integer 100000 and
//! `2.5ms` the `f64` nearest to 0.0025, as if written so. A table given
//! `fmax = 64kHz` is the table given `fmax = 64_000`.

use std::format;
use std::string::{String, ToString};

use super::suggest::{Hint, did_you_mean, phrase};
use super::{Value, quoted};
use crate::numbers::Num;
use profile_core::Key;

/// What a numeric key measures, when it has a unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Quantity {
    /// A frequency: `Hz`, `kHz`, `MHz`.
    Frequency,
    /// A time: `s`, `ms`, `us`.
    Time,
    /// A driver's pulse or setup time: `s`, `ms`, `us`, `ns`.
    Pulse,
    /// A moment of inertia: `kgm2` (kg·m²), `gcm2` (g·cm², 1e-7 kg·m²).
    Inertia,
    /// A torque: `Nm` (N·m), `Ncm` (N·cm), `mNm` (mN·m).
    Torque,
    /// A resistance: `ohm` (Ω), `mohm` (mΩ).
    Resistance,
    /// An inductance: `H`, `mH`, `uH`.
    Inductance,
    /// A current: `A`, `mA`.
    Current,
    /// A voltage: `V`.
    Voltage,
    /// An angle: `deg` (°).
    Angle,
}

/// Other spellings of units: the symbols a datasheet prints, which a Rust
/// literal's suffix cannot hold but a string can (`"68 g·cm²"`).
const ALIASES: [(&str, &str); 14] = [
    ("µs", "us"),
    ("μs", "us"),
    ("µH", "uH"),
    ("μH", "uH"),
    ("kg·m²", "kgm2"),
    ("g·cm²", "gcm2"),
    ("N·m", "Nm"),
    ("N·cm", "Ncm"),
    ("mN·m", "mNm"),
    ("Ω", "ohm"),
    // U+2126 OHM SIGN, which some keyboards and fonts give for Ω.
    ("\u{2126}", "ohm"),
    ("ohms", "ohm"),
    ("mΩ", "mohm"),
    ("°", "deg"),
];

/// SI prefixes, for a unit no key takes: their names and powers of ten.
/// `K` and `u` are read as the kilo and micro they are written for.
const PREFIXES: [(&str, &str, i32); 18] = [
    ("E", "exa", 18),
    ("P", "peta", 15),
    ("T", "tera", 12),
    ("G", "giga", 9),
    ("M", "mega", 6),
    ("k", "kilo", 3),
    ("K", "kilo", 3),
    ("h", "hecto", 2),
    ("da", "deca", 1),
    ("d", "deci", -1),
    ("c", "centi", -2),
    ("m", "milli", -3),
    ("u", "micro", -6),
    ("µ", "micro", -6),
    ("μ", "micro", -6),
    ("n", "nano", -9),
    ("p", "pico", -12),
    ("f", "femto", -15),
];

impl Quantity {
    /// The units accepted, each with its power of ten, the base unit first.
    pub fn units(self) -> &'static [(&'static str, i32)] {
        match self {
            Quantity::Frequency => &[("Hz", 0), ("kHz", 3), ("MHz", 6)],
            Quantity::Time => &[("s", 0), ("ms", -3), ("us", -6)],
            Quantity::Pulse => &[("s", 0), ("ms", -3), ("us", -6), ("ns", -9)],
            Quantity::Inertia => &[("kgm2", 0), ("gcm2", -7)],
            Quantity::Torque => &[("Nm", 0), ("Ncm", -2), ("mNm", -3)],
            Quantity::Resistance => &[("ohm", 0), ("mohm", -3)],
            Quantity::Inductance => &[("H", 0), ("mH", -3), ("uH", -6)],
            Quantity::Current => &[("A", 0), ("mA", -3)],
            Quantity::Voltage => &[("V", 0)],
            Quantity::Angle => &[("deg", 0)],
        }
    }

    /// The unit a datasheet prints values of this quantity in, with its
    /// power of ten, for a motor's figures; `None` for frequencies and
    /// times, shown in the largest unit that leaves a number of at least 1.
    fn shown_in(self) -> Option<(&'static str, i32)> {
        match self {
            Quantity::Frequency | Quantity::Time | Quantity::Pulse => None,
            Quantity::Inertia => Some(("g·cm²", -7)),
            Quantity::Torque => Some(("N·m", 0)),
            Quantity::Resistance => Some(("Ω", 0)),
            Quantity::Inductance => Some(("mH", -3)),
            Quantity::Current => Some(("A", 0)),
            Quantity::Voltage => Some(("V", 0)),
            Quantity::Angle => Some(("°", 0)),
        }
    }

    /// The power of ten of `unit`, if accepted, written as listed or as
    /// one of its symbols (`µs`, `g·cm²`, `N·m`, `Ω`).
    fn exponent(self, unit: &str) -> Option<i32> {
        let unit = ALIASES
            .iter()
            .find(|(alias, _)| *alias == unit)
            .map_or(unit, |(_, name)| name);
        self.units()
            .iter()
            .find(|(u, _)| *u == unit)
            .map(|(_, e)| *e)
    }

    /// What `unit`, refused, reads as: the base unit in any case (`hz`,
    /// `S`) or an SI prefix on it (`mHz`, `ns`, `MNm`, `kΩ`), with the
    /// prefix and its power of ten; `None` when it is neither.
    fn scale(self, unit: &str) -> Option<(Option<(&'static str, &'static str)>, i32)> {
        let base = self.units()[0].0;
        let is_base = |u: &str| {
            u.eq_ignore_ascii_case(base)
                || ALIASES
                    .iter()
                    .any(|(alias, name)| *name == base && alias.eq_ignore_ascii_case(u))
        };
        if is_base(unit) {
            return Some((None, 0));
        }
        PREFIXES
            .iter()
            .find(|(p, _, _)| unit.strip_prefix(p).is_some_and(is_base))
            .map(|&(p, name, e)| (Some((p, name)), e))
    }

    /// What to add to the refusal of `unit`: the accepted unit of the same
    /// scale (`KHz` is `kHz`, `cNm` is `Ncm`), or that its prefix is not
    /// accepted (`mHz` is not `MHz`, `ns` not `ms`); for a unit of no
    /// known scale, the nearest in spelling.
    fn hint(self, unit: &str) -> String {
        let Some((prefix, exponent)) = self.scale(unit) else {
            return did_you_mean(unit, self.units().iter().map(|(u, _)| *u), Hint::After);
        };
        match (self.units().iter().find(|(_, e)| *e == exponent), prefix) {
            (Some((same, _)), _) => phrase(same, Hint::After),
            (None, Some((p, name))) => {
                format!("; the prefix `{p}` ({name}, 1e{exponent}) is not accepted")
            }
            (None, None) => String::new(),
        }
    }

    /// The accepted units, for messages, each with the symbol a datasheet
    /// prints where it has one: `` `Hz`, `kHz`, `MHz` ``,
    /// `` `kgm2` (`kg·m²`), `gcm2` (`g·cm²`) ``.
    pub fn listed(self) -> String {
        let symbol = |unit: &str| {
            ALIASES
                .iter()
                .find(|(alias, name)| *name == unit && !alias.is_ascii())
                .map_or(String::new(), |(alias, _)| format!(" (`{alias}`)"))
        };
        self.units()
            .iter()
            .map(|(u, _)| format!("{}{}", quoted([u]), symbol(u)))
            .collect::<std::vec::Vec<_>>()
            .join(", ")
    }
}

/// What `key` measures, if it takes a unit: read off the unit it is given
/// in.
pub fn quantity(key: Key) -> Option<Quantity> {
    if super::keys::DRIVER_TIMING.contains(&key) {
        return Some(Quantity::Pulse);
    }
    match super::unit(key) {
        "Hz" | "Hz (steps/s)" => Some(Quantity::Frequency),
        "s" => Some(Quantity::Time),
        "kg·m²" => Some(Quantity::Inertia),
        "N·m" => Some(Quantity::Torque),
        "Ω" => Some(Quantity::Resistance),
        "H" => Some(Quantity::Inductance),
        "A" => Some(Quantity::Current),
        "V" => Some(Quantity::Voltage),
        "degrees" => Some(Quantity::Angle),
        _ => None,
    }
}

/// Rust's numeric type suffixes, which a key refuses as such.
const TYPE_SUFFIXES: [&str; 14] = [
    "u8", "u16", "u32", "u64", "u128", "usize", "i8", "i16", "i32", "i64", "i128", "isize", "f32",
    "f64",
];

/// The value of `number` (decimal, as written: sign, digits, point,
/// exponent, no `_`) in `unit`, as `key` reads it, or what is wrong;
/// `written` is the value as the user wrote it, for messages.
pub fn with_unit(key: Key, number: &str, unit: &str, written: &str) -> Result<Value, String> {
    let got = format!("`{written}`");
    if TYPE_SUFFIXES.contains(&unit) {
        let units = quantity(key).map_or(String::new(), |q| {
            format!(", or with a unit ({})", q.listed())
        });
        return Err(format!(
            "`{key}` takes a number without a type suffix (got {got}): write `{number}`{units}"
        ));
    }
    let Some(q) = quantity(key) else {
        let plain = match super::unit(key) {
            "" => String::new(),
            u => format!(" (in {u})"),
        };
        return Err(format!(
            "`{key}` takes a plain number{plain}, without a unit (got {got})"
        ));
    };
    let Some(exponent) = q.exponent(unit) else {
        let hint = q.hint(unit);
        let units = if q.units().len() == 1 {
            "unit"
        } else {
            "units"
        };
        return Err(format!(
            "`{key}` accepts the {units} {} (got {got}){hint}",
            q.listed()
        ));
    };
    scaled(number, exponent).map_err(|why| match why {
        Unscaled::NotANumber => format!("`{key}` expects a number, got {got}"),
        Unscaled::Digits(digits) => super::too_many_digits(key.name(), digits),
        Unscaled::TooLarge => format!(
            "`{key}` is too large for a 64-bit float (at most about 1.8e308 {}), got {got}",
            q.units()[0].0
        ),
    })
}

/// Why a number with a unit was not read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unscaled {
    /// It is not a decimal number.
    NotANumber,
    /// It is written with this many digits, more than
    /// [`MAX_DIGITS`](super::MAX_DIGITS).
    Digits(usize),
    /// It is beyond the largest `f64` once scaled.
    TooLarge,
}

/// `number` times `10^exponent`, shifted in decimal: an integer when the
/// result is one, else the nearest `f64` (0 for an exponent far below
/// any float's); or why it cannot be read.
pub fn scaled(number: &str, exponent: i32) -> Result<Value, Unscaled> {
    let (negative, rest) = match number.strip_prefix('-') {
        Some(r) => (true, r),
        None => (false, number.strip_prefix('+').unwrap_or(number)),
    };
    let (mantissa, exp10) = match rest.find(['e', 'E']) {
        Some(i) => (
            &rest[..i],
            power(&rest[i + 1..]).ok_or(Unscaled::NotANumber)?,
        ),
        None => (rest, 0),
    };
    let (int, written_frac) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    // `10.0MHz` is the whole number it reads as.
    let frac = written_frac.trim_end_matches('0');
    let digits_ok = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if int.is_empty() && mantissa.len() < 2 || !digits_ok(int) || !digits_ok(frac) {
        return Err(Unscaled::NotANumber);
    }
    if int.len() + frac.len() > super::MAX_DIGITS {
        return Err(Unscaled::Digits(int.len() + written_frac.len()));
    }
    let digits = match format!("{int}{frac}") {
        d if d.is_empty() => "0".to_string(),
        d => d,
    };
    // Within `power`'s bounds, far past any float's either way.
    let shift = exp10 + exponent - frac.len() as i32;
    let sign = if negative { "-" } else { "" };
    let trimmed = digits.trim_start_matches('0');
    if (0..=38).contains(&shift) && trimmed.len() + shift as usize <= 38 {
        let whole = format!("{sign}{}{}", digits, "0".repeat(shift as usize));
        return whole
            .parse::<i128>()
            .map(Value::Int)
            .map_err(|_| Unscaled::NotANumber);
    }
    let v: f64 = format!("{sign}{digits}e{shift}")
        .parse()
        .map_err(|_| Unscaled::NotANumber)?;
    if v.is_finite() {
        Ok(Value::Float(v))
    } else {
        Err(Unscaled::TooLarge)
    }
}

/// An exponent's digits (`5`, `-3`, `+40000000000`), held within a
/// million either way: far past any float's, so that adding to it cannot
/// overflow. `None` when it is not a whole number.
fn power(text: &str) -> Option<i32> {
    const FAR: i32 = 1_000_000;
    let digits = text.strip_prefix(['+', '-']).unwrap_or(text);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let far = if text.starts_with('-') { -FAR } else { FAR };
    Some(text.parse::<i32>().map_or(far, |e| e.clamp(-FAR, FAR)))
}

/// `"64 kHz"`, `"5ms"`, `"64_000 Hz"`: a string read as a number and a
/// unit, split; `None` when it does not start with a number followed by
/// letters. The number keeps its `_` separators.
pub fn split(text: &str) -> Option<(&str, &str)> {
    let text = text.trim();
    let bytes = text.as_bytes();
    let mut i = 0;
    let mut seen_digit = false;
    let mut seen_e = false;
    while i < bytes.len() {
        let b = bytes[i];
        let sign_ok = i == 0 || (seen_e && matches!(bytes[i - 1], b'e' | b'E'));
        match b {
            b'0'..=b'9' => seen_digit = true,
            // A digit separator between two digits, as in TOML's numbers:
            // `64_000 Hz`, not `64__000` nor `64000_`.
            b'_' if i > 0
                && bytes[i - 1].is_ascii_digit()
                && bytes.get(i + 1).is_some_and(u8::is_ascii_digit) => {}
            b'.' if !seen_e => {}
            b'+' | b'-' if sign_ok => {}
            // An exponent only when a digit follows it, so `5 e` is not one.
            b'e' | b'E'
                if seen_digit
                    && !seen_e
                    && bytes
                        .get(i + 1)
                        .is_some_and(|n| n.is_ascii_digit() || *n == b'+' || *n == b'-') =>
            {
                seen_e = true
            }
            _ => break,
        }
        i += 1;
    }
    let (number, unit) = (&text[..i], text[i..].trim_start());
    let letters = !unit.is_empty() && !unit.contains(char::is_whitespace);
    (seen_digit && letters && unit.starts_with(|c: char| !c.is_ascii_digit()))
        .then_some((number, unit))
}

/// `v` of `key` as a user would write it: `64 kHz`, `10 MHz`, `5 ms`,
/// `1500 Hz/s`; the largest unit that leaves a number of at least 1. A
/// value beyond 1e16 or below 1e-6 in the base unit in exponent form
/// (`1e200 Hz/s`), not hundreds of digits. A motor's figures in the units
/// datasheets print: `68 g·cm²`, `0.4 N·m`, `0.6 mH`, `1.8°`.
pub fn show(key: Key, v: f64) -> String {
    let plain = Num(v).to_string();
    if let Some((unit, exponent)) = quantity(key).and_then(Quantity::shown_in) {
        let shown = shift_exponent(&plain, -exponent);
        let space = if unit == "°" { "" } else { " " };
        return format!("{shown}{space}{unit}");
    }
    if plain.contains('e') {
        let unit = match quantity(key) {
            Some(q) => q.units()[0].0,
            None => super::unit(key).split(' ').next().unwrap_or(""),
        };
        return if unit.is_empty() {
            plain
        } else {
            format!("{plain} {unit}")
        };
    }
    let Some(q) = quantity(key) else {
        return match super::unit(key) {
            "" => plain,
            unit => format!("{plain} {}", unit.split(' ').next().unwrap_or(unit)),
        };
    };
    let abs = v.abs();
    let base = q.units()[0];
    let (unit, exponent) = q
        .units()
        .iter()
        .copied()
        .filter(|(_, e)| abs >= 10f64.powi(*e))
        .max_by_key(|(_, e)| *e)
        .unwrap_or(base);
    let shown = shift_decimal(&plain, -exponent).unwrap_or(plain);
    format!("{shown} {unit}")
}

/// The decimal text `s`, in exponent form or not (as [`Num`] writes it),
/// times `10^k`: without an exponent where the result lies within 1e-6 to
/// 1e16, as [`Num`] writes such numbers.
fn shift_exponent(s: &str, k: i32) -> String {
    let (mantissa, exponent) = match s.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (s, 0),
    };
    let exponent = exponent.saturating_add(k);
    if (-6..=16).contains(&exponent) {
        shift_decimal(mantissa, exponent).unwrap_or_else(|| s.to_string())
    } else {
        format!("{mantissa}e{exponent}")
    }
}

/// The decimal text `s` (no exponent, as `f64`'s `Display` writes) times
/// `10^k`, written without trailing zeros after a point.
fn shift_decimal(s: &str, k: i32) -> Option<String> {
    let (sign, rest) = match s.strip_prefix('-') {
        Some(r) => ("-", r),
        None => ("", s),
    };
    let (int, frac) = rest.split_once('.').unwrap_or((rest, ""));
    let digits = format!("{int}{frac}");
    let point = i64::try_from(int.len()).ok()? + i64::from(k);
    // A point before the first digit: zeros in front of them.
    let lead = (1 - point).max(0);
    let digits = format!("{}{digits}", "0".repeat(usize::try_from(lead).ok()?));
    let point = usize::try_from(point + lead).ok()?;
    let digits = if point > digits.len() {
        format!("{digits}{}", "0".repeat(point - digits.len()))
    } else {
        digits
    };
    let (whole, fraction) = digits.split_at(point);
    let whole = whole.trim_start_matches('0');
    let whole = if whole.is_empty() { "0" } else { whole };
    let fraction = fraction.trim_end_matches('0');
    Some(if fraction.is_empty() {
        format!("{sign}{whole}")
    } else {
        format!("{sign}{whole}.{fraction}")
    })
}

/// A torque curve's frequency (in Hz) or torque (in N·m) written
/// `number` `unit` (`written` as the source has it, for messages), or what
/// is wrong.
pub fn curve_point(
    key: &str,
    q: Quantity,
    number: &str,
    unit: &str,
    written: &str,
) -> Result<f64, String> {
    let (what, one) = match q {
        Quantity::Frequency => ("frequencies", "frequency"),
        _ => ("torques", "torque"),
    };
    let Some(exponent) = q.exponent(unit) else {
        let hint = q.hint(unit);
        return Err(format!(
            "`{key}` {what} accept the units {} (got `{written}`){hint}",
            q.listed()
        ));
    };
    match scaled(number, exponent) {
        Ok(Value::Int(v)) => Ok(v as f64),
        Ok(Value::Float(v)) => Ok(v),
        Err(Unscaled::Digits(digits)) => Err(super::too_many_digits(key, digits)),
        Err(Unscaled::TooLarge) => Err(format!(
            "`{key}` has a {one} too large for a 64-bit float (at most about 1.8e308 \
             {}), got `{written}`",
            q.units()[0].0
        )),
        _ => Err(not_a_point(key, q, &format!("`{written}`"))),
    }
}

/// What the pairs of `key`'s list hold, if it takes a list of pairs: a
/// torque curve's (step frequency, torque), resonance bands' (lowest,
/// highest frequency).
pub fn pair(key: &str) -> Option<(Quantity, Quantity)> {
    if key == Key::TORQUE_CURVE.name() {
        Some((Quantity::Frequency, Quantity::Torque))
    } else if key == Key::AVOID.name() {
        Some((Quantity::Frequency, Quantity::Frequency))
    } else {
        None
    }
}

/// The message for a pair's frequency (`q` a frequency) or torque that is
/// not a number, in `key`'s list; `got` is what it is: `` `"fast"` ``, `an
/// array`.
pub fn not_a_point(key: &str, q: Quantity, got: &str) -> String {
    let (what, examples) = match q {
        Quantity::Frequency => ("frequencies", "`1000`, `\"1 kHz\"`"),
        _ => ("torques", "`0.4`, `\"40 N·cm\"`"),
    };
    format!("`{key}` {what} are numbers, with or without a unit ({examples}), got {got}")
}

#[cfg(test)]
#[path = "units_tests.rs"]
mod tests;
