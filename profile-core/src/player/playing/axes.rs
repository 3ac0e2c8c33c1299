//! Coordinated axes: several motors on one ramp, stepping in proportion.

use crate::base::timer::TableWord;
use crate::player::playing::axis::{Direction, Moving};
use crate::player::playing::edges::{Edges, bit, follower_steps};
use crate::player::playing::lines::{Line, Queued};
use crate::player::playing::targets::Targets;
use crate::player::{AnyLayout, Layout, Player};

/// `N` axes that move together on one [`Player`]'s ramp: a straight line in
/// `N` dimensions, every axis starting and finishing with the others.
///
/// The axis with the most steps leads (of equal ones, the lowest index) and
/// plays the ramp exactly as a single [`Player`] would: the same periods,
/// stops and cruise changes. Each other axis follows it: an axis `i` of
/// `d` steps in a move whose lead takes `L` takes its `k`-th step
/// (`k = 1..=d`) on the lead's step
///
/// ```text
/// s_k = floor((2·k·L + d) / (2·d))      (lead steps numbered 1..=L)
/// ```
///
/// the lead step nearest `k·L/d`, a tie going to the later step. So its
/// last step is the lead's last (`s_d = L`), it never takes two steps on
/// one edge, and its steps are spread as evenly as the lead's edges allow.
/// The step path computes this with an integer accumulator per follower
/// (Bresenham's, set so that the rule holds exactly): an addition, and a
/// subtraction on the edges where the follower steps (for a follower of
/// more than half the lead's steps, on those where it does not: at most
/// half the edges); no division.
///
/// [`Axes::step`] hands the lead's period and a mask of the axes that step
/// on the edge now starting (bit `i` for axis `i`; the lead's bit is set on
/// every edge) to a closure that sets the step pins and loads the timer.
/// [`Axes::position`] is exact after every step, stops included: after
/// [`Axes::stop`] the lead ends early and each follower stands where the
/// rule has taken it. An axis with no steps in a move never steps; a move
/// where every axis stays has no steps. A move of more than `u32::MAX`
/// steps on an axis stops there on that axis.
///
/// `N` is at most 32 (one bit of the mask per axis) and at least 1: other
/// values do not compile.
///
/// A plotter's two axes, from `(0, 0)` to `(10, -4)`:
///
/// ```
/// use profile_core::player::{Axes, Direction, Player, Ramp};
///
/// static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
/// let mut plotter = Axes::new(Player::new(Ramp::steps(&RAMP)), [0, 0]);
/// // Set the direction pins, then step.
/// let directions = plotter.move_to([10, -4]);
/// assert_eq!(directions, [Direction::Forward, Direction::Backward]);
/// let (mut reload, mut x_pin, mut y_pin) = (0u16, 0, 0);
/// let mut y_steps_at = vec![];
/// let mut edge = 0;
/// while plotter.step(|period, mask| {
///     // Each edge: the step pins of the axes in `mask`, then the period
///     // until the next edge into the timer.
///     x_pin += mask & 1;
///     y_pin += (mask >> 1) & 1;
///     reload = period;
/// }) {
///     edge += 1;
///     if y_pin as usize > y_steps_at.len() {
///         y_steps_at.push(edge);
///     }
/// }
/// assert_eq!((x_pin, y_pin, reload), (10, 4, 4000));
/// // The y axis steps on the x axis's steps nearest 2.5, 5, 7.5 and 10.
/// assert_eq!(y_steps_at, [3, 5, 8, 10]);
/// assert_eq!(plotter.position(), [10, -4]);
/// ```
// The edges' state first, read by every step at the smallest offsets (an
// M0 loads a word at most 124 bytes from its base; 4 + 16·N bytes), then
// the player, whose step path reads only its first fields.
#[derive(Clone, Debug)]
#[repr(C)]
pub struct Axes<'a, W, const N: usize, L = AnyLayout> {
    pub(in crate::player) edges: Edges<N>,
    player: Player<'a, W, L>,
    /// Each axis's position when the move began.
    pub(in crate::player) start: [i64; N],
    /// Each axis's steps in the move.
    steps: [u32; N],
    directions: [Direction; N],
    /// The lead's steps in the move as begun (the rule's `L`).
    lead_steps: u32,
    /// The lead's steps in the move as it now ends (fewer after a stop).
    pub(in crate::player) lead_total: u32,
    /// The axis leading the move.
    lead: usize,
    /// Where the move ends as begun: its target, or where its steps, each
    /// clamped to a `u32`, take the axes.
    target: [i64; N],
    /// The move after this one: a target given while this one played.
    pub(in crate::player) then: Option<[i64; N]>,
    /// The last turn to a queued move: the directions before it, and the
    /// steps the player had left once it handed out the move's first
    /// period ([`Buffered`](crate::player::Buffered) reads the pins' directions
    /// from it).
    pub(in crate::player) turn: Option<([Direction; N], u32)>,
    /// Lines queued after `then` or the line playing ([`Axes::queue`]).
    pub(in crate::player) lines: Targets<Queued<N>>,
    /// The line playing's figures, when lines are queued after it.
    pub(in crate::player) line: Line<N>,
    /// `1/√(a·δ)` for the junctions, `a` the acceleration ramp's mean
    /// acceleration and `δ` the junction deviation
    /// ([`Axes::with_junction_deviation`]), in Q8 ticks; `u32::MAX` for
    /// none.
    pub(in crate::player) scale: u32,
    /// The cruise position's period, in ticks, for the junctions.
    pub(in crate::player) cruise: u32,
    /// The queued lines' tails hold: the last backward pass was over them
    /// all, at the cruise set now.
    pub(in crate::player) tails: bool,
    /// The steps in which the lead stops from the speed the line playing
    /// ends at: 0 when it ends at rest.
    pub(in crate::player) tail: u32,
}

