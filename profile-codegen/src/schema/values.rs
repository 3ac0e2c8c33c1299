//! Reading values from arguments: the collector of diagnostics, the reader
//! curves read their parameters through, and the motor's keys.

use std::format;
use std::string::{String, ToString};
use std::vec::Vec;

use super::suggest::{Hint, did_you_mean};
use super::{Arg, Diagnostic, Value, quoted, unit, units};
use crate::bands::{Bands, MAX_BANDS};
use crate::cpu::{CORES, Core, Cpu, MAX_AXES};
use crate::driver::{Driver, PRESETS};
use crate::motor::{
    CurrentSetting, Drive, MAX_CURVE_POINTS, MAX_MICROSTEPS, Motor, TorqueCurve, Windings,
};
use crate::numbers::Num;
use crate::schema::curves::Reader;
use crate::schema::keys::{BUDGET, DRIVER_TIMING};
use profile_core::Error;
use profile_core::Key;
use profile_core::MAX_LEN;

/// 2^53: every integer up to it is exactly a `f64`.
const EXACT_FLOAT_INT: f64 = 9_007_199_254_740_992.0;

/// Arguments being read, and what is wrong with them so far.
pub(crate) struct Collector<'a, L> {
    pub(crate) args: &'a [Arg<L>],
    pub(crate) whole: &'a L,
    /// Diagnostics with the index of the argument they concern, for source order.
    pub(crate) diagnostics: Vec<(usize, Diagnostic<L>)>,
}

