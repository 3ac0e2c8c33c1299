//! The lines of a polyline queued on [`Axes`](crate::player::Axes): each
//! line's figures, computed once when it is queued, and the path period its
//! junction with the line before allows; in fixed point, by the roots of
//! [`fixed`](super::fixed), every figure rounded to the slower side.
//!
//! A *path period* is ticks a step of path length (the reciprocal of a
//! path speed), in Q32, [`REST`] at rest, 0 for no limit. A lead's period
//! in ticks read from one is rounded up but for 2⁻²² of it: the figures'
//! own errors (below 2⁻²⁴) do not turn a lead's period read back from its
//! own path period into the next integer.

use crate::player::playing::fixed::{recip_q28, rsqrt, sqrt};

/// A path period at rest.
pub(crate) const REST: u64 = u64::MAX;

/// Units of 2⁻³⁰ added to a line's direction's figures, more than the
/// roots' error (2⁻²⁷ of at most 1, 8 units) and the truncation to Q30
/// (one unit) leave them below the exact.
const MARGIN: u32 = 10;

/// A line of a polyline: the axes it moves forward and backward, its
/// lead's steps, its direction and its `ρ = L / |d|` (its lead's steps
/// over its length).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Line<const N: usize> {
    /// One bit per axis that steps forward.
    pub(crate) forward: u32,
    /// One bit per axis that steps backward.
    pub(crate) backward: u32,
    pub(crate) lead: u32,
    /// `|dᵢ| / |d|`, each axis's steps over the line's length, Q30, below
    /// the exact by less than [`MARGIN`] units.
    pub(crate) unit: [u32; N],
    /// `ρ`, Q30, above the exact by less than [`MARGIN`] units.
    pub(crate) rho: u32,
    /// `1/ρ = |d| / L`, Q28, above the exact.
    pub(crate) per_lead: u32,
}

impl<const N: usize> Line<N> {
    /// No steps.
    pub(crate) const NONE: Self = Line {
        forward: 0,
        backward: 0,
        lead: 0,
        unit: [0; N],
        rho: 1 << 30,
        per_lead: 1 << 28,
    };

    pub(crate) fn between(from: [i64; N], to: [i64; N]) -> Self {
        let mut line = Self::NONE;
        for i in 0..N {
            let steps = u32::try_from(to[i].abs_diff(from[i])).unwrap_or(u32::MAX);
            line.unit[i] = steps;
            line.forward |= u32::from(to[i] > from[i]) << i;
            line.backward |= u32::from(to[i] < from[i]) << i;
            line.lead = line.lead.max(steps);
        }
        if line.lead == 0 {
            return line;
        }
        // |d|², exact, shifted right by 2j to fit a u64 (only past 2²⁹
        // steps): 1/|d| = y·2^(h − j − 62), so that an axis's steps over
        // |d| in Q30 are its steps times y / 2^(32 + j − h).
        let (square, j) = if line.lead < 1 << 29 {
            // N ≤ 32 squares below 2⁵⁸.
            let square = line.unit.iter().map(|&s| u64::from(s) * u64::from(s)).sum();
            (square, 0)
        } else {
            let square: u128 = line
                .unit
                .iter()
                .map(|&s| u128::from(s) * u128::from(s))
                .sum();
            let j = (128 - square.leading_zeros()).saturating_sub(63) / 2;
            ((square >> (2 * j)) as u64, j)
        };
        let (y, h) = rsqrt(square);
        let down = 32 + j - h;
        for u in &mut line.unit {
            *u = ((u64::from(*u) * u64::from(y)) >> down) as u32;
        }
        // ρ is the lead's figure, below the exact by less than MARGIN
        // units: its reciprocal is not below 1/ρ but for the reciprocal's
        // own error (2⁻²⁷ below), which 2⁻²⁶ more and a unit make up.
        let below = ((u64::from(line.lead) * u64::from(y)) >> down) as u32;
        let k = recip_q28(below);
        line.per_lead = k.saturating_add((k >> 26) + 1);
        line.rho = below + MARGIN;
        line
    }

