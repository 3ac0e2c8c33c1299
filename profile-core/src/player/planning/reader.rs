//! Reading a ramp's periods by position for the searches of a plan.

use crate::base::timer::TableWord;
use crate::player::planning::search::{self, faster_by};
use crate::player::planning::threshold;
use crate::player::ramps::ramp::{Cursor, Ramp, ticks_at};
use crate::player::ramps::runs::{end_run, place, run_holding};
use crate::table::runs::{IndexedRun, IndexedRuns, LinearRun, ahead, behind, period};

/// A run of no steps: what a reader of no runs keeps.
static EMPTY: IndexedRun = IndexedRun {
    step: 0,
    words: [0; 5],
    frac: 0,
};

/// Reads an indexed ramp by position: the run read last kept, so that
/// reads within it are closed-form, and any other run found through the
/// index ([`run_holding`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct RunRead<'a> {
    index: IndexedRuns<'a>,
    /// The run read last (the first before any read): its index, its
    /// first step, its count, its remainder and interval at its first
    /// step, its change.
    entry: u32,
    first: u32,
    count: u32,
    frac: u32,
    interval: u32,
    add: u32,
}

impl<'a> RunRead<'a> {
    /// A reader of `index`, its first run kept (none when there is none).
    pub(crate) fn new(index: IndexedRuns<'a>) -> Self {
        match index.runs().first() {
            Some(run) => RunRead::keep(index, 0, run, LinearRun::decode(&run.words)),
            None => RunRead::keep(index, 0, &EMPTY, LinearRun::decode(&EMPTY.words)),
        }
    }

    /// A reader of `index` keeping run `entry`, `run` (decoded).
    #[inline(always)]
    fn keep(index: IndexedRuns<'a>, entry: u32, run: &IndexedRun, decoded: LinearRun) -> Self {
        RunRead {
            index,
            entry,
            first: run.step,
            count: u32::from(decoded.count),
            frac: u32::from(run.frac),
            interval: decoded.interval,
            add: decoded.add as u32,
        }
    }

    /// The period at step `pos`, in ticks; `None` past the ramp's end.
    #[inline]
    pub(crate) fn ticks(&mut self, pos: u32) -> Option<u32> {
        let mut within = pos.wrapping_sub(self.first);
        if within >= self.count {
            within = self.enter(pos)?;
        }
        let (frac, interval) = ahead(self.frac, self.interval, self.add, within);
        Some(period(frac, interval))
    }

    /// Probes the runs' first steps strictly between `lo` and `hi`, by
    /// bisection, for where `fast` (of a period, in ticks) stops being
    /// false: the largest probed step where it is false (`lo` if none) and
    /// the smallest probed step after it where it is true (`hi` if none).
    /// Each probe's period is read off the index, no run entered; the run
    /// of the first kept. Only probes: the caller's search holds whatever
    /// order the ramp's periods are in.
    pub(crate) fn bracket(&mut self, lo: u32, hi: u32, fast: impl Fn(u32) -> bool) -> (u32, u32) {
        let runs = self.index.runs();
        // One bisection over all the runs, those that begin outside
        // `lo..hi` (strictly) passed over unprobed, so that only runs
        // inside are probed.
        let (outside_lo, outside_hi) = (lo, hi);
        let (mut a, mut b) = (0, runs.len());
        let (mut lo, mut hi, mut kept) = (lo, hi, None);
        while a < b {
            let mid = a + (b - a) / 2;
            let Some(run) = runs.get(mid) else {
                break;
            };
            if run.step <= outside_lo {
                a = mid + 1;
                continue;
            }
            if run.step >= outside_hi {
                b = mid;
                continue;
            }
            let decoded = LinearRun::decode(&run.words);
            // A run of no steps: its first step is the next run's.
            let period = if decoded.count == 0 {
                self.ticks(run.step)
            } else {
                Some(period(u32::from(run.frac), decoded.interval))
            };
            match period {
                Some(t) if fast(t) => {
                    hi = run.step;
                    b = mid;
                }
                Some(_) => {
                    (lo, kept) = (run.step, Some((mid, run, decoded)));
                    a = mid + 1;
                }
                None => break,
            }
        }
        if let Some((entry, run, decoded)) = kept {
            if decoded.count > 0 {
                *self = RunRead::keep(self.index, entry as u32, run, decoded);
            }
        }
        (lo, hi)
    }

