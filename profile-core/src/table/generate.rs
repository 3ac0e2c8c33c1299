//! From a checked spec to integer periods, one per step: exact times,
//! quantization, figures.

use crate::base::error::Error;
use crate::base::modes::{Discretization, Rounding};
use crate::base::solve::{EDGE_TOLERANCE_TICKS, Edges, edge_time};
use crate::base::timer::TableWord;
use crate::curves::{LinearEdges, TimeModel};
use crate::table::quantize::{Figures, Quantizer};
use crate::table::spec::{CheckedSpec, Spec};

impl CheckedSpec {
    /// Computes the table into `out` and returns its figures.
    ///
    /// `out` receives what the table stores: each period plus
    /// [`reload_offset`](Spec::reload_offset); the figures are the periods'.
    /// `out` must hold exactly [`len`](CheckedSpec::len) entries of the
    /// spec's word. No allocation, no panic: the same bits as `period_table!`
    /// on any target.
    pub fn generate<W: TableWord>(&self, out: &mut [W]) -> Result<Figures, Error> {
        self.check_buffer::<W>(out.len())?;
        let spec = self.spec();
        self.for_each_period(|index, ticks| {
            if let Some(slot) = out.get_mut(index as usize) {
                *slot = W::from_ticks(spec.stored(ticks));
            }
        })
    }

    /// A buffer of `len` words `W` for the table: the spec's word, its
    /// length.
    fn check_buffer<W: TableWord>(&self, len: usize) -> Result<(), Error> {
        if W::WORD != self.word() {
            return Err(Error::WordMismatch {
                expected: self.word(),
                got: W::WORD,
            });
        }
        if len != self.len() as usize {
            return Err(Error::BufferLength {
                expected: self.len(),
                got: len,
            });
        }
        Ok(())
    }

    /// Computes the table's figures without storing it.
    pub fn figures(&self) -> Result<Figures, Error> {
        self.for_each_period(|_, _| {})
    }

    /// Calls `sink(k, t)` with the exact time `t` (in s) of every pulse edge
    /// `k = 1..=len` of the continuous curve, before discretization: where
    /// `N(t) = k` for curves in time; for `discretization = index`, the
    /// running sum of the unrounded entries (the index curve has no other
    /// time). Measures how far any table strays from the curve.
    pub fn for_each_exact_edge<F: FnMut(u32, f64)>(&self, mut sink: F) -> Result<(), Error> {
        let spec = self.spec();
        if spec.discretization == Discretization::Index {
            let modes = self.modes();
            let scale = modes.scale();
            let (mut k, mut t) = (0, 0.0);
            // The f32 and integer modes keep their own arithmetic.
            return spec.curve.index_entries(&modes, &mut |entry| {
                k += 1;
                t += entry.ticks() / scale;
                sink(k, t);
                Ok(())
            });
        }
        let model = spec.curve.time_model();
        let mut edges = Edges::new(model.curve(), EDGE_TOLERANCE_TICKS / self.modes().scale());
        for k in 1..=self.len() {
            sink(k, edges.time(k)?);
        }
        Ok(())
    }

    /// Computes the table entry by entry, calling `sink(index, ticks)` for
    /// each period (without [`reload_offset`](Spec::reload_offset): add it
    /// with [`Spec::stored`]), and returns its figures. Stops at the first
    /// entry that does not fit, or that the offset takes out of the word.
    pub fn for_each_period<F: FnMut(u32, u32)>(&self, mut sink: F) -> Result<Figures, Error> {
        self.for_each_period_and_edge(|k, ticks, _| sink(k, ticks))
    }

    /// [`for_each_period`](Self::for_each_period), with the exact time (in
    /// s) of the entry's closing edge as
    /// [`for_each_exact_edge`](Self::for_each_exact_edge) gives it: one
    /// pass for both.
    pub fn for_each_period_and_edge<F: FnMut(u32, u32, f64)>(
        &self,
        sink: F,
    ) -> Result<Figures, Error> {
        self.quantize(Quantizer::new(self.spec()), true, sink)
    }

