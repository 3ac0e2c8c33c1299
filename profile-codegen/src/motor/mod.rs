//! The motor a table drives, and the check that it can follow the table.
//!
//! A ramp the motor cannot follow loses steps, as every article on ramps
//! warns ("Design and implementation of speed increase/decrease in stepper
//! motor control"; Zeng, Hu and Hu, "Control Algorithm of Acceleration Curve
//! for Stepper Motor", 2016; the S3C4510 article). From the
//! integer table itself, [`Motor::check`] computes the angular acceleration
//! each step demands, the torque that needs (`J α` for the rotor and load,
//! plus friction and viscous damping `β ω`), and the torque the motor gives
//! at that step frequency (its pull-out curve over the safety factor). A step
//! that needs more is an error naming the step, the frequency, both torques
//! and the shortfall; otherwise the smallest margin and where it is are the
//! table's figures.
//!
//! The acceleration judged is the one the rotor feels: the table's, its
//! speed averaged on each side of an edge over at least one full step
//! (`microsteps` entries) and at least the rotor's `1 / ω_n`
//! ([`Motor::felt_window`]). Rounding to whole timer ticks makes consecutive
//! periods differ by a tick or so, which read one by one are accelerations
//! far above the ramp's (on a 1 MHz timer a 1/8-step ramp at 28 kHz would
//! read 0.29 N·m of torque on a 1e-4 kg·m² load from one tick), yet they
//! move the field by a small fraction of a step, which the rotor, a spring
//! and mass of natural frequency `ω_n`, does not follow (the simulation in
//! `simulate` shows it). A change of speed faster than `1 / ω_n` (a segment
//! table's jump) pulls the rotor with the spring's torque, `J Δω ω_n`: what
//! the window reads.
//!
//! Units: angles in degrees as written (`step_angle`), inertia in kg·m²,
//! torque in N·m, damping in N·m·s/rad, frequencies in Hz of the table's
//! steps (microsteps when `microsteps > 1`).

pub(crate) mod bounds;
mod builder;
mod check;
mod chopper;
mod limited;
// Public as `simulate`, at the crate root (one path per item); declared
// here, beside the model it plays.
#[doc(hidden)]
pub mod simulate;
mod start;
mod stepped;
mod windings;

pub use start::{Remedies, StartLimit};
pub use windings::{CurrentSetting, Drive, Windings};

use core::fmt;

use crate::numbers::{Fixed, Num};
use profile_core::Key;

/// The largest [`Motor::damping_ratio`]: critical damping. A motor's own
/// electromagnetic damping is a small fraction of it.
pub const MAX_DAMPING_RATIO: f64 = 1.0;

/// The most table steps per full step [`Motor::validate`] takes: the finest
/// microstepping drivers set 1/256, and the check's and the simulation's
/// work grows with it.
pub const MAX_MICROSTEPS: u32 = 1024;

/// The most points a pull-out torque curve may have.
pub const MAX_CURVE_POINTS: usize = 32;

/// A pull-out torque curve: `(step frequency in Hz, torque in N·m)` points
/// with rising frequencies, interpolated linearly. Below the first point the
/// first torque holds; beyond the last point the motor is not characterised
/// and gives no torque, so a ramp must stay within the curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TorqueCurve {
    points: [(f64, f64); MAX_CURVE_POINTS],
    len: usize,
}

impl TorqueCurve {
    /// A curve from up to [`MAX_CURVE_POINTS`] points; `None` when there are
    /// more or none.
    pub fn new(points: &[(f64, f64)]) -> Option<Self> {
        if points.is_empty() || points.len() > MAX_CURVE_POINTS {
            return None;
        }
        let mut curve = TorqueCurve {
            points: [(0.0, 0.0); MAX_CURVE_POINTS],
            len: points.len(),
        };
        curve.points[..points.len()].copy_from_slice(points);
        Some(curve)
    }

    /// The points.
    pub fn points(&self) -> &[(f64, f64)] {
        &self.points[..self.len]
    }

