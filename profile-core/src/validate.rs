//! Parameter checks shared by every front end.

use crate::error::{Error, Key};
use crate::spec::{
    Arithmetic, Curve, Discretization, ExponentialExtent, LinearExtent, MAX_LEN, Rounding, Spec,
};

/// The largest `flexible` accepted: the logistic then spans `[-500, 500]`,
/// already a step function at any table length, and `exp` stays finite.
pub const MAX_FLEXIBLE: f64 = 500.0;

fn finite(key: Key, value: f64) -> Result<(), Error> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(Error::NotFinite { key, value })
    }
}

fn positive(key: Key, value: f64) -> Result<(), Error> {
    finite(key, value)?;
    if value <= 0.0 {
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

/// `value > other_value`, both finite.
fn greater(key: Key, value: f64, other: Key, other_value: f64) -> Result<(), Error> {
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
fn range(fmin: f64, fmax: f64) -> Result<(), Error> {
    positive(Key::Fmin, fmin)?;
    greater(Key::Fmax, fmax, Key::Fmin, fmin)
}

/// A ramp whose length follows from its parameters must stay within `MAX_LEN`.
fn derived_len(spec: &Spec, key: Key) -> Result<(), Error> {
    let index = spec.discretization == Discretization::Index;
    let (steps, _) = crate::curves::ramp_steps(&spec.curve, index);
    if !(steps.is_finite() && steps > 0.0 && steps <= MAX_LEN as f64) || spec.len() > MAX_LEN {
        return Err(Error::RampTooLong {
            key,
            steps,
            max: MAX_LEN,
        });
    }
    Ok(())
}

fn curve(spec: &Spec) -> Result<(), Error> {
    match spec.curve {
        Curve::Sigmoid(s) => {
            len(s.len)?;
            range(s.fmin, s.fmax)?;
            positive(Key::Flexible, s.flexible)?;
            if s.flexible > MAX_FLEXIBLE {
                return Err(Error::TooLarge {
                    key: Key::Flexible,
                    value: s.flexible,
                    max: MAX_FLEXIBLE,
                });
            }
        }
        Curve::Exponential(e) => {
            range(e.fmin, e.fmax)?;
            greater(Key::FInf, e.f_inf, Key::Fmax, e.fmax)?;
            match e.extent {
                ExponentialExtent::Len(n) => len(n)?,
                ExponentialExtent::Tau(tau) => {
                    positive(Key::Tau, tau)?;
                    derived_len(spec, Key::Tau)?;
                }
            }
        }
        Curve::Linear(l) => {
            range(l.fmin, l.fmax)?;
            match l.extent {
                LinearExtent::Len(n) => {
                    len(n)?;
                    if n < 2 && spec.discretization == Discretization::Index {
                        return Err(Error::TooSmall {
                            key: Key::Len,
                            value: n as f64,
                            min: 1.0,
                            why: " for a linear ramp over the index: its `len` entries span trans = len - 1 steps",
                        });
                    }
                }
                LinearExtent::Accel(a) => {
                    positive(Key::Accel, a)?;
                    derived_len(spec, Key::Accel)?;
                }
            }
        }
        Curve::ThreeStage(z) => {
            positive(Key::Fmin, z.fmin)?;
            greater(Key::F1, z.f1, Key::Fmin, z.fmin)?;
            finite(Key::F2, z.f2)?;
            if z.f2 < z.f1 {
                return Err(Error::NotAtLeast {
                    key: Key::F2,
                    value: z.f2,
                    other: Key::F1,
                    other_value: z.f1,
                });
            }
            greater(Key::Fmax, z.fmax, Key::F2, z.f2)?;
            positive(Key::Accel, z.accel)?;
            finite(Key::Shape, z.shape)?;
            if z.shape == 0.0 {
                return Err(Error::Zero { key: Key::Shape });
            }
            let min_shape = -z.accel / (z.f1 - z.fmin);
            if z.shape <= min_shape {
                return Err(Error::TooSmall {
                    key: Key::Shape,
                    value: z.shape,
                    min: min_shape,
                    why: ", that is -accel / (f1 - fmin), for a concave start",
                });
            }
            derived_len(spec, Key::Accel)?;
        }
        Curve::JerkLimited(j) => {
            range(j.fmin, j.fmax)?;
            positive(Key::Accel, j.accel)?;
            positive(Key::Jerk, j.jerk)?;
            derived_len(spec, Key::Jerk)?;
        }
    }
    Ok(())
}

fn combination(spec: &Spec) -> Result<(), Error> {
    let index = spec.discretization == Discretization::Index;
    if index && !matches!(spec.curve, Curve::Sigmoid(_) | Curve::Linear(_)) {
        return Err(Error::Unsupported {
            key: Key::Discretization,
            value: "index",
            applies: "to `curve = sigmoid` and `curve = linear`, which are defined over the step index",
        });
    }
    match spec.arithmetic {
        Arithmetic::F64 => {}
        Arithmetic::F32 => {
            if !(index && matches!(spec.curve, Curve::Sigmoid(_))) {
                return Err(Error::Unsupported {
                    key: Key::Arithmetic,
                    value: "f32",
                    applies: "to `curve = sigmoid` with `discretization = index`, as the S-curve article's C function `CalculateSModelLine` computes",
                });
            }
        }
        Arithmetic::Integer => {
            let Curve::Linear(l) = spec.curve else {
                return Err(Error::Unsupported {
                    key: Key::Arithmetic,
                    value: "integer",
                    applies: "to `curve = linear`, as the constant-acceleration article's integer `pulse()` code computes",
                });
            };
            if !index {
                return Err(Error::Unsupported {
                    key: Key::Arithmetic,
                    value: "integer",
                    applies: "with `discretization = index`, as the article's `f[i]` table is built",
                });
            }
            if spec.rounding != Rounding::Truncate {
                return Err(Error::Unsupported {
                    key: Key::Arithmetic,
                    value: "integer",
                    applies: "with `rounding = truncate`: the article's code rounds by integer division",
                });
            }
            if let LinearExtent::Accel(_) = l.extent {
                return Err(Error::Unsupported {
                    key: Key::Arithmetic,
                    value: "integer",
                    applies: "with `len`: the article's integer code takes the step count (trans + 1), not `accel`",
                });
            }
        }
    }
    Ok(())
}

pub(crate) fn validate(spec: &Spec) -> Result<(), Error> {
    curve(spec)?;
    if spec.timer.timer_hz == 0 {
        return Err(Error::TimerZero);
    }
    if !matches!(spec.timer.ticks_per_step, 1 | 2) {
        return Err(Error::TicksPerStep {
            value: spec.timer.ticks_per_step as u64,
        });
    }
    combination(spec)?;
    if spec.arithmetic == Arithmetic::Integer {
        if let Curve::Linear(l) = spec.curve {
            crate::linear::IntegerLinear::new(
                &l,
                spec.len(),
                spec.timer.ticks_per_step,
                spec.timer.timer_hz,
            )?;
        }
    }
    Ok(())
}