    /// The last step up to `top` whose period is at least `ticks`, `slack`
    /// the ramp's ([`search::slack`]); `None` when no step is. The run that
    /// holds it is kept ([`RunRead::cursor`]). Exactly the step a walk down
    /// from `top` finds, on runs in any order: a bisection over the runs'
    /// first steps finds a run past which no step is that long (its first
    /// period more than `slack` short, or past `top`), and the runs before
    /// it are asked in turn, last first, each in closed form
    /// ([`threshold::last_at_least`]).
    ///
    /// From the first run (`from` 0), the index's buckets are asked
    /// first: the first step of a bucket whose period is more than `slack`
    /// short ([`Buckets::first_short`]) bounds the step sought, and only
    /// the runs from the one holding the bucket before's first step to the
    /// one holding that step are bisected. Else the search begins at run
    /// `from`, probing runs 1, 2, 4, ... on from there until one is such a
    /// run, then bisecting: a caller that knows run `from - 1` is not one
    /// is spared the probes before it. Any `from` gives the same step.
    ///
    /// [`Buckets::first_short`]: crate::table::runs::Buckets::first_short
    pub(crate) fn last_at_least(
        &mut self,
        top: u32,
        ticks: u32,
        slack: u32,
        from: u32,
    ) -> Option<u32> {
        let runs = self.index.runs();
        let (mut top, mut a, mut b) = (top, from as usize, runs.len());
        if from == 0 {
            match self.index.buckets().first_short(top, ticks, slack) {
                // Every step is short of it.
                Some((0, _, _)) => return None,
                // None from the bucket's first step on: the runs from the
                // one before the bucket's to the one holding that step are
                // bisected, as below.
                Some((step, before, run)) => {
                    top = top.min(step - 1);
                    (a, b) = (before, run + 1);
                }
                None => {}
            }
        }
        // A run of no steps tells nothing: its first step is the next
        // run's.
        let short = |run: &IndexedRun| {
            run.step > top
                || (run.words[0] > 0 && {
                    let decoded = LinearRun::decode(&run.words);
                    faster_by(period(u32::from(run.frac), decoded.interval), slack, ticks)
                })
        };
        if a > 0 {
            let mut reach = 1;
            while let Some(run) = runs.get(a + reach - 1).filter(|_| a + reach <= b) {
                if short(run) {
                    b = a + reach - 1;
                    break;
                }
                a += reach;
                reach *= 2;
            }
        }
        while a < b {
            let mid = a + (b - a) / 2;
            let Some(run) = runs.get(mid) else {
                break;
            };
            if short(run) {
                b = mid;
            } else {
                a = mid + 1;
            }
        }
        while a > 0 {
            a -= 1;
            let Some(run) = runs.get(a) else {
                break;
            };
            let decoded = LinearRun::decode(&run.words);
            let Some(last) = u32::from(decoded.count).checked_sub(1) else {
                continue;
            };
            // (Past `top`: runs a search begun past it did not probe.)
            let Some(room) = top.checked_sub(run.step) else {
                continue;
            };
            let within = last.min(room);
            let (frac, add) = (u32::from(run.frac), decoded.add as u32);
            let found = threshold::last_at_least(frac, decoded.interval, add, within, ticks)
                .unwrap_or_else(|| {
                    // Out of the closed form's range: step by step.
                    (0..=within).rev().find(|&k| {
                        let (f, i) = ahead(frac, decoded.interval, add, k);
                        period(f, i) >= ticks
                    })
                });
            if let Some(k) = found {
                *self = RunRead::keep(self.index, a as u32, run, decoded);
                return Some(run.step + k);
            }
        }
        None
    }

    /// The cursor at step `pos` if the run kept holds it.
    pub(crate) fn cursor(&self, pos: u32) -> Option<Cursor> {
        let within = pos.checked_sub(self.first).filter(|&w| w < self.count)?;
        let (frac, interval) = ahead(self.frac, self.interval, self.add, within);
        Some(Cursor {
            pos,
            entry: self.entry,
            within,
            frac,
            interval,
        })
    }

