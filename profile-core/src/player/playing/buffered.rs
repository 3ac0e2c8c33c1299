//! [`Buffered`]: a player for reload registers that take effect at the next
//! wrap.

use crate::base::timer::TableWord;
use crate::player::Player;
use crate::player::playing::axes::Axes;
use crate::player::playing::axis::{Axis, Direction};
use crate::player::playing::targets::QueueFull;
use crate::player::ramps::layout::Layout;

mod axes;
pub use axes::AxesStart;

mod sealed {
    pub trait Sealed {}
}

/// What [`Buffered`] plays: one period per call, as [`Player`] and [`Axis`]
/// hand them out. ([`Axes`](crate::player::Axes) hand out a period and a mask of
/// the axes that step: `Buffered<Axes>` has its own calls, which hand on
/// both.) Sealed:
/// the two are all there is.
pub trait Steps: sealed::Sealed {
    /// The table's word.
    type Word;
    /// Hands the next step's period to `write` and returns `true`, or
    /// returns `false` when the move is done ([`Player::step`]).
    fn step(&mut self, write: impl FnMut(Self::Word)) -> bool;
    /// The next step's period, or `None` when the move is done.
    fn next_period(&mut self) -> Option<Self::Word>;
    /// Steps left to hand out.
    fn remaining(&self) -> u32;
    /// A buffered register's step: `false`, calling nothing, when the
    /// player has returned `false` and handed out nothing since (no period
    /// in the register has its step to take); else calls `pulse`, hands
    /// the next period to `write` if there is one, and returns `true`.
    #[doc(hidden)]
    fn step_pulsed(&mut self, pulse: impl FnOnce(), write: impl FnMut(Self::Word)) -> bool;
    /// [`Steps::step_pulsed`] without a pulse, the step path the player's
    /// own.
    #[doc(hidden)]
    fn step_buffered(&mut self, write: impl FnMut(Self::Word)) -> bool;
    /// `true` when the player has returned `false` and handed out nothing
    /// since.
    #[doc(hidden)]
    fn ended(&self) -> bool;
    /// The interrupt that ends the move's last interval has come (the
    /// buffered step has returned `false`), or nothing has played yet.
    #[doc(hidden)]
    fn rested(&self) -> bool;
    /// A move has begun (`false`).
    #[doc(hidden)]
    fn set_rested(&mut self, rested: bool);
}

/// The calls that change a move without starting one, the same on a
/// [`Player`], an [`Axis`] and [`Axes`](crate::player::Axes): what
/// [`Buffered`] hands on to what it wraps unchanged. (A call that starts a
/// move says what to load, and [`Buffered`] has its own.) Sealed: the
/// three are all there is.
pub trait Adjust: sealed::Sealed {
    /// The table's word.
    type Word;
    /// Decelerates to rest ([`Player::stop`]).
    fn stop(&mut self);
    /// Stops along the emergency ramp ([`Player::abort`]).
    fn abort(&mut self);
    /// Cruises at step `pos` of the acceleration ramp
    /// ([`Player::set_cruise`]).
    fn set_cruise(&mut self, pos: u32);
    /// Cruises at a period in ticks ([`Player::set_cruise_period`]).
    fn set_cruise_period(&mut self, period: Self::Word);
}

impl<W: TableWord, L: Layout> sealed::Sealed for Player<'_, W, L> {}
impl<W: TableWord, L: Layout> sealed::Sealed for Axis<'_, W, L> {}
impl<W: TableWord, const N: usize, L: Layout> sealed::Sealed for Axes<'_, W, N, L> {}

