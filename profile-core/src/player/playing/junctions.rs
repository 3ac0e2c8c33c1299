//! Lines queued on [`Axes`] that join at speed: [`Axes::queue`].
//!
//! A polyline is a queue of straight lines. Each plays as a move of its
//! own (its lead, its followers' rule from its first step, so every
//! vertex is exact), but where two lines meet the lead's player does not
//! come to rest: it plays the line as the first steps of a longer move,
//! whose extra steps (its *tail*) are the deceleration after the speed the
//! vertex allows, and the next line starts at that speed. The speed at a
//! vertex (a path speed: steps of the line's length a tick) is the least
//! of:
//!
//! - the junction's: grbl's rule from the angle `θ` between the lines and
//!   the junction deviation `δ` ([`Axes::with_junction_deviation`]),
//!   `v² = a·δ·s / (1 − s)` with `s = sin(φ/2)`, `φ` the angle between the
//!   line before reversed and the line after (`s = 1`, no limit, for a
//!   straight continuation; `0`, rest, where an axis reverses), `a` the
//!   acceleration ramp's mean acceleration;
//! - the cruise: neither line's lead faster than the cruise position;
//! - the backward pass: from it, the next line's lead can still slow to
//!   the next vertex's speed within the line, and so on to the end of the
//!   queue, which ends at rest.
//!
//! Path speed `v` and a line's lead step rate differ by the line's
//! `ρ = L / |d|` (its lead's steps over its length): the lead steps at
//! `v·ρ`. At a vertex the path speed holds and the new lead enters the
//! ramp at its fastest entry not faster than `v·ρ'` (on the deceleration
//! ramp, the one the acceleration ramp mirrors when they are one).

use crate::base::timer::TableWord;
use crate::player::playing::axis::Direction;
use crate::player::playing::lines::{Line, Queued, period_of, tail_from};
use crate::player::playing::targets::QueueFull;
use crate::player::{Axes, Layout};

impl<'a, W: TableWord, const N: usize, L: Layout> Axes<'a, W, N, L> {
    /// The same axes with a junction deviation of `steps` (grbl's
    /// `junction_deviation`, in steps of the axes): how far from the
    /// vertex a circle tangent to both lines may pass, which sets how fast
    /// queued lines ([`Axes::queue`]) join where they meet at an angle.
    /// 0 (the default, and for anything not finite or negative) stops at
    /// every vertex but where the lines go on straight.
    #[must_use]
    pub fn with_junction_deviation(mut self, steps: f32) -> Self {
        self.deviation = if steps.is_finite() && steps > 0.0 {
            steps
        } else {
            0.0
        };
        self.accel = self.mean_accel();
        self
    }

    /// Queues a straight line to `target` after the lines queued before
    /// it, and returns the directions to set now (the move's, or at rest
    /// the new one's). At rest, it starts the line, as [`Axes::move_to`]
    /// does. While lines play, the line joins the one before at the
    /// fastest speed the junction, the cruise and the lines after it allow
    /// (the module's rules): the lead's player ends the line before at that
    /// speed, and the new line's lead starts at it, the positions exact at
    /// the vertex as at every step. [`QueueFull`] when [`QUEUE`](crate::player::QUEUE)
    /// lines wait after the one playing. A target where the last line ends
    /// changes nothing.
    ///
    /// [`Axes::move_to`], [`Axes::move_by`], [`Axes::stop`] and
    /// [`Axes::abort`] drop what is queued.
    ///
    /// ```
    /// use profile_core::player::{Axes, Player};
    ///
    /// static RAMP: [u16; 6] = [4000, 3000, 2400, 2000, 1700, 1500];
    /// let mut plotter = Axes::new(Player::new(&RAMP), [0, 0]).with_junction_deviation(2.0);
    /// plotter.queue([100, 0]).unwrap();
    /// plotter.queue([200, 10]).unwrap(); // a shallow bend: no stop there
    /// let mut periods = vec![];
    /// while let Some((period, _mask)) = plotter.next_step() {
    ///     periods.push(period);
    /// }
    /// assert_eq!(plotter.position(), [200, 10]);
    /// assert_eq!(periods.len(), 200);
    /// // The vertex (after the 100th step) at speed: the path's speed holds,
    /// // and the new lead's 1508 ticks a step (its line is 0.5 % longer
    /// // than its steps) round to the entry not faster, 1700.
    /// assert_eq!(periods[98..102], [1500, 1500, 1700, 1500]);
    /// ```
    pub fn queue(&mut self, target: [i64; N]) -> Result<[Direction; N], QueueFull<[i64; N]>> {
        if self.is_done() {
            return Ok(self.move_to(target));
        }
        self.enqueue(target, true)?;
        Ok(self.directions())
    }