impl<L: Clone> Collector<'_, L> {
    pub(crate) fn at_arg(&mut self, index: usize, key: bool, message: String) {
        let arg = &self.args[index];
        let loc = if key { &arg.key_loc } else { &arg.value_loc };
        self.diagnostics.push((
            index,
            Diagnostic {
                loc: loc.clone(),
                message,
            },
        ));
    }

    /// At element `part` of a list's value, or at the value where the
    /// front end gave no place for it.
    pub(crate) fn at_part(&mut self, index: usize, part: usize, message: String) {
        let arg = &self.args[index];
        let loc = arg.parts.get(part).unwrap_or(&arg.value_loc);
        self.diagnostics.push((
            index,
            Diagnostic {
                loc: loc.clone(),
                message,
            },
        ));
    }

    pub(crate) fn at_whole(&mut self, message: String) {
        self.diagnostics.push((
            usize::MAX,
            Diagnostic {
                loc: self.whole.clone(),
                message,
            },
        ));
    }

    pub(crate) fn find(&self, key: Key) -> Option<(usize, &Arg<L>)> {
        self.args
            .iter()
            .enumerate()
            .find(|(_, a)| a.key == key.name())
    }

    /// The value of a numeric key, its unit applied; a unit the key does not
    /// take is reported.
    fn numeric(&mut self, key: Key) -> Option<(usize, Value)> {
        let (i, _) = self.find(key)?;
        let args = self.args;
        let arg_value = &args[i].value;
        let (number, unit) = match arg_value {
            Value::Quantity { number, unit, .. } => (number.as_str(), unit.as_str()),
            Value::Name(text) => match units::split(text) {
                Some(split) => split,
                None => return Some((i, arg_value.clone())),
            },
            other => return Some((i, other.clone())),
        };
        let written = match arg_value {
            Value::Name(text) => text.trim().to_string(),
            other => other.to_string(),
        };
        let number = number.replace('_', "");
        match units::with_unit(key, &number, unit, &written) {
            Ok(v) => Some((i, v)),
            Err(message) => {
                self.at_arg(i, false, message);
                None
            }
        }
    }

    pub(crate) fn float(&mut self, key: Key) -> Option<f64> {
        let (i, value) = self.numeric(key)?;
        match &value {
            Value::Int(v) => Some(*v as f64),
            Value::Float(v) => Some(*v),
            other => {
                let unit = match unit(key) {
                    "" => String::new(),
                    unit => format!(" in {unit}"),
                };
                let message = format!("`{key}` expects a number{unit}, got {}", other.quoted());
                self.at_arg(i, false, message);
                None
            }
        }
    }

    /// An integer key's value. A float literal with a whole value (`1e7`,
    /// `1000.0`) counts as that integer, as TOML and Rust write `1e3` as a
    /// float; beyond 2^53, where floats skip integers, as 2^53 (out of every
    /// key's range: [`Collector::ranged`] then quotes the value as written).
    pub(crate) fn int(&mut self, key: Key, expected: &str) -> Option<i128> {
        let (i, value) = self.numeric(key)?;
        match &value {
            Value::Int(v) => Some(*v),
            Value::Float(v) if v.is_finite() && libm::trunc(*v) == *v => {
                Some(v.clamp(-EXACT_FLOAT_INT, EXACT_FLOAT_INT) as i128)
            }
            other => {
                let message = format!("`{key}` expects {expected}, got {}", other.quoted());
                self.at_arg(i, false, message);
                None
            }
        }
    }

    /// An integer key with a range; `check` says what is wrong with a value.
    pub(crate) fn ranged<T>(
        &mut self,
        key: Key,
        expected: &str,
        check: impl Fn(i128) -> Result<T, String>,
    ) -> Option<T> {
        let v = self.int(key, expected)?;
        // Read again, units applied (no diagnostic: it was read once).
        let (i, value) = self.numeric(key)?;
        let beyond = match value {
            Value::Float(f) if libm::fabs(f) > EXACT_FLOAT_INT => Some(f),
            _ => None,
        };
        let message = match (check(v), beyond) {
            (Ok(t), None) => return Some(t),
            (Err(message), None) => message,
            // A whole float beyond 2^53 was read as 2^53: the range's
            // message, with the value as written.
            (Err(message), Some(f)) => message.replace(
                &(v.unsigned_abs()).to_string(),
                &Num(libm::fabs(f)).to_string(),
            ),
            (Ok(_), Some(f)) => format!("`{key}` expects {expected}, got `{}`", Num(f)),
        };
        self.at_arg(i, false, message);
        None
    }

    pub(crate) fn name<T: Copy>(&mut self, key: Key, choices: &[(&'static str, T)]) -> Option<T> {
        let (i, arg) = self.find(key)?;
        let names = quoted(choices.iter().map(|(n, _)| *n));
        let message = match &arg.value {
            Value::Name(n) => match choices.iter().find(|(c, _)| c == n) {
                Some((_, v)) => return Some(*v),
                None => {
                    let hint = did_you_mean(n, choices.iter().map(|(c, _)| *c), Hint::After);
                    format!("`{key}` must be one of {names} (got `{n}`){hint}")
                }
            },
            other => format!("`{key}` expects one of {names}, got {}", other.quoted()),
        };
        self.at_arg(i, false, message);
        None
    }

    pub(crate) fn finish(mut self) -> Vec<Diagnostic<L>> {
        self.diagnostics.sort_by_key(|(i, _)| *i);
        self.diagnostics.into_iter().map(|(_, d)| d).collect()
    }
}

impl<L: Clone> Reader for Collector<'_, L> {
    fn number(&mut self, key: Key) -> Option<f64> {
        self.float(key)
    }

    fn len(&mut self) -> Option<u32> {
        self.ranged(Key::LEN, "an integer number of entries", len_check)
    }

    fn has(&self, key: Key) -> bool {
        self.find(key).is_some()
    }
}

fn len_check(len: i128) -> Result<u32, String> {
    if len < 1 {
        Err(format!("`len` must be at least 1 (got {len})"))
    } else if len > MAX_LEN as i128 {
        Err(Error::LenTooLarge {
            len: u64::try_from(len).unwrap_or(u64::MAX),
            max: MAX_LEN,
        }
        .to_string())
    } else {
        Ok(len as u32)
    }
}

