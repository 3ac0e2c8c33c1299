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
//! Figures as datasheets give them:
//!
//! - `rated_current` is the phase current a driver is set to, regulated as
//!   an RMS value by a microstepping driver: the sine's amplitude is
//!   `I = sqrt(2) · rated_current`, the current each phase carries with
//!   two phases on at rated current in full steps.
//! - `holding_torque` is measured at rated current with two phases on, the
//!   amplitude of the static torque-angle curve: `K_m = holding_torque / I`.
//! - The chopper's H-bridge puts `±supply_voltage` on a phase and switches
//!   at once: its ripple, its decay mode, the drops in its transistors and
//!   the supply's own resistance are not modelled.
//! - Back-EMF constant and torque constant are the same `K_m` in SI units,
//!   as the model's energy balance requires (`e · i = T · ω`).
//!
//! Not modelled: iron losses, saturation, mid-band resonance.

use core::f64::consts::SQRT_2;

use crate::base::key::Key;
use crate::motor::chopper::Phase;
use crate::motor::stepped::{FULL_STEPS, HALF_STEPS, SteppedPhase};
use crate::motor::{Motor, MotorError, bounds};

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
    /// Rated phase current, in A: RMS, as a microstepping driver is set,
    /// for [`Drive::Sine`]; the current each phase is switched to, for the
    /// stepped drives.
    pub rated_current: f64,
    /// Holding torque at rated current, two phases on, in N·m.
    pub holding_torque: f64,
    /// The driver's supply voltage, in V.
    pub supply_voltage: f64,
    /// Detent torque (unpowered), in N·m; 0 when not known.
    pub detent_torque: f64,
    /// The current's waveform the driver sets.
    pub drive: Drive,
}

impl Windings {
    /// Windings of `resistance` Ω and `inductance` H per phase, the driver
    /// set to `rated_current` A (RMS for the sine drive), giving
    /// `holding_torque` N·m at rated current with two phases on, fed from
    /// `supply_voltage` V: no detent torque (0, not known) and a sine drive
    /// ([`Drive::Sine`]).
    ///
    /// ```
    /// use profile_core::motor::{Drive, Windings};
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

    /// The phase current's amplitude the driver sets, `sqrt(2) ·
    /// rated_current`, in A.
    pub fn amplitude(&self) -> f64 {
        SQRT_2 * self.rated_current
    }

