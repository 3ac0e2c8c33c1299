//! Planning, on two indexed ramps, a move that reaches its cruise
//! position before the deceleration takes over: the most common plan (a
//! start of a long move, a new cruise speed or target while cruising),
//! written out in the few reads it needs.
//!
//! Such a move walks to the cruise position, holds there, and
//! decelerates from the deceleration ramp's last entry not shorter than
//! the cruise position's period: the crossing of a held side is one
//! search. It plans the stretches [`Sides::plan`](crate::player::planning::plan::Sides)
//! plans for it; the other cases (a walk capped by the deceleration
//! ramp's fastest entry, a crossing while walking, a walk down into reach
//! that neither the ramps' [`Fall`](crate::table::fall::Fall) nor the
//! buckets clear) are left to that planner.

use crate::base::timer::TableWord;
use crate::player::planning::crossing::{Block, blocks_down, buckets_faster};
use crate::player::planning::plan::{Source, Stretch};
use crate::player::planning::reader::RunRead;
use crate::player::ramps::ramp::{Cursor, Ramp};
use crate::player::{Layout, Player};
use crate::table::runs::{IndexedRuns, period};

/// The shortest block of a walk down into reach the buckets are asked
/// to clear; a block that short they do not clear leaves the plan to the
/// general planner, which reads it.
const BUCKETS_BLOCK: u32 = 64;

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    /// Plans `r` steps from `p` (the acceleration side's position) if
    /// both ramps are indexed, the acceleration side is never faster than
    /// the deceleration ramp's fastest entry, and it reaches the cruise
    /// position without the deceleration taking over: walking up, before
    /// the deceleration ramp is in reach; walking down, where the
    /// deceleration ramp stands far enough ahead to be faster at every
    /// step in reach ([`Fall`](crate::table::fall::Fall)), or where the buckets
    /// show it, a block of steps at a time. `false`, planning nothing,
    /// otherwise. `held`, if given, is the cursor at the cruise position.
    #[inline(never)]
    pub(in crate::player) fn plan_cruising(
        &mut self,
        p: u32,
        r: u32,
        held: Option<Cursor>,
    ) -> bool {
        let (Ramp::Indexed(a), Ramp::Indexed(d)) = (self.accel, self.decel) else {
            return false;
        };
        let (c, l) = (self.cruise, self.decel_last);
        let walked = p.abs_diff(c);
        // Out of reach for `far` steps: all but the deceleration ramp's
        // (none when the move is shorter); then the deceleration ramp
        // stands at its step `reach`: its top, or the last step the move
        // reaches.
        let Some(last) = r.checked_sub(1).filter(|_| p.max(c) < self.cap) else {
            return false;
        };
        let far = last.saturating_sub(l);
        let reach = last - far;
        // The walk's steps within reach: none may be a crossing.
        let within = walked.saturating_sub(far);
        if within > 0 && (p < c || within > reach || !self.clear_down(a, d, p - far, reach, within))
        {
            return false;
        }
        let [Some(a_top), Some(d_top)] = &self.known.tops else {
            return false;
        };
        let at_c = match held.filter(|h| h.pos == c) {
            Some(at) => at,
            None => match Cursor::at(&self.accel, c) {
                Some(at) => at,
                None => return false,
            },
        };
        let held_ticks = period(at_c.frac, at_c.interval);
        // The deceleration ramp's last step up to `top` (where it stands
        // when the walk ends) not shorter than the held period, and the
        // cursor there: its top first, when the walk ends there or out of
        // reach (a long move's deceleration joins there); on one ramp both ways,
        // the cruise position itself when no later step is known to be
        // as long, else a search from the run after it. `None` when no
        // step is that long.
        let top = reach - within;
        let one_ramp = core::ptr::eq(a.runs(), d.runs()) && c <= top;
        let (entry, entry_at) = if top == l && period(d_top.frac, d_top.interval) >= held_ticks {
            (Some(l), *d_top)
        } else if one_ramp && self.cruise_last {
            (Some(c), at_c)
        } else {
            let from = if one_ramp { at_c.entry + 1 } else { 0 };
            let mut read = RunRead::new(d);
            let found = read.last_at_least(top, held_ticks, self.decel_slack, from);
            let at = found.and_then(|pos| read.cursor(pos));
            (found, at.unwrap_or(Cursor::ZERO))
        };
        // The walk from the top's cursor, or near where the plan played.
        let walk = match walked {
            0 => None,
            _ if p == self.accel_last => Some(*a_top),
            _ => {
                let plan = &self.plan;
                match plan.stretches[..plan.len].get(plan.at) {
                    Some(Stretch {
                        decel: false,
                        source: Source::At(at),
                        ..
                    }) => Cursor::near(Some(*at), &self.accel, p),
                    _ => Cursor::at(&self.accel, p),
                }
            }
        };
        let plan = &mut self.plan;
        plan.clear();
        if walked > 0 {
            let dir = if p < c { 1 } else { -1 };
            let from = Source::At(walk.unwrap_or(Cursor::ZERO));
            plan.push(Stretch::new(from, false, p, dir, walked, p, dir));
        }
        // Held out of reach, then within reach until the deceleration.
        let crossing = entry.map_or(reach + 1, |pos| reach - pos);
        for n in [far.saturating_sub(walked), crossing - within] {
            if n > 0 {
                plan.push(Stretch::new(Source::At(at_c), false, c, 0, n, c, 0));
            }
        }
        if let Some(pos) = entry {
            let from = Source::At(entry_at);
            plan.push(Stretch::new(from, true, pos, -1, pos + 1, c, 0));
        }
        true
    }
}

