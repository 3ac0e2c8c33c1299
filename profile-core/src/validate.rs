//! Parameter checks shared by every front end.

use crate::error::{Error, Key};
use crate::spec::{Arithmetic, Curve, Discretization, MAX_LEN, Spec};

/// The largest `flexible` accepted: the logistic then spans `[-500, 500]`,
/// already a step function at any table length, and `exp` stays finite.
pub const MAX_FLEXIBLE: f64 = 500.0;

fn positive(key: Key, value: f64) -> Result<(), Error> {
    if !value.is_finite() {
        Err(Error::NotFinite { key, value })
    } else if value <= 0.0 {
        Err(Error::NotPositive { key, value })
    } else {
        Ok(())
    }
}

fn len(len: u32) -> Result<(), Error> {
    match len {
        0 => Err(Error::LenZero),
        n if n > MAX_LEN => Err(Error::LenTooLarge {
            len: n as u64,
            max: MAX_LEN,
        }),
        _ => Ok(()),
    }
}

fn greater(key: Key, value: f64, other: Key, other_value: f64) -> Result<(), Error> {
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

pub(crate) fn validate(spec: &Spec) -> Result<(), Error> {
    match spec.curve {
        Curve::Sigmoid(s) => {
            len(s.len)?;
            positive(Key::Fmin, s.fmin)?;
            positive(Key::Fmax, s.fmax)?;
            greater(Key::Fmax, s.fmax, Key::Fmin, s.fmin)?;
            positive(Key::Flexible, s.flexible)?;
            if s.flexible > MAX_FLEXIBLE {
                return Err(Error::TooLarge {
                    key: Key::Flexible,
                    value: s.flexible,
                    max: MAX_FLEXIBLE,
                });
            }
        }
    }
    if spec.timer.timer_hz == 0 {
        return Err(Error::TimerZero);
    }
    if !matches!(spec.timer.ticks_per_step, 1 | 2) {
        return Err(Error::TicksPerStep {
            value: spec.timer.ticks_per_step as u64,
        });
    }
    if spec.arithmetic == Arithmetic::F32 && spec.discretization != Discretization::Index {
        return Err(Error::Unsupported {
            key: Key::Arithmetic,
            value: "f32",
            applies: "with `discretization = index`, the arithmetic of seed 000's C code",
        });
    }
    Ok(())
}
