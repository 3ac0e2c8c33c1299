//! A ramp to play, and positions along it.

use crate::base::timer::TableWord;
use crate::player::ramps::runs::{Placed, RunList, RunState, place, place_beside, run_at};
use crate::table::runs::{
    Expand, FRACTION_MASK, IndexedRuns, LinearRun, RUN_FRACTION_BITS, RUN_START_FRACTION, RunIndex,
    ahead, behind, period as run_period,
};

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
    /// A compressed table (`compress = E`): runs of fixed-point periods,
    /// five words each (see [`runs`](crate::runs)), slowest first.
    Runs(&'a [[u16; 5]]),
    /// A compressed table with its index ([`RunIndex`]): played as
    /// [`Ramp::Runs`] plays its runs, any step of it found through the
    /// index (its bucket of steps, then a bisection over the few runs the
    /// bucket spans) instead of a walk over the runs when a move is
    /// planned.
    Indexed(IndexedRuns<'a>),
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

    /// A compressed table: the runs `period_table!(.., compress = E)` or a
    /// profile's `RUNS` holds. Played period for period as
    /// [`runs::Expand`](crate::runs::Expand) plays them.
    pub const fn runs(runs: &'a [[u16; 5]]) -> Self {
        Ramp::Runs(runs)
    }

    /// A compressed table and its index: a profile's `RUN_INDEX`, or
    /// `static INDEX: RunIndex<97> = RunIndex::new(&RUNS);` for 97 runs of
    /// your own.
    pub const fn indexed<const N: usize>(index: &'a RunIndex<N>) -> Self {
        Ramp::Indexed(index.indexed())
    }

    /// The periods of a per-step table played entry by entry, else `None`.
    #[inline]
    pub(crate) fn per_step(&self) -> Option<&'a [W]> {
        match *self {
            Ramp::Steps {
                periods,
                hold: 0..=1,
            } => Some(periods),
            _ => None,
        }
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
            Ramp::Runs(runs) => runs
                .iter()
                .fold(0u32, |n, r| n.saturating_add(u32::from(r[0]))),
            Ramp::Indexed(index) => index
                .runs()
                .last()
                .map_or(0, |r| r.step().saturating_add(u32::from(r.words()[0]))),
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
            Ramp::Runs(runs) => Expand::new(runs).min(),
            // Computed with the index.
            Ramp::Indexed(index) => Some(index.buckets().fastest),
        }
        .unwrap_or(0)
    }
}

/// A position along a ramp, kept as (entry, step within entry) so that
/// moving by one step needs no division.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Cursor {
    pub(crate) pos: u32,
    pub(crate) entry: u32,
    pub(crate) within: u32,
    /// On runs: the edges' sub-tick remainder before this step.
    pub(crate) frac: u32,
    /// On runs: this step's period, in fixed point.
    pub(crate) interval: u32,
}

