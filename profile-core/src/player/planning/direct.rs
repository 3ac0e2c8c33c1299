//! Planning on per-step tables: the crossing of a plan ([`Sides::crossing`])
//! found by reading both tables directly, a bounds check and a load per
//! entry, no cursor.

use crate::base::timer::TableWord;
use crate::player::planning::crossing::{Block, SCAN_BLOCK, blocks_down};
use crate::player::planning::plan::Sides;
use crate::player::planning::search::{self, faster_by, past_shorter};
use crate::player::ramps::ramp::ticks_at;

/// The first of `from..to` (steps of the last `r`) at which the
/// deceleration table read at the steps that remain is not faster than
/// `held`: `Some(to)` reached without one, `None` when the table ends.
#[inline(always)]
fn scan_held<W: TableWord>(d: &[W], r: u32, from: u32, to: u32, held: u32) -> Option<u32> {
    // Steps `from..to` read the deceleration table from `r - 1 - from`
    // down to `r - to`.
    let read = d.get((r - to) as usize..(r - from) as usize)?;
    Some(
        match read.iter().rev().position(|x| x.into_ticks() >= held) {
            Some(i) => from + i as u32,
            None => to,
        },
    )
}

impl<W: TableWord> Sides<'_, '_, W> {
    /// [`Sides::crossing`] on two per-step tables `a` (acceleration) and
    /// `d` (deceleration): the same steps read, the same answer.
    pub(in crate::player) fn crossing_direct(&self, a: &[W], d: &[W], p: u32, r: u32) -> u32 {
        let dir = self.toward(p).1;
        let (walked_down, slack) = match dir {
            -1 => ((p - self.cruise).min(r), self.slack),
            1 => (0, self.slack),
            _ => (0, self.decel_slack),
        };
        if walked_down > 0 {
            if !self.falls_ahead(p, r, walked_down) {
                if let Some(j) = self.down_direct(a, d, p, r, walked_down) {
                    return j;
                }
            }
            if walked_down == r {
                return r;
            }
        }
        let p = self.walked_by(p, dir, walked_down);
        let dir = self.toward(p).1;
        if dir == 0 {
            // Held: one period to compare the deceleration table with.
            let Some(held) = ticks_at(a, p) else {
                return r;
            };
            // Often the first: a long move's deceleration ramp joins at
            // its top.
            match scan_held(d, r, walked_down, walked_down + 1, held) {
                Some(j) if j == walked_down => return j,
                None => return r,
                _ => {}
            }
            let from = past_shorter(d, r, walked_down, r, slack, held);
            return scan_held(d, r, from, r, held).unwrap_or(r);
        }
        // Walking up to the cruise position, then held there.
        let at = |j: u32| self.walked_by(p, dir, j - walked_down);
        let faster = |j: u32| match (ticks_at(d, r - 1 - j), ticks_at(a, at(j))) {
            (Some(x), Some(y)) => Some(x < y),
            _ => None,
        };
        match faster(walked_down) {
            Some(false) => return walked_down,
            None => return r,
            Some(true) => {}
        }
        let from = search::past(walked_down, r, &mut |j| match (
            ticks_at(d, r - 1 - j),
            ticks_at(a, at(j)),
        ) {
            (Some(x), Some(y)) => faster_by(x, slack, y),
            _ => false,
        });
        for j in from..r {
            match faster(j) {
                Some(true) => {}
                Some(false) => return j,
                None => return r,
            }
        }
        r
    }