impl<'a, W: TableWord, const N: usize, L: Layout> Axes<'a, W, N, L> {
    /// One bit of the mask per axis, and at least one axis.
    const AXES: () = assert!(N >= 1 && N <= 32, "Axes has 1 to 32 axes");

    /// Axes at `position` with their player at rest.
    pub fn new(player: Player<'a, W, L>, position: [i64; N]) -> Self {
        let () = Self::AXES;
        Axes {
            cruise: player.cruise_period(),
            player,
            edges: Edges::REST,
            start: position,
            steps: [0; N],
            directions: [Direction::Forward; N],
            lead_steps: 0,
            lead_total: 0,
            target: position,
            lead: 0,
            then: None,
            turn: None,
            lines: Targets::empty(Queued::NONE),
            line: Line::NONE,
            scale: u32::MAX,
            tails: false,
            tail: 0,
        }
    }

    /// The positions, in steps: exact after every step.
    pub fn position(&self) -> [i64; N] {
        self.position_after(self.lead_played())
    }

    /// The positions after the lead's `s`-th step of the move.
    pub(in crate::player) fn position_after(&self, s: u32) -> [i64; N] {
        let mut at = self.start;
        for (i, p) in at.iter_mut().enumerate() {
            let n = follower_steps(self.steps[i], s, self.lead_steps);
            *p = p.saturating_add(self.directions[i].sign() * i64::from(n));
        }
        at
    }

    /// The lead's steps played.
    pub(in crate::player) fn lead_played(&self) -> u32 {
        self.lead_total.saturating_sub(self.player.remaining())
    }

    /// Sets the positions (after homing, say), at rest; refused while a
    /// move plays.
    pub fn set_position(&mut self, position: [i64; N]) -> Result<(), Moving> {
        self.idle()?;
        self.start = position;
        self.target = position;
        self.steps = [0; N];
        self.lead_steps = 0;
        self.lead_total = 0;
        Ok(())
    }

