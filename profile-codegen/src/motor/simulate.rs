//! Whether the rotor really follows a table: its dynamics integrated under
//! the table's exact pulse train, and the steps it loses.
//!
//! [`Motor::check`] compares torques step by step; this module plays the
//! pulses to a model of the rotor and watches it. The model is the one of
//! "Design and implementation of speed increase/decrease in stepper motor
//! control",
//! `J θ'' + β θ' + k θ = T_d - T_z` with the two-phase hybrid stepper's
//! sinusoidal torque for `k θ` and `T_d`:
//!
//! ```text
//! J θ'' = T_peak(f) · sin(lag_e) - friction · sign(θ') - damping · θ'
//!         + D · (ω_cmd - θ')
//! lag_e = (θ_cmd - θ) · (π/2) / θ_fullstep
//! ```
//!
//! - `J` is the rotor and load inertia; `friction` a Coulomb torque that
//!   opposes motion and holds the rotor still while the drive torque is
//!   smaller (stiction); `damping` the viscous coefficient `β`; `D` the
//!   electromagnetic damping on the rotor's speed relative to the field's
//!   `ω_cmd` ([`Motor::field_damping`], from
//!   [`Motor::damping_ratio`](crate::motor::Motor::damping_ratio)).
//! - `lag_e` is the electrical lag of the rotor behind the commanded angle: a
//!   full step is 90° electrical (a 1.8° motor has 50 rotor teeth), the
//!   torque is largest at a lag of one full step and changes sign beyond two,
//!   where the rotor falls into the next stable position, four full steps
//!   away. That is a slip: four full steps (`4 · microsteps` table steps) lost.
//! - `T_peak(f)` is the motor's pull-out torque at the commanded step
//!   frequency `f`, [`Motor::pull_out`]: the measured `torque_curve` when
//!   given ([`TorqueCurve::torque`](crate::motor::TorqueCurve::torque)),
//!   else the torque the windings give behind the chopper at the steady
//!   speed `f` ([`Windings`](crate::motor::Windings): the driver's current
//!   regulation in its steady state at that speed, the current falling
//!   behind under the full supply). This is a modelling choice: at 0 Hz
//!   `T_peak` is about the holding torque, the amplitude of the static
//!   torque-angle curve; at speed the winding current no longer reaches its
//!   set value (inductance, back EMF) and the torque the motor can develop
//!   falls as the curve says, so it scales the whole sine. With this choice
//!   the largest torque the model gives at a steady `f` is the pull-out
//!   torque there, as measured. Beyond the curve's last point the motor is
//!   not characterised and gives no torque, as in the check. The safety
//!   factor is not applied: the simulation predicts what the motor does, the
//!   check keeps a margin.
//! - `ω_cmd` is the field's commanded speed, one table step
//!   ([`Motor::step_radians`]) per period: `step_radians / period_k` rad/s
//!   while entry `k` elapses (`period_k` in seconds), 0 while the motor holds.
//! - `θ_cmd` advances by one table step ([`Motor::step_radians`]) at each
//!   pulse edge. The timer starts at `t = 0` and entry `k` elapses before
//!   pulse `k + 1`, as a step interrupt plays a table: pulse `k` (from 1) is
//!   at `t_k = (periods[0] + ... + periods[k-1]) / (timer_hz / ticks_per_step)`.
//!   While entry `k` elapses the commanded frequency is `1 / period_k`; after
//!   the last pulse it is 0 (the motor holds, `T_peak(0)`) and `θ_cmd` stays
//!   fixed for [`SimOptions::settle_s`].
//!
//! The integrator is semi-implicit (symplectic) Euler, the damping terms
//! taken on the new speed (implicit, so no damping makes it unstable), with
//! a fixed step of at most [`SimOptions::dt_s`], shortened so that every pulse edge falls on a
//! step boundary (no edge is moved by the grid), with friction applied as an
//! impulse that can stop the rotor but never reverse it within a step. Halve
//! `dt_s` to check that it is small enough: the results should not change.
//!
//! Not modelled: the phase currents' transients (the torque's amplitude is
//! the steady state's at the commanded rate, reached at once when the rate
//! changes: no electrical time constant within a step), the detent torque as
//! a torque on the rotor (the windings' pull-out torque is reduced by it, the
//! equation above has no term for it), mid-band resonance.
//!
//! ```
//! use profile_codegen::motor::{Motor, TorqueCurve};
//! use profile_codegen::simulate::{self, SimOptions};
//! use profile_core::{Curve, Linear, LinearExtent, Spec, Timer};
//!
//! let curve = TorqueCurve::new(&[(0.0, 0.40), (1000.0, 0.33), (2000.0, 0.24)])
//!     .expect("from 1 to 32 points");
//! let motor = Motor::new(1.8, 1, 5.4e-6)
//!     .with_torque_curve(curve)
//!     .with_load_inertia(2.0e-5)
//!     .with_friction(0.02)
//!     .with_damping(1e-4)
//!     .with_safety(1.5);
//! let spec = Spec::new(
//!     Curve::Linear(Linear { fmin: 300.0, fmax: 1000.0, extent: LinearExtent::Len(200) }),
//!     Timer::new(1_000_000),
//! );
//! let mut table = [0u16; 200];
//! spec.generate(&mut table)?;
//! let periods = table.map(u32::from);
//! let options = SimOptions { dt_s: 2e-6, settle_s: 0.05 };
//! let result = simulate::run(&motor, &spec, &periods, &options).expect("valid input");
//! // The rotor follows the ramp, then stops from 1000 full steps/s at once:
//! // it swings past its final position but falls back into it.
//! assert_eq!((result.lost_steps, result.slips), (0, 0));
//! // Each full step moves the field 90° electrical; the rotor never lags
//! // the 180° at which it would slip.
//! assert!(result.max_lag_deg >= 90.0 && result.max_lag_deg < 180.0);
//! assert!(result.settled);
//! # Ok::<(), profile_core::Error>(())
//! ```

