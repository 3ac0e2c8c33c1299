//! Owned tables, for hosts.

use std::vec::Vec;

use crate::error::Error;
use crate::generate::Figures;
use crate::segments::SegmentFigures;
use crate::spec::Spec;

/// A generated table with its spec and figures.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// What the table was computed from.
    pub spec: Spec,
    /// The periods, in ticks; each fits `spec.timer.word`.
    pub periods: Vec<u32>,
    /// What the table amounts to.
    pub figures: Figures,
}

impl Spec {
    /// Computes the table into a new vector.
    pub fn table(&self) -> Result<Table, Error> {
        self.validate()?;
        let mut periods = Vec::with_capacity(self.len() as usize);
        let figures = self.for_each_period(|_, ticks| periods.push(ticks))?;
        Ok(Table {
            spec: *self,
            periods,
            figures,
        })
    }
}

/// A generated segment table (seed 001's layout) with its spec and figures.
#[derive(Clone, Debug, PartialEq)]
pub struct SegmentTable {
    /// What the table was computed from.
    pub spec: Spec,
    /// `(period, step count)` per segment, in ticks and steps.
    pub pairs: Vec<(u32, u32)>,
    /// What the table amounts to.
    pub figures: SegmentFigures,
}

impl Spec {
    /// Computes the ramp as `segments` equal-time segments into a new vector.
    pub fn segment_table(&self, segments: u32) -> Result<SegmentTable, Error> {
        self.check_segments(segments)?;
        let mut pairs = Vec::with_capacity(segments as usize);
        let figures =
            self.for_each_segment(segments, |_, period, count| pairs.push((period, count)))?;
        Ok(SegmentTable {
            spec: *self,
            pairs,
            figures,
        })
    }
}