    /// Keeps the run that holds step `pos` (the next or the previous run
    /// first, else through the index's lookup, [`run_holding`]); `pos`'s
    /// step within it.
    #[inline(never)]
    fn enter(&mut self, pos: u32) -> Option<u32> {
        let runs = self.index.runs();
        let neighbour = if pos >= self.first {
            self.entry.wrapping_add(1)
        } else {
            self.entry.wrapping_sub(1)
        };
        let (entry, run, decoded) = match end_run(runs, neighbour as usize, pos) {
            Some(held) => held,
            None => run_holding(self.index, pos)?,
        };
        *self = RunRead::keep(self.index, entry, run, decoded);
        Some(pos - run.step)
    }
}

/// Walks an indexed ramp a step at a time either way, by the run's
/// recurrence (an addition and a mask a step), into the next or previous
/// run through the index.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RunWalk<'a> {
    read: RunRead<'a>,
    /// The step within the run, the remainder before it and its interval.
    within: u32,
    frac: u32,
    interval: u32,
}

impl<'a> RunWalk<'a> {
    /// At step `pos` of `index`; `None` past the ramp's end.
    pub(crate) fn at(index: IndexedRuns<'a>, pos: u32) -> Option<Self> {
        let at = place(index, pos)?;
        Some(RunWalk {
            read: RunRead::keep(index, at.entry, at.run, at.decoded),
            within: at.within,
            frac: at.frac,
            interval: at.interval,
        })
    }

    /// At `cursor`'s step of `runs` (a cursor on them); `None` if its run
    /// is not there.
    pub(crate) fn from_cursor(index: IndexedRuns<'a>, cursor: Cursor) -> Option<Self> {
        let run = index.runs().get(cursor.entry as usize)?;
        Some(RunWalk {
            read: RunRead::keep(index, cursor.entry, run, LinearRun::decode(&run.words)),
            within: cursor.within,
            frac: cursor.frac,
            interval: cursor.interval,
        })
    }

    /// The cursor at the step it stands at.
    pub(crate) fn cursor(&self) -> Cursor {
        Cursor {
            pos: self.read.first + self.within,
            entry: self.read.entry,
            within: self.within,
            frac: self.frac,
            interval: self.interval,
        }
    }

    /// The period of the step it stands at, in ticks.
    #[inline(always)]
    pub(crate) fn ticks(&self) -> u32 {
        period(self.frac, self.interval)
    }

    /// One step towards the fast end; `None` past the ramp's end.
    #[inline(always)]
    pub(crate) fn forward(&mut self) -> Option<()> {
        if self.within + 1 < self.read.count {
            self.within += 1;
            (self.frac, self.interval) = ahead(self.frac, self.interval, self.read.add, 1);
            return Some(());
        }
        self.enter(self.read.first + self.within + 1)
    }

    /// One step towards the slow end; `None` at step 0.
    #[inline(always)]
    pub(crate) fn backward(&mut self) -> Option<()> {
        if self.within > 0 {
            self.within -= 1;
            (self.frac, self.interval) = behind(self.frac, self.interval, self.read.add, 1);
            return Some(());
        }
        self.enter(self.read.first.checked_sub(1)?)
    }

    /// The steps it can take `dir` (1 towards the fast end, -1 towards
    /// the slow end) without leaving its run; any number when `dir` is 0.
    /// (A walk stands on a step of its run: the run has one at least.)
    #[inline(always)]
    pub(crate) fn room(&self, dir: i8) -> u32 {
        match dir {
            1 => self.read.count - 1 - self.within,
            -1 => self.within,
            _ => u32::MAX,
        }
    }