use core::f64::consts::{PI, TAU};
use core::fmt;

use crate::motor::{Motor, MotorError};
use crate::numbers::Num;
use profile_core::Spec;

/// The most integration steps one run may take. A run that would take more
/// is refused with [`SimError::TooManySteps`] before it starts (about a
/// second of computation).
pub const MAX_STEPS: u64 = 20_000_000;

/// How to integrate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimOptions {
    /// Largest integration step, in s. A small fraction of the shortest
    /// period and of the rotor's natural period (see [`SimOptions::suggested`]).
    pub dt_s: f64,
    /// Time to keep integrating after the last pulse, with `θ_cmd` fixed, in s.
    pub settle_s: f64,
}

impl SimOptions {
    /// A step of a fiftieth of the shortest period and a two-hundredth of the
    /// rotor's natural period at holding torque, whichever is shorter (and
    /// at most a quarter of the longest stable step), and a
    /// settle time of ten natural periods (at least 10 ms).
    ///
    /// The natural angular frequency is `sqrt(T_peak(0) · (π/2) / θ_fullstep / J)`:
    /// the rotor's small oscillations about a held position.
    pub fn suggested(motor: &Motor, spec: &Spec, periods: &[u32]) -> Self {
        let per_second = spec.timer.frequency_scale();
        let shortest = periods
            .iter()
            .filter(|&&p| p > 0)
            .min()
            .map_or(f64::INFINITY, |&p| p as f64 / per_second);
        SimOptions {
            dt_s: step_for(motor, shortest),
            settle_s: (10.0 * natural_period(motor)).max(0.01),
        }
    }
}

/// What the rotor did.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct SimResult {
    /// Table steps lost by the end, after settling: the rotor's final
    /// electrical lag rounded to whole electrical turns, each
    /// `4 · microsteps` table steps. Positive when the rotor ends behind the
    /// command, negative when it overshot into a later position.
    pub lost_steps: i64,
    /// Times the rotor fell into another stable position (its lag crossed
    /// ±180° electrical from the position it was in), either way.
    pub slips: u32,
    /// Pulses given when the rotor first slipped (`periods.len()` when it
    /// slipped only after the last pulse), if it did.
    pub first_slip_pulse: Option<u32>,
    /// Largest electrical lag `|lag_e|` while pulses were given, in degrees:
    /// below 90° the motor had torque to spare; above 180° it slipped.
    pub max_lag_deg: f64,
    /// The same lag in table steps (`90°` is one full step, `microsteps`
    /// table steps).
    pub max_lag_steps: f64,
    /// Pulses given when the largest lag occurred.
    pub max_lag_pulse: u32,
    /// Largest `θ - θ_cmd` after the last pulse, in table steps: how far the
    /// rotor swings past its final position (0 when it never reaches it).
    pub overshoot_steps: f64,
    /// `θ_cmd - θ` at the end, in table steps.
    pub final_error_steps: f64,
    /// Whether, at the end, the rotor no longer had the energy to leave the
    /// stable position it was in, so that `lost_steps` is final. A longer
    /// `settle_s` (or some damping or friction) settles it.
    pub settled: bool,
    /// Integration steps taken.
    pub steps: u64,
}

