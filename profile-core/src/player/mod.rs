//! Playing tables in firmware: a move of `S` steps from an acceleration
//! table and a deceleration table, one call per step.
//!
//! A move follows two sides:
//!
//! - the acceleration side: a cursor on the acceleration ramp that walks one
//!   step per step towards the cruise position (up at the start, up or down
//!   after [`Player::set_cruise`]);
//! - the deceleration side: the deceleration ramp read backwards, indexed by
//!   the steps that remain, so the last step of the move is always the
//!   deceleration ramp's slowest entry.
//!
//! The acceleration side plays, no faster than the deceleration ramp's
//! fastest entry while that ramp is out of reach, until the deceleration
//! side, read at the steps that remain, is not faster; from then on the
//! deceleration ramp plays to the end. That gives the full trapezoid for long
//! moves and the triangle for short ones, with the switch point exactly where
//! the two ramps cross, for symmetric and asymmetric tables alike; the move
//! ends at exactly `S` steps, at rest, and every table plays exactly as it is
//! written (a diffused table's one-tick ties included).
//!
//! [`Player::start`], [`Player::stop`] and [`Player::set_cruise`] plan: they
//! find where the move changes from one stretch of a table to another (at
//! most a few per move), searching the tables once. [`Player::next_period`]
//! plays: a countdown, a load and an index step, with a short refill at the
//! few places the plan changes stretch (or a held or segment table changes
//! entry). No division, no floating point and no panic in playing, on any
//! input.
//!
//! A player knows from its type which tables it plays ([`Layout`]):
//! [`Player::new`] plays every layout, its step path trying the per-step
//! table's way first; [`Player::new`] of a compressed table plays compressed tables only,
//! its step path trying their run first. Each plays at nearly the cost of
//! a load.
//!
//! Around it: [`Axis`] (a position and a direction), [`Axes`] (up to 32
//! axes on one ramp, each stepping in proportion to its move), [`Buffered`]
//! (for reload registers that take effect at the next wrap).
//!
//! ```
//! use profile_core::player::{Player, Ramp};
//!
//! static ACCEL: [u16; 4] = [4000, 2500, 2000, 1800];
//! let mut player = Player::new(Ramp::steps(&ACCEL));
//! player.start(10);
//! let mut periods = [0u16; 10];
//! for p in periods.iter_mut() {
//!     *p = player.next_period().unwrap();
//! }
//! assert_eq!(player.next_period(), None);
//! assert_eq!(periods, [4000, 2500, 2000, 1800, 1800, 1800, 1800, 2000, 2500, 4000]);
//! ```

/// What the planner knows of a player (`Sides`), borrowed field by
/// field, so that the player's plan stays free to be written (the ramps'
/// tops by reference: they are large to copy).
macro_rules! sides {
    ($player:expr) => {
        $crate::player::planning::plan::Sides {
            accel: $player.accel,
            decel: $player.decel,
            accel_last: $player.accel_last,
            decel_last: $player.decel_last,
            decel_fastest: $player.decel_fastest,
            cap: $player.cap,
            cruise: $player.cruise,
            cruise_last: $player.cruise_last,
            slack: $player.slack,
            decel_slack: $player.decel_slack,
            known: &$player.known,
            recent: core::cell::Cell::new([None; 2]),
            crossed: core::cell::Cell::new(None),
            read_a: core::cell::Cell::new(None),
        }
    };
}

mod planning;
mod playing;
mod ramps;

use core::marker::PhantomData;

use crate::base::timer::TableWord;
pub use planning::motion::band_periods;
use planning::plan::{Known, Plan, Run, Source};
use planning::reader::{Reader, RunRead};
use planning::stops::DecelSide;
pub use playing::axes::Axes;
pub use playing::axis::{Axis, Direction, Moving};
pub use playing::buffered::{Adjust, AxesStart, Buffered, Steps};
pub use playing::rated::Rated;
#[cfg(feature = "fugit")]
pub use playing::rated::{OffsetMismatch, Timed};
pub use playing::targets::{QUEUE, QueueFull};
pub use ramps::layout::{AnyLayout, Compressed, IntoRamp, Layout};
pub use ramps::ramp::Ramp;
use ramps::ramp::{Cursor, ticks_at};
use ramps::runs::RunState;

