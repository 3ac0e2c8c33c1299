//! Moves that end at speed, for moves that join: a move of `steps` steps
//! planned as one of `steps + tail` and cut after its first `steps`, so
//! that it ends at the speed from which the deceleration ramp stops in
//! `tail` steps, and the next move begins at a given speed.
//!
//! The cut keeps every rule of a move: the first `steps` of the longer
//! move play exactly as they would, and the longer move can always stop,
//! so the speed at its cut is one from which the next `tail` steps (the
//! moves after it) can still stop.

use crate::base::timer::TableWord;
use crate::player::planning::plan::{Run, Source};
use crate::player::{Layout, Player};

/// `run` without its last `n` steps (at most its steps).
fn shortened<W>(run: Run<'_, W>, n: u32) -> Run<'_, W> {
    let keep = |len: usize| len - (n as usize).min(len);
    match run {
        Run::Up(periods) => {
            let periods = periods.as_slice();
            Run::Up(periods[..keep(periods.len())].iter())
        }
        // Played last to first: the first periods play last.
        Run::Down(periods) => {
            let periods = periods.as_slice();
            Run::Down(periods[periods.len() - keep(periods.len())..].iter())
        }
        Run::Hold(period, left) => Run::Hold(period, left - n.min(left)),
        Run::Ended(periods) => Run::Ended(periods),
    }
}

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    /// Starts a move of `steps` steps that ends at speed: as the first
    /// `steps` of a move of `steps + tail` (at rest when `tail` is 0).
    /// From rest when `entry` is `None`; else from a speed of `entry`
    /// ticks a step, entering the acceleration ramp at its first step not
    /// longer (as a new end does while decelerating), that period counted
    /// as the one played before the move.
    #[inline(never)]
    pub(crate) fn begin_joined(&mut self, steps: u32, tail: u32, entry: Option<u32>) {
        let total = steps.saturating_add(tail);
        match entry {
            Some(ticks) if ticks > 0 && steps > 0 => {
                // A move of one step, its step not played: the player
                // stands at rest on the deceleration ramp, and a new end
                // from there enters the acceleration ramp at its first
                // entry not longer than the period played before, `ticks`
                // ([`Player::retarget`]).
                self.begin(1);
                self.before = ticks;
                if self.remaining() == 0 || !self.retarget(total) {
                    return self.begin(total);
                }
            }
            _ => self.begin(total),
        }
        self.cut(total - steps);
    }

    /// Has the move playing end at speed: as the steps that remain of a
    /// move `tail` steps longer (at rest when `tail` is 0), from where it
    /// stands ([`Player::retarget`], then cut). `false`, changing nothing,
    /// at rest or while an abort plays.
    #[inline(never)]
    pub(crate) fn rejoin(&mut self, tail: u32) -> bool {
        let remaining = self.remaining();
        let longer = remaining.saturating_add(tail);
        if remaining == 0 || !self.retarget_from(remaining, longer) {
            return false;
        }
        self.cut(longer - remaining);
        true
    }

    /// Drops the move's last `tail` steps, fewer than it has, none played
    /// yet of the stretches they are in but the first's: from the plan's
    /// stretches, last first, then from the run of its first stretch
    /// being played.
    #[inline(never)]
    fn cut(&mut self, mut tail: u32) {
        while tail > 0 && self.plan.len > 0 {
            let s = &mut self.plan.stretches[self.plan.len - 1];
            if s.count == s.total && s.total <= tail && self.plan.len > 1 {
                tail -= s.total;
                self.plan.len -= 1;
                continue;
            }
            // Its steps not yet handed to a run, then the run.
            let pending = s.count.min(tail);
            if let Source::Run(run) = &mut s.source {
                *run = shortened(core::mem::replace(run, Run::empty()), pending);
            }
            s.count -= pending;
            s.total -= pending;
            tail -= pending;
            let handed = tail.min(self.run.left());
            if handed > 0 {
                self.run = shortened(core::mem::replace(&mut self.run, Run::empty()), handed);
                s.total -= handed;
            }
            break;
        }
    }

    /// The period of the move's last step, in ticks, as planned (0 for a
    /// move of no steps): where a move that joins the next ends.
    #[inline(never)]
    pub(crate) fn last_step_period(&self) -> u32 {
        let stretches = &self.plan.stretches[..self.plan.len];
        match stretches.last() {
            Some(s) if s.total > 0 => self.period_read(s, s.read_at(s.total - 1)),
            _ => 0,
        }
    }

    /// The acceleration ramp's slowest and fastest periods in ticks and
    /// its steps: what the mean acceleration of a junction's rule is read
    /// from.
    pub(crate) fn accel_extent(&self) -> (u32, u32, u32) {
        let first = self.cruise_period_at(0);
        let last = self.cruise_period_at(self.accel_last);
        (first, last, self.accel_last)
    }

    /// The cruise position's period, in ticks.
    pub(crate) fn cruise_period(&self) -> u32 {
        self.cruise_period_at(self.cruise)
    }

    fn cruise_period_at(&self, pos: u32) -> u32 {
        crate::player::ramps::ramp::Cursor::at(&self.accel, pos)
            .map_or(0, |c| c.period(&self.accel).into_ticks())
    }
}
