//! The start from rest: the fastest step rate the loaded rotor pulls in to,
//! from a datasheet's no-load figure or from the model, and the motor's
//! stiffness and electromagnetic damping the model uses.

use core::fmt;

use crate::motor::simulate::{Rotor, natural_period, stable_step, step_for, substeps};
use crate::motor::{Motor, MotorError};
use crate::numbers::{Fixed, Num};

/// The fastest step frequency a motor starts at from rest with its load,
/// and how it was found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StartLimit {
    /// A datasheet's no-load start frequency corrected for the load's
    /// inertia: `max_start_hz / sqrt(1 + load_inertia / rotor_inertia)`, the
    /// sizing rule of motor makers (Oriental Motor's "Motor Sizing
    /// Calculations": `f = f_s / sqrt(1 + J_L / J_0)`).
    Corrected {
        /// The limit, in Hz.
        hz: f64,
        /// `max_start_hz`, in Hz.
        max_start_hz: f64,
        /// `sqrt(1 + load_inertia / rotor_inertia)`.
        factor: f64,
    },
    /// From the model: the fastest constant step rate the rotor, starting at
    /// rest, pulls in to (reaches the field's speed before its lag passes
    /// 180° electrical, within four full steps), under the
    /// pull-out torque over the safety factor.
    Model {
        /// The limit, in Hz (to a thousandth of a hertz).
        hz: f64,
    },
}

impl StartLimit {
    /// The limit, in Hz of the table's steps.
    pub fn hz(&self) -> f64 {
        match *self {
            StartLimit::Corrected { hz, .. } | StartLimit::Model { hz } => hz,
        }
    }
}

/// Full steps of the start the model plays from rest at a constant rate:
/// one electrical turn, in which a rotor that cannot pull in falls behind
/// the field by more than half a turn.
pub(crate) const START_FULL_STEPS: u32 = 4;

/// Full steps of each end of a move the check plays to the model's rotor
/// ([`Motor::check`]): from rest up the ramp's first entries, and the
/// shortest move up them and down again.
pub(crate) const END_FULL_STEPS: u32 = 4 * START_FULL_STEPS;

/// The field damping ratio the model tries when its rotor slips at an end
/// of a move with less ([`Remedies::damping`]): a small fraction of
/// critical, as a motor's own electromagnetic damping is.
pub(crate) const REMEDY_DAMPING_RATIO: f64 = 0.1;

/// What the model found, by playing them, would let its rotor make an end
/// of a move it slips on. A refusal advises only what is found here.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub struct Remedies {
    /// Tried (the motor's `damping_ratio` is below 0.1) and found to
    /// help: with `damping_ratio = 0.1` the rotor makes it.
    pub damping: Option<bool>,
    /// The same pulses at half the rate (every period doubled: half the
    /// start frequency, a quarter of the acceleration) let the rotor make
    /// it.
    pub slower: bool,
}

/// The relative resolution of a start limit found from the model.
pub(crate) const START_RESOLUTION: f64 = 1e-3;

/// Above this bound (Hz), [`Motor::start_limit`] narrows its search
/// geometrically before it bisects.
const GEOMETRIC_ABOVE: f64 = 1e6;

impl Motor {
    /// The torque-angle stiffness at rest, `K = N_r · T_hold` in N·m/rad:
    /// `N_r` electrical radians per mechanical radian (90° electrical per
    /// full step), `T_hold` the pull-out torque at 0 Hz.
    pub fn stiffness(&self) -> f64 {
        self.poles() * self.pull_out(0.0)
    }

    /// Electrical radians per mechanical radian: a full step is 90°
    /// electrical (50 for a 1.8° motor, its rotor's teeth).
    pub fn poles(&self) -> f64 {
        core::f64::consts::FRAC_PI_2 / self.step_angle.to_radians()
    }

    /// The electromagnetic damping coefficient `D = 2 ζ sqrt(K J)`, in
    /// N·m·s/rad, from [`Motor::damping_ratio`].
    pub fn field_damping(&self) -> f64 {
        2.0 * self.damping_ratio
            * libm::sqrt(self.stiffness() * (self.rotor_inertia + self.load_inertia))
    }

