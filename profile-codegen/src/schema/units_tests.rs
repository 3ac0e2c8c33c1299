//! Units: reading numbers with units, the units each key takes, and how
//! values are shown.

use super::*;

#[test]
fn units_scale_in_decimal() {
    assert_eq!(scaled("64", 3), Ok(Value::Int(64_000)));
    assert_eq!(scaled("0.1", 6), Ok(Value::Int(100_000)));
    assert_eq!(scaled("2.5e3", 0), Ok(Value::Int(2_500)));
    assert_eq!(scaled("-1.5", 3), Ok(Value::Int(-1_500)));
    assert_eq!(scaled("2.5", -3), Ok(Value::Float(0.0025)));
    assert_eq!(scaled("5", -6), Ok(Value::Float(5e-6)));
    assert_eq!(scaled("1e400", 0), Err(Unscaled::TooLarge));
    assert_eq!(scaled("1e306", 3), Err(Unscaled::TooLarge));
    assert_eq!(scaled("1e40000000000", 0), Err(Unscaled::TooLarge));
    assert_eq!(scaled("1e-40000000000", 0), Ok(Value::Float(0.0)));
    assert_eq!(scaled("0e40000000000", 0), Ok(Value::Float(0.0)));
    assert_eq!(scaled("x", 0), Err(Unscaled::NotANumber));
    assert_eq!(scaled(".", 0), Err(Unscaled::NotANumber));
    assert_eq!(scaled("1e", 0), Err(Unscaled::NotANumber));
    assert_eq!(scaled(&"1".repeat(44), 0), Err(Unscaled::Digits(44)));
    assert_eq!(scaled("9e38", 0), Ok(Value::Float(9e38)));
}

#[test]
fn a_number_too_long_or_too_large_says_so() {
    let long = "12345678901234567890123456789012345678901234";
    assert_eq!(
        with_unit(Key::FMAX, long, "Hz", &format!("{long} Hz")),
        Err(
            "`fmax` has a number of 44 digits, more than the 40 any key takes: write it with an \
             exponent, as in `1.5e9`"
                .into()
        )
    );
    assert_eq!(
        with_unit(Key::FMAX, "1e306", "MHz", "1e306 MHz"),
        Err(
            "`fmax` is too large for a 64-bit float (at most about 1.8e308 Hz), got `1e306 MHz`"
                .into()
        )
    );
    assert_eq!(
        with_unit(Key::TAU, "5", "ms", "5 ms"),
        Ok(Value::Float(0.005))
    );
    assert_eq!(
        curve_point("torque_curve", Quantity::Frequency, long, "kHz", "x"),
        Err(
            "`torque_curve` has a number of 44 digits, more than the 40 any key takes: write it \
             with an exponent, as in `1.5e9`"
                .into()
        )
    );
    assert_eq!(
        curve_point("torque_curve", Quantity::Torque, "1e400", "Nm", "1e400 Nm"),
        Err(
            "`torque_curve` has a torque too large for a 64-bit float (at most about 1.8e308 \
             Nm), got `1e400 Nm`"
                .into()
        )
    );
}

#[test]
fn keys_accept_their_units_only() {
    assert_eq!(
        with_unit(Key::FMAX, "64", "kHz", "64kHz"),
        Ok(Value::Int(64_000))
    );
    assert_eq!(
        with_unit(Key::TIMER_HZ, "10", "MHz", "10MHz"),
        Ok(Value::Int(10_000_000))
    );
    assert_eq!(
        with_unit(Key::FMIN, "500", "Hz", "500Hz"),
        Ok(Value::Int(500))
    );
    assert_eq!(
        with_unit(Key::FMAX, "64", "kHz2", "64kHz2"),
        Err(
            "`fmax` accepts the units `Hz`, `kHz`, `MHz` (got `64kHz2`); did you mean `kHz`?"
                .into()
        )
    );
    assert_eq!(
        with_unit(Key::FMIN, "500", "u32", "500u32"),
        Err(
            "`fmin` takes a number without a type suffix (got `500u32`): write `500`, or \
             with a unit (`Hz`, `kHz`, `MHz`)"
                .into()
        )
    );
    assert_eq!(
        with_unit(Key::LEN, "1000", "usize", "1000usize"),
        Err("`len` takes a number without a type suffix (got `1000usize`): write `1000`".into())
    );
    assert_eq!(
        with_unit(Key::ACCEL, "5", "kHz", "5kHz"),
        Err("`accel` takes a plain number (in Hz/s), without a unit (got `5kHz`)".into())
    );
}