    /// Whether an axis moves one way on `self` and the other on `next`.
    pub(crate) fn reverses(&self, next: &Line<N>) -> bool {
        (self.forward & next.backward) | (self.backward & next.forward) != 0
    }

    /// The path period the junction from `self` to `next` allows: grbl's
    /// `v = √(a·δ·s / (1 − s))`, `s = sin(φ/2)` for the angle `φ` between
    /// the line before reversed and the line after, from `scale`
    /// `= 1/√(a·δ)` in Q8 ticks (`u32::MAX` for no deviation). With `u` and
    /// `w` the lines' directions, `s = |u + w|/2` and
    /// `1 − s = |u − w|² / (2·(2 + |u + w|))`, so
    /// `1/v = scale · |u − w| / √(|u + w|·(2 + |u + w|))`, where no
    /// difference of near numbers is taken: a shallow bend's `|u − w|` is
    /// as near as the directions are; and `|u + w|² = 4 − |u − w|²`, so the
    /// root under the line is a function of `|u − w|²` alone, [`bend`].
    /// Rounded to the slower side; 0 (no
    /// limit) where the directions agree to within their error (the lines
    /// go on straight, to 2⁻²⁶), [`REST`] where an axis reverses or a line
    /// has no steps.
    pub(crate) fn junction(&self, next: &Line<N>, scale: u32) -> u64 {
        if self.lead == 0 || next.lead == 0 || self.reverses(next) {
            return REST;
        }
        let mut diff = 0u64;
        for (&u, &w) in self.unit.iter().zip(&next.unit) {
            // No axis reverses: |uᵢ − wᵢ| is ||uᵢ| − |wᵢ||, in Q30; squared
            // in Q60, |u − w|² ≤ 2 in 2⁶¹.
            diff += u64::from(u.abs_diff(w)).pow(2);
        }
        // |u − w|, Q30: each axis's difference off by less than 2·MARGIN
        // units, so the length by less than `err`, and its root below by
        // less than 2⁻²⁷ of it and a unit.
        let err = 2 * MARGIN * N as u32;
        let apart = sqrt(diff);
        if apart <= err {
            return 0;
        }
        if scale == u32::MAX {
            return REST;
        }
        let apart = apart + (apart >> 26) + 1 + err;
        // |u − w|² in Q30, above the exact; at most 2 (no axis reversing,
        // the lines meet at 90° at most).
        let square = ((u64::from(apart) * u64::from(apart)) >> 30) + 1;
        let bend = bend(square.min(2 << 30) as u32);
        // Q8 times Q30, then times Q31 to Q32: below 2⁶³.
        let scaled = (u64::from(scale) * u64::from(apart)).div_ceil(1 << 30);
        (scaled * u64::from(bend)).div_ceil(1 << 7)
    }
}

/// `1/√(S·(2 + S))` for `S = |u + w| = √(4 − z)`, `z = |u − w|²` of two
/// unit vectors, on `z` in `[0, 2]`: the Chebyshev fit of degree 9 in
/// `z − 1` (within 1.8·10⁻⁹ of it), its coefficients in Q31, highest
/// first.
const BEND: [i32; 10] = [
    4263, 13931, 35367, 119353, 420521, 1489277, 5509589, 22003473, 103054214, 844648042,
];

/// `1/√(S·(2 + S))` (as [`BEND`]) for `z` in Q30, in Q31, above the exact
/// by less than 16 units: the fit's error and Horner's truncations (each
/// a unit at most, `z − 1` at most 1) lie within 11 units below and 4
/// above (the module's tests), and 12 are added.
fn bend(z: u32) -> u32 {
    let x = (i64::from(z) - (1 << 30)) as i32;
    let mut acc = BEND[0];
    for &c in &BEND[1..] {
        acc = c + ((i64::from(acc) * i64::from(x)) >> 30) as i32;
    }
    (acc + 12) as u32
}
/// A line queued after the one playing: where it ends, its figures, the
/// path period its junction with the line before it allows, and its tail
/// as the last backward pass found it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Queued<const N: usize> {
    pub(crate) target: [i64; N],
    pub(crate) line: Line<N>,
    pub(crate) junction: u64,
    /// The steps in which its lead stops from the speed its end allows
    /// (`Axes::tails` says whether it holds).
    pub(crate) tail: u32,
}

