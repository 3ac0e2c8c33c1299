//! From a spec to integer periods: exact times, quantization, figures.

use crate::curves::TimeModel;
use crate::error::Error;
use crate::linear::IntegerLinear;
use crate::solve::{MAX_ITERATIONS, TimeCurve, pulse_time, time_after_ramp};
use crate::spec::{Arithmetic, Curve, Discretization, Rounding, Spec, Timer, Word};

mod sealed {
    pub trait Sealed {}
    impl Sealed for u16 {}
    impl Sealed for u32 {}
}

/// An integer type a table can be generated into: `u16` or `u32`.
pub trait TableWord: Copy + sealed::Sealed {
    /// The [`Word`] this type is.
    const WORD: Word;
    /// Converts a period already checked to fit.
    fn from_ticks(ticks: u32) -> Self;
    /// The value as `u32`.
    fn into_ticks(self) -> u32;
}

impl TableWord for u16 {
    const WORD: Word = Word::U16;
    fn from_ticks(ticks: u32) -> Self {
        ticks as u16
    }
    fn into_ticks(self) -> u32 {
        self as u32
    }
}

impl TableWord for u32 {
    const WORD: Word = Word::U32;
    fn from_ticks(ticks: u32) -> Self {
        ticks
    }
    fn into_ticks(self) -> u32 {
        self
    }
}

/// What a generated table amounts to. Times in seconds, frequencies in Hz
/// (steps/s), acceleration in Hz/s, jerk in Hz/s².
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Figures {
    /// Number of entries.
    pub len: u32,
    /// First entry, in ticks.
    pub first_ticks: u32,
    /// Last entry, in ticks.
    pub last_ticks: u32,
    /// Shortest entry, in ticks.
    pub min_ticks: u32,
    /// Longest entry, in ticks.
    pub max_ticks: u32,
    /// Sum of all entries, in ticks.
    pub total_ticks: u64,
    /// Ramp duration as played: `total_ticks * ticks_per_step / timer_hz`.
    pub duration_s: f64,
    /// Step frequency of the first entry.
    pub start_hz: f64,
    /// Step frequency of the last entry.
    pub final_hz: f64,
    /// Largest acceleration between consecutive entries of the integer table.
    pub max_accel_hz_s: f64,
    /// Largest jerk between consecutive accelerations of the integer table.
    pub max_jerk_hz_s2: f64,
    /// Largest distance of a pulse edge (a prefix sum of the table) from its
    /// unrounded time under the chosen discretization, in ticks.
    pub max_edge_error_ticks: f64,
    /// Last pulse edge minus its unrounded time, in ticks (the drift).
    pub total_error_ticks: f64,
    /// Ticks left between the longest entry and the largest value the word holds.
    pub overflow_margin_ticks: u32,
}

/// Turns exact periods into integers and keeps the figures.
struct Quantizer {
    rounding: Rounding,
    timer: Timer,
    scale: f64,
    exact_edge: f64,
    emitted: u64,
    prev_ticks: u32,
    prev_accel: f64,
    figures: Figures,
}

impl Quantizer {
    fn new(spec: &Spec) -> Self {
        Quantizer {
            rounding: spec.rounding,
            timer: spec.timer,
            scale: spec.timer.ticks_per_second(),
            exact_edge: 0.0,
            emitted: 0,
            prev_ticks: 0,
            prev_accel: 0.0,
            figures: Figures {
                len: 0,
                first_ticks: 0,
                last_ticks: 0,
                min_ticks: u32::MAX,
                max_ticks: 0,
                total_ticks: 0,
                duration_s: 0.0,
                start_hz: 0.0,
                final_hz: 0.0,
                max_accel_hz_s: 0.0,
                max_jerk_hz_s2: 0.0,
                max_edge_error_ticks: 0.0,
                total_error_ticks: 0.0,
                overflow_margin_ticks: 0,
            },
        }
    }

    /// Quantizes entry `index`, whose exact length is `entry` ticks and whose
    /// exact end is `edge` ticks from the start (the running sum of entries when
    /// `None`).
    fn push(&mut self, index: u32, entry: f64, edge: Option<f64>) -> Result<u32, Error> {
        self.exact_edge = match edge {
            Some(edge) => edge,
            None => self.exact_edge + entry,
        };
        let rounded = match self.rounding {
            Rounding::Truncate => libm::trunc(entry),
            Rounding::Nearest => libm::round(entry),
            Rounding::Diffuse => libm::round(self.exact_edge) - self.emitted as f64,
        };
        self.check(index, rounded, entry)
    }

