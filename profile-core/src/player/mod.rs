//! Playing tables in firmware: a move of `S` steps from an acceleration
//! table and a deceleration table, one call per step.
//!
//! A move follows two sides:
//!
//! - the acceleration side: a cursor on the acceleration ramp that walks one
//!   step per step towards the cruise position (up at the start, up or down
//!   after [`Player::set_cruise`]);
//! - the deceleration side: the deceleration ramp read backwards, indexed by
//!   the steps that remain, so the last step of the move is always the
//!   deceleration ramp's slowest entry.
//!
//! The acceleration side plays, no faster than the deceleration ramp's
//! fastest entry while that ramp is out of reach, until the deceleration
//! side, read at the steps that remain, is not faster; from then on the
//! deceleration ramp plays to the end. That gives the full trapezoid for long
//! moves and the triangle for short ones, with the switch point exactly where
//! the two ramps cross, for symmetric and asymmetric tables alike; the move
//! ends at exactly `S` steps, at rest, and every table plays exactly as it is
//! written (a diffused table's one-tick ties included).
//!
//! [`Player::start`], [`Player::stop`] and [`Player::set_cruise`] plan: they
//! find where the move changes from one stretch of a table to another (at
//! most a few per move), searching the tables once. [`Player::next_period`]
//! plays: a countdown, a load and an index step, with a short refill at the
//! few places the plan changes stretch (or a held or segment table changes
//! entry). No division, no floating point and no panic in playing, on any
//! input.
//!
//! ```
//! use profile_core::player::{Player, Ramp};
//!
//! static ACCEL: [u16; 4] = [4000, 2500, 2000, 1800];
//! let mut player = Player::new(Ramp::steps(&ACCEL));
//! player.start(10);
//! let mut periods = [0u16; 10];
//! for p in periods.iter_mut() {
//!     *p = player.next_period().unwrap();
//! }
//! assert_eq!(player.next_period(), None);
//! assert_eq!(periods, [4000, 2500, 2000, 1800, 1800, 1800, 1800, 2000, 2500, 4000]);
//! ```

mod plan;
mod ramp;

use core::slice;

use crate::base::timer::TableWord;
use plan::{Plan, Sides};
use ramp::Cursor;
pub use ramp::Ramp;

/// Plays moves from an acceleration ramp and a deceleration ramp.
#[derive(Clone, Debug)]
pub struct Player<'a, W> {
    accel: Ramp<'a, W>,
    decel: Ramp<'a, W>,
    accel_last: u32,
    decel_last: u32,
    /// The deceleration ramp's shortest period: no move runs faster while
    /// that ramp is out of reach.
    decel_fastest: u32,
    /// The first acceleration step faster than `decel_fastest`.
    cap: u32,
    cruise: u32,
    /// The run being played: `left` periods read from `table` at `index`,
    /// `index` moving by `stride` (wrapping: 1, 0 or -1) per step.
    table: &'a [W],
    index: u32,
    stride: u32,
    left: u32,
    /// Steps in the run when it began.
    run_len: u32,
    /// The period played before the run began, in ticks (0 at rest).
    before: u32,
    /// Steps of the plan after the run.
    rest: u32,
    plan: Plan,
}

impl<'a, W: TableWord> Player<'a, W> {
    /// A player that decelerates along the acceleration ramp read backwards.
    pub fn new(accel: Ramp<'a, W>) -> Self {
        Self::with_decel(accel, accel)
    }

    /// A player with its own deceleration ramp (also ordered slow to fast),
    /// for asymmetric moves.
    pub fn with_decel(accel: Ramp<'a, W>, decel: Ramp<'a, W>) -> Self {
        let accel_last = accel.len_steps().saturating_sub(1);
        let decel_fastest = decel.fastest();
        Player {
            accel,
            decel,
            accel_last,
            decel_last: decel.len_steps().saturating_sub(1),
            decel_fastest,
            cap: accel.first_faster_than(decel_fastest),
            cruise: accel_last,
            table: &[],
            index: 0,
            stride: 0,
            left: 0,
            run_len: 0,
            before: 0,
            rest: 0,
            plan: Plan::EMPTY,
        }
    }

    fn sides(&self) -> Sides<'_, 'a, W> {
        Sides {
            accel: &self.accel,
            decel: &self.decel,
            accel_last: self.accel_last,
            decel_last: self.decel_last,
            decel_fastest: self.decel_fastest,
            cap: self.cap,
            cruise: self.cruise,
        }
    }

    /// Follows `plan` from its start: nothing played of it yet.
    fn follow(&mut self, plan: Plan, before: u32) {
        self.rest = plan.steps();
        self.plan = plan;
        self.left = 0;
        self.run_len = 0;
        self.before = before;
    }

    /// Starts a move of `steps` steps from rest, cruising at the top of the
    /// acceleration ramp. A move on an empty ramp has no steps.
    pub fn start(&mut self, steps: u32) {
        self.cruise = self.accel_last;
        let empty = self.accel.period_at(0).is_none() || self.decel.period_at(0).is_none();
        let plan = if empty || steps == 0 {
            Plan::EMPTY
        } else {
            self.sides().plan(0, steps)
        };
        self.follow(plan, 0);
    }

    /// Cruises at step `pos` of the acceleration ramp (the entry index for a
    /// table without divider) instead of its top; takes effect by walking the
    /// ramp up or down one step per step. Clamped to the ramp.
    pub fn set_cruise(&mut self, pos: u32) {
        self.cruise = pos.min(self.accel_last);
        let (acc, decelerating) = self.state();
        let remaining = self.remaining();
        if remaining > 0 && !decelerating {
            let last = self.last_period();
            let plan = self.sides().plan(acc, remaining);
            self.follow(plan, last);
        }
    }