    /// Computes the table into `out`, as [`generate`](Self::generate)
    /// does, bit for bit, without its figures: what firmware that computes
    /// its ramps at run time needs, in a fraction of the time where `f64`
    /// is software (the figures' acceleration and jerk take a few divisions
    /// an entry; `docs/performance.md` gives both on three cores).
    pub fn generate_periods<W: TableWord>(&self, out: &mut [W]) -> Result<(), Error> {
        self.check_buffer::<W>(out.len())?;
        let spec = self.spec();
        self.quantize(
            Quantizer::new(spec).without_figures(),
            false,
            |index, ticks, _| {
                if let Some(slot) = out.get_mut(index as usize) {
                    *slot = W::from_ticks(spec.stored(ticks));
                }
            },
        )?;
        Ok(())
    }

    /// The table through `quantizer`, entry by entry to `sink` with the time
    /// of the entry's closing edge; over the index that time is a division
    /// an entry, summed only where `edges` asks for it (`sink` gets 0
    /// otherwise).
    fn quantize<F: FnMut(u32, u32, f64)>(
        &self,
        mut quantizer: Quantizer,
        edges_asked: bool,
        mut sink: F,
    ) -> Result<Figures, Error> {
        let spec = self.spec();
        let modes = self.modes();
        let scale = modes.scale();
        if spec.discretization == Discretization::Index {
            if quantizer.keeps_figures() {
                // The windows of the acceleration figure are bounded by the
                // ramp's duration: one pass over the entries.
                let mut duration = 0.0;
                spec.curve.index_entries(&modes, &mut |entry| {
                    duration += entry.ticks();
                    Ok(())
                })?;
                quantizer.set_duration(duration);
            }
            let (mut k, mut t) = (0, 0.0);
            spec.curve.index_entries(&modes, &mut |entry| {
                let ticks = match entry.rounded {
                    Some(ticks) => quantizer.push_rounded(k, ticks, || entry.ticks())?,
                    None => quantizer.push(k, entry.ticks(), None)?,
                };
                if edges_asked {
                    t += entry.ticks() / scale;
                }
                sink(k, ticks, t);
                k += 1;
                Ok(())
            })?;
            return Ok(quantizer.finish());
        }
        let model = spec.curve.time_model();
        let c = model.curve();
        quantizer.reachable(c.freq(0.0), c.end_freq())?;
        if quantizer.keeps_figures() {
            let duration = edge_time(c, self.len())?;
            quantizer.set_duration(duration * scale);
        }
        let mut edges = Edges::new(c, EDGE_TOLERANCE_TICKS / scale);
        // A linear ramp's edges proved rounded without solving them, where
        // only the periods are asked for.
        let mut proved = match (&model, spec.discretization, spec.rounding) {
            (TimeModel::Linear(l), Discretization::Exact, Rounding::Diffuse)
                if !quantizer.keeps_figures() && !edges_asked =>
            {
                Some(LinearEdges::new(l, scale))
            }
            _ => None,
        };
        let mut t = 0.0;
        for k in 0..self.len() {
            if let Some(fast) = proved.as_mut() {
                let pushed = fast
                    .edge(k + 1)
                    .and_then(|edge| quantizer.push_nearest_edge(k, edge));
                if let Some(ticks) = pushed {
                    sink(k, ticks, 0.0);
                    continue;
                }
            }
            let next = edges.time(k + 1)?;
            if let Some(fast) = proved.as_mut() {
                fast.solved(k + 1, libm::round(next * scale) as u64);
            }
            let ticks = match spec.discretization {
                Discretization::LeftEndpoint => quantizer.push(k, scale / c.freq(t), None)?,
                _ => quantizer.push(k, (next - t) * scale, Some(next * scale))?,
            };
            sink(k, ticks, next);
            t = next;
        }
        Ok(quantizer.finish())
    }
}

