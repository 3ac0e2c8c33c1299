//! Moves queued on an [`Axis`] that join at speed: [`Axis::queue`].
//!
//! An axis keeps the targets it is to go on to after the move playing.
//! Consecutive targets the same way make one move to the farthest, so
//! the motor passes the ones between at speed: the fastest that still
//! stops at the end of the queue, which is where the move ends (a queued
//! target farther the same way moves that end out while the move plays).
//! A target the other way is a reversal, which passes through rest: the
//! move to it starts where the one before ended. The queue holds those
//! turning points (`targets.rs`), up to [`QUEUE`](crate::player::QUEUE) beyond the move playing
//! and the one after it.

use crate::base::timer::TableWord;
use crate::player::Layout;
use crate::player::playing::axis::{Axis, Direction, Then};
use crate::player::playing::targets::QueueFull;

/// The way from `from` to `to`, `None` where they are the same.
fn way(from: i64, to: i64) -> Option<Direction> {
    match to.saturating_sub(from) {
        0 => None,
        delta => Some(Direction::of(delta)),
    }
}

impl<'a, W: TableWord, L: Layout> Axis<'a, W, L> {
    /// Queues a move to `target` after the moves queued before it, and
    /// returns the direction to set now (the move's, or at rest the new
    /// one's). At rest, it starts the move, as [`Axis::move_to`] does.
    /// While moves play, a target the same way as the last one, beyond it,
    /// joins it at speed: the move (or the last one queued) goes on to the
    /// new target, the motor passing the old one at the fastest speed from
    /// which it can still stop at the end of the queue, and the position
    /// exact there as at every step. A target the other way waits for the
    /// move before it to end at rest, then reverses ([`QueueFull`] when
    /// [`QUEUE`](crate::player::QUEUE) such turning points wait already beyond the move playing
    /// and the next). A target the last move already ends at changes
    /// nothing.
    ///
    /// [`Axis::move_to`], [`Axis::move_by`], [`Axis::run`],
    /// [`Axis::stop`] and [`Axis::abort`] drop what is queued.
    ///
    /// ```
    /// use profile_core::player::{Axis, Player};
    ///
    /// static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
    /// let mut axis = Axis::new(Player::new(&RAMP), 0);
    /// axis.queue(10).unwrap();
    /// axis.queue(20).unwrap(); // joins the move to 10: no stop there
    /// axis.queue(15).unwrap(); // a reversal, at rest
    /// let mut path = vec![];
    /// while let Some(period) = axis.next_period() {
    ///     path.push((axis.position(), period));
    /// }
    /// assert_eq!(path[9..11], [(10, 1500), (11, 1500)]);
    /// assert_eq!(path[19..21], [(20, 4000), (19, 4000)]);
    /// assert_eq!(path.len(), 25);
    /// assert_eq!(axis.position(), 15);
    /// ```
    pub fn queue(&mut self, target: i64) -> Result<Direction, QueueFull> {
        if self.is_done() {
            return Ok(self.move_to(target));
        }
        self.enqueue(target, true)?;
        Ok(self.direction())
    }

    /// Targets queued after the move playing: the move that follows it
    /// and the turning points beyond.
    pub fn queued(&self) -> usize {
        match self.then {
            Then::To(_) => 1 + self.targets.len(),
            _ => self.targets.len(),
        }
    }

    /// Queues `target` while a move plays; `extend`: the move playing may
    /// go on to it (not when its last period is handed out, for a buffered
    /// register).
    pub(crate) fn enqueue(&mut self, target: i64, extend: bool) -> Result<(), QueueFull> {
        // A run has no end to go on from: the target ends it, as a new
        // target does.
        if matches!(self.then, Then::Run(_)) || self.player().is_running() {
            if extend {
                self.move_to(target);
            } else {
                self.move_after(target);
            }
            return Ok(());
        }
        // The last target and the way the move to it goes.
        let (last, into) = match (self.then, self.targets.last_two()) {
            (Then::To(then), (Some(last), before)) => (last, way(before.unwrap_or(then), last)),
            (Then::To(then), (None, _)) => (then, way(self.end, then)),
            _ => (self.end, Some(self.direction())),
        };
        let ahead = way(last, target);
        if ahead.is_none() {
            return Ok(());
        }
        if ahead == into {
            match (self.then, self.targets.len()) {
                (Then::To(_), 0) => self.then = Then::To(target),
                (Then::To(_), _) => self.targets.replace_last(target),
                _ if extend => {
                    self.move_to(target);
                }
                _ => self.move_after(target),
            }
            return Ok(());
        }
        match self.then {
            Then::Rest => {
                self.then = Then::To(target);
                Ok(())
            }
            _ => self.targets.push(target),
        }
    }
}
