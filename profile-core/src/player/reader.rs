//! Reading a ramp's periods by position for the searches of a plan.

use super::ramp::{Cursor, Ramp, ticks_at};
use super::runs::run_holding;
use crate::base::timer::TableWord;
use crate::table::runs::{IndexedRun, RUN_FRACTION_BITS, ahead};

/// Reads an indexed ramp by position: the run read last kept, so that
/// reads within it are closed-form, and any other run found by bisection.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RunRead<'a> {
    runs: &'a [IndexedRun],
    /// The run read last: its first step, its count (0 before the first
    /// read), its remainder and interval at its first step, its change.
    first: u32,
    count: u32,
    frac: u32,
    interval: u32,
    add: u32,
}

impl<'a> RunRead<'a> {
    pub(crate) fn new(runs: &'a [IndexedRun]) -> Self {
        RunRead {
            runs,
            first: 0,
            count: 0,
            frac: 0,
            interval: 0,
            add: 0,
        }
    }

    /// The period at step `pos`, in ticks; `None` past the ramp's end.
    #[inline]
    pub(crate) fn ticks(&mut self, pos: u32) -> Option<u32> {
        let mut within = pos.wrapping_sub(self.first);
        if within >= self.count {
            let (_, run, decoded) = run_holding(self.runs, pos)?;
            *self = RunRead {
                runs: self.runs,
                first: run.step,
                count: u32::from(decoded.count),
                frac: u32::from(run.frac),
                interval: decoded.interval,
                add: decoded.add as u32,
            };
            within = pos - run.step;
        }
        let (frac, interval) = ahead(self.frac, self.interval, self.add, within);
        Some(frac.wrapping_add(interval) >> RUN_FRACTION_BITS)
    }
}

/// Reads a ramp's periods by position, in ticks, for the searches of a
/// plan: a per-step table directly; any other ramp through a cursor moved
/// from read to read (on runs a whole run at a time, so that reads near
/// each other cost the runs between them, not the runs from the start).
/// Chosen once per search, so that a read of a per-step table is a bounds
/// check and a load.
pub(crate) enum Reader<'r, 'a, W> {
    /// A per-step table, each entry played once.
    Table(&'a [W]),
    /// An indexed compressed ramp, and the run read last.
    Indexed(RunRead<'a>),
    /// Any other ramp, and the cursor of the last read.
    Seek(&'r Ramp<'a, W>, Option<Cursor>),
}

impl<'r, 'a, W: TableWord> Reader<'r, 'a, W> {
    /// A reader of `ramp`, its first read sought from `hint` when that is
    /// nearer than the ramp's start.
    pub(crate) fn new(ramp: &'r Ramp<'a, W>, hint: Option<Cursor>) -> Self {
        match (ramp.per_step(), *ramp) {
            (Some(periods), _) => Reader::Table(periods),
            (None, Ramp::Indexed(index)) => Reader::Indexed(RunRead::new(index.runs())),
            (None, _) => Reader::Seek(ramp, hint),
        }
    }

    /// The period at step `pos`, in ticks; `None` past the ramp's end.
    #[inline]
    pub(crate) fn ticks(&mut self, pos: u32) -> Option<u32> {
        match self {
            Reader::Table(periods) => ticks_at(periods, pos),
            Reader::Indexed(run) => run.ticks(pos),
            Reader::Seek(ramp, cursor) => {
                let c = Cursor::near(*cursor, ramp, pos)?;
                *cursor = Some(c);
                Some(c.period(ramp).into_ticks())
            }
        }
    }
}
