//! From arguments to what they ask for: the curve and its keys, the common
//! keys, the motor; every problem located at its argument.

use std::format;
use std::string::ToString;
use std::vec::Vec;

use super::suggest::{Hint, did_you_mean, suggest};
use super::values::{Collector, avoid, cpu, driver, motor};
use super::{Arg, Diagnostic, TableLayout, Value, curve_names, keys_for, listed, quoted};
use crate::bands::Bands;
use crate::cpu::Cpu;
use crate::driver::Driver;
use crate::motor::{Motor, MotorError};
use crate::schema::curves::CurveSchema;
use crate::table::computed::SpecTables;
use profile_core::Error;
use profile_core::Key;
use profile_core::MAX_LEN;
use profile_core::Spec;
use profile_core::{Arithmetic, Discretization, Rounding};
use profile_core::{Curve, TorqueLimited};
use profile_core::{Timer, Word};

/// What a list of arguments asks for, before the spec is checked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Request {
    /// The table's spec.
    pub spec: Spec,
    /// Its layout.
    pub layout: TableLayout,
    /// The motor it drives, when described.
    pub motor: Option<Motor>,
    /// The step driver it plays into, when described.
    pub driver: Option<Driver>,
    /// The step interrupt's core and clock, when described.
    pub cpu: Option<Cpu>,
    /// The speed bands to keep the top out of, when given.
    pub avoid: Option<Bands>,
}

/// Checks the keys, kinds and names of `args` and says what they ask for.
///
/// `whole` locates the entire argument list, for missing keys. `assumed`
/// are keys not to report as missing: keys another diagnostic already
/// covers, such as the target of a misspelt default. All problems found are
/// reported together, in source order.
pub fn read<L: Clone>(
    args: &[Arg<L>],
    whole: &L,
    assumed: &[Key],
) -> Result<Request, Vec<Diagnostic<L>>> {
    let mut c = Collector {
        args,
        whole,
        diagnostics: Vec::new(),
    };
    let schema = curve(&mut c);
    let valid = match schema {
        Some(r) => keys_for(r.name),
        None => crate::schema::keys::all().into_iter().collect(),
    };
    let mut suggested = assumed.to_vec();
    check_keys(&mut c, schema, &valid, &mut suggested);
    let Some(schema) = schema else {
        return Err(c.finish());
    };
    let complete = check_required(&mut c, schema, &suggested);
    let timer = timer(&mut c);
    let reload_offset = c.ranged(Key::RELOAD_OFFSET, "an integer number of ticks", |v| {
        i32::try_from(v).map_err(|_| {
            format!(
                "`reload_offset` must be from {} to {} (got {v})",
                i32::MIN,
                i32::MAX
            )
        })
    });
    let modes = modes(&mut c);
    let segments = c.ranged(Key::SEGMENTS, "an integer number of segments", |v| {
        if v < 1 {
            Err(format!("`segments` must be at least 1 (got {v})"))
        } else if v > MAX_LEN as i128 {
            Err(format!("`segments` must be at most {MAX_LEN} (got {v})"))
        } else {
            Ok(v as u32)
        }
    });
    let compress = c.float(Key::COMPRESS);
    if let (Some(_), Some(_), Some((i, _))) = (segments, compress, c.find(Key::COMPRESS)) {
        c.at_arg(
            i,
            true,
            "`compress` and `segments` are two layouts of the table: give one".to_string(),
        );
    }
    let mut curve = (schema.read)(&mut c);
    let motor = motor(&mut c, &suggested);
    let driver = driver(&mut c);
    let cpu = cpu(&mut c);
    let avoid = avoid(&mut c, motor.as_ref());
    if let (Some(Curve::TorqueLimited(ramp)), Some(timer)) = (&mut curve, timer) {
        limited_by(&mut c, ramp, motor.as_ref(), timer);
    }
    let (Some(curve), Some(timer), true, true) = (curve, timer, complete, c.diagnostics.is_empty())
    else {
        return Err(c.finish());
    };
    let (discretization, rounding, arithmetic) = modes;
    Ok(Request {
        spec: Spec::new(curve, timer)
            .with_discretization(discretization)
            .with_rounding(rounding)
            .with_arithmetic(arithmetic)
            .with_reload_offset(reload_offset.unwrap_or(0)),
        layout: match (segments, compress) {
            (Some(n), _) => TableLayout::Segments(n),
            (None, Some(e)) => TableLayout::Runs(e),
            (None, None) => TableLayout::Steps,
        },
        motor,
        driver,
        cpu,
        avoid,
    })
}