impl<const N: usize> Queued<N> {
    /// No line: what the queue's free places hold.
    pub(crate) const NONE: Self = Queued {
        target: [0; N],
        line: Line::NONE,
        junction: REST,
        tail: 0,
    };
}

/// The tail of a line that ends at a speed from which a stop takes
/// `stop` steps: its last step has that many after it, the stop's first
/// step its entry (the step a move plays with `r` steps left, itself
/// included, is no faster than the deceleration ramp's entry `r - 1`).
pub(crate) fn tail_from(stop: u32) -> u32 {
    stop.saturating_sub(1)
}

/// `a · b / 2^shift` (`shift` at least 32) rounded up but for 2⁻²² of
/// it, `u32::MAX` past it.
#[inline(always)]
fn product(a: u64, b: u32, shift: u32) -> u32 {
    // a·b in 96 bits, to 64 past its low word (a unit there if any).
    let low = (a & u64::from(u32::MAX)) * u64::from(b);
    let high = (a >> 32) * u64::from(b) + (low >> 32) + u64::from(low as u32 != 0);
    let high = high - (high >> 22);
    u32::try_from(high.div_ceil(1 << (shift - 32))).unwrap_or(u32::MAX)
}

/// The period, in ticks, of a lead of `per_lead` (`1/ρ`, Q28) on a path
/// period `path` (Q32): rounded up (but for 2⁻²²), `u32::MAX` at rest,
/// at least 1.
#[inline]
pub(crate) fn lead_period(path: u64, per_lead: u32) -> u32 {
    if path == REST {
        return u32::MAX;
    }
    product(path, per_lead, 60).max(1)
}

/// The path period (Q32) of a lead stepping every `ticks` on a line of
/// `rho` (`ρ`, Q30), exact.
pub(crate) fn path_period(ticks: u32, rho: u32) -> u64 {
    (u64::from(ticks) * u64::from(rho)) << 2
}

