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
use crate::player::planning::plan::{Plan, Run, Source};
use crate::player::{Layout, Player};

impl<W: TableWord> Plan<'_, W> {
    /// Drops the plan's last `tail` steps (none handed to a run yet).
    pub(crate) fn cut(&mut self, mut tail: u32) {
        while tail > 0 && self.len > 0 {
            let s = &mut self.stretches[self.len - 1];
            if s.total <= tail {
                tail -= s.total;
                self.len -= 1;
                continue;
            }
            let keep = (s.total - tail) as usize;
            if let Source::Run(run) = &mut s.source {
                *run = match core::mem::replace(run, Run::empty()) {
                    Run::Up(periods) => Run::Up(periods.as_slice()[..keep].iter()),
                    // Played last to first: the first periods play last.
                    Run::Down(periods) => {
                        let periods = periods.as_slice();
                        Run::Down(periods[periods.len() - keep..].iter())
                    }
                    Run::Hold(period, _) => Run::Hold(period, keep as u32),
                    Run::Ended(periods) => Run::Ended(periods),
                };
            }
            s.total -= tail;
            s.count -= tail;
            tail = 0;
        }
    }
}

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    /// Starts a move of `steps` steps that ends at speed: as the first
    /// `steps` of a move of `steps + tail` (at rest when `tail` is 0).
    /// From rest when `entry` is `None`; else from a speed of `entry`
    /// ticks a step, entering the acceleration ramp at its last step not
    /// shorter (the fastest not faster), that period counted as the one
    /// played before the move.
    pub(crate) fn begin_joined(&mut self, steps: u32, tail: u32, entry: Option<u32>) {
        self.restore_decel();
        self.endless = false;
        self.extended = 0;
        let empty = self.known.tops[0].is_none() || self.known.tops[1].is_none();
        if empty || steps == 0 {
            self.plan.clear();
            self.follow(0);
            return;
        }
        let (from, before) = match entry {
            Some(ticks) if ticks > 0 => (self.cruise_position(ticks).0, ticks),
            _ => (0, 0),
        };
        self.plan_steps(from, steps.saturating_add(tail));
        self.plan.cut(tail.min(u32::MAX - steps));
        self.follow(before);
    }

    /// Has the move playing end at speed: as the steps that remain of a
    /// move `tail` steps longer (at rest when `tail` is 0), from where it
    /// stands. `false`, changing nothing, at rest or while an abort plays.
    pub(crate) fn rejoin(&mut self, tail: u32) -> bool {
        let remaining = self.remaining();
        if remaining == 0 || self.aborting {
            return false;
        }
        let (acc, decelerating, current) = self.now();
        let from = match (current, decelerating) {
            (0, _) => 0,
            (_, true) => self.accel_entry(current),
            (_, false) => acc,
        };
        self.plan_steps(from, remaining.saturating_add(tail));
        self.plan.cut(tail.min(u32::MAX - remaining));
        self.follow(current);
        true
    }

    /// The period of the move's last step, in ticks, as planned (0 for a
    /// move of no steps): where a move that joins the next ends.
    pub(crate) fn last_step_period(&self) -> u32 {
        let stretches = &self.plan.stretches[..self.plan.len];
        match stretches.last() {
            Some(s) if s.total > 0 => self.period_read(s, s.read_at(s.total - 1)),
            _ => 0,
        }
    }

    /// Steps a stop from a speed of `ticks` a step takes on the
    /// deceleration ramp (0 when it is slower than every entry).
    pub(crate) fn stop_steps_from(&self, ticks: u32) -> u32 {
        self.stop_steps(ticks)
    }

    /// The deceleration ramp's period at step `pos`, in ticks (`None`
    /// past its last step).
    pub(crate) fn decel_period(&self, pos: u32) -> Option<u32> {
        self.decel_ticks(pos)
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
