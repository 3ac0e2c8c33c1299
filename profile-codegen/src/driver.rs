//! The step driver's timing: how long its STEP input must stay high and low,
//! and how long before a step its DIR input must hold the new direction.
//!
//! A step pulse shorter than the driver's minimum, or a step too soon after
//! the direction changed, loses the step without a sign. A profile that
//! names its driver (`driver = "drv8825"`, or the times themselves:
//! `step_pulse`, `step_space`, `dir_setup`) has every period of its table
//! checked against them at compile time ([`Driver::check`]).
//!
//! ```
//! use profile_codegen::driver::Driver;
//!
//! let drv8825 = Driver::preset("drv8825").unwrap();
//! // 1.9 µs high and 1.9 µs low: at most 263 157 steps/s.
//! assert_eq!(drv8825.max_rate(1) as u32, 263_157);
//! ```

use std::format;
use std::string::String;

use profile_core::Timer;

/// A step driver's timing, in seconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Driver {
    /// The shortest time STEP may stay high (`step_pulse`).
    pub step_pulse: f64,
    /// The shortest time STEP may stay low between two pulses
    /// (`step_space`).
    pub step_space: f64,
    /// The shortest time from a change of DIR to the step edge that takes
    /// the new direction (`dir_setup`).
    pub dir_setup: f64,
}

/// The drivers `driver = NAME` names, with their datasheets' figures: the
/// name, the timing, and where the figures come from.
pub const PRESETS: [(&str, Driver, &str); 4] = [
    (
        "a4988",
        Driver {
            step_pulse: 1e-6,
            step_space: 1e-6,
            dir_setup: 200e-9,
        },
        "Allegro A4988 datasheet, logic interface timing: STEP high and low at least 1 µs, \
         DIR set up 200 ns before the step",
    ),
    (
        "drv8825",
        Driver {
            step_pulse: 1.9e-6,
            step_space: 1.9e-6,
            dir_setup: 650e-9,
        },
        "TI DRV8825 datasheet, timing requirements: STEP high and low at least 1.9 µs \
         (250 kHz at most), DIR set up 650 ns before the step",
    ),
    (
        "tmc2209",
        Driver {
            step_pulse: 100e-9,
            step_space: 100e-9,
            dir_setup: 20e-9,
        },
        "TRINAMIC TMC2209 datasheet, STEP/DIR timing: STEP high and low at least 100 ns, \
         DIR set up 20 ns before the step",
    ),
    (
        "dm542",
        Driver {
            step_pulse: 2.5e-6,
            step_space: 2.5e-6,
            dir_setup: 5e-6,
        },
        "Leadshine DM542 manual (and TB6600-class drivers built alike): PUL high and low at \
         least 2.5 µs, DIR 5 µs ahead of the PUL edge",
    ),
];

/// What a table does past its driver's timing.
#[derive(Clone, Debug, PartialEq)]
pub struct DriverError {
    /// The first entry too short for the driver.
    pub index: usize,
    /// Its period, in ticks.
    pub ticks: u32,
    /// The step rate it plays, in steps/s.
    pub rate: f64,
    /// The shortest period the driver takes, in ticks (rounded up).
    pub shortest: u32,
    /// The fastest step rate the driver takes, in steps/s.
    pub max_rate: f64,
    /// `Some((wait, setup))` where the entries are long enough for the
    /// steps but not for a reversal: the players reverse through the
    /// table's first entry, so the firmware sets DIR one step of it
    /// (`wait` ticks) ahead of the step that takes it, and the driver
    /// needs `setup` ticks (`dir_setup`).
    pub dir_setup: Option<(u32, u32)>,
}

impl Driver {
    /// The driver `name` names ([`PRESETS`]).
    pub fn preset(name: &str) -> Option<Driver> {
        PRESETS
            .iter()
            .find(|(n, _, _)| *n == name)
            .map(|(_, d, _)| *d)
    }

    /// The shortest time from one step edge to the next, in seconds, when
    /// each table entry is `ticks_per_step` times played: with one, the
    /// pulse and the space share the period; with two, the timer toggles
    /// STEP at every entry, which must then hold the longer of the two.
    pub fn shortest_step(&self, ticks_per_step: u8) -> f64 {
        if ticks_per_step >= 2 {
            f64::from(ticks_per_step) * self.step_pulse.max(self.step_space)
        } else {
            self.step_pulse + self.step_space
        }
    }

    /// The fastest step rate the driver takes, in steps/s.
    pub fn max_rate(&self, ticks_per_step: u8) -> f64 {
        1.0 / self.shortest_step(ticks_per_step)
    }

    /// `seconds` in ticks of `timer` (its tick rate, not its steps),
    /// rounded up: a hair under a whole tick counts as it.
    pub fn ticks(&self, seconds: f64, timer: &Timer) -> u32 {
        libm::ceil(seconds * timer.timer_hz as f64 * (1.0 - 1e-12)) as u32
    }

    /// The shortest table entry the driver takes, in ticks of `timer`: a
    /// hair under a whole tick counts as it (0.9999999 of a tick is a
    /// tick).
    pub fn shortest_entry(&self, timer: &Timer) -> u32 {
        let per_entry = self.shortest_step(timer.ticks_per_step) / f64::from(timer.ticks_per_step);
        self.ticks(per_entry, timer)
    }