/// Implements [`Adjust`] by the inherent calls of the same names.
macro_rules! adjust_by_inherent {
    ($ty:ty, $($generics:tt)*) => {
        impl<$($generics)*> Adjust for $ty {
            type Word = W;
            fn stop(&mut self) {
                <$ty>::stop(self);
            }
            fn abort(&mut self) {
                <$ty>::abort(self);
            }
            fn set_cruise(&mut self, pos: u32) {
                <$ty>::set_cruise(self, pos);
            }
            fn set_cruise_period(&mut self, period: W) {
                <$ty>::set_cruise_period(self, period);
            }
        }
    };
}
adjust_by_inherent!(Player<'_, W, L>, W: TableWord, L: Layout);
adjust_by_inherent!(Axis<'_, W, L>, W: TableWord, L: Layout);
adjust_by_inherent!(Axes<'_, W, N, L>, W: TableWord, const N: usize, L: Layout);

impl<W: TableWord, L: Layout> Steps for Player<'_, W, L> {
    type Word = W;
    #[inline]
    fn step(&mut self, write: impl FnMut(W)) -> bool {
        Player::step(self, write)
    }
    #[inline]
    fn next_period(&mut self) -> Option<W> {
        Player::next_period(self)
    }
    fn remaining(&self) -> u32 {
        Player::remaining(self)
    }
    #[inline]
    fn step_pulsed(&mut self, pulse: impl FnOnce(), write: impl FnMut(W)) -> bool {
        match self.play_pulsed(pulse, write) {
            Pulsed::Ended => self.rest(),
            Pulsed::Played => true,
            Pulsed::Empty(write) => {
                self.step_past_run(write);
                true
            }
        }
    }
    #[inline]
    fn step_buffered(&mut self, write: impl FnMut(W)) -> bool {
        Player::step_buffered(self, write)
    }
    fn ended(&self) -> bool {
        self.is_ended()
    }
    fn rested(&self) -> bool {
        self.is_rested()
    }
    fn set_rested(&mut self, rested: bool) {
        Player::set_rested(self, rested);
    }
}

impl<W: TableWord, L: Layout> Steps for Axis<'_, W, L> {
    type Word = W;
    #[inline]
    fn step(&mut self, write: impl FnMut(W)) -> bool {
        Axis::step(self, write)
    }
    #[inline]
    fn next_period(&mut self) -> Option<W> {
        Axis::next_period(self)
    }
    fn remaining(&self) -> u32 {
        Axis::remaining(self)
    }
    #[inline]
    fn step_pulsed(&mut self, pulse: impl FnOnce(), mut write: impl FnMut(W)) -> bool {
        match Axis::player_mut(self).play_pulsed(pulse, &mut write) {
            Pulsed::Ended => Axis::player_mut(self).rest(),
            Pulsed::Played => true,
            Pulsed::Empty(write) => {
                self.step_past_run(write);
                true
            }
        }
    }
    #[inline]
    fn step_buffered(&mut self, write: impl FnMut(W)) -> bool {
        Axis::step_buffered(self, write)
    }
    fn ended(&self) -> bool {
        self.player().is_ended()
    }
    fn rested(&self) -> bool {
        self.player().is_rested()
    }
    fn set_rested(&mut self, rested: bool) {
        Axis::player_mut(self).set_rested(rested);
    }
}

/// What [`Player::play_pulsed`] did.
pub(crate) enum Pulsed<F> {
    /// No step is ahead of the pin: nothing called.
    Ended,
    /// Pulsed and handed the run's next period.
    Played,
    /// Pulsed; the run is played: `write` back, for the path past it.
    Empty(F),
}

/// A [`Player`], an [`Axis`] or [`Axes`](crate::player::Axes) for a reload
/// register that takes effect at the next wrap.
///
/// Playing a move on a timer whose reload register takes effect at the next
/// wrap: SysTick, an STM32 timer's `ARR` with preload on, an AVR timer's
/// compare register in a PWM mode, and many others.
///
/// Such a timer has two periods in hand: the one it counts now and the one
/// it loads when that ends. When its interrupt runs, the counter has
/// already loaded the next interval, so the period written then is the one
/// *after* the interval now starting. [`Player::step`] hands out the period
/// of the interval that starts now, right for a register that takes effect
/// at once (`ARR` without preload, a compare register scheduled at
/// `last + period`); on a buffered register every period would play one
/// interval late. [`Buffered`] keeps the player one period ahead: its
/// [`start`](Buffered::start) gives the first two periods, to load before
/// and right after the counter starts, and each interrupt hands out the one
/// after the interval now starting.
///
/// The steps: the first is taken at the start, at once; each interrupt
/// (the end of an interval) takes the next, and the interrupt that ends the
/// last interval ends the move. Step `k` (from 0) is at the sum of the first
/// `k` periods the player hands out, as with [`Player::step`] on a register
/// that takes effect at once.
///
/// ```
/// use profile_core::player::{Buffered, Player, Ramp};
///
/// static RAMP: [u16; 3] = [3000, 2000, 1500];
/// let mut stepper = Buffered::new(Player::new(Ramp::steps(&RAMP)));
/// let (first, next) = stepper.start(4);
/// // Load `first`, start the counter, then load `next`; step 0 is now.
/// assert_eq!((first, next), (Some(3000), Some(2000)));
/// let mut loaded = vec![];
/// let mut steps = 1;
/// // Each interrupt: a step now, and the period after the one starting.
/// while stepper.step(|period| loaded.push(period)) {
///     steps += 1;
/// }
/// assert_eq!((steps, loaded), (4, vec![2000, 3000]));
/// ```
///
/// [`stop`](Buffered::stop) and [`set_cruise`](Buffered::set_cruise) act on
/// the periods not yet handed out, as the player's do: the pin plays
/// exactly the periods the player hands out, in their order, stops and
/// cruise changes included. One period is always in the timer's hands, so
/// they take effect one interval after the same call on a register that
/// takes effect at once.
///
/// A call that starts a move (`start`, `run`, `move_to`, `move_by`) says
/// what to load by where the timer stands:
///
/// - at rest (the interrupt that ends the last interval has come, or
///   nothing has played yet): `(Some(first), next)`: load `first`, start
///   the counter (the first step is taken now), then load `next`;
/// - in a move's last interval, every step taken and the counter still
///   counting: `(None, Some(first))`: load `first` into the reload register
///   now, the counter running on; the interrupt that ends the interval
///   takes the new move's first step, as on a register that takes effect
///   at once;
/// - while a step is ahead of the pin (its period in the register): `(None,
///   None)`, nothing to load: the new move follows the periods in the
///   timer's hands, the last of them taken in its own move's direction.
///
/// So the same two lines serve every case: load `first` and start the
/// counter if there is one, then load `next` if there is one.
///
/// ```
/// use profile_core::player::{Buffered, Player, Ramp};
///
/// static RAMP: [u16; 3] = [3000, 2000, 1500];
/// let mut stepper = Buffered::new(Player::new(Ramp::steps(&RAMP)));
/// assert_eq!(stepper.start(2), (Some(3000), Some(3000)));
/// // One interrupt: the second and last step; the counter counts the
/// // last interval.
/// assert!(stepper.step(|_| unreachable!()));
/// assert!(stepper.is_done());
/// // A move from there: its first period to the register now, and the
/// // interrupt that ends the interval takes its first step.
/// assert_eq!(stepper.start(3), (None, Some(3000)));
/// let mut loaded = vec![];
/// while stepper.step(|period| loaded.push(period)) {}
/// assert_eq!(loaded, [2000, 3000]);
/// ```
// The stepper first, so that its step path keeps its offsets (an M0 loads
// a word at most 124 bytes from its base).
#[derive(Clone, Debug)]
#[repr(C)]
pub struct Buffered<S> {
    inner: S,
    /// For [`Axes`](crate::player::Axes): the mask of the axes that step on the
    /// edge whose period is in the reload register, its step not taken
    /// yet; 0 when
    /// there is none (never 0 else: the lead steps on every edge). A
    /// [`Player`] or an [`Axis`] says so itself: a step is ahead of the pin
    /// until its step returns `false`.
    ahead: u32,
}

/// Where the timer stands for a call that may start a move.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Timer {
    /// Stopped: a move starts the counter.
    Rest,
    /// Counting a move's last interval, every step taken: a move's first
    /// period goes to the register.
    Last,
    /// A step is ahead of the pin: a move follows the periods in the
    /// timer's hands.
    Playing,
}

