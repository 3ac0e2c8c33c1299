//! Held and segment tables entry by entry: one period for many steps, so
//! that a search or a scan over them costs their entries, not their steps,
//! whatever an entry's count.

use crate::base::timer::TableWord;
use crate::player::ramps::ramp::{Cursor, Ramp};

impl<W: TableWord> Ramp<'_, W> {
    /// The first step whose period is shorter than `ticks`, or `u32::MAX`.
    /// Held and segment tables entry by entry, whatever their counts;
    /// runs step by step.
    pub(crate) fn first_faster_than(&self, ticks: u32) -> u32 {
        let entries = match *self {
            Ramp::Steps { periods, hold } => Some(
                periods
                    .iter()
                    .position(|p| p.into_ticks() < ticks)
                    .map(|i| i as u64 * u64::from(hold.max(1))),
            ),
            Ramp::Segments(pairs) => {
                let mut start = 0u64;
                Some(pairs.iter().find_map(|&(period, count)| {
                    let (at, count) = (start, count.into_ticks());
                    start += u64::from(count);
                    (count > 0 && period.into_ticks() < ticks).then_some(at)
                }))
            }
            Ramp::Runs(_) | Ramp::Indexed(_) => None,
        };
        if let Some(found) = entries {
            // (Past the last step a position counts: none.)
            let last = u64::from(self.len_steps().saturating_sub(1));
            return found
                .filter(|&pos| pos <= last)
                .map_or(u32::MAX, |pos| pos as u32);
        }
        let Some(mut c) = Cursor::at(self, 0) else {
            return u32::MAX;
        };
        let last = self.len_steps().saturating_sub(1);
        loop {
            if c.period(self).into_ticks() < ticks {
                return c.pos;
            }
            if !c.forward(self, last) {
                return u32::MAX;
            }
        }
    }
}

impl Cursor {
    /// Steps it can take `dir` (1 towards the fast end, -1 towards the
    /// slow end) on a held or segment table without leaving its entry, so
    /// without a change of period: 0 on runs, whose period changes every
    /// step; any number standing (`dir` 0), on any ramp.
    pub(crate) fn room_in_entry<W: TableWord>(&self, ramp: &Ramp<'_, W>, dir: i8) -> u32 {
        if dir == 0 {
            return u32::MAX;
        }
        let count = match *ramp {
            Ramp::Steps { hold, .. } => hold.max(1),
            Ramp::Segments(pairs) => pairs
                .get(self.entry as usize)
                .map_or(0, |p| p.1.into_ticks()),
            Ramp::Runs(_) | Ramp::Indexed(_) => return 0,
        };
        match dir {
            1 => count.saturating_sub(self.within + 1),
            _ => self.within,
        }
    }

    /// `n` steps `dir` within its entry ([`Cursor::room_in_entry`] at
    /// least `n`).
    pub(crate) fn skip_in_entry(&mut self, dir: i8, n: u32) {
        match dir {
            1 => (self.pos, self.within) = (self.pos + n, self.within + n),
            -1 => (self.pos, self.within) = (self.pos - n, self.within - n),
            _ => {}
        }
    }
}
