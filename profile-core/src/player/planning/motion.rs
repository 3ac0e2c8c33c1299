//! Moves that change while they play: a speed without an end
//! ([`Player::run`]), a cruise speed in ticks ([`Player::set_cruise_period`])
//! and a new end ([`Player::retarget`]).

use crate::base::timer::TableWord;
use crate::player::planning::reader::{Reader, RunRead};
use crate::player::planning::search;
use crate::player::planning::threshold;
use crate::player::ramps::ramp::{Cursor, ticks_at};
use crate::player::{Layout, Player, Ramp};

/// Steps a run plans at a time: when they are played but for the
/// deceleration, the run plans as many again from where it stands.
const LAP: u32 = 1 << 31;

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    /// Starts a move without an end: up the acceleration ramp to the cruise
    /// position (its top, or where [`Player::set_cruise`] or
    /// [`Player::set_cruise_period`] put it), and at cruise until
    /// [`Player::stop`] decelerates it to rest. [`Player::remaining`]
    /// counts to an end that is put off, a lap of 2³¹ steps at a time,
    /// for as long as the run goes on.
    ///
    /// ```
    /// use profile_core::player::{Player, Ramp};
    ///
    /// static RAMP: [u16; 3] = [3000, 2000, 1500];
    /// let mut player = Player::new(Ramp::steps(&RAMP));
    /// player.run();
    /// let jog: Vec<u16> = (0..6).map(|_| player.next_period().unwrap()).collect();
    /// assert_eq!(jog, [3000, 2000, 1500, 1500, 1500, 1500]);
    /// player.stop();
    /// let rest: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
    /// assert_eq!(rest, [1500, 2000, 3000]);
    /// ```
    ///
    /// While a move plays, it goes on from where it stands (as
    /// [`Player::retarget`] does) and no longer ends.
    pub fn run(&mut self) {
        if self.remaining() > 0 {
            // (An abort refuses it.)
            self.endless = self.retarget(LAP);
        } else {
            self.run_lap(LAP);
        }
    }

    fn run_lap(&mut self, lap: u32) {
        self.begin(lap);
        self.endless = self.remaining() > 0;
    }

    /// The run's next lap, its deceleration reached: as many steps again
    /// from where the acceleration side stands. A ramp whose deceleration
    /// is longer than a lap ends the run there.
    #[cold]
    pub(in crate::player) fn next_lap(&mut self) {
        // Within reach of the deceleration ramp at once: no lap to add.
        if LAP - 1 <= self.decel_last {
            self.endless = false;
            return;
        }
        let (acc, _, last) = self.now();
        let before = self.remaining();
        self.plan_steps(acc, LAP);
        self.extended += u64::from(LAP - before);
        self.before = last;
    }

    /// Steps the laps of a run have added since it started: a run's
    /// position is its start plus the steps played, and those are the
    /// first lap's steps plus these, less the steps that remain.
    pub(crate) fn extended(&self) -> u64 {
        self.extended
    }

    /// `true` while a run ([`Player::run`]) plays at cruise, not stopped.
    pub fn is_running(&self) -> bool {
        self.endless && self.remaining() > 0
    }

    /// Cruises at the fastest entry of the acceleration ramp whose period is
    /// not shorter than `period` (in the table's ticks, as it holds them),
    /// or at its slowest entry when every entry is shorter: a speed set in
    /// timer ticks, without the table's indices. Then as
    /// [`Player::set_cruise`]. (On a table rounded by diffusion, whose
    /// neighbours may differ by a tick either way, the last entry not
    /// shorter.)
    ///
    /// ```
    /// use profile_core::player::{Player, Ramp};
    ///
    /// static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
    /// let mut player = Player::new(Ramp::steps(&RAMP));
    /// player.set_cruise_period(2500);
    /// player.run();
    /// let jog: Vec<u16> = (0..4).map(|_| player.next_period().unwrap()).collect();
    /// assert_eq!(jog, [4000, 3000, 3000, 3000]);
    /// ```
    ///
    /// An entry inside a band the player avoids ([`Player::avoiding`])
    /// gives way to the fastest entry slower than the band.
    pub fn set_cruise_period(&mut self, period: W) {
        self.cruise_from(period.into_ticks());
    }

    /// Cruises at the last entry not shorter than `ticks` outside every
    /// band ([`Player::set_cruise_period`] in ticks).
    #[inline(always)]
    fn cruise_from(&mut self, ticks: u32) {
        let ticks = match self.avoid.is_empty() {
            true => ticks,
            false => self.outside_bands(ticks),
        };
        match self.cruise_position(ticks) {
            (_, _, Some(held)) => self.cruise_at_found(held),
            (pos, none_later, None) => self.cruise_at(pos, none_later),
        }
    }

    /// The same player keeping its cruise out of `bands` of periods,
    /// `(shortest, longest)` inclusive as the table holds them
    /// ([`band_periods`] makes them from step
    /// rates): a cruise that [`Player::set_cruise`] or
    /// [`Player::set_cruise_period`] would set inside a band is the fastest
    /// entry slower than the band instead, the side never faster than
    /// asked (the slowest entry where no entry is slower). Moves still
    /// cross the bands as they accelerate and decelerate; the ramp's top,
    /// where [`Player::start`] cruises, is the table's to keep out of them
    /// (a profile's `avoid` checks it at compile time).
    ///
    /// ```
    /// use profile_core::player::{Player, Ramp};
    ///
    /// static RAMP: [u16; 5] = [4000, 3000, 2000, 1500, 1200];
    /// // The motor rings between 1800 and 3200 ticks a step.
    /// static AVOID: [(u32, u32); 1] = [(1800, 3200)];
    /// let mut player = Player::new(Ramp::steps(&RAMP)).avoiding(&AVOID);
    /// player.set_cruise_period(2000); // 2000 and 3000 are in the band
    /// player.run();
    /// let jog: Vec<u16> = (0..3).map(|_| player.next_period().unwrap()).collect();
    /// assert_eq!(jog, [4000, 4000, 4000]);
    /// ```
    #[must_use]
    pub fn avoiding(mut self, bands: &'a [(u32, u32)]) -> Self {
        self.avoid = bands;
        self
    }

    /// The longest period of the band the entry at `pos` lies in, if any.
    fn band_at(&self, pos: u32) -> Option<u32> {
        let period = self.accel.period_at(pos)?.into_ticks();
        self.avoid
            .iter()
            .find(|&&(shortest, longest)| period >= shortest && period <= longest)
            .map(|&(_, longest)| longest)
    }

    /// The period to search from instead of `ticks` so that the entry found
    /// lies outside every band: past each band the search lands in.
    #[cold]
    #[inline(never)]
    fn outside_bands(&self, mut ticks: u32) -> u32 {
        for _ in 0..self.avoid.len() {
            match self.band_at(self.cruise_position(ticks).0) {
                Some(longest) if longest >= ticks && longest < u32::MAX => ticks = longest + 1,
                _ => break,
            }
        }
        ticks
    }

    /// [`Player::set_cruise`] with bands to avoid.
    #[cold]
    #[inline(never)]
    pub(in crate::player) fn set_cruise_avoiding(&mut self, pos: u32) {
        match self.band_at(pos.min(self.accel_last)) {
            Some(longest) if longest < u32::MAX => self.cruise_from(longest + 1),
            _ => self.cruise_at(pos, false),
        }
    }

    /// The position [`Player::set_cruise_period`] cruises at: the last
    /// whose period is not shorter than `ticks`, 0 when none is; whether
    /// no later step is known to be as long as it (on an indexed ramp,
    /// where a plan uses it: the step found is that long); and on an
    /// indexed ramp the cursor at the step found.
    pub(in crate::player) fn cruise_position(&self, ticks: u32) -> (u32, bool, Option<Cursor>) {
        let (last, slack) = (self.accel_last, self.accel_slack);
        match (self.accel.per_step(), self.accel) {
            (Some(a), _) => (
                search::last_at_least(|pos| ticks_at(a, pos), last, slack, ticks),
                false,
                None,
            ),
            (None, Ramp::Indexed(index)) => {
                // The runs' first periods, then each run in closed form.
                let mut accel = RunRead::new(index);
                match accel.last_at_least(last, ticks, slack, 0) {
                    Some(pos) => (pos, true, accel.cursor(pos)),
                    None => (0, false, None),
                }
            }
            (None, _) => (
                threshold::last_at_least_on(&self.accel, self.known.tops[0], last, slack, ticks)
                    .unwrap_or(0),
                false,
                None,
            ),
        }
    }

    /// Ends the move `steps` steps from now, at rest, if it can stop in
    /// that many ([`Player::steps_to_stop`]); returns `false`, changing
    /// nothing, when it cannot. A retarget to the steps that remain is
    /// taken and changes nothing (but that a run, [`Player::run`], then
    /// ends there). At rest there is no move to end later: only
    /// `retarget(0)` is taken; [`Player::start`] starts a move. Nor is
    /// there while an abort plays ([`Player::abort`]).
    ///
    /// The move goes on from where it stands: accelerating, cruising or
    /// decelerating, it plays on along the acceleration ramp towards the
    /// cruise position (entering it, when the deceleration ramp had taken
    /// over, at its first entry not slower than the current period) until
    /// the deceleration ramp, read at the steps that remain, is not faster,
    /// and down that ramp to rest. The cruise position stays.
    ///
    /// ```
    /// use profile_core::player::{Player, Ramp};
    ///
    /// static RAMP: [u16; 3] = [3000, 2000, 1500];
    /// let mut player = Player::new(Ramp::steps(&RAMP));
    /// player.start(4);
    /// assert_eq!(player.next_period(), Some(3000));
    /// assert_eq!(player.next_period(), Some(2000));
    /// assert!(player.retarget(5));
    /// let rest: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
    /// assert_eq!(rest, [1500, 1500, 1500, 2000, 3000]);
    /// assert!(!{ player.start(6); player.next_period(); player.next_period(); player.retarget(1) });
    /// // At rest, nothing to end later.
    /// while player.next_period().is_some() {}
    /// assert!(!player.retarget(5) && player.next_period().is_none());
    /// ```
    pub fn retarget(&mut self, steps: u32) -> bool {
        self.retarget_from(self.remaining(), steps)
    }

    /// [`Player::retarget`] with the steps that remain, `remaining`, read.
    pub(crate) fn retarget_from(&mut self, remaining: u32, steps: u32) -> bool {
        if steps == remaining {
            // Where the move ends already (a run's end, no longer put off).
            self.endless = false;
            return true;
        }
        if remaining == 0 || self.aborting {
            return false;
        }
        // As `steps_to_stop`, where the move stands read once; a move
        // made no shorter can always end where it would have.
        let (acc, decelerating, current) = self.now();
        // A stop takes the deceleration ramp's steps at most: a target at
        // least that far is taken without searching its entry; and so is
        // one where that ramp is faster than the current period by more
        // than its slack, one read.
        if steps < remaining
            && steps <= self.decel_last
            && !self.stops_within(steps, current)
            && steps < self.stop_steps(current).min(remaining)
        {
            return false;
        }
        self.endless = false;
        let from = match (current, decelerating) {
            (0, _) => 0,
            (_, true) => self.accel_entry(current),
            (_, false) => acc,
        };
        if steps == 0 {
            self.plan.clear();
            self.follow(current);
        } else {
            self.replan(from, steps, current);
        }
        true
    }

    /// `true` when a stop from a period of `current` ticks takes at most
    /// `steps` steps, read at one step: the deceleration ramp's step
    /// `steps` is faster than `current` by more than the ramp's slack, and
    /// so no step after it is as long, and the stop's entry is before it.
    /// `false` when that one read does not show it.
    fn stops_within(&self, steps: u32, current: u32) -> bool {
        self.decel_ticks(steps)
            .is_some_and(|t| search::faster_by(t, self.decel_slack, current))
    }

    /// The first position of the acceleration ramp whose period is not
    /// longer than `current`; its top when none is.
    pub(in crate::player) fn accel_entry(&self, current: u32) -> u32 {
        let (last, slack) = (self.accel_last, self.accel_slack);
        match (self.accel.per_step(), self.accel) {
            (Some(a), _) => search::first_at_most(|pos| ticks_at(a, pos), last, slack, current),
            (None, Ramp::Indexed(index)) => {
                // The runs' first steps first: a step longer by more than
                // the slack is ruled out with every step before it.
                let mut accel = RunRead::new(index);
                let near = |t: u32| u64::from(t) <= u64::from(current) + u64::from(slack);
                let (long, near) = accel.bracket(0, last, near);
                let lo = if long > 0 { long + 1 } else { 0 };
                search::first_at_most_in(|pos| accel.ticks(pos), lo, near, last, slack, current)
            }
            // Held and segment tables entry by entry, whatever an entry's
            // count: the first step not longer, exactly as the search
            // finds it (no step before it is).
            (None, Ramp::Steps { .. } | Ramp::Segments(_)) => match current.checked_add(1) {
                Some(above) => match self.accel.first_faster_than(above) {
                    u32::MAX => last,
                    pos => pos,
                },
                None => 0,
            },
            (None, _) => {
                let mut accel = Reader::new(&self.accel, self.known.tops[0]);
                search::first_at_most(|pos| accel.ticks(pos), last, slack, current)
            }
        }
    }
}

