//! Planning, on two indexed ramps, a move that reaches its cruise
//! position before the deceleration ramp is in reach: the most common
//! plan (a start of a long move, a new cruise speed or target while
//! cruising), written out in the few reads it needs.
//!
//! Such a move walks to the cruise position, holds there, and
//! decelerates from the deceleration ramp's last entry not shorter than
//! the cruise position's period: the crossing of a held side is one
//! search, and the rest of [`Sides::plan`](super::plan::Sides)'s cases
//! (a walk capped by the deceleration ramp's fastest entry, a crossing
//! while walking) do not arise. It plans the stretches that planner plans.

use super::crossing::buckets_faster;
use super::plan::{Source, Stretch};
use super::ramp::{Cursor, Ramp};
use super::reader::RunRead;
use super::{Layout, Player};
use crate::base::timer::TableWord;
use crate::table::runs::period;

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    /// Plans `r` steps from `p` (the acceleration side's position) if
    /// both ramps are indexed, the acceleration side is never faster than
    /// the deceleration ramp's fastest entry, and it reaches the cruise
    /// position without the deceleration taking over: walking up, before
    /// the deceleration ramp is in reach; walking down, where the
    /// buckets show the deceleration ramp faster than it at every step in
    /// reach. `false`, planning nothing, otherwise. `held`, if given, is
    /// the cursor at the cruise position.
    #[inline(never)]
    pub(super) fn plan_cruising(&mut self, p: u32, r: u32, held: Option<Cursor>) -> bool {
        let (Ramp::Indexed(a), Ramp::Indexed(d)) = (self.accel, self.decel) else {
            return false;
        };
        let (c, l) = (self.cruise, self.decel_last);
        let walked = p.abs_diff(c);
        // Out of reach for `far` steps: all but the deceleration ramp's.
        let far = match r.checked_sub(l).and_then(|n| n.checked_sub(1)) {
            Some(far) if far > 0 && p.max(c) < self.cap => far,
            _ => return false,
        };
        // The walk's steps within reach, walking down: the deceleration
        // ramp at the last of them, more than both ramps' slack faster
        // than the acceleration side where it comes into reach, is faster
        // than it at each of them (a step further up is not slower but
        // for the slack, a step walked down not faster).
        let within = walked.saturating_sub(far);
        if within > 0
            && (p < c
                || within > l
                || !buckets_faster(a, d, l + 1 - within, p - far, self.slack, self.decel_slack))
        {
            return false;
        }
        let at_c = match held.filter(|h| h.pos == c) {
            Some(at) => Some(at),
            None => Cursor::at(&self.accel, c),
        };
        let ([Some(a_top), Some(d_top)], Some(at_c)) = (self.tops, at_c) else {
            return false;
        };
        let held = period(at_c.frac, at_c.interval);
        // The deceleration ramp's last step up to `top` (where it stands
        // when the walk ends) not shorter than the held period, and the
        // cursor there: its top first, when the walk ends out of reach (a
        // long move's deceleration joins there); on one ramp both ways,
        // the cruise position itself when no later step is known to be
        // as long, else a search from the run after it.
        let top = l - within;
        let one_ramp = core::ptr::eq(a.runs(), d.runs()) && c <= top;
        let entry = if within == 0 && period(d_top.frac, d_top.interval) >= held {
            Some((l, d_top))
        } else if one_ramp && self.cruise_last {
            Some((c, at_c))
        } else {
            let from = if one_ramp { at_c.entry + 1 } else { 0 };
            let mut read = RunRead::new(d);
            read.last_at_least(top, held, self.decel_slack, from)
                .map(|pos| (pos, read.cursor(pos).unwrap_or(Cursor::ZERO)))
        };
        // The walk from the top's cursor, or near where the plan played.
        let walk = match walked {
            0 => None,
            _ if p == self.accel_last => Some(a_top),
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
            plan.push(stretch(
                false,
                p,
                dir,
                walked,
                p,
                dir,
                walk.unwrap_or(Cursor::ZERO),
            ));
        }
        // Held out of reach, then within reach until the deceleration.
        let crossing = entry.map_or(l + 1, |(pos, _)| l - pos);
        for n in [far.saturating_sub(walked), crossing - within] {
            if n > 0 {
                plan.push(stretch(false, c, 0, n, c, 0, at_c));
            }
        }
        if let Some((pos, at)) = entry {
            plan.push(stretch(true, pos, -1, pos + 1, c, 0, at));
        }
        true
    }
}

/// A stretch read from cursor `at` (a compressed ramp's).
fn stretch<'a, W>(
    decel: bool,
    start: u32,
    dir: i8,
    count: u32,
    acc: u32,
    acc_dir: i8,
    at: Cursor,
) -> Stretch<'a, W> {
    Stretch {
        source: Source::At(at),
        decel,
        start,
        dir,
        count,
        total: count,
        acc,
        acc_dir,
        decelerating: decel && dir == -1,
    }
}