/// Why a simulation did not run.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum SimError {
    /// The motor's parameters are invalid.
    Motor(MotorError),
    /// The spec's timer has `timer_hz` or `ticks_per_step` 0.
    Timer,
    /// `dt_s` is not a finite number above 0, or `settle_s` not a finite
    /// number, 0 or more.
    Options {
        /// `dt_s`.
        dt_s: f64,
        /// `settle_s`.
        settle_s: f64,
    },
    /// The run would take more than [`MAX_STEPS`] integration steps.
    TooManySteps {
        /// Steps the run needs (at least this many; `u64::MAX` when it
        /// needs more).
        needed: u64,
        /// [`MAX_STEPS`].
        max: u64,
        /// The shortest integration step with which the run would fit, in s,
        /// if one within [`SimError::StepTooLong`]'s bound would.
        fits_with_dt_s: Option<f64>,
    },
    /// The integration step is too long for the rotor's stiffness or damping:
    /// the integrator would be unstable and the results meaningless.
    StepTooLong {
        /// The step asked for, in s.
        dt_s: f64,
        /// The longest step the model integrates stably, in s.
        max_dt_s: f64,
    },
    /// The rotor's state stopped being a finite number: the motor's figures
    /// are beyond what the model can integrate.
    Diverged {
        /// Pulses given when it happened.
        pulse: u32,
    },
}

impl fmt::Display for SimError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            SimError::Motor(e) => e.fmt(f),
            SimError::Timer => {
                f.write_str("the timer must have `timer_hz` and `ticks_per_step` above 0")
            }
            SimError::Options { dt_s, settle_s } => write!(
                f,
                "the integration step must be a finite number of seconds above 0 and the settle time one of 0 or more (got dt_s = {}, settle_s = {})",
                Num(dt_s),
                Num(settle_s)
            ),
            SimError::TooManySteps {
                needed,
                max,
                fits_with_dt_s,
            } => {
                match needed {
                    u64::MAX => f.write_str(
                        "the simulation needs more integration steps than 64 bits count",
                    )?,
                    _ => write!(f, "the simulation needs {needed} integration steps")?,
                }
                write!(f, ", more than the {max} allowed: ")?;
                match fits_with_dt_s {
                    Some(dt) => write!(f, "use a step of at least {dt:.3e} s"),
                    None => f.write_str(
                        "no stable step fits; simulate a shorter table or a shorter settle time",
                    ),
                }
            }
            SimError::StepTooLong { dt_s, max_dt_s } => write!(
                f,
                "the integration step of {dt_s:.3e} s is too long for this rotor: the model is \
                 integrated stably with steps of at most {max_dt_s:.3e} s"
            ),
            SimError::Diverged { pulse } => write!(
                f,
                "the rotor's motion stopped being a finite number after pulse {pulse}: the motor's \
                 torque, inertia or damping is beyond what the model can integrate"
            ),
        }
    }
}

impl std::error::Error for SimError {}

impl From<MotorError> for SimError {
    fn from(e: MotorError) -> Self {
        SimError::Motor(e)
    }
}

/// The rotor's natural period at holding torque, `2π / sqrt(K / J)` in s
/// ([`Motor::stiffness`]); 1 ms when that is not a finite number above 0.
pub(super) fn natural_period(motor: &Motor) -> f64 {
    let natural = TAU / libm::sqrt(motor.stiffness() / (motor.rotor_inertia + motor.load_inertia));
    if natural.is_finite() && natural > 0.0 {
        natural
    } else {
        1e-3
    }
}

/// The integration step for pulses of at least `shortest` s: a fiftieth of
/// that, a two-hundredth of the natural period, a quarter of the longest
/// stable step, whichever is shortest.
pub(super) fn step_for(motor: &Motor, shortest: f64) -> f64 {
    (shortest / 50.0)
        .min(natural_period(motor) / 200.0)
        .min(stable_step(motor) / 4.0)
}

/// The longest integration step the semi-implicit Euler integrator takes
/// stably, in s, with a factor of 2 to spare: `1/ω` where `ω` is the rotor's
/// natural angular frequency at the curve's largest torque (the method is
/// stable for `h ω < 2`). The viscous and the electromagnetic damping are
/// taken implicitly, stable at any step: no damping makes the model
/// unable to integrate.
pub(super) fn stable_step(motor: &Motor) -> f64 {
    let (poles, inertia) = (motor.poles(), motor.rotor_inertia + motor.load_inertia);
    let peak = motor.peak_torque();
    1.0 / libm::sqrt(peak * poles / inertia)
}