    /// The torque at step frequency `hz`, in N·m.
    pub fn torque(&self, hz: f64) -> f64 {
        let p = self.points();
        let Some(&(f0, t0)) = p.first() else {
            return 0.0;
        };
        if hz <= f0 {
            return t0;
        }
        for w in p.windows(2) {
            let ((fa, ta), (fb, tb)) = (w[0], w[1]);
            if hz <= fb {
                return ta + (tb - ta) * (hz - fa) / (fb - fa);
            }
        }
        0.0
    }

    /// The frequency of the last point, in Hz.
    pub fn top(&self) -> f64 {
        self.points().last().map_or(0.0, |p| p.0)
    }
}

/// A stepper motor and its load.
///
/// Build one with [`Motor::new`] and the `with_*` methods (`const`, so a
/// motor can be a `const` item); the fields stay public to read and assign.
/// It is `#[non_exhaustive]`: it may gain fields, each with a default that
/// leaves the model as it was.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Motor {
    /// Full-step angle, in degrees (1.8 for 200 steps per turn).
    pub step_angle: f64,
    /// Microsteps per full step: the table's steps are microsteps.
    pub microsteps: u32,
    /// Rotor inertia, in kg·m².
    pub rotor_inertia: f64,
    /// Load inertia seen at the shaft, in kg·m².
    pub load_inertia: f64,
    /// Pull-out torque against the table's step frequency, as measured
    /// (a datasheet's curve). When given, it is the torque the check and the
    /// simulation use; otherwise the curve is derived from `windings`.
    pub torque_curve: Option<TorqueCurve>,
    /// The windings and the driver, from which the pull-out torque is
    /// derived when `torque_curve` is `None` ([`Windings::pull_out`]). A
    /// motor needs one or the other.
    pub windings: Option<Windings>,
    /// Constant load and friction torque, in N·m.
    pub friction: f64,
    /// Viscous damping, in N·m·s/rad: a drag on the rotor's own speed
    /// (bearings, a fluid), `damping · ω`.
    pub damping: f64,
    /// Electromagnetic damping as a ratio of critical damping, `ζ` (0 for
    /// none): the torque `D · (ω_cmd - ω)` that pulls the rotor's speed
    /// towards the field's, `D = 2 ζ sqrt(K J)` with the stiffness
    /// `K = N_r · T_hold` ([`Motor::stiffness`]). It acts on the rotor's
    /// speed relative to the field, so it does not drag a rotor that keeps up.
    pub damping_ratio: f64,
    /// The available torque is divided by this (at least 1).
    pub safety: f64,
    /// Maximum no-load start frequency, in Hz of the table's steps, if known
    /// (a datasheet's start or pull-in frequency without load). A ramp must
    /// start below it once corrected for the load (the advice of "Design
    /// and implementation of speed increase/decrease in stepper motor
    /// control"): see [`Motor::start_limit`]. Without it the limit comes from
    /// the model.
    pub max_start_hz: Option<f64>,
}

/// Where the motor has the least torque to spare over a ramp.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct TorqueFigures {
    /// Smallest available minus needed torque, in N·m.
    pub min_margin_nm: f64,
    /// The step (index of the table entry after the edge) where it is.
    pub step: u32,
    /// The step frequency there, in Hz.
    pub hz: f64,
    /// Torque needed there, in N·m.
    pub needed_nm: f64,
    /// Torque available there (over the safety factor), in N·m.
    pub available_nm: f64,
}

