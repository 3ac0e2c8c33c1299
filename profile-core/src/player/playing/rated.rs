//! A ramp with its timer's rate as a type, and what its table stores: for
//! periods typed by that rate (`Timed`, feature `fugit`), so that a table
//! played on a timer of another rate is a type error, not a wrong speed.

use crate::base::timer::TableWord;
use crate::player::Ramp;

/// A ramp whose table is in ticks of a timer of `HZ` ticks per second,
/// storing each period plus `reload_offset`.
///
/// A module of `include_profiles!` has one as `RAMP`, its rate the
/// profile's `TIMER_HZ`: the rate comes with the table, not from the code
/// that plays it. For a `period_table!`, name the rate the table was made
/// for (its `timer_hz`) and its `reload_offset`:
///
/// ```
/// use profile_core::player::{Ramp, Rated};
///
/// static TABLE: [u16; 3] = [999, 499, 332]; // 1000, 500, 333 ticks, less one
/// const RAMP: Rated<'static, u16, 1_000_000> = Rated::new(Ramp::steps(&TABLE), -1);
/// assert_eq!(RAMP.period_ticks(TABLE[0]), 1000);
/// assert_eq!(Rated::<u16, 1_000_000>::TIMER_HZ, 1_000_000);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rated<'a, W, const HZ: u32> {
    ramp: Ramp<'a, W>,
    reload_offset: i32,
}

impl<'a, W: TableWord, const HZ: u32> Rated<'a, W, HZ> {
    /// The timer's rate: `HZ` ticks per second.
    pub const TIMER_HZ: u32 = HZ;

    /// `ramp`, whose table is in ticks of `HZ` and stores each period plus
    /// `reload_offset` (a profile's `RELOAD_OFFSET`; 0 without one).
    pub const fn new(ramp: Ramp<'a, W>, reload_offset: i32) -> Self {
        Rated {
            ramp,
            reload_offset,
        }
    }

    /// The ramp, for a [`Player`](crate::player::Player).
    pub const fn ramp(&self) -> Ramp<'a, W> {
        self.ramp
    }

    /// What its table adds to each period it stores.
    pub const fn reload_offset(&self) -> i32 {
        self.reload_offset
    }

    /// The period, in ticks, of a value the table stores (or a player
    /// hands out): the value less the offset.
    pub fn period_ticks(&self, stored: W) -> u32 {
        stored
            .into_ticks()
            .wrapping_add_signed(self.reload_offset.wrapping_neg())
    }
}

#[cfg(feature = "fugit")]
pub use timed::{OffsetMismatch, Timed};

#[cfg(feature = "fugit")]
mod timed {
    use fugit::TimerDurationU32;

    use super::Rated;
    use crate::base::timer::TableWord;
    use crate::player::Player;