/// A `torque_limited` ramp's start and acceleration, from its motor: an
/// error at `curve` without one, at the motor's figure or `fmax` when the
/// motor has no torque to spare. Without `fmin`, the start is the fastest
/// the start-from-rest check accepts with the ramp's acceleration after
/// it: the model's fastest constant start times `margin`, and four fifths
/// of that as often as the check refuses the start or the margin cannot be
/// kept on it (at most 20 times).
fn limited_by<L: Clone>(
    c: &mut Collector<'_, L>,
    ramp: &mut TorqueLimited,
    motor: Option<&Motor>,
    timer: Timer,
) {
    let given = c.find(Key::FMIN).is_some();
    let Some(motor) = motor else {
        // Without a motor read (none given, or one in error, reported).
        if !c.diagnostics.is_empty() {
            return;
        }
        let message = "`curve = torque_limited` takes its acceleration from the motor's torque: \
                       describe the motor (`motor = NAME`, or its keys)"
            .to_string();
        match c.find(Key::CURVE) {
            Some((i, _)) => c.at_arg(i, false, message),
            None => c.at_whole(message),
        }
        return;
    };
    let mut fmin = given.then_some(ramp.fmin);
    if fmin.is_none() {
        // The model's fastest constant start, times `margin`, as a user
        // would write it.
        let start = motor.start_limit(ramp.fmax).hz() * ramp.margin;
        fmin = Some(three_digits_down(start));
    }
    for tried in 0..START_TRIES {
        let limited = match motor.torque_limited(fmin, ramp.fmax, ramp.margin, timer) {
            Ok(limited) => limited,
            // A slower start the margin cannot be kept on is passed over:
            // a slower one yet may keep it, or the last start that kept it
            // is the motor check's to report.
            Err(_) if tried > 0 => {
                fmin = fmin.map(|hz| three_digits_down(hz * 0.8));
                continue;
            }
            Err(e) => {
                let d = super::locate_motor(&e, c.args, c.whole);
                c.diagnostics.push((usize::MAX, d));
                return;
            }
        };
        *ramp = limited;
        if given || !starts_too_fast(motor, limited, timer) {
            return;
        }
        fmin = Some(three_digits_down(limited.fmin * 0.8));
    }
}

/// `hz` rounded down to three significant digits, as a user would write a
/// start frequency (2614.7 Hz is 2610 Hz).
fn three_digits_down(hz: f64) -> f64 {
    if !(hz.is_finite() && hz > 0.0) {
        return hz;
    }
    let unit = libm::pow(10.0, libm::floor(libm::log10(hz)) - 2.0);
    libm::floor(hz / unit) * unit
}

/// Times the start of a `torque_limited` ramp without `fmin` is lowered.
const START_TRIES: u32 = 20;

/// Whether the motor check refuses `ramp`'s start from rest (any other
/// problem is the check's to report, with the table).
fn starts_too_fast(motor: &Motor, ramp: TorqueLimited, timer: Timer) -> bool {
    let spec = Spec::new(Curve::TorqueLimited(ramp), timer);
    let Ok(table) = spec.table() else {
        return false;
    };
    matches!(
        motor.check(&spec, &table.periods),
        Err(MotorError::PullIn { .. } | MotorError::ShortMove { .. } | MotorError::Start { .. })
    )
}