    /// Refuses, before any pulse time is solved, a curve whose every period
    /// (between `1 / f_start` and `1 / f_end`) is too long for the word or
    /// rounds to 0 ticks: entry 0 is then out of range whatever the curve.
    fn reachable(&self, f_start: f64, f_end: f64) -> Result<(), Error> {
        let (shortest, longest) = (self.scale / f_end, self.scale / f_start);
        if shortest.is_nan() || shortest > self.timer.word.max() as f64 + 1.0 {
            return Err(Error::PeriodOverflow {
                index: 0,
                ticks: longest,
                word: self.timer.word,
                timer_hz: self.timer.timer_hz,
                lowest_hz: self.timer.lowest_frequency(),
            });
        }
        if longest.is_nan() || longest < 0.5 {
            return Err(Error::PeriodZero {
                index: 0,
                highest_hz: self.scale,
            });
        }
        Ok(())
    }

    /// Records entry `index` already rounded by the curve's own arithmetic.
    fn push_exact(&mut self, index: u32, ticks: u64, entry: f64) -> Result<u32, Error> {
        self.exact_edge += entry;
        self.check(index, ticks as f64, entry)
    }

    fn check(&mut self, index: u32, rounded: f64, entry: f64) -> Result<u32, Error> {
        let max = self.timer.word.max();
        if !rounded.is_finite() || rounded > max as f64 {
            return Err(Error::PeriodOverflow {
                index,
                ticks: entry,
                word: self.timer.word,
                timer_hz: self.timer.timer_hz,
                lowest_hz: self.timer.lowest_frequency(),
            });
        }
        if rounded < 1.0 {
            return Err(Error::PeriodZero {
                index,
                highest_hz: self.scale,
            });
        }
        let ticks = rounded as u32;
        self.emitted += ticks as u64;
        self.record(index, ticks);
        Ok(ticks)
    }

    fn record(&mut self, index: u32, ticks: u32) {
        let fig = &mut self.figures;
        let error = self.emitted as f64 - self.exact_edge;
        fig.max_edge_error_ticks = fig.max_edge_error_ticks.max(libm::fabs(error));
        fig.total_error_ticks = error;
        fig.min_ticks = fig.min_ticks.min(ticks);
        fig.max_ticks = fig.max_ticks.max(ticks);
        if index == 0 {
            fig.first_ticks = ticks;
        } else {
            // Acceleration at the edge between the two entries: frequency change
            // over the time between the entries' midpoints.
            let f_prev = self.scale / self.prev_ticks as f64;
            let f = self.scale / ticks as f64;
            let dt = (self.prev_ticks as f64 + ticks as f64) / 2.0 / self.scale;
            let accel = (f - f_prev) / dt;
            fig.max_accel_hz_s = fig.max_accel_hz_s.max(libm::fabs(accel));
            if index >= 2 {
                // Consecutive accelerations sit one entry apart.
                let jerk = (accel - self.prev_accel) / (self.prev_ticks as f64 / self.scale);
                fig.max_jerk_hz_s2 = fig.max_jerk_hz_s2.max(libm::fabs(jerk));
            }
            self.prev_accel = accel;
        }
        self.prev_ticks = ticks;
        fig.last_ticks = ticks;
        fig.len = index + 1;
    }

    fn finish(mut self) -> Figures {
        let fig = &mut self.figures;
        fig.total_ticks = self.emitted;
        fig.duration_s = self.emitted as f64 / self.scale;
        fig.start_hz = self.scale / fig.first_ticks as f64;
        fig.final_hz = self.scale / fig.last_ticks as f64;
        fig.overflow_margin_ticks = self.timer.word.max() - fig.max_ticks;
        self.figures
    }
}

/// The exact time of pulse edge `k` (when `N(t) = k`), in s.
pub(crate) fn edge_time(c: &dyn TimeCurve, k: u32) -> Result<f64, Error> {
    let steps = k as f64;
    if let Some(t) = c.time_at(steps) {
        return Ok(t);
    }
    let (ramp_time, ramp_steps) = c.ramp_end();
    if steps >= ramp_steps {
        return Ok(time_after_ramp(c, steps));
    }
    // f is non-decreasing from f(0) to the end frequency, so edge k is no
    // earlier than k / f_end and no later than k / f(0).
    let hi = ramp_time.min(steps / c.freq(0.0));
    let lo = (steps / c.end_freq()).min(hi);
    pulse_time(c, steps, lo, hi, MAX_ITERATIONS).ok_or(Error::NoConvergence {
        index: k,
        iterations: MAX_ITERATIONS,
    })
}

