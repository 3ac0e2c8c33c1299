//! The runs of a compressed ramp as the player reads them, indexed
//! ([`RunIndex`](crate::runs::RunIndex): each run knows its first step and
//! the remainder carried into it, so that any step is found by a lookup
//! and a bisection over the few runs its bucket spans) or not, and where a
//! run being played stands.

use crate::table::runs::{
    FRACTION_MASK, IndexedRun, IndexedRuns, IndexedSteps, LinearRun, RUN_FRACTION_BITS, ahead,
};

/// The runs of a compressed ramp, plain words or indexed: the code that
/// reads them is made for each, so that neither pays for the other.
pub(crate) trait RunList: Copy {
    /// Run `index`, decoded; `None` past the last.
    fn run(self, index: u32) -> Option<LinearRun>;
}

impl RunList for &[[u16; 5]] {
    #[inline(always)]
    fn run(self, index: u32) -> Option<LinearRun> {
        self.get(index as usize).map(LinearRun::decode)
    }
}

impl RunList for &[IndexedRun] {
    #[inline(always)]
    fn run(self, index: u32) -> Option<LinearRun> {
        self.get(index as usize)
            .map(|r| LinearRun::decode(&r.words))
    }
}

/// Run `index` of `runs`, decoded.
#[inline(always)]
pub(crate) fn run_at(runs: impl RunList, index: u32) -> Option<LinearRun> {
    runs.run(index)
}

/// Step `pos` of a whole indexed ramp (its first run at step 0): the run
/// that holds it as [`run_holding`] finds it, but the slowest run and the
/// fastest (where a move starts and where it cruises) without a lookup;
/// the step within the run and the run's state there in closed form.
/// `None` past the ramp's end.
#[inline(always)]
pub(crate) fn place(index: IndexedRuns<'_>, pos: u32) -> Option<Placed<'_>> {
    let runs = index.runs();
    let (entry, run, decoded) = match runs {
        [_, next, ..] if pos < next.step => end_run(runs, 0, pos)?,
        [.., last] if last.step <= pos => end_run(runs, runs.len() - 1, pos)?,
        _ => run_holding(index, pos)?,
    };
    Some(placed(entry, run, decoded, pos))
}

/// Step `pos` if the run after run `near` or the one before holds it
/// (a step near one placed before), placed as [`place`] places it.
pub(crate) fn place_beside(runs: &[IndexedRun], pos: u32, near: u32) -> Option<Placed<'_>> {
    let near = near as usize;
    let (entry, run, decoded) = end_run(runs, near.wrapping_add(1), pos)
        .or_else(|| end_run(runs, near.wrapping_sub(1), pos))?;
    Some(placed(entry, run, decoded, pos))
}

/// Step `pos` of run `entry`, `run` (decoded), which holds it.
#[inline(always)]
fn placed(entry: u32, run: &IndexedRun, decoded: LinearRun, pos: u32) -> Placed<'_> {
    let within = pos - run.step;
    let (frac, interval) = ahead(
        u32::from(run.frac),
        decoded.interval,
        decoded.add as u32,
        within,
    );
    Placed {
        entry,
        run,
        decoded,
        within,
        frac,
        interval,
    }
}

/// Run `entry` of `runs`, decoded, if it holds step `pos` (its count, the
/// first word, read before the rest is decoded).
#[inline(always)]
pub(crate) fn end_run(
    runs: &[IndexedRun],
    entry: usize,
    pos: u32,
) -> Option<(u32, &IndexedRun, LinearRun)> {
    let run = runs.get(entry)?;
    let within = pos.checked_sub(run.step)?;
    (within < u32::from(run.words[0])).then(|| (entry as u32, run, LinearRun::decode(&run.words)))
}

/// A step of an indexed ramp ([`place`]): its run's index, the run and its
/// decoding, the step within the run, the remainder before it and its
/// interval.
pub(crate) struct Placed<'r> {
    pub(crate) entry: u32,
    pub(crate) run: &'r IndexedRun,
    pub(crate) decoded: LinearRun,
    pub(crate) within: u32,
    pub(crate) frac: u32,
    pub(crate) interval: u32,
}

/// The run of `index` that holds step `pos`, decoded, and its index;
/// `None` past the ramp's end. The last run that begins at or before `pos`
/// (a run of no steps begins where the next one does, so the one found
/// holds a step unless the ramp ends first): among the runs `pos`'s bucket
/// spans ([`Buckets::span`](crate::table::runs::Buckets::span)), by bisection over their first steps.
#[inline]
pub(crate) fn run_holding(
    index: IndexedRuns<'_>,
    pos: u32,
) -> Option<(u32, &IndexedRun, LinearRun)> {
    let runs = index.runs();
    let (lo, hi) = index.buckets().span(pos, runs.len());
    let within = runs.get(lo..hi)?.partition_point(|r| r.step <= pos);
    let entry = (lo + within).checked_sub(1)?;
    let run = runs.get(entry)?;
    let decoded = LinearRun::decode(&run.words);
    (pos - run.step < u32::from(decoded.count)).then_some((entry as u32, run, decoded))
}

/// The periods an indexed ramp plays, in ticks: each run played from its
/// own remainder, as the index gives it (not carried from the run before,
/// as [`Expand`](crate::runs::Expand) carries it).
pub(crate) fn periods(index: IndexedRuns<'_>) -> IndexedSteps<'_> {
    IndexedSteps::new(index.runs())
}

/// Where a run of a compressed ramp stands: `left` steps to play, the
/// next one's period `(frac + interval) >> 16`. Either way along the ramp
/// the same recurrence plays it (see [`Cursor::take_run`](crate::player::ramps::ramp::Cursor::take_run)). The step path
/// of a player of any layout plays it behind an empty `Down` run, so that
/// tables pay nothing for it; a compressed player's step path plays it
/// first.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct RunState {
    pub(crate) left: u32,
    pub(crate) frac: u32,
    pub(crate) interval: u32,
    pub(crate) add: u32,
}

impl RunState {
    /// The period of the step it played last, in ticks (one at least
    /// played): that step's interval less the change, and a tick more
    /// when the remainder it left is below that interval's fraction (its
    /// sum carried). Wrapped to the word, as the step's own sum.
    #[inline(always)]
    pub(crate) fn last(&self) -> u32 {
        let interval = self.interval.wrapping_sub(self.add);
        let carried = self.frac < interval & FRACTION_MASK;
        ((interval >> RUN_FRACTION_BITS) + u32::from(carried)) & FRACTION_MASK
    }

    /// The next step's period, in ticks, or `None` when the run is played.
    #[inline(always)]
    pub(crate) fn next(&mut self) -> Option<u32> {
        if self.left == 0 {
            return None;
        }
        self.left -= 1;
        let x = self.frac.wrapping_add(self.interval);
        self.frac = x & FRACTION_MASK;
        self.interval = self.interval.wrapping_add(self.add);
        Some(x >> RUN_FRACTION_BITS)
    }
}
