//! The pull-out torque a motor's windings give behind a chopper driver,
//! derived from the datasheet's electrical figures when no measured curve is
//! at hand.
//!
//! The model is the standard two-phase hybrid stepper (Bodson, Chiasson,
//! Novotnak and Rekowski, "High-performance nonlinear feedback control of a
//! permanent magnet stepper motor", IEEE Trans. Control Systems Technology,
//! 1993), each phase a winding with back-EMF:
//!
//! ```text
//! L di_a/dt = v_a - R i_a + K_m ω sin(N_r θ)
//! L di_b/dt = v_b - R i_b - K_m ω cos(N_r θ)
//! T = K_m (i_b cos(N_r θ) - i_a sin(N_r θ)) - T_detent sin(4 N_r θ)
//! ```
//!
//! The driver is a chopper that regulates each phase current to a sine of
//! its set amplitude as long as the supply lets it, and puts the full
//! supply on the phase where it cannot. At a steady speed `ω` (mechanical
//! rad/s) each phase's steady state is solved exactly (see the `chopper`
//! module): held where the voltage the sine needs stays within the supply,
//! partly held where it rises above it for part of each turn (the current
//! falls behind under the full supply, then is caught again), a square wave
//! of the full supply where it is never caught. The rotor's lag behind the
//! field chooses the state; the pull-out torque is the largest mean torque
//! over the lag, less the detent torque (which, at its worst angle, opposes
//! the rotor). A driver that steps the current instead ([`Drive::HalfStep`],
//! [`Drive::FullStep`]) is solved the same way, stretch by stretch (the
//! `stepped` module).
//!
//! Figures as datasheets and driver manuals give them:
//!
//! - `rated_current` is the motor's rated phase current, the one its
//!   holding torque is measured at, two phases on: `K_m = holding_torque /
//!   (sqrt(2) · rated_current)`, the amplitude of the static torque-angle
//!   curve over the current's amplitude.
//! - `driver_current` is what the driver is set to (`rated_current` when
//!   not given), the sine's RMS or its peak as the driver's manual says
//!   (`driver_current_is`, RMS when not given): the sine's amplitude is
//!   `sqrt(2) · driver_current`, or `driver_current`. The stepped drives
//!   switch each phase to `driver_current`. A driver set below the rating
//!   gives proportionally less torque.
//! - Back-EMF constant and torque constant are the same `K_m` in SI units,
//!   as the model's energy balance requires (`e · i = T · ω`).
//!
//! Two losses make the ideal chopper's torque what published charts show at
//! speed; neither is on a datasheet, so each has a default taken from
//! published pull-out charts (the tests keep them, with their sources), and
//! a key to set it where a motor's own chart says better:
//!
//! - `supply_utilization`, the share of the supply the chopper puts across
//!   a winding (default 0.76): the bridge's and the sense resistor's drops,
//!   the dead time and the shortest off time of its PWM, the supply's own
//!   sag. The chopper's ripple and decay mode are not modelled otherwise.
//! - `iron_loss`, the drag of the iron's hysteresis and eddy currents at an
//!   electrical frequency of 1 kHz, in N·m (default 0.11 of the holding
//!   torque); it grows as the electrical frequency's 0.4th power, between
//!   hysteresis (a constant drag) and eddy currents (a drag in proportion
//!   to the frequency), and is taken off the torque.
//!
//! Not modelled: saturation, mid-band resonance.

use core::f64::consts::SQRT_2;

use crate::motor::chopper::Phase;
use crate::motor::stepped::{FULL_STEPS, HALF_STEPS, SteppedPhase};
use crate::motor::{Motor, MotorError, bounds};
use profile_core::Key;

/// How the driver sets the phase currents: the waveform its chopper
/// regulates each phase to, at `rated_current`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum Drive {
    /// A sine (any microstepping driver, at any microstep setting): the
    /// amplitude is `sqrt(2) · rated_current`, `rated_current` the RMS value
    /// the driver is set to.
    #[default]
    Sine,
    /// Half steps without current compensation (an L297, or a driver
    /// stepping its phases on and off): in turn one phase, then both, each
    /// at `rated_current`. Its fundamental is `(4/π) cos(π/8) = 0.83` of the
    /// sine's, and so is the torque at low speed.
    HalfStep,
    /// Full steps with both phases on at `rated_current`: a square wave on
    /// each phase, whose fundamental is `(4/π)/sqrt(2) = 0.90` of the
    /// sine's.
    FullStep,
}

impl Drive {
    /// Every drive, with its name as written in a profile.
    pub const ALL: [(&'static str, Drive); 3] = [
        ("sine", Drive::Sine),
        ("half_step", Drive::HalfStep),
        ("full_step", Drive::FullStep),
    ];

    /// The name as written in a profile (`sine`, `half_step`, `full_step`).
    pub fn name(self) -> &'static str {
        match self {
            Drive::Sine => "sine",
            Drive::HalfStep => "half_step",
            Drive::FullStep => "full_step",
        }
    }
}

