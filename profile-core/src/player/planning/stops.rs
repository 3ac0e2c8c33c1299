//! Stops: down the deceleration ramp ([`Player::stop`]) or down a second,
//! steeper one for emergencies ([`Player::with_emergency`],
//! [`Player::abort`]), and the steps each takes from where the move
//! stands ([`Player::steps_to_stop`], [`Player::steps_to_abort`]).
//!
//! An abort swaps the emergency ramp in for the deceleration ramp, with
//! everything planning knows of it (its last step, fastest period, slack,
//! top and [`Fall`]), and plans the stop on it as [`Player::stop`] plans
//! one; the step paths play it as they play any deceleration. The next
//! move started swaps the deceleration ramp back.

use crate::base::timer::TableWord;
use crate::player::planning::reader::{Reader, RunRead};
use crate::player::planning::search;
use crate::player::planning::threshold;
use crate::player::ramps::ramp::{Cursor, ticks_at};
use crate::player::{Layout, Player, Ramp};
use crate::table::fall::Fall;
/// A deceleration ramp and what planning knows of it beside an
/// acceleration ramp: the player's fields of the same names.
#[derive(Clone, Debug)]
pub(crate) struct DecelSide<'a, W> {
    pub(crate) decel: Ramp<'a, W>,
    pub(crate) decel_last: u32,
    pub(crate) decel_fastest: u32,
    /// The first acceleration step faster than `decel_fastest`.
    pub(crate) cap: u32,
    pub(crate) decel_slack: u32,
    /// The two ramps' slack added.
    pub(crate) slack: u32,
    pub(crate) top: Option<Cursor>,
    pub(crate) fall: Fall,
}

impl<'a, W: TableWord> DecelSide<'a, W> {
    /// `decel` beside `accel`, and the acceleration ramp's slack: a pass
    /// or two over both ramps.
    pub(crate) fn of(accel: &Ramp<'a, W>, decel: Ramp<'a, W>) -> (Self, u32) {
        let decel_fastest = decel.fastest();
        let one = search::one_ramp(accel, &decel);
        let (accel_slack, decel_slack) = search::slacks(accel, &decel, one);
        let decel_last = decel.len_steps().saturating_sub(1);
        let side = DecelSide {
            decel,
            decel_last,
            decel_fastest,
            // One ramp both ways has no step faster than its fastest.
            cap: match one {
                true => u32::MAX,
                false => accel.first_faster_than(decel_fastest),
            },
            decel_slack,
            slack: accel_slack.saturating_add(decel_slack),
            top: Cursor::at(&decel, decel_last),
            fall: search::fall(accel, &decel, decel_slack, one),
        };
        (side, accel_slack)
    }
}