    /// The direction of each axis in the move playing, or in the last one
    /// (forward for an axis that stays in a move of some steps; a move of
    /// no steps keeps them).
    pub fn directions(&self) -> [Direction; N] {
        self.directions
    }

    /// The directions of the edge the next [`Axes::step`] hands out: the
    /// move's, or a queued move's where the move has ended. Set the pins to
    /// them right after pulsing an edge: an axis that turns steps the other
    /// way a period of the ramp's slowest entry later
    /// ([`Axis::next_direction`](crate::player::Axis::next_direction)).
    pub fn next_directions(&self) -> [Direction; N] {
        match self
            .then
            .or_else(|| self.lines.iter().next().map(|q| q.target))
        {
            Some(target) if self.player.remaining() == 0 => {
                // As the move to it will start ([`Axes::start_by`]).
                let position = self.position();
                core::array::from_fn(|i| Direction::of(target[i].saturating_sub(position[i])))
            }
            _ => self.directions,
        }
    }

    /// The index of the axis leading the move playing, or the last one.
    pub fn lead(&self) -> usize {
        self.lead
    }

    /// Moves to `target`; returns the direction each axis's pin must say
    /// now. From rest, starts the move. While a move plays, the axes
    /// decelerate to rest along the ramp ([`Axes::stop`]: a straight line
    /// does not bend in the middle) and then move to `target` in a straight
    /// line from where they stopped; [`Axes::directions`] changes at the
    /// step that begins that move.
    ///
    /// The target the axes already go to (the one given last, or where a
    /// stop ends) changes nothing, and a move to where they stand has no
    /// steps and keeps the directions.
    pub fn move_to(&mut self, target: [i64; N]) -> [Direction; N] {
        self.lines.clear();
        if !self.player.is_done() {
            if self.destination() != target {
                self.stop();
                self.then = Some(target);
            }
            return self.directions;
        }
        self.then = None;
        let position = self.position();
        if position == target {
            return self.directions;
        }
        self.turn = None;
        self.start_to(target, None, None);
        self.directions
    }

    /// Where the move playing ends, or the last one queued after it.
    pub(in crate::player) fn destination(&self) -> [i64; N] {
        self.lines
            .iter()
            .next_back()
            .map(|q| q.target)
            .or(self.then)
            .unwrap_or_else(|| self.line_end())
    }

    /// Where the line playing ends: its target unless a stop ends it
    /// sooner, then where the rule has taken each axis.
    pub(in crate::player) fn line_end(&self) -> [i64; N] {
        if self.lead_total != self.lead_steps {
            return self.position_after(self.lead_total);
        }
        self.target
    }

    /// Moves to `target` once the move playing has ended: for a register
    /// that still holds the move's last edge when the lead has handed out
    /// every period (`Buffered`), so that the pins take that edge in the
    /// move's directions. The target the axes already go to changes
    /// nothing.
    pub(in crate::player) fn move_after(&mut self, target: [i64; N]) {
        self.lines.clear();
        if self.destination() != target {
            self.then = Some(target);
        }
    }

    /// Moves by `delta` steps on each axis from the positions (negative:
    /// backward), as [`Axes::move_to`] does; returns the direction each
    /// axis's pin must say now.
    pub fn move_by(&mut self, delta: [i64; N]) -> [Direction; N] {
        let mut target = self.position();
        for (t, d) in target.iter_mut().zip(delta) {
            *t = t.saturating_add(d);
        }
        self.move_to(target)
    }