/// The motor the arguments describe, if any; problems go to the collector.
/// `assumed` keys (what a misspelt key probably meant) are not reported
/// missing.
pub(crate) fn motor<L: Clone>(c: &mut Collector<'_, L>, assumed: &[Key]) -> Option<Motor> {
    let described = crate::schema::keys::MOTOR_KEYS
        .iter()
        .any(|k| c.find(*k).is_some());
    if !described {
        if let Some((i, arg)) = c.find(Key::MOTOR) {
            let message = format!(
                "`motor = {}` names no motor description: declare `[motors.{}]` in the \
                 profiles file, or give the motor's keys (`step_angle`, `rotor_inertia`, \
                 `torque_curve`, ...)",
                arg.value, arg.value
            );
            c.at_arg(i, false, message);
        }
        return None;
    }
    missing_keys(c, assumed);
    let step_angle = c.float(Key::STEP_ANGLE);
    let microsteps = c.ranged(
        Key::MICROSTEPS,
        "an integer number of microsteps per full step",
        |v| {
            u32::try_from(v)
                .ok()
                .filter(|m| (1..=MAX_MICROSTEPS).contains(m))
                .ok_or_else(|| format!("`microsteps` must be from 1 to {MAX_MICROSTEPS} (got {v})"))
        },
    );
    let rotor_inertia = c.float(Key::ROTOR_INERTIA);
    let load_inertia = c.float(Key::LOAD_INERTIA);
    let friction = c.float(Key::FRICTION);
    let damping = c.float(Key::DAMPING);
    let damping_ratio = c.float(Key::DAMPING_RATIO);
    let safety = c.float(Key::SAFETY);
    let max_start_hz = c.float(Key::MAX_START_HZ);
    let windings = windings(c);
    // `Some(None)` without a curve; `None` for a curve in error.
    let curve = match c.find(Key::TORQUE_CURVE) {
        None => Some(None),
        Some((i, arg)) => match &arg.value {
            Value::Points(points) => match TorqueCurve::new(points) {
                Some(curve) => Some(Some(curve)),
                None => {
                    let message = format!(
                        "`torque_curve` must have from 1 to {MAX_CURVE_POINTS} points (got {})",
                        points.len()
                    );
                    c.at_arg(i, false, message);
                    None
                }
            },
            Value::Refused { message, part } => {
                c.at_part(i, *part, message.clone());
                None
            }
            other => {
                let message = format!(
                    "`torque_curve` expects a list of (step frequency in Hz, torque in N·m) \
                     points, such as `[(0, 0.4), (1000, 0.3)]` in the macro or \
                     `[[0, 0.4], [1000, 0.3]]` in a profiles file, got {}",
                    other.quoted()
                );
                c.at_arg(i, false, message);
                None
            }
        },
    };
    Some(Motor {
        step_angle: step_angle?,
        microsteps: microsteps.unwrap_or(1),
        rotor_inertia: rotor_inertia?,
        load_inertia: load_inertia.unwrap_or(0.0),
        torque_curve: curve?,
        windings: windings?,
        friction: friction.unwrap_or(0.0),
        damping: damping.unwrap_or(0.0),
        damping_ratio: damping_ratio.unwrap_or(0.0),
        safety: safety.unwrap_or(1.0),
        max_start_hz,
    })
}

/// The keys a motor lacks, as one error at its `motor` name (or on the
/// whole): `step_angle` and `rotor_inertia`, and its pull-out torque
/// (`torque_curve`, or every required key of the windings once one is
/// given).
fn missing_keys<L: Clone>(c: &mut Collector<'_, L>, assumed: &[Key]) {
    let windings = &crate::schema::keys::WINDINGS_KEYS[..5];
    let any_windings = crate::schema::keys::WINDINGS_KEYS
        .iter()
        .any(|k| c.find(*k).is_some());
    let lacking = |c: &Collector<'_, L>, keys: &[Key]| -> Vec<Key> {
        keys.iter()
            .copied()
            .filter(|k| c.find(*k).is_none() && !assumed.contains(k))
            .collect()
    };
    let mut missing = lacking(c, &[Key::STEP_ANGLE, Key::ROTOR_INERTIA]);
    let curve = c.find(Key::TORQUE_CURVE).is_some();
    if curve && any_windings {
        // Windings beside a curve only draw the derived curve over it: an
        // incomplete set is an error at the first of them given.
        let lacks = lacking(c, windings);
        let first = crate::schema::keys::WINDINGS_KEYS
            .iter()
            .find_map(|k| c.find(*k).map(|(i, _)| (i, *k)));
        if let (false, Some((i, key))) = (lacks.is_empty(), first) {
            let message = format!(
                "`{}` describes the windings, whose pull-out curve the report compares with \
                 `torque_curve`; give the rest of them ({} missing) or remove it",
                key.name(),
                quoted(lacks.iter().map(|k| k.name()))
            );
            c.at_arg(i, true, message);
        }
    }
    let torque = if curve {
        Vec::new()
    } else if any_windings {
        lacking(c, windings)
    } else {
        lacking(c, &[Key::TORQUE_CURVE])
    };
    let through_windings = any_windings && !curve;
    missing.extend(torque);
    if missing.is_empty() {
        return;
    }
    let needs = if through_windings {
        format!(
            "a motor needs `step_angle`, `rotor_inertia`, and for windings {}",
            quoted(windings.iter().map(|k| k.name()))
        )
    } else {
        format!(
            "a motor needs `step_angle`, `rotor_inertia`, and `torque_curve` or the \
             windings' {}",
            quoted(windings.iter().map(|k| k.name()))
        )
    };
    let message = format!(
        "missing motor {} {}: {needs}",
        if missing.len() == 1 { "key" } else { "keys" },
        quoted(missing.iter().map(|k| k.name())),
    );
    // At the name of the motor that lacks them, in a profiles file.
    match c.find(Key::MOTOR) {
        Some((i, _)) => c.at_arg(i, false, message),
        None => c.at_whole(message),
    }
}

