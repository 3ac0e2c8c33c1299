//! Where the motor is: a player that knows its position and its direction.

use crate::base::timer::TableWord;
use crate::player::playing::targets::Targets;
use crate::player::{AnyLayout, Layout, Player};

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

    /// The way a move of `delta` steps turns (forward for none).
    pub(crate) const fn of(delta: i64) -> Self {
        if delta < 0 {
            Direction::Backward
        } else {
            Direction::Forward
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

/// What an [`Axis`] plays when the move playing ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Then {
    /// Rest.
    Rest,
    /// A move to this position: the target was behind, or nearer than the
    /// motor could stop.
    To(i64),
    /// A run this way.
    Run(Direction),
}

/// A [`Player`] with a position, in steps: [`Axis::move_to`] and
/// [`Axis::move_by`] choose the direction and start the move, and the
/// position follows every step played.
///
/// The position costs nothing per step: it is the move's end less the steps
/// that remain, so [`Axis::step`] is [`Player::step`].
///
/// A new target while a move plays is taken at once. Ahead, and at least
/// the steps the motor needs to stop ([`Player::steps_to_stop`]), the move
/// goes on and ends there ([`Player::retarget`]). Nearer or behind, the
/// axis decelerates along its deceleration ramp to rest, then moves to the
/// target from there: when that is behind, it reverses at the ramp's
/// slowest entry, and [`Axis::direction`] changes at the step that starts
/// the way back. The speed never jumps: each period is the one before, or
/// a neighbouring entry of a ramp.
///
/// A cruise speed set on an axis ([`Axis::set_cruise`],
/// [`Axis::set_cruise_period`]) holds for its moves and runs until it is
/// set again (where [`Player::start`] cruises at the ramp's top).
///
/// ```
/// use profile_core::player::{Axis, Direction, Player, Ramp};
///
/// static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
/// let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 0);
/// // Set the driver's direction pin, then step.
/// assert_eq!(axis.move_to(-10), Direction::Backward);
/// let mut reload = 0;
/// for _ in 0..4 {
///     axis.step(|period| reload = period);
/// }
/// assert_eq!(axis.position(), -4);
/// // Back to 0: a stop, then the way back.
/// axis.move_to(0);
/// let mut path = vec![];
/// while axis.step(|period| reload = period) {
///     path.push((axis.position(), axis.direction(), reload));
/// }
/// assert_eq!(path[3], (-8, Direction::Backward, 4000));
/// assert_eq!(path[4], (-7, Direction::Forward, 4000));
/// assert_eq!((axis.position(), reload), (0, 4000));
/// ```
// The player first, so that its step path keeps its offsets.
#[derive(Clone, Debug)]
#[repr(C)]
pub struct Axis<'a, W, L = AnyLayout> {
    player: Player<'a, W, L>,
    /// Where the move playing ends, in steps (before a run's laps); like
    /// the position, it wraps past the ends of `i64`.
    pub(crate) end: i64,
    direction: Direction,
    /// The move after this one.
    pub(crate) then: Then,
    /// The last reversal.
    turn: Option<Turn>,
    /// Targets queued after `then` ([`Axis::queue`]).
    pub(crate) targets: Targets<i64>,
}

/// A reversal: the direction before it, and where the player stood once it
/// had handed out the first period after it (a run's laps change the steps
/// left, and add to those they have added, so the two never stand there
/// again).
#[derive(Clone, Copy, Debug)]
struct Turn {
    before: Direction,
    remaining: u32,
    extended: u64,
}

impl<'a, W: TableWord, L: Layout> Axis<'a, W, L> {
    /// An axis at `position` with its player at rest.
    pub fn new(player: Player<'a, W, L>, position: i64) -> Self {
        Axis {
            player,
            end: position,
            direction: Direction::Forward,
            then: Then::Rest,
            turn: None,
            targets: Targets::empty(0),
        }
    }

    /// The steps to the move's end, a run's laps taken off (modulo 2^64,
    /// as positions are).
    fn left(&self) -> i64 {
        i64::from(self.player.remaining()).wrapping_sub(self.player.extended() as i64)
    }

