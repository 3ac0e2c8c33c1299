//! The schema's vocabulary: keys as users spell them.

use core::fmt;

/// A parameter of a table spec, as spelled in macro arguments and TOML.
///
/// The keys every curve shares are constants here; a key that only one
/// curve takes is declared in that curve's module (`Key::FLEXIBLE` with the
/// sigmoid, `Key::JERK` with the jerk-limited ramp). An [`Error`](crate::Error)
/// names the key it is about ([`Error::key`](crate::Error::key)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Key(pub(crate) &'static str);

impl Key {
    /// `curve`: which curve.
    pub const CURVE: Key = Key("curve");
    /// `len`: entries (steps) of the table.
    pub const LEN: Key = Key("len");
    /// `fmin`: the start frequency, in Hz.
    pub const FMIN: Key = Key("fmin");
    /// `fmax`: the end frequency, in Hz.
    pub const FMAX: Key = Key("fmax");
    /// `accel`: an acceleration, in Hz/s.
    pub const ACCEL: Key = Key("accel");
    /// `timer_hz`: the timer's tick rate.
    pub const TIMER_HZ: Key = Key("timer_hz");
    /// `word`: `u16` or `u32`.
    pub const WORD: Key = Key("word");
    /// `ticks_per_step`: timer reloads per step.
    pub const TICKS_PER_STEP: Key = Key("ticks_per_step");
    /// `reload_offset`: what the timer's reload register adds to a period
    /// (-1 where it holds the period less one); stored in every entry.
    pub const RELOAD_OFFSET: Key = Key("reload_offset");
    /// `discretization`: how the curve becomes entries.
    pub const DISCRETIZATION: Key = Key("discretization");
    /// `rounding`: how exact periods become integers.
    pub const ROUNDING: Key = Key("rounding");
    /// `arithmetic`: `f64`, or an article's own arithmetic.
    pub const ARITHMETIC: Key = Key("arithmetic");
    /// `segments`: the equal-time segment layout.
    pub const SEGMENTS: Key = Key("segments");
    /// `compress`: the compressed layout, its largest pulse-edge error in
    /// ticks.
    pub const COMPRESS: Key = Key("compress");
    /// `motor`: the motor a profile drives.
    pub const MOTOR: Key = Key("motor");
    /// `step_angle`
    pub const STEP_ANGLE: Key = Key("step_angle");
    /// `microsteps`
    pub const MICROSTEPS: Key = Key("microsteps");
    /// `rotor_inertia`
    pub const ROTOR_INERTIA: Key = Key("rotor_inertia");
    /// `load_inertia`
    pub const LOAD_INERTIA: Key = Key("load_inertia");
    /// `torque_curve`
    pub const TORQUE_CURVE: Key = Key("torque_curve");
    /// `friction`
    pub const FRICTION: Key = Key("friction");
    /// `damping`
    pub const DAMPING: Key = Key("damping");
    /// `damping_ratio`
    pub const DAMPING_RATIO: Key = Key("damping_ratio");
    /// `safety`
    pub const SAFETY: Key = Key("safety");
    /// `max_start_hz`
    pub const MAX_START_HZ: Key = Key("max_start_hz");
    /// `resistance`: phase resistance, Ω.
    pub const RESISTANCE: Key = Key("resistance");
    /// `inductance`: phase inductance, H.
    pub const INDUCTANCE: Key = Key("inductance");
    /// `rated_current`: rated phase current, A.
    pub const RATED_CURRENT: Key = Key("rated_current");
    /// `holding_torque`: holding torque at rated current, N·m.
    pub const HOLDING_TORQUE: Key = Key("holding_torque");
    /// `supply_voltage`: the driver's supply, V.
    pub const SUPPLY_VOLTAGE: Key = Key("supply_voltage");
    /// `detent_torque`: the unpowered motor's detent torque, N·m.
    pub const DETENT_TORQUE: Key = Key("detent_torque");
    /// `drive`: the current's waveform the driver sets (`sine`,
    /// `half_step`, `full_step`).
    pub const DRIVE: Key = Key("drive");
    /// `driver_current`: the driver's current setting, A.
    pub const DRIVER_CURRENT: Key = Key("driver_current");
    /// `driver_current_is`: whether the setting is the sine's `rms` or
    /// `peak` value.
    pub const DRIVER_CURRENT_IS: Key = Key("driver_current_is");
    /// `supply_utilization`: the share of the supply the chopper puts
    /// across a winding.
    pub const SUPPLY_UTILIZATION: Key = Key("supply_utilization");
    /// `iron_loss`: the iron's drag at an electrical frequency of 1 kHz,
    /// N·m.
    pub const IRON_LOSS: Key = Key("iron_loss");

    /// `driver`: the step driver a profile plays into, by name.
    pub const DRIVER: Key = Key("driver");
    /// `step_pulse`: the shortest time the driver's STEP input may stay
    /// high, s.
    pub const STEP_PULSE: Key = Key("step_pulse");
    /// `step_space`: the shortest time the driver's STEP input may stay
    /// low between pulses, s.
    pub const STEP_SPACE: Key = Key("step_space");
    /// `dir_setup`: the shortest time from a change of the driver's DIR
    /// input to the next step edge, s.
    pub const DIR_SETUP: Key = Key("dir_setup");

    /// `core`: the core whose step interrupt plays the table, by name.
    pub const CORE: Key = Key("core");
    /// `cpu_hz`: the core's clock, Hz.
    pub const CPU_HZ: Key = Key("cpu_hz");
    /// `cpu_load`: the largest share of the CPU the step interrupt may take
    /// at the table's fastest entry, from 0 to 1.
    pub const CPU_LOAD: Key = Key("cpu_load");
    /// `axes`: the axes one step interrupt steps.
    pub const AXES: Key = Key("axes");

    /// `avoid`: speed bands where the motor rings, in full steps/s.
    pub const AVOID: Key = Key("avoid");

    /// The key as written by users.
    pub const fn name(self) -> &'static str {
        self.0
    }
}

impl fmt::Display for Key {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.0)
    }
}