#[test]
fn a_motors_keys_take_the_units_of_its_datasheet() {
    let read = |key, number, unit: &str| with_unit(key, number, unit, "");
    assert_eq!(read(Key::INDUCTANCE, "3.4", "mH"), Ok(Value::Float(0.0034)));
    assert_eq!(read(Key::INDUCTANCE, "850", "µH"), Ok(Value::Float(850e-6)));
    assert_eq!(
        read(Key::ROTOR_INERTIA, "68", "gcm2"),
        Ok(Value::Float(6.8e-6))
    );
    assert_eq!(
        read(Key::LOAD_INERTIA, "200", "g·cm²"),
        Ok(Value::Float(2e-5))
    );
    assert_eq!(read(Key::LOAD_INERTIA, "2", "kg·m²"), Ok(Value::Int(2)));
    assert_eq!(
        read(Key::HOLDING_TORQUE, "40", "Ncm"),
        Ok(Value::Float(0.4))
    );
    assert_eq!(
        read(Key::DETENT_TORQUE, "15", "mN·m"),
        Ok(Value::Float(0.015))
    );
    assert_eq!(read(Key::FRICTION, "0.02", "N·m"), Ok(Value::Float(0.02)));
    assert_eq!(read(Key::RESISTANCE, "0.88", "Ω"), Ok(Value::Float(0.88)));
    assert_eq!(
        read(Key::RESISTANCE, "0.88", "\u{2126}"),
        Ok(Value::Float(0.88))
    );
    assert_eq!(
        read(Key::RATED_CURRENT, "4200", "mA"),
        Ok(Value::Float(4.2))
    );
    assert_eq!(read(Key::SUPPLY_VOLTAGE, "36", "V"), Ok(Value::Int(36)));
    assert_eq!(read(Key::STEP_ANGLE, "1.8", "°"), Ok(Value::Float(1.8)));
    assert_eq!(
        with_unit(Key::INDUCTANCE, "3.4", "mh", "3.4mh"),
        Err(
            "`inductance` accepts the units `H`, `mH`, `uH` (`µH`) (got `3.4mh`); did you mean `mH`?"
                .into()
        )
    );
    assert_eq!(
        with_unit(Key::ROTOR_INERTIA, "68", "gcm²", "68 gcm²"),
        Err("`rotor_inertia` accepts the units `kgm2` (`kg·m²`), `gcm2` (`g·cm²`) (got `68 gcm²`); did you mean `gcm2`?".into())
    );
    // A torque is not a current, nor an inertia a torque.
    assert!(read(Key::HOLDING_TORQUE, "2.8", "A").is_err());
    assert!(read(Key::ROTOR_INERTIA, "0.4", "Nm").is_err());
    assert_eq!(
        with_unit(Key::DAMPING, "1", "mNms", "1mNms"),
        Err("`damping` takes a plain number (in N·m·s/rad), without a unit (got `1mNms`)".into())
    );
}

#[test]
fn a_suggestion_keeps_the_scale() {
    let hint = |key, unit: &str| {
        let message = with_unit(key, "1", unit, "").unwrap_err();
        message.split(" (got ``)").nth(1).unwrap_or("").to_string()
    };
    // A case fix where the prefix means the same.
    assert_eq!(hint(Key::FMAX, "KHz"), "; did you mean `kHz`?");
    assert_eq!(hint(Key::FMAX, "khz"), "; did you mean `kHz`?");
    assert_eq!(hint(Key::FMAX, "hz"), "; did you mean `Hz`?");
    assert_eq!(hint(Key::INDUCTANCE, "mh"), "; did you mean `mH`?");
    assert_eq!(hint(Key::INDUCTANCE, "UH"), "; did you mean `uH`?");
    assert_eq!(hint(Key::FRICTION, "mnm"), "; did you mean `mNm`?");
    // The same scale spelt otherwise: cN·m is N·cm.
    assert_eq!(hint(Key::FRICTION, "cNm"), "; did you mean `Ncm`?");
    // Never a unit a thousand or a billion times off.
    assert_eq!(
        hint(Key::FMIN, "mHz"),
        "; the prefix `m` (milli, 1e-3) is not accepted"
    );
    assert_eq!(
        hint(Key::FMIN, "mhz"),
        "; the prefix `m` (milli, 1e-3) is not accepted"
    );
    assert_eq!(
        hint(Key::FRICTION, "MNm"),
        "; the prefix `M` (mega, 1e6) is not accepted"
    );
    assert_eq!(
        hint(Key::TAU, "ns"),
        "; the prefix `n` (nano, 1e-9) is not accepted"
    );
    assert_eq!(
        hint(Key::TAU, "Ms"),
        "; the prefix `M` (mega, 1e6) is not accepted"
    );
    assert_eq!(
        hint(Key::TAU, "MS"),
        "; the prefix `M` (mega, 1e6) is not accepted"
    );
    assert_eq!(
        hint(Key::RESISTANCE, "kΩ"),
        "; the prefix `k` (kilo, 1e3) is not accepted"
    );
    assert_eq!(
        hint(Key::SUPPLY_VOLTAGE, "kV"),
        "; the prefix `k` (kilo, 1e3) is not accepted"
    );
    // A typo of no known scale: the nearest unit, as before.
    assert_eq!(hint(Key::FMAX, "kHz2"), "; did you mean `kHz`?");
    assert_eq!(hint(Key::FRICTION, "N.cm"), "; did you mean `Ncm`?");
    assert_eq!(hint(Key::TAU, "min"), "");
    // The torque curve's points say the same.
    assert_eq!(
        curve_point("torque_curve", Quantity::Torque, "20", "MNm", "20 MNm"),
        Err(
            "`torque_curve` torques accept the units `Nm` (`N·m`), `Ncm` (`N·cm`), `mNm` \
             (`mN·m`) (got `20 MNm`); the prefix `M` (mega, 1e6) is not accepted"
                .into()
        )
    );
    assert_eq!(
        curve_point("torque_curve", Quantity::Frequency, "2", "mhz", "2 mhz"),
        Err(
            "`torque_curve` frequencies accept the units `Hz`, `kHz`, `MHz` (got `2 mhz`); \
             the prefix `m` (milli, 1e-3) is not accepted"
                .into()
        )
    );
}