    /// The position, in steps: exact after every step (past `i64::MAX` it
    /// wraps to `i64::MIN`, and back, as a hardware counter does).
    pub fn position(&self) -> i64 {
        self.end
            .wrapping_sub(self.direction.sign().wrapping_mul(self.left()))
    }

    /// Where the move playing and the one queued after it end, in steps;
    /// `None` for a run.
    fn destination(&self) -> Option<i64> {
        match self.then {
            Then::To(target) => Some(target),
            Then::Run(_) => None,
            Then::Rest if self.player.is_running() => None,
            Then::Rest => Some(
                self.position()
                    .wrapping_add(self.direction.sign() * i64::from(self.player.remaining())),
            ),
        }
    }

    /// Sets the position (after homing, say), at rest; refused while a move
    /// plays.
    pub fn set_position(&mut self, position: i64) -> Result<(), Moving> {
        self.idle()?;
        self.end = position;
        Ok(())
    }

    /// The direction of the move playing, or of the last one: what the
    /// driver's direction pin must say for the step [`Axis::step`] plays.
    pub fn direction(&self) -> Direction {
        self.direction
    }

    /// The direction of the step the next [`Axis::step`] plays: the
    /// move's, but where the move has ended and one the other way follows
    /// (a target behind, a run the other way). Set the driver's direction
    /// pin to it right after pulsing a step, and the step that takes a new
    /// direction comes a whole period later: a reversal passes through
    /// rest, so that period is the ramp's slowest entry, which the table's
    /// `dir_setup` check holds against the driver.
    ///
    /// ```
    /// use profile_core::player::{Axis, Direction, Player, Ramp};
    ///
    /// static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
    /// let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 0);
    /// axis.move_to(-10);
    /// for _ in 0..4 {
    ///     axis.step(|_| {});
    /// }
    /// axis.move_to(0); // a stop, then the way back
    /// let mut pin = axis.next_direction();
    /// while axis.step(|_| {}) {
    ///     // The pin was set a period ahead of this step.
    ///     assert_eq!(axis.direction(), pin);
    ///     pin = axis.next_direction();
    /// }
    /// assert_eq!(axis.position(), 0);
    /// ```
    pub fn next_direction(&self) -> Direction {
        if self.player.remaining() > 0 {
            return self.direction;
        }
        match self.then {
            Then::Rest => self.direction,
            Then::Run(direction) => direction,
            // As the move to it will start ([`Axis::start_to`]).
            Then::To(target) => match target.saturating_sub(self.position()) {
                0 => self.direction,
                delta => Direction::of(delta),
            },
        }
    }

    /// Moves to `target` and returns the direction to set now. From rest,
    /// starts the move (a move to the position itself has no steps and
    /// keeps the direction; one of more than `u32::MAX` steps stops
    /// `u32::MAX` steps along). While a move plays, takes the new target as
    /// the type's docs say; the target the move already ends at changes
    /// nothing.
    pub fn move_to(&mut self, target: i64) -> Direction {
        self.targets = Targets::empty(0);
        if self.player.is_done() {
            self.turn = None;
            self.then = Then::Rest;
            self.start_to(target);
            return self.direction;
        }
        if self.destination() == Some(target) {
            return self.direction;
        }
        let position = self.position();
        let delta = target.saturating_sub(position);
        let ahead = delta != 0 && delta.signum() == self.direction.sign();
        // Farther than a move can be: as far as one can, at speed.
        let steps = u32::try_from(delta.unsigned_abs()).unwrap_or(u32::MAX);
        if ahead && steps >= self.player.steps_to_stop() {
            self.then = Then::Rest;
            self.replan(|p| {
                p.retarget(steps);
            });
        } else {
            self.then = Then::To(target);
            self.replan(Player::stop);
        }
        self.direction
    }

    /// Moves to `target` once the move playing has ended: for a register
    /// that still holds the move's last period when the player has handed
    /// out every period (`Buffered`), so that the pin takes that step in
    /// the move's direction. The target the move ends at changes nothing.
    pub(crate) fn move_after(&mut self, target: i64) {
        self.targets = Targets::empty(0);
        if self.destination() != Some(target) {
            self.then = Then::To(target);
        }
    }

