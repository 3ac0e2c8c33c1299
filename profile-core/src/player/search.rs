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

use super::ramp::{Ramp, ticks_at};
use crate::base::timer::TableWord;
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
        Ramp::Indexed(index) => rise(super::runs::periods(index)),
    }
}

/// Parts of the acceleration ramp [`Fall`] keeps a figure for.
const FALL_PARTS: usize = 16;

/// How far ahead of the acceleration ramp the deceleration ramp is read
/// where it is faster at every step, for each sixteenth of the
/// acceleration ramp: at a step `y` of the first in part `i`, and any
/// step `z >= y + ahead[i]` of the second, the second's period is
/// shorter ([`Fall::of`]). A part's figure is kept where the ramp falls
/// steeply as where it is nearly flat, so that a walk in the steep parts
/// is not held to the flat ones' figure.
///
/// A plan that walks the acceleration side down while the deceleration
/// ramp, read at the steps that remain, stands at least that far ahead
/// has no crossing in the walk, however long: a comparison a part
/// instead of a search ([`Fall::clears`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Fall {
    /// Steps a part spans: `1 << shift`.
    shift: u8,
    /// Each part's figure; `u16::MAX` when not known to be less.
    ahead: [u16; FALL_PARTS],
    /// The largest figure: ahead that far, every part is cleared at once.
    most: u16,
}

impl Fall {
    /// No figure: held and segment tables, whose planning reads entries,
    /// not steps.
    const UNKNOWN: Fall = Fall {
        shift: 31,
        ahead: [u16::MAX; FALL_PARTS],
        most: u16::MAX,
    };

    /// The figures of two ramps, `decel_slack` the second's ([`slack`]).
    pub(crate) fn new<W: TableWord>(
        accel: &Ramp<'_, W>,
        decel: &Ramp<'_, W>,
        decel_slack: u32,
    ) -> Self {
        let steps = accel.len_steps();
        let mut shift = 0u8;
        while steps.checked_shr(shift.into()).unwrap_or(0) > FALL_PARTS as u32 {
            shift += 1;
        }
        let mut fall = None;
        with_steps(accel, &mut |a| {
            with_steps(decel, &mut |d| {
                fall = Some(Fall::of(a, d, decel_slack, shift))
            });
        });
        fall.unwrap_or(Fall::UNKNOWN)
    }

    /// [`Fall`] of two ramps' periods, parts of `1 << shift` steps: each
    /// part's largest `t(y) - y` (0 at least), where `t(y)` is the first
    /// step of the second more than `decel_slack` faster than the fastest
    /// of the first's steps up to `y` (one past its last when none is).
    /// From `t(y)` on, the second is no slower than at `t(y)` but for its
    /// slack, so faster than every one of those steps, `y`'s among them.
    /// The fastest step so far only gets faster as `y` grows, so `t(y)`
    /// only moves on: one pass over each ramp.
    pub(crate) fn of(
        accel: &mut dyn Iterator<Item = u32>,
        decel: &mut dyn Iterator<Item = u32>,
        decel_slack: u32,
        shift: u8,
    ) -> Self {
        let mut fall = Fall {
            shift,
            ahead: [0; FALL_PARTS],
            most: 0,
        };
        let mut fastest = u32::MAX;
        let (mut t, mut at_t) = (0u32, decel.next());
        for (y, period) in (0u32..).zip(accel) {
            fastest = fastest.min(period);
            while at_t.is_some_and(|d| !faster_by(d, decel_slack, fastest)) {
                (t, at_t) = (t + 1, decel.next());
            }
            let ahead = u16::try_from(t.saturating_sub(y)).unwrap_or(u16::MAX);
            if let Some(part) = fall.ahead.get_mut((y >> shift) as usize) {
                *part = (*part).max(ahead);
            }
            fall.most = fall.most.max(ahead);
        }
        fall
    }

    /// `true` when the deceleration ramp, read `ahead` steps ahead of the
    /// acceleration ramp, is faster than it at each of the latter's steps
    /// `from..=to`: at least each of their parts' figures ahead.
    #[inline]
    pub(crate) fn clears(&self, from: u32, to: u32, ahead: u32) -> bool {
        // `u16::MAX` is never cleared.
        let ahead = ahead.min(u32::from(u16::MAX) - 1) as u16;
        if ahead >= self.most {
            return true;
        }
        // From the top down: a ramp is flattest near its top.
        let part = |y: u32| (y >> self.shift) as usize;
        self.ahead
            .get(part(from)..=part(to))
            .is_some_and(|parts| parts.iter().rev().all(|&f| ahead >= f))
    }
}