/// What is wrong with one argument's value on its own (its kind, its unit,
/// a name it does not take), as any profile that took it would say: for a
/// `[defaults]` key no profile takes. `nowhere` locates nothing of the
/// input; what is said there (the keys the argument alone lacks) is left
/// out.
pub(crate) fn value_problems<L: Clone + PartialEq>(
    arg: &Arg<L>,
    nowhere: &L,
) -> Vec<Diagnostic<L>> {
    let Some(key) = crate::schema::keys::from_name(&arg.key) else {
        return Vec::new();
    };
    if let Some(d) = own_problem(arg, key) {
        return Vec::from([d]);
    }
    let mut args = Vec::from([arg.clone()]);
    if key != Key::CURVE {
        // A curve that takes the key, so that it is read as a profile would.
        let Some(curve) = curve_names().find(|c| keys_for(c).contains(&key)) else {
            return Vec::new();
        };
        args.push(Arg {
            key: Key::CURVE.name().to_string(),
            key_loc: nowhere.clone(),
            value: Value::Name(curve.to_string()),
            value_loc: nowhere.clone(),
            parts: Vec::new(),
        });
    }
    let every: Vec<Key> = crate::schema::keys::all().into_iter().collect();
    match read(&args, nowhere, &every) {
        Ok(_) => Vec::new(),
        Err(found) => found
            .into_iter()
            .filter(|d| d.loc == arg.key_loc || d.loc == arg.value_loc)
            .collect(),
    }
}

/// What is wrong with a number whatever profile takes it: not a finite
/// number, or a motor's figure out of its range ([`Motor::validate`]).
fn own_problem<L: Clone>(arg: &Arg<L>, key: Key) -> Option<Diagnostic<L>> {
    let value = match arg.value {
        Value::Int(v) => v as f64,
        Value::Float(v) => v,
        _ => return None,
    };
    let message = match crate::motor::bounds::of(key) {
        Some(bounds) => crate::motor::bounds::within(key, value, bounds)
            .err()?
            .to_string(),
        None if !value.is_finite() => Error::NotFinite { key, value }.to_string(),
        None => return None,
    };
    Some(Diagnostic {
        loc: arg.value_loc.clone(),
        message,
    })
}