impl<W: TableWord, L: Layout> Player<'_, W, L> {
    /// Whether walking down `within` steps from `y` to the cruise
    /// position, the deceleration ramp from its step `reach`, has no
    /// crossing: the deceleration ramp stands far enough ahead to be
    /// faster at each step ([`Fall::clears`](crate::table::fall::Fall::clears)), or
    /// else, a block of them at a time, the deceleration ramp at a
    /// block's last step, more than both ramps' slack faster than the
    /// acceleration side at its first, is faster than it at each of them
    /// (a step further up is not slower but for the slack, a step walked
    /// down not faster): for the whole walk, or block by block
    /// ([`cleared_down`]).
    #[inline(always)]
    fn clear_down(
        &self,
        a: IndexedRuns<'_>,
        d: IndexedRuns<'_>,
        y: u32,
        reach: u32,
        within: u32,
    ) -> bool {
        let (slack, decel_slack) = (self.slack, self.decel_slack);
        reach
            .checked_sub(y)
            .is_some_and(|ahead| self.known.fall.clears(self.cruise + 1, y, ahead))
            || buckets_faster(a, d, reach + 1 - within, y, slack, decel_slack)
            || cleared_down(a, d, reach, y, within, slack, decel_slack)
    }
}

/// Whether the buckets of indexed ramps `a` and `d` show the
/// deceleration ramp faster than the acceleration side at each of `n`
/// steps walking down, the deceleration ramp from its step `l`, the
/// acceleration side from `y` ([`buckets_faster`]), a block of steps at a
/// time ([`blocks_down`]); a block of [`BUCKETS_BLOCK`] steps or fewer
/// they do not clear answers `false`. (The caller asked the whole walk.)
///
/// Walking down together, the two steps a block compares are its length
/// closer than `l + 1 - y`, and the buckets tell apart only steps some
/// buckets apart (a step's bound is its bucket's first period, or the
/// next bucket's, and the slack): the blocks are four buckets shorter
/// than `l + 1 - y`, all alike (on one ramp both ways, each then as far
/// apart as any), or half the walk when that leaves none.
#[inline(never)]
fn cleared_down(
    a: IndexedRuns<'_>,
    d: IndexedRuns<'_>,
    l: u32,
    y: u32,
    n: u32,
    slack: u32,
    decel_slack: u32,
) -> bool {
    let apart = (l + 1).saturating_sub(y);
    let buckets = 4u32 << d.buckets().shift.max(a.buckets().shift).min(30);
    let size = match apart.saturating_sub(buckets) {
        0 => n / 2,
        size => size,
    };
    blocks_down(0, n, size, false, |j, end| {
        if buckets_faster(a, d, l + 1 - end, y - j, slack, decel_slack) {
            Block::Pass
        } else if end - j > BUCKETS_BLOCK {
            Block::Split
        } else {
            Block::Stop
        }
    })
}