    /// Whether the loaded rotor starts from rest at `hz` (table steps per
    /// second): below `max_start_hz` corrected for the load when it is
    /// given, otherwise when the model's rotor follows a constant rate of
    /// `hz` (pulls in within four full steps). A motor
    /// [`Motor::validate`] refuses starts at no rate.
    pub fn starts_at(&self, hz: f64) -> bool {
        if self.validate().is_err() {
            return false;
        }
        match self.max_start_hz {
            Some(_) => hz <= self.start_limit(hz).hz(),
            None => pulls_in(self, hz),
        }
    }

    /// The fastest start from rest with the load: `max_start_hz` corrected
    /// for the load when it is given; otherwise the fastest constant rate,
    /// searched by bisection below `below` Hz (to a thousandth of a hertz;
    /// geometric first from 1 Hz when `below` is above a million, or
    /// infinite), at which the model's rotor pulls in from rest. A motor
    /// [`Motor::validate`] refuses starts at no rate: `Model` at 0 Hz.
    pub fn start_limit(&self, below: f64) -> StartLimit {
        if self.validate().is_err() {
            return StartLimit::Model { hz: 0.0 };
        }
        if let Some(max_start_hz) = self.max_start_hz {
            let factor = libm::sqrt(1.0 + self.load_inertia / self.rotor_inertia);
            return StartLimit::Corrected {
                hz: max_start_hz / factor,
                max_start_hz,
                factor,
            };
        }
        let (mut lo, mut hi) = (0.0, below);
        if pulls_in(self, hi) {
            return StartLimit::Model { hz: hi };
        }
        // A bound far above any step rate (a motor whose torque never
        // falls): narrow it by geometric halving from 1 Hz first, so that
        // the linear search starts within a factor of two.
        if hi > GEOMETRIC_ABOVE {
            hi = hi.min(f64::MAX);
            if pulls_in(self, 1.0) {
                lo = 1.0;
                for _ in 0..64 {
                    if hi <= 2.0 * lo {
                        break;
                    }
                    let mid = libm::sqrt(lo) * libm::sqrt(hi);
                    if pulls_in(self, mid) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
            } else {
                hi = 1.0;
            }
        }
        // At most 64 halvings: the interval shrinks below the resolution
        // long before (2^-10 per ten), or the loop ends regardless.
        for _ in 0..64 {
            if hi - lo <= START_RESOLUTION * hi {
                break;
            }
            let mid = 0.5 * (lo + hi);
            if pulls_in(self, mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        StartLimit::Model { hz: lo }
    }

    /// The ends of a move on `periods`, played to the model's rotor: from
    /// rest, the start must pull in before the rotor slips; and the shortest
    /// move on the ramp's start (up its first 16 full steps,
    /// down again, the field held) must leave the rotor within the field's stable region.
    pub(super) fn check_ends(&self, per_second: f64, periods: &[u32]) -> Result<(), MotorError> {
        let hz = per_second / periods.first().map_or(1, |&p| p) as f64;
        let window = END_FULL_STEPS as usize * self.microsteps.max(1) as usize;
        let window = &periods[..window.min(periods.len())];
        // The start up the window, then the shortest move: up and down.
        let start = |motor: &Motor, stretch: f64| {
            let seconds = |p: &u32| *p as f64 * stretch / per_second;
            meets(motor, window.iter().map(seconds), End::Start)
        };
        let short = |motor: &Motor, stretch: f64| {
            let seconds = |p: &u32| *p as f64 * stretch / per_second;
            let there_and_back = window.iter().chain(window.iter().rev());
            meets(motor, there_and_back.map(seconds), End::Stop)
        };
        if let Some(pulse) = start(self, 1.0) {
            let remedies = self.remedies(|m, stretch| start(m, stretch).is_none());
            return Err(MotorError::PullIn {
                pulse,
                hz,
                remedies,
            });
        }
        if let Some(pulse) = short(self, 1.0) {
            let remedies = self.remedies(|m, stretch| short(m, stretch).is_none());
            return Err(MotorError::ShortMove {
                hz,
                pulse,
                steps: 2 * window.len() as u32,
                remedies,
            });
        }
        Ok(())
    }

    /// Which changes let the model's rotor make an end of a move it slips
    /// on: `makes(motor, stretch)` plays it to `motor` with every period
    /// `stretch` times as long.
    fn remedies(&self, makes: impl Fn(&Motor, f64) -> bool) -> Remedies {
        let damping = (self.damping_ratio < REMEDY_DAMPING_RATIO)
            .then(|| makes(&self.with_damping_ratio(REMEDY_DAMPING_RATIO), 1.0));
        Remedies {
            damping,
            slower: makes(self, 2.0),
        }
    }
}

/// The most integration steps of one start judged from the model
/// ([`Motor::starts_at`]).
pub(crate) const START_MAX_STEPS: u64 = 200_000;

/// Whether the rotor, at rest and aligned, pulls in to a field stepping at a
/// constant `hz` table steps per second: reaches the field's speed without
/// slipping, within [`START_FULL_STEPS`] full steps, under the pull-out
/// torque at `hz` over the safety factor.
pub(super) fn pulls_in(motor: &Motor, hz: f64) -> bool {
    if hz <= 0.0 {
        return true;
    }
    if !hz.is_finite() {
        return false;
    }
    let pulses = START_FULL_STEPS.saturating_mul(motor.microsteps) as usize + 1;
    let seconds = core::iter::repeat_n(1.0 / hz, pulses);
    meets(motor, seconds, End::Start).is_none()
}

/// Which end of a move the model's rotor plays.
#[derive(Clone, Copy, PartialEq)]
pub(super) enum End {
    /// From rest, until the rotor moves as fast as the field: it has pulled
    /// in. What it does next (ringing, resonance) is not the start's.
    Start,
    /// From rest, through the periods, then held for two of the rotor's
    /// natural periods: the rotor must come to rest within the field's stable
    /// region.
    Stop,
}

/// Plays `seconds` (one period per table step) to the model's rotor for one
/// [`End`] of a move, under the pull-out torque over the safety factor;
/// `Some(pulse)` when the rotor slips (its lag passes 180° electrical)
/// before `pulse`, from 1 (one more than the pulses when it slips while
/// held). At most [`START_MAX_STEPS`] integration steps:
/// longer steps, while they are stable, for a slow pulse train; a train too
/// slow for the budget is not judged (each step is taken from rest, which
/// the torque check judges).
pub(super) fn meets<I: Iterator<Item = f64> + Clone>(
    motor: &Motor,
    seconds: I,
    end: End,
) -> Option<u32> {
    let hold = if end == End::Stop {
        2.0 * natural_period(motor)
    } else {
        0.0
    };
    let (shortest, total) = seconds
        .clone()
        .fold((f64::INFINITY, hold), |(s, t), d| (s.min(d), t + d));
    if !(shortest > 0.0 && total.is_finite()) {
        return None;
    }
    let dt = step_for(motor, shortest).max(total / START_MAX_STEPS as f64);
    if dt > stable_step(motor) || dt.is_nan() {
        return None;
    }
    let step = motor.step_radians();
    let mut rotor = Rotor::at_rest(motor);
    let mut caught_up = false;
    let mut count = 0u32;
    for (k, duration) in seconds.enumerate() {
        let n = substeps(duration, dt);
        let h = duration / n;
        let field = step / duration;
        let peak = motor.available_of_valid(1.0 / duration);
        rotor.advance(
            (k as f64 * step, field),
            peak,
            n as u64,
            h,
            |_, _, omega| {
                caught_up |= omega >= field;
            },
        );
        if rotor.slips > 0 || !rotor.theta.is_finite() {
            return Some(k as u32 + 1);
        }
        if end == End::Start && caught_up {
            return None;
        }
        count = k as u32 + 1;
        rotor.pulses = count;
    }
    if end == End::Stop {
        let n = substeps(hold, dt);
        let holding = motor.available_of_valid(0.0);
        rotor.advance(
            (count as f64 * step, 0.0),
            holding,
            n as u64,
            hold / n,
            |_, _, _| {},
        );
        if rotor.slips > 0 || !rotor.theta.is_finite() {
            return Some(count + 1);
        }
    }
    None
}

/// The advice of a refusal at an end of a move: only what the model found
/// to help ([`Remedies`]), or that neither helps.
fn advise(remedies: Remedies, f: &mut fmt::Formatter<'_>) -> fmt::Result {
    let slower = "start slower and accelerate less: at half the rate throughout (half the start \
                  frequency, a quarter of the acceleration) the model's rotor makes it";
    match (remedies.damping, remedies.slower) {
        (Some(true), true) => write!(
            f,
            " (with `damping_ratio = {REMEDY_DAMPING_RATIO}` the model's rotor makes it: give \
             the motor's own damping, as a rotor without rings; or {slower})"
        ),
        (Some(true), false) => write!(
            f,
            " (with `damping_ratio = {REMEDY_DAMPING_RATIO}` the model's rotor makes it: give \
             the motor's own damping, as a rotor without rings; at half the rate it slips too, \
             so starting slower does not help)"
        ),
        (_, true) => write!(f, " ({slower})"),
        (Some(false), false) => write!(
            f,
            " (neither half the rate nor `damping_ratio = {REMEDY_DAMPING_RATIO}` helps the \
             model's rotor here)"
        ),
        (None, false) => f.write_str(
            " (at half the rate throughout it slips too: starting slower does not help here)",
        ),
    }
}

/// [`MotorError::PullIn`]'s message.
pub(super) fn pull_in(
    f: &mut fmt::Formatter<'_>,
    pulse: u32,
    hz: f64,
    remedies: Remedies,
) -> fmt::Result {
    write!(
        f,
        "the motor cannot start on this ramp with its load: from rest at {hz} Hz the \
         model's rotor slips before pulse {pulse}, before it reaches the field's speed",
        hz = Fixed(hz, 1)
    )?;
    advise(remedies, f)
}

/// [`MotorError::ShortMove`]'s message.
pub(super) fn short_move(
    f: &mut fmt::Formatter<'_>,
    hz: f64,
    (pulse, steps): (u32, u32),
    remedies: Remedies,
) -> fmt::Result {
    write!(
        f,
        "the motor cannot make the shortest move on this ramp, from rest up its first {} \
         steps and down again: ",
        steps / 2
    )?;
    if pulse <= steps {
        write!(f, "the model's rotor slips before pulse {pulse} of {steps}")?;
    } else {
        write!(
            f,
            "when the field stops at {hz} Hz the model's rotor runs past it by half \
             an electrical turn",
            hz = Fixed(hz, 1)
        )?;
    }
    advise(remedies, f)
}

/// [`MotorError::Start`]'s message.
pub(super) fn start(f: &mut fmt::Formatter<'_>, hz: f64, limit: StartLimit) -> fmt::Result {
    let hz = Fixed(hz, 1);
    write!(
        f,
        "the motor cannot start at {hz} Hz with its load: it starts at {} Hz at most, ",
        Fixed(limit.hz(), 1)
    )?;
    match limit {
        StartLimit::Corrected {
            max_start_hz,
            factor,
            ..
        } => write!(
            f,
            "`max_start_hz = {}` (without load) over \
             sqrt(1 + load_inertia / rotor_inertia) = {}",
            Num(max_start_hz),
            Fixed(factor, 3)
        ),
        StartLimit::Model { .. } => write!(
            f,
            "the fastest rate found (by bisection below {hz} Hz) that the model's \
             rotor pulls in to from rest: it reaches the field's speed before lagging \
             180° electrical (torque over the safety factor; give `max_start_hz` \
             from the datasheet to use it instead)"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::string::{String, ToString};

    /// Every combination of what the model found says only that.
    #[test]
    fn each_refusal_advises_what_was_found() {
        let message = |damping, slower| {
            MotorError::PullIn {
                pulse: 3,
                hz: 200.0,
                remedies: Remedies { damping, slower },
            }
            .to_string()
        };
        let head = "the motor cannot start on this ramp with its load: from rest at 200.0 Hz \
                    the model's rotor slips before pulse 3, before it reaches the field's speed";
        let slower = "start slower and accelerate less: at half the rate throughout (half the \
                      start frequency, a quarter of the acceleration) the model's rotor makes it";
        let cases: [(Option<bool>, bool, String); 6] = [
            (
                Some(true),
                true,
                std::format!(
                    " (with `damping_ratio = 0.1` the model's rotor makes it: give the motor's \
                     own damping, as a rotor without rings; or {slower})"
                ),
            ),
            (
                Some(true),
                false,
                " (with `damping_ratio = 0.1` the model's rotor makes it: give the motor's own \
                 damping, as a rotor without rings; at half the rate it slips too, so starting \
                 slower does not help)"
                    .into(),
            ),
            (Some(false), true, std::format!(" ({slower})")),
            (None, true, std::format!(" ({slower})")),
            (
                Some(false),
                false,
                " (neither half the rate nor `damping_ratio = 0.1` helps the model's rotor here)"
                    .into(),
            ),
            (
                None,
                false,
                " (at half the rate throughout it slips too: starting slower does not help here)"
                    .into(),
            ),
        ];
        for (damping, slower_helps, advice) in cases {
            assert_eq!(
                message(damping, slower_helps),
                std::format!("{head}{advice}")
            );
        }
    }
}