/// Why a motor cannot follow a table, or cannot be described as given.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum MotorError {
    /// A parameter out of range: `key` must satisfy `expected`.
    Invalid {
        /// The motor key.
        key: Key,
        /// Its value.
        value: f64,
        /// What is expected, in words.
        expected: &'static str,
    },
    /// The torque curve's points must be finite numbers, its frequencies
    /// rise from 0 or more up to 1e8 Hz and its torques be above 0 and up
    /// to 10 000 N·m.
    Curve {
        /// The offending point's index, from 0.
        index: usize,
        /// Its frequency, in Hz.
        hz: f64,
        /// Its torque, in N·m.
        nm: f64,
    },
    /// A step needs more torque than the motor gives.
    Torque {
        /// The step.
        step: u32,
        /// Its frequency, in Hz.
        hz: f64,
        /// Torque needed, in N·m.
        needed_nm: f64,
        /// Torque available over the safety factor, in N·m.
        available_nm: f64,
        /// Whether the frequency is beyond the torque curve's last point.
        beyond_curve: bool,
        /// The drive, when the torque available is derived from the
        /// windings (no `torque_curve` given).
        from_windings: Option<Drive>,
    },
    /// A torque the check computes is not a finite number: the motor's
    /// figures are too large for `f64` arithmetic.
    NotFinite {
        /// The step where it happens.
        step: u32,
        /// What is not finite: `needed`, `available` or their difference,
        /// `margin`.
        what: &'static str,
    },
    /// The table to check has no entries.
    EmptyTable,
    /// The motor has neither a torque curve nor windings to derive one
    /// from.
    NoTorque,
    /// The model's rotor, from rest, slips on the ramp's first steps before
    /// it reaches the field's speed: the start and the acceleration right
    /// after it are too much together.
    PullIn {
        /// The pulse before which it slips, from 1.
        pulse: u32,
        /// The ramp's start frequency, in Hz.
        hz: f64,
        /// What the model found would let its rotor start.
        remedies: Remedies,
    },
    /// The model's rotor slips on the shortest move the ramp's start makes:
    /// from rest up the ramp's first entries (16 full steps) and down again,
    /// then held.
    ShortMove {
        /// The ramp's start frequency, in Hz.
        hz: f64,
        /// The pulse before which it slips, from 1; `steps + 1` when it
        /// slips after the last pulse, the field held.
        pulse: u32,
        /// The move's steps.
        steps: u32,
        /// What the model found would let its rotor make the move.
        remedies: Remedies,
    },
    /// The loaded rotor cannot pull in to the ramp's first step from rest.
    Start {
        /// The ramp's start frequency, in Hz.
        hz: f64,
        /// The fastest start the loaded rotor follows, and how it was found.
        limit: StartLimit,
    },
    /// A `torque_limited` ramp whose table, on 0.8 of the torque its
    /// `margin` allows, still needs more than that at an edge, read off
    /// its rounded periods: too few ticks a period for the torque there is
    /// to spare there.
    MarginUnkept {
        /// The step (index of the table entry after the edge).
        step: u32,
        /// The step frequency there, in Hz.
        hz: f64,
        /// The torque the edge needs, in N·m.
        needed_nm: f64,
        /// The torque `margin` allows there (the pull-out torque times
        /// `margin`, over the safety factor), in N·m.
        available_nm: f64,
    },
    /// A `torque_limited` ramp: at `hz` the motor has no torque to spare
    /// for accelerating.
    NoSpareTorque {
        /// The step frequency, in Hz.
        hz: f64,
        /// The torque the ramp plans on there (its margin's share of the
        /// torque after the safety factor), in N·m.
        available_nm: f64,
        /// What the load, friction and damping take there, in N·m.
        load_nm: f64,
    },
}

impl MotorError {
    /// The key a front end should point at.
    pub fn key(&self) -> Key {
        match *self {
            MotorError::Invalid { key, .. } => key,
            MotorError::Curve { .. } | MotorError::NoTorque => Key::TORQUE_CURVE,
            MotorError::Torque { .. }
            | MotorError::Start { .. }
            | MotorError::PullIn { .. }
            | MotorError::ShortMove { .. } => Key::MOTOR,
            MotorError::NotFinite { .. } => Key::ROTOR_INERTIA,
            MotorError::EmptyTable => Key::MOTOR,
            MotorError::NoSpareTorque { .. } | MotorError::MarginUnkept { .. } => Key::FMAX,
        }
    }
}

