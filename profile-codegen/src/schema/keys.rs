//! The schema's lists of keys: the common ones, the motor's, every key in
//! documentation order, and the key a name spells. The keys themselves are
//! `profile-core`'s ([`Key`]).

use std::vec::Vec;

use profile_core::Key;

use super::curve_keys;

/// The keys every curve takes, after the curve's own, in documentation
/// order (the motor's keys aside).
pub(crate) const COMMON: &[Key] = &[
    Key::TIMER_HZ,
    Key::WORD,
    Key::TICKS_PER_STEP,
    Key::RELOAD_OFFSET,
    Key::DISCRETIZATION,
    Key::ROUNDING,
    Key::ARITHMETIC,
    Key::SEGMENTS,
    Key::COMPRESS,
    Key::MOTOR,
    Key::DRIVER,
    Key::STEP_PULSE,
    Key::STEP_SPACE,
    Key::DIR_SETUP,
    Key::CORE,
    Key::CPU_HZ,
    Key::CPU_LOAD,
    Key::AXES,
    Key::AVOID,
];

/// The keys of the step interrupt's budget (`core` and `cpu_hz` name it).
pub(crate) const BUDGET: [Key; 4] = [Key::CORE, Key::CPU_HZ, Key::CPU_LOAD, Key::AXES];

/// The keys of the step driver's timing (`driver` names a preset of them).
pub(crate) const DRIVER_TIMING: [Key; 3] = [Key::STEP_PULSE, Key::STEP_SPACE, Key::DIR_SETUP];

/// The keys that describe a motor (all but `motor` itself).
pub(crate) const MOTOR_KEYS: &[Key] = &[
    Key::STEP_ANGLE,
    Key::MICROSTEPS,
    Key::ROTOR_INERTIA,
    Key::LOAD_INERTIA,
    Key::TORQUE_CURVE,
    Key::FRICTION,
    Key::DAMPING,
    Key::DAMPING_RATIO,
    Key::SAFETY,
    Key::MAX_START_HZ,
    Key::RESISTANCE,
    Key::INDUCTANCE,
    Key::RATED_CURRENT,
    Key::HOLDING_TORQUE,
    Key::SUPPLY_VOLTAGE,
    Key::DETENT_TORQUE,
    Key::DRIVE,
    Key::DRIVER_CURRENT,
    Key::DRIVER_CURRENT_IS,
    Key::SUPPLY_UTILIZATION,
    Key::IRON_LOSS,
];

/// The keys of [`MOTOR_KEYS`] that describe the motor's body, before its
/// windings.
const BODY_KEYS: usize = 10;

/// The keys that describe a motor's windings, from which its pull-out
/// curve is derived ([`Windings`](crate::motor::Windings)) and the driver
/// behind them: the first five are required together, the rest have
/// defaults. The last keys of [`MOTOR_KEYS`].
pub(crate) const WINDINGS_KEYS: &[Key] = MOTOR_KEYS.split_at(BODY_KEYS).1;

/// Whether `key` describes a motor.
pub(crate) fn is_motor(key: Key) -> bool {
    MOTOR_KEYS.contains(&key)
}

/// Every key, in the order documentation lists them: `curve`, each curve's
/// own keys (in the order of the curves), the common keys, the motor's.
pub fn all() -> Vec<Key> {
    let mut keys = Vec::from([Key::CURVE]);
    keys.extend(curve_keys());
    keys.extend_from_slice(COMMON);
    keys.extend_from_slice(MOTOR_KEYS);
    keys
}

/// The key spelled `name`, if there is one.
pub(crate) fn from_name(name: &str) -> Option<Key> {
    all().into_iter().find(|k| k.name() == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_windings_keys_follow_the_body_s() {
        assert_eq!(MOTOR_KEYS[BODY_KEYS - 1], Key::MAX_START_HZ);
        assert_eq!(WINDINGS_KEYS[0], Key::RESISTANCE);
        assert_eq!(WINDINGS_KEYS.last(), Some(&Key::IRON_LOSS));
    }

    #[test]
    fn every_key_is_listed_once() {
        let keys = all();
        for (i, k) in keys.iter().enumerate() {
            assert!(!keys[..i].contains(k), "{k} twice");
        }
        assert_eq!(from_name("flexible"), Some(Key::FLEXIBLE));
        assert_eq!(from_name("flexibel"), None);
    }
}
