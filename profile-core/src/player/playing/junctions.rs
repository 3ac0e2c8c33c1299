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
use crate::player::playing::lines::{
    Line, Queued, REST, handed_period, lead_period, path_period, tail_from,
};
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
        let deviation = if steps.is_finite() && steps > 0.0 {
            steps
        } else {
            0.0
        };
        // 1/√(a·δ) in Q8 ticks, rounded up (f32's error, 2⁻²³ at most in
        // the root and the quotient, taken up by 2⁻²⁰).
        let root = libm::sqrtf(self.mean_accel() * deviation);
        let scale = libm::ceilf(256.0 / root * (1.0 + 1.0 / (1u32 << 20) as f32));
        self.scale = if root > 0.0 && scale < u32::MAX as f32 {
            scale as u32
        } else {
            u32::MAX
        };
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
            let from = self.position();
            let directions = self.move_to(target);
            // The line's figures, for the lines queued after it.
            self.line = Line::between(from, target);
            return Ok(directions);
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
        let line = Line::between(from, target);
        // Its junction with the line before: the last queued, or the one
        // playing (or that a stop ends and a new target follows).
        let junction = match (self.lines.iter().next_back(), self.then) {
            (Some(last), _) => last.line.junction(&line, self.scale),
            (None, Some(then)) => Line::between(self.line_end(), then).junction(&line, self.scale),
            (None, None) => {
                if self.line.lead == 0 {
                    self.line = Line::between(self.start, from);
                }
                self.line.junction(&line, self.scale)
            }
        };
        self.lines
            .push(Queued {
                target,
                line,
                junction,
                tail: 0,
            })
            .map_err(|_| QueueFull { target })?;
        // The lines' tails change with the line queued: the backward pass
        // below finds them again, or they are found at their vertices.
        self.tails = false;
        if rejoin && self.then.is_none() {
            let tail = self.tail();
            if tail > self.tail {
                let turn = self.at_turn().map(|b| (b, self.player().remaining()));
                if self.player_mut().rejoin(tail) {
                    self.tail = tail;
                }
                self.turn = turn;
            }
        }
        Ok(())
    }

    /// The tail of the line playing: the steps in which its lead stops
    /// from the speed its end allows, by the backward pass over the lines
    /// queued after it.
    pub(in crate::player) fn tail(&mut self) -> u32 {
        let path = self.vertex_period();
        self.tail_on(path, self.line.per_lead)
    }

    /// The tail of a line of `per_lead` (`1/ρ`) that ends at the path
    /// period `path`.
    fn tail_on(&self, path: u64, per_lead: u32) -> u32 {
        match path {
            REST => 0,
            _ => tail_from(self.player().stop_steps(lead_period(path, per_lead))),
        }
    }

    /// The path period at the end of the line playing by the backward
    /// pass over the lines queued after it (at rest at the end of the
    /// last), each line's tail kept with it for its vertex.
    fn vertex_period(&mut self) -> u64 {
        let cruise = self.cruise.max(1);
        let mut end = REST;
        for i in (0..self.lines.len()).rev() {
            let Some(&Queued { line, junction, .. }) = self.lines.get(i) else {
                break;
            };
            // The line's lead from the vertex's speed can slow to the next
            // vertex's within the line.
            let tail = self.tail_on(end, line.per_lead);
            if let Some(kept) = self.lines.get_mut(i) {
                kept.tail = tail;
            }
            let reach = line.lead.saturating_add(tail);
            let stop = match self.player().decel_ticks(reach.saturating_sub(1)) {
                Some(p) if reach > 0 => path_period(p, line.rho),
                Some(_) => REST,
                None => 0,
            };
            let before = match i {
                0 => self.line.rho,
                _ => self.lines.get(i - 1).map_or(self.line.rho, |b| b.line.rho),
            };
            let fastest = path_period(cruise, before.max(line.rho));
            end = stop.max(junction).max(fastest);
        }
        self.tails = true;
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
        let last = self.player().last_step_period();
        let p = handed_period(last, self.line.rho, next.per_lead);
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