/// The period, in ticks, of the next line's lead at the path speed at
/// which a lead of `rho` (`ρ`, Q30) on the line before steps every
/// `ticks`: `ticks · ρ / ρ'`, with `per_lead` `1/ρ'` (Q28), rounded up
/// (but for 2⁻²²).
pub(crate) fn handed_period(ticks: u32, rho: u32, per_lead: u32) -> u32 {
    product(u64::from(rho) * u64::from(per_lead), ticks, 58)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::format;
    use std::string::String;

    /// A figure rounded to the slower side: at or above the exact, by less
    /// than `rel` of it and `units`.
    fn above(got: f64, exact: f64, rel: f64, units: f64, what: &str) -> Result<(), String> {
        if got < exact || got > exact * (1.0 + rel) + units {
            return Err(format!("{what}: {got} for {exact}"));
        }
        Ok(())
    }

    fn random() -> impl FnMut() -> u64 {
        crate::base::xorshift(0x2545_F491_4F6C_DD1D)
    }

    /// A random line of three axes, of every length to 2³².
    fn line(next: &mut impl FnMut() -> u64) -> [i64; 3] {
        let bits = next() % 33;
        [0, 1, 2].map(|_| {
            let r = next();
            let v = ((r >> 8) & ((1u64 << bits) - 1)) as i64;
            if r & 1 == 0 { v } else { -v }
        })
    }

    fn length(d: [i64; 3]) -> f64 {
        d.iter()
            .map(|&x| (x as f64) * (x as f64))
            .sum::<f64>()
            .sqrt()
    }

    #[test]
    fn a_lines_figures_are_on_the_slower_side_and_near() -> Result<(), String> {
        let mut next = random();
        for _ in 0..100_000 {
            let d = line(&mut next);
            let l = Line::between([0; 3], d);
            let lead = d.iter().map(|x| x.unsigned_abs()).max().unwrap();
            if lead == 0 {
                continue;
            }
            let rho = lead as f64 / length(d);
            let what = format!("{d:?}");
            above(
                f64::from(l.rho),
                rho * f64::from(1u32 << 30),
                0.0,
                10.0,
                &what,
            )?;
            let k = f64::from(1u32 << 28) / rho;
            above(f64::from(l.per_lead), k, 1e-7, 1.0, &what)?;
            for i in 0..3 {
                let u = d[i].unsigned_abs() as f64 / length(d) * f64::from(1u32 << 30);
                let got = f64::from(l.unit[i]);
                if got > u || u - got >= 10.0 {
                    return Err(format!("{what}: unit {i} {got} for {u}"));
                }
                let (forward, backward) = (l.forward >> i & 1, l.backward >> i & 1);
                if (forward, backward) != (u32::from(d[i] > 0), u32::from(d[i] < 0)) {
                    return Err(format!(
                        "{what}: axis {i} forward {forward} backward {backward}"
                    ));
                }
            }
        }
        Ok(())
    }

    /// The junction's path period computed in `f64` by grbl's formula,
    /// from the angle `θ` between the lines (their cross product's length
    /// against their dot product): `s = cos(θ/2)`, `1 − s = 2·sin²(θ/4)`.
    fn exact_junction(a: [i64; 3], b: [i64; 3], scale: f64) -> f64 {
        let (a, b) = (a.map(|x| x as f64), b.map(|x| x as f64));
        let dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        let cross = [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ];
        let theta = cross.iter().map(|c| c * c).sum::<f64>().sqrt().atan2(dot);
        let s = (theta / 2.0).cos();
        let below = 2.0 * (theta / 4.0).sin().powi(2);
        scale * (below / s).sqrt()
    }

    #[test]
    fn junctions_are_on_the_slower_side_and_near() -> Result<(), String> {
        let mut next = random();
        let mut bends = 0;
        while bends < 100_000 {
            let (a, b) = (line(&mut next), line(&mut next));
            let scale = (next() % (1 << 24)) as u32 + 1;
            let got = Line::between([0; 3], a).junction(&Line::between([0; 3], b), scale);
            let reverses = (0..3).any(|i| a[i].signum() * b[i].signum() < 0);
            let what = format!("{a:?} {b:?} at {scale}");
            if reverses || a == [0; 3] || b == [0; 3] {
                if got != REST {
                    return Err(format!("{what}: {got}, not at rest"));
                }
                continue;
            }
            bends += 1;
            let exact = exact_junction(a, b, f64::from(scale));
            // Straight to 2⁻²⁶: no limit.
            if got == 0 {
                if exact > f64::from(scale) * 1e-7 {
                    return Err(format!("{what}: no limit, {exact} exact"));
                }
                continue;
            }
            // The directions' error, 2⁻²⁶ of the scale, counts where the
            // bend is shallow.
            // Q32 against the scale's Q8.
            let got = got as f64 / f64::from(1u32 << 24);
            above(got, exact, 1e-6, 2.0 + f64::from(scale) * 1e-7, &what)?;
        }
        Ok(())
    }

    /// The fit of `1/√(S·(2 + S))`, evaluated as the junction does, at
    /// 2¹⁸ points of `z` in `[0, 2]` and at its ends: above the exact, by
    /// less than 16 units of Q31.
    #[test]
    fn the_bend_is_above_and_near() -> Result<(), String> {
        for i in 0..=1u32 << 18 {
            let z = i << 13;
            let zf = f64::from(z) / f64::from(1u32 << 30);
            let s = (4.0 - zf).sqrt();
            let exact = 1.0 / (s * (2.0 + s)).sqrt() * f64::from(1u32 << 31);
            above(f64::from(bend(z)), exact, 0.0, 16.0, &format!("bend({zf})"))?;
        }
        Ok(())
    }
}
