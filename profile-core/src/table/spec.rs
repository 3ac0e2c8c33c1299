//! The description of a table (curve, timer, modes) and its checked form.

use crate::base::MAX_LEN;
use crate::base::error::Error;
use crate::base::key::Key;
use crate::base::modes::{Arithmetic, Discretization, Rounding};
use crate::base::timer::{Timer, Word};
use crate::curves::{CURVE_SCHEMAS, Curve, Length, Modes};

/// What `discretization = index` applies to, as messages say it: the curves
/// whose schema says `INDEX` (a test keeps the two in step).
pub(crate) const INDEX_APPLIES: &str =
    "to `curve = sigmoid` and `curve = linear`, which are defined over the step index";

/// Everything needed to compute one period table.
///
/// Build one with [`Spec::new`] and the `with_*` methods, then call
/// [`Spec::generate`] (into a buffer) or [`Spec::validate`].
///
/// ```
/// use profile_core::{Curve, Sigmoid, Spec, Timer};
///
/// let spec = Spec::new(
///     Curve::Sigmoid(Sigmoid { fmin: 500.0, fmax: 64_000.0, flexible: 8.0, len: 1000 }),
///     Timer::new(10_000_000),
/// );
/// let mut table = [0u16; 1000];
/// let figures = spec.generate(&mut table).unwrap();
/// assert_eq!(figures.len, 1000);
/// assert!(table[0] > table[999]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub struct Spec {
    /// The curve and its parameters.
    pub curve: Curve,
    /// The timer the table is for.
    pub timer: Timer,
    /// Curve to entries.
    pub discretization: Discretization,
    /// Fractional ticks to integers.
    pub rounding: Rounding,
    /// Floating-point arithmetic.
    pub arithmetic: Arithmetic,
    /// Added to every period the table stores (`reload_offset`): -1 for a
    /// reload register that holds the period less one (STM32's `ARR`,
    /// SysTick's `RVR`, AVR's `OCRnA` in CTC mode), so that the table can be
    /// copied to it as it is, by DMA. The figures stay those of the periods.
    pub reload_offset: i32,
}

impl Spec {
    /// A spec with the default discretization (`exact`), rounding (`diffuse`)
    /// and arithmetic (`f64`).
    pub const fn new(curve: Curve, timer: Timer) -> Self {
        Spec {
            curve,
            timer,
            discretization: Discretization::Exact,
            rounding: Rounding::Diffuse,
            arithmetic: Arithmetic::F64,
            reload_offset: 0,
        }
    }

    /// The same spec storing every period plus `offset` ticks
    /// (`reload_offset`): `-1` for a register that holds the period less
    /// one. [`generate`](Spec::generate) then writes the stored values and
    /// returns the figures of the periods.
    ///
    /// ```
    /// use profile_core::{Curve, Sigmoid, Spec, Timer};
    ///
    /// let curve = Curve::Sigmoid(Sigmoid { fmin: 500.0, fmax: 2000.0, flexible: 4.0, len: 8 });
    /// let spec = Spec::new(curve, Timer::new(1_000_000));
    /// let (mut periods, mut arr) = ([0u16; 8], [0u16; 8]);
    /// let figures = spec.generate(&mut periods)?;
    /// let same = spec.with_reload_offset(-1).generate(&mut arr)?;
    /// assert!(periods.iter().zip(&arr).all(|(p, r)| *r == *p - 1));
    /// assert_eq!(figures, same);
    /// # Ok::<(), profile_core::Error>(())
    /// ```
    pub const fn with_reload_offset(mut self, offset: i32) -> Self {
        self.reload_offset = offset;
        self
    }

    /// What the table stores for a period of `ticks`: `ticks` plus
    /// [`reload_offset`](Spec::reload_offset), wrapping (checked when the
    /// table is computed).
    pub const fn stored(&self, ticks: u32) -> u32 {
        ticks.wrapping_add_signed(self.reload_offset)
    }

    /// The same spec with another discretization.
    pub const fn with_discretization(mut self, discretization: Discretization) -> Self {
        self.discretization = discretization;
        self
    }

    /// The same spec with another rounding.
    pub const fn with_rounding(mut self, rounding: Rounding) -> Self {
        self.rounding = rounding;
        self
    }

    /// The same spec with another arithmetic.
    pub const fn with_arithmetic(mut self, arithmetic: Arithmetic) -> Self {
        self.arithmetic = arithmetic;
        self
    }