impl Spec {
    /// Computes the table into `out` and returns its figures.
    ///
    /// `out` must hold exactly [`len`](Spec::len) entries of the spec's word.
    /// No allocation, no panic: the same bits as `period_table!` on any target.
    ///
    /// ```
    /// use profile_core::{Curve, Discretization, Rounding, Arithmetic, Sigmoid, Spec, Timer};
    ///
    /// // Seed 000's orange curve, as its C code computes it.
    /// let spec = Spec::new(
    ///     Curve::Sigmoid(Sigmoid { fmin: 500.0, fmax: 64_000.0, flexible: 8.0, len: 1000 }),
    ///     Timer::new(10_000_000),
    /// )
    /// .with_discretization(Discretization::Index)
    /// .with_rounding(Rounding::Truncate)
    /// .with_arithmetic(Arithmetic::F32);
    /// let mut period = [0u16; 1000];
    /// spec.generate(&mut period)?;
    /// assert_eq!((period[0], period[999]), (19183, 156));
    /// # Ok::<(), profile_core::Error>(())
    /// ```
    pub fn generate<W: TableWord>(&self, out: &mut [W]) -> Result<Figures, Error> {
        self.validate()?;
        if W::WORD != self.timer.word {
            return Err(Error::WordMismatch {
                expected: self.timer.word,
                got: W::WORD,
            });
        }
        if out.len() != self.len() as usize {
            return Err(Error::BufferLength {
                expected: self.len(),
                got: out.len(),
            });
        }
        self.for_each_period(|index, ticks| {
            if let Some(slot) = out.get_mut(index as usize) {
                *slot = W::from_ticks(ticks);
            }
        })
    }

    /// Calls `sink(k, t)` with the exact time `t` (in s) of every pulse edge
    /// `k = 1..=len` of the continuous curve, before discretization: where
    /// `N(t) = k` for curves in time; for `discretization = index`, the
    /// running sum of the unrounded entries (the index curve has no other
    /// time). Measures how far any table strays from the curve.
    pub fn for_each_exact_edge<F: FnMut(u32, f64)>(&self, mut sink: F) -> Result<(), Error> {
        self.validate()?;
        let len = self.len();
        if self.discretization == Discretization::Index {
            let scale = self.timer.ticks_per_second();
            let mut k = 0;
            let mut t = 0.0;
            // The f32 and integer modes keep their own arithmetic.
            return self.exact_index_entries(|entry_ticks| {
                k += 1;
                t += entry_ticks / scale;
                sink(k, t);
            });
        }
        let model = TimeModel::new(&self.curve);
        for k in 1..=len {
            sink(k, edge_time(model.curve(), k)?);
        }
        Ok(())
    }

    /// Unrounded entries of an index-discretized table, in ticks.
    fn exact_index_entries<F: FnMut(f64)>(&self, mut sink: F) -> Result<(), Error> {
        let len = self.len();
        let scale = self.timer.ticks_per_second();
        match self.curve {
            Curve::Sigmoid(s) => {
                for k in 0..len {
                    sink(match self.arithmetic {
                        Arithmetic::F32 => scale / s.freq_at_index_f32(k) as f64,
                        _ => scale / s.freq_at_index(k),
                    });
                }
            }
            Curve::Linear(l) => {
                if self.arithmetic == Arithmetic::Integer {
                    let t = self.timer;
                    let int = IntegerLinear::new(&l, len, t.ticks_per_step, t.timer_hz)?;
                    for k in 0..len {
                        sink(scale / int.freq(k) as f64);
                    }
                } else {
                    for k in 0..len {
                        sink(scale / l.freq_at_index(k));
                    }
                }
            }
            _ => {}
        }
        Ok(())
    }

    /// Computes the table's figures without storing it.
    pub fn figures(&self) -> Result<Figures, Error> {
        self.for_each_period(|_, _| {})
    }

