//! Computed tables, for hosts: a table in its layout, held with its spec
//! and figures (`Table`, `SegmentTable`, `RunTable` in `Generated`).

use std::vec::Vec;

use profile_core::runs::Expand;
use profile_core::{CheckedSpec, CompactFigures, Error, Figures, Spec};

use super::compress::{self, RunTable};

/// A generated table with its spec and figures.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// What the table was computed from.
    pub spec: Spec,
    /// The periods, in ticks; each fits `spec.timer.word`, and so does each
    /// plus `spec.reload_offset` ([`Table::stored_periods`]).
    pub periods: Vec<u32>,
    /// What the table amounts to.
    pub figures: Figures,
}

impl Table {
    /// The entries as the table stores them: each period plus
    /// [`reload_offset`](Spec::reload_offset).
    pub fn stored_periods(&self) -> Vec<u32> {
        self.periods.iter().map(|&p| self.spec.stored(p)).collect()
    }
}

/// A generated segment table (the exponential-ramp article's layout) with
/// its spec and figures.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct SegmentTable {
    /// What the table was computed from.
    pub spec: Spec,
    /// `(period, step count)` per segment, in ticks and steps, without
    /// `spec.reload_offset` ([`SegmentTable::stored_pairs`]).
    pub pairs: Vec<(u32, u32)>,
    /// What the table amounts to.
    pub figures: CompactFigures,
}

impl SegmentTable {
    /// The segments as the table stores them: each period plus
    /// [`reload_offset`](Spec::reload_offset), the counts as they are.
    pub fn stored_pairs(&self) -> Vec<(u32, u32)> {
        self.pairs
            .iter()
            .map(|&(p, c)| (self.spec.stored(p), c))
            .collect()
    }
}

/// A generated table in one of its layouts.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum Generated {
    /// One period per step.
    Steps(Table),
    /// Equal-time segments of `(period, count)`.
    Segments(SegmentTable),
    /// Runs of fixed-point periods, each edge within `compress` ticks.
    Runs(RunTable),
}

/// `(period, count)` segments as one period per step: the one place a
/// segment table is expanded.
pub(crate) fn expand(pairs: &[(u32, u32)]) -> Vec<u32> {
    pairs
        .iter()
        .flat_map(|&(p, c)| core::iter::repeat_n(p, c as usize))
        .collect()
}

impl Generated {
    /// One period per step: the table itself, or the segments expanded.
    pub fn step_periods(&self) -> Vec<u32> {
        match self {
            Generated::Steps(t) => t.periods.clone(),
            Generated::Segments(t) => expand(&t.pairs),
            Generated::Runs(t) => Expand::new(&t.runs).collect(),
        }
    }

    /// The figures of a compact layout (segments, runs); `None` for one
    /// entry per step.
    pub fn compact(&self) -> Option<CompactFigures> {
        match self {
            Generated::Steps(_) => None,
            Generated::Segments(t) => Some(t.figures),
            Generated::Runs(t) => Some(t.figures),
        }
    }

    /// The spec the table was computed from.
    pub fn spec(&self) -> &Spec {
        match self {
            Generated::Steps(t) => &t.spec,
            Generated::Segments(t) => &t.spec,
            Generated::Runs(t) => &t.spec,
        }
    }
}

/// A spec's tables on the heap: per step, in equal-time segments, or
/// compressed into runs. For a [`CheckedSpec`] and for a [`Spec`], which is
/// checked first.
///
/// ```
/// use profile_codegen::SpecTables;
/// use profile_core::{Curve, Linear, LinearExtent, Spec, Timer};
///
/// let spec = Spec::new(
///     Curve::Linear(Linear { fmin: 500.0, fmax: 20_000.0, extent: LinearExtent::Len(200) }),
///     Timer::new(1_000_000),
/// );
/// assert_eq!(spec.table()?.periods.len(), 200);
/// assert_eq!(spec.segment_table(8)?.pairs.len(), 8);
/// # Ok::<(), profile_core::Error>(())
/// ```
pub trait SpecTables {
    /// Computes the table into a new vector.
    fn table(&self) -> Result<Table, Error>;

    /// Computes the ramp as `segments` equal-time segments into a new
    /// vector.
    fn segment_table(&self, segments: u32) -> Result<SegmentTable, Error>;

    /// Checks that the table can be compressed with step edges within
    /// `tolerance` timer ticks: from half a tick (a whole tick with
    /// `ticks_per_step = 2`) to [`MAX_COMPRESS_TICKS`](crate::MAX_COMPRESS_TICKS),
    /// 16-bit periods, `exact` or `index` discretization, diffuse rounding.
    fn check_compress(&self, tolerance: f64) -> Result<(), Error>;

    /// Fits runs to the curve's exact edges, each played step edge within
    /// `tolerance` timer ticks of its exact time, and no period shorter than
    /// the curve's shortest, rounded down.
    ///
    /// The runs stand for the per-step table of the same spec and hold the
    /// same 16-bit periods: a period that table refuses (longer than the
    /// word holds, or rounding to 0 ticks) is refused here first, at its
    /// step, before any run is fitted. A period the runs play that
    /// [`reload_offset`](Spec::reload_offset) takes out of the word is
    /// refused at its step; the runs are those of the periods
    /// ([`RunTable::stored_runs`] adds the offset).
    fn run_table(&self, tolerance: f64) -> Result<RunTable, Error>;
}

impl SpecTables for CheckedSpec {
    fn table(&self) -> Result<Table, Error> {
        let mut periods = Vec::with_capacity(self.len() as usize);
        let figures = self.for_each_period(|_, ticks| periods.push(ticks))?;
        Ok(Table {
            spec: *self.spec(),
            periods,
            figures,
        })
    }

    fn segment_table(&self, segments: u32) -> Result<SegmentTable, Error> {
        self.check_segments(segments)?;
        let mut pairs = Vec::with_capacity(segments as usize);
        let figures =
            self.for_each_segment(segments, |_, period, count| pairs.push((period, count)))?;
        Ok(SegmentTable {
            spec: *self.spec(),
            pairs,
            figures,
        })
    }

    fn check_compress(&self, tolerance: f64) -> Result<(), Error> {
        compress::check_compress(self, tolerance)
    }

    fn run_table(&self, tolerance: f64) -> Result<RunTable, Error> {
        compress::run_table(self, tolerance)
    }
}

impl SpecTables for Spec {
    fn table(&self) -> Result<Table, Error> {
        self.check()?.table()
    }

    fn segment_table(&self, segments: u32) -> Result<SegmentTable, Error> {
        self.check()?.segment_table(segments)
    }

    fn check_compress(&self, tolerance: f64) -> Result<(), Error> {
        self.check()?.check_compress(tolerance)
    }

    fn run_table(&self, tolerance: f64) -> Result<RunTable, Error> {
        self.check()?.run_table(tolerance)
    }
}