/// Plays moves from an acceleration ramp and a deceleration ramp.
///
/// `L` says which ramps it plays, and so which path its step takes first:
/// [`AnyLayout`] (the default, from [`Player::new`]) plays every layout,
/// [`Compressed`] (from [`Player::new`] of a compressed table) only compressed tables,
/// at the least cost per step.
///
/// It hands out what the tables hold. A table made with `reload_offset`
/// holds register values (each period plus the offset, `-1` for STM32's
/// `ARR` or SysTick's reload), and the player hands those out: written to
/// the register, or copied there by DMA from [`Player::fill`], with no
/// instruction per step. Every decision the player takes compares entries
/// of its tables with each other (where the ramps cross, where a stop
/// joins the deceleration ramp), which one offset shifts alike: a move,
/// its stops and its cruise changes play the same steps as the periods
/// would, each value the period plus the offset. Give both ramps the same
/// offset. (The periods themselves, typed by the timer's rate, come from
/// `Timed` behind the `fugit` feature, from a [`Rated`] ramp.)
// The fields of the run being played come first, at the smallest offsets,
// for the step paths.
#[derive(Clone, Debug)]
#[repr(C)]
pub struct Player<'a, W, L = AnyLayout> {
    /// The run being played: what is left of it.
    run: Run<'a, W>,
    /// The run of a compressed ramp being played (`run` is then empty).
    computed: RunState,
    /// The move's stretches, and the one being played.
    plan: Plan<'a, W>,
    /// The period played before the plan began, in ticks (0 at rest).
    before: u32,
    accel: Ramp<'a, W>,
    decel: Ramp<'a, W>,
    accel_last: u32,
    decel_last: u32,
    /// The deceleration ramp's shortest period: no move runs faster while
    /// that ramp is out of reach.
    decel_fastest: u32,
    /// The first acceleration step faster than `decel_fastest`.
    cap: u32,
    cruise: u32,
    /// No step after the cruise position is known to be as long as it
    /// (so it is its own crossing's entry, on one indexed ramp both ways):
    /// at the ramp's top, or found on an indexed ramp by
    /// [`Player::set_cruise_period`].
    cruise_last: bool,
    /// The ramps' slack added ([`planning::search::slack`]): how far from ordered
    /// slow to fast they are, for planning's searches.
    slack: u32,
    /// The acceleration ramp's alone.
    accel_slack: u32,
    /// The deceleration ramp's alone.
    decel_slack: u32,
    /// What planning knows of the two ramps from when the player was
    /// made.
    known: Known,
    /// Playing [`Player::run`]: the deceleration is put off, a lap at a
    /// time, until [`Player::stop`].
    endless: bool,
    /// Steps the laps of a run have added to the move since it started.
    extended: u64,
    /// For [`Buffered`]: the interrupt that ends the last interval has
    /// come (the buffered step has returned `false`), or nothing has
    /// played yet; set on the buffered step's path past its run, where
    /// the move has ended, so that the run's own path does not pay for it.
    rested: bool,
    /// Period bands a cruise keeps out of ([`Player::avoiding`]).
    avoid: &'a [(u32, u32)],
    /// The emergency ramp ([`Player::with_emergency`]) and what planning
    /// knows of it; while an abort plays, the deceleration ramp's, the
    /// two swapped.
    spare: Option<DecelSide<'a, W>>,
    /// An abort has swapped the emergency ramp in.
    aborting: bool,
    layout: PhantomData<L>,
}

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    /// A player of `ramp`, decelerating along it read backwards
    /// ([`with_decel`](Self::with_decel) gives it a deceleration ramp of
    /// its own). The table's type chooses the player's step path
    /// ([`IntoRamp`]): a per-step table or any [`Ramp`] plays through
    /// [`AnyLayout`], a compressed table or its [`RunIndex`](crate::runs::RunIndex) through
    /// [`Compressed`], which plays what `Player::new(Ramp::runs(..))` plays,
    /// period for period, with a step path that knows its ramps are runs.
    /// On a compressed ramp a planning call (`start`, `stop`, a new cruise
    /// or target) leaves the first run of its plan to the step after it,
    /// which decodes it as a step does at the end of every run: that step
    /// costs what any step that begins a run costs, and the call does not.
    /// An indexed one plans its moves by bisection over the runs instead
    /// of a walk over them.
    ///
    /// Making a player reads its ramps, a pass or two over every step
    /// (their slack, their fastest periods, and how far ahead the
    /// deceleration ramp is faster at every step, which planning asks
    /// before it searches): about 96 000 instructions for a 1000-entry
    /// table on a Cortex-M3, 1.2 million for a compressed ramp of 7192
    /// steps, and under a thousand indexed (the index has all of it
    /// already). Make it once, at boot, and plan each move with
    /// [`Player::start`] or [`Player::retarget`].
    ///
    /// ```
    /// use profile_core::player::{Player, Ramp};
    ///
    /// // 3 steps from 4000.5 ticks, 500 shorter each, then 2 of 2000.
    /// static RUNS: [[u16; 5]; 2] = [[3, 4000, 0x8000, 0xFE0C, 0], [2, 2000, 0, 0, 0]];
    /// let mut fast = Player::<u16, _>::new(&RUNS);
    /// let mut any = Player::new(Ramp::runs(&RUNS));
    /// fast.start(12);
    /// any.start(12);
    /// let mut periods = [0u16; 12];
    /// for p in periods.iter_mut() {
    ///     *p = fast.next_period().unwrap();
    ///     assert_eq!(Some(*p), any.next_period());
    /// }
    /// assert_eq!(fast.next_period(), None);
    /// assert_eq!(periods[..6], [4001, 3500, 3001, 2000, 2000, 2000]);
    /// ```
    pub fn new<R: IntoRamp<'a, W, Layout = L>>(ramp: R) -> Self {
        let ramp = ramp.into_ramp();
        Self::build(ramp, ramp)
    }

    /// The same player with a deceleration ramp of its own (also ordered
    /// slow to fast, of the same layout), for asymmetric moves: it reads
    /// its two ramps again, as making a player does.
    ///
    /// ```
    /// use profile_core::player::Player;
    ///
    /// static UP: [u16; 4] = [4000, 3000, 2000, 1500];
    /// static DOWN: [u16; 2] = [4000, 1500];
    /// let mut player = Player::new(&UP).with_decel(&DOWN);
    /// player.start(6);
    /// let periods: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
    /// assert_eq!(periods, [4000, 3000, 2000, 1500, 1500, 4000]);
    /// ```
    #[must_use]
    pub fn with_decel<R: IntoRamp<'a, W, Layout = L>>(mut self, decel: R) -> Self {
        self.restore_decel();
        Self {
            avoid: self.avoid,
            spare: self.spare,
            ..Self::build(self.accel, decel.into_ramp())
        }
    }
}