/// Integration steps for an interval of `duration` s, at most `dt` each.
pub(super) fn substeps(duration: f64, dt: f64) -> f64 {
    libm::ceil(duration / dt).max(0.0)
}

/// The rotor's state and what has been seen of it.
pub(super) struct Rotor {
    pub(super) theta: f64,
    pub(super) omega: f64,
    /// Electrical radians per mechanical radian: `(π/2) / θ_fullstep`.
    pub(super) poles: f64,
    pub(super) inertia: f64,
    pub(super) friction: f64,
    pub(super) damping: f64,
    /// Electromagnetic damping `D`, on the speed relative to the field's.
    pub(super) field_damping: f64,
    /// The stable position the rotor is in, in electrical turns behind the command.
    pub(super) well: i64,
    pub(super) slips: u32,
    pub(super) first_slip: Option<u32>,
    /// Pulses given so far.
    pub(super) pulses: u32,
    pub(super) steps: u64,
}

impl Rotor {
    /// `motor`'s rotor and load, at rest and aligned with the field.
    pub(super) fn at_rest(motor: &Motor) -> Self {
        Rotor {
            theta: 0.0,
            omega: 0.0,
            poles: motor.poles(),
            inertia: motor.rotor_inertia + motor.load_inertia,
            friction: motor.friction,
            damping: motor.damping,
            field_damping: motor.field_damping(),
            well: 0,
            slips: 0,
            first_slip: None,
            pulses: 0,
            steps: 0,
        }
    }

    /// Integrates `settle_s` with the command held at `cmd` and the holding
    /// torque; returns the largest swing past `cmd`, in radians.
    fn settle(&mut self, cmd: f64, holding: f64, settle_s: f64, dt_s: f64) -> f64 {
        let n = substeps(settle_s, dt_s);
        let h = if n > 0.0 { settle_s / n } else { 0.0 };
        let mut overshoot = 0.0f64;
        self.advance((cmd, 0.0), holding, n as u64, h, |_, theta, _| {
            overshoot = overshoot.max(theta - cmd);
        });
        overshoot
    }

    fn lag(&self, cmd: f64) -> f64 {
        self.poles * (cmd - self.theta)
    }

    /// `n` semi-implicit Euler steps of `h` s with `θ_cmd = cmd` and a torque
    /// amplitude `peak`; `each(lag_e, θ)` after every step.
    /// `n` integration steps of `h` s with the field at `cmd`, moving at
    /// `field_omega` rad/s (the commanded step rate; 0 while holding), under
    /// a torque amplitude `peak`.
    pub(super) fn advance(
        &mut self,
        (cmd, field_omega): (f64, f64),
        peak: f64,
        n: u64,
        h: f64,
        mut each: impl FnMut(f64, f64, f64),
    ) {
        let impulse = self.friction * h / self.inertia;
        // The damping on the new speed (implicit): `ω' = ω + h (T - β ω' +
        // D (ω_f - ω')) / J`, solved for `ω'`, is stable at any step.
        let drag = 1.0 + h * (self.damping + self.field_damping) / self.inertia;
        for _ in 0..n {
            let drive = peak * libm::sin(self.lag(cmd)) + self.field_damping * field_omega;
            let mut omega = (self.omega + h * drive / self.inertia) / drag;
            // Friction opposes the motion and may stop it, never reverse it.
            if omega > impulse {
                omega -= impulse;
            } else if omega < -impulse {
                omega += impulse;
            } else {
                omega = 0.0;
            }
            self.omega = omega;
            self.theta += h * omega;
            self.steps += 1;
            let lag = self.lag(cmd);
            // Into the next stable position when the lag passes ±180°
            // electrical from the current one.
            let rel = lag - TAU * self.well as f64;
            if !(-PI..=PI).contains(&rel) {
                let well = libm::round(lag / TAU) as i64;
                self.slips = self
                    .slips
                    .saturating_add(well.abs_diff(self.well).min(u32::MAX as u64) as u32);
                self.well = well;
                self.first_slip.get_or_insert(self.pulses);
            }
            each(lag, self.theta, self.omega);
        }
    }
}

