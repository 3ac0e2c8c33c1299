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
//! acceleration ramp at its fastest entry not faster than `v·ρ'`.

use libm::sqrtf;

use crate::base::timer::TableWord;
use crate::player::playing::axis::Direction;
use crate::player::playing::targets::QueueFull;
use crate::player::{Axes, Layout};

/// A line of a polyline: its steps on each axis, its lead's steps and
/// its `ρ = L / |d|`.
#[derive(Clone, Copy)]
struct Line<const N: usize> {
    delta: [i64; N],
    lead: u32,
    rho: f32,
}

impl<const N: usize> Line<N> {
    fn between(from: [i64; N], to: [i64; N]) -> Self {
        let mut delta = [0i64; N];
        let (mut lead, mut square) = (0u32, 0f32);
        for i in 0..N {
            delta[i] = to[i].saturating_sub(from[i]);
            let steps = u32::try_from(delta[i].unsigned_abs()).unwrap_or(u32::MAX);
            lead = lead.max(steps);
            square += (steps as f32) * (steps as f32);
        }
        let rho = match lead {
            0 => 1.0,
            _ => lead as f32 / sqrtf(square),
        };
        Line { delta, lead, rho }
    }

    /// `sin(φ/2)` of the junction from `self` to `next`: `(1 + cos θ) / 2`
    /// under the root, `θ` the angle between the two; 0 where an axis
    /// reverses or a line has no steps.
    fn junction_sine(&self, next: &Line<N>) -> f32 {
        let (mut dot, mut a, mut b) = (0f32, 0f32, 0f32);
        for i in 0..N {
            let (x, y) = (self.delta[i] as f32, next.delta[i] as f32);
            if x * y < 0.0 {
                return 0.0;
            }
            dot += x * y;
            a += x * x;
            b += y * y;
        }
        if a == 0.0 || b == 0.0 {
            return 0.0;
        }
        let cos = (dot / (sqrtf(a) * sqrtf(b))).clamp(-1.0, 1.0);
        sqrtf((1.0 + cos) / 2.0)
    }
}

/// The tail of a line that ends at a speed from which a stop takes
/// `stop` steps: its last step has that many after it, the stop's first
/// step its entry (the step a move plays with `r` steps left, itself
/// included, is no faster than the deceleration ramp's entry `r - 1`).
fn tail_from(stop: u32) -> u32 {
    stop.saturating_sub(1)
}

/// The period of a lead stepping at `rate` steps a tick, rounded up (no
/// faster); `u32::MAX` at rest.
fn period_of(rate: f32) -> u32 {
    if rate <= 0.0 {
        return u32::MAX;
    }
    let p = libm::ceilf(1.0 / rate);
    if p >= u32::MAX as f32 {
        u32::MAX
    } else {
        (p as u32).max(1)
    }
}

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
        if self.destination() == target {
            return Ok(());
        }
        self.lines.push(target)?;
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
        let current = Line::between(self.start, self.position_after(self.lead_total));
        let mut from = self.position_after(self.lead_total);
        let mut lines = [current; crate::player::QUEUE + 1];
        let mut n = 1;
        for target in self.lines.iter() {
            lines[n] = Line::between(from, target);
            from = target;
            n += 1;
        }
        let speed = self.vertex_speeds(&lines[..n]);
        tail_from(
            self.player()
                .stop_steps_from(period_of(speed * current.rho)),
        )
    }

    /// The path speed at the end of the first of `lines` by the backward
    /// pass: at rest at the end of the last.
    fn vertex_speeds(&self, lines: &[Line<N>]) -> f32 {
        let player = self.player();
        let cruise = player.cruise_period().max(1) as f32;
        let accel = self.mean_accel();
        let mut end = 0f32;
        for j in (1..lines.len()).rev() {
            let (before, line) = (&lines[j - 1], &lines[j]);
            // The line's lead from the vertex's speed can slow to the next
            // vertex's within the line.
            let tail = tail_from(player.stop_steps_from(period_of(end * line.rho)));
            let reach = line.lead.saturating_add(tail);
            let stop = match player.decel_period(reach.saturating_sub(1)) {
                Some(p) if reach > 0 => 1.0 / (p as f32 * line.rho),
                Some(_) => 0.0,
                None => f32::INFINITY,
            };
            let sine = before.junction_sine(line);
            let junction = if sine >= 1.0 {
                f32::INFINITY
            } else {
                sqrtf(accel * self.deviation * sine / (1.0 - sine))
            };
            let fastest = 1.0 / (cruise * before.rho.max(line.rho));
            end = stop.min(junction).min(fastest);
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
    /// line (`to` its end).
    pub(in crate::player) fn entry_period(&self, to: [i64; N]) -> Option<u32> {
        if self.tail == 0 {
            return None;
        }
        let end = self.position_after(self.lead_total);
        let before = Line::between(self.start, end);
        let next = Line::between(end, to);
        let last = self.player().last_step_period() as f32;
        let p = libm::ceilf(last * before.rho / next.rho);
        Some(if p >= u32::MAX as f32 {
            u32::MAX
        } else {
            p as u32
        })
    }
}