    /// Starts a line to `target` from the position: from rest, or at a
    /// speed of `entry` ticks a step of its lead ([`Player::begin_joined`]),
    /// ending at the speed the lines queued after it allow.
    fn start_to(&mut self, target: [i64; N], entry: Option<u32>, queued: Option<Queued<N>>) {
        self.start = self.position();
        self.line = match queued {
            Some(q) => q.line,
            None if self.lines.len() > 0 => Line::between(self.start, target),
            None => Line::NONE,
        };
        let mut lead = 0;
        for (i, &to) in target.iter().enumerate() {
            let d = to.saturating_sub(self.start[i]);
            self.steps[i] = u32::try_from(d.unsigned_abs()).unwrap_or(u32::MAX);
            self.directions[i] = Direction::of(d);
            self.target[i] = match u64::from(self.steps[i]) == d.unsigned_abs() {
                true => to,
                false => self.start[i].saturating_add(d.signum() * i64::from(u32::MAX)),
            };
            if self.steps[i] > self.steps[lead] {
                lead = i;
            }
        }
        let l = self.steps[lead];
        let mut edges = Edges::REST;
        edges.base = bit(lead);
        let followers = (0..N).filter(|&i| i != lead);
        for (j, i) in (1..N).zip(followers) {
            let d = self.steps[i];
            // (d·0 + h) mod L: `h` is below `d`, so below `L`.
            edges.set(j, d, d.saturating_sub(1) / 2, bit(i), l);
        }
        self.edges = edges;
        self.lead_steps = l;
        self.lead = lead;
        self.lead_total = l;
        // A queued line's tail as the last backward pass found it, if that
        // was over every line after it at this cruise.
        self.tail = match (self.lines.len(), queued) {
            (0, _) => 0,
            (_, Some(q)) if self.tails => {
                // What the backward pass finds now, in the tests' builds.
                #[cfg(debug_assertions)]
                {
                    let tail = self.tail();
                    debug_assert_eq!(q.tail, tail, "a queued line's tail kept");
                }
                q.tail
            }
            _ => self.tail(),
        };
        // The cruise set on the axes holds.
        self.player.begin_joined(l, self.tail, entry);
        // `l`, or none on an empty ramp.
        self.lead_total = self.player.remaining();
    }

    /// Decelerates to rest from the current speed ([`Player::stop`]): the
    /// lead ends short of its target, and each follower where the rule has
    /// taken it by then.
    pub fn stop(&mut self) {
        self.shorten(Player::stop);
    }

    /// [`Axes::stop`] along the emergency ramp ([`Player::abort`]).
    pub fn abort(&mut self) {
        self.shorten(Player::abort);
    }