    /// Computes the table entry by entry, calling `sink(index, ticks)` for each,
    /// and returns its figures. Stops at the first entry that does not fit.
    pub fn for_each_period<F: FnMut(u32, u32)>(&self, mut sink: F) -> Result<Figures, Error> {
        self.validate()?;
        let len = self.len();
        let scale = self.timer.ticks_per_second();
        let mut quantizer = Quantizer::new(self);
        match (self.curve, self.discretization) {
            (Curve::Linear(l), Discretization::Index) if self.arithmetic == Arithmetic::Integer => {
                // The article's integer division is the rounding; the exact
                // value is the same ratio before truncation.
                let t = self.timer;
                let int = IntegerLinear::new(&l, len, t.ticks_per_step, t.timer_hz)?;
                for k in 0..len {
                    let exact = scale / int.freq(k) as f64;
                    sink(k, quantizer.push_exact(k, int.reload(k), exact)?);
                }
            }
            (_, Discretization::Index) => {
                let mut k = 0;
                let mut failed = None;
                self.exact_index_entries(|entry| {
                    if failed.is_none() {
                        match quantizer.push(k, entry, None) {
                            Ok(ticks) => sink(k, ticks),
                            Err(e) => failed = Some(e),
                        }
                        k += 1;
                    }
                })?;
                if let Some(e) = failed {
                    return Err(e);
                }
            }
            (curve, discretization) => {
                let model = TimeModel::new(&curve);
                let c = model.curve();
                quantizer.reachable(c.freq(0.0), c.end_freq())?;
                let mut t = 0.0;
                for k in 0..len {
                    let next = edge_time(c, k + 1)?;
                    let ticks = match discretization {
                        Discretization::LeftEndpoint => {
                            quantizer.push(k, scale / c.freq(t), None)?
                        }
                        _ => quantizer.push(k, (next - t) * scale, Some(next * scale))?,
                    };
                    sink(k, ticks);
                    t = next;
                }
            }
        }
        Ok(quantizer.finish())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::Sigmoid;

    fn orange() -> Spec {
        Spec::new(
            Curve::Sigmoid(Sigmoid {
                fmin: 500.0,
                fmax: 64_000.0,
                flexible: 8.0,
                len: 1000,
            }),
            Timer::new(10_000_000),
        )
    }

    #[test]
    fn seed_orange_in_compatibility_mode() {
        let spec = orange()
            .with_discretization(Discretization::Index)
            .with_rounding(Rounding::Truncate)
            .with_arithmetic(Arithmetic::F32);
        let fig = spec.figures().unwrap();
        assert_eq!((fig.first_ticks, fig.last_ticks), (19183, 156));
        // The seed says "about 1 s"; the table plays in 0.412 s.
        assert!(
            (fig.duration_s - 0.412).abs() < 0.0005,
            "{}",
            fig.duration_s
        );
        // Truncation drifts about -500 ticks over the ramp.
        assert!(fig.total_error_ticks < -400.0 && fig.total_error_ticks > -600.0);
    }

    #[test]
    fn default_mode_edges_within_half_a_tick() {
        let fig = orange().figures().unwrap();
        assert!(
            fig.max_edge_error_ticks <= 0.5,
            "{}",
            fig.max_edge_error_ticks
        );
        // The exact total is len / mean frequency.
        let exact = 1e7 * 1000.0 / 32_250.0;
        assert!((fig.total_ticks as f64 - exact).abs() <= 0.5);
    }

    #[test]
    fn overflow_names_the_entry_and_the_lowest_frequency() {
        let spec = Spec::new(
            Curve::Sigmoid(Sigmoid {
                fmin: 100.0,
                fmax: 1000.0,
                flexible: 4.0,
                len: 100,
            }),
            Timer::new(10_000_000),
        )
        .with_discretization(Discretization::Index);
        let err = spec.figures().unwrap_err();
        let Error::PeriodOverflow {
            index, lowest_hz, ..
        } = err
        else {
            panic!("{err:?}")
        };
        assert_eq!(index, 0);
        assert!((lowest_hz - 152.59).abs() < 0.005);
    }

    #[test]
    fn buffer_must_match_len_and_word() {
        let mut short = [0u16; 10];
        assert_eq!(
            orange().generate(&mut short),
            Err(Error::BufferLength {
                expected: 1000,
                got: 10
            })
        );
        let mut wide = [0u32; 1000];
        assert_eq!(
            orange().generate(&mut wide),
            Err(Error::WordMismatch {
                expected: Word::U16,
                got: Word::U32
            })
        );
    }
}
