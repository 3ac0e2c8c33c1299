//! Saying where a problem is, and what a spec holds, as a user writes it.

use std::string::{String, ToString};
use std::vec::Vec;

use super::{Arg, Diagnostic};
use crate::motor::{Motor, MotorError, StartLimit};
use crate::numbers::Num;
use crate::numbers::Significant;
use crate::schema::curves::Param;
use profile_core::Error;
use profile_core::Key;
use profile_core::Spec;

/// The spec's parameters as `(key, value)` pairs, in documentation order, as
/// a user would write them (defaults included, but `reload_offset` only
/// where it is not 0): for docs, headers, reports.
pub fn describe(spec: &Spec) -> Vec<(Key, String)> {
    let mut out = std::vec![(Key::CURVE, spec.curve.name().to_string())];
    super::curves::describe(&spec.curve, &mut |key, value| {
        out.push((
            key,
            match value {
                Param::Number(v) => super::units::show(key, v),
                Param::Count(n) => n.to_string(),
            },
        ))
    });
    out.extend([
        (
            Key::TIMER_HZ,
            super::units::show(Key::TIMER_HZ, f64::from(spec.timer.timer_hz)),
        ),
        (Key::WORD, spec.timer.word.name().to_string()),
        (Key::TICKS_PER_STEP, spec.timer.ticks_per_step.to_string()),
    ]);
    if spec.reload_offset != 0 {
        out.push((Key::RELOAD_OFFSET, spec.reload_offset.to_string()));
    }
    out.extend([
        (Key::DISCRETIZATION, spec.discretization.name().to_string()),
        (Key::ROUNDING, spec.rounding.name().to_string()),
        (Key::ARITHMETIC, spec.arithmetic.name().to_string()),
    ]);
    out
}

/// A motor's figures as `(key, value)` pairs, in documentation order,
/// defaults included, in the units its datasheet prints (`68 g·cm²`,
/// `0.6 mH`): what the check reads, for reports. A torque curve's points
/// in Hz and N·m, as a profiles file writes them.
pub fn describe_motor(motor: &Motor) -> Vec<(Key, String)> {
    let show = |key: Key, v: f64| (key, super::units::show(key, v));
    let mut out = std::vec![
        show(Key::STEP_ANGLE, motor.step_angle),
        (Key::MICROSTEPS, motor.microsteps.to_string()),
        show(Key::ROTOR_INERTIA, motor.rotor_inertia),
        show(Key::LOAD_INERTIA, motor.load_inertia),
    ];
    if let Some(curve) = &motor.torque_curve {
        let points: Vec<String> = curve
            .points()
            .iter()
            .map(|(hz, nm)| std::format!("[{}, {}]", Num(*hz), Num(*nm)))
            .collect();
        out.push((Key::TORQUE_CURVE, std::format!("[{}]", points.join(", "))));
    }
    if let Some(w) = &motor.windings {
        out.extend([
            show(Key::RESISTANCE, w.resistance),
            show(Key::INDUCTANCE, w.inductance),
            show(Key::RATED_CURRENT, w.rated_current),
            show(Key::HOLDING_TORQUE, w.holding_torque),
            show(Key::SUPPLY_VOLTAGE, w.supply_voltage),
            show(Key::DETENT_TORQUE, w.detent_torque),
            (Key::DRIVE, w.drive.name().to_string()),
            show(Key::DRIVER_CURRENT, w.setting()),
            (
                Key::DRIVER_CURRENT_IS,
                w.driver_current_is.name().to_string(),
            ),
            (
                Key::SUPPLY_UTILIZATION,
                Num(w.supply_utilization).to_string(),
            ),
            // The default, a share of the holding torque, to the figures
            // a datasheet prints (0.044, not 0.044000000000000004).
            show(Key::IRON_LOSS, six_digits(w.iron_loss_at_1khz())),
        ]);
    }
    out.extend([
        show(Key::FRICTION, motor.friction),
        show(Key::DAMPING, motor.damping),
        (Key::DAMPING_RATIO, Num(motor.damping_ratio).to_string()),
        (Key::SAFETY, Num(motor.safety).to_string()),
    ]);
    if let Some(hz) = motor.max_start_hz {
        out.push(show(Key::MAX_START_HZ, hz));
    }
    out
}

/// Places a motor error: at a torque curve's point it blames, at the value
/// of its key, at `motor` for a table the
/// motor cannot follow (when no `motor` names it: for a start too fast at
/// `max_start_hz`, or at `fmin` when the model judged it or the ends of a
/// move; at `supply_voltage` for a torque the windings give too little of;
/// at `drive` for `microsteps` a stepped drive does not take, when
/// `microsteps` is not written; else at `torque_curve`), or on `whole`.
pub fn locate_motor<L: Clone>(error: &MotorError, args: &[Arg<L>], whole: &L) -> Diagnostic<L> {
    let find = |k: Key| {
        args.iter()
            .find(|a| a.key == k.name())
            .map(|a| a.value_loc.clone())
    };
    let inline = match error {
        MotorError::Start {
            limit: StartLimit::Model { .. },
            ..
        }
        | MotorError::PullIn { .. }
        | MotorError::ShortMove { .. } => Key::FMIN,
        MotorError::Start { .. } => Key::MAX_START_HZ,
        MotorError::NoSpareTorque { .. } | MotorError::MarginUnkept { .. } => Key::FMAX,
        MotorError::Torque {
            from_windings: Some(_),
            ..
        } => Key::SUPPLY_VOLTAGE,
        // `microsteps` left at 1 under a stepped drive: at the drive.
        MotorError::Invalid {
            key: Key::MICROSTEPS,
            ..
        } => Key::DRIVE,
        _ => Key::TORQUE_CURVE,
    };
    // A torque curve's point, where the front door knows where it is.
    let point = match error {
        MotorError::Curve { index, .. } => args
            .iter()
            .find(|a| a.key == Key::TORQUE_CURVE.name())
            .and_then(|a| a.parts.get(*index).cloned()),
        _ => None,
    };
    let loc = point
        .or_else(|| find(error.key()))
        .or_else(|| find(inline))
        .or_else(|| find(Key::TORQUE_CURVE))
        .unwrap_or_else(|| whole.clone());
    Diagnostic {
        loc,
        message: error.to_string(),
    }
}

/// Places a core error at the value of the key it blames (or on `whole`).
pub fn locate<L: Clone>(error: &Error, args: &[Arg<L>], whole: &L) -> Diagnostic<L> {
    at_value(error.key(), args, whole, error.to_string())
}

/// `message` at the value of `key` among `args`, or on `whole` where the
/// key is not given.
pub(crate) fn at_value<L: Clone>(
    key: Option<Key>,
    args: &[Arg<L>],
    whole: &L,
    message: String,
) -> Diagnostic<L> {
    let loc = key
        .and_then(|k| args.iter().find(|a| a.key == k.name()))
        .map_or(whole, |a| &a.value_loc)
        .clone();
    Diagnostic { loc, message }
}

/// `v` to six significant digits, as messages print figures.
fn six_digits(v: f64) -> f64 {
    Significant(v).to_string().parse().unwrap_or(v)
}