#[cfg(test)]
mod tests {
    extern crate std;
    use crate::player::planning::plan::Plan;
    use crate::player::{Compressed, Player};
    use crate::table::runs::{Expand, RunIndex};
    use core_test_support::{cases, falling_runs, padded};
    use proptest::prelude::*;
    use proptest::test_runner::{Config, TestRunner};
    use std::string::String;
    use std::vec::Vec;

    /// A plan's stretches, every field written out (on compressed ramps
    /// each reads from a cursor, which it shows).
    fn stretches(plan: &Plan<'_, u16>) -> String {
        std::format!("{:?}", &plan.stretches[..plan.len])
    }

    /// Where the plan written out applies (a start, a new cruise position
    /// or period, or a new target, after steps played, on one ramp both
    /// ways or two), it writes the stretches the planner of every case
    /// writes, stretch by stretch, cursors included; and it applies in a
    /// good share of those calls.
    #[test]
    fn the_plan_written_out_is_the_general_planners() {
        let mut runner = TestRunner::new(Config {
            cases: cases() * 4,
            failure_persistence: None,
            ..Config::default()
        });
        let (taken, asked) = (core::cell::Cell::new(0u32), core::cell::Cell::new(0u32));
        let ramps = (
            falling_runs(1 << 12),
            prop_oneof![Just(None), falling_runs(1 << 12).prop_map(Some)],
        );
        // The move, the steps played, then a new cruise position, a new
        // cruise period (a tick or two from one the ramp plays, or any),
        // or a new target (its steps from now), or none.
        let value = prop_oneof![
            (any::<prop::sample::Index>(), -2i64..=2).prop_map(|(at, by)| (Some(at), by)),
            any::<u16>().prop_map(|v| (None, i64::from(v))),
        ];
        let calls = (0u32..3000, 0u32..1500, 0u8..4, value, 0u32..3000);
        runner
            .run(
                &(ramps, calls),
                |((accel, decel), (steps, played, call, value, target))| {
                    let decel = decel.unwrap_or_else(|| accel.clone());
                    let (a_all, d_all) = (padded::<40>(&accel), padded::<40>(&decel));
                    let (a_index, d_index) = (RunIndex::new(&a_all), RunIndex::new(&d_all));
                    let mut player = if accel == decel {
                        Player::<u16, Compressed>::new(&a_index)
                    } else {
                        Player::<u16, Compressed>::new(&a_index).with_decel(&d_index)
                    };
                    player.start(steps);
                    for _ in 0..played {
                        player.next_period();
                    }
                    // A position, or a period in ticks.
                    let value = match value {
                        (Some(at), by) => {
                            let periods: Vec<u32> = Expand::new(&accel).collect();
                            let near = periods.get(at.index(periods.len().max(1))).copied();
                            (i64::from(near.unwrap_or(0)) + by).max(0) as u32
                        }
                        (None, v) => v as u32,
                    };
                    let mut held = None;
                    match call {
                        0 => player.set_cruise(value),
                        1 => {
                            let (pos, none_later, at) = player.cruise_position(value);
                            (player.cruise, player.cruise_last, held) =
                                (pos.min(player.accel_last), none_later, at);
                        }
                        _ => {}
                    }
                    let r = match call {
                        2 => target,
                        _ => player.remaining(),
                    };
                    let (p, decelerating, _) = player.now();
                    if r == 0 || decelerating {
                        return Ok(());
                    }
                    let (mut written, mut general) = (player.clone(), player.clone());
                    asked.set(asked.get() + 1);
                    if written.plan_cruising(p, r, held) {
                        taken.set(taken.get() + 1);
                        general.plan_by_sides(p, r);
                        prop_assert_eq!(stretches(&written.plan), stretches(&general.plan));
                    }
                    Ok(())
                },
            )
            .unwrap();
        std::println!(
            "the plan written out: {} of {} plans, each the general planner's",
            taken.get(),
            asked.get()
        );
        assert!(
            taken.get() * 4 > asked.get(),
            "{} of {}",
            taken.get(),
            asked.get()
        );
    }
}