    /// Compares `decel`, walking towards the slow end, with `self`, walking
    /// `dir` (held when 0), before each of `moves` steps that both take
    /// within their runs ([`RunWalk::room`]): the first of those compared
    /// where `decel`'s period is not shorter than this one's, both walks
    /// moved to it; `None` when none is, both walks moved `moves` steps.
    /// One loop for each direction, the runs' state in registers.
    pub(crate) fn first_not_shorter(
        &mut self,
        dir: i8,
        decel: &mut RunWalk<'_>,
        moves: u32,
    ) -> Option<u32> {
        let (mut df, mut di, da) = (decel.frac, decel.interval, decel.read.add);
        let (mut af, mut ai, aa) = (self.frac, self.interval, self.read.add);
        let ticks = period;
        let mut left = moves;
        match dir {
            1 => {
                while left > 0 && ticks(df, di) < ticks(af, ai) {
                    (af, ai) = ahead(af, ai, aa, 1);
                    (df, di) = behind(df, di, da, 1);
                    left -= 1;
                }
            }
            -1 => {
                while left > 0 && ticks(df, di) < ticks(af, ai) {
                    (af, ai) = behind(af, ai, aa, 1);
                    (df, di) = behind(df, di, da, 1);
                    left -= 1;
                }
            }
            _ => {
                let held = ticks(af, ai);
                while left > 0 && ticks(df, di) < held {
                    (df, di) = behind(df, di, da, 1);
                    left -= 1;
                }
            }
        }
        let k = moves - left;
        (decel.frac, decel.interval, decel.within) = (df, di, decel.within - k);
        (self.frac, self.interval) = (af, ai);
        self.within = match dir {
            1 => self.within + k,
            -1 => self.within - k,
            _ => self.within,
        };
        (left > 0).then_some(k)
    }

    /// To step `pos`, through the index.
    #[inline(never)]
    fn enter(&mut self, pos: u32) -> Option<()> {
        self.within = self.read.enter(pos)?;
        let r = &self.read;
        (self.frac, self.interval) = ahead(r.frac, r.interval, r.add, self.within);
        Some(())
    }
}