    /// Runs `direction` once the move playing has ended
    /// ([`Axis::move_after`]).
    pub(crate) fn run_after(&mut self, direction: Direction) {
        self.targets = Targets::empty(0);
        self.then = Then::Run(direction);
    }

    /// Moves by `delta` steps from the position (negative: backward), as
    /// [`Axis::move_to`] does.
    pub fn move_by(&mut self, delta: i64) -> Direction {
        self.move_to(self.position().saturating_add(delta))
    }

    /// Runs `direction` without an end ([`Player::run`]) until
    /// [`Axis::stop`]: at once from rest or moving that way, after a stop
    /// when moving the other way. Returns the direction to set now.
    pub fn run(&mut self, direction: Direction) -> Direction {
        self.targets = Targets::empty(0);
        if self.player.is_done() {
            self.turn = None;
            self.then = Then::Rest;
            self.direction = direction;
            self.replan(Player::run);
        } else if direction == self.direction {
            self.then = Then::Rest;
            self.replan(Player::run);
        } else {
            self.then = Then::Run(direction);
            self.replan(Player::stop);
        }
        self.direction
    }

    /// Changes the player's move, the position kept, and a reversal whose
    /// first period nothing has followed yet kept with it.
    fn replan(&mut self, change: impl FnOnce(&mut Player<'a, W, L>)) {
        let position = self.position();
        let turn = self.at_turn();
        change(&mut self.player);
        self.end = position.wrapping_add(self.direction.sign().wrapping_mul(self.left()));
        self.turn = turn.map(|before| self.turn_from(before));
    }

    /// A reversal from `before`, the player having handed out the first
    /// period after it.
    fn turn_from(&self, before: Direction) -> Turn {
        Turn {
            before,
            remaining: self.player.remaining(),
            extended: self.player.extended(),
        }
    }

    /// The direction before the last reversal, when the player has handed
    /// out nothing since the first period after it (which may still be in
    /// a buffered register's hands, its step not taken).
    fn at_turn(&self) -> Option<Direction> {
        let turn = self.turn?;
        let (remaining, extended) = (self.player.remaining(), self.player.extended());
        let here = remaining == turn.remaining && extended == turn.extended;
        (here && (remaining > 0 || !self.player.is_ended())).then_some(turn.before)
    }

    /// Starts a move from rest to `target`.
    fn start_to(&mut self, target: i64) {
        let position = self.position();
        let delta = target.saturating_sub(position);
        let steps = u32::try_from(delta.unsigned_abs()).unwrap_or(u32::MAX);
        if delta != 0 {
            self.direction = Direction::of(delta);
        }
        self.player.begin(steps);
        self.end = position.wrapping_add(self.direction.sign() * i64::from(steps));
    }

    /// Decelerates to rest from the current speed ([`Player::stop`]); the
    /// move then ends short of its target, and a target it was to go on to
    /// is dropped.
    pub fn stop(&mut self) {
        self.then = Then::Rest;
        self.targets = Targets::empty(0);
        self.replan(Player::stop);
    }

    /// Stops along the emergency ramp ([`Player::abort`],
    /// [`Player::with_emergency`]); the move then ends short of its
    /// target, and a target it was to go on to is dropped.
    pub fn abort(&mut self) {
        self.then = Then::Rest;
        self.targets = Targets::empty(0);
        self.replan(Player::abort);
    }

    /// Cruises slower or faster ([`Player::set_cruise`]); the target stays.
    pub fn set_cruise(&mut self, pos: u32) {
        self.replan(|p| p.set_cruise(pos));
    }

    /// Cruises at a period in ticks ([`Player::set_cruise_period`]); the
    /// target stays.
    pub fn set_cruise_period(&mut self, period: W) {
        self.replan(|p| p.set_cruise_period(period));
    }

    /// Plays the next step ([`Player::step`]): its period to `write`,
    /// `false` when the move is done. Where the move ends and another
    /// follows (a reversal), the next's first step.
    #[inline]
    pub fn step(&mut self, mut write: impl FnMut(W)) -> bool {
        if self.player.step(&mut write) {
            return true;
        }
        self.then_step(write)
    }

    /// The step past the end of the player's run
    /// ([`Player::step_past_run`]), then the move after the one that ended.
    #[cold]
    #[inline(never)]
    pub(crate) fn step_past_run(&mut self, mut write: impl FnMut(W)) -> bool {
        self.player.step_past_run(&mut write) || self.then_step(write)
    }

    /// A buffered register's step without a pulse
    /// ([`Player::step_buffered`]).
    #[inline(always)]
    pub(crate) fn step_buffered(&mut self, mut write: impl FnMut(W)) -> bool {
        match self.player.play(&mut write) {
            Ok(()) => true,
            Err(_) => self.buffered_past_run(write),
        }
    }

    /// [`Axis::step_buffered`] past the player's run: `true` when a step is
    /// taken now.
    #[cold]
    #[inline(never)]
    fn buffered_past_run(&mut self, mut write: impl FnMut(W)) -> bool {
        if self.player.is_ended() {
            // No step ahead of the pin: a move that follows, or rest.
            return self.player.step_past_run(&mut write)
                || self.then_step(write)
                || self.player.rest();
        }
        let _ = self.player.step_past_run(&mut write) || self.then_step(write);
        true
    }

    /// The player, to play from.
    pub(crate) fn player_mut(&mut self) -> &mut Player<'a, W, L> {
        &mut self.player
    }