impl Cursor {
    pub(crate) const ZERO: Cursor = Cursor {
        pos: 0,
        entry: 0,
        within: 0,
        frac: 0,
        interval: 0,
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
                ((entry as usize) < periods.len()).then_some(Cursor {
                    pos,
                    entry,
                    within,
                    ..Cursor::ZERO
                })
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
                            ..Cursor::ZERO
                        });
                    }
                    start = start.saturating_add(count);
                    if start > pos {
                        return None;
                    }
                }
                None
            }
            Ramp::Indexed(index) => Cursor::indexed(index, pos),
            Ramp::Runs(runs) => {
                // The remainder carried through every run before.
                let (mut start, mut frac) = (0u32, RUN_START_FRACTION);
                for (i, words) in runs.iter().enumerate() {
                    let run = LinearRun::decode(words);
                    let count = u32::from(run.count);
                    if pos - start < count {
                        let within = pos - start;
                        let (frac, interval) = ahead(frac, run.interval, run.add as u32, within);
                        return Some(Cursor {
                            pos,
                            entry: i as u32,
                            within,
                            frac,
                            interval,
                        });
                    }
                    frac = ahead(frac, run.interval, run.add as u32, count).0;
                    start = start.saturating_add(count);
                    if start > pos {
                        return None;
                    }
                }
                None
            }
        }
    }

    /// The cursor at step `pos` of an indexed ramp, placed by [`place`].
    fn indexed(index: IndexedRuns<'_>, pos: u32) -> Option<Cursor> {
        place(index, pos).map(|at| Cursor::placed(pos, at))
    }

    /// The cursor at step `pos`, placed there through the index.
    fn placed(pos: u32, at: Placed<'_>) -> Cursor {
        Cursor {
            pos,
            entry: at.entry,
            within: at.within,
            frac: at.frac,
            interval: at.interval,
        }
    }

    /// The cursor at `pos`: on runs moved there from `hint` (a cursor on
    /// the same ramp) when that is nearer than the ramp's start, a run at a
    /// time; else placed as [`Cursor::at`] places it.
    pub(crate) fn near<W: TableWord>(
        hint: Option<Cursor>,
        ramp: &Ramp<'_, W>,
        pos: u32,
    ) -> Option<Cursor> {
        match (hint, *ramp) {
            (Some(mut c), Ramp::Runs(runs)) if c.pos.abs_diff(pos) < pos => {
                c.seek_runs(runs, pos);
                // Past the last run: no step there.
                run_at(runs, c.entry).filter(|_| c.pos == pos)?;
                Some(c)
            }
            // Indexed: within the hint's run in closed form, else by the
            // index, the runs beside the hint's first (a stretch's cursor
            // stands at the run after the one it plays).
            (Some(mut c), Ramp::Indexed(index)) => {
                if pos >= c.pos - c.within
                    && run_at(index.runs(), c.entry)
                        .is_some_and(|r| pos - (c.pos - c.within) < u32::from(r.count))
                {
                    c.seek_runs(index.runs(), pos);
                    return Some(c);
                }
                match place_beside(index.runs(), pos, c.entry) {
                    Some(at) => Some(Cursor::placed(pos, at)),
                    None => Cursor::at(ramp, pos),
                }
            }
            _ => Cursor::at(ramp, pos),
        }
    }

    /// Moves the cursor to step `pos` of `runs` (which holds it), a run at a
    /// time: within a run in closed form ([`ahead`], [`behind`]), across runs
    /// by their ends, the remainder carried as [`Cursor::at`] carries it.
    pub(crate) fn seek_runs(&mut self, runs: impl RunList, pos: u32) {
        while self.pos < pos {
            let Some(run) = run_at(runs, self.entry) else {
                return;
            };
            let (count, add) = (u32::from(run.count), run.add as u32);
            let left = count.saturating_sub(self.within);
            if pos - self.pos < left {
                let n = pos - self.pos;
                (self.frac, self.interval) = ahead(self.frac, self.interval, add, n);
                (self.pos, self.within) = (pos, self.within + n);
                return;
            }
            self.frac = ahead(self.frac, self.interval, add, left).0;
            self.pos += left;
            self.enter_next_run(runs);
        }
        while self.pos > pos {
            let back = self.pos - pos;
            if back <= self.within {
                let add = run_at(runs, self.entry).map_or(0, |r| r.add as u32);
                (self.frac, self.interval) = behind(self.frac, self.interval, add, back);
                (self.pos, self.within) = (pos, self.within - back);
                return;
            }
            // To the run's first step, then to the last of the one before.
            let add = run_at(runs, self.entry).map_or(0, |r| r.add as u32);
            (self.frac, self.interval) = behind(self.frac, self.interval, add, self.within);
            self.pos -= self.within;
            self.within = 0;
            self.pos -= 1;
            self.run_backward(runs);
        }
    }

    /// The period under the cursor.
    pub(crate) fn period<W: TableWord>(&self, ramp: &Ramp<'_, W>) -> W {
        let found = match *ramp {
            Ramp::Steps { periods, .. } => periods.get(self.entry as usize).copied(),
            Ramp::Segments(pairs) => pairs.get(self.entry as usize).map(|p| p.0),
            Ramp::Runs(_) | Ramp::Indexed(_) => {
                Some(W::from_ticks(run_period(self.frac, self.interval)))
            }
        };
        found.unwrap_or(W::from_ticks(0))
    }

    /// One step towards the fast end, up to step `last`; `false` at `last`.
    pub(crate) fn forward<W: TableWord>(&mut self, ramp: &Ramp<'_, W>, last: u32) -> bool {
        if self.pos >= last {
            return false;
        }
        self.pos += 1;
        self.within += 1;
        match *ramp {
            Ramp::Runs(runs) => self.run_forward(runs),
            Ramp::Indexed(index) => self.run_forward(index.runs()),
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
        match *ramp {
            Ramp::Runs(runs) => self.run_backward(runs),
            Ramp::Indexed(index) => self.run_backward(index.runs()),
            _ => {
                if self.within > 0 {
                    self.within -= 1;
                } else {
                    self.enter_previous_entry(ramp);
                }
            }
        }
        true
    }

    /// [`Cursor::forward`] on runs, past the step's position and within.
    fn run_forward(&mut self, runs: impl RunList) {
        let run = run_at(runs, self.entry);
        let add = run.map_or(0, |r| r.add as u32);
        (self.frac, self.interval) = ahead(self.frac, self.interval, add, 1);
        if self.within >= run.map_or(u32::MAX, |r| u32::from(r.count)) {
            self.enter_next_run(runs);
        }
    }

    /// Back to the last step of the previous entry of a held or segment
    /// table that holds one.
    #[inline(always)]
    fn enter_previous_entry<W: TableWord>(&mut self, ramp: &Ramp<'_, W>) {
        match *ramp {
            Ramp::Steps { hold, .. } => {
                self.entry = self.entry.saturating_sub(1);
                self.within = hold.max(1) - 1;
            }
            Ramp::Runs(_) | Ramp::Indexed(_) => {}
            Ramp::Segments(pairs) => {
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
    }

    /// On to the first step of the next run that holds one, the remainder
    /// carried.
    fn enter_next_run(&mut self, runs: impl RunList) {
        self.within = 0;
        loop {
            self.entry += 1;
            match run_at(runs, self.entry) {
                Some(r) if r.count == 0 => continue,
                Some(r) => self.interval = r.interval,
                None => {}
            }
            break;
        }
    }

    /// One step back on runs: within the run, or to the last step of the
    /// previous run that holds one.
    fn run_backward(&mut self, runs: impl RunList) {
        if self.within > 0 {
            self.within -= 1;
            let add = run_at(runs, self.entry).map_or(0, |r| r.add as u32);
            (self.frac, self.interval) = behind(self.frac, self.interval, add, 1);
            return;
        }
        while self.entry > 0 {
            self.entry -= 1;
            let Some(run) = run_at(runs, self.entry) else {
                break;
            };
            if run.count > 0 {
                let last = u32::from(run.count) - 1;
                self.within = last;
                self.interval = run.interval.wrapping_add(last.wrapping_mul(run.add as u32));
                self.frac = self.frac.wrapping_sub(self.interval) & FRACTION_MASK;
                break;
            }
        }
    }

    /// Hands out the entry under the cursor of a held or segment table to a
    /// stretch reading towards the fast end (`dir` 1), the slow end (-1) or
    /// held (0): its period and at most `limit` steps of it, and moves the
    /// cursor past them when the stretch goes on (past empty segments). At
    /// least one step when `limit` is not 0; `None` on a compressed table
    /// (see [`take_run`](Self::take_run)) or past the table's end.
    pub(crate) fn take_entry<'r, W: TableWord>(
        &mut self,
        ramp: &Ramp<'r, W>,
        dir: i8,
        limit: u32,
    ) -> Option<(&'r W, u32)> {
        let (period, size) = match *ramp {
            Ramp::Steps { periods, hold } => (periods.get(self.entry as usize)?, hold.max(1)),
            Ramp::Segments(pairs) => {
                let pair = pairs.get(self.entry as usize)?;
                (&pair.0, pair.1.into_ticks())
            }
            Ramp::Runs(_) | Ramp::Indexed(_) => return None,
        };
        let n = match dir {
            1 => size.saturating_sub(self.within).max(1).min(limit),
            -1 => (self.within + 1).min(limit),
            _ => limit,
        };
        if n < limit && dir == 1 {
            // On to the next entry that holds a step.
            self.pos += n;
            self.within = 0;
            self.entry += 1;
            if let Ramp::Segments(pairs) = *ramp {
                while pairs
                    .get(self.entry as usize)
                    .is_some_and(|p| p.1.into_ticks() == 0)
                {
                    self.entry += 1;
                }
            }
        } else if n < limit && dir == -1 {
            self.pos -= n;
            self.enter_previous_entry(ramp);
        }
        Some((period, n))
    }

    /// Hands out the run under the cursor to a stretch reading towards the
    /// fast end (`dir` 1), the slow end (-1) or held (0): at most `limit`
    /// steps of it, as the state the step path plays (the forward
    /// recurrence `x = frac + interval; period = x >> 16; frac = x &
    /// 0xFFFF; interval += add`), and moves the cursor past them when the
    /// stretch goes on. At least one step when `limit` is not 0. One
    /// decoding of the run, and of the next one when the cursor moves to it.
    ///
    /// Backwards, the periods are the ceiling differences of the reflected
    /// edges, which the same recurrence gives from the remainder's
    /// complement after this step, this step's interval and `-add`.
    pub(crate) fn take_run(&mut self, runs: impl RunList, dir: i8, limit: u32) -> RunState {
        let run = run_at(runs, self.entry);
        let add = run.map_or(0, |r| r.add as u32);
        let (frac, interval) = (self.frac, self.interval);
        match dir {
            1 => {
                let count = run.map_or(limit, |r| u32::from(r.count));
                let n = count.saturating_sub(self.within).max(1).min(limit);
                if n < limit {
                    self.pos += n;
                    self.frac = ahead(frac, interval, add, n).0;
                    self.enter_next_run(runs);
                }
                RunState {
                    left: n,
                    frac,
                    interval,
                    add,
                }
            }
            -1 => {
                let n = (self.within + 1).min(limit);
                if n < limit {
                    // To the run's first step, then the last step of the
                    // previous run that holds one.
                    self.pos -= n;
                    (self.frac, self.interval) = behind(frac, interval, add, self.within);
                    self.within = 0;
                    self.run_backward(runs);
                }
                let end = frac.wrapping_add(interval);
                RunState {
                    left: n,
                    frac: FRACTION_MASK.wrapping_sub(end) & FRACTION_MASK,
                    interval,
                    add: add.wrapping_neg(),
                }
            }
            _ => {
                // One period, again and again: no remainder, no change.
                let period = run_period(frac, interval);
                RunState {
                    left: limit,
                    frac: 0,
                    interval: period << RUN_FRACTION_BITS,
                    add: 0,
                }
            }
        }
    }
}

/// The period of entry `i` of a per-step table, in ticks; `None` past its
/// end.
#[inline(always)]
pub(crate) fn ticks_at<W: TableWord>(table: &[W], i: u32) -> Option<u32> {
    table.get(i as usize).map(|p| p.into_ticks())
}
