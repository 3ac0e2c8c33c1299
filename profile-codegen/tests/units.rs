//! Units through the schema: a number with a unit is the number it stands
//! for, and no suffix is ever ignored. Random numbers and suffixes, on
//! every key that takes a number, against the value computed by another
//! route (the float parser on `number e exponent`).

use profile_codegen::__private::schema::{self, Arg, Value};

/// A valid argument list of `curve`, as `(key, value)`.
fn base(curve: &str) -> Vec<(&'static str, Value)> {
    let n = |v: i128| Value::Int(v);
    let mut args = vec![("curve", Value::Name(curve.into()))];
    match curve {
        "sigmoid" => args.extend([
            ("len", n(200)),
            ("fmin", n(500)),
            ("fmax", n(64_000)),
            ("flexible", n(6)),
        ]),
        _ => args.extend([
            ("fmin", n(200)),
            ("fmax", n(1_200)),
            ("f_inf", n(1_300)),
            ("tau", Value::Float(0.05)),
        ]),
    }
    args.push(("timer_hz", n(10_000_000)));
    args
}

fn read(args: &[(&'static str, Value)]) -> Result<schema::Request, String> {
    let args: Vec<Arg<()>> = args
        .iter()
        .map(|(k, v)| Arg {
            key: (*k).to_string(),
            key_loc: (),
            value: v.clone(),
            value_loc: (),
            parts: Vec::new(),
        })
        .collect();
    schema::read(&args, &(), &[]).map_err(|d| d[0].message.clone())
}

/// The units a key of each kind accepts, written out here.
fn exponent(key: &str, unit: &str) -> Option<i32> {
    let frequency = ["fmin", "fmax", "f_inf", "timer_hz"].contains(&key);
    let time = key == "tau";
    match unit {
        "Hz" if frequency => Some(0),
        "kHz" if frequency => Some(3),
        "MHz" if frequency => Some(6),
        "s" if time => Some(0),
        "ms" if time => Some(-3),
        "us" | "µs" | "μs" if time => Some(-6),
        _ => None,
    }
}

/// Reads `args`, whose value at `slot` is `number` with a unit (written
/// `written`, of power of ten `exponent` where the key accepts it), and
/// judges the outcome: refused with a message that names the key where the
/// key does not take the unit, else `project`ed the same as the plain
/// number computed by another route (the float parser on `number e
/// exponent`, as `plain` writes it). `true` where accepted.
fn judge<T: PartialEq + std::fmt::Debug>(
    args: &[(&'static str, Value)],
    (slot, number, exponent): (usize, &str, Option<i32>),
    written: &str,
    plain: impl Fn(f64) -> Value,
    project: impl Fn(&schema::Request) -> T,
) -> bool {
    let key = args[slot].0;
    let with_unit = read(args);
    let Some(e) = exponent else {
        let message = with_unit.expect_err(&format!("`{key} = {written}` accepted"));
        assert!(
            message.starts_with(&format!("`{key}` ")),
            "`{key} = {written}`: {message}"
        );
        return false;
    };
    let value: f64 = format!("{number}e{e}").parse().unwrap();
    let mut plain_args = args.to_vec();
    plain_args[slot].1 = plain(value);
    assert_eq!(
        with_unit.as_ref().map(&project),
        read(&plain_args).as_ref().map(&project),
        "`{key} = {written}` against `{key} = {value}`"
    );
    true
}

/// A small deterministic generator (xorshift).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

const SUFFIXES: &[&str] = &[
    "Hz", "kHz", "MHz", "s", "ms", "us", "µs", "hz", "khz", "KHz", "mHz", "GHz", "kHz2", "min",
    "h", "ns", "u32", "u16", "usize", "i64", "f64", "Hz_", "k", "e", "x", "rpm",
];

#[test]
fn no_suffix_is_ever_ignored() {
    let cases: usize = std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3000);
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut accepted, mut refused) = (0, 0);
    for _ in 0..cases {
        let curve = ["sigmoid", "exponential"][rng.below(2)];
        let mut args = base(curve);
        let slot = 1 + rng.below(args.len() - 1);
        let key = args[slot].0;
        let unit = if rng.below(3) == 0 {
            // A unit some key accepts.
            ["Hz", "kHz", "MHz", "s", "ms", "us"][rng.below(6)].to_string()
        } else if rng.below(4) == 0 {
            // Random letters.
            let len = 1 + rng.below(4);
            (0..len)
                .map(|_| char::from(b'a' + rng.below(26) as u8))
                .collect()
        } else {
            SUFFIXES[rng.below(SUFFIXES.len())].to_string()
        };
        let k = exponent(key, &unit).unwrap_or(0);
        // A number that, in the unit, stands near the base value.
        let base_value = match &args[slot].1 {
            Value::Int(v) => *v as f64,
            Value::Float(v) => *v,
            _ => 1.0,
        };
        let digits = rng.below(4);
        let scaled = base_value / 10f64.powi(k);
        let number = format!("{scaled:.digits$}");
        args[slot].1 = Value::Quantity {
            number: number.clone(),
            unit: unit.clone(),
            written: format!("{number}{unit}"),
        };
        let plain = |value: f64| {
            if value.fract() == 0.0 && value.abs() < 1e15 {
                Value::Int(value as i128)
            } else {
                Value::Float(value)
            }
        };
        let with_unit = (slot, number.as_str(), exponent(key, &unit));
        if judge(&args, with_unit, &format!("{number}{unit}"), plain, |r| {
            r.spec
        }) {
            accepted += 1;
        } else {
            refused += 1;
        }
    }
    println!("{cases} random suffixes: {accepted} read as their value, {refused} refused");
    assert!(
        accepted > cases / 20 && refused > cases / 2,
        "{accepted} accepted, {refused} refused"
    );
}

#[test]
fn strings_with_units_read_as_numbers() {
    let mut args = base("sigmoid");
    args[3].1 = Value::Name("64 kHz".into());
    args[5].1 = Value::Name("10MHz".into());
    assert_eq!(
        read(&args).map(|r| r.spec),
        read(&base("sigmoid")).map(|r| r.spec)
    );
    args[3].1 = Value::Name("64 kHz2".into());
    assert_eq!(
        read(&args).unwrap_err(),
        "`fmax` accepts the units `Hz`, `kHz`, `MHz` (got `64 kHz2`); did you mean `kHz`?"
    );
    args[3].1 = Value::Name("64000".into());
    assert_eq!(
        read(&args).unwrap_err(),
        "`fmax` expects a number in Hz (steps/s), got the string `\"64000\"` (write numbers \
         without quotes)"
    );
}

/// A sigmoid driving a motor given by its windings, every motor key that
/// takes a number set.
fn motor_base() -> Vec<(&'static str, Value)> {
    let f = |v: f64| Value::Float(v);
    let mut args = base("sigmoid");
    args.extend([
        ("step_angle", f(1.8)),
        ("rotor_inertia", f(6.8e-6)),
        ("load_inertia", f(1.36e-5)),
        ("friction", f(0.02)),
        ("resistance", f(0.88)),
        ("inductance", f(3.4e-3)),
        ("rated_current", f(4.2)),
        ("holding_torque", f(3.0)),
        ("supply_voltage", f(36.0)),
        ("detent_torque", f(0.015)),
    ]);
    args
}

/// The units a motor key accepts and their powers of ten, written out here
/// from the datasheets' symbols.
fn motor_exponent(key: &str, unit: &str) -> Option<i32> {
    let inertia = key.ends_with("_inertia");
    let torque = ["friction", "holding_torque", "detent_torque"].contains(&key);
    match unit {
        "kgm2" | "kg·m²" if inertia => Some(0),
        "gcm2" | "g·cm²" if inertia => Some(-7),
        "Nm" | "N·m" if torque => Some(0),
        "Ncm" | "N·cm" if torque => Some(-2),
        "mNm" | "mN·m" if torque => Some(-3),
        "ohm" | "ohms" | "Ω" | "\u{2126}" if key == "resistance" => Some(0),
        "mohm" | "mΩ" if key == "resistance" => Some(-3),
        "H" if key == "inductance" => Some(0),
        "mH" if key == "inductance" => Some(-3),
        "uH" | "µH" | "μH" if key == "inductance" => Some(-6),
        "A" if key == "rated_current" => Some(0),
        "mA" if key == "rated_current" => Some(-3),
        "V" if key == "supply_voltage" => Some(0),
        "deg" | "°" if key == "step_angle" => Some(0),
        _ => None,
    }
}

const MOTOR_UNITS: &[&str] = &[
    "kgm2", "kg·m²", "gcm2", "g·cm²", "Nm", "N·m", "Ncm", "N·cm", "mNm", "mN·m", "ohm", "ohms",
    "Ω", "\u{2126}", "H", "mH", "uH", "µH", "μH", "A", "mA", "V", "deg", "°", "kgcm2", "gm2",
    "Nmm", "kNm", "mohm", "mΩ", "kohm", "h", "mh", "MH", "nH", "a", "kA", "mV", "kV", "v", "rad",
    "Hz", "ms", "oz·in", "lb", "f64", "u32",
];

#[test]
fn a_motors_keys_read_units_as_the_numbers_they_stand_for() {
    let cases: usize = std::env::var("FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3000);
    let mut rng = Rng(0x2545_F491_4F6C_DD1D);
    let plain_motor = read(&motor_base()).map(|r| r.motor);
    assert!(matches!(plain_motor, Ok(Some(_))), "{plain_motor:?}");
    let (mut accepted, mut refused) = (0, 0);
    for _ in 0..cases {
        let mut args = motor_base();
        let first_motor_key = args.len() - 10;
        let slot = first_motor_key + rng.below(10);
        let key = args[slot].0;
        // Half the time a unit the key accepts.
        let own = rng.below(2) == 0;
        let unit = loop {
            let unit = MOTOR_UNITS[rng.below(MOTOR_UNITS.len())];
            if !own || motor_exponent(key, unit).is_some() {
                break unit;
            }
        };
        let base_value = match &args[slot].1 {
            Value::Float(v) => *v,
            other => panic!("{other:?}"),
        };
        let k = motor_exponent(key, unit).unwrap_or(0);
        let digits = rng.below(4);
        let scaled = base_value / 10f64.powi(k);
        let number = format!("{scaled:.digits$}");
        // As a macro's literal with a suffix, or as a string.
        args[slot].1 = if rng.below(2) == 0 {
            Value::Quantity {
                number: number.clone(),
                unit: unit.to_string(),
                written: format!("{number}{unit}"),
            }
        } else {
            Value::Name(format!("{number} {unit}"))
        };
        let with_unit = (slot, number.as_str(), motor_exponent(key, unit));
        let written = format!("{number} {unit}");
        if judge(&args, with_unit, &written, Value::Float, |r| r.motor) {
            accepted += 1;
        } else {
            refused += 1;
        }
    }
    println!("{cases} random motor units: {accepted} read as their value, {refused} refused");
    assert!(
        accepted > cases / 3 && refused > cases / 3,
        "{accepted} accepted, {refused} refused"
    );
}
