//! One phase behind an ideal chopper whose set current steps instead of
//! following a sine: half steps (each phase at the set current, off, or at
//! minus it) or full steps (both phases always on), at a steady speed.
//!
//! In the rotor's electrical angle `θ`, as in the `chopper` module,
//!
//! ```text
//! X di/dθ = v - R i + E sin θ        X = ω_e L, E = K_m ω
//! ```
//!
//! with the set current `c(θ) = I s(θ + φ)`, `s` the drive's staircase
//! (for half steps `1, 1, 0, -1, -1, -1, 0, 1` over eighths of a turn
//! centred on `0, π/4, ...`; for full steps the sign of `cos`), `φ` the
//! field's lead. Where the current is below the set one the chopper puts
//! `+V` on the phase, above it `-V`; on it, it holds it while the voltage
//! that takes, `R c - E sin θ`, is within `±V`. Under a constant `v` the
//! current is `v/R + a sin θ + b cos θ + K e^(-ρ θ)` (`ρ = R/X`), so every
//! stretch is a closed form, and so is where holding the current takes more
//! than the supply; only where a driven current meets the set one is
//! searched for, a bracketed root within each step of the staircase.
//!
//! The staircase flips sign half a turn on, as the back-EMF does, so the
//! steady current does too: `i(θ0 + π) = -i(θ0)`, a fixed point found by
//! the secant method (the half-turn map is monotone and contracts). The
//! torque is `K_m` times the mean `q` current, `(2/π) ∫ -i sin θ dθ` over
//! half a turn, largest over the lead.

use core::f64::consts::{PI, TAU};

use super::chopper::{Response, STILL, largest_over_lead};

/// A drive's set current over a turn: the levels (times the set current)
/// of its steps, each `width` radians wide, the first centred on `0`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Staircase {
    pub levels: &'static [f64],
    pub width: f64,
}

/// Half steps without compensation: one phase, then both, each at the set
/// current.
pub(super) const HALF_STEPS: Staircase = Staircase {
    levels: &[1.0, 1.0, 0.0, -1.0, -1.0, -1.0, 0.0, 1.0],
    width: PI / 4.0,
};

/// Full steps with both phases on.
pub(super) const FULL_STEPS: Staircase = Staircase {
    levels: &[1.0, -1.0],
    width: PI,
};

/// Samples per eighth of a turn when looking for where a stretch ends, and
/// the steps of the root search within the bracket the samples give.
const SAMPLES: f64 = 8.0;
const ROOT_STEPS: u32 = 100;
/// Stretches within one step of the staircase at most (a current caught
/// and lost again takes two).
const STRETCHES: u32 = 16;
/// Steps of the search for the periodic current.
const PERIODIC_STEPS: u32 = 100;

/// A phase at one steady speed: `r` in Ω, `x = ω_e L` in Ω, `e = K_m ω`
/// in V, `amp` the set current in A, `volts` the supply in V.
#[derive(Clone, Copy, Debug)]
pub(super) struct SteppedPhase {
    pub r: f64,
    pub x: f64,
    pub e: f64,
    pub amp: f64,
    pub volts: f64,
    pub steps: Staircase,
}

/// What the chopper does over a stretch: holds the set current, or puts
/// a constant voltage on the phase.
#[derive(Clone, Copy)]
enum Mode {
    Held,
    Driven(f64),
}

impl SteppedPhase {
    /// The largest mean `q` current over the field's lead, in A.
    pub fn largest_q(&self) -> f64 {
        if self.x <= STILL * self.r {
            return self.still_q();
        }
        largest_over_lead(&|lead| self.mean_q(lead))
    }

    /// At rest: the staircase, clipped at `V / R` where the supply cannot
    /// drive the set current; its fundamental, the mean at a lead of a
    /// quarter turn.
    fn still_q(&self) -> f64 {
        let level = self.amp.min(self.volts / self.r);
        level * self.fundamental()
    }

    /// The staircase's fundamental, `(1/π) ∫ s(ψ) cos ψ dψ` over a turn:
    /// `(4/π) cos(π/8)` for half steps, `4/π` for full steps.
    fn fundamental(&self) -> f64 {
        let w = self.steps.width;
        let mut sum = 0.0;
        for (k, level) in self.steps.levels.iter().enumerate() {
            let centre = w * k as f64;
            sum += level * (libm::sin(centre + 0.5 * w) - libm::sin(centre - 0.5 * w));
        }
        sum / PI
    }

    /// The mean `q` current with the field `lead` ahead of the rotor.
    fn mean_q(&self, lead: f64) -> f64 {
        // Half a turn from the start of the first step.
        let from = -0.5 * self.steps.width - lead;
        2.0 / PI * self.periodic(&|i0| self.half_turn(from, i0))
    }