impl fmt::Display for MotorError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            MotorError::Invalid {
                key,
                value,
                expected,
            } => {
                write!(f, "`{key}` must be {expected} (got {})", Num(value))
            }
            MotorError::Curve { index, hz, nm } if !(hz.is_finite() && nm.is_finite()) => {
                let (what, value) = if hz.is_finite() {
                    ("torque", nm)
                } else {
                    ("frequency", hz)
                };
                write!(
                    f,
                    "`torque_curve` point {}'s {what} must be a finite number (got {})",
                    index + 1,
                    Num(value)
                )
            }
            MotorError::Curve { index, hz, nm } => {
                write!(
                    f,
                    "`torque_curve` point {} ({}, {}) must have ",
                    index + 1,
                    Num(hz),
                    Num(nm)
                )?;
                f.write_str(if index == 0 {
                    "a frequency from 0"
                } else {
                    "a frequency higher than the point before it and"
                })?;
                f.write_str(" up to 1e8 Hz, and a torque above 0 and up to 10000 N·m")
            }
            MotorError::Torque {
                step,
                hz,
                needed_nm,
                available_nm,
                beyond_curve,
                from_windings,
            } => torque(
                f,
                (step, hz),
                (needed_nm, available_nm),
                beyond_curve,
                from_windings,
            ),
            MotorError::NotFinite { step, what } => write!(
                f,
                "the torque {what} at step {step} is not a finite number: the motor's inertia, \
                 friction, damping or torque is too large to compute with"
            ),
            MotorError::EmptyTable => f.write_str("the table to check has no entries"),
            MotorError::NoTorque => f.write_str(
                "the motor has no pull-out torque: give `torque_curve`, or the windings' \
                 `resistance`, `inductance`, `rated_current`, `holding_torque` and \
                 `supply_voltage`",
            ),
            MotorError::PullIn {
                pulse,
                hz,
                remedies,
            } => start::pull_in(f, pulse, hz, remedies),
            MotorError::ShortMove {
                hz,
                pulse,
                steps,
                remedies,
            } => start::short_move(f, hz, (pulse, steps), remedies),
            MotorError::Start { hz, limit } => start::start(f, hz, limit),
            MotorError::MarginUnkept { .. } | MotorError::NoSpareTorque { .. } => limited(f, self),
        }
    }
}

/// The messages of a `torque_limited` ramp the motor cannot give:
/// [`MotorError::MarginUnkept`] and [`MotorError::NoSpareTorque`].
fn limited(f: &mut fmt::Formatter<'_>, e: &MotorError) -> fmt::Result {
    match *e {
        MotorError::MarginUnkept {
            step,
            hz,
            needed_nm,
            available_nm,
        } => write!(
            f,
            "a `torque_limited` ramp cannot keep its `margin` on this timer: at step {step} \
             ({} Hz) its periods, rounded to whole ticks, read as needing {} N·m where \
             `margin` of the torque is {} N·m, even planned on 0.8 of it; raise \
             `timer_hz`, lower `fmax` or raise `margin`",
            Fixed(hz, 1),
            Fixed(needed_nm, 4),
            Fixed(available_nm, 4)
        ),
        MotorError::NoSpareTorque {
            hz,
            available_nm,
            load_nm,
        } => write!(
            f,
            "the motor has no torque to spare at {} Hz to accelerate a `torque_limited` \
             ramp: the ramp plans on {} N·m of its torque there (`margin` of it, after the \
             safety factor), and the load, friction and damping take {} N·m; lower `fmax` \
             or raise `margin`",
            Fixed(hz, 1),
            Fixed(available_nm, 4),
            Fixed(load_nm, 4)
        ),
        _ => Ok(()),
    }
}

/// [`MotorError::Torque`]'s message: step `step` at `hz`, the torque
/// needed and available.
fn torque(
    f: &mut fmt::Formatter<'_>,
    (step, hz): (u32, f64),
    (needed_nm, available_nm): (f64, f64),
    beyond_curve: bool,
    from_windings: Option<Drive>,
) -> fmt::Result {
    let hz = Fixed(hz, 1);
    if step == 0 {
        write!(f, "the motor cannot start at {hz} Hz")?;
    } else {
        write!(f, "the motor cannot follow step {step} at {hz} Hz")?;
    }
    write!(
        f,
        ": it needs {} N·m but gives {} N·m after the safety factor, short by {} N·m",
        Fixed(needed_nm, 4),
        Fixed(available_nm, 4),
        Fixed(needed_nm - available_nm, 4)
    )?;
    if beyond_curve {
        f.write_str(" (the frequency is beyond the last point of `torque_curve`)")?;
    }
    match from_windings {
        Some(Drive::HalfStep) => {
            f.write_str(" (the pull-out torque derived from the windings, in half steps)")
        }
        Some(Drive::FullStep) => {
            f.write_str(" (the pull-out torque derived from the windings, in full steps)")
        }
        Some(_) => f.write_str(" (the pull-out torque derived from the windings)"),
        None => Ok(()),
    }
}

