//! The ramp player as it was before it planned its moves: it decides every
//! step between the two ramps. The planned player must play every move
//! exactly as this model does. One fix: a cruise position set slower while
//! the deceleration ramp caps the speed walks the acceleration side down
//! (the model it replaces kept playing the cap).

use profile_core::TableWord;
use profile_core::player::Ramp;

fn len_steps<W: TableWord>(ramp: &Ramp<'_, W>) -> u32 {
    ramp.len_steps()
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
            Ramp::Runs(_) | Ramp::Indexed(_) => {
                unreachable!("the reference plays runs as their expansion")
            }
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
            Ramp::Runs(_) | Ramp::Indexed(_) => {
                unreachable!("the reference plays runs as their expansion")
            }
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
            Ramp::Runs(_) | Ramp::Indexed(_) => {
                unreachable!("the reference plays runs as their expansion")
            }
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
            Ramp::Runs(_) | Ramp::Indexed(_) => {
                unreachable!("the reference plays runs as their expansion")
            }
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
        Ramp::Runs(_) | Ramp::Indexed(_) => {
            unreachable!("the reference plays runs as their expansion")
        }
        Ramp::Steps { periods, .. } => periods.iter().map(|p| p.into_ticks()).min(),
        Ramp::Segments(pairs) => pairs
            .iter()
            .filter(|p| p.1.into_ticks() > 0)
            .map(|p| p.0.into_ticks())
            .min(),
    }
    .unwrap_or(0)
}

/// The per-step player: the reference model.
#[derive(Clone, Debug)]
pub struct Reference<'a, W> {
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
}

impl<'a, W: TableWord> Reference<'a, W> {
    /// A player with its own deceleration ramp (also ordered slow to fast),
    /// for asymmetric moves.
    pub fn with_decel(accel: Ramp<'a, W>, decel: Ramp<'a, W>) -> Self {
        let accel_last = len_steps(&accel).saturating_sub(1);
        let decel_last = len_steps(&decel).saturating_sub(1);
        Reference {
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
        }
    }

    /// Starts a move of `steps` steps from rest, cruising at the top of the
    /// acceleration ramp. A move on an empty ramp has no steps.
    pub fn start(&mut self, steps: u32) {
        self.cruise = self.accel_last;
        self.remaining = 0;
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
    }

    /// Decelerates from the current speed to rest: the deceleration ramp is
    /// entered at its last entry whose period is not shorter than the
    /// current one, and the move ends when the ramp's slowest entry has
    /// played (at once, when the motor already runs slower than that
    /// entry). A stop never lengthens a move.
    pub fn stop(&mut self) {
        if self.remaining == 0 {
            return;
        }
        if self.last_period == 0 {
            // Not moving yet: nothing to stop.
            self.remaining = 0;
            return;
        }
        let current = self.last_period;
        if self.period_dec(0) < current {
            // Already slower than the ramp's slowest entry: at rest now.
            self.remaining = 0;
            return;
        }
        // The last position whose period is not shorter than the current
        // one: a walk down from the top.
        let mut lo = self.decel_last;
        while lo > 0 && self.period_dec(lo) < current {
            lo -= 1;
        }
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

    /// The period of the next step, in ticks, or `None` when the move is done.
    ///
    /// Until the deceleration side is within reach (the steps left fit its
    /// ramp), the acceleration side plays alone, exactly as its table reads.
    /// From then on each step compares the two; as soon as the deceleration
    /// side is the slower, it takes over and plays its ramp to the end,
    /// again exactly as its table reads.
    pub fn next_period(&mut self) -> Option<W> {
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
        let period = {
            let pa = self.acc_period;
            let take_decel = if after <= self.decel_last {
                self.decelerating = self.dec_period.into_ticks() >= pa.into_ticks();
                self.decelerating
            } else {
                // The deceleration ramp cannot start from a faster speed than
                // its top: go no faster (its entries may tie by a tick near
                // the top, so compare with its fastest entry).
                self.decel_fastest > pa.into_ticks()
            };
            if take_decel {
                // Capped by the deceleration ramp's fastest entry while it is
                // out of reach: the acceleration side still walks down to a
                // slower cruise position (this model's fix of the per-step
                // player, which ignored a slower cruise there).
                if after > self.decel_last && self.acc.pos > self.cruise {
                    if let Some(p) = self.acc.backward(&self.accel) {
                        self.acc_period = p;
                    }
                }
                self.dec_period
            } else {
                if self.acc.pos != self.cruise {
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
        Some(period)
    }
}