    /// The integral of `-i sin θ` over the half turn that `turn` maps a
    /// start `i0` through (to the current at its end, and that integral),
    /// for the periodic current: the `i0` that ends at `-i0`, a root of
    /// `g(i0) = i0 + end(i0)`, whose slope is between 1 and 2 (the half
    /// turn's map neither falls nor grows). From a guess `x`, the root lies
    /// between `x - g(x)` and `x - g(x)/2`; secant steps within that
    /// bracket, halving where a step would leave it.
    fn periodic(&self, turn: &impl Fn(f64) -> (f64, f64)) -> f64 {
        let (g0, integral0) = turn(0.0);
        if g0 == 0.0 {
            return integral0;
        }
        let (mut lo, mut hi) = if g0 > 0.0 {
            (-g0, -0.5 * g0)
        } else {
            (-0.5 * g0, -g0)
        };
        // The slope-1 step: exact when the half turn forgets its start.
        let mut x = -g0;
        let (end, mut integral) = turn(x);
        let mut gx = x + end;
        let (mut prev, mut gprev) = (0.0, g0);
        let scale = self.amp + libm::fabs(x);
        for _ in 0..PERIODIC_STEPS {
            if gx == 0.0 {
                break;
            }
            if gx < 0.0 {
                lo = lo.max(x);
            } else {
                hi = hi.min(x);
            }
            let secant = x - gx * (x - prev) / (gx - gprev);
            let next = if secant > lo && secant < hi {
                secant
            } else {
                0.5 * (lo + hi)
            };
            if libm::fabs(next - x) <= 1e-15 * scale || hi - lo <= 1e-15 * scale {
                break;
            }
            (prev, gprev) = (x, gx);
            x = next;
            let (end, part) = turn(x);
            (gx, integral) = (x + end, part);
        }
        integral
    }

    /// The current half a turn after `from`, starting at `i0` there, and
    /// the integral of `-i sin θ` over that half turn.
    fn half_turn(&self, from: f64, i0: f64) -> (f64, f64) {
        let w = self.steps.width;
        let count = libm::round(PI / w) as usize;
        let (mut i, mut integral) = (i0, 0.0);
        for k in 0..count {
            let level = self.amp * self.steps.levels[k % self.steps.levels.len()];
            let start = from + w * k as f64;
            let (end, part) = self.step(start, start + w, level, i);
            i = end;
            integral += part;
        }
        (i, integral)
    }

    /// One step of the staircase, `[t0, t1]` at the set current `level`,
    /// from the current `i0`: the current at `t1` and the integral of
    /// `-i sin θ`.
    fn step(&self, t0: f64, t1: f64, level: f64, i0: f64) -> (f64, f64) {
        let (mut t, mut i, mut integral) = (t0, i0, 0.0);
        let mut mode = if i < level {
            Mode::Driven(self.volts)
        } else if i > level {
            Mode::Driven(-self.volts)
        } else {
            self.on_level(t, level)
        };
        for _ in 0..STRETCHES {
            match mode {
                Mode::Held => {
                    let end = self.hold_ends(t, t1, level);
                    integral += level * (libm::cos(end) - libm::cos(t));
                    t = end;
                    // Lost by the side the voltage it takes leaves by.
                    let needed = self.r * level - self.e * libm::sin(t);
                    let v = if needed > 0.0 {
                        self.volts
                    } else {
                        -self.volts
                    };
                    mode = Mode::Driven(v);
                }
                Mode::Driven(v) => {
                    let (end, current) = self.drive_ends(t, t1, level, i, v);
                    integral += self.driven_integral(t, end, i, v);
                    (t, i) = (end, current);
                    mode = self.on_level(t, level);
                }
            }
            if t >= t1 {
                return (i, integral);
            }
        }
        // Out of stretches (a current caught and lost at one angle over
        // and over): the rest under the voltage the last one chose.
        let v = match mode {
            Mode::Driven(v) => v,
            Mode::Held => self.volts,
        };
        integral += self.driven_integral(t, t1, i, v);
        (self.driven(t, i, v)(t1), integral)
    }

    /// What the chopper does with the current on the set one at `t`:
    /// holds it if the supply lets it, else the full supply of the side the
    /// voltage holding it would take.
    fn on_level(&self, t: f64, level: f64) -> Mode {
        let needed = self.r * level - self.e * libm::sin(t);
        if needed > self.volts {
            Mode::Driven(self.volts)
        } else if needed < -self.volts {
            Mode::Driven(-self.volts)
        } else {
            Mode::Held
        }
    }