/// `f` given a ramp's periods step by step, for a per-step table or a
/// compressed ramp; not called for held and segment tables.
fn with_steps<W: TableWord>(ramp: &Ramp<'_, W>, f: &mut dyn FnMut(&mut dyn Iterator<Item = u32>)) {
    match *ramp {
        _ if ramp.per_step().is_some() => f(&mut ramp
            .per_step()
            .unwrap_or(&[])
            .iter()
            .map(|p| p.into_ticks())),
        Ramp::Runs(runs) => f(&mut Expand::new(runs)),
        Ramp::Indexed(index) => f(&mut super::runs::periods(index)),
        Ramp::Steps { .. } | Ramp::Segments(_) => {}
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

    /// [`Fall::of`] two ramps' periods, parts of `1 << shift` steps.
    fn fall_on(accel: &[u32], decel: &[u32], decel_slack: u32, shift: u8) -> Fall {
        Fall::of(
            &mut accel.iter().copied(),
            &mut decel.iter().copied(),
            decel_slack,
            shift,
        )
    }

    /// Read as far ahead as [`Fall::clears`] takes, or farther, the
    /// second ramp is faster than the first at every pair of steps
    /// (checked pair by pair): on every ramp of up to 6 steps of periods
    /// 1 to 4, one ramp both ways or two, parts of 1, 2 and 4 steps, any
    /// steps of the first and any distance; on ramps ordered strictly,
    /// a step ahead clears them all.
    #[test]
    fn the_deceleration_read_far_enough_ahead_is_faster() {
        let ramps: Vec<Vec<u32>> = (0..7u32)
            .flat_map(|len| (0..4u32.pow(len)).map(move |n| (len, n)))
            .map(|(len, n)| (0..len).map(|i| n / 4u32.pow(i) % 4 + 1).collect())
            .collect();
        let (mut checked, mut cleared) = (0u32, 0u32);
        for (i, a) in ramps.iter().enumerate() {
            let n = a.len() as u32;
            // One ramp both ways, and a few others.
            for d in [a]
                .into_iter()
                .chain(ramps.iter().skip(i % 97).step_by(301))
            {
                for shift in [0, 1, 2] {
                    let fall = fall_on(a, d, rise_of(d), shift);
                    for (from, to) in (0..n).flat_map(|f| (f..n).map(move |t| (f, t))) {
                        for ahead in 0..=d.len() as u32 {
                            if !fall.clears(from, to, ahead) {
                                continue;
                            }
                            cleared += 1;
                            for y in from..=to {
                                for z in (y + ahead) as usize..d.len() {
                                    assert!(
                                        d[z] < a[y as usize],
                                        "{a:?} {d:?} {fall:?}: {from}..={to} {ahead} ahead, {y} -> {z}"
                                    );
                                    checked += 1;
                                }
                            }
                        }
                    }
                    let strict = d.windows(2).all(|w| w[1] < w[0]);
                    if core::ptr::eq(a, d) && strict && n > 0 {
                        assert!(fall.clears(0, n - 1, 1), "{a:?}: {fall:?}");
                    }
                }
            }
        }
        assert!(
            checked > 100_000 && cleared > 100_000,
            "{checked} {cleared}"
        );
        // Flat for three steps from step 2: read three ahead there, and
        // a step ahead elsewhere.
        let f = [9, 8, 5, 5, 5, 4, 2];
        let fall = fall_on(&f, &f, 0, 0);
        assert!(fall.clears(0, 1, 1) && fall.clears(4, 6, 1) && fall.clears(2, 2, 3));
        assert!(!fall.clears(2, 2, 2) && !fall.clears(0, 6, 2) && fall.clears(0, 6, 3));
    }

    /// The slack of periods, by its definition: the most a period exceeds
    /// the shortest before it.
    fn rise_of(periods: &[u32]) -> u32 {
        (0..periods.len())
            .map(|i| {
                let before = periods[..i].iter().min().copied().unwrap_or(u32::MAX);
                periods[i].saturating_sub(before)
            })
            .max()
            .unwrap_or(0)
    }
}