    /// Ends the move sooner by `stop` on the lead's player.
    fn shorten(&mut self, stop: fn(&mut Player<'a, W, L>)) {
        self.then = None;
        self.lines.clear();
        self.tail = 0;
        let played = self.lead_played();
        let turn = self.at_turn();
        stop(&mut self.player);
        self.lead_total = played + self.player.remaining();
        // A turn whose first edge nothing has followed stays one.
        self.turn = turn.map(|before| (before, self.player.remaining()));
    }

    /// Cruises slower or faster ([`Player::set_cruise`]) for this move and
    /// the next; the targets stay.
    pub fn set_cruise(&mut self, pos: u32) {
        self.player.set_cruise(pos);
        self.cruise = self.player.cruise_period();
        self.tails = false;
    }

    /// Cruises at a period in ticks ([`Player::set_cruise_period`]) for
    /// this move and the next; the targets stay.
    pub fn set_cruise_period(&mut self, period: W) {
        self.player.set_cruise_period(period);
        self.cruise = self.player.cruise_period();
        self.tails = false;
    }

    /// Plays the next edge: hands the period until the one after it and
    /// the mask of the axes that step on it (bit `i` for axis `i`) to
    /// `write`, and returns `true`; or returns `false` when the move is
    /// done. The lead's [`Player::step`] with the followers' accumulators:
    /// an addition and a branch per follower, and on the edges where its
    /// accumulator carries (where it steps, or for a follower of more than
    /// half the lead's steps where it does not) a subtraction and its bit
    /// of the mask flipped. Three axes (two followers stepping on 86 % and
    /// 25 % of the lead's steps) take 9.2 instructions per step
    /// more than the player on a Cortex-M3 or M4F and 12.5 on an M0
    /// (`rigs/measure/measure.sh`). `write` is called
    /// once a step at most; it is `FnMut` so that the step can hand it on
    /// to the path that refills the run.
    #[inline]
    pub fn step(&mut self, mut write: impl FnMut(W, u32)) -> bool {
        // The followers first, with the registers free: after the move's
        // last step the accumulators move on unread.
        let mask = self.edges.next();
        if L::COMPRESSED {
            if self.player.step(|period| write(period, mask)) {
                return true;
            }
            return self.then_step(write);
        }
        // The run being played, inline; everything else in one cold call
        // at the end, so that the step keeps no register across a call.
        match self
            .player
            .play_run_counted::<true, _>(|period| write(period, mask))
        {
            Ok(()) => true,
            Err(_) => self.step_refilled(write, mask),
        }
    }

    /// The lead's step after its run is played: the next run, or the
    /// queued move.
    #[cold]
    #[inline(never)]
    fn step_refilled(&mut self, mut write: impl FnMut(W, u32), mask: u32) -> bool {
        if self.player.step_refilled(|period| write(period, mask)) {
            return true;
        }
        self.then_step(write)
    }

    /// The queued move, if any, and its first edge.
    #[cold]
    #[inline(never)]
    fn then_step(&mut self, write: impl FnOnce(W, u32)) -> bool {
        let (target, entry, line) = match (self.then.take(), self.lines.pop()) {
            (Some(target), None) => (target, None, None),
            (Some(target), Some(next)) => {
                self.lines.push_front(next);
                (target, None, None)
            }
            (None, Some(q)) => (q.target, self.entry_period(&q.line), Some(q)),
            (None, None) => return false,
        };
        let before = self.directions;
        self.start_to(target, entry, line);
        let mask = self.edges.next();
        if !self.player.step(|period| write(period, mask)) {
            return false;
        }
        self.turn = Some((before, self.player.remaining()));
        true
    }

    /// The directions before the last turn to a queued move, when the
    /// lead has handed out nothing since the first edge after it (which
    /// may still be in a buffered register's hands, not taken).
    pub(in crate::player) fn at_turn(&self) -> Option<[Direction; N]> {
        let (before, mark) = self.turn?;
        let remaining = self.player.remaining();
        (remaining == mark && (mark > 0 || !self.player.is_ended())).then_some(before)
    }

    /// The directions of the edge whose period the lead handed out last:
    /// those before a turn while nothing has followed its first edge
    /// ([`Buffered`](crate::player::Buffered)'s pins take that edge one interval
    /// later).
    pub(in crate::player) fn handed_directions(&self) -> [Direction; N] {
        self.at_turn().unwrap_or(self.directions)
    }

    /// The next edge's period and mask ([`Axes::step`]), or `None` when
    /// the move is done.
    #[inline]
    pub fn next_step(&mut self) -> Option<(W, u32)> {
        let mut next = None;
        self.step(|period, mask| next = Some((period, mask)));
        next
    }

    /// The lead's steps left in the move: the edges left.
    pub fn remaining(&self) -> u32 {
        self.player.remaining()
    }

    /// `true` when the move has played all its steps and no other follows.
    pub fn is_done(&self) -> bool {
        self.player.is_done() && self.then.is_none() && self.lines.len() == 0
    }

    /// The player: the lead's.
    pub fn player(&self) -> &Player<'a, W, L> {
        &self.player
    }

    /// The lead's player, for [`Buffered`](crate::player::Buffered)'s rest.
    pub(in crate::player) fn player_mut(&mut self) -> &mut Player<'a, W, L> {
        &mut self.player
    }

    fn idle(&self) -> Result<(), Moving> {
        match self.player.remaining() {
            0 if self.then.is_none() && self.lines.len() == 0 => Ok(()),
            remaining => Err(Moving { remaining }),
        }
    }
}