    /// [`Sides::crossing_direct`] over the first `walked_down` of the
    /// last `r` steps, the acceleration side walking down from `p`: the
    /// step found, `Some(r)` when a table ends, `None` when none of them
    /// is.
    #[inline(never)]
    fn down_direct(&self, a: &[W], d: &[W], p: u32, r: u32, walked_down: u32) -> Option<u32> {
        // Walking down, the acceleration side is never faster than at `p`
        // but for its slack: a deceleration step more than both ramps'
        // slack faster than that has every step before it faster than the
        // acceleration side.
        let at_p = ticks_at(a, p).unwrap_or(0);
        let both = self.slack;
        let from = past_shorter(d, r, 0, walked_down, both, at_p);
        // Then a block at a time: the deceleration table at a block's last
        // step more than both slacks faster than the acceleration table at
        // its first (its slowest and fastest there but for their slack) is
        // faster at every step of it. A block not cleared is halved, and
        // read step by step from `SCAN_BLOCK` steps down.
        let mut found = None;
        blocks_down(from, walked_down, walked_down - from, true, |j, end| {
            let clear = match (ticks_at(d, r - end), ticks_at(a, p - j)) {
                (Some(x), Some(y)) => faster_by(x, both, y),
                _ => false,
            };
            if clear {
                return Block::Pass;
            }
            if end - j > SCAN_BLOCK {
                return Block::Split;
            }
            for j in j..end {
                let (Some(x), Some(y)) = (ticks_at(d, r - 1 - j), ticks_at(a, p - j)) else {
                    found = Some(r);
                    return Block::Stop;
                };
                if x >= y {
                    found = Some(j);
                    return Block::Stop;
                }
            }
            Block::Pass
        });
        found
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use crate::player::planning::plan::{Known, Sides};
    use crate::player::planning::search;
    use crate::player::ramps::ramp::{Cursor, Ramp};
    use proptest::prelude::*;
    use std::vec::Vec;

    /// The crossing as its definition reads it, one step at a time: the
    /// first of the last `r` steps at which the deceleration table, read at
    /// the steps that remain, is not faster than the acceleration side
    /// walking one step a step from `p` towards `cruise`; `r` when none is
    /// or a table ends first.
    fn walked(a: &[u16], d: &[u16], p: u32, cruise: u32, r: u32) -> u32 {
        let mut at = p;
        for j in 0..r {
            let (Some(&x), Some(&y)) = (d.get((r - 1 - j) as usize), a.get(at as usize)) else {
                return r;
            };
            if x >= y {
                return j;
            }
            at = match at.cmp(&cruise) {
                core::cmp::Ordering::Less => at + 1,
                core::cmp::Ordering::Greater => at - 1,
                core::cmp::Ordering::Equal => at,
            };
        }
        r
    }

    /// A table falling from about `start` ticks, each entry `drop` below
    /// the one before give or take `jitter` (a table rounded by diffusion
    /// when `jitter` is 1, flat stretches where `drop` is 0).
    fn table(len: usize) -> impl Strategy<Value = Vec<u16>> {
        (
            1000u16..3000,
            proptest::collection::vec(
                (
                    prop_oneof![3 => Just(0u16), 2 => 0u16..3, 1 => 0u16..40],
                    0u16..3,
                ),
                len,
            ),
        )
            .prop_map(|(start, steps)| {
                let mut p = start;
                steps
                    .iter()
                    .map(|&(drop, jitter)| {
                        p = p.saturating_sub(drop).max(20);
                        p + jitter
                    })
                    .collect()
            })
    }

    fn sides<'t>(
        accel: Ramp<'t, u16>,
        decel: Ramp<'t, u16>,
        cruise: u32,
        tops: &'t [Option<Cursor>; 2],
    ) -> Sides<'t, 't, u16> {
        let decel_fastest = decel.fastest();
        Sides {
            accel,
            decel,
            accel_last: accel.len_steps() - 1,
            decel_last: decel.len_steps() - 1,
            decel_fastest,
            cap: accel.first_faster_than(decel_fastest),
            cruise,
            cruise_last: false,
            slack: search::slack(&accel) + search::slack(&decel),
            decel_slack: search::slack(&decel),
            known: std::boxed::Box::leak(std::boxed::Box::new(Known {
                tops: *tops,
                fall: search::fall(
                    &accel,
                    &decel,
                    search::slack(&decel),
                    search::one_ramp(&accel, &decel),
                ),
            })),
            recent: core::cell::Cell::new([None; 2]),
            crossed: core::cell::Cell::new(None),
            read_a: core::cell::Cell::new(None),
        }
    }

    /// Every move on two tables that end differently (the acceleration
    /// table falling to its top, the deceleration table rising to it, out
    /// of order): a crossing read at both tops reads their cursors, and a
    /// crossing read at one top only does not.
    #[test]
    fn the_crossing_reads_the_tops_only_at_the_tops() {
        let falling = |i: u16| 3000 - 50 * i;
        let a: Vec<u16> = (0..38).map(falling).chain([1010, 1000]).collect();
        let d: Vec<u16> = (0..38).map(falling).chain([995, 1005]).collect();
        let pairs = |t: &[u16]| -> Vec<(u16, u16)> { t.iter().map(|&x| (x, 1)).collect() };
        let (sa, sd) = (pairs(&a), pairs(&d));
        let (ra, rd) = (Ramp::segments(&sa), Ramp::segments(&sd));
        let tops = [Cursor::at(&ra, 39), Cursor::at(&rd, 39)];
        for cruise in 0..40 {
            let cursors = sides(ra, rd, cruise, &tops);
            for (p, r) in (0..40).flat_map(|p| (1..=40).map(move |r| (p, r))) {
                let want = walked(&a, &d, p, cruise, r);
                assert_eq!(cursors.crossing(p, r), want, "{p} {cruise} {r}");
            }
        }
    }