/// Reads a ramp's periods by position, in ticks, for the searches of a
/// plan: a per-step table directly; an indexed ramp through its index
/// ([`RunRead`]); any other ramp through a cursor moved from read to read
/// (on runs a whole run at a time, so that reads near each other cost the
/// runs between them, not the runs from the start). Chosen once per
/// search, so that a read of a per-step table is a bounds check and a
/// load.
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
            (None, Ramp::Indexed(index)) => Reader::Indexed(RunRead::new(index)),
            (None, _) => Reader::Seek(ramp, hint),
        }
    }

    /// [`search::past`] over steps `lo..hi` of the last `r`, each ruled
    /// out (with every step before it) when the ramp read at the steps
    /// that remain (`r - 1 - j`) is shorter than `value` by more than
    /// `slack`: a per-step table sliced once, an indexed ramp's runs
    /// probed at their first steps first.
    pub(crate) fn past_shorter(&mut self, r: u32, lo: u32, hi: u32, slack: u32, value: u32) -> u32 {
        if lo >= hi {
            return lo;
        }
        let (mut lo, mut hi) = (lo, hi);
        match self {
            Reader::Table(periods) => {
                return search::past_shorter(periods, r, lo, hi, slack, value);
            }
            Reader::Indexed(run) => {
                // The steps read positions `r - hi..=r - 1 - lo`: the runs
                // that begin strictly inside are probed; the fast end is
                // ruled out.
                let short = |t: u32| faster_by(t, slack, value);
                let (long, shorter) = run.bracket(r - hi, r - lo, short);
                if shorter < r - lo {
                    lo = r - shorter;
                }
                if long > r - hi {
                    hi = r - 1 - long;
                }
                return search::past(lo, hi, &mut |j| {
                    run.ticks(r - 1 - j)
                        .is_some_and(|x| faster_by(x, slack, value))
                });
            }
            Reader::Seek(..) => {}
        }
        search::past(lo, hi, &mut |j| {
            self.ticks(r - 1 - j)
                .is_some_and(|x| faster_by(x, slack, value))
        })
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::runs::{Expand, RunIndex};
    use core_test_support::{any_runs, falling_runs, padded};
    use proptest::prelude::*;

    fn state(w: &RunWalk<'_>) -> (u32, u32, u32, u32) {
        (w.read.entry, w.within, w.frac, w.interval)
    }

    proptest! {
        /// The walks compared in one loop stop at the first step where the
        /// expansions of the runs (`Expand`, step by step from the first
        /// run) have the deceleration side's period not shorter than the
        /// acceleration side's, and stand where the index places those
        /// steps in closed form; a walk made from a walk's cursor stands
        /// where it stood.
        #[test]
        fn walks_compared_in_one_loop_stop_as_the_expansions_say(
            a in any_runs(),
            // The same runs on both sides half the time: equal periods.
            d in prop_oneof![Just(None), any_runs().prop_map(Some)],
            ap in any::<prop::sample::Index>(),
            dp in any::<prop::sample::Index>(),
            dir in -1i8..=1,
            moves in 0u32..40,
        ) {
            let d = d.unwrap_or_else(|| a.clone());
            let (a_all, d_all) = (padded::<12>(&a), padded::<12>(&d));
            let (a_index, d_index) = (RunIndex::new(&a_all), RunIndex::new(&d_all));
            let (a_runs, d_runs) = (a_index.indexed(), d_index.indexed());
            let (a_steps, d_steps): (std::vec::Vec<u32>, std::vec::Vec<u32>) =
                (Expand::new(&a).collect(), Expand::new(&d).collect());
            prop_assume!(!a_steps.is_empty() && !d_steps.is_empty());
            let (ap, dp) = (ap.index(a_steps.len()) as u32, dp.index(d_steps.len()) as u32);
            let (mut wa, mut wd) = (RunWalk::at(a_runs, ap).unwrap(), RunWalk::at(d_runs, dp).unwrap());
            let moves = moves.min(wa.room(dir)).min(wd.room(-1));
            let a_at = |k: u32| (i64::from(ap) + i64::from(dir) * i64::from(k)) as u32;
            let expected = (0..moves).find(|&k| d_steps[(dp - k) as usize] >= a_steps[a_at(k) as usize]);
            let found = wa.first_not_shorter(dir, &mut wd, moves);
            prop_assert_eq!(found, expected);
            let k = found.unwrap_or(moves);
            prop_assert_eq!(state(&wa), state(&RunWalk::at(a_runs, a_at(k)).unwrap()));
            prop_assert_eq!(state(&wd), state(&RunWalk::at(d_runs, dp - k).unwrap()));
            prop_assert_eq!(wa.ticks(), a_steps[a_at(k) as usize]);
            prop_assert_eq!(wd.ticks(), d_steps[(dp - k) as usize]);
            // A walk made from its cursor stands where it stood.
            let again = RunWalk::from_cursor(a_runs, wa.cursor()).unwrap();
            prop_assert_eq!(state(&again), state(&wa));
            prop_assert_eq!(again.cursor().pos, wa.cursor().pos);
        }

        /// The last step up to any top whose period is at least one asked
        /// (near a period the ramp plays, or any) is the one a walk down
        /// the expansion of the runs (`Expand`, step by step from the
        /// first run) finds, on runs in any order, their slack computed
        /// here from the expansion; the reader's cursor there is the
        /// index's.
        #[test]
        fn the_last_step_at_least_a_period_is_the_expansions(
            runs in prop_oneof![any_runs(), falling_runs(4000)],
            top in any::<prop::sample::Index>(),
            at in any::<prop::sample::Index>(),
            offset in -3i64..=3,
            // Where the search begins, any run: the step found the same.
            from in any::<prop::sample::Index>(),
        ) {
            let all = padded::<48>(&runs);
            let index = RunIndex::new(&all);
            let steps: std::vec::Vec<u32> = Expand::new(&runs).collect();
            prop_assume!(!steps.is_empty());
            let mut slack = 0;
            for (i, &p) in steps.iter().enumerate() {
                let shortest = steps[..i].iter().copied().min().unwrap_or(u32::MAX);
                slack = slack.max(p.saturating_sub(shortest));
            }
            let top = top.index(steps.len()) as u32;
            let asked = (i64::from(steps[at.index(steps.len())]) + offset).max(0) as u32;
            let walk = (0..=top).rev().find(|&k| steps[k as usize] >= asked);
            // From the first run (the buckets asked first), and from any.
            for from in [0, from.index(index.indexed().runs().len() + 1) as u32] {
                let mut read = RunRead::new(index.indexed());
                let found = read.last_at_least(top, asked, slack, from);
                prop_assert_eq!(found, walk);
                if let Some(pos) = found {
                    let c = read.cursor(pos).unwrap();
                    let placed = Cursor::at(&Ramp::<u16>::Indexed(index.indexed()), pos).unwrap();
                    prop_assert_eq!((c.entry, c.within, c.frac, c.interval), (placed.entry, placed.within, placed.frac, placed.interval));
                }
            }
        }
    }
}