    /// The same spec with another table word.
    pub const fn with_word(mut self, word: Word) -> Self {
        self.timer.word = word;
        self
    }

    /// The same spec with another number of timer reloads per step.
    pub const fn with_ticks_per_step(mut self, ticks_per_step: u8) -> Self {
        self.timer.ticks_per_step = ticks_per_step;
        self
    }

    /// The number of entries the table has: `len` where given, otherwise the
    /// steps until the curve reaches `fmax`, rounded up (the final fraction of
    /// a step is taken at `fmax`). 0 for an invalid spec.
    pub fn len(&self) -> u32 {
        self.curve
            .length(self.discretization == Discretization::Index)
            .entries()
    }

    /// `true` when the table has no entries (never for a valid spec).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Checks every parameter and combination without computing the table.
    ///
    /// A period that does not fit the word is found only when the table is
    /// computed.
    pub fn validate(&self) -> Result<(), Error> {
        self.check().map(|_| ())
    }

    /// Checks the spec once and returns it in the form that computes tables:
    /// every parameter, the length, the timer and the combination of modes.
    pub fn check(&self) -> Result<CheckedSpec, Error> {
        let index = self.discretization == Discretization::Index;
        self.curve.check(index)?;
        let len = self.len();
        if let Length::Derived { steps, key, .. } = self.curve.length(index) {
            if !(steps.is_finite() && steps > 0.0 && steps <= MAX_LEN as f64) || len > MAX_LEN {
                return Err(Error::RampTooLong {
                    key,
                    steps,
                    max: MAX_LEN,
                });
            }
        }
        if self.timer.timer_hz == 0 {
            return Err(Error::TimerZero);
        }
        if !matches!(self.timer.ticks_per_step, 1 | 2) {
            return Err(Error::TicksPerStep {
                value: self.timer.ticks_per_step as u64,
            });
        }
        let max = self.timer.word.max() - 1;
        if self.reload_offset.unsigned_abs() > max {
            return Err(Error::ReloadOffsetRange {
                offset: self.reload_offset,
                word: self.timer.word,
            });
        }
        let schema = self.curve.schema();
        if index && !schema.index {
            return Err(Error::Unsupported {
                key: Key::DISCRETIZATION,
                value: "index",
                applies: INDEX_APPLIES,
            });
        }
        if self.arithmetic != Arithmetic::F64
            && !schema.arithmetic.iter().any(|(a, _)| *a == self.arithmetic)
        {
            let owner = CURVE_SCHEMAS
                .iter()
                .flat_map(|r| r.arithmetic)
                .find(|(a, _)| *a == self.arithmetic);
            return Err(Error::Unsupported {
                key: Key::ARITHMETIC,
                value: self.arithmetic.name(),
                applies: owner.map_or("", |(_, applies)| applies),
            });
        }
        let checked = CheckedSpec { spec: *self, len };
        self.curve.check_modes(&checked.modes())?;
        Ok(checked)
    }
}

/// A spec whose every parameter and combination has been checked: the only
/// form that computes tables. Made by [`Spec::check`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CheckedSpec {
    spec: Spec,
    len: u32,
}

impl CheckedSpec {
    /// The spec.
    pub fn spec(&self) -> &Spec {
        &self.spec
    }

    /// Entries of the table, from 1 to [`MAX_LEN`].
    pub fn len(&self) -> u32 {
        self.len
    }

    /// Never: a checked spec has at least one entry.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The word of the table's entries.
    pub fn word(&self) -> Word {
        self.spec.timer.word
    }

    pub(crate) fn modes(&self) -> Modes {
        Modes {
            discretization: self.spec.discretization,
            rounding: self.spec.rounding,
            arithmetic: self.spec.arithmetic,
            timer: self.spec.timer,
            len: self.len,
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// The message for `discretization = index` names the curves whose schema
    /// is defined over the index.
    #[test]
    fn index_message_names_the_index_curves() {
        let named: std::vec::Vec<_> = CURVE_SCHEMAS
            .iter()
            .filter(|r| r.index)
            .map(|r| std::format!("`curve = {}`", r.name))
            .collect();
        assert_eq!(
            INDEX_APPLIES,
            std::format!(
                "to {}, which are defined over the step index",
                named.join(" and ")
            )
        );
    }
}