/// How a driver's current setting is meant: its manual's table gives the
/// sine's RMS and peak values for each setting.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum CurrentSetting {
    /// The sine's RMS value: its amplitude is `sqrt(2)` times the setting.
    #[default]
    Rms,
    /// The sine's amplitude.
    Peak,
}

impl CurrentSetting {
    /// Both, with their names as written in a profile.
    pub const ALL: [(&'static str, CurrentSetting); 2] =
        [("rms", CurrentSetting::Rms), ("peak", CurrentSetting::Peak)];

    /// The name as written in a profile (`rms`, `peak`).
    pub fn name(self) -> &'static str {
        match self {
            CurrentSetting::Rms => "rms",
            CurrentSetting::Peak => "peak",
        }
    }
}

/// The share of the supply a chopper puts across a winding when a
/// driver's is not known ([`Windings::supply_utilization`]).
const SUPPLY_UTILIZATION: f64 = 0.76;

/// The iron's drag at an electrical frequency of 1 kHz, as a share of the
/// holding torque, when a motor's is not known ([`Windings::iron_loss`]).
const IRON_LOSS_SHARE: f64 = 0.11;

/// The power of the electrical frequency the iron's drag grows with.
const IRON_LOSS_POWER: f64 = 0.4;

/// A two-phase hybrid motor's windings and the chopper driver behind them,
/// as a datasheet gives them: per phase, with the driver set to the rated
/// current and fed from `supply_voltage`.
///
/// Build them with [`Windings::new`] and the `with_*` methods (`const`);
/// the fields stay public to read and assign. They are
/// `#[non_exhaustive]`: they may gain fields, each with a default that
/// leaves the model as it was.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Windings {
    /// Phase resistance, in Ω.
    pub resistance: f64,
    /// Phase inductance, in H.
    pub inductance: f64,
    /// The motor's rated phase current, in A: the current its holding
    /// torque is measured at, and the driver's setting unless
    /// [`Windings::driver_current`] says otherwise.
    pub rated_current: f64,
    /// Holding torque at rated current, two phases on, in N·m.
    pub holding_torque: f64,
    /// The driver's supply voltage, in V.
    pub supply_voltage: f64,
    /// Detent torque (unpowered), in N·m; 0 when not known.
    pub detent_torque: f64,
    /// The current's waveform the driver sets.
    pub drive: Drive,
    /// The driver's current setting, in A: the sine's RMS or peak value
    /// ([`Windings::driver_current_is`]) for [`Drive::Sine`], the current
    /// each phase is switched to for the stepped drives. `None`: the
    /// motor's `rated_current`.
    pub driver_current: Option<f64>,
    /// Whether [`Windings::driver_current`] is the sine's RMS or peak
    /// value, as the driver's manual gives it (RMS by default; the stepped
    /// drives take the setting as the level they switch to).
    pub driver_current_is: CurrentSetting,
    /// The share of the supply the chopper puts across a winding, above 0
    /// and at most 1: 0.76 unless a driver is known better (the bridge's
    /// drops, its PWM's dead and off times).
    pub supply_utilization: f64,
    /// The iron's drag at an electrical frequency of 1 kHz, in N·m,
    /// growing as the frequency's 0.4th power. `None`: 0.11 of the
    /// holding torque, as the budget motors whose published charts the
    /// model was checked against have it (a motor of better iron loses
    /// less: its own chart tells).
    pub iron_loss: Option<f64>,
}

impl Windings {
    /// Windings of `resistance` Ω and `inductance` H per phase, the driver
    /// set to `rated_current` A (RMS for the sine drive), giving
    /// `holding_torque` N·m at rated current with two phases on, fed from
    /// `supply_voltage` V: no detent torque (0, not known) and a sine drive
    /// ([`Drive::Sine`]).
    ///
    /// ```
    /// use profile_codegen::motor::{Drive, Windings};
    ///
    /// const HALF: Windings = Windings::new(0.5, 0.6e-3, 2.8, 0.40, 24.0)
    ///     .with_detent_torque(0.015)
    ///     .with_drive(Drive::HalfStep);
    ///
    /// assert_eq!(HALF.validate(), Ok(()));
    /// assert_eq!(Windings::new(0.5, 0.6e-3, 2.8, 0.40, 24.0).drive, Drive::Sine);
    /// ```
    #[must_use]
    pub const fn new(
        resistance: f64,
        inductance: f64,
        rated_current: f64,
        holding_torque: f64,
        supply_voltage: f64,
    ) -> Self {
        Windings {
            resistance,
            inductance,
            rated_current,
            holding_torque,
            supply_voltage,
            detent_torque: 0.0,
            drive: Drive::Sine,
            driver_current: None,
            driver_current_is: CurrentSetting::Rms,
            supply_utilization: SUPPLY_UTILIZATION,
            iron_loss: None,
        }
    }

