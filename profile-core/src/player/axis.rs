//! Where the motor is: a player that knows its position and its direction.

use super::{AnyLayout, Layout, Player};
use crate::base::timer::TableWord;

/// The way a move turns the motor, for the driver's direction pin.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// Towards higher positions.
    Forward,
    /// Towards lower positions.
    Backward,
}

impl Direction {
    /// The change of position per step: 1 or -1.
    pub const fn sign(self) -> i64 {
        match self {
            Direction::Forward => 1,
            Direction::Backward => -1,
        }
    }
}

/// A move was asked for while another is playing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Moving {
    /// Steps the move playing has left.
    pub remaining: u32,
}

impl core::fmt::Display for Moving {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "a move is playing ({} steps left): stop it and let it end before the next",
            self.remaining
        )
    }
}

/// A [`Player`] with a position, in steps: [`Axis::move_to`] and
/// [`Axis::move_by`] choose the direction and start the move, and the
/// position follows every step played.
///
/// The position costs nothing per step: it is the move's end less the steps
/// that remain, so [`Axis::step`] is [`Player::step`].
///
/// ```
/// use profile_core::player::{Axis, Direction, Player, Ramp};
///
/// static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
/// let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 0);
/// // Set the driver's direction pin, then step.
/// assert_eq!(axis.move_to(-10), Ok(Direction::Backward));
/// let mut reload = 0;
/// for _ in 0..4 {
///     axis.step(|period| reload = period);
/// }
/// assert_eq!(axis.position(), -4);
/// while axis.step(|period| reload = period) {}
/// assert_eq!((axis.position(), reload), (-10, 4000));
/// ```
// The player first, so that its step path keeps its offsets.
#[derive(Clone, Debug)]
#[repr(C)]
pub struct Axis<'a, W, L = AnyLayout> {
    player: Player<'a, W, L>,
    /// Where the move playing ends, in steps.
    end: i64,
    direction: Direction,
}

impl<'a, W: TableWord, L: Layout> Axis<'a, W, L> {
    /// An axis at `position` with its player at rest.
    pub fn new(player: Player<'a, W, L>, position: i64) -> Self {
        Axis {
            player,
            end: position,
            direction: Direction::Forward,
        }
    }

    /// The position, in steps: exact after every step.
    pub fn position(&self) -> i64 {
        self.end - self.direction.sign() * i64::from(self.player.remaining())
    }

    /// Sets the position (after homing, say), at rest; refused while a move
    /// plays.
    pub fn set_position(&mut self, position: i64) -> Result<(), Moving> {
        self.idle()?;
        self.end = position;
        Ok(())
    }

    /// The direction of the move playing, or of the last one: what the
    /// driver's direction pin must say.
    pub fn direction(&self) -> Direction {
        self.direction
    }

    /// Starts a move from rest to `target`; returns the direction to set
    /// before the first step. A move to the position itself has no steps.
    /// Refused while another move plays; a move of more than `u32::MAX`
    /// steps stops there.
    pub fn move_to(&mut self, target: i64) -> Result<Direction, Moving> {
        let delta = target.saturating_sub(self.position());
        self.move_by(delta)
    }

    /// Starts a move of `delta` steps from rest (negative: backward);
    /// returns the direction to set before the first step.
    pub fn move_by(&mut self, delta: i64) -> Result<Direction, Moving> {
        self.idle()?;
        let steps = u32::try_from(delta.unsigned_abs()).unwrap_or(u32::MAX);
        self.direction = if delta < 0 {
            Direction::Backward
        } else {
            Direction::Forward
        };
        self.end = self.position() + self.direction.sign() * i64::from(steps);
        self.player.start(steps);
        Ok(self.direction)
    }

    /// Decelerates to rest from the current speed ([`Player::stop`]); the
    /// move then ends short of its target.
    pub fn stop(&mut self) {
        let position = self.position();
        self.player.stop();
        self.end = position + self.direction.sign() * i64::from(self.player.remaining());
    }

    /// Cruises slower or faster ([`Player::set_cruise`]); the target stays.
    pub fn set_cruise(&mut self, pos: u32) {
        self.player.set_cruise(pos);
    }

    /// Plays the next step ([`Player::step`]): its period to `write`,
    /// `false` when the move is done.
    #[inline]
    pub fn step(&mut self, write: impl FnOnce(W)) -> bool {
        self.player.step(write)
    }

    /// The period of the next step ([`Player::next_period`]).
    #[inline]
    pub fn next_period(&mut self) -> Option<W> {
        self.player.next_period()
    }

    /// Writes the next periods into `buf` ([`Player::fill`]): how many,
    /// fewer than `buf.len()` only when the move ends. The position follows
    /// them as it follows steps.
    pub fn fill(&mut self, buf: &mut [W]) -> usize {
        self.player.fill(buf)
    }

    /// Steps left in the move.
    pub fn remaining(&self) -> u32 {
        self.player.remaining()
    }

    /// `true` when the move has played all its steps.
    pub fn is_done(&self) -> bool {
        self.player.is_done()
    }

    /// The player.
    pub fn player(&self) -> &Player<'a, W, L> {
        &self.player
    }

    fn idle(&self) -> Result<(), Moving> {
        match self.player.remaining() {
            0 => Ok(()),
            remaining => Err(Moving { remaining }),
        }
    }
}
