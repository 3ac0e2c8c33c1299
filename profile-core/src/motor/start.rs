//! The start from rest: the fastest step rate the loaded rotor pulls in to,
//! from a datasheet's no-load figure or from the model, and the motor's
//! stiffness and electromagnetic damping the model uses.

use core::f64::consts::{PI, TAU};

use crate::motor::Motor;
use crate::motor::simulate::{Rotor, stable_step, substeps};

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
    /// 180° electrical, within [`START_FULL_STEPS`] full steps), under the
    /// pull-out torque over the safety factor.
    Model {
        /// The limit, in Hz (to [`START_RESOLUTION`]).
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
pub const START_FULL_STEPS: u32 = 4;

/// The relative resolution of a start limit found from the model.
pub const START_RESOLUTION: f64 = 1e-3;

impl Motor {
    /// The torque-angle stiffness at rest, `K = N_r · T_hold` in N·m/rad:
    /// `N_r` electrical radians per mechanical radian (90° electrical per
    /// full step), `T_hold` the torque curve at 0 Hz.
    pub fn stiffness(&self) -> f64 {
        self.poles() * self.torque_curve.torque(0.0)
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
    /// `hz` (pulls in within [`START_FULL_STEPS`] full steps).
    pub fn starts_at(&self, hz: f64) -> bool {
        match self.max_start_hz {
            Some(_) => hz <= self.start_limit(hz).hz(),
            None => pulls_in(self, hz),
        }
    }

    /// The fastest start from rest with the load: `max_start_hz` corrected
    /// for the load when it is given; otherwise the fastest constant rate,
    /// searched by bisection below `below` Hz (to [`START_RESOLUTION`]), at
    /// which the model's rotor pulls in from rest.
    pub fn start_limit(&self, below: f64) -> StartLimit {
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
}

/// The most integration steps of one start judged from the model
/// ([`Motor::starts_at`]).
pub const START_MAX_STEPS: u64 = 200_000;

/// Whether the rotor, at rest and aligned, pulls in to a field stepping at a
/// constant `hz` table steps per second: reaches the field's speed without
/// slipping, within [`START_FULL_STEPS`]
/// full steps, under the pull-out torque at `hz` over the safety factor. The
/// integration step is the one
/// [`SimOptions::suggested`](crate::simulate::SimOptions::suggested) takes
/// for that pulse train.
pub(super) fn pulls_in(motor: &Motor, hz: f64) -> bool {
    if hz <= 0.0 {
        return true;
    }
    if !hz.is_finite() {
        return false;
    }
    let poles = motor.poles();
    let inertia = motor.rotor_inertia + motor.load_inertia;
    let period = 1.0 / hz;
    let natural = TAU / libm::sqrt(motor.stiffness() / inertia);
    let natural = if natural.is_finite() && natural > 0.0 {
        natural
    } else {
        1e-3
    };
    let pulses = START_FULL_STEPS.saturating_mul(motor.microsteps);
    let stable = stable_step(motor, poles, inertia);
    let dt = (period / 50.0).min(natural / 200.0).min(stable / 4.0);
    // At most START_MAX_STEPS integration steps: longer steps, as long as
    // they stay stable, for a slow pulse train.
    let budget = period * (pulses as f64 + 1.0) / START_MAX_STEPS as f64;
    let dt = dt.max(budget);
    if dt > stable || dt.is_nan() {
        // Pulses so far apart that the rotor's own motion between them
        // cannot be integrated within the budget: each step is taken from
        // rest, which the torque check judges.
        return true;
    }
    let n = substeps(period, dt);
    if !(n.is_finite() && n >= 1.0) {
        return false;
    }
    let h = period / n;
    let step = motor.step_radians();
    let peak = motor.available(hz);
    let mut rotor = Rotor {
        theta: 0.0,
        omega: 0.0,
        poles,
        inertia,
        friction: motor.friction,
        damping: motor.damping,
        field_damping: motor.field_damping(),
        well: 0,
        slips: 0,
        first_slip: None,
        pulses: 0,
        steps: 0,
    };
    // As `run` plays a table of `pulses` equal periods, and one period more
    // after the last pulse.
    let field = step * hz;
    // The first time the rotor moves as fast as the field, before its lag
    // passes half an electrical turn (a slip), it has pulled in. What it does
    // next (ringing, resonance) is not the start's.
    let mut verdict = None;
    for k in 0..=pulses {
        rotor.advance(
            (k as f64 * step, field),
            peak,
            n as u64,
            h,
            |lag, _, omega| {
                if verdict.is_none() {
                    if libm::fabs(lag) > PI || lag.is_nan() {
                        verdict = Some(false);
                    } else if omega >= field {
                        verdict = Some(true);
                    }
                }
            },
        );
        if let Some(pulled_in) = verdict {
            return pulled_in;
        }
    }
    // Never as fast as the field within the start, never slipped: a field
    // too slow to judge (friction holds the rotor) passes to the torque check.
    true
}
