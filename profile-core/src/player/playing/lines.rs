//! The lines of a polyline queued on [`Axes`](crate::player::Axes): each
//! line's figures, computed once when it is queued, and the speed its
//! junction with the line before allows.

use libm::sqrtf;

/// A line of a polyline: its steps on each axis, its lead's steps, its
/// length `|d|` in steps and its `ρ = L / |d|`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Line<const N: usize> {
    pub(crate) delta: [i64; N],
    pub(crate) lead: u32,
    pub(crate) norm: f32,
    pub(crate) rho: f32,
}

impl<const N: usize> Line<N> {
    /// No steps.
    pub(crate) const NONE: Self = Line {
        delta: [0; N],
        lead: 0,
        norm: 0.0,
        rho: 1.0,
    };

    pub(crate) fn between(from: [i64; N], to: [i64; N]) -> Self {
        let mut delta = [0i64; N];
        let (mut lead, mut square) = (0u32, 0f32);
        for i in 0..N {
            delta[i] = to[i].saturating_sub(from[i]);
            let steps = u32::try_from(delta[i].unsigned_abs()).unwrap_or(u32::MAX);
            lead = lead.max(steps);
            square += (steps as f32) * (steps as f32);
        }
        let norm = sqrtf(square);
        let rho = match lead {
            0 => 1.0,
            _ => lead as f32 / norm,
        };
        Line {
            delta,
            lead,
            norm,
            rho,
        }
    }

    /// The path speed the junction from `self` to `next` allows, steps a
    /// tick: `sqrt(a·δ·s / (1 − s))` for a mean acceleration `accel` and a
    /// deviation `deviation`, `s = sin(φ/2) = sqrt((1 + cos θ) / 2)`, `θ`
    /// the angle between the two lines; no limit where they go on
    /// straight, 0 where an axis reverses or a line has no steps.
    pub(crate) fn junction(&self, next: &Line<N>, accel: f32, deviation: f32) -> f32 {
        let mut dot = 0f32;
        for i in 0..N {
            let (x, y) = (self.delta[i] as f32, next.delta[i] as f32);
            if x * y < 0.0 {
                return 0.0;
            }
            dot += x * y;
        }
        if self.norm == 0.0 || next.norm == 0.0 {
            return 0.0;
        }
        let cos = (dot / (self.norm * next.norm)).clamp(-1.0, 1.0);
        let sine = sqrtf((1.0 + cos) / 2.0);
        if sine >= 1.0 {
            return f32::INFINITY;
        }
        sqrtf(accel * deviation * sine / (1.0 - sine))
    }
}

/// A line queued after the one playing: where it ends, its figures, and
/// the speed its junction with the line before it allows.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Queued<const N: usize> {
    pub(crate) target: [i64; N],
    pub(crate) line: Line<N>,
    pub(crate) junction: f32,
}

impl<const N: usize> Queued<N> {
    /// No line: what the queue's free places hold.
    pub(crate) const NONE: Self = Queued {
        target: [0; N],
        line: Line::NONE,
        junction: 0.0,
    };
}

/// The tail of a line that ends at a speed from which a stop takes
/// `stop` steps: its last step has that many after it, the stop's first
/// step its entry (the step a move plays with `r` steps left, itself
/// included, is no faster than the deceleration ramp's entry `r - 1`).
pub(crate) fn tail_from(stop: u32) -> u32 {
    stop.saturating_sub(1)
}

/// The period of a lead stepping at `rate` steps a tick, rounded up (no
/// faster); `u32::MAX` at rest.
pub(crate) fn period_of(rate: f32) -> u32 {
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
