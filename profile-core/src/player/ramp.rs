//! A ramp to play, and positions along it.

use crate::base::timer::TableWord;

/// A ramp to play: a table ordered from slow (rest) to fast.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ramp<'a, W> {
    /// One period per table entry, each held for `hold` steps (the S-curve
    /// article's `CountForAcc` divider; 1 plays every entry once).
    Steps {
        /// Periods in ticks, slowest first.
        periods: &'a [W],
        /// Steps per entry; 0 is taken as 1.
        hold: u32,
    },
    /// The exponential-ramp article's layout: `(period, steps)` per segment,
    /// slowest first.
    Segments(&'a [(W, W)]),
}

impl<'a, W: TableWord> Ramp<'a, W> {
    /// A per-step table, each entry played once.
    pub const fn steps(periods: &'a [W]) -> Self {
        Ramp::Steps { periods, hold: 1 }
    }

    /// A per-step table, each entry held for `hold` steps.
    pub const fn held(periods: &'a [W], hold: u32) -> Self {
        Ramp::Steps { periods, hold }
    }

    /// A segment table.
    pub const fn segments(pairs: &'a [(W, W)]) -> Self {
        Ramp::Segments(pairs)
    }

    /// Steps the ramp takes from rest to its top speed.
    pub fn len_steps(&self) -> u32 {
        match *self {
            Ramp::Steps { periods, hold } => {
                (periods.len() as u64 * hold.max(1) as u64).min(u32::MAX as u64) as u32
            }
            Ramp::Segments(pairs) => pairs
                .iter()
                .fold(0u32, |n, &(_, c)| n.saturating_add(c.into_ticks())),
        }
    }

    /// Period of the step at `pos` along the ramp (0 = slowest).
    pub fn period_at(&self, pos: u32) -> Option<W> {
        let c = Cursor::at(self, pos)?;
        Some(c.period(self))
    }

    /// The shortest period of the ramp.
    pub(crate) fn fastest(&self) -> u32 {
        match *self {
            Ramp::Steps { periods, .. } => periods.iter().map(|p| p.into_ticks()).min(),
            Ramp::Segments(pairs) => pairs
                .iter()
                .filter(|p| p.1.into_ticks() > 0)
                .map(|p| p.0.into_ticks())
                .min(),
        }
        .unwrap_or(0)
    }

    /// The first step whose period is shorter than `ticks`, or `u32::MAX`.
    pub(crate) fn first_faster_than(&self, ticks: u32) -> u32 {
        let Some(mut c) = Cursor::at(self, 0) else {
            return u32::MAX;
        };
        let last = self.len_steps().saturating_sub(1);
        loop {
            if c.period(self).into_ticks() < ticks {
                return c.pos;
            }
            if !c.forward(self, last) {
                return u32::MAX;
            }
        }
    }
}

/// A position along a ramp, kept as (entry, step within entry) so that
/// moving by one step needs no division.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Cursor {
    pub(crate) pos: u32,
    pub(crate) entry: u32,
    pub(crate) within: u32,
}

impl Cursor {
    pub(crate) const ZERO: Cursor = Cursor {
        pos: 0,
        entry: 0,
        within: 0,
    };

    /// The cursor at step `pos`, or `None` past the end or on an empty ramp.
    pub(crate) fn at<W: TableWord>(ramp: &Ramp<'_, W>, pos: u32) -> Option<Cursor> {
        match *ramp {
            Ramp::Steps { periods, hold } => {
                // No division for a table played entry by entry.
                let (entry, within) = if hold <= 1 {
                    (pos, 0)
                } else {
                    (pos / hold, pos % hold)
                };
                ((entry as usize) < periods.len()).then_some(Cursor { pos, entry, within })
            }
            Ramp::Segments(pairs) => {
                let mut start = 0u32;
                for (i, &(_, count)) in pairs.iter().enumerate() {
                    let count = count.into_ticks();
                    if pos - start < count {
                        return Some(Cursor {
                            pos,
                            entry: i as u32,
                            within: pos - start,
                        });
                    }
                    start = start.saturating_add(count);
                    if start > pos {
                        return None;
                    }
                }
                None
            }
        }
    }

    /// The period under the cursor.
    pub(crate) fn period<W: TableWord>(&self, ramp: &Ramp<'_, W>) -> W {
        let found = match *ramp {
            Ramp::Steps { periods, .. } => periods.get(self.entry as usize).copied(),
            Ramp::Segments(pairs) => pairs.get(self.entry as usize).map(|p| p.0),
        };
        found.unwrap_or(W::from_ticks(0))
    }

    /// Steps left in the cursor's entry, this one included, towards the
    /// fast end (`forward`) or the slow end.
    pub(crate) fn left_in_entry<W: TableWord>(&self, ramp: &Ramp<'_, W>, forward: bool) -> u32 {
        if !forward {
            return self.within + 1;
        }
        let size = match *ramp {
            Ramp::Steps { hold, .. } => hold.max(1),
            Ramp::Segments(pairs) => pairs
                .get(self.entry as usize)
                .map_or(0, |p| p.1.into_ticks()),
        };
        size - self.within
    }

    /// One step towards the fast end, up to step `last`; `false` at `last`.
    pub(crate) fn forward<W: TableWord>(&mut self, ramp: &Ramp<'_, W>, last: u32) -> bool {
        if self.pos >= last {
            return false;
        }
        self.pos += 1;
        self.within += 1;
        match *ramp {
            Ramp::Steps { hold, .. } => {
                if self.within >= hold.max(1) {
                    self.within = 0;
                    self.entry += 1;
                }
            }
            Ramp::Segments(pairs) => {
                // Past empty segments to the next that holds a step.
                while self.within
                    >= pairs
                        .get(self.entry as usize)
                        .map_or(u32::MAX, |p| p.1.into_ticks())
                {
                    self.within = 0;
                    self.entry += 1;
                }
            }
        }
        true
    }

    /// One step towards the slow end; `false` at step 0.
    pub(crate) fn backward<W: TableWord>(&mut self, ramp: &Ramp<'_, W>) -> bool {
        if self.pos == 0 {
            return false;
        }
        self.pos -= 1;
        if self.within > 0 {
            self.within -= 1;
            return true;
        }
        match *ramp {
            Ramp::Steps { hold, .. } => {
                self.entry = self.entry.saturating_sub(1);
                self.within = hold.max(1) - 1;
            }
            Ramp::Segments(pairs) => {
                // The previous segment that holds a step.
                while self.entry > 0 {
                    self.entry -= 1;
                    let count = pairs
                        .get(self.entry as usize)
                        .map_or(0, |p| p.1.into_ticks());
                    if count > 0 {
                        self.within = count - 1;
                        break;
                    }
                }
            }
        }
        true
    }
}
