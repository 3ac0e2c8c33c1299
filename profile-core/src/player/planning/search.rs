//! Searching along ramps that are ordered slow to fast but for a tick or
//! two: exact, in far fewer reads than a walk.
//!
//! A planner's question is "the first of these steps where ...": the first
//! step where the deceleration ramp is not faster than the acceleration
//! side, the first entry not slower than a period. On ramps ordered slow to
//! fast the answer is a boundary, found by bisection. Generated tables are
//! ordered only within a tick or so (rounding by diffusion lets neighbours
//! differ by a tick either way), and the answer a walk from the first step
//! finds can lie anywhere among the steps within that tick of the
//! boundary. A step far enough from the boundary that the ramps' slack
//! cannot reach it fails, and so does every step before it: [`past`] finds
//! one such step by bisection, and the planner reads the steps after it one
//! by one, as a walk would. The answer is the walk's, on any ramp; the
//! reads are the bisection's and the steps within the slack of the
//! boundary.

use crate::base::timer::TableWord;
use crate::player::ramps::ramp::{Ramp, ticks_at};
use crate::table::fall::Fall;
use crate::table::runs::Expand;

/// A step just past the steps that `before` rules out: bisects `lo..hi`
/// for a step `j` such that `before(j - 1)` holds (or `j == lo`) and
/// `before(j)` does not (or `j == hi`). `before(j)` must say that step `j`
/// and every step before it fail; then no step before the one returned
/// answers.
pub(crate) fn past(mut lo: u32, mut hi: u32, before: &mut impl FnMut(u32) -> bool) -> u32 {
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if before(mid) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    lo
}

/// `x` shorter than `y` by more than `slack` ticks.
#[inline(always)]
pub(crate) fn faster_by(x: u32, slack: u32, y: u32) -> bool {
    // Saturated, `x + slack` is not below any `y`, as the exact sum.
    x.saturating_add(slack) < y
}

/// [`past`] over steps `lo..hi` of the last `r`, each ruled out
/// (with every step before it) when the deceleration table read at the
/// steps that remain is shorter than `value` by more than `slack`: the
/// table's entries for those steps sliced once, so that a probe is a load
/// and a compare.
#[inline(always)]
pub(crate) fn past_shorter<W: TableWord>(
    d: &[W],
    r: u32,
    lo: u32,
    hi: u32,
    slack: u32,
    value: u32,
) -> u32 {
    // Steps `lo..hi` read the table from `r - 1 - lo` down to `r - hi`.
    let Some(read) = d.get((r - hi) as usize..(r - lo) as usize) else {
        return past(lo, hi, &mut |j| {
            ticks_at(d, r - 1 - j).is_some_and(|x| faster_by(x, slack, value))
        });
    };
    let n = read.len();
    let (mut a, mut b) = (0usize, n);
    while a < b {
        let mid = a + (b - a) / 2;
        let before = read
            .get(n - 1 - mid)
            .is_some_and(|x| faster_by(x.into_ticks(), slack, value));
        if before {
            a = mid + 1;
        } else {
            b = mid;
        }
    }
    lo + a as u32
}

/// The last position up to `last` whose period (`read`, in ticks) is not
/// shorter than `ticks`, 0 when none is; `slack` the ramp's
/// ([`slack`]). Exactly the first such position a walk down from `last`
/// finds: past the steps [`short_above`] rules out, then one by one.
#[inline(always)]
pub(crate) fn last_at_least(
    mut read: impl FnMut(u32) -> Option<u32>,
    last: u32,
    slack: u32,
    ticks: u32,
) -> u32 {
    let k = short_above(&mut read, last, slack, ticks);
    let mut pos = last.saturating_sub(k);
    loop {
        match read(pos) {
            Some(p) if p >= ticks => return pos,
            None => return 0,
            _ if pos == 0 => return 0,
            _ => pos -= 1,
        }
    }
}

/// Steps `k` below `last` from which a walk down for a period as long as
/// `ticks` begins: every step above `last - k` is shorter than `ticks` by
/// more than `slack` (the ramp's, [`slack`]), and so none is that long. A
/// bisection ([`past`]) on the periods `read` gives, in ticks.
#[inline(always)]
pub(crate) fn short_above(
    read: &mut impl FnMut(u32) -> Option<u32>,
    last: u32,
    slack: u32,
    ticks: u32,
) -> u32 {
    past(0, last.saturating_add(1), &mut |k| {
        read(last - k).is_some_and(|p| faster_by(p, slack, ticks))
    })
}

