//! Resonance bands: speeds where the motor rings or stalls (mid-band
//! resonance), which a ramp should cross and never cruise in.
//!
//! A profile gives them in full steps per second (`avoid = [[80, 120]]`),
//! as a motor's datasheet or a test on the machine finds them; a table
//! steps `microsteps` times faster ([`Bands::steps`]). The ramp's top, where
//! the player cruises, is checked against them at compile time
//! ([`Bands::check`]), and the report gives the time the ramp spends in
//! each ([`Bands::time_in`]).
//!
//! ```
//! use profile_codegen::bands::Bands;
//!
//! // 100 to 140 full steps/s, in 1/8 microsteps: 800 to 1120 steps/s.
//! let bands = Bands::new(&[(100.0, 140.0)], 8);
//! assert_eq!(bands.steps(), vec![(800.0, 1120.0)]);
//! ```

use std::format;
use std::string::String;
use std::vec::Vec;

use profile_core::Timer;

/// The most bands a profile names.
pub const MAX_BANDS: usize = 16;

/// Speed bands to stay out of, in full steps/s, and the microsteps a full
/// step is played in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Bands {
    bands: [(f64, f64); MAX_BANDS],
    len: usize,
    /// Table steps per full step (the motor's `microsteps`, 1 without one).
    pub microsteps: u32,
}

/// A table whose top lies in a band.
#[derive(Clone, Debug, PartialEq)]
pub struct BandError {
    /// The band, full steps/s.
    pub band: (f64, f64),
    /// The top's rate, steps/s.
    pub top: f64,
    /// The microsteps a full step is played in.
    pub microsteps: u32,
}

impl Bands {
    /// The bands `full_steps` (`(lowest, highest)`, full steps/s; the
    /// first [`MAX_BANDS`]), for a table of `microsteps` steps a full step.
    pub fn new(full_steps: &[(f64, f64)], microsteps: u32) -> Self {
        let mut bands = [(0.0, 0.0); MAX_BANDS];
        let len = full_steps.len().min(MAX_BANDS);
        bands[..len].copy_from_slice(&full_steps[..len]);
        Bands {
            bands,
            len,
            microsteps,
        }
    }

    /// The bands, `(lowest, highest)` full steps/s.
    pub fn full_steps(&self) -> &[(f64, f64)] {
        &self.bands[..self.len]
    }

    /// The bands in the table's steps/s.
    pub fn steps(&self) -> Vec<(f64, f64)> {
        let m = f64::from(self.microsteps);
        self.full_steps()
            .iter()
            .map(|&(lo, hi)| (lo * m, hi * m))
            .collect()
    }

    /// The band a rate (steps/s) lies in, bounds included.
    pub fn containing(&self, rate: f64) -> Option<(f64, f64)> {
        self.full_steps()
            .iter()
            .zip(self.steps())
            .find(|(_, (lo, hi))| (*lo..=*hi).contains(&rate))
            .map(|(full, _)| *full)
    }

    /// The ramp's top (its shortest period, `ticks` of `timer`), where the
    /// player cruises, outside every band; else the band.
    pub fn check(&self, timer: &Timer, periods: &[u32]) -> Result<(), BandError> {
        let Some(&shortest) = periods.iter().min() else {
            return Ok(());
        };
        let top = rate(timer, shortest);
        match self.containing(top) {
            None => Ok(()),
            Some(band) => Err(BandError {
                band,
                top,
                microsteps: self.microsteps,
            }),
        }
    }

    /// The time the ramp's steps spend in each band, in seconds: the
    /// periods of the steps whose rate lies in it, summed.
    pub fn time_in(&self, timer: &Timer, periods: &[u32]) -> Vec<f64> {
        let tick = f64::from(timer.ticks_per_step) / timer.timer_hz as f64;
        self.steps()
            .into_iter()
            .map(|(lo, hi)| {
                periods
                    .iter()
                    .filter(|&&p| (lo..=hi).contains(&rate(timer, p)))
                    .map(|&p| f64::from(p) * tick)
                    .sum()
            })
            .collect()
    }
}

/// The step rate of a period of `ticks`, steps/s.
fn rate(timer: &Timer, ticks: u32) -> f64 {
    timer.timer_hz as f64 / (f64::from(timer.ticks_per_step) * f64::from(ticks))
}

impl BandError {
    /// The message.
    pub fn message(&self) -> String {
        let full = self.top / f64::from(self.microsteps);
        let (lo, hi) = self.band;
        let rate = if self.microsteps == 1 {
            format!("{} steps/s", crate::numbers::Significant(self.top))
        } else {
            format!(
                "{} steps/s, {} full steps/s",
                crate::numbers::Significant(self.top),
                crate::numbers::Significant(full)
            )
        };
        format!(
            "the ramp's top, {rate}, lies in the band `avoid` [{}, {}] full steps/s, where the \
             motor rings: the player cruises at the top; choose `fmax` outside the band",
            crate::numbers::Num(lo),
            crate::numbers::Num(hi),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_top_in_a_band_is_refused_and_the_time_in_bands_summed() {
        // 1 MHz: periods 1000, 500, 250 ticks are 1000, 2000, 4000 steps/s.
        let timer = Timer::new(1_000_000);
        let periods = [1000, 500, 250];
        let bands = Bands::new(&[(900.0, 1100.0), (3000.0, 5000.0)], 1);
        let e = bands.check(&timer, &periods).unwrap_err();
        assert_eq!((e.band, e.top), ((3000.0, 5000.0), 4000.0));
        assert_eq!(
            e.message(),
            "the ramp's top, 4000 steps/s, lies in the band `avoid` [3000, 5000] full steps/s, \
             where the motor rings: the player cruises at the top; choose `fmax` outside the band"
        );
        assert_eq!(bands.time_in(&timer, &periods), vec![1e-3, 0.25e-3]);
        // In half steps, the same bands are twice as fast: the top is 2000
        // full steps/s, in neither.
        let half = Bands::new(&[(900.0, 1100.0), (3000.0, 5000.0)], 2);
        assert_eq!(half.check(&timer, &periods), Ok(()));
        assert_eq!(half.time_in(&timer, &periods), vec![0.5e-3, 0.0]);
    }
}