/// Refuses a run of more than [`MAX_STEPS`] integration steps, saying which
/// step would fit if a stable one would.
fn fits(
    periods: &[u32],
    per_second: f64,
    options: &SimOptions,
    max_dt_s: f64,
) -> Result<(), SimError> {
    let SimOptions { dt_s, settle_s } = *options;
    let mut needed = substeps(settle_s, dt_s);
    let mut total_s = settle_s;
    for &p in periods {
        let duration = p as f64 / per_second;
        needed += substeps(duration, dt_s);
        total_s += duration;
    }
    if needed > MAX_STEPS as f64 {
        // Each interval takes at most one step more than its share of the
        // time: `total / dt + intervals` steps fit when dt is at least this.
        let intervals = periods.len() as f64 + 1.0;
        let room = MAX_STEPS as f64 - intervals;
        let fits = total_s / room;
        return Err(SimError::TooManySteps {
            needed: if needed < u64::MAX as f64 {
                needed as u64
            } else {
                u64::MAX
            },
            max: MAX_STEPS,
            fits_with_dt_s: (room > 0.0 && fits <= max_dt_s).then_some(fits),
        });
    }

    Ok(())
}

/// Plays `periods` (a table of `spec`, or any pulse train in its timer's
/// ticks) to `motor` and reports what the rotor did. See the module
/// documentation for the model.
///
/// Errors, never panics: an invalid motor, a timer at 0 Hz, a step that is
/// not a finite positive number or too long for the integrator to be stable,
/// a run of more than [`MAX_STEPS`] steps, or a rotor whose motion overflows.
pub fn run(
    motor: &Motor,
    spec: &Spec,
    periods: &[u32],
    options: &SimOptions,
) -> Result<SimResult, SimError> {
    motor.validate()?;
    if spec.timer.timer_hz == 0 || spec.timer.ticks_per_step == 0 {
        return Err(SimError::Timer);
    }
    let SimOptions { dt_s, settle_s } = *options;
    if !(dt_s.is_finite() && dt_s > 0.0 && settle_s.is_finite() && settle_s >= 0.0) {
        return Err(SimError::Options { dt_s, settle_s });
    }
    let per_second = spec.timer.frequency_scale();
    let poles = motor.poles();
    let max_dt_s = stable_step(motor);
    if dt_s > max_dt_s {
        return Err(SimError::StepTooLong { dt_s, max_dt_s });
    }
    // Count the steps first: refuse a run that is too long before it starts.
    fits(periods, per_second, options, max_dt_s)?;

    let step = motor.step_radians();
    // Electrical radians to table steps.
    let to_steps = 1.0 / (poles * step);
    let mut rotor = Rotor::at_rest(motor);
    let mut max_lag = 0.0f64;
    let mut max_lag_pulse = 0u32;
    for (k, &p) in periods.iter().enumerate() {
        let cmd = k as f64 * step;
        let duration = p as f64 / per_second;
        let n = substeps(duration, dt_s);
        let h = if n > 0.0 { duration / n } else { 0.0 };
        let peak = motor.pull_out_of_valid(per_second / p as f64);
        let field_omega = step * per_second / p as f64;
        rotor.advance((cmd, field_omega), peak, n as u64, h, |lag, _, _| {
            if lag.abs() > max_lag {
                max_lag = lag.abs();
                max_lag_pulse = k as u32;
            }
        });
        // The pulse at the end of entry k: one more table step commanded.
        rotor.pulses = rotor.pulses.saturating_add(1);
        let lag = rotor.lag(cmd + step);
        if lag.abs() > max_lag {
            max_lag = lag.abs();
            max_lag_pulse = k as u32 + 1;
        }
    }

    // Settle with the command fixed; the motor holds (0 Hz on the curve).
    let cmd = periods.len() as f64 * step;
    let holding = motor.pull_out_of_valid(0.0);
    let overshoot = rotor.settle(cmd, holding, settle_s, dt_s);
    // Trapped: kinetic plus potential energy within the well below the
    // barrier at ±180° electrical, 2 T / poles above its bottom.
    let lag = rotor.lag(cmd);
    let rel = lag - TAU * libm::round(lag / TAU);
    let energy =
        0.5 * rotor.inertia * rotor.omega * rotor.omega + holding / poles * (1.0 - libm::cos(rel));
    let settled = energy < 2.0 * holding / poles;
    let turns = libm::round(lag / TAU);
    if !(rotor.theta.is_finite() && rotor.omega.is_finite() && max_lag.is_finite())
        || libm::fabs(turns) > (i64::MAX / 4 / 1024) as f64
    {
        return Err(SimError::Diverged {
            pulse: rotor.pulses,
        });
    }
    Ok(SimResult {
        lost_steps: turns as i64 * 4 * motor.microsteps as i64,
        slips: rotor.slips,
        first_slip_pulse: rotor.first_slip,
        max_lag_deg: max_lag.to_degrees(),
        max_lag_steps: max_lag * to_steps,
        max_lag_pulse,
        overshoot_steps: (overshoot.max(0.0)) / step,
        final_error_steps: lag * to_steps,
        settled,
        steps: rotor.steps,
    })
}