/// The windings the arguments give, if any: `Some(None)` without them,
/// `None` when a key is missing or in error (reported).
fn windings<L: Clone>(c: &mut Collector<'_, L>) -> Option<Option<Windings>> {
    if !crate::schema::keys::WINDINGS_KEYS
        .iter()
        .any(|k| c.find(*k).is_some())
    {
        return Some(None);
    }
    let resistance = c.float(Key::RESISTANCE);
    let inductance = c.float(Key::INDUCTANCE);
    let rated_current = c.float(Key::RATED_CURRENT);
    let holding_torque = c.float(Key::HOLDING_TORQUE);
    let supply_voltage = c.float(Key::SUPPLY_VOLTAGE);
    let detent_torque = c.float(Key::DETENT_TORQUE);
    let drive = c.name(Key::DRIVE, &Drive::ALL);
    let driver_current = c.float(Key::DRIVER_CURRENT);
    let driver_current_is = c.name(Key::DRIVER_CURRENT_IS, &CurrentSetting::ALL);
    let supply_utilization = c.float(Key::SUPPLY_UTILIZATION);
    let iron_loss = c.float(Key::IRON_LOSS);
    let defaults = Windings::new(0.0, 0.0, 0.0, 0.0, 0.0);
    Some(Some(Windings {
        resistance: resistance?,
        inductance: inductance?,
        rated_current: rated_current?,
        holding_torque: holding_torque?,
        supply_voltage: supply_voltage?,
        detent_torque: detent_torque.unwrap_or(0.0),
        drive: drive.unwrap_or_default(),
        driver_current,
        driver_current_is: driver_current_is.unwrap_or_default(),
        supply_utilization: supply_utilization.unwrap_or(defaults.supply_utilization),
        iron_loss,
    }))
}

/// The step driver's timing: a preset by name (`driver`), each time given
/// (`step_pulse`, `step_space`, `dir_setup`) over the preset's; a time
/// neither gives is 0, no bound. `None` when none of the four is given, or
/// one is in error (reported).
pub(crate) fn driver<L: Clone>(c: &mut Collector<'_, L>) -> Option<Driver> {
    let given = |c: &Collector<'_, L>, k: Key| c.find(k).is_some();
    if !given(c, Key::DRIVER) && !DRIVER_TIMING.iter().any(|k| given(c, *k)) {
        return None;
    }
    let choices = PRESETS.map(|(name, driver, _)| (name, driver));
    let errors = c.diagnostics.len();
    let mut driver = if given(c, Key::DRIVER) {
        c.name(Key::DRIVER, &choices)
    } else {
        Some(Driver {
            step_pulse: 0.0,
            step_space: 0.0,
            dir_setup: 0.0,
        })
    };
    for key in DRIVER_TIMING {
        let Some(time) = c.float(key) else {
            continue;
        };
        if !(time > 0.0 && time < 1.0) {
            let (i, arg) = c.find(key)?;
            let message = format!(
                "`{key}` must be a time above 0 and below 1 s (got `{}`)",
                arg.value
            );
            c.at_arg(i, false, message);
            continue;
        }
        if let Some(d) = &mut driver {
            match key {
                Key::STEP_PULSE => d.step_pulse = time,
                Key::STEP_SPACE => d.step_space = time,
                _ => d.dir_setup = time,
            }
        }
    }
    driver.filter(|_| c.diagnostics.len() == errors)
}