impl<'a, W: TableWord, L: Layout> Player<'a, W, L> {
    fn build(accel: Ramp<'a, W>, decel: Ramp<'a, W>) -> Self {
        let accel_last = accel.len_steps().saturating_sub(1);
        let (side, accel_slack) = DecelSide::of(&accel, decel);
        Player {
            accel,
            decel,
            accel_last,
            decel_last: side.decel_last,
            decel_fastest: side.decel_fastest,
            cap: side.cap,
            cruise: accel_last,
            cruise_last: true,
            slack: side.slack,
            accel_slack,
            decel_slack: side.decel_slack,
            known: Known {
                tops: [Cursor::at(&accel, accel_last), side.top],
                fall: side.fall,
            },
            endless: false,
            extended: 0,
            // At rest: nothing to hand out, as after a move's end.
            run: Run::ended(),
            computed: RunState::default(),
            before: 0,
            plan: Plan::EMPTY,
            rested: true,
            avoid: &[],
            spare: None,
            aborting: false,
            layout: PhantomData,
        }
    }

    /// Plans `r` steps from `p` (the acceleration side's position) into
    /// the player's plan.
    fn plan_steps(&mut self, p: u32, r: u32) {
        // Two indexed ramps: the most common plan first, out of line.
        if let (Ramp::Indexed(_), Ramp::Indexed(_)) = (self.accel, self.decel) {
            if self.plan_cruising(p, r, None) {
                return;
            }
        }
        // The planner borrows the fields it reads, not the plan.
        let sides = sides!(self);
        sides.plan(&mut self.plan, p, r);
    }