    /// Lines queued after the one playing.
    pub fn queued(&self) -> usize {
        usize::from(self.then.is_some()) + self.lines.len()
    }

    /// Queues `target` while a line plays; `rejoin`: the line playing may
    /// end at speed for it (not when its last period is handed out, for a
    /// buffered register).
    pub(in crate::player) fn enqueue(
        &mut self,
        target: [i64; N],
        rejoin: bool,
    ) -> Result<(), QueueFull<[i64; N]>> {
        let from = self.destination();
        if from == target {
            return Ok(());
        }
        // The line before: the last queued, or the one playing (or that a
        // stop ends and a new target follows).
        let before = match (self.lines.iter().next_back(), self.then) {
            (Some(last), _) => last.line,
            (None, Some(then)) => Line::between(self.line_end(), then),
            (None, None) if self.line.norm == 0.0 => {
                self.line = Line::between(self.start, from);
                self.line
            }
            (None, None) => self.line,
        };
        let line = Line::between(from, target);
        let junction = before.junction(&line, self.accel, self.deviation);
        self.lines
            .push(Queued {
                target,
                line,
                junction,
            })
            .map_err(|_| QueueFull { target })?;
        if rejoin && self.then.is_none() {
            let tail = self.tail();
            if tail > self.tail {
                let remaining = self.player().remaining();
                let turn = self.at_turn();
                if self.player_mut().rejoin(tail) {
                    self.tail = tail;
                }
                self.turn = turn.map(|before| (before, remaining));
            }
        }
        Ok(())
    }

    /// The tail of the line playing: the steps in which its lead stops
    /// from the speed its end allows, by the backward pass over the lines
    /// queued after it.
    pub(in crate::player) fn tail(&self) -> u32 {
        let speed = self.vertex_speed();
        tail_from(self.player().stop_steps(period_of(speed * self.line.rho)))
    }

    /// The path speed at the end of the line playing by the backward pass
    /// over the lines queued after it: at rest at the end of the last.
    fn vertex_speed(&self) -> f32 {
        let player = self.player();
        let cruise = player.cruise_period().max(1) as f32;
        let mut end = 0f32;
        let mut lines = self.lines.iter().rev().peekable();
        while let Some(q) = lines.next() {
            let line = &q.line;
            // The line's lead from the vertex's speed can slow to the next
            // vertex's within the line.
            let tail = tail_from(player.stop_steps(period_of(end * line.rho)));
            let reach = line.lead.saturating_add(tail);
            let stop = match player.decel_ticks(reach.saturating_sub(1)) {
                Some(p) if reach > 0 => 1.0 / (p as f32 * line.rho),
                Some(_) => 0.0,
                None => f32::INFINITY,
            };
            let before = lines.peek().map_or(self.line.rho, |b| b.line.rho);
            let fastest = 1.0 / (cruise * before.max(line.rho));
            end = stop.min(q.junction).min(fastest);
        }
        end
    }

    /// The acceleration ramp's mean acceleration, steps a tick²: from its
    /// first step's rate to its last's over its steps.
    fn mean_accel(&self) -> f32 {
        let (first, last, steps) = self.player().accel_extent();
        if steps == 0 || first == 0 || last == 0 {
            return 0.0;
        }
        let (f0, f1) = (1.0 / first as f32, 1.0 / last as f32);
        ((f1 * f1 - f0 * f0) / (2.0 * steps as f32)).max(0.0)
    }

    /// The speed, in ticks a step of the next line's lead, at which the
    /// line now ending hands over: its last step's path speed on the next
    /// line.
    pub(in crate::player) fn entry_period(&self, next: &Line<N>) -> Option<u32> {
        if self.tail == 0 {
            return None;
        }
        let before = &self.line;
        let last = self.player().last_step_period() as f32;
        let p = libm::ceilf(last * before.rho / next.rho);
        let p = if p >= u32::MAX as f32 {
            u32::MAX
        } else {
            p as u32
        };
        // The ramp's entry not faster than that (the deceleration ramp's
        // last entry not shorter, which on one ramp both ways is the
        // acceleration ramp's too): the new lead's first step is no
        // faster along the path. Slower than every entry: from rest.
        match self.player().stop_steps(p) {
            0 => None,
            n => self.player().decel_ticks(n - 1),
        }
    }
}