/// The first position up to `last` whose period (`read`, in ticks) is not
/// longer than `current`; `last` when none is; `slack` the ramp's
/// ([`slack`]). Exactly the first such position a walk up from 0 finds.
#[inline(always)]
pub(crate) fn first_at_most(
    read: impl FnMut(u32) -> Option<u32>,
    last: u32,
    slack: u32,
    current: u32,
) -> u32 {
    first_at_most_in(read, 0, last, last, slack, current)
}

/// [`first_at_most`], its bisection begun within `lo..hi` (`lo - 1` ruled
/// out when `lo > 0`; `hi` not when it is below `last`).
#[inline(always)]
pub(crate) fn first_at_most_in(
    mut read: impl FnMut(u32) -> Option<u32>,
    lo: u32,
    hi: u32,
    last: u32,
    slack: u32,
    current: u32,
) -> u32 {
    let (slack, current) = (u64::from(slack), u64::from(current));
    // Longer by more than the slack, and so is every step before it.
    let mut pos = past(lo, hi, &mut |pos| {
        read(pos).is_some_and(|p| u64::from(p) > current + slack)
    });
    loop {
        match read(pos) {
            Some(p) if u64::from(p) <= current => return pos,
            None => return last,
            _ if pos >= last => return last,
            _ => pos += 1,
        }
    }
}

/// The most a step's period exceeds the shortest period before it, in
/// ticks: 0 for a ramp ordered slow to fast, a tick or so for a table
/// rounded by diffusion (neighbours may differ by a tick either way).
/// With it a search along the ramp by period is exact: no step after
/// one whose period is more than `slack` ticks below a value reaches
/// that value ([`past`]).
pub(crate) fn slack<W: TableWord>(ramp: &Ramp<'_, W>) -> u32 {
    fn rise(periods: impl Iterator<Item = u32>) -> u32 {
        let mut fastest = u32::MAX;
        let mut rise = 0u32;
        for p in periods {
            rise = rise.max(p.saturating_sub(fastest));
            fastest = fastest.min(p);
        }
        rise
    }
    match *ramp {
        Ramp::Steps { periods, .. } => rise(periods.iter().map(|p| p.into_ticks())),
        Ramp::Segments(pairs) => rise(
            pairs
                .iter()
                .filter(|p| p.1.into_ticks() > 0)
                .map(|p| p.0.into_ticks()),
        ),
        Ramp::Runs(runs) => rise(Expand::new(runs)),
        // Computed with the index.
        Ramp::Indexed(index) => index.buckets().slack,
    }
}

/// `true` when two ramps are one: the same periods at the same address,
/// read the same way.
pub(crate) fn one_ramp<W: TableWord>(accel: &Ramp<'_, W>, decel: &Ramp<'_, W>) -> bool {
    match (*accel, *decel) {
        (
            Ramp::Steps {
                periods: a,
                hold: x,
            },
            Ramp::Steps {
                periods: d,
                hold: y,
            },
        ) => core::ptr::eq(a, d) && x == y,
        (Ramp::Segments(a), Ramp::Segments(d)) => core::ptr::eq(a, d),
        (Ramp::Runs(a), Ramp::Runs(d)) => core::ptr::eq(a, d),
        (Ramp::Indexed(a), Ramp::Indexed(d)) => core::ptr::eq(a.runs(), d.runs()),
        _ => false,
    }
}

/// The slack of a player's acceleration and deceleration ramps
/// ([`slack`]), read once when they are `one` ramp ([`one_ramp`]).
pub(crate) fn slacks<W: TableWord>(
    accel: &Ramp<'_, W>,
    decel: &Ramp<'_, W>,
    one: bool,
) -> (u32, u32) {
    let accel_slack = slack(accel);
    let decel_slack = match one {
        true => accel_slack,
        false => slack(decel),
    };
    (accel_slack, decel_slack)
}

/// How far ahead of the acceleration ramp the deceleration ramp is
/// faster at every step ([`Fall`]), `decel_slack` the latter's
/// ([`slack`]): an indexed ramp's own, computed with its index, when it
/// is both (`one` ramp, [`one_ramp`]); else read off the two ramps'
/// steps, one pass over each; [`Fall::UNKNOWN`] for held and segment
/// tables.
pub(crate) fn fall<W: TableWord>(
    accel: &Ramp<'_, W>,
    decel: &Ramp<'_, W>,
    decel_slack: u32,
    one: bool,
) -> Fall {
    if let (Ramp::Indexed(index), true) = (accel, one) {
        return index.buckets().fall;
    }
    match (Steps::of(accel), Steps::of(decel)) {
        (Some(a), Some(d)) => Fall::of(a, d, accel.len_steps(), decel_slack),
        _ => Fall::UNKNOWN,
    }
}