    /// Where holding `level` from `t` takes more than the supply, or `t1`.
    /// The voltage it takes, `R c - E sin θ`, stays within `±V` while
    /// `sin θ` is within `[(R c - V)/E, (R c + V)/E]`; it leaves that band
    /// upwards where `sin θ` rises through the top (at `asin(top)`, a turn
    /// apart) and downwards where it falls through the bottom (at
    /// `π - asin(bottom)`): the first of these from `t` on.
    fn hold_ends(&self, t: f64, t1: f64, level: f64) -> f64 {
        let (top, bottom) = (
            (self.r * level + self.volts) / self.e,
            (self.r * level - self.volts) / self.e,
        );
        // The first angle `base + 2πk` at or after `t`.
        let from_t = |base: f64| base + TAU * libm::ceil((t - base) / TAU);
        let mut end = t1;
        if top < 1.0 {
            end = end.min(from_t(libm::asin(top.max(-1.0))));
        }
        if bottom > -1.0 {
            end = end.min(from_t(PI - libm::asin(bottom.min(1.0))));
        }
        end.max(t)
    }

    /// Where the current under `v` from `(t, i)` meets `level`, or `t1`;
    /// and the current there.
    fn drive_ends(&self, t: f64, t1: f64, level: f64, i: f64, v: f64) -> (f64, f64) {
        let current = self.driven(t, i, v);
        // Under `+V` the current comes up to the set one from below, under
        // `-V` down to it from above.
        let side = if v > 0.0 { 1.0 } else { -1.0 };
        let gap = |s: f64| side * (level - current(s));
        match first_below(&gap, t, t1) {
            Some(met) => (met, level),
            None => (t1, current(t1)),
        }
    }

    /// The current under `v` from `i` at `t`, as a function of the angle.
    fn driven(&self, t: f64, i: f64, v: f64) -> impl Fn(f64) -> f64 {
        let response = self.response();
        let dc = v / self.r;
        let offset = i - (dc + response.steady(t));
        move |s| dc + response.steady(s) + offset * libm::exp(-response.rho * (s - t))
    }

    /// The winding's response to the back-EMF and its decay.
    fn response(&self) -> Response {
        Response::new(self.r, self.x, self.e)
    }

    /// `∫ -i sin θ dθ` over `[t, s]` for the current under `v` from `i`
    /// at `t`.
    fn driven_integral(&self, t: f64, s: f64, i: f64, v: f64) -> f64 {
        let response = self.response();
        let dc = v / self.r;
        let k = i - (dc + response.steady(t));
        response.integral(dc, k, t, s) - response.integral(dc, k, t, t)
    }
}

/// The first point in `(t0, t1]` where `f`, positive just after `t0`,
/// falls to 0 or below: sampled, then searched within the first bracket
/// (the secant method, halving where a step would leave it). `None` when
/// no sample is at or below 0.
fn first_below(f: &impl Fn(f64) -> f64, t0: f64, t1: f64) -> Option<f64> {
    let samples = libm::ceil(SAMPLES * (t1 - t0) / (PI / 4.0)).max(1.0) as u32;
    let h = (t1 - t0) / samples as f64;
    let mut lo = (t0, f(t0));
    for k in 1..=samples {
        let s = if k == samples { t1 } else { t0 + h * k as f64 };
        let fs = f(s);
        if fs <= 0.0 {
            return Some(root(f, lo, (s, fs)));
        }
        lo = (s, fs);
    }
    None
}

/// The root of `f` between `lo` (above 0, or at 0 at the stretch's start)
/// and `hi` (at or below 0), each with its value: the Illinois method (the
/// secant through the bracket's ends, the value kept at an end that stays
/// twice in a row halved, so that an exponential's tail does not hold the
/// secant to one end), a halving where the secant leaves the bracket.
fn root(f: &impl Fn(f64) -> f64, mut lo: (f64, f64), mut hi: (f64, f64)) -> f64 {
    // Which end the last step kept: -1 the low one, 1 the high one.
    let mut kept = 0;
    for _ in 0..ROOT_STEPS {
        let width = hi.0 - lo.0;
        let resolution = 4.0 * f64::EPSILON * libm::fabs(hi.0).max(1.0);
        if width <= resolution || hi.1 == 0.0 {
            break;
        }
        let secant = lo.0 + width * lo.1 / (lo.1 - hi.1);
        let s = if secant > lo.0 && secant < hi.0 {
            secant
        } else {
            lo.0 + 0.5 * width
        };
        let fs = f(s);
        if fs > 0.0 {
            lo = (s, fs);
            if kept == 1 {
                hi.1 *= 0.5;
            }
            kept = 1;
        } else {
            hi = (s, fs);
            if kept == -1 {
                lo.1 *= 0.5;
            }
            kept = -1;
        }
    }
    hi.0
}