    /// Checks every entry of `periods` (ticks of `timer`) against the
    /// driver: the first one shorter than the driver takes, or `Ok`. Then
    /// the first entry against `dir_setup`: a player reverses through rest,
    /// at the first entry, and the firmware sets DIR for the next step
    /// right after it pulses a step, so the step that takes a new
    /// direction comes one step of the first entry (`ticks_per_step`
    /// entries) after DIR changed.
    pub fn check(&self, timer: &Timer, periods: &[u32]) -> Result<(), DriverError> {
        let tick = f64::from(timer.ticks_per_step) / timer.timer_hz as f64;
        let shortest = self.shortest_entry(timer);
        let error = |index: usize, dir_setup: Option<(u32, u32)>| {
            let ticks = periods[index];
            Err(DriverError {
                index,
                ticks,
                rate: 1.0 / (f64::from(ticks) * tick),
                shortest,
                max_rate: 1.0 / (f64::from(shortest) * tick),
                dir_setup,
            })
        };
        if let Some(index) = periods.iter().position(|&p| p < shortest) {
            return error(index, None);
        }
        let setup = self.dir_setup_ticks(timer);
        match periods.first() {
            Some(&first) if first * u32::from(timer.ticks_per_step) < setup => {
                error(0, Some((first * u32::from(timer.ticks_per_step), setup)))
            }
            _ => Ok(()),
        }
    }

    /// `dir_setup` in ticks of `timer`, rounded up.
    pub fn dir_setup_ticks(&self, timer: &Timer) -> u32 {
        self.ticks(self.dir_setup, timer)
    }
}

impl DriverError {
    /// The message, naming what the driver takes (`what`: "`driver =
    /// \"drv8825\"`", or the keys).
    pub fn message(&self, what: &str) -> String {
        if let Some((wait, setup)) = self.dir_setup {
            return format!(
                "entry {} is {} ticks: a reversal sets DIR a step of it ({wait} ticks) ahead of \
                 the step that takes the new direction, and the driver's timing ({what}) needs \
                 {setup}; lower `fmin`, or choose a faster driver",
                self.index, self.ticks,
            );
        }
        format!(
            "entry {} is {} ticks, {} steps/s: the driver's timing ({what}) takes at least {} \
             ticks a step, at most {} steps/s; lower `fmax`, or choose a faster driver",
            self.index,
            self.ticks,
            crate::numbers::Significant(self.rate),
            self.shortest,
            crate::numbers::Num(libm::floor(self.max_rate)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_carry_their_datasheets_figures() {
        let a4988 = Driver::preset("a4988").unwrap();
        assert_eq!((a4988.step_pulse, a4988.step_space), (1e-6, 1e-6));
        assert_eq!(Driver::preset("tmc2209").unwrap().dir_setup, 20e-9);
        assert!((Driver::preset("dm542").unwrap().max_rate(1) - 200_000.0).abs() < 1e-6);
        assert_eq!(Driver::preset("l298"), None);
    }

    #[test]
    fn the_first_entry_too_short_is_named_with_the_rate_the_driver_takes() {
        // DRV8825 on a 10 MHz timer: 3.8 µs a step, 38 ticks.
        let drv = Driver::preset("drv8825").unwrap();
        let timer = Timer::new(10_000_000);
        assert_eq!(drv.check(&timer, &[100, 50, 38]), Ok(()));
        let e = drv.check(&timer, &[100, 50, 37, 30]).unwrap_err();
        assert_eq!((e.index, e.ticks, e.shortest), (2, 37, 38));
        assert_eq!(
            e.message("`driver = \"drv8825\"`"),
            "entry 2 is 37 ticks, 270270 steps/s: the driver's timing (`driver = \"drv8825\"`) \
             takes at least 38 ticks a step, at most 263157 steps/s; lower `fmax`, or choose a \
             faster driver"
        );
    }

    #[test]
    fn with_two_ticks_a_step_each_entry_holds_the_longer_of_pulse_and_space() {
        // 2.5 µs high at 1 MHz: 3 ticks an entry, 6 µs a step.
        let dm542 = Driver::preset("dm542").unwrap();
        let timer = Timer {
            ticks_per_step: 2,
            ..Timer::new(1_000_000)
        };
        assert_eq!(dm542.check(&timer, &[3]), Ok(()));
        assert_eq!(dm542.check(&timer, &[2]).unwrap_err().shortest, 3);
    }

    #[test]
    fn a_first_entry_shorter_than_the_direction_setup_is_refused() {
        // 1 µs high and low, DIR 5 µs ahead, at 1 MHz: 2 ticks a step, 5
        // ticks at a reversal.
        let driver = Driver {
            step_pulse: 1e-6,
            step_space: 1e-6,
            dir_setup: 5e-6,
        };
        let timer = Timer::new(1_000_000);
        assert_eq!(driver.dir_setup_ticks(&timer), 5);
        assert_eq!(driver.check(&timer, &[5, 3, 2]), Ok(()));
        let e = driver.check(&timer, &[4, 3, 2]).unwrap_err();
        assert_eq!((e.index, e.ticks, e.dir_setup), (0, 4, Some((4, 5))));
        assert_eq!(
            e.message("`dir_setup`"),
            "entry 0 is 4 ticks: a reversal sets DIR a step of it (4 ticks) ahead of the step \
             that takes the new direction, and the driver's timing (`dir_setup`) needs 5; lower \
             `fmin`, or choose a faster driver"
        );
        // Two entries a step: the step of the first entry is 8 ticks.
        let two = Timer {
            ticks_per_step: 2,
            ..timer
        };
        assert_eq!(driver.check(&two, &[4, 3, 2]), Ok(()));
    }
}