/// The step interrupt's budget: the core (`core`) and its clock (`cpu_hz`),
/// both needed, with the axes it steps (`axes`, 1) and the share of the CPU
/// it may take (`cpu_load`, 0.5). `None` when none of the four is given, or
/// one is in error (reported).
pub(crate) fn cpu<L: Clone>(c: &mut Collector<'_, L>) -> Option<Cpu> {
    if !BUDGET.iter().any(|k| c.find(*k).is_some()) {
        return None;
    }
    let errors = c.diagnostics.len();
    let core = c.name(Key::CORE, &CORES);
    let cpu_hz = c.float(Key::CPU_HZ);
    if let Some(hz) = cpu_hz {
        if !(1e3..=1e10).contains(&hz) {
            let (i, _) = c.find(Key::CPU_HZ)?;
            c.at_arg(
                i,
                false,
                format!("`cpu_hz` must be from 1 kHz to 10 GHz (got {} Hz)", Num(hz)),
            );
        }
    }
    let axes = c.ranged(Key::AXES, "an integer number of axes", |v| {
        u32::try_from(v)
            .ok()
            .filter(|a| (1..=MAX_AXES).contains(a))
            .ok_or_else(|| format!("`axes` must be from 1 to {MAX_AXES} (got {v})"))
    });
    let load = c.float(Key::CPU_LOAD);
    if let Some(load) = load {
        if !(load > 0.0 && load <= 1.0) {
            let (i, _) = c.find(Key::CPU_LOAD)?;
            c.at_arg(
                i,
                false,
                format!(
                    "`cpu_load` must be a share of the CPU above 0 and at most 1 (got {})",
                    Num(load)
                ),
            );
        }
    }
    if c.diagnostics.len() != errors {
        return None;
    }
    let (core, cpu_hz) = match (core, cpu_hz) {
        (Some(core), Some(hz)) => (core, hz),
        (core, _) => {
            let (given, missing) = match core {
                Some(_) => (Key::CORE, "`cpu_hz`, the core's clock".to_string()),
                None => {
                    let given = BUDGET.into_iter().find(|k| c.find(*k).is_some())?;
                    let names: Vec<String> =
                        CORES.iter().map(|(n, _)| format!("\"{n}\"")).collect();
                    let missing = format!("`core` (one of {}) and `cpu_hz`", names.join(", "));
                    (given, missing)
                }
            };
            let (i, _) = c.find(given)?;
            c.at_arg(
                i,
                true,
                format!("`{given}` checks the step interrupt's budget, which needs {missing}"),
            );
            return None;
        }
    };
    if core == Core::Avr && axes.is_some_and(|a| a > 1) {
        let (i, _) = c.find(Key::AXES)?;
        c.at_arg(
            i,
            false,
            "`core = \"avr\"` measures the C player, which steps one axis".to_string(),
        );
        return None;
    }
    Some(Cpu {
        axes: axes.unwrap_or(1),
        max_load: load.unwrap_or(0.5),
        ..Cpu::new(core, cpu_hz)
    })
}

/// Resonance bands (`avoid`), full steps/s, in a table of the motor's
/// `microsteps` (1 without a motor). `None` without the key, or with an
/// error (reported).
pub(crate) fn avoid<L: Clone>(c: &mut Collector<'_, L>, motor: Option<&Motor>) -> Option<Bands> {
    let (i, arg) = c.find(Key::AVOID)?;
    let points = match &arg.value {
        Value::Points(points) => points.clone(),
        Value::Refused { message, part } => {
            let (message, part) = (message.clone(), *part);
            c.at_part(i, part, message);
            return None;
        }
        other => {
            let message = format!(
                "`avoid` expects a list of (lowest, highest) full steps/s bands, such as \
                 `[(80, 120)]` in the macro or `[[80, 120]]` in a profiles file, got {}",
                other.quoted()
            );
            c.at_arg(i, false, message);
            return None;
        }
    };
    if points.is_empty() || points.len() > MAX_BANDS {
        let message = format!(
            "`avoid` must have from 1 to {MAX_BANDS} bands (got {})",
            points.len()
        );
        c.at_arg(i, false, message);
        return None;
    }
    for (part, &(lo, hi)) in points.iter().enumerate() {
        if !(lo.is_finite() && hi.is_finite() && lo >= 0.0 && lo < hi) {
            let message = format!(
                "`avoid` bands are (lowest, highest) full steps/s, from 0 up, the lowest below \
                 the highest (got ({}, {}))",
                Num(lo),
                Num(hi)
            );
            c.at_part(i, part, message);
            return None;
        }
    }
    Some(Bands::new(&points, motor.map_or(1, |m| m.microsteps)))
}