/// A band of step rates, `lowest` to `highest` steps/s, as the periods of a
/// timer of `steps_hz` ticks a step (its rate over `ticks_per_step`) that
/// play in it, `(shortest, longest)` inclusive: what
/// [`Player::avoiding`] takes. A resonance band in full steps/s is its
/// motor's microsteps times faster in table steps; add a table's
/// `reload_offset` to both where it stores one. `lowest = 0` reaches every
/// period.
///
/// ```
/// use profile_core::player::band_periods;
///
/// // 100 to 150 full steps/s in 1/8 steps on a 1 MHz timer.
/// const AVOID: [(u32, u32); 1] = [band_periods(1_000_000, 800, 1200)];
/// assert_eq!(AVOID, [(834, 1250)]);
/// ```
pub const fn band_periods(steps_hz: u32, lowest: u32, highest: u32) -> (u32, u32) {
    let shortest = match highest {
        0 => u32::MAX,
        h => steps_hz.div_ceil(h),
    };
    let longest = match lowest {
        0 => u32::MAX,
        l => steps_hz / l,
    };
    (shortest, longest)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use crate::player::{Player, Ramp};
    use std::vec::Vec;

    /// A run plays lap after lap at cruise, the laps joined without a
    /// deceleration, and a stop after many laps decelerates from cruise.
    #[test]
    fn a_run_joins_its_laps_at_cruise() {
        static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
        let mut player = Player::new(Ramp::steps(&RAMP));
        player.run_lap(10);
        let mut played = Vec::new();
        for _ in 0..100 {
            played.push(player.next_period().unwrap());
        }
        assert_eq!(played[..4], [4000, 3000, 2000, 1500]);
        assert!(played[3..].iter().all(|&p| p == 1500), "{played:?}");
        assert!(player.is_running());
        // Each lap after the first added its steps but the deceleration.
        let steps = 100 + u64::from(player.remaining());
        assert_eq!(steps, 10 + player.extended());
        player.stop();
        let rest: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
        assert_eq!(rest, [1500, 2000, 3000, 4000]);
    }

    /// At the top speed a stop takes the whole deceleration ramp: a target
    /// one step short of it is refused, one that far is taken, however
    /// many steps the move has left, on tables and on runs, indexed or
    /// not.
    #[test]
    fn a_target_as_far_as_the_whole_deceleration_is_taken() {
        use crate::table::runs::RunIndex;
        static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
        // The same steps as runs of one step each.
        static RUNS: [[u16; 5]; 4] = [
            [1, 4000, 0, 0, 0],
            [1, 3000, 0, 0, 0],
            [1, 2000, 0, 0, 0],
            [1, 1500, 0, 0, 0],
        ];
        static INDEX: RunIndex<4> = RunIndex::new(&RUNS);
        for ramp in [Ramp::steps(&RAMP), Ramp::runs(&RUNS), Ramp::indexed(&INDEX)] {
            let mut player = Player::new(ramp);
            player.start(100);
            for _ in 0..10 {
                player.next_period();
            }
            assert_eq!(player.steps_to_stop(), 4);
            assert!(!player.retarget(3), "{ramp:?}");
            assert_eq!(player.remaining(), 90);
            assert!(player.retarget(4), "{ramp:?}");
            let rest: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
            assert_eq!(rest, [1500, 2000, 3000, 4000]);
        }
    }

    /// A target is taken at one read only where the deceleration ramp is
    /// faster than the current period by more than its slack: here its
    /// step 3 is a tick faster, but step 4, a tick slower again, is as
    /// long, so the stop takes 5 steps and a target of 3 is refused, on
    /// tables and on runs, indexed or not.
    #[test]
    fn a_target_within_the_slack_is_searched() {
        use crate::table::runs::RunIndex;
        static RAMP: [u16; 6] = [3000, 2000, 1500, 1499, 1500, 1400];
        static RUNS: [[u16; 5]; 6] = [
            [1, 3000, 0, 0, 0],
            [1, 2000, 0, 0, 0],
            [1, 1500, 0, 0, 0],
            [1, 1499, 0, 0, 0],
            [1, 1500, 0, 0, 0],
            [1, 1400, 0, 0, 0],
        ];
        static INDEX: RunIndex<6> = RunIndex::new(&RUNS);
        for ramp in [Ramp::steps(&RAMP), Ramp::runs(&RUNS), Ramp::indexed(&INDEX)] {
            let mut player = Player::new(ramp);
            player.start(100);
            let played: Vec<u16> = (0..3).filter_map(|_| player.next_period()).collect();
            assert_eq!(played, [3000, 2000, 1500]);
            assert_eq!(player.steps_to_stop(), 5, "{ramp:?}");
            assert!(!player.retarget(3), "{ramp:?}");
            assert!(!player.retarget(4), "{ramp:?}");
            assert!(player.retarget(5), "{ramp:?}");
            let rest: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
            assert_eq!(rest, [1500, 1499, 1500, 2000, 3000]);
        }
    }
}