    /// Walking down, a block of steps is passed over only where the
    /// deceleration table at its last step is more than both tables'
    /// slack faster than the acceleration table at its first: here the
    /// two tables are a tick or two apart where they cross, the
    /// acceleration table dipping by two ticks, and a block whose ends
    /// are less than the slacks apart holds the crossing (found by
    /// proptest against a block test without the slack).
    #[test]
    fn a_block_walked_down_is_passed_only_past_both_slacks() {
        let a: Vec<u16> = [1669, 1669, 1668, 1666, 1668]
            .into_iter()
            .chain([1666; 35])
            .collect();
        let d: Vec<u16> = [
            1806, 1806, 1806, 1806, 1802, 1802, 1802, 1802, 1767, 1767, 1767, 1735, 1730, 1728,
            1728, 1707, 1690, 1690, 1690, 1668, 1668, 1667, 1667,
        ]
        .into_iter()
        .chain([1666; 17])
        .collect();
        let (p, cruise, r) = (4, 0, 25);
        let want = walked(&a, &d, p, cruise, r);
        let tops = [None; 2];
        let direct = sides(Ramp::steps(&a), Ramp::steps(&d), cruise, &tops);
        assert_eq!(direct.crossing_direct(&a, &d, p, r), want);
    }

    /// On one table both ways, steep then nearly flat with a tick of
    /// diffusion, the direct crossing answers as the step-by-step
    /// definition does for every position, cruise position and number of
    /// steps: walking down with the deceleration read exactly as far
    /// ahead as [`Fall`](crate::table::fall::Fall) clears, and a step nearer.
    #[test]
    fn the_crossing_on_one_table_is_the_walks_everywhere() {
        let steep = (0..24u16).map(|i| 3000 - 90 * i);
        let flat = (0..40u16).map(|i| 900 - i / 4 + [0, 1, 0, 0, 1][usize::from(i % 5)]);
        let t: Vec<u16> = steep.chain(flat).collect();
        let n = t.len() as u32;
        let tops = [None; 2];
        for cruise in 0..n {
            let direct = sides(Ramp::steps(&t), Ramp::steps(&t), cruise, &tops);
            for (p, r) in (0..n).flat_map(|p| (1..=n).map(move |r| (p, r))) {
                let want = walked(&t, &t, p, cruise, r);
                assert_eq!(
                    direct.crossing_direct(&t, &t, p, r),
                    want,
                    "{p} {cruise} {r}"
                );
            }
        }
    }

    proptest! {
        /// The direct crossing on two per-step tables, and the cursors'
        /// crossing on the same periods as segments of one step each,
        /// answer as the step-by-step definition does: tables with flat
        /// stretches and a tick of diffusion, the acceleration side
        /// walking up, down or held, any number of steps within reach.
        #[test]
        fn the_crossing_is_the_walks(
            a in table(40), d in table(40),
            p in 0u32..40, cruise in 0u32..40, r in 1u32..=40,
        ) {
            let want = walked(&a, &d, p, cruise, r);
            let tops = [None; 2];
            let direct = sides(Ramp::steps(&a), Ramp::steps(&d), cruise, &tops);
            prop_assert_eq!(direct.crossing_direct(&a, &d, p, r), want);
            let pairs = |t: &[u16]| -> Vec<(u16, u16)> { t.iter().map(|&x| (x, 1)).collect() };
            let (sa, sd) = (pairs(&a), pairs(&d));
            let (ra, rd) = (Ramp::segments(&sa), Ramp::segments(&sd));
            // With the cursors at the tops, as a player keeps them: a step
            // read at both tops reads them.
            let tops = [Cursor::at(&ra, 39), Cursor::at(&rd, 39)];
            let cursors = sides(ra, rd, cruise, &tops);
            prop_assert_eq!(cursors.crossing(p, r), want);
        }

        /// The same on one table both ways, where the deceleration read
        /// far enough ahead is faster at every step of a walk down
        /// ([`Fall`](crate::table::fall::Fall)).
        #[test]
        fn the_crossing_on_one_table_is_the_walks(
            a in table(40), p in 0u32..40, cruise in 0u32..40, r in 1u32..=40,
        ) {
            let want = walked(&a, &a, p, cruise, r);
            let tops = [None; 2];
            let direct = sides(Ramp::steps(&a), Ramp::steps(&a), cruise, &tops);
            prop_assert_eq!(direct.crossing_direct(&a, &a, p, r), want);
        }
    }
}