impl<S> Buffered<S> {
    /// Wraps a player, an axis or axes at rest: a new one, or one whose
    /// step has returned `false`. (A player that has handed out periods
    /// since its step last returned `false` has the last of them in the
    /// register, its step not taken.)
    pub fn new(inner: S) -> Self {
        Buffered { inner, ahead: 0 }
    }

    /// The player or axis: what it has handed out is one period ahead of
    /// the pin.
    pub fn inner(&self) -> &S {
        &self.inner
    }

    /// The player or axis, the move given up.
    pub fn into_inner(self) -> S {
        self.inner
    }
}

impl<S: Steps> Buffered<S> {
    /// Begins the move the inner player has started: the first period (load
    /// it, then start the counter; the first step is taken now) and the
    /// second (load it right after). `(None, None)` for a move without
    /// steps; a one-step move has no second period.
    pub fn begin(&mut self) -> (Option<S::Word>, Option<S::Word>) {
        // Without a second period the inner player has returned `false`:
        // no step is ahead of the pin.
        let first = self.inner.next_period();
        let next = first.as_ref().and_then(|_| self.inner.next_period());
        if first.is_some() {
            self.inner.set_rested(false);
        }
        (first, next)
    }

    /// Where the timer stands.
    fn timer(&self) -> Timer {
        match (self.inner.ended(), self.inner.rested()) {
            (false, _) => Timer::Playing,
            (true, false) => Timer::Last,
            (true, true) => Timer::Rest,
        }
    }