/// A ramp's periods step by step, in ticks: a per-step table's or a
/// compressed ramp's (one type for every kind, so that [`Fall::of`] is
/// compiled once, each step's read a match on the kind).
enum Steps<'a, W> {
    Table(core::slice::Iter<'a, W>),
    Runs(Expand<'a>),
    Indexed(crate::table::runs::IndexedSteps<'a>),
}

impl<'a, W: TableWord> Steps<'a, W> {
    /// `None` for held and segment tables.
    fn of(ramp: &Ramp<'a, W>) -> Option<Self> {
        Some(match *ramp {
            Ramp::Runs(runs) => Steps::Runs(Expand::new(runs)),
            Ramp::Indexed(index) => Steps::Indexed(crate::player::ramps::runs::periods(index)),
            _ => Steps::Table(ramp.per_step()?.iter()),
        })
    }
}

impl<W: TableWord> Iterator for Steps<'_, W> {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        match self {
            Steps::Table(periods) => periods.next().map(|p| p.into_ticks()),
            Steps::Runs(runs) => runs.next(),
            Steps::Indexed(runs) => runs.next(),
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use std::vec::Vec;

    /// On every sequence of length up to 10 of steps that answer or fail,
    /// `before` true wherever it may be (every step up to it fails) or
    /// only at some of those places: the walk's answer is never before the
    /// step returned, and the steps `before` held at are all before it.
    /// One ramp both ways has no step faster than its shortest period, so
    /// a player of one ramp takes no step for its first faster one: on a
    /// table (with a step a tick slower after a faster one), held,
    /// segments, runs and an index; two ramps at different addresses are
    /// not one, even with the same periods.
    #[test]
    fn one_ramp_has_no_step_faster_than_its_fastest() {
        use crate::table::runs::RunIndex;
        static TABLE: [u16; 5] = [900, 700, 500, 501, 400];
        static OTHER: [u16; 5] = [900, 700, 500, 501, 400];
        static PAIRS: [(u16, u16); 3] = [(900, 2), (500, 0), (450, 3)];
        static RUNS: [[u16; 5]; 2] = [[3, 4000, 0x8000, 0xFE0C, 0], [2, 2000, 0, 0, 0]];
        static INDEX: RunIndex<2> = RunIndex::new(&RUNS);
        let ramps = [
            Ramp::steps(&TABLE),
            Ramp::held(&TABLE, 3),
            Ramp::segments(&PAIRS),
            Ramp::runs(&RUNS),
            Ramp::indexed(&INDEX),
        ];
        for ramp in ramps {
            assert!(one_ramp(&ramp, &ramp), "{ramp:?}");
            assert_eq!(ramp.first_faster_than(ramp.fastest()), u32::MAX, "{ramp:?}");
            assert!(ramp.fastest() > 0, "{ramp:?}");
        }
        assert!(!one_ramp(&Ramp::steps(&TABLE), &Ramp::steps(&OTHER)));
        assert!(!one_ramp(&Ramp::steps(&TABLE), &Ramp::held(&TABLE, 2)));
        assert!(!one_ramp(&Ramp::<u16>::runs(&RUNS), &Ramp::indexed(&INDEX)));
        assert_eq!(Ramp::<u16>::indexed(&INDEX).fastest(), 2000);
    }

    #[test]
    fn nothing_before_the_step_returned_answers() {
        for len in 0..10u32 {
            for answers in 0..1u32 << len {
                let walk = (0..len).find(|j| answers >> j & 1 == 1).unwrap_or(len);
                for holds in [u32::MAX, 0x5555_5555, 0xAAAA_AAAA, 0] {
                    let mut said = Vec::new();
                    let j = past(0, len, &mut |j| {
                        let b = j < walk && holds >> j & 1 == 1;
                        if b {
                            said.push(j);
                        }
                        b
                    });
                    assert!(
                        j <= walk,
                        "{answers:b} {holds:x}: {j} past the walk's {walk}"
                    );
                    assert!(said.iter().all(|&s| s < j));
                    if holds == u32::MAX {
                        assert_eq!(j, walk);
                    }
                }
            }
        }
    }
}