    /// [`Player::plan_steps`] by the planner of every case, never by
    /// [`Player::plan_cruising`]: what the tests compare that one with.
    #[cfg(test)]
    fn plan_by_sides(&mut self, p: u32, r: u32) {
        let sides = sides!(self);
        sides.plan(&mut self.plan, p, r);
    }

    /// Plans `r` steps from `p` (the acceleration side's position) and
    /// follows the plan, `before` the period played before it.
    fn replan(&mut self, p: u32, r: u32, before: u32) {
        self.plan_steps(p, r);
        self.follow(before);
    }

    /// Follows the plan from its start: nothing played of it yet.
    fn follow(&mut self, before: u32) {
        self.run = Run::empty();
        self.computed = RunState::default();
        self.before = before;
        // A per-step table's first run now, made when the move was planned:
        // the first step plays it at once. A compressed ramp's first run is
        // decoded by the step that plays it, as at the end of every run, so
        // that a planning call does not pay for it: the step after costs no
        // more than one that ends a run.
        if !L::COMPRESSED {
            if let Some(run) = self.next_run() {
                self.run = run;
            }
        }
    }

    /// Starts a move of `steps` steps from rest, cruising at the top of the
    /// acceleration ramp. A move on an empty ramp has no steps.
    pub fn start(&mut self, steps: u32) {
        (self.cruise, self.cruise_last) = (self.accel_last, true);
        self.begin(steps);
    }

    /// Starts a move of `steps` steps from rest to the cruise position.
    pub(crate) fn begin(&mut self, steps: u32) {
        self.restore_decel();
        self.endless = false;
        self.extended = 0;
        // A ramp of no steps has no top.
        let empty = self.known.tops[0].is_none() || self.known.tops[1].is_none();
        if empty || steps == 0 {
            self.plan.clear();
            self.follow(0);
        } else {
            self.replan(0, steps, 0);
        }
    }

    /// Cruises at step `pos` of the acceleration ramp (the entry index for a
    /// table without divider) instead of its top; takes effect by walking the
    /// ramp up or down one step per step. Clamped to the ramp. An entry
    /// inside a band the player avoids ([`Player::avoiding`]) gives way to
    /// the fastest entry slower than the band.
    pub fn set_cruise(&mut self, pos: u32) {
        if !self.avoid.is_empty() {
            return self.set_cruise_avoiding(pos);
        }
        self.cruise_at(pos, false);
    }

    /// [`Player::set_cruise`], `none_later` when no later step is known
    /// to be as long as the one at `pos`.
    fn cruise_at(&mut self, pos: u32, none_later: bool) {
        self.cruise_held(pos, none_later, None);
    }

    /// [`Player::cruise_at`] a step of an indexed acceleration ramp that
    /// a search found, `held` the cursor there, no later step known to be
    /// as long.
    pub(super) fn cruise_at_found(&mut self, held: Cursor) {
        self.cruise_held(held.pos, true, Some(held));
    }

    /// [`Player::cruise_at`], the plan handed `held`, the cursor at `pos`,
    /// if given (written in, so that a call without one plans as before).
    #[inline(always)]
    fn cruise_held(&mut self, pos: u32, none_later: bool, held: Option<Cursor>) {
        self.cruise = pos.min(self.accel_last);
        self.cruise_last = none_later || self.cruise == self.accel_last;
        let remaining = self.remaining();
        if remaining > 0 {
            let (acc, decelerating, last) = self.now();
            if !decelerating {
                match held {
                    Some(held) if self.plan_cruising(acc, remaining, Some(held)) => {}
                    _ => self.plan_steps(acc, remaining),
                }
                self.follow(last);
            }
        }
    }