/// The curve the arguments name, so that its keys are known.
fn curve<L: Clone>(c: &mut Collector<'_, L>) -> Option<&'static CurveSchema> {
    let names = curve_names();
    let Some((i, arg)) = c.find(Key::CURVE) else {
        c.at_whole(format!(
            "missing key `curve`: expected one of {}",
            quoted(names)
        ));
        return None;
    };
    let message = match &arg.value {
        Value::Name(n) => match CurveSchema::named(n) {
            Some(schema) => return Some(schema),
            None => format!(
                "`curve` must be one of {} (got `{n}`){}",
                quoted(names.clone()),
                did_you_mean(n, names, Hint::After)
            ),
        },
        other => format!(
            "`curve` expects one of {}, got {}",
            quoted(names),
            other.quoted()
        ),
    };
    c.at_arg(i, false, message);
    None
}

/// Unknown, inapplicable and duplicate keys. A near miss of a key is added
/// to `suggested`: it is not missing too.
fn check_keys<L: Clone>(
    c: &mut Collector<'_, L>,
    schema: Option<&CurveSchema>,
    valid: &[Key],
    suggested: &mut Vec<Key>,
) {
    for (i, arg) in c.args.iter().enumerate() {
        match crate::schema::keys::from_name(&arg.key) {
            None => {
                let near = suggest(&arg.key, valid.iter().map(|k| k.name()));
                suggested.extend(near.and_then(crate::schema::keys::from_name));
                let message = format!(
                    "unknown key `{}`; {}expected one of {}, or a motor's keys",
                    arg.key,
                    did_you_mean(&arg.key, near, Hint::Before),
                    quoted(listed(valid))
                );
                c.at_arg(i, true, message);
            }
            Some(key) => {
                if let Some(schema) = schema {
                    if !valid.contains(&key) {
                        let message = format!(
                            "`{key}` does not apply to `curve = {}`, which takes {}",
                            schema.name,
                            quoted(listed(valid))
                        );
                        c.at_arg(i, true, message);
                    }
                }
                if c.args[..i].iter().any(|a| a.key == arg.key) {
                    c.at_arg(i, true, format!("duplicate key `{key}`"));
                }
            }
        }
    }
}

/// Missing keys, and the curve's pair of which exactly one is given. Whether
/// every required key is there (a near miss covered elsewhere is still
/// absent: the spec cannot be built, whatever else is right).
fn check_required<L: Clone>(
    c: &mut Collector<'_, L>,
    schema: &CurveSchema,
    suggested: &[Key],
) -> bool {
    let mut required = schema.required.to_vec();
    required.push(Key::TIMER_HZ);
    let missing: Vec<Key> = required
        .iter()
        .copied()
        .filter(|k| c.find(*k).is_none() && !suggested.contains(k))
        .collect();
    let complete = required.iter().all(|k| c.find(*k).is_some());
    if !missing.is_empty() {
        let plural = if missing.len() == 1 { "key" } else { "keys" };
        c.at_whole(format!(
            "missing {plural} {}: `curve = {}` needs {}",
            quoted(missing.iter().map(|k| k.name())),
            schema.name,
            quoted(required.iter().map(|k| k.name()))
        ));
    }
    if let Some([a, b]) = schema.one_of {
        match (c.find(a).map(|(i, _)| i), c.find(b).map(|(i, _)| i)) {
            (Some(i), Some(j)) => c.at_arg(
                i.max(j),
                true,
                format!("give one of `{a}` and `{b}`, not both: each sets the ramp's length"),
            ),
            (None, None) if !suggested.contains(&a) && !suggested.contains(&b) => {
                c.at_whole(format!(
                    "missing key: `curve = {}` needs one of `{a}` and `{b}`",
                    schema.name
                ))
            }
            _ => {}
        }
    }
    complete
}

/// `timer_hz`, `word` and `ticks_per_step`.
fn timer<L: Clone>(c: &mut Collector<'_, L>) -> Option<Timer> {
    let timer_hz = c.ranged(Key::TIMER_HZ, "an integer number of Hz", |v| {
        if v < 1 {
            Err(format!("`timer_hz` must be greater than 0 (got {v})"))
        } else {
            u32::try_from(v)
                .map_err(|_| format!("`timer_hz` must be at most {} (got {v})", u32::MAX))
        }
    });
    let word = c.name(Key::WORD, &[("u16", Word::U16), ("u32", Word::U32)]);
    let ticks_per_step = c.ranged(Key::TICKS_PER_STEP, "1 or 2", |v| match v {
        1 | 2 => Ok(v as u8),
        _ => Err(format!("`ticks_per_step` must be 1 or 2 (got {v})")),
    });
    Some(Timer {
        timer_hz: timer_hz?,
        word: word.unwrap_or(Word::U16),
        ticks_per_step: ticks_per_step.unwrap_or(1),
    })
}

/// `discretization`, `rounding` and `arithmetic`, defaults where not given.
fn modes<L: Clone>(c: &mut Collector<'_, L>) -> (Discretization, Rounding, Arithmetic) {
    let discretization = c.name(
        Key::DISCRETIZATION,
        &[
            ("exact", Discretization::Exact),
            ("left_endpoint", Discretization::LeftEndpoint),
            ("index", Discretization::Index),
        ],
    );
    let rounding = c.name(
        Key::ROUNDING,
        &[
            ("truncate", Rounding::Truncate),
            ("nearest", Rounding::Nearest),
            ("diffuse", Rounding::Diffuse),
        ],
    );
    let arithmetic = c.name(
        Key::ARITHMETIC,
        &[
            ("f64", Arithmetic::F64),
            ("f32", Arithmetic::F32),
            ("integer", Arithmetic::Integer),
        ],
    );
    (
        discretization.unwrap_or_default(),
        rounding.unwrap_or_default(),
        arithmetic.unwrap_or_default(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::{String, ToString};
    use std::vec;

    fn args(list: &[(&str, Value)]) -> Vec<Arg<usize>> {
        list.iter()
            .enumerate()
            .map(|(i, (k, v))| Arg {
                key: k.to_string(),
                key_loc: 2 * i,
                value: v.clone(),
                value_loc: 2 * i + 1,
                parts: Vec::new(),
            })
            .collect()
    }

    fn name(s: &str) -> Value {
        Value::Name(s.to_string())
    }

    fn orange() -> Vec<(&'static str, Value)> {
        vec![
            ("curve", name("sigmoid")),
            ("len", Value::Int(1000)),
            ("fmin", Value::Int(500)),
            ("fmax", Value::Float(64000.0)),
            ("flexible", Value::Int(8)),
            ("timer_hz", Value::Int(10_000_000)),
        ]
    }

    fn errors(list: &[(&str, Value)]) -> Vec<(usize, String)> {
        read(&args(list), &999, &[])
            .unwrap_err()
            .into_iter()
            .map(|d| (d.loc, d.message))
            .collect()
    }

    #[test]
    fn builds_the_orange_spec_with_defaults() {
        let spec = read(&args(&orange()), &999, &[]).unwrap().spec;
        assert_eq!(spec.discretization, Discretization::Exact);
        assert_eq!(spec.rounding, Rounding::Diffuse);
        assert_eq!(spec.timer, Timer::new(10_000_000));
        assert_eq!(spec.len(), 1000);
    }

    #[test]
    fn typo_gets_a_suggestion_on_the_key() {
        let mut list = orange();
        list[4].0 = "flexibel";
        assert_eq!(
            errors(&list),
            vec![(
                8,
                "unknown key `flexibel`; did you mean `flexible`? expected one of `curve`, \
                     `len`, `fmin`, `fmax`, `flexible`, `timer_hz`, `word`, `ticks_per_step`, \
                     `reload_offset`, `discretization`, `rounding`, `arithmetic`, `segments`, `compress`, \
                     or a motor's keys"
                    .to_string()
            )]
        );
    }

    #[test]
    fn duplicate_is_reported_on_the_second() {
        let mut list = orange();
        list.push(("fmin", Value::Int(600)));
        assert_eq!(
            errors(&list),
            vec![(12, "duplicate key `fmin`".to_string())]
        );
    }

    #[test]
    fn whole_floats_are_integers() {
        let mut list = orange();
        list[1].1 = Value::Float(1e3);
        list[5].1 = Value::Float(1e7);
        let spec = read(&args(&list), &999, &[]).unwrap().spec;
        assert_eq!((spec.len(), spec.timer), (1000, Timer::new(10_000_000)));
        // Beyond 2^53 the range says so, with the value as written.
        list[1].1 = Value::Float(1e20);
        list[5].1 = Value::Float(-1e300);
        assert_eq!(
            errors(&list),
            vec![
                (3, "`len` must be at most 65536 (got 1e20)".to_string()),
                (
                    11,
                    "`timer_hz` must be greater than 0 (got -1e300)".to_string()
                ),
            ]
        );
        // With a unit too.
        list[1].1 = Value::Int(1000);
        list[5].1 = Value::Quantity {
            number: "1e50".to_string(),
            unit: "Hz".to_string(),
            written: "1e50Hz".to_string(),
        };
        assert_eq!(
            errors(&list),
            vec![(
                11,
                "`timer_hz` must be at most 4294967295 (got 1e50)".to_string()
            )]
        );
    }

    #[test]
    fn wrong_kinds() {
        let mut list = orange();
        list[1].1 = Value::Float(1000.5);
        list[2].1 = name("slow");
        list.push(("rounding", name("round")));
        // Reported together, in source order.
        assert_eq!(
            errors(&list),
            vec![
                (
                    3,
                    "`len` expects an integer number of entries, got `1000.5`".to_string()
                ),
                (
                    5,
                    "`fmin` expects a number in Hz (steps/s), got `slow`".to_string()
                ),
                (
                    13,
                    "`rounding` must be one of `truncate`, `nearest`, `diffuse` (got `round`)"
                        .to_string()
                ),
            ]
        );
    }
}
