//! Compile-time stepper-motor period tables.
//!
//! Use these macros through the `stepper-profiles` crate, which re-exports them
//! with the run-time API of `profile-core`.
#![forbid(unsafe_code)]

mod args;
mod expand;
mod include;

/// Computes a period table at compile time and expands to an array expression.
///
/// ```
/// # extern crate profile_macros as stepper_profiles;
/// use stepper_profiles::period_table;
///
/// // The S-curve article's orange curve, bit for bit as its C code computes it.
/// static PERIOD: [u16; 1000] = period_table!(
///     curve = sigmoid, len = 1000, fmin = 500, fmax = 64000, flexible = 8,
///     timer_hz = 10_000_000,
///     discretization = index, rounding = truncate, arithmetic = f32,
/// );
/// assert_eq!((PERIOD[0], PERIOD[999]), (19183, 156));
///
/// // The default mode: exact pulse times, diffused rounding.
/// const EXACT: [u16; 1000] = period_table!(
///     curve = sigmoid, len = 1000, fmin = 500, fmax = 64000, flexible = 8,
///     timer_hz = 10_000_000,
/// );
/// assert_eq!(EXACT.iter().map(|&p| p as u32).sum::<u32>(), 310_078);
/// ```
///
/// Keys, in any order (frequencies in Hz = steps/s; entry `k` is the timer
/// ticks between step `k` and step `k + 1`):
///
/// | key | value | default |
/// | --- | --- | --- |
/// | `curve` | `sigmoid`, `exponential`, `linear`, `three_stage`, `jerk_limited`, `torque_limited` | required |
/// | `timer_hz` | timer tick rate after the prescaler | required |
/// | `word` | `u16`, `u32`: the reload register's width | `u16` |
/// | `ticks_per_step` | `1`, or `2` when the timer toggles the pin (each entry a half period, played twice: step edges fall on every other tick, within one tick of the curve; the edge figures and `compress` are in timer ticks at the step edges) | `1` |
/// | `reload_offset` | an integer added to every period the table stores: `-1` where the timer's reload register holds the period less one (STM32's `ARR`, SysTick, AVR's `OCRnA`), so that DMA copies the table to it as it is; segments store it in each period, runs in each run's interval (every period played is offset); the figures and the motor check are the periods'; a stored value must be from 1 to the word's largest | `0` |
/// | `discretization` | `exact` (pulse edges where the curve puts them), `left_endpoint` (`1/f` at the step's start), `index` (the curve's x axis is the step index) | `exact` |
/// | `rounding` | `truncate` (C's cast), `nearest`, `diffuse` (every edge within 0.5 tick) | `diffuse` |
/// | `arithmetic` | `f64`; `f32` for the S-curve article's C code (`sigmoid`, `index`); `integer` for the S3C4510 article's (`linear`, `index`, `truncate`) | `f64` |
/// | `segments` | N equal-time `(period, count)` pairs instead of one entry per step (a `[(u16, u16); N]`); each step's own period must fit the word | off |
/// | `compress` | runs instead of one entry per step (an `[[u16; 5]; N]`, played by `runs::Expand` or the player), every step edge within this many timer ticks of the curve, from 0.5 (1 with `ticks_per_step = 2`) to 65535: about a tenth of the flash of a long ramp at 1 tick | off |
/// | `motor` | in a profiles file, the `[motors.NAME]` table of the motor the profile drives; the macro takes the motor's keys inline (below) | none |
/// | `driver` | the step driver, by name: `a4988`, `drv8825`, `tmc2209`, `dm542`; every period must last its `step_pulse` + `step_space` (the longer of the two with `ticks_per_step = 2`), or the table is an error at `fmax` | none |
/// | `step_pulse`, `step_space`, `dir_setup` | the driver's times, s (`ns`, `us`, `ms`): STEP high, STEP low, DIR before the step edge; each replaces the preset's | the preset's, else 0 |
/// | `core` | the core whose step interrupt plays the table: `"cortex-m0"`, `"cortex-m3"`, `"cortex-m4f"`, `"avr"` (the C player); with `cpu_hz`, every period must leave the interrupt's measured cost within `cpu_load` of the CPU and its largest step within the period, or the table is an error at `fmax` | none |
/// | `cpu_hz` | the core's clock, Hz (`kHz`, `MHz`) | none |
/// | `cpu_load` | the largest share of the CPU the step interrupt may take at any entry, above 0 and at most 1 | 0.5 |
/// | `axes` | the axes one step interrupt steps (`Axes`: each follower adds its measured cost), 1 to 16; 1 on the AVR | 1 |
/// | `avoid` | speed bands where the motor rings, `[(lowest, highest), ...]` in full steps/s (`Hz`, `kHz`; a motor's `microsteps` table steps a full step): the ramp's top, where the player cruises, must lie outside every band, or the table is an error at `fmax`; the report gives the time the ramp spends in each | none |
///
/// Each curve's own keys:
///
/// | curve | keys |
/// | --- | --- |
/// | `sigmoid` | `fmin`, `fmax`, `flexible` (steepness, over 0 up to 500), `len` (entries, 1 to 65 536) |
/// | `exponential` | `fmin`, `fmax` (reached at the end), `f_inf` (the asymptote, above `fmax`), and `len` or `tau` (the time constant, s) |
/// | `linear` | `fmin`, `fmax`, and `len` or `accel` (Hz/s) |
/// | `three_stage` | `fmin`, `fmax`, `accel` (Hz/s), `f1`, `f2` (where the stages meet), `shape` (1/s) |
/// | `jerk_limited` | `fmin`, `fmax`, `accel` (Hz/s), `jerk` (Hz/s²) |
/// | `torque_limited` | `fmax`, `margin` (above 0, at most 0.99), optionally `fmin`; needs a motor (below): at every speed the acceleration is what `margin` times the motor's pull-out torque (over `safety`) leaves after friction and damping, over the inertia, so that the ramp passes the motor check with `safety / margin`. Without `fmin`, the start is the fastest that check accepts |
///
/// Where the length follows from the parameters (`tau`, `accel`,
/// `three_stage`, `jerk_limited`, `torque_limited`), the table has as many
/// entries as the ramp takes steps to reach `fmax`.
///
/// A motor, to check at compile time that it can follow the table (each
/// step's torque against the pull-out curve; a ramp it cannot follow is a
/// compile error). The macro takes the motor's keys inline; a profiles file
/// declares them in a `[motors.NAME]` table that a profile names with
/// `motor = "NAME"`. Frequencies are the table's steps per second (with
/// `microsteps = 8`, a datasheet's 4000 full steps/s is 32 000):
///
/// | key | value | default |
/// | --- | --- | --- |
/// | `step_angle` | full-step angle, degrees | required |
/// | `microsteps` | table steps per full step | `1` |
/// | `rotor_inertia` | kg·m² | required |
/// | `load_inertia` | the load's inertia at the shaft, kg·m² | `0` |
/// | `torque_curve` | pull-out torque, up to 32 `(step frequency, N·m)` pairs with rising frequencies: `[(0, 0.40), (1000, 0.33), (4000, 0.12)]`; no torque beyond the last | required, unless the windings are given |
/// | `resistance`, `inductance` | phase resistance (Ω) and inductance (H): with `rated_current`, `holding_torque` and `supply_voltage`, the pull-out curve is derived (`profile_codegen::motor::Windings`) | none |
/// | `rated_current` | the motor's rated phase current, A: its holding torque is measured at it, and the driver is set to it unless `driver_current` says otherwise | none |
/// | `holding_torque` | holding torque at rated current, two phases on, N·m | none |
/// | `supply_voltage` | the driver's supply, V | none |
/// | `detent_torque` | the unpowered motor's detent torque, N·m, taken off the derived curve | `0` |
/// | `drive` | the current the driver sets: `sine` (a microstepping driver, at any microstep setting), `half_step` (each phase on at the driver's current or off, in turn one phase then both), `full_step` (both phases on) | `sine` |
/// | `driver_current` | the driver's current setting, A: the sine's RMS or peak value, as `driver_current_is` says; the level each phase is switched to with `half_step` or `full_step`. Below the rating, the torque falls in proportion | `rated_current` |
/// | `driver_current_is` | `rms` or `peak`, as the driver's manual gives its setting | `rms` |
/// | `supply_utilization` | the share of the supply the chopper puts across a winding (its bridge's drops, its PWM's dead and off times), above 0 and at most 1 | `0.76` |
/// | `iron_loss` | the iron's drag at an electrical frequency of 1 kHz (N·m), growing as the frequency's 0.4th power, taken off the derived torque | `0.11 · holding_torque` |
/// | `friction` | constant load and friction torque, N·m | `0` |
/// | `damping` | viscous damping on the rotor's speed, N·m·s/rad | `0` |
/// | `damping_ratio` | electromagnetic damping ζ, on the rotor's speed relative to the field's (`simulate`), from 0 to 1 | `0` |
/// | `safety` | the curve's torque is divided by it (at least 1) | `1` |
/// | `max_start_hz` | the motor's start frequency without load: the table must start below it over `sqrt(1 + load_inertia / rotor_inertia)`; without it, below the start the model's rotor pulls in to | none |
///
/// Integer literals are accepted where a number is expected. A frequency may
/// carry a unit, `Hz`, `kHz` or `MHz`, and a time `s`, `ms` or `us`, with or
/// without a space (`fmax = 64kHz`, `timer_hz = 10 MHz`, `tau = 5ms`): the
/// number is scaled in decimal, so `64kHz` gives the table of `64_000`. A
/// motor's keys take its datasheet's units: inertia `kgm2` or `gcm2`
/// (`rotor_inertia = 68gcm2`), torque `Nm`, `Ncm` or `mNm`, resistance
/// `ohm` or `mohm`, inductance `H`, `mH` or `uH`, current `A` or `mA`,
/// voltage `V`, `step_angle` `deg`; a string takes the symbols too
/// (`"68 g·cm²"`, `"0.5 Ω"`, `"40 N·cm"`, `"1.8°"`), and `torque_curve`'s
/// points take frequency and torque units (`[(0, 40Ncm), (1kHz, 33Ncm)]`,
/// or in strings, `("1 kHz", "33 N·cm")`).
/// Any other suffix, a type suffix such as `500u32` included, is an error.
/// Every mistake is a compile error at the offending key or value, saying
/// what is expected.
#[proc_macro]
pub fn period_table(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    expand::period_table(input.into()).into()
}

/// Declares one module per profile of a TOML file, at compile time.
///
/// The path is relative to the crate's `Cargo.toml` (`CARGO_MANIFEST_DIR`).
/// Each `[profiles.NAME]` becomes `pub mod NAME` with `PERIODS` (or
/// `SEGMENTS`, or `RUNS`), `LEN`, `TIMER_HZ`, `TICKS_PER_STEP`,
/// `RELOAD_OFFSET`, `TOTAL_TICKS` and the other figures as constants,
/// documented with the profile's parameters, and `RAMP`, the table as a
/// `stepper_profiles::player::Rated` ramp of its timer's rate (for
/// `player::Timed`, feature `fugit`).
/// Cargo rebuilds the crate when the file changes.
///
/// ```ignore
/// stepper_profiles::include_profiles!("profiles.toml");
///
/// fn first_period() -> u16 {
///     orange::PERIODS[0]
/// }
/// ```
///
/// A mistake in the file is a compile error on the path, reading
/// `profiles.toml:LINE:COL: message` with the line and a caret.
#[proc_macro]
pub fn include_profiles(input: proc_macro::TokenStream) -> proc_macro::TokenStream {
    include::include_profiles(input.into()).into()
}