#[test]
fn strings_split_into_number_and_unit() {
    assert_eq!(split("64 kHz"), Some(("64", "kHz")));
    assert_eq!(split(" 5ms "), Some(("5", "ms")));
    assert_eq!(split("1.5e3 Hz"), Some(("1.5e3", "Hz")));
    assert_eq!(split("5 min"), Some(("5", "min")));
    assert_eq!(split("5e"), Some(("5", "e")));
    assert_eq!(split("64000"), None);
    assert_eq!(split("kHz"), None);
    assert_eq!(split("8 000"), None);
    assert_eq!(split("5 k Hz"), None);
    assert_eq!(split("64_000 Hz"), Some(("64_000", "Hz")));
    assert_eq!(split("1_000_000Hz"), Some(("1_000_000", "Hz")));
    assert_eq!(split("64__000 Hz"), None);
    assert_eq!(split("64000_ Hz"), None);
}

#[test]
fn values_show_in_the_largest_unit() {
    assert_eq!(show(Key::FMAX, 64_000.0), "64 kHz");
    assert_eq!(show(Key::FMIN, 500.0), "500 Hz");
    assert_eq!(show(Key::TIMER_HZ, 10_000_000.0), "10 MHz");
    assert_eq!(show(Key::TIMER_HZ, 2_500_000.0), "2.5 MHz");
    assert_eq!(show(Key::FMIN, 0.5), "0.5 Hz");
    assert_eq!(show(Key::FMIN, 0.0), "0 Hz");
    assert_eq!(show(Key::ACCEL, 1500.0), "1500 Hz/s");
    assert_eq!(show(Key::LEN, 1000.0), "1000");
    assert_eq!(show(Key::TAU, 0.005), "5 ms");
    assert_eq!(show(Key::ACCEL, 1e200), "1e200 Hz/s");
    assert_eq!(show(Key::FMAX, 2.5e-9), "2.5e-9 Hz");
    assert_eq!(show(Key::TAU, 1e20), "1e20 s");
    assert_eq!(show(Key::TAU, 2.0), "2 s");
    assert_eq!(show(Key::TAU, 0.0000125), "12.5 us");
    // A motor's figures in a datasheet's units.
    assert_eq!(show(Key::ROTOR_INERTIA, 6.8e-6), "68 g·cm²");
    assert_eq!(show(Key::LOAD_INERTIA, 5.4e-7), "5.4 g·cm²");
    assert_eq!(show(Key::LOAD_INERTIA, 0.0), "0 g·cm²");
    assert_eq!(show(Key::LOAD_INERTIA, 2.5e-3), "25000 g·cm²");
    assert_eq!(show(Key::HOLDING_TORQUE, 0.4), "0.4 N·m");
    assert_eq!(show(Key::INDUCTANCE, 0.6e-3), "0.6 mH");
    assert_eq!(show(Key::INDUCTANCE, 3.4e-3), "3.4 mH");
    assert_eq!(show(Key::INDUCTANCE, 2.5e-5), "0.025 mH");
    assert_eq!(show(Key::RESISTANCE, 0.88), "0.88 Ω");
    assert_eq!(show(Key::RATED_CURRENT, 2.8), "2.8 A");
    assert_eq!(show(Key::SUPPLY_VOLTAGE, 24.0), "24 V");
    assert_eq!(show(Key::STEP_ANGLE, 1.8), "1.8°");
    assert_eq!(show(Key::DAMPING, 1e-4), "0.0001 N·m·s/rad");
    assert_eq!(show(Key::MAX_START_HZ, 1200.0), "1.2 kHz");
}