    /// What to load for the move the inner player has just started, the
    /// timer standing at `timer` (the type's docs).
    fn load(&mut self, timer: Timer) -> (Option<S::Word>, Option<S::Word>) {
        match timer {
            Timer::Rest => self.begin(),
            Timer::Last => (None, self.inner.next_period()),
            Timer::Playing => (None, None),
        }
    }

    /// From the timer's interrupt, at the end of an interval: `true` when a
    /// step is taken now, having handed the period after the interval now
    /// starting to `write` (not called near the move's end, where there is
    /// none); `false` when the interval that ended was the move's last.
    #[inline]
    pub fn step(&mut self, write: impl FnMut(S::Word)) -> bool {
        // While the player has periods, one is always in the register; then
        // the period in the register, if any, is the last interval,
        // starting now: one kind of the run being played says which.
        // The player comes to rest on its path past the run, where the
        // move has ended.
        self.inner.step_buffered(write)
    }

    /// From the timer's interrupt, at the end of an interval: when a step
    /// is taken now, calls `pulse` first (so that every edge comes the same
    /// time after its wrap, whatever work the step then does: a refill at a
    /// change of stretch takes longer than a load), then hands the period
    /// after the interval now starting to `write`, and returns `true`;
    /// `false` when the interval that ended was the move's last.
    /// [`Buffered::step`] with the pin pulsed first.
    #[inline]
    pub fn pulse_and_step(&mut self, pulse: impl FnOnce(), write: impl FnMut(S::Word)) -> bool {
        self.inner.step_pulsed(pulse, write)
    }

    /// Steps not yet taken (at most `u32::MAX`).
    pub fn remaining(&self) -> u32 {
        self.inner
            .remaining()
            .saturating_add(u32::from(!self.inner.ended()))
    }

    /// `true` when every step has been taken (the last interval may still
    /// be counting).
    pub fn is_done(&self) -> bool {
        self.remaining() == 0
    }
}

impl<S: Adjust> Buffered<S> {
    /// Decelerates to rest ([`Player::stop`], [`Axis::stop`],
    /// [`Axes::stop`](crate::player::Axes::stop)), from the first period
    /// not yet in the timer's hands.
    pub fn stop(&mut self) {
        self.inner.stop();
    }

    /// Stops along the emergency ramp ([`Player::abort`],
    /// [`Axis::abort`], [`Axes::abort`](crate::player::Axes::abort)), from
    /// the first period not yet in the timer's hands.
    pub fn abort(&mut self) {
        self.inner.abort();
    }

    /// Cruises at step `pos` of the acceleration ramp
    /// ([`Player::set_cruise`]), from the first period not yet in the
    /// timer's hands.
    pub fn set_cruise(&mut self, pos: u32) {
        self.inner.set_cruise(pos);
    }

    /// Cruises at a period in ticks ([`Player::set_cruise_period`]), from
    /// the first period not yet in the timer's hands.
    pub fn set_cruise_period(&mut self, period: S::Word) {
        self.inner.set_cruise_period(period);
    }
}

impl<'a, W: TableWord, L: Layout> Buffered<Player<'a, W, L>> {
    /// Starts a move of `steps` steps ([`Player::start`]): what to load as
    /// the type's docs say (from rest, [`Buffered::begin`]).
    pub fn start(&mut self, steps: u32) -> (Option<W>, Option<W>) {
        let timer = self.timer();
        self.inner.start(steps);
        self.load(timer)
    }

