//! Numbers in messages: as a user wrote them, to a fixed number of decimals,
//! or to a few significant digits, never three hundred digits long; without
//! allocation.

use core::fmt;

/// A number as a user wrote it: plain between 1e-6 and 1e16 (`500`,
/// `0.25`), in exponent form beyond (`1e308`, `2.5e-9`), so that no message
/// spells out three hundred digits.
pub(crate) struct Num(pub(crate) f64);

impl fmt::Display for Num {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        let magnitude = libm::fabs(v);
        if !v.is_finite() || v == 0.0 || (1e-6..1e16).contains(&magnitude) {
            write!(f, "{v}")
        } else {
            write!(f, "{v:e}")
        }
    }
}

/// A figure to a fixed number of decimals (`0.1799` N·m, `1757.5` Hz), as
/// [`Significant`] where those decimals would read 0 or the number is
/// 1e16 or more (`0.000003`, `2.00152e300`): no message spells out three
/// hundred digits.
pub(crate) struct Fixed(pub(crate) f64, pub(crate) usize);

impl fmt::Display for Fixed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (v, decimals) = (self.0, self.1);
        let smallest = libm::pow(10.0, -(decimals as f64));
        if v == 0.0 || (smallest..1e16).contains(&libm::fabs(v)) {
            write!(f, "{v:.decimals$}")
        } else {
            Significant(v).fmt(f)
        }
    }
}

/// A frequency to two decimals (`152.59`), or to six significant digits
/// where two decimals would read 0 (`0.00232831`).
pub(crate) struct Hundredths(pub(crate) f64);

impl fmt::Display for Hundredths {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        Fixed(self.0, 2).fmt(f)
    }
}

/// A number with at most six significant digits, trailing zeros dropped;
/// in exponent form below 1e-6 and from 1e16 (`1.33333e300`), as [`Num`].
pub(crate) struct Significant(pub(crate) f64);

impl fmt::Display for Significant {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        if v == 0.0 || !v.is_finite() {
            return write!(f, "{v}");
        }
        let exponent = !(1e-6..1e16).contains(&libm::fabs(v));
        let mut buf = [0u8; 64];
        let mut w = Buf {
            buf: &mut buf,
            len: 0,
        };
        if exponent {
            let _ = fmt::write(&mut w, format_args!("{v:.5e}"));
        } else {
            let digits = 5 - libm::floor(libm::log10(libm::fabs(v))) as i32;
            let decimals = digits.clamp(0, 17) as usize;
            let _ = fmt::write(&mut w, format_args!("{v:.decimals$}"));
        }
        let len = w.len;
        let text = core::str::from_utf8(&buf[..len]).unwrap_or("");
        let (mantissa, power) = text.split_at(text.find('e').unwrap_or(text.len()));
        let mantissa = if mantissa.contains('.') {
            mantissa.trim_end_matches('0').trim_end_matches('.')
        } else {
            mantissa
        };
        f.write_str(mantissa)?;
        f.write_str(power)
    }
}

/// A fixed buffer for formatting without allocation.
struct Buf<'a> {
    buf: &'a mut [u8],
    len: usize,
}

impl fmt::Write for Buf<'_> {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        let end = self.len + s.len();
        let dst = self.buf.get_mut(self.len..end).ok_or(fmt::Error)?;
        dst.copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

/// A number as this crate's messages print it, for tools that print
/// figures beside them: [`plain`](MessageNumber::plain) as a user wrote it
/// (`500`, `0.25`, `1e308`), [`fixed`](MessageNumber::fixed) to a number of
/// decimals (`0.1799`), [`significant`](MessageNumber::significant) to six
/// significant digits (`1.33333e300`); never three hundred digits long, and
/// without allocation.
///
/// ```
/// use profile_core::MessageNumber;
///
/// assert_eq!(MessageNumber::plain(64_000.0).to_string(), "64000");
/// assert_eq!(MessageNumber::plain(1e300).to_string(), "1e300");
/// assert_eq!(MessageNumber::fixed(0.17994, 4).to_string(), "0.1799");
/// assert_eq!(MessageNumber::fixed(3e-6, 2).to_string(), "0.000003");
/// assert_eq!(MessageNumber::significant(4.0 / 3.0 * 1e300).to_string(), "1.33333e300");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MessageNumber(Shown);

#[derive(Clone, Copy, Debug, PartialEq)]
enum Shown {
    Plain(f64),
    Fixed(f64, usize),
    Significant(f64),
}

impl MessageNumber {
    /// Plain between 1e-6 and 1e16, in exponent form beyond.
    pub const fn plain(value: f64) -> Self {
        MessageNumber(Shown::Plain(value))
    }

    /// To `decimals` decimals, or as [`significant`](Self::significant)
    /// where they would read 0 or the number is 1e16 or more.
    pub const fn fixed(value: f64, decimals: usize) -> Self {
        MessageNumber(Shown::Fixed(value, decimals))
    }

    /// At most six significant digits, trailing zeros dropped; in exponent
    /// form below 1e-6 and from 1e16.
    pub const fn significant(value: f64) -> Self {
        MessageNumber(Shown::Significant(value))
    }
}

impl fmt::Display for MessageNumber {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            Shown::Plain(v) => Num(v).fmt(f),
            Shown::Fixed(v, decimals) => Fixed(v, decimals).fmt(f),
            Shown::Significant(v) => Significant(v).fmt(f),
        }
    }
}