    /// The torque constant `K_m = holding_torque / amplitude`, in N·m/A
    /// (and V·s/rad: the back-EMF constant).
    pub fn torque_constant(&self) -> f64 {
        self.holding_torque / self.amplitude()
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
        let (r, volts) = (self.resistance, self.supply_voltage);
        let x = poles * omega.abs() * self.inductance;
        let e = km * omega.abs();
        let stepped = |steps| SteppedPhase {
            r,
            x,
            e,
            amp: self.rated_current,
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
        (km * q - self.detent_torque).max(0.0)
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
mod tests {
    use core::f64::consts::{FRAC_PI_4, PI};

    use super::*;

    fn nema17() -> Windings {
        Windings::new(0.7, 1.1e-3, 2.8, 0.40, 24.0)
    }

    #[test]
    fn at_rest_the_holding_torque_unless_the_supply_cannot_drive_the_current() {
        assert_eq!(nema17().pull_out(50.0, 0.0), 0.40);
        // 2 V over 0.7 Ω drives 2.86 A of the 3.96 A set: the current
        // follows the sine up to 2.86 A and is clipped there. The mean
        // torque is `K_m` times the clipped sine's fundamental, here summed
        // over a half turn.
        let weak = Windings {
            supply_voltage: 2.0,
            ..nema17()
        };
        let (amp, cap) = (SQRT_2 * 2.8, 2.0 / 0.7);
        let n = 100_000;
        let fundamental = (0..n)
            .map(|k| {
                let t = PI * (k as f64 + 0.5) / n as f64;
                (amp * t.sin()).min(cap) * t.sin()
            })
            .sum::<f64>()
            * 2.0
            / n as f64;
        let expected = 0.40 / amp * fundamental;
        let at_rest = weak.pull_out(50.0, 0.0);
        assert!(
            (at_rest - expected).abs() < 1e-9,
            "{at_rest} against {expected}"
        );
        // Slowly turning, the same.
        let slowly = weak.pull_out(50.0, 1e-4);
        assert!(
            (slowly - at_rest).abs() < 1e-5,
            "{slowly} against {at_rest}"
        );
        let detent = nema17().with_detent_torque(0.015);
        assert!((detent.pull_out(50.0, 0.0) - 0.385).abs() < 1e-15);
    }

    #[test]
    fn falls_with_speed_and_as_one_over_speed_at_the_top() {
        let w = nema17();
        let mut last = f64::INFINITY;
        for k in 0..400 {
            let t = w.pull_out(50.0, k as f64 * 2.0);
            assert!(t <= last, "rises at {k}");
            last = t;
        }
        // High up, `K_m (V - K_m R / (N_r L)) / (N_r L ω)`.
        let (km, nl) = (w.torque_constant(), 50.0 * w.inductance);
        let omega = 5000.0;
        let asymptote = km * (24.0 / FRAC_PI_4 - km * w.resistance / nl) / (nl * omega);
        let t = w.pull_out(50.0, omega);
        assert!(
            (t / asymptote - 1.0).abs() < 1e-3,
            "{t} against {asymptote}"
        );
    }

    #[test]
    fn a_short_circuit_current_above_the_set_one_brakes_at_speed() {
        // `K_m / (N_r L)` = 0.101 / 0.01 = 10.1 A, above the 3.96 A set:
        // once the back-EMF drives more than the chopper is set to, the
        // windings give nothing, and never more again.
        let w = Windings {
            resistance: 0.5,
            inductance: 0.2e-3,
            ..nema17()
        };
        assert!(w.torque_constant() / (50.0 * w.inductance) > w.amplitude());
        let mut last = f64::INFINITY;
        let mut zero_from = None;
        for k in 0..10_000 {
            let omega = k as f64 * 0.5;
            let t = w.pull_out(50.0, omega);
            assert!(t <= last, "rises to {t} at {omega} rad/s");
            if t == 0.0 && zero_from.is_none() {
                zero_from = Some(omega);
            }
            last = t;
        }
        let zero_from = zero_from.expect("falls to nothing");
        // 508 rad/s: 16 170 full steps/s.
        assert!((450.0..550.0).contains(&zero_from), "{zero_from}");
    }

    /// The largest supply taken, 1e5 V, and one beyond: finite limits, and
    /// a motor refused starts at no rate.
    #[test]
    fn a_supply_beyond_reason_gives_finite_limits() {
        let motor = Motor::new(1.8, 1, 5.4e-6)
            .with_windings(Windings {
                supply_voltage: 1e5,
                ..nema17()
            })
            .with_load_inertia(2.0e-5)
            .with_damping_ratio(0.1);
        let top = motor.top_hz();
        assert!(top.is_finite() && top > 1e5, "{top}");
        let mut beyond = motor;
        beyond.windings = Some(Windings {
            supply_voltage: 1e300,
            ..nema17()
        });
        assert!(beyond.top_hz().is_finite());
        assert_eq!(beyond.start_limit(1e6).hz(), 0.0);
        let start = motor.start_limit(top).hz();
        assert!(start > 100.0 && start < 1e6, "{start}");
        let unbounded = motor.start_limit(f64::INFINITY).hz();
        assert!(
            (unbounded / start - 1.0).abs() < 2e-3,
            "{unbounded} against {start}"
        );
    }

    /// Windings and motors `validate` refuses, and arguments the model has
    /// no answer for, give no torque and no top frequency: not a figure
    /// made of them (a resistance of -1 Ω gave 0.4 N·m up to 3.8 MHz).
    #[test]
    fn refused_figures_give_no_torque() {
        let bad = [-1e300, -1.0, 0.0, 1e-300, 1e300, f64::NAN, f64::INFINITY];
        for drive in [Drive::Sine, Drive::HalfStep, Drive::FullStep] {
            for field in 0..6 {
                for &value in &bad {
                    let mut w = nema17().with_drive(drive);
                    let slot = match field {
                        0 => &mut w.resistance,
                        1 => &mut w.inductance,
                        2 => &mut w.rated_current,
                        3 => &mut w.holding_torque,
                        4 => &mut w.supply_voltage,
                        _ => &mut w.detent_torque,
                    };
                    *slot = value;
                    if w.validate().is_ok() {
                        continue;
                    }
                    let motor = Motor::new(1.8, drive_steps(drive), 5.4e-6).with_windings(w);
                    let case = (drive, field, value);
                    assert_eq!(w.pull_out(50.0, 10.0), 0.0, "{case:?}");
                    assert_eq!(motor.pull_out(100.0), 0.0, "{case:?}");
                    assert_eq!(motor.available(100.0), 0.0, "{case:?}");
                    assert_eq!(motor.derived_pull_out(100.0), None, "{case:?}");
                    assert_eq!(motor.peak_torque(), 0.0, "{case:?}");
                    assert_eq!(motor.top_hz(), 0.0, "{case:?}");
                    assert_eq!(motor.stiffness(), 0.0, "{case:?}");
                }
            }
        }
        let good = nema17();
        for (poles, omega) in [
            (0.0, 10.0),
            (-50.0, 10.0),
            (f64::NAN, 10.0),
            (50.0, f64::NAN),
        ] {
            assert_eq!(good.pull_out(poles, omega), 0.0, "{poles} {omega}");
        }
        assert!(good.pull_out(50.0, 10.0) > 0.3);
        let motor = Motor::new(1.8, 8, 5.4e-6).with_windings(good);
        assert!(motor.pull_out(100.0) > 0.3);
        for hz in [f64::NAN, f64::INFINITY] {
            assert_eq!(motor.pull_out(hz), 0.0);
            assert_eq!(motor.derived_pull_out(hz), None);
        }
        let refused = Motor::new(f64::NAN, 8, 5.4e-6).with_windings(good);
        assert_eq!((refused.pull_out(100.0), refused.top_hz()), (0.0, 0.0));
        let curve = crate::motor::TorqueCurve::new(&[(0.0, 0.4), (1000.0, 0.3)]).unwrap();
        let refused = Motor::new(1.8, 0, 5.4e-6).with_torque_curve(curve);
        assert_eq!((refused.pull_out(100.0), refused.peak_torque()), (0.0, 0.0));
    }

    fn drive_steps(drive: Drive) -> u32 {
        match drive {
            Drive::Sine => 8,
            Drive::HalfStep => 2,
            Drive::FullStep => 1,
        }
    }
}