    /// A [`Player`] whose periods are durations of its timer,
    /// [`fugit::TimerDurationU32<HZ>`]: a table made for a timer of another
    /// rate does not fit where a timer of `HZ` takes its durations, at
    /// compile time. The periods are the table's own, the
    /// `reload_offset` its [`Rated`] ramp names taken off; [`Timed::fill`]
    /// and [`Timed::player`] hand out what the table stores, for a register
    /// or DMA. With `ticks_per_step = 2` a period is a half step, as the
    /// table's entries are.
    ///
    /// ```
    /// use fugit::TimerDurationU32;
    /// use profile_core::player::{Ramp, Rated, Timed};
    ///
    /// static TABLE: [u16; 3] = [999, 499, 332]; // 1000, 500, 333 ticks, less one
    /// const RAMP: Rated<'static, u16, 1_000_000> = Rated::new(Ramp::steps(&TABLE), -1);
    ///
    /// /// A timer of 1 MHz, as a HAL types it.
    /// fn schedule(after: TimerDurationU32<1_000_000>) -> u32 {
    ///     after.ticks()
    /// }
    ///
    /// let mut timed = Timed::new(RAMP);
    /// timed.start(4);
    /// let mut ticks = [0; 4];
    /// for t in &mut ticks {
    ///     *t = schedule(timed.next_duration().unwrap());
    /// }
    /// assert_eq!(ticks, [1000, 500, 500, 1000]);
    /// assert_eq!(timed.next_duration(), None);
    /// ```
    #[derive(Clone, Debug)]
    pub struct Timed<'a, W, const HZ: u32> {
        player: Player<'a, W>,
        reload_offset: i32,
    }

    /// Two ramps whose tables store their periods with different offsets:
    /// one player cannot compare them.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct OffsetMismatch {
        /// The acceleration ramp's `reload_offset`.
        pub accel: i32,
        /// The deceleration ramp's.
        pub decel: i32,
    }

    impl core::fmt::Display for OffsetMismatch {
        fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
            write!(
                f,
                "the acceleration ramp stores `reload_offset = {}` and the deceleration ramp \
                 `{}`: one player needs one offset",
                self.accel, self.decel
            )
        }
    }

    impl core::error::Error for OffsetMismatch {}

    impl<'a, W: TableWord, const HZ: u32> Timed<'a, W, HZ> {
        /// A player of `ramp`, decelerating along it read backwards.
        pub fn new(ramp: Rated<'a, W, HZ>) -> Self {
            Timed {
                player: Player::new(ramp.ramp()),
                reload_offset: ramp.reload_offset(),
            }
        }

        /// A player with its own deceleration ramp, of the same rate (the
        /// type says so) and the same offset.
        pub fn with_decel(
            accel: Rated<'a, W, HZ>,
            decel: Rated<'a, W, HZ>,
        ) -> Result<Self, OffsetMismatch> {
            if accel.reload_offset() != decel.reload_offset() {
                return Err(OffsetMismatch {
                    accel: accel.reload_offset(),
                    decel: decel.reload_offset(),
                });
            }
            Ok(Timed {
                player: Player::new(accel.ramp()).with_decel(decel.ramp()),
                reload_offset: accel.reload_offset(),
            })
        }

        /// The duration of a value the tables store.
        #[inline]
        fn duration(&self, stored: W) -> TimerDurationU32<HZ> {
            let ticks = stored
                .into_ticks()
                .wrapping_add_signed(self.reload_offset.wrapping_neg());
            TimerDurationU32::from_ticks(ticks)
        }

        /// Starts a move of `steps` steps ([`Player::start`]).
        pub fn start(&mut self, steps: u32) {
            self.player.start(steps);
        }

        /// Decelerates to rest ([`Player::stop`]).
        pub fn stop(&mut self) {
            self.player.stop();
        }

        /// Cruises at step `pos` of the acceleration ramp
        /// ([`Player::set_cruise`]).
        pub fn set_cruise(&mut self, pos: u32) {
            self.player.set_cruise(pos);
        }

        /// The next step's period as a duration of the timer, or `None`
        /// when the move is done.
        #[inline]
        pub fn next_duration(&mut self) -> Option<TimerDurationU32<HZ>> {
            let stored = self.player.next_period()?;
            Some(self.duration(stored))
        }

        /// Plays the next step: its period, a duration of the timer, to
        /// `write`; `false` when the move is done ([`Player::step`]).
        #[inline]
        pub fn step(&mut self, write: impl FnOnce(TimerDurationU32<HZ>)) -> bool {
            let offset = self.reload_offset;
            self.player.step(|stored| {
                let ticks = stored
                    .into_ticks()
                    .wrapping_add_signed(offset.wrapping_neg());
                write(TimerDurationU32::from_ticks(ticks))
            })
        }

        /// Writes the next values the tables store into `buf`, for DMA
        /// ([`Player::fill`]).
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

        /// What the tables add to each period they store.
        pub fn reload_offset(&self) -> i32 {
            self.reload_offset
        }

        /// The player, handing out what the tables store.
        pub fn player(&self) -> &Player<'a, W> {
            &self.player
        }
    }
}