    /// The same windings with a detent torque (unpowered), in N·m: 0 or
    /// more and below the holding torque.
    #[must_use]
    pub const fn with_detent_torque(mut self, detent_torque: f64) -> Self {
        self.detent_torque = detent_torque;
        self
    }

    /// The same windings behind a driver setting another current waveform.
    #[must_use]
    pub const fn with_drive(mut self, drive: Drive) -> Self {
        self.drive = drive;
        self
    }

    /// The same windings behind a driver set to `amps`, the sine's RMS or
    /// peak value as `is` says (the level each phase is switched to, for
    /// the stepped drives).
    ///
    /// ```
    /// use profile_codegen::motor::{CurrentSetting, Windings};
    ///
    /// // A 4.2 A motor behind a driver set to 4.2 A peak: 3.0 A RMS.
    /// let w = Windings::new(0.65, 3.2e-3, 4.0, 2.4, 36.0)
    ///     .with_driver_current(4.2, CurrentSetting::Peak);
    /// assert!((w.amplitude() - 4.2).abs() < 1e-12);
    /// ```
    #[must_use]
    pub const fn with_driver_current(mut self, amps: f64, is: CurrentSetting) -> Self {
        self.driver_current = Some(amps);
        self.driver_current_is = is;
        self
    }

    /// The same windings behind a chopper that puts `share` of its supply
    /// across a winding (above 0, at most 1).
    #[must_use]
    pub const fn with_supply_utilization(mut self, share: f64) -> Self {
        self.supply_utilization = share;
        self
    }

    /// The same windings with the iron's drag at an electrical frequency
    /// of 1 kHz, in N·m (0 or more).
    #[must_use]
    pub const fn with_iron_loss(mut self, nm: f64) -> Self {
        self.iron_loss = Some(nm);
        self
    }

    /// Checks every figure: each within the range of every motor and
    /// driver, and far beyond (`resistance` from 1e-4 to 1e5 Ω,
    /// `inductance` from 1e-8 to 100 H, `rated_current` from 1e-4 to 1000
    /// A, `holding_torque` from 1e-6 to 10 000 N·m, `supply_voltage` from
    /// 0.1 to 1e5 V), the detent torque 0 or more and below the holding
    /// torque.
    pub fn validate(&self) -> Result<(), MotorError> {
        bounds::check(&bounds::WINDINGS, self)?;
        if !(self.detent_torque >= 0.0 && self.detent_torque < self.holding_torque) {
            return Err(MotorError::Invalid {
                key: Key::DETENT_TORQUE,
                value: self.detent_torque,
                expected: "0 or more and below `holding_torque`",
            });
        }
        Ok(())
    }

    /// The driver's current setting, in A: [`Windings::driver_current`],
    /// or the motor's rated current.
    pub fn setting(&self) -> f64 {
        self.driver_current.unwrap_or(self.rated_current)
    }

    /// The sine's amplitude the driver sets, in A: `sqrt(2)` times an RMS
    /// setting, or the peak setting.
    pub fn amplitude(&self) -> f64 {
        match self.driver_current_is {
            CurrentSetting::Rms => SQRT_2 * self.setting(),
            CurrentSetting::Peak => self.setting(),
        }
    }

    /// The torque constant `K_m = holding_torque / (sqrt(2) ·
    /// rated_current)`, in N·m/A (and V·s/rad: the back-EMF constant).
    pub fn torque_constant(&self) -> f64 {
        self.holding_torque / (SQRT_2 * self.rated_current)
    }

    /// The iron's drag at an electrical frequency of 1 kHz, in N·m:
    /// [`Windings::iron_loss`], or its default share of the holding
    /// torque.
    pub fn iron_loss_at_1khz(&self) -> f64 {
        self.iron_loss
            .unwrap_or(IRON_LOSS_SHARE * self.holding_torque)
    }

    /// The iron's drag at an electrical frequency of `hz`, in N·m.
    pub fn iron_drag(&self, hz: f64) -> f64 {
        self.iron_loss_at_1khz() * libm::pow(libm::fabs(hz) / 1000.0, IRON_LOSS_POWER)
    }

    /// The pull-out torque at a steady mechanical speed `omega` (rad/s) of
    /// a rotor with `poles` electrical radians per mechanical radian
    /// ([`Motor::poles`](crate::motor::Motor::poles)), in N·m: 0 where the
    /// windings give no more than the detent torque, and 0 for windings
    /// [`Windings::validate`] refuses, `poles` not finite and above 0, or
    /// `omega` not finite (the model holds no answer for them).
    pub fn pull_out(&self, poles: f64, omega: f64) -> f64 {
        let fair = poles.is_finite() && poles > 0.0 && omega.is_finite();
        if !fair || self.validate().is_err() {
            return 0.0;
        }
        self.pull_out_of_valid(poles, omega)
    }

