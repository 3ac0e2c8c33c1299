//! The range each of a motor's figures is taken in, one row per key:
//! [`Motor::validate`] and [`Windings::validate`] check them, and the
//! profiles file's check of values no profile reads finds them by key.

use crate::motor::{Motor, MotorError, Windings};
use profile_core::Key;

/// The range a motor's figure is taken in, in the unit of its plain number,
/// and the words that say so. Every stepper motor and driver lies well
/// inside: a figure outside is a mistake (a unit, an exponent), and
/// inside, the check's and the simulation's arithmetic stays finite.
pub(crate) type Bounds = (f64, f64, &'static str);

/// A figure's key, its range and where a motor or windings keep it
/// (`None` for an optional figure not given).
pub(crate) type Row<T> = (Key, Bounds, fn(&T) -> Option<f64>);

/// The motor's own figures, in the order [`Motor::validate`] checks
/// them.
pub(crate) const MOTOR: [Row<Motor>; 8] = [
    (
        Key::STEP_ANGLE,
        (0.01, 180.0, "from 0.01 to 180 degrees"),
        |m| Some(m.step_angle),
    ),
    (
        Key::ROTOR_INERTIA,
        (1e-12, 10.0, "from 1e-12 to 10 kg·m²"),
        |m| Some(m.rotor_inertia),
    ),
    (
        Key::LOAD_INERTIA,
        (0.0, 1e4, "from 0 to 10000 kg·m²"),
        |m| Some(m.load_inertia),
    ),
    (Key::FRICTION, (0.0, 1e4, "from 0 to 10000 N·m"), |m| {
        Some(m.friction)
    }),
    (
        Key::DAMPING,
        (0.0, 1e4, "from 0 to 10000 N·m·s/rad"),
        |m| Some(m.damping),
    ),
    (
        Key::DAMPING_RATIO,
        (
            0.0,
            crate::motor::MAX_DAMPING_RATIO,
            "from 0 to 1, a fraction of critical damping: a motor's own electromagnetic \
             damping is a small fraction of critical, and a larger ratio would drag the \
             model's rotor along with any field",
        ),
        |m| Some(m.damping_ratio),
    ),
    (Key::SAFETY, (1.0, 1000.0, "from 1 to 1000"), |m| {
        Some(m.safety)
    }),
    (
        Key::MAX_START_HZ,
        (1e-3, 1e8, "from 0.001 to 1e8 Hz"),
        |m| m.max_start_hz,
    ),
];

/// The windings' figures, in the order [`Windings::validate`] checks
/// them.
pub(crate) const WINDINGS: [Row<Windings>; 8] = [
    (Key::RESISTANCE, (1e-4, 1e5, "from 1e-4 to 1e5 Ω"), |w| {
        Some(w.resistance)
    }),
    (Key::INDUCTANCE, (1e-8, 100.0, "from 1e-8 to 100 H"), |w| {
        Some(w.inductance)
    }),
    (
        Key::RATED_CURRENT,
        (1e-4, 1000.0, "from 1e-4 to 1000 A"),
        |w| Some(w.rated_current),
    ),
    (
        Key::HOLDING_TORQUE,
        (1e-6, 1e4, "from 1e-6 to 10000 N·m"),
        |w| Some(w.holding_torque),
    ),
    (Key::SUPPLY_VOLTAGE, (0.1, 1e5, "from 0.1 to 1e5 V"), |w| {
        Some(w.supply_voltage)
    }),
    (
        Key::DRIVER_CURRENT,
        (1e-4, 1000.0, "from 1e-4 to 1000 A"),
        |w| w.driver_current,
    ),
    (
        Key::SUPPLY_UTILIZATION,
        (0.05, 1.0, "from 0.05 to 1"),
        |w| Some(w.supply_utilization),
    ),
    (Key::IRON_LOSS, (0.0, 1e4, "from 0 to 10000 N·m"), |w| {
        w.iron_loss
    }),
];

/// A torque curve's frequencies, Hz, and torques, N·m (above 0), as
/// [`MotorError::Curve`]'s message says them.
pub(crate) const CURVE_HZ: f64 = 1e8;
pub(crate) const CURVE_NM: f64 = 1e4;

/// The bounds of a motor key's number, if it is one of these.
pub(crate) fn of(key: Key) -> Option<Bounds> {
    let motor = MOTOR.iter().map(|&(k, b, _)| (k, b));
    let windings = WINDINGS.iter().map(|&(k, b, _)| (k, b));
    motor
        .chain(windings)
        .find(|&(k, _)| k == key)
        .map(|(_, b)| b)
}

/// Checks each row's figure that `figures` hold against its bounds.
pub(crate) fn check<T>(rows: &[Row<T>], figures: &T) -> Result<(), MotorError> {
    for &(key, bounds, read) in rows {
        if let Some(value) = read(figures) {
            within(key, value, bounds)?;
        }
    }
    Ok(())
}

/// `value` of `key` within `bounds`, ends included.
pub(crate) fn within(key: Key, value: f64, bounds: Bounds) -> Result<(), MotorError> {
    let (lo, hi, expected) = bounds;
    if value >= lo && value <= hi {
        Ok(())
    } else {
        Err(MotorError::Invalid {
            key,
            value,
            expected,
        })
    }
}
