//! Checks the curves share: numbers finite, positive, in order; lengths in range.

use crate::base::MAX_LEN;
use crate::base::error::Error;
use crate::base::key::Key;

pub(crate) fn finite(key: Key, value: f64) -> Result<(), Error> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::NotFinite { key, value })
    }
}

/// Greater than 0 and a normal float: a subnormal one (below 2.2e-308)
/// has lost its precision, and the curves' arithmetic with it.
pub(crate) fn positive(key: Key, value: f64) -> Result<(), Error> {
    finite(key, value)?;
    if value < f64::MIN_POSITIVE {
        Err(Error::NotPositive { key, value })
    } else {
        Ok(())
    }
}

/// `len` from 1 to [`MAX_LEN`].
pub(crate) fn len(len: u32) -> Result<(), Error> {
    match len {
        0 => Err(Error::LenZero),
        n if n > MAX_LEN => Err(Error::LenTooLarge {
            len: n as u64,
            max: MAX_LEN,
        }),
        _ => Ok(()),
    }
}

/// `value > other_value`, both finite.
pub(crate) fn greater(key: Key, value: f64, other: Key, other_value: f64) -> Result<(), Error> {
    finite(key, value)?;
    if value > other_value {
        Ok(())
    } else {
        Err(Error::NotGreater {
            key,
            value,
            other,
            other_value,
        })
    }
}

/// `fmin > 0` and `fmax > fmin`.
pub(crate) fn range(fmin: f64, fmax: f64) -> Result<(), Error> {
    positive(Key::FMIN, fmin)?;
    greater(Key::FMAX, fmax, Key::FMIN, fmin)
}