    /// [`Windings::pull_out`] for windings and arguments already checked.
    pub(crate) fn pull_out_of_valid(&self, poles: f64, omega: f64) -> f64 {
        let km = self.torque_constant();
        let r = self.resistance;
        let volts = self.supply_voltage * self.supply_utilization;
        let electrical = poles * omega.abs();
        let x = electrical * self.inductance;
        let e = km * omega.abs();
        let stepped = |steps| SteppedPhase {
            r,
            x,
            e,
            amp: self.setting(),
            volts,
            steps,
        };
        let q = match self.drive {
            Drive::Sine => Phase {
                r,
                x,
                e,
                amp: self.amplitude(),
                volts,
            }
            .largest_q(),
            Drive::HalfStep => stepped(HALF_STEPS).largest_q(),
            Drive::FullStep => stepped(FULL_STEPS).largest_q(),
        };
        let drag = self.iron_drag(electrical / core::f64::consts::TAU);
        (km * q - self.detent_torque - drag).max(0.0)
    }
}

/// The motor's pull-out torque, from its curve or its windings.
impl Motor {
    /// The pull-out torque at step frequency `hz` (table steps per second),
    /// in N·m: `torque_curve` when given, else the one `windings` give at
    /// that speed, else 0. 0 for a motor [`Motor::validate`] refuses, and
    /// for `hz` not finite.
    pub fn pull_out(&self, hz: f64) -> f64 {
        if !hz.is_finite() || self.validate().is_err() {
            return 0.0;
        }
        self.pull_out_of_valid(hz)
    }

    /// [`Motor::pull_out`] for a motor already validated and a finite `hz`.
    pub(crate) fn pull_out_of_valid(&self, hz: f64) -> f64 {
        match (&self.torque_curve, &self.windings) {
            (Some(curve), _) => curve.torque(hz),
            (None, Some(w)) => self.derived(w, hz),
            (None, None) => 0.0,
        }
    }

    /// The pull-out torque `windings` give at step frequency `hz`, in N·m,
    /// whether or not a measured curve is given: to compare the two.
    /// `None` without windings, for a motor [`Motor::validate`] refuses,
    /// and for `hz` not finite.
    pub fn derived_pull_out(&self, hz: f64) -> Option<f64> {
        if !hz.is_finite() || self.validate().is_err() {
            return None;
        }
        self.windings.as_ref().map(|w| self.derived(w, hz))
    }

    fn derived(&self, windings: &Windings, hz: f64) -> f64 {
        windings.pull_out_of_valid(self.poles(), hz * self.step_radians())
    }

    /// The largest pull-out torque, in N·m: the curve's largest point, or
    /// the windings' torque at rest (it falls with speed). 0 for a motor
    /// [`Motor::validate`] refuses.
    pub fn peak_torque(&self) -> f64 {
        match &self.torque_curve {
            Some(_) if self.validate().is_err() => 0.0,
            Some(curve) => curve.points().iter().fold(0.0f64, |m, &(_, nm)| m.max(nm)),
            None => self.pull_out(0.0),
        }
    }

    /// The highest step frequency the motor is characterised at, in Hz:
    /// the torque curve's last point, or where the windings' torque has
    /// fallen to a hundredth of the torque at rest (or to nothing, with
    /// detent torque). Beyond it a search for the motor's limits need not
    /// look. 0 for a motor [`Motor::validate`] refuses.
    pub fn top_hz(&self) -> f64 {
        if self.validate().is_err() {
            return 0.0;
        }
        match (&self.torque_curve, &self.windings) {
            (Some(curve), _) => curve.top(),
            (None, Some(_)) => {
                let floor = self.pull_out_of_valid(0.0) / 100.0;
                let low = |hz: f64| self.pull_out_of_valid(hz) <= floor;
                // Doubling, then halving, each with a bound: the torque
                // falls with speed, as `1/ω` at the top.
                // A torque that never falls (a supply beyond any the model
                // was made for) stops the doubling at the largest finite
                // power of two.
                let mut hi = 1.0;
                for _ in 0..1023 {
                    if low(hi) {
                        break;
                    }
                    hi *= 2.0;
                }
                let mut lo = if hi > 1.0 { 0.5 * hi } else { 0.0 };
                for _ in 0..64 {
                    let mid = 0.5 * (lo + hi);
                    if low(mid) {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                hi
            }
            (None, None) => 0.0,
        }
    }
}

#[cfg(test)]
#[path = "windings_tests.rs"]
mod tests;