    /// The move after the one that ended, and its first step.
    #[cold]
    #[inline(never)]
    fn then_step(&mut self, write: impl FnOnce(W)) -> bool {
        let before = self.direction;
        match core::mem::replace(&mut self.then, Then::Rest) {
            Then::Rest => return false,
            Then::To(target) => {
                // The next turning point, if queued, follows this move.
                self.then = self.targets.pop().map_or(Then::Rest, Then::To);
                self.start_to(target);
            }
            Then::Run(direction) => {
                self.direction = direction;
                self.replan(Player::run);
            }
        }
        if !self.player.step(write) {
            return false;
        }
        self.turn = Some(self.turn_from(before));
        true
    }

    /// The period of the next step ([`Player::next_period`]).
    #[inline]
    pub fn next_period(&mut self) -> Option<W> {
        let mut period = None;
        self.step(|p| period = Some(p));
        period
    }

    /// Writes the next periods into `buf` ([`Player::fill`]): how many,
    /// fewer than `buf.len()` only when the move ends. The position follows
    /// them as it follows steps. A reversal's way back is not written: it
    /// begins at the next [`Axis::step`] or fill, once the direction pin is
    /// set for it.
    pub fn fill(&mut self, buf: &mut [W]) -> usize {
        let n = self.player.fill(buf);
        if n == 0 {
            if let Some(first) = buf.first_mut() {
                if self.step(|p| *first = p) {
                    return 1 + self.player.fill(&mut buf[1..]);
                }
            }
        }
        n
    }

    /// Steps left in the move (a run: to an end it keeps putting off).
    pub fn remaining(&self) -> u32 {
        self.player.remaining()
    }

    /// `true` when the move has played all its steps and no other follows.
    pub fn is_done(&self) -> bool {
        self.player.is_done() && self.then == Then::Rest
    }

    /// The player.
    pub fn player(&self) -> &Player<'a, W, L> {
        &self.player
    }

    /// The direction of the step whose period the player handed out last:
    /// the one before a reversal while nothing has followed the first
    /// period after it ([`Buffered`](crate::player::Buffered)'s pin takes that
    /// period's step one interval later).
    pub(crate) fn handed_direction(&self) -> Direction {
        self.at_turn().unwrap_or(self.direction)
    }

    fn idle(&self) -> Result<(), Moving> {
        match self.player.remaining() {
            0 if self.then == Then::Rest => Ok(()),
            remaining => Err(Moving { remaining }),
        }
    }
}