/// The steps a stop plays down `decel` (its last step `last`, its slack
/// `slack`, a cursor at its top `top`) when the period of the last step
/// played is `current`: from the ramp's last entry not shorter than it
/// down to rest; 0 before the first step (`current` 0) or when the motor
/// already runs slower than the ramp's slowest entry. The cursor at the
/// entry the stop plays first is put in `at`, if given, where the search
/// has it at hand. The entry is the last whose period is not shorter than
/// `current`, exactly as a walk down from the ramp's top finds it: a
/// search past the steps the ramp's slack rules out, then on an indexed
/// ramp each run in closed form, else the steps one by one.
fn stop_steps_on<W: TableWord>(
    decel: &Ramp<'_, W>,
    (last, slack, top): (u32, u32, Option<Cursor>),
    current: u32,
    at: Option<&mut Option<Cursor>>,
) -> u32 {
    if current == 0 {
        return 0;
    }
    if let Ramp::Indexed(index) = *decel {
        let mut read = RunRead::new(index);
        if read.ticks(0).is_none_or(|t| t < current) {
            return 0;
        }
        let entry = read.last_at_least(last, current, slack, 0).unwrap_or(0);
        if let Some(at) = at {
            *at = read.cursor(entry);
        }
        return entry + 1;
    }
    let slowest = match decel.per_step() {
        Some(d) => ticks_at(d, 0),
        None => Reader::new(decel, top).ticks(0),
    };
    if slowest.unwrap_or(0) < current {
        return 0;
    }
    let entry = match decel.per_step() {
        Some(d) => search::last_at_least(|pos| ticks_at(d, pos), last, slack, current),
        // (Step 0 is that long: checked above.)
        None => threshold::last_at_least_on(decel, top, last, slack, current).unwrap_or(0),
    };
    entry + 1
}

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    /// Decelerates from the current speed to rest: the deceleration ramp is
    /// entered at its last entry whose period is not shorter than the
    /// current one (the fastest not faster), and the move ends when the
    /// ramp's slowest entry has played (at once, when the motor already
    /// runs slower than that entry). A stop never lengthens a move.
    pub fn stop(&mut self) {
        self.endless = false;
        if self.remaining() == 0 {
            return;
        }
        let (acc, _, current) = self.now();
        self.stop_from(acc, current);
    }

    /// [`Player::stop`], the acceleration side standing at `acc` and the
    /// last step played `current` ticks long; `true` when it changed the
    /// move.
    fn stop_from(&mut self, acc: u32, current: u32) -> bool {
        let remaining = self.remaining();
        let mut at = None;
        let needed = self.stop_steps_at(current, Some(&mut at));
        if needed == 0 {
            // Not moving yet, or already slower than the ramp's slowest
            // entry: at rest now.
            self.plan.clear();
            self.follow(current);
        } else if needed < remaining {
            let sides = sides!(self);
            // Where the search left a cursor at the entry: taken.
            sides.crossed.set(at);
            let stretch = sides.decelerate(needed - 1, acc);
            self.plan.clear();
            self.plan.push(stretch);
            self.follow(current);
        } else {
            return false;
        }
        true
    }

    /// The steps a stop plays when the period of the last step played is
    /// `current` ([`stop_steps_on`] the deceleration ramp).
    pub(in crate::player) fn stop_steps(&self, current: u32) -> u32 {
        self.stop_steps_at(current, None)
    }

    /// [`Player::stop_steps`], the cursor at the deceleration ramp's entry
    /// the stop plays first put in `at`, if given.
    fn stop_steps_at(&self, current: u32, at: Option<&mut Option<Cursor>>) -> u32 {
        let side = (self.decel_last, self.decel_slack, self.known.tops[1]);
        stop_steps_on(&self.decel, side, current, at)
    }

    /// Steps a [`Player::stop`] now would play: the deceleration ramp from
    /// its last entry not shorter than the current period, or the
    /// steps that remain when fewer. 0 at rest, before the first step, and
    /// when the motor already runs slower than the ramp's slowest entry.
    pub fn steps_to_stop(&self) -> u32 {
        match self.remaining() {
            0 => 0,
            remaining => self.stop_steps(self.now().2).min(remaining),
        }
    }

    /// The same player with an emergency ramp (ordered slow to fast, of
    /// the same layout and `reload_offset`, and as fast at its top as the
    /// acceleration ramp, or an abort from full speed enters it at its
    /// fastest entry, slower than the motor runs): what [`Player::abort`]
    /// decelerates along. It reads the ramp once, as making a player does.
    /// Without one, an abort is a [`Player::stop`].
    ///
    /// ```
    /// use profile_core::player::Player;
    ///
    /// static RAMP: [u16; 5] = [4000, 3000, 2400, 2000, 1700];
    /// static ESTOP: [u16; 2] = [4000, 1700];
    /// let mut player = Player::new(&RAMP).with_emergency(&ESTOP);
    /// player.start(100);
    /// for _ in 0..10 {
    ///     player.next_period();
    /// }
    /// assert_eq!(player.steps_to_stop(), 5);
    /// assert_eq!(player.steps_to_abort(), 2);
    /// player.abort();
    /// assert!(player.is_aborting());
    /// let rest: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
    /// assert_eq!(rest, [1700, 4000]);
    /// // The next move decelerates along the ramp again.
    /// player.start(6);
    /// let periods: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
    /// assert_eq!(periods, [4000, 3000, 2400, 2400, 3000, 4000]);
    /// ```
    #[must_use]
    pub fn with_emergency<R: crate::player::IntoRamp<'a, W, Layout = L>>(
        mut self,
        emergency: R,
    ) -> Self {
        self.restore_decel();
        let (side, _) = DecelSide::of(&self.accel, emergency.into_ramp());
        self.spare = Some(side);
        self
    }

    /// Stops as soon as the emergency ramp ([`Player::with_emergency`])
    /// allows: the ramp is entered at its last entry whose period is not
    /// shorter than the current one (the fastest not faster), and plays
    /// down to its slowest entry, where the move ends (at once, when the
    /// motor already runs slower than that entry). As [`Player::stop`]
    /// does on the deceleration ramp, which is what an abort without an
    /// emergency ramp plays; an abort never lengthens a move. Once it
    /// plays, the move changes no more but by another stop or abort:
    /// [`Player::retarget`] refuses a new end and a new cruise waits for
    /// the next move.
    pub fn abort(&mut self) {
        if self.spare.is_none() || self.aborting {
            return self.stop();
        }
        self.endless = false;
        if self.remaining() == 0 {
            return;
        }
        // Where the move stands, read on the ramps it plays now.
        let (acc, _, current) = self.now();
        self.swap_decel();
        self.aborting = true;
        if !self.stop_from(acc, current) {
            // The move's own end is nearer: it stays planned on its
            // deceleration ramp.
            self.restore_decel();
        }
    }

    /// Steps an [`Player::abort`] now would play, as
    /// [`Player::steps_to_stop`] counts a stop's: the emergency ramp from
    /// its last entry not shorter than the current period, or the steps
    /// that remain when fewer.
    pub fn steps_to_abort(&self) -> u32 {
        let Some(side) = self.spare.as_ref().filter(|_| !self.aborting) else {
            return self.steps_to_stop();
        };
        match self.remaining() {
            0 => 0,
            remaining => {
                let at = (side.decel_last, side.decel_slack, side.top);
                stop_steps_on(&side.decel, at, self.now().2, None).min(remaining)
            }
        }
    }

    /// `true` while an [`Player::abort`] plays.
    pub fn is_aborting(&self) -> bool {
        self.aborting && self.remaining() > 0
    }

    /// The deceleration ramp back in place of the emergency ramp, if an
    /// abort had swapped them: before a new move is planned.
    pub(in crate::player) fn restore_decel(&mut self) {
        if self.aborting {
            self.swap_decel();
            self.aborting = false;
        }
    }

    /// Swaps the deceleration side with the spare one.
    fn swap_decel(&mut self) {
        let Some(side) = self.spare.as_mut() else {
            return;
        };
        core::mem::swap(&mut self.decel, &mut side.decel);
        core::mem::swap(&mut self.decel_last, &mut side.decel_last);
        core::mem::swap(&mut self.decel_fastest, &mut side.decel_fastest);
        core::mem::swap(&mut self.cap, &mut side.cap);
        core::mem::swap(&mut self.decel_slack, &mut side.decel_slack);
        core::mem::swap(&mut self.slack, &mut side.slack);
        core::mem::swap(&mut self.known.tops[1], &mut side.top);
        core::mem::swap(&mut self.known.fall, &mut side.fall);
    }
}
