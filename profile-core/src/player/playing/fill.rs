//! Filling a buffer with the next periods: for a DMA channel that copies
//! them to the timer (ping-pong halves), or a PIO or RMT queue.

use crate::base::timer::TableWord;
use crate::player::planning::plan::Run;
use crate::player::ramps::runs::RunState;
use crate::player::{Layout, Player};
use crate::table::runs::{FRACTION_MASK, RUN_FRACTION_BITS};

impl<W: TableWord, L: Layout> Player<'_, W, L> {
    /// Writes the next periods into `buf`, from its start, and returns how
    /// many: `buf.len()`, or fewer when the move ends in it (0 once it is
    /// done). Exactly what as many calls of [`next_period`](Self::next_period)
    /// would hand out, in order: fills concatenated are the move, however
    /// the buffer is cut, with [`stop`](Self::stop) and
    /// [`set_cruise`](Self::set_cruise) between fills as between steps.
    ///
    /// Each stretch of the plan is written in one loop: a copy of a
    /// per-step table's entries (forward or backward), one period repeated,
    /// or a compressed run's recurrence, with no call per period.
    ///
    /// ```
    /// use profile_core::player::{Player, Ramp};
    ///
    /// static RAMP: [u16; 4] = [4000, 2500, 2000, 1800];
    /// let mut player = Player::new(Ramp::steps(&RAMP));
    /// player.start(10);
    /// // A DMA channel's two halves, filled in turn.
    /// let mut half = [0u16; 4];
    /// assert_eq!(player.fill(&mut half), 4);
    /// assert_eq!(half, [4000, 2500, 2000, 1800]);
    /// assert_eq!(player.fill(&mut half), 4);
    /// assert_eq!(half, [1800, 1800, 1800, 2000]);
    /// assert_eq!(player.fill(&mut half), 2); // the move ends here
    /// assert_eq!(half[..2], [2500, 4000]);
    /// assert_eq!(player.fill(&mut half), 0);
    /// ```
    pub fn fill(&mut self, buf: &mut [W]) -> usize {
        let mut done = 0;
        loop {
            let Some(rest) = buf.get_mut(done..).filter(|r| !r.is_empty()) else {
                return done;
            };
            let n = if L::COMPRESSED {
                fill_computed(&mut self.computed, rest)
            } else {
                self.fill_run(rest)
            };
            done += n;
            if n == 0 {
                // The run is played: the plan's next, as the step path
                // takes it.
                let more = if L::COMPRESSED {
                    self.refill_runs().is_some()
                } else {
                    self.refill().is_some()
                };
                if !more {
                    return done;
                }
            }
        }
    }

    /// Writes what is left of the run being played (at most `out.len()`
    /// periods) and returns how many: 0 when it is played.
    #[inline(always)]
    fn fill_run(&mut self, out: &mut [W]) -> usize {
        match &mut self.run {
            Run::Up(periods) => {
                let from = periods.as_slice();
                let n = from.len().min(out.len());
                let (now, later) = from.split_at(n);
                // Two at a time, not `copy_from_slice`: a `memcpy` copies
                // word by word only where the table and the buffer are
                // aligned alike, and a byte at a time where they are not.
                let out = &mut out[..n];
                let mut to = out.chunks_exact_mut(2);
                let mut from = now.chunks_exact(2);
                for (to, from) in (&mut to).zip(&mut from) {
                    to[0] = from[0];
                    to[1] = from[1];
                }
                if let ([to], [from]) = (to.into_remainder(), from.remainder()) {
                    *to = *from;
                }
                *periods = later.iter();
                n
            }
            Run::Down(periods) | Run::Ended(periods) => {
                let from = periods.as_slice();
                if from.is_empty() {
                    // A compressed ramp's run, behind an empty `Down` (none
                    // when the run is `Ended`).
                    return fill_computed(&mut self.computed, out);
                }
                let n = from.len().min(out.len());
                let (later, now) = from.split_at(from.len() - n);
                // Two at a time, from both ends of equal chunks: no bound
                // checked in the loop, half its own instructions a period.
                let out = &mut out[..n];
                let pairs = out.chunks_exact_mut(2).zip(now.rchunks_exact(2));
                for (to, from) in pairs {
                    to[0] = from[1];
                    to[1] = from[0];
                }
                if n % 2 == 1 {
                    out[n - 1] = now[0];
                }
                *periods = later.iter();
                n
            }
            Run::Hold(p, left) => {
                let n = (*left as usize).min(out.len());
                out[..n].fill(*p);
                *left -= n as u32;
                n
            }
        }
    }
}

/// Writes the next periods of a compressed run (at most `out.len()`) with
/// [`RunState::next`]'s recurrence, its state in registers; returns how
/// many.
#[inline(always)]
fn fill_computed<W: TableWord>(r: &mut RunState, out: &mut [W]) -> usize {
    let n = (r.left as usize).min(out.len());
    let (mut frac, mut interval, add) = (r.frac, r.interval, r.add);
    for slot in &mut out[..n] {
        let x = frac.wrapping_add(interval);
        frac = x & FRACTION_MASK;
        interval = interval.wrapping_add(add);
        *slot = W::from_ticks(x >> RUN_FRACTION_BITS);
    }
    (r.frac, r.interval, r.left) = (frac, interval, r.left - n as u32);
    n
}