    /// Decelerates from the current speed to rest: the deceleration ramp is
    /// entered at its entry nearest the current period that is not faster,
    /// and the move ends when the ramp's slowest entry has played (at once,
    /// when the motor already runs slower than that entry). A stop never
    /// lengthens a move.
    pub fn stop(&mut self) {
        let remaining = self.remaining();
        if remaining == 0 {
            return;
        }
        let current = self.last_period();
        // Not moving yet, or already slower than the ramp's slowest entry:
        // at rest now.
        if current == 0 || self.period_dec(0) < current {
            self.follow(Plan::EMPTY, current);
            return;
        }
        let needed = self.entry_point(current) + 1;
        if needed < remaining {
            let mut plan = Plan::EMPTY;
            let (acc, _) = self.state();
            plan.stretches[0] = plan::Stretch {
                decel: true,
                at: Cursor::at(&self.decel, needed - 1).unwrap_or(Cursor::ZERO),
                dir: -1,
                count: needed,
                total: needed,
                acc,
                acc_dir: 0,
                decelerating: true,
            };
            plan.len = 1;
            self.follow(plan, current);
        }
    }

    /// The largest position of the deceleration ramp whose period is not
    /// faster than `current`: periods fall along the ramp, so a binary
    /// search, then a bounded look past the boundary for the ties of
    /// diffused tables.
    fn entry_point(&self, current: u32) -> u32 {
        let (mut lo, mut hi) = (0u32, self.decel_last);
        if self.period_dec(hi) >= current {
            lo = hi;
        } else {
            while hi - lo > 1 {
                let mid = lo + (hi - lo) / 2;
                if self.period_dec(mid) >= current {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
        }
        for _ in 0..16 {
            if lo >= self.decel_last || self.period_dec(lo + 1) < current {
                break;
            }
            lo += 1;
        }
        lo
    }

    fn period_dec(&self, pos: u32) -> u32 {
        self.decel.period_at(pos).map_or(0, |w| w.into_ticks())
    }

    /// Where the acceleration side stands after the steps played, and
    /// whether the deceleration ramp has taken over.
    fn state(&self) -> (u32, bool) {
        let Some(s) = self
            .plan
            .stretches
            .get(self.plan.at)
            .filter(|_| self.plan.at < self.plan.len)
        else {
            return (0, false);
        };
        let played = s.total - s.count - self.left;
        (s.acc_after(played), s.decelerating)
    }

    /// The period of the last step played, in ticks (0 at rest).
    fn last_period(&self) -> u32 {
        if self.left < self.run_len {
            let last = self.index.wrapping_sub(self.stride);
            self.table.get(last as usize).map_or(0, |w| w.into_ticks())
        } else {
            self.before
        }
    }

    /// Steps left in the move.
    pub fn remaining(&self) -> u32 {
        self.left + self.rest
    }

    /// `true` when the move has played all its steps.
    pub fn is_done(&self) -> bool {
        self.remaining() == 0
    }

    /// The period of the next step, in ticks, or `None` when the move is done.
    #[inline]
    pub fn next_period(&mut self) -> Option<W> {
        if self.left == 0 {
            return self.refill();
        }
        self.left -= 1;
        let period = self.table.get(self.index as usize).copied();
        self.index = self.index.wrapping_add(self.stride);
        period
    }

    /// Begins the plan's next run and plays its first step.
    #[cold]
    #[inline(never)]
    fn refill(&mut self) -> Option<W> {
        self.before = self.last_period();
        let n = self.next_run()?;
        self.rest -= n;
        self.left = n - 1;
        let period = self.table.get(self.index as usize).copied();
        self.index = self.index.wrapping_add(self.stride);
        period
    }

    /// Sets up the next run from the plan; its length, or `None` when the
    /// plan is played.
    fn next_run(&mut self) -> Option<u32> {
        while self.plan.at < self.plan.len {
            let at = self.plan.at;
            if self.plan.stretches[at].count > 0 {
                break;
            }
            // The next stretch: nothing of it played yet.
            if at + 1 >= self.plan.len {
                return None;
            }
            self.plan.at += 1;
        }
        let s = self.plan.stretches.get_mut(self.plan.at)?;
        if s.count == 0 {
            return None;
        }
        let ramp = if s.decel { self.decel } else { self.accel };
        let forward = s.dir > 0;
        let n = match ramp {
            Ramp::Steps { periods, hold } if hold <= 1 => {
                // The whole stretch is one run over the table itself.
                self.table = periods;
                self.index = s.at.pos;
                self.stride = s.dir as i32 as u32;
                s.count
            }
            _ => {
                let n = if s.dir == 0 {
                    s.count
                } else {
                    s.at.left_in_entry(&ramp, forward).min(s.count)
                };
                self.table = match ramp {
                    Ramp::Steps { periods, .. } => periods,
                    Ramp::Segments(pairs) => pairs
                        .get(s.at.entry as usize)
                        .map_or(&[][..], |p| slice::from_ref(&p.0)),
                };
                self.index = match ramp {
                    Ramp::Steps { .. } => s.at.entry,
                    Ramp::Segments(_) => 0,
                };
                self.stride = 0;
                // On to the next entry in the stretch's direction: to this
                // entry's last step that way, then one more.
                if s.dir != 0 && n < s.count {
                    if forward {
                        s.at.pos += n - 1;
                        s.at.within += n - 1;
                        s.at.forward(&ramp, u32::MAX);
                    } else {
                        s.at.pos -= n - 1;
                        s.at.within -= n - 1;
                        s.at.backward(&ramp);
                    }
                }
                n
            }
        };
        s.count -= n;
        self.run_len = n;
        Some(n)
    }
}