impl Spec {
    /// Checks the spec, computes the table into `out` and returns its figures
    /// ([`CheckedSpec::generate`]).
    ///
    /// ```
    /// use profile_core::{Curve, Discretization, Rounding, Arithmetic, Sigmoid, Spec, Timer};
    ///
    /// // The S-curve article's orange curve, as its C code computes it.
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
        self.check()?.generate(out)
    }

    /// Checks the spec and computes the table into `out` without its
    /// figures ([`CheckedSpec::generate_periods`]): the same bits as
    /// [`generate`](Self::generate).
    ///
    /// ```
    /// use profile_core::{Curve, Sigmoid, Spec, Timer};
    ///
    /// let spec = Spec::new(
    ///     Curve::Sigmoid(Sigmoid { fmin: 500.0, fmax: 64_000.0, flexible: 8.0, len: 1000 }),
    ///     Timer::new(10_000_000),
    /// );
    /// let (mut fast, mut full) = ([0u16; 1000], [0u16; 1000]);
    /// spec.generate_periods(&mut fast)?;
    /// spec.generate(&mut full)?;
    /// assert_eq!(fast, full);
    /// # Ok::<(), profile_core::Error>(())
    /// ```
    pub fn generate_periods<W: TableWord>(&self, out: &mut [W]) -> Result<(), Error> {
        self.check()?.generate_periods(out)
    }

    /// Checks the spec and computes the table's figures without storing it.
    pub fn figures(&self) -> Result<Figures, Error> {
        self.check()?.figures()
    }

    /// Checks the spec and calls `sink` with every exact pulse edge
    /// ([`CheckedSpec::for_each_exact_edge`]).
    pub fn for_each_exact_edge<F: FnMut(u32, f64)>(&self, sink: F) -> Result<(), Error> {
        self.check()?.for_each_exact_edge(sink)
    }

    /// Checks the spec and computes the table entry by entry
    /// ([`CheckedSpec::for_each_period`]).
    pub fn for_each_period<F: FnMut(u32, u32)>(&self, sink: F) -> Result<Figures, Error> {
        self.check()?.for_each_period(sink)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::modes::{Arithmetic, Rounding};
    use crate::base::timer::{Timer, Word};
    use crate::curves::{Curve, Sigmoid};

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

    /// The table of `spec` (`len` words `W`) by `generate` and by
    /// `generate_periods`: the same periods or the same error; `true` for
    /// a table.
    fn same<W: TableWord + Default + PartialEq + core::fmt::Debug>(spec: &Spec, len: u32) -> bool {
        let (mut a, mut b) = (
            std::vec![W::default(); len as usize],
            std::vec![W::default(); len as usize],
        );
        let whole = spec.generate(&mut a).map(|_| ());
        assert_eq!(spec.generate_periods(&mut b), whole, "{spec:?}");
        assert!(whole.is_err() || a == b, "{spec:?}");
        whole.is_ok()
    }

    /// `generate_periods` against `generate` on random linear ramps (whose
    /// edges it proves rather than solves) of both words, with and without
    /// a reload offset, the ramps out of the word's reach included: the
    /// same periods, or the same error.
    #[test]
    fn periods_alone_are_the_tables_periods() {
        use crate::{Linear, LinearExtent};
        let mut next = crate::base::xorshift(0x5EED_0F11_AE77_1234);
        let mut tables = 0;
        for case in 0..300 {
            let timer_hz = [1_000_000, 8_000_000, 10_000_000, 16_000_000, 72_000_000][case % 5];
            let word = if next() % 3 == 0 {
                Word::U32
            } else {
                Word::U16
            };
            // First periods of 50 to 70 000 ticks (some past a u16), up to
            // 2²² on a u32.
            let first = match word {
                Word::U16 => 50 + next() % 70_000,
                Word::U32 => 50 + next() % (1 << 22),
            };
            let fmin = f64::from(timer_hz) / first as f64;
            let fmax = fmin * (1.05 + (next() % 300) as f64 / 10.0);
            let len = 1 + (next() % 2000) as u32;
            let spec = Spec::new(
                Curve::Linear(Linear {
                    fmin,
                    fmax,
                    extent: LinearExtent::Len(len),
                }),
                Timer::new(timer_hz),
            )
            .with_word(word)
            .with_reload_offset((next() % 3) as i32);
            let whole = match word {
                Word::U16 => same::<u16>(&spec, len),
                Word::U32 => same::<u32>(&spec, len),
            };
            tables += u32::from(whole);
        }
        // Most are tables, some errors.
        assert!(tables > 200, "{tables} tables of 300");
    }

    #[test]
    fn each_edge_is_solved_from_the_one_before_in_a_few_evaluations() {
        use crate::base::solve::EVALUATIONS;
        EVALUATIONS.with(|n| n.set(0));
        orange().figures().unwrap();
        let per_edge = EVALUATIONS.with(|n| n.get()) as f64 / 999.0;
        assert!(per_edge < 1.3, "{per_edge} evaluations per edge");
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
