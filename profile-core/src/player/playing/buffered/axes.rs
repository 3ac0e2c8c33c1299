//! [`Buffered`] [`Axes`]: coordinated axes on a reload register that
//! takes effect at the next wrap.

use super::Buffered;
use crate::base::timer::TableWord;
use crate::player::playing::axes::Axes;
use crate::player::playing::axis::Direction;
use crate::player::playing::targets::QueueFull;
use crate::player::ramps::layout::Layout;

/// How a move of [`Buffered`] [`Axes`] begins: set the direction pins,
/// load `first`, start the counter and take the first step (on the axes in
/// `mask`), then load `next`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AxesStart<W, const N: usize> {
    /// The direction each axis's pin must say before the first step.
    pub directions: [Direction; N],
    /// The axes that step on the first edge (0 for a move without steps).
    pub mask: u32,
    /// The first period: `None` for a move without steps.
    pub first: Option<W>,
    /// The second: `None` for a move of fewer than two steps.
    pub next: Option<W>,
}

impl<'a, W: TableWord, const N: usize, L: Layout> Buffered<Axes<'a, W, N, L>> {
    /// Moves to `target` ([`Axes::move_to`]), what to load as the type's
    /// docs say. From rest, begins the move: the directions, the first
    /// edge's mask and the first two periods. In a move's last interval,
    /// every edge taken: the directions to set now and the first period to
    /// load into the register (mask 0: the first edge's mask comes from
    /// the interrupt that takes it). While a move plays, the new target is
    /// taken from the first period not yet in the timer's hands, and there
    /// is nothing to load: the directions now, mask 0 and no periods; with
    /// the move's last edge in the timer's hands, the move to `target`
    /// follows that edge, which the pins take in the directions of its own
    /// move.
    pub fn move_to(&mut self, target: [i64; N]) -> AxesStart<W, N> {
        self.start_to(target)
    }

    /// Queues a line to `target` ([`Axes::queue`]): from rest it begins
    /// the move as [`Buffered::move_to`] does; while lines play, the
    /// directions now, mask 0 and no periods. With the line's last edge in
    /// the timer's hands (the lead's periods all handed out) a line that
    /// would end at rest no longer joins at speed: the new one follows
    /// that edge from rest.
    pub fn queue(&mut self, target: [i64; N]) -> Result<AxesStart<W, N>, QueueFull<[i64; N]>> {
        if self.ahead == 0 && self.inner.is_done() {
            return Ok(self.start_to(target));
        }
        let rejoin = self.inner.remaining() > 0;
        self.inner.enqueue(target, rejoin)?;
        Ok(AxesStart {
            directions: self.inner.directions(),
            mask: 0,
            first: None,
            next: None,
        })
    }

    /// [`Buffered::move_to`].
    fn start_to(&mut self, target: [i64; N]) -> AxesStart<W, N> {
        let mut start = AxesStart {
            directions: self.inner.directions(),
            mask: 0,
            first: None,
            next: None,
        };
        if self.ahead != 0 {
            if self.inner.remaining() == 0 {
                // The last edge in the timer's hands: the move to `target`
                // follows it, as it follows a stop.
                self.inner.move_after(target);
            } else {
                start.directions = self.inner.move_to(target);
            }
            return start;
        }
        start.directions = self.inner.move_to(target);
        let first = self.inner.next_step();
        if self.inner.player().is_rested() {
            // Load the first, start the counter, load the next.
            start.mask = first.map_or(0, |(_, mask)| mask);
            start.first = first.map(|(period, _)| period);
            let next = first.and_then(|_| self.inner.next_step());
            self.ahead = next.map_or(0, |(_, mask)| mask);
            start.next = next.map(|(period, _)| period);
            self.inner.player_mut().set_rested(first.is_none());
        } else {
            // The last interval counting: the first edge follows it.
            self.ahead = first.map_or(0, |(_, mask)| mask);
            start.next = first.map(|(period, _)| period);
        }
        start
    }

    /// Moves by `delta` steps on each axis from the positions at the pins,
    /// as [`Buffered::move_to`] does.
    pub fn move_by(&mut self, delta: [i64; N]) -> AxesStart<W, N> {
        let mut target = self.position();
        for (t, d) in target.iter_mut().zip(delta) {
            *t = t.saturating_add(d);
        }
        self.move_to(target)
    }

    /// The direction each axis's pin must say for the edge the pins take
    /// now, from the interrupt [`Buffered::step`] returned a mask in: at a
    /// turn to a queued move the axes' own directions are one edge ahead.
    pub fn directions(&self) -> [Direction; N] {
        self.inner.handed_directions()
    }

    /// From the timer's interrupt, at the end of an interval: the mask of
    /// the axes that step now, on the edge the interval now starting
    /// begins with, having handed the period after that interval to
    /// `write` (not called near the move's end, where there is none); 0
    /// when the interval that ended was the move's last.
    #[inline]
    pub fn step(&mut self, mut write: impl FnMut(W)) -> u32 {
        let now = self.ahead;
        let ahead = &mut self.ahead;
        if !self.inner.step(|period, mask| {
            *ahead = mask;
            write(period);
        }) {
            *ahead = 0;
            // At rest once the interrupt that ends the last interval has
            // come: no edge was ahead.
            self.inner.player_mut().set_rested(now == 0);
        }
        now
    }

    /// Edges not yet taken.
    pub fn remaining(&self) -> u32 {
        self.inner.remaining() + u32::from(self.ahead != 0)
    }

    /// `true` when every step has been taken (the last interval may still
    /// be counting).
    pub fn is_done(&self) -> bool {
        self.remaining() == 0
    }

    /// The positions at the pins, in steps: the axes' less the edge whose
    /// period is in the timer's hands and not yet taken.
    pub fn position(&self) -> [i64; N] {
        let played = self.inner.lead_played();
        self.inner
            .position_after(played - u32::from(self.ahead != 0 && played > 0))
    }
}