    /// The deceleration ramp's period at step `pos`, in ticks; `None`
    /// past its last step.
    #[inline(always)]
    pub(in crate::player) fn decel_ticks(&self, pos: u32) -> Option<u32> {
        match (self.decel.per_step(), self.decel) {
            (Some(d), _) => ticks_at(d, pos),
            (None, Ramp::Indexed(index)) => RunRead::new(index).ticks(pos),
            (None, _) => Reader::new(&self.decel, self.known.tops[1]).ticks(pos),
        }
    }

    /// Where the move stands, read off the plan once: where the
    /// acceleration side stands after the steps played, whether the
    /// deceleration ramp has taken over, and the period of the last step
    /// played, in ticks (0 at rest; read where the stretch being played,
    /// or the one before it, read it).
    fn now(&self) -> (u32, bool, u32) {
        let stretches = &self.plan.stretches[..self.plan.len];
        let Some(s) = stretches.get(self.plan.at) else {
            return (0, false, self.before);
        };
        let played = s.total - s.count - self.run.left() - self.computed.left;
        let (acc, decelerating) = (s.acc_after(played), s.decelerating);
        let (s, k) = match played {
            0 => match self.plan.at.checked_sub(1).and_then(|i| stretches.get(i)) {
                Some(prev) => (prev, prev.total),
                None => return (acc, decelerating, self.before),
            },
            // A compressed player plays every step of a stretch from the
            // run it holds, refilled by the step that plays its first: the
            // last step played is that run's.
            _ if L::COMPRESSED => return (acc, decelerating, self.computed.last()),
            _ => (s, played),
        };
        (acc, decelerating, self.period_read(s, s.read_at(k - 1)))
    }

    /// The period `s` reads at position `pos`, in ticks.
    #[inline(always)]
    fn period_read(&self, s: &planning::plan::Stretch<'a, W>, pos: u32) -> u32 {
        let ramp = if s.decel { &self.decel } else { &self.accel };
        if let Some(periods) = ramp.per_step() {
            return ticks_at(periods, pos).unwrap_or(0);
        }
        // The stretch's cursor stands near: where it reads next.
        let hint = match s.source {
            Source::At(at) => Some(at),
            _ => None,
        };
        Cursor::near(hint, ramp, pos).map_or(0, |c| c.period(ramp).into_ticks())
    }

    /// Steps left in the move.
    pub fn remaining(&self) -> u32 {
        self.run.left() + self.computed.left + self.plan.steps()
    }

    /// `true` when the move has played all its steps.
    pub fn is_done(&self) -> bool {
        self.remaining() == 0
    }

    /// `true` when the step has returned `false` and the player has handed
    /// out nothing since.
    pub(crate) fn is_ended(&self) -> bool {
        matches!(self.run, Run::Ended(_))
    }

    /// The period of the next step, in ticks, or `None` when the move is done.
    ///
    /// [`Player::step`], the period returned: the run being played inline,
    /// and past its end the plan's next run by a call, as the step takes
    /// them. It costs what the step costs, within one instruction per step
    /// on a Cortex-M0, M3 and M4F (`docs/performance.md`).
    #[inline(always)]
    pub fn next_period(&mut self) -> Option<W> {
        self.next_played()
    }

    /// Plays the next step: hands its period to `write` (a step interrupt
    /// writes it to its timer's reload register) and returns `true`, or
    /// returns `false` when the move is done. [`Player::next_period`] with
    /// the period handed to `write`: each kind of run writes from its own
    /// path.
    ///
    /// ```
    /// use profile_core::player::{Player, Ramp};
    ///
    /// static RAMP: [u16; 3] = [3000, 2000, 1500];
    /// let mut player = Player::new(Ramp::steps(&RAMP));
    /// player.start(4);
    /// let mut reload = 0;
    /// while player.step(|period| reload = period) {}
    /// assert_eq!(reload, 3000);
    /// ```
    #[inline]
    pub fn step(&mut self, write: impl FnOnce(W)) -> bool {
        if L::COMPRESSED {
            return self.step_runs(write);
        }
        // The run being played, with no call on the way: a step interrupt
        // that inlines this keeps no register for the refill's call.
        match self.play_run(write) {
            Ok(()) => true,
            Err(write) => self.step_refilled(write),
        }
    }
}
