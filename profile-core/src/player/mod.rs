//! Playing tables in firmware: a move of `S` steps from an acceleration
//! table and a deceleration table, one call per step.
//!
//! The period of each step is the slower of two candidates:
//!
//! - the acceleration side: a cursor on the acceleration ramp that walks one
//!   step per step towards the cruise position (up at the start, up or down
//!   after [`Player::set_cruise`]);
//! - the deceleration side: the deceleration ramp read backwards, indexed by
//!   the steps that remain, so the last step of the move is always the
//!   deceleration ramp's slowest entry.
//!
//! Taking the slower of the two gives the full trapezoid for long moves and
//! the triangle for short ones, with the switch point exactly where the two
//! ramps cross, for symmetric and asymmetric tables alike; the move ends at
//! exactly `S` steps, at rest. Consecutive periods never differ by more than
//! consecutive entries of the tables do.
//!
//! [`Player::next_period`] is O(1), with no division, no floating point and no
//! panic on any input. [`Player::stop`] searches the deceleration ramp once
//! (O(log n) for a per-step table, O(segments) for a segment table).
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

use crate::base::timer::TableWord;

/// A ramp to play: a table ordered from slow (rest) to fast.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ramp<'a, W> {
    /// One period per table entry, each held for `hold` steps (seed 000's
    /// `CountForAcc` divider; 1 plays every entry once).
    Steps {
        /// Periods in ticks, slowest first.
        periods: &'a [W],
        /// Steps per entry; 0 is taken as 1.
        hold: u32,
    },
    /// Seed 001's layout: `(period, steps)` per segment, slowest first.
    Segments(&'a [(W, W)]),
}

impl<'a, W: TableWord> Ramp<'a, W> {
    /// A per-step table, each entry played once.
    pub const fn steps(periods: &'a [W]) -> Self {
        Ramp::Steps { periods, hold: 1 }
    }

    /// A per-step table, each entry held for `hold` steps.
    pub const fn held(periods: &'a [W], hold: u32) -> Self {
        Ramp::Steps { periods, hold }
    }

    /// A segment table.
    pub const fn segments(pairs: &'a [(W, W)]) -> Self {
        Ramp::Segments(pairs)
    }

    /// Steps the ramp takes from rest to its top speed.
    pub fn len_steps(&self) -> u32 {
        match *self {
            Ramp::Steps { periods, hold } => {
                (periods.len() as u64 * hold.max(1) as u64).min(u32::MAX as u64) as u32
            }
            Ramp::Segments(pairs) => pairs
                .iter()
                .fold(0u32, |n, &(_, c)| n.saturating_add(c.into_ticks())),
        }
    }

    /// Period of the step at `pos` along the ramp (0 = slowest).
    pub fn period_at(&self, pos: u32) -> Option<W> {
        let c = Cursor::at(self, pos)?;
        Some(c.period(self))
    }
}

/// A position along a ramp, kept as (entry, step within entry) so that
/// moving by one step needs no division.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Cursor {
    pos: u32,
    entry: u32,
    within: u32,
}

impl Cursor {
    const ZERO: Cursor = Cursor {
        pos: 0,
        entry: 0,
        within: 0,
    };

    /// The cursor at step `pos`, or `None` past the end or on an empty ramp.
    fn at<W: TableWord>(ramp: &Ramp<'_, W>, pos: u32) -> Option<Cursor> {
        match *ramp {
            Ramp::Steps { periods, hold } => {
                let hold = hold.max(1);
                let entry = pos / hold;
                ((entry as usize) < periods.len()).then_some(Cursor {
                    pos,
                    entry,
                    within: pos % hold,
                })
            }
            Ramp::Segments(pairs) => {
                let mut start = 0u32;
                for (i, &(_, count)) in pairs.iter().enumerate() {
                    let count = count.into_ticks();
                    if pos - start < count {
                        return Some(Cursor {
                            pos,
                            entry: i as u32,
                            within: pos - start,
                        });
                    }
                    start = start.saturating_add(count);
                    if start > pos {
                        return None;
                    }
                }
                None
            }
        }
    }

    #[inline(always)]
    fn period<W: TableWord>(&self, ramp: &Ramp<'_, W>) -> W {
        let found = match *ramp {
            Ramp::Steps { periods, .. } => periods.get(self.entry as usize).copied(),
            Ramp::Segments(pairs) => pairs.get(self.entry as usize).map(|p| p.0),
        };
        found.unwrap_or(W::from_ticks(0))
    }

