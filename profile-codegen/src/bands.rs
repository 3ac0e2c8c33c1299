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

    /// The bands as the periods of `timer` that play in them, `(shortest,
    /// longest)` in ticks, inclusive, each plus `reload_offset` as a table
    /// stores it (saturating; `u32::MAX`, every longer period, stays): what the players' `avoiding` and C's
    /// `_avoid` take, and a profile's `AVOID` holds. A period lies in a
    /// band exactly when its rate does ([`Bands::containing`]'s rule); a
    /// band from 0 steps/s reaches `u32::MAX`, and a band no whole period
    /// plays in has its shortest above its longest.
    ///
    /// ```
    /// use profile_codegen::bands::Bands;
    /// use profile_core::Timer;
    ///
    /// // 100 to 150 full steps/s in 1/8 steps on a 1 MHz timer.
    /// let bands = Bands::new(&[(100.0, 150.0)], 8);
    /// assert_eq!(bands.periods(&Timer::new(1_000_000), 0), vec![(834, 1250)]);
    /// ```
    pub fn periods(&self, timer: &Timer, reload_offset: i32) -> Vec<(u32, u32)> {
        let at = |t: u64| rate(timer, u32::try_from(t).unwrap_or(u32::MAX));
        let ticks_at = |r: f64| timer.timer_hz as f64 / (f64::from(timer.ticks_per_step) * r);
        let clamp = |t: f64| {
            if t.is_finite() && t >= 1.0 {
                (t as u64).min(u64::from(u32::MAX))
            } else if t.is_finite() {
                1
            } else {
                u64::from(u32::MAX)
            }
        };
        self.steps()
            .into_iter()
            .map(|(lo, hi)| {
                // The first period at most `hi` steps/s: from the quotient,
                // then a tick at a time to the rule's own boundary.
                let mut shortest = clamp(libm::ceil(ticks_at(hi)));
                while shortest > 1 && at(shortest - 1) <= hi {
                    shortest -= 1;
                }
                while shortest < u64::from(u32::MAX) && at(shortest) > hi {
                    shortest += 1;
                }
                // The last period at least `lo` steps/s.
                let longest = if lo <= 0.0 {
                    u64::from(u32::MAX)
                } else {
                    let mut longest = clamp(libm::floor(ticks_at(lo)));
                    while longest < u64::from(u32::MAX) && at(longest + 1) >= lo {
                        longest += 1;
                    }
                    while longest > 0 && at(longest) < lo {
                        longest -= 1;
                    }
                    longest
                };
                let stored = |t: u64| match u32::try_from(t) {
                    Ok(u32::MAX) | Err(_) => u32::MAX,
                    Ok(t) => t.saturating_add_signed(reload_offset),
                };
                (stored(shortest), stored(longest))
            })
            .collect()
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

    /// A period lies in a band's periods exactly when its rate lies in the
    /// band, on timers, ticks per step, microsteps and bounds that fall on
    /// whole periods and between them; a band from 0 reaches every long
    /// period; an offset moves both ends.
    #[test]
    fn band_periods_hold_the_periods_whose_rates_lie_in_the_band() {
        let cases = [
            (1_000_000, 1, 1, (800.0, 1200.0)),
            (1_000_000, 1, 8, (100.0, 150.0)),
            (16_000_000, 2, 16, (33.3, 47.9)),
            (72_000_000, 1, 1, (1000.0, 1000.0)),
            (10_000, 1, 1, (2.0, 10_000.0)),
            (1_000_000, 4, 1, (1000.0 / 3.0, 250.0)),
        ];
        for (hz, tps, microsteps, band) in cases {
            let mut timer = Timer::new(hz);
            timer.ticks_per_step = tps;
            let bands = Bands::new(&[band], microsteps);
            let [(shortest, longest)] = bands.periods(&timer, 0)[..] else {
                panic!("one band");
            };
            let steps = bands.steps()[0];
            for p in 1..200_000u32 {
                let r = rate(&timer, p);
                let inside = (steps.0..=steps.1).contains(&r);
                assert_eq!(
                    (shortest..=longest).contains(&p),
                    inside,
                    "{hz} Hz, {tps} ticks a step, {microsteps}: period {p} at {r} steps/s"
                );
            }
        }
        let timer = Timer::new(1_000_000);
        assert_eq!(
            Bands::new(&[(0.0, 1000.0)], 1).periods(&timer, 0),
            vec![(1000, u32::MAX)]
        );
        assert_eq!(
            Bands::new(&[(800.0, 1200.0)], 1).periods(&timer, 3),
            vec![(837, 1253)]
        );
        // No whole period plays between 2995 and 2999 steps/s (333.4 to 333.9
        // ticks).
        let (s, l) = Bands::new(&[(2995.0, 2999.0)], 1).periods(&timer, 0)[0];
        assert!(s > l, "{s} {l}");
    }
}