    /// Ends the move `steps` periods after those already handed out (one
    /// is in the timer's hands), if it can stop in that many
    /// ([`Player::retarget`]); `false`, changing nothing, when it cannot.
    /// As the player's: with every period handed out (at rest, or in the
    /// move's last interval) there is no move to end later, and only
    /// `retarget(0)` is taken, changing nothing.
    pub fn retarget(&mut self, steps: u32) -> bool {
        self.inner.retarget(steps)
    }

    /// A move without an end ([`Player::run`]) until [`Buffered::stop`]:
    /// what to load as the type's docs say. While a move plays, it goes on
    /// from the first period not yet in the timer's hands and there is
    /// nothing to load, `(None, None)`.
    pub fn run(&mut self) -> (Option<W>, Option<W>) {
        let timer = self.timer();
        self.inner.run();
        self.load(timer)
    }
}

impl<'a, W: TableWord, L: Layout> Buffered<Axis<'a, W, L>> {
    /// Moves to `target` ([`Axis::move_to`]): the direction to set now,
    /// and, when the move starts from rest, its first two periods
    /// ([`Buffered::begin`]). While a move plays, the new target is taken
    /// from the first period not yet in the timer's hands, and there is
    /// nothing to load: `(direction, None, None)`. In the move's last
    /// interval (its last period in the timer's hands, the player's all
    /// handed out), the move to `target` follows that step as it would
    /// follow a stop: every step is taken in the direction of the move it
    /// belongs to, and [`Buffered::direction`] changes at the step that
    /// starts the way back.
    pub fn move_to(&mut self, target: i64) -> (Direction, Option<W>, Option<W>) {
        if self.last_ahead() {
            self.inner.move_after(target);
            return (self.inner.direction(), None, None);
        }
        let timer = self.timer();
        let direction = self.inner.move_to(target);
        let (first, next) = self.load(timer);
        (direction, first, next)
    }

    /// Queues a move to `target` ([`Axis::queue`]): the direction to set
    /// now, and, when it starts a move from rest, its first two periods
    /// ([`Buffered::begin`]). In the move's last interval (its periods all
    /// in the timer's hands), a target the same way no longer joins it at
    /// speed: it follows that step at rest, as a new target does
    /// ([`Buffered::move_to`]).
    pub fn queue(&mut self, target: i64) -> Result<(Direction, Option<W>, Option<W>), QueueFull> {
        if self.last_ahead() {
            self.inner.enqueue(target, false)?;
            return Ok((self.inner.direction(), None, None));
        }
        let timer = self.timer();
        let direction = self.inner.queue(target)?;
        let (first, next) = self.load(timer);
        Ok((direction, first, next))
    }

    /// `true` when the move's last period is in the timer's hands, its
    /// step not taken, and the axis has no period left to hand out.
    fn last_ahead(&self) -> bool {
        self.inner.remaining() == 0 && !self.inner.ended()
    }

    /// Moves by `delta` steps from the position at the pin, as
    /// [`Buffered::move_to`] does.
    pub fn move_by(&mut self, delta: i64) -> (Direction, Option<W>, Option<W>) {
        self.move_to(self.position().saturating_add(delta))
    }

    /// Runs `direction` without an end ([`Axis::run`]): the direction to
    /// set now, and from rest the first two periods to load. In the move's
    /// last interval, the run follows its last step, as a new target does
    /// ([`Buffered::move_to`]).
    pub fn run(&mut self, direction: Direction) -> (Direction, Option<W>, Option<W>) {
        if self.last_ahead() {
            self.inner.run_after(direction);
            return (self.inner.direction(), None, None);
        }
        let timer = self.timer();
        let direction = self.inner.run(direction);
        let (first, next) = self.load(timer);
        (direction, first, next)
    }

    /// The direction of the step the pin takes now, from the interrupt that
    /// [`Buffered::step`] returned `true` in: what the driver's direction pin
    /// must say for it. The axis's own direction is one step ahead at a
    /// reversal.
    pub fn direction(&self) -> Direction {
        // At a reversal, the first period after it is in the timer's
        // hands, its step not taken: the pin takes the last step before.
        self.inner.handed_direction()
    }

    /// The position at the pin, in steps: the axis's less the step whose
    /// period is in the timer's hands and not yet taken (wrapping past the
    /// ends of `i64` as the axis's does).
    pub fn position(&self) -> i64 {
        let ahead = i64::from(!self.inner.ended());
        self.inner
            .position()
            .wrapping_sub(self.inner.direction().sign() * ahead)
    }
}