    /// One step towards the fast end; stays put at the last step. Returns
    /// the new entry's period when the step enters another entry.
    #[inline(always)]
    fn forward<W: TableWord>(&mut self, ramp: &Ramp<'_, W>, last: u32) -> Option<W> {
        if self.pos >= last {
            return None;
        }
        self.pos += 1;
        self.within += 1;
        match *ramp {
            Ramp::Steps { periods, hold } => {
                // `hold` 0 counts as 1: `within` is at least 1 here.
                if self.within < hold {
                    return None;
                }
                self.within = 0;
                self.entry += 1;
                periods.get(self.entry as usize).copied()
            }
            Ramp::Segments(pairs) => {
                // Past empty segments to the next that holds a step.
                while self.within
                    >= pairs
                        .get(self.entry as usize)
                        .map_or(0, |p| p.1.into_ticks())
                {
                    self.within = 0;
                    self.entry += 1;
                    if self.entry as usize >= pairs.len() {
                        return None;
                    }
                }
                (self.within == 0)
                    .then(|| pairs.get(self.entry as usize).map(|p| p.0))
                    .flatten()
            }
        }
    }

    /// One step towards the slow end; stays put at step 0. Returns the new
    /// entry's period when the step enters another entry.
    #[inline(always)]
    fn backward<W: TableWord>(&mut self, ramp: &Ramp<'_, W>) -> Option<W> {
        if self.pos == 0 {
            return None;
        }
        self.pos -= 1;
        if self.within > 0 {
            self.within -= 1;
            return None;
        }
        match *ramp {
            Ramp::Steps { periods, hold } => {
                // `pos > 0` with `within == 0`: there is an entry before.
                self.entry = self.entry.saturating_sub(1);
                self.within = hold.max(1) - 1;
                periods.get(self.entry as usize).copied()
            }
            Ramp::Segments(pairs) => {
                // The previous segment that holds a step.
                while self.entry > 0 {
                    self.entry -= 1;
                    if let Some(&(period, count)) = pairs.get(self.entry as usize) {
                        if count.into_ticks() > 0 {
                            self.within = count.into_ticks() - 1;
                            return Some(period);
                        }
                    }
                }
                None
            }
        }
    }
}

/// The shortest period of a ramp (O(n), once per player).
fn fastest<W: TableWord>(ramp: &Ramp<'_, W>) -> u32 {
    match *ramp {
        Ramp::Steps { periods, .. } => periods.iter().map(|p| p.into_ticks()).min(),
        Ramp::Segments(pairs) => pairs
            .iter()
            .filter(|p| p.1.into_ticks() > 0)
            .map(|p| p.0.into_ticks())
            .min(),
    }
    .unwrap_or(0)
}