impl std::error::Error for MotorError {}

impl Motor {
    /// Checks every parameter. Each figure is taken within the range of
    /// every stepper motor, and far beyond, so that a figure outside is a
    /// mistake (a unit, an exponent) and the check's arithmetic stays
    /// finite: `step_angle` from 0.01 to 180 degrees, `microsteps` from 1
    /// to [`MAX_MICROSTEPS`], `rotor_inertia` from
    /// 1e-12 to 10 kg·m², `load_inertia` from 0 to 10 000 kg·m², `friction`
    /// from 0 to 10 000 N·m, `damping` from 0 to 10 000 N·m·s/rad,
    /// `damping_ratio` from 0 to 1, `safety` from 1 to 1000, `max_start_hz`
    /// from 0.001 to 1e8 Hz, the torque curve's points at frequencies from 0
    /// to 1e8 Hz, rising, with torques above 0 and at most 10 000 N·m; the
    /// windings as [`Windings::validate`] checks them.
    pub fn validate(&self) -> Result<(), MotorError> {
        if !(1..=MAX_MICROSTEPS).contains(&self.microsteps) {
            return Err(MotorError::Invalid {
                key: Key::MICROSTEPS,
                value: f64::from(self.microsteps),
                expected: "from 1 to 1024",
            });
        }
        bounds::check(&bounds::MOTOR, self)?;
        if let Some(windings) = &self.windings {
            windings.validate()?;
            self.validate_drive(windings.drive)?;
        }
        let Some(curve) = &self.torque_curve else {
            return match self.windings {
                Some(_) => Ok(()),
                None => Err(MotorError::NoTorque),
            };
        };
        let mut prev = f64::NEG_INFINITY;
        for (index, &(hz, nm)) in curve.points().iter().enumerate() {
            let hz_ok = hz >= 0.0 && hz > prev && hz <= bounds::CURVE_HZ;
            if !(hz_ok && nm > 0.0 && nm <= bounds::CURVE_NM) {
                return Err(MotorError::Curve { index, hz, nm });
            }
            prev = hz;
        }
        Ok(())
    }

    /// A driver that steps the current plays its own steps, one per table
    /// entry: half steps (`microsteps = 2`) or full steps (`microsteps = 1`).
    fn validate_drive(&self, drive: Drive) -> Result<(), MotorError> {
        let (steps, expected) = match drive {
            Drive::Sine => return Ok(()),
            Drive::HalfStep => (
                2,
                "2 with `drive = half_step`: the driver moves half a step per pulse, so each \
                 table step is a half step",
            ),
            Drive::FullStep => (
                1,
                "1 with `drive = full_step`: the driver moves a full step per pulse, so each \
                 table step is a full step",
            ),
        };
        if self.microsteps == steps {
            return Ok(());
        }
        Err(MotorError::Invalid {
            key: Key::MICROSTEPS,
            value: f64::from(self.microsteps),
            expected,
        })
    }

    /// Radians per table step.
    pub fn step_radians(&self) -> f64 {
        self.step_angle.to_radians() / self.microsteps as f64
    }

    /// Torque available at step frequency `hz` over the safety factor, in
    /// N·m: 0 for a motor [`Motor::validate`] refuses, and for `hz` not
    /// finite.
    pub fn available(&self, hz: f64) -> f64 {
        self.pull_out(hz) / self.safety
    }

    /// [`Motor::available`] for a motor already validated and a finite
    /// `hz`.
    pub(crate) fn available_of_valid(&self, hz: f64) -> f64 {
        self.pull_out_of_valid(hz) / self.safety
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn curve_interpolates_and_stops_at_its_end() {
        let c = TorqueCurve::new(&[(0.0, 0.4), (1000.0, 0.3), (3000.0, 0.1)]).unwrap();
        assert_eq!(c.torque(0.0), 0.4);
        assert!((c.torque(500.0) - 0.35).abs() < 1e-12);
        assert!((c.torque(2000.0) - 0.2).abs() < 1e-12);
        assert_eq!(c.torque(3000.1), 0.0);
        assert!(TorqueCurve::new(&[]).is_none());
        assert!(TorqueCurve::new(&[(0.0, 1.0); MAX_CURVE_POINTS + 1]).is_none());
    }
}
