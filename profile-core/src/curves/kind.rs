//! The contract of a curve's module, and what it deals in.

use crate::base::error::Error;
use crate::base::key::Key;
use crate::base::modes::{Arithmetic, Discretization, Rounding};
use crate::base::solve::TimeCurve;
use crate::base::timer::Timer;

/// How long a ramp is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Length {
    /// `len` entries, as given.
    Given(u32),
    /// The steps the curve takes to reach `fmax` (a real number), set by
    /// `key`, and `extra` entries after them (one at `fmax` over the index
    /// of a linear ramp).
    Derived { steps: f64, key: Key, extra: u32 },
}

impl Length {
    /// Entries of the table: `len`, or the steps rounded up plus `extra`.
    /// Rounding forgives a relative 1e-9, so a ramp of 120.000000001 steps
    /// is 120 entries. 0 for a non-finite or non-positive count.
    pub(crate) fn entries(self) -> u32 {
        let (steps, extra) = match self {
            Length::Given(len) => return len,
            Length::Derived { steps, extra, .. } => (steps, extra),
        };
        if !(steps.is_finite() && steps > 0.0) {
            return 0;
        }
        let whole = libm::ceil(steps - 1e-9 * steps.max(1.0)).max(1.0) + extra as f64;
        if whole > u32::MAX as f64 {
            u32::MAX
        } else {
            whole as u32
        }
    }
}

/// What a curve's own checks may depend on besides its parameters.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Modes {
    pub(crate) discretization: Discretization,
    pub(crate) rounding: Rounding,
    pub(crate) arithmetic: Arithmetic,
    pub(crate) timer: Timer,
    /// Entries of the table.
    pub(crate) len: u32,
}

impl Modes {
    /// [`Timer::frequency_scale`](crate::Timer::frequency_scale).
    pub(crate) fn scale(&self) -> f64 {
        self.timer.frequency_scale()
    }
}

/// An entry over the step index, in ticks: its unrounded value and, where
/// the curve's arithmetic rounds by itself (an article's integer code), the
/// rounded one.
#[derive(Clone, Copy, Debug)]
pub(crate) struct IndexEntry {
    pub(crate) exact: Unrounded,
    pub(crate) rounded: Option<u64>,
}

/// An entry's unrounded length in ticks, or what it is computed from where
/// the curve rounds by itself (the division costs thousands of
/// instructions where `f64` is software, and only the figures need it).
#[derive(Clone, Copy, Debug)]
pub(crate) enum Unrounded {
    Ticks(f64),
    /// `scale / freq`.
    Over {
        scale: f64,
        freq: f32,
    },
}

impl IndexEntry {
    /// An entry the quantizer rounds, `ticks` long.
    pub(crate) fn exact(ticks: f64) -> Self {
        IndexEntry {
            exact: Unrounded::Ticks(ticks),
            rounded: None,
        }
    }

    /// The unrounded length in ticks.
    pub(crate) fn ticks(&self) -> f64 {
        match self.exact {
            Unrounded::Ticks(ticks) => ticks,
            Unrounded::Over { scale, freq } => scale / freq as f64,
        }
    }
}

/// What every curve provides: the contract of its module.
pub(crate) trait CurveKind: Copy {
    /// The name in `curve = NAME`.
    const NAME: &'static str;
    /// Arithmetic besides `f64` the curve computes in, each with where it
    /// applies, as messages say it.
    const ARITHMETIC: &'static [(Arithmetic, &'static str)] = &[];
    /// Whether the curve is defined over the step index (`discretization = index`).
    const INDEX: bool = false;
    /// The curve's model in time, for `exact` and `left_endpoint`.
    type Time: TimeCurve;

    /// The model in time of a checked curve.
    fn time(&self) -> Self::Time;
    /// The start and end frequencies, in Hz.
    fn frequencies(&self) -> (f64, f64);
    /// How long the ramp is, over the index or in time.
    fn length(&self, index: bool) -> Length;
    /// Checks the parameters, in the order messages should come.
    fn check(&self, index: bool) -> Result<(), Error>;
    /// Checks what the curve's own arithmetic needs, once the common keys
    /// and the combination of modes are known to be right.
    fn check_modes(&self, _modes: &Modes) -> Result<(), Error> {
        Ok(())
    }
    /// Calls `sink` with every entry over the step index (only called where
    /// [`CurveKind::INDEX`] holds).
    fn index_entries(
        &self,
        _modes: &Modes,
        _sink: &mut dyn FnMut(IndexEntry) -> Result<(), Error>,
    ) -> Result<(), Error> {
        Ok(())
    }
}

/// What the table's own checks know of a curve besides its parameters:
/// its name and the arithmetic and discretization it takes.
pub(crate) struct CurveSchema {
    pub(crate) name: &'static str,
    pub(crate) arithmetic: &'static [(Arithmetic, &'static str)],
    pub(crate) index: bool,
}