/// Plays moves from an acceleration ramp and a deceleration ramp.
#[derive(Clone, Debug)]
pub struct Player<'a, W> {
    accel: Ramp<'a, W>,
    decel: Ramp<'a, W>,
    accel_last: u32,
    decel_last: u32,
    /// Where the acceleration side is, and where it is heading.
    acc: Cursor,
    cruise: u32,
    /// The deceleration side, at `min(remaining - 1, decel_last)`.
    dec: Cursor,
    remaining: u32,
    last_period: u32,
    /// The deceleration side has taken over: it plays to the end.
    decelerating: bool,
    /// The deceleration ramp's shortest period: no move runs faster.
    decel_fastest: u32,
    /// The periods under the two cursors, read when a cursor moves.
    acc_period: W,
    dec_period: W,
    /// Steps ahead that repeat the last one (cruising, the deceleration side
    /// out of reach): played with no decision at all.
    coast: u32,
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
        let decel_last = decel.len_steps().saturating_sub(1);
        Player {
            accel,
            decel,
            accel_last,
            decel_last,
            acc: Cursor::ZERO,
            cruise: accel_last,
            dec: Cursor::ZERO,
            remaining: 0,
            last_period: 0,
            decelerating: false,
            decel_fastest: fastest(&decel),
            acc_period: W::from_ticks(0),
            dec_period: W::from_ticks(0),
            coast: 0,
        }
    }

    /// Starts a move of `steps` steps from rest, cruising at the top of the
    /// acceleration ramp. A move on an empty ramp has no steps.
    pub fn start(&mut self, steps: u32) {
        self.cruise = self.accel_last;
        self.remaining = 0;
        self.coast = 0;
        // A move on an empty ramp has no steps.
        let (Some(acc), Some(dec)) = (
            Cursor::at(&self.accel, 0),
            Cursor::at(&self.decel, steps.saturating_sub(1).min(self.decel_last)),
        ) else {
            return;
        };
        self.acc = acc;
        self.dec = dec;
        self.acc_period = acc.period(&self.accel);
        self.dec_period = dec.period(&self.decel);
        self.remaining = steps;
        self.last_period = 0;
        self.decelerating = false;
    }

    /// Cruises at step `pos` of the acceleration ramp (the entry index for a
    /// table without divider) instead of its top; takes effect by walking the
    /// ramp up or down one step per step. Clamped to the ramp.
    pub fn set_cruise(&mut self, pos: u32) {
        self.cruise = pos.min(self.accel_last);
        self.coast = 0;
    }

    /// Decelerates from the current speed to rest: the deceleration ramp is
    /// entered at its entry nearest the current period that is not faster,
    /// and the move ends when the ramp's slowest entry has played (at once,
    /// when the motor already runs slower than that entry). A stop never
    /// lengthens a move.
    pub fn stop(&mut self) {
        self.coast = 0;
        if self.remaining == 0 {
            return;
        }
        if self.last_period == 0 {
            // Not moving yet: nothing to stop.
            self.remaining = 0;
            return;
        }
        // Largest position whose period is not faster than the current one:
        // periods fall along the ramp, so search for the boundary.
        let current = self.last_period;
        if self.period_dec(0) < current {
            // Already slower than the ramp's slowest entry: at rest now.
            self.remaining = 0;
            return;
        }
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
        // Tables rounded by diffusion may tie by a tick: take the last entry
        // of the run that still qualifies (a bounded look past the boundary).
        let mut probe = lo;
        for _ in 0..16 {
            if probe >= self.decel_last || self.period_dec(probe + 1) < current {
                break;
            }
            probe += 1;
        }
        let lo = probe;
        let needed = lo + 1;
        if needed < self.remaining {
            self.remaining = needed;
            if let Some(dec) = Cursor::at(&self.decel, lo) {
                self.dec = dec;
                self.dec_period = dec.period(&self.decel);
                self.decelerating = true;
            } else {
                self.remaining = 0;
            }
        }
    }

    fn period_dec(&self, pos: u32) -> u32 {
        self.decel.period_at(pos).map_or(0, |w| w.into_ticks())
    }

    /// Steps left in the move.
    pub fn remaining(&self) -> u32 {
        self.remaining
    }

    /// `true` when the move has played all its steps.
    pub fn is_done(&self) -> bool {
        self.remaining == 0
    }

    /// The period of the next step, in ticks, or `None` when the move is done.
    ///
    /// Until the deceleration side is within reach (the steps left fit its
    /// ramp), the acceleration side plays alone, exactly as its table reads.
    /// From then on each step compares the two; as soon as the deceleration
    /// side is the slower, it takes over and plays its ramp to the end,
    /// again exactly as its table reads.
    pub fn next_period(&mut self) -> Option<W> {
        if self.coast > 0 {
            // `coast < remaining`, and nothing changes but the count.
            self.coast -= 1;
            self.remaining -= 1;
            return W::from_ticks(self.last_period).into();
        }
        if self.remaining == 0 {
            return None;
        }
        // Steps after this one; the deceleration side stands at
        // `min(after, decel_last)`.
        let after = self.remaining - 1;
        self.remaining = after;
        if self.decelerating {
            // The deceleration side plays to the end; its cursor stands at
            // exactly `after`, one entry lower each step.
            let period = self.dec_period;
            if after > 0 {
                if let Some(p) = self.dec.backward(&self.decel) {
                    self.dec_period = p;
                }
            }
            self.last_period = period.into_ticks();
            return Some(period);
        }
        // Whether this step left both sides as they were, so that the steps
        // after it repeat it until the deceleration side comes within reach.
        let mut still = false;
        let period = {
            let pa = self.acc_period;
            let take_decel = if after <= self.decel_last {
                self.decelerating = self.dec_period.into_ticks() >= pa.into_ticks();
                self.decelerating
            } else {
                // The deceleration ramp cannot start from a faster speed than
                // its top: go no faster (its entries may tie by a tick near
                // the top, so compare with its fastest entry).
                still = self.decel_fastest > pa.into_ticks();
                still
            };
            if take_decel {
                self.dec_period
            } else {
                if self.acc.pos == self.cruise {
                    still = true;
                } else {
                    let moved = if self.acc.pos < self.cruise {
                        self.acc.forward(&self.accel, self.accel_last)
                    } else {
                        self.acc.backward(&self.accel)
                    };
                    if let Some(p) = moved {
                        self.acc_period = p;
                    }
                }
                pa
            }
        };
        if after > 0 && after - 1 < self.dec.pos {
            if let Some(p) = self.dec.backward(&self.decel) {
                self.dec_period = p;
            }
        }
        self.last_period = period.into_ticks();
        if still {
            self.coast = self.remaining.saturating_sub(self.decel_last + 1);
        }
        Some(period)
    }
}
