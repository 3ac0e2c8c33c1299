//! One phase of a two-phase hybrid motor behind an ideal chopper, at a
//! steady speed, solved exactly: the current the chopper holds to its
//! reference while the supply lets it, and the current the winding carries
//! under the full supply once it cannot.
//!
//! In the rotor's electrical angle `θ` (so `d/dt = ω_e d/dθ`), phase A is
//!
//! ```text
//! X di/dθ = v - R i + E sin θ        X = ω_e L, E = K_m ω
//! ```
//!
//! and its reference, led by the field by `φ`, is `r(θ) = I cos(θ + φ)`
//! (phase B is the same a quarter turn on, and gives the same torque).
//! Holding the reference takes `u(θ) = R r + X r' - E sin θ`, a sinusoid of
//! amplitude `U`. A chopper with a supply `V` holds the current while
//! `|u| <= V`; where `u` rises above `V` it puts `+V` on the phase and the
//! current falls behind, following `X i' = V - R i + E sin θ` (an
//! exponential and a sinusoid) until it meets the reference again, where
//! the chopper takes hold once more. If it has not met the reference half a
//! turn later it never does: the chopper then switches only where the
//! current crosses the reference, a square wave of `±V` whose switching
//! angle the periodic current fixes. The three cases (held, partly held,
//! square wave) are the whole steady state; each is a closed form but for
//! the angle where a partly held current is caught, found by Newton's
//! method within a bracket.
//!
//! The torque is `K_m` times the current's mean `q` component,
//! `(2/π) ∫ -i sin θ dθ` over half a turn (the half-wave symmetry
//! `i(θ + π) = -i(θ)` gives the other half).

use core::f64::consts::{PI, TAU};

/// A phase at one steady speed, all figures per phase: `r` in Ω, `x` the
/// reactance `ω_e L` in Ω, `e` the back-EMF amplitude `K_m ω` in V, `amp`
/// the reference's amplitude in A, `volts` the supply in V.
#[derive(Clone, Copy, Debug)]
pub(super) struct Phase {
    pub r: f64,
    pub x: f64,
    pub e: f64,
    pub amp: f64,
    pub volts: f64,
}

/// Steps of the root search (Newton's, kept within a bracket that halves
/// where a step would leave it): it ends sooner, once the bracket is as
/// narrow as an angle's resolution.
const ROOT_STEPS: u32 = 80;

/// Leads scanned over `(0, π)` before Brent's search around the best of
/// them; that search's steps at most, and the lead's tolerance: 1e-7 rad,
/// where the torque is flat to 1e-13 of itself.
const LEADS: u32 = 12;
const BRENT_STEPS: u32 = 60;
const LEAD_TOLERANCE: f64 = 1e-7;

/// Below this reactance over resistance the winding is taken as a resistor
/// (the speed as 0): the current lags the voltage by less than 1e-9 rad.
pub(super) const STILL: f64 = 1e-9;

impl Phase {
    /// The largest mean `q` current over the field's lead, in A: what the
    /// pull-out torque is `K_m` times. May be negative where the back-EMF
    /// brakes the rotor at every lead.
    pub fn largest_q(&self) -> f64 {
        // The current all on the `q` axis, if the supply holds it.
        let (p, q) = self.required(PI / 2.0);
        if libm::hypot(p, q) <= self.volts {
            return self.amp;
        }
        if self.x <= STILL * self.r {
            return self.still_q();
        }
        largest_over_lead(&|lead| self.mean_q(lead))
    }

    /// The voltage that holds the reference, `u(θ) = P cos θ + Q sin θ`:
    /// `(P, Q)` for the lead `lead`.
    fn required(&self, lead: f64) -> (f64, f64) {
        let (s, c) = (libm::sin(lead), libm::cos(lead));
        let p = self.amp * (self.r * c - self.x * s);
        let q = -self.amp * (self.r * s + self.x * c) - self.e;
        (p, q)
    }

    /// At rest with a supply that cannot drive the set current: the current
    /// follows the reference up to `V / R` and is clipped there. The best
    /// lead is a quarter turn; the clipped sine's fundamental is the mean.
    fn still_q(&self) -> f64 {
        let cap = self.volts / self.r;
        if cap >= self.amp {
            return self.amp;
        }
        let t0 = libm::asin(cap / self.amp);
        4.0 / PI * (self.amp * (0.5 * t0 - 0.25 * libm::sin(2.0 * t0)) + cap * libm::cos(t0))
    }

    /// The mean `q` current with the field `lead` ahead of the rotor.
    fn mean_q(&self, lead: f64) -> f64 {
        let (p, q) = self.required(lead);
        let need = libm::hypot(p, q);
        if need <= self.volts {
            return self.amp * libm::sin(lead);
        }
        // `u` is above `V` on `(start, start + wide)`.
        let half = libm::acos(self.volts / need);
        let start = libm::atan2(q, p) - half;
        let wide = 2.0 * half;
        let w = Winding::new(self, lead);
        let from = w.start(start, w.reference(start));
        let ahead = |t: f64| w.ahead(t, from);
        // Where the current meets the reference again, if within half a
        // turn: held from there on. Beyond `start + wide` the supply
        // outruns the reference wherever the two meet, so the current
        // meets it at most once: if it is still below half a turn on, it
        // never met it.
        let (lo, hi) = (start + wide, start + PI);
        let met = if ahead(lo).0 >= 0.0 {
            Some(lo)
        } else if ahead(hi).0 >= 0.0 {
            Some(root(&ahead, lo, hi))
        } else {
            None
        };
        if let Some(met) = met {
            let held = w.reference_integral(hi) - w.reference_integral(met);
            let pushed = w.driven_integral(met, from) - w.driven_integral(start, from);
            return 2.0 / PI * (held + pushed);
        }
        // A square wave: `+V` from `s`, where the periodic current, coming
        // down under `-V`, crosses the reference, which it does where `u`
        // is above `V`.
        let s = w.switching(start, wide);
        let from = w.start(s, w.periodic(s));
        let integral = w.driven_integral(s + PI, from) - w.driven_integral(s, from);
        2.0 / PI * integral
    }
}

/// The winding's responses for one lead: the reference, the current under
/// `+V` from a given start, their integrals against `-sin θ`.
struct Winding {
    amp: f64,
    lead: f64,
    /// The lead's sine and cosine.
    lead_sc: (f64, f64),
    /// `V / R`, the current `+V` drives at rest.
    dc: f64,
    /// The winding's response to the back-EMF and its decay.
    response: Response,
    /// `E / X`: the back-EMF's push on the current per radian.
    emf: f64,
}

/// Where a stretch under `+V` starts: the angle, and the current there less
/// the steady response to the back-EMF.
#[derive(Clone, Copy)]
struct Start {
    t0: f64,
    offset: f64,
}

/// A phase's current under a constant voltage `v`,
/// `v/R + a sin θ + b cos θ + k e^(-ρ(θ - t0))`: its steady response to the
/// back-EMF (`a`, `b`) and its decay per radian `ρ = R / X`, the same for
/// every voltage and start.
#[derive(Clone, Copy, Debug)]
pub(super) struct Response {
    pub a: f64,
    pub b: f64,
    pub rho: f64,
}

impl Response {
    /// The response of a winding of resistance `r`, reactance `x` and
    /// back-EMF amplitude `e`.
    pub fn new(r: f64, x: f64, e: f64) -> Self {
        let den = r * r + x * x;
        Response {
            a: e * r / den,
            b: -e * x / den,
            rho: r / x,
        }
    }

    /// The steady response at `t`, `a sin t + b cos t`.
    pub fn steady(&self, t: f64) -> f64 {
        self.a * libm::sin(t) + self.b * libm::cos(t)
    }

    /// An antiderivative of `-i(u) sin u` at `u` for the current
    /// `dc + a sin u + b cos u + k e^(-ρ(u - t0))`.
    pub fn integral(&self, dc: f64, k: f64, t0: f64, u: f64) -> f64 {
        let (a, b, rho) = (self.a, self.b, self.rho);
        let decaying = k * libm::exp(-rho * (u - t0)) * (rho * libm::sin(u) + libm::cos(u))
            / (rho * rho + 1.0);
        let steady = dc * libm::cos(u) - a * (0.5 * u - 0.25 * libm::sin(2.0 * u))
            + 0.25 * b * libm::cos(2.0 * u);
        decaying + steady
    }
}

impl Winding {
    fn new(phase: &Phase, lead: f64) -> Self {
        Winding {
            amp: phase.amp,
            lead,
            lead_sc: (libm::sin(lead), libm::cos(lead)),
            dc: phase.volts / phase.r,
            response: Response::new(phase.r, phase.x, phase.e),
            emf: phase.e / phase.x,
        }
    }

    fn start(&self, t0: f64, i0: f64) -> Start {
        let offset = i0 - self.response.steady(t0);
        Start { t0, offset }
    }

    fn reference(&self, t: f64) -> f64 {
        self.amp * libm::cos(t + self.lead)
    }

    /// How far the current under `+V` from `from` is above the reference
    /// at `t`, and how fast that grows per radian:
    /// `i(t) = (i0 - s(t0)) e^-ρΔ + (V/R)(1 - e^-ρΔ) + s(t)` and
    /// `i' = ρ (V/R - i) + (E/X) sin t`.
    fn ahead(&self, t: f64, from: Start) -> (f64, f64) {
        let Response { a, b, rho } = self.response;
        let grown = libm::expm1(-rho * (t - from.t0));
        let (sin, cos) = (libm::sin(t), libm::cos(t));
        let current = from.offset * (1.0 + grown) - self.dc * grown + a * sin + b * cos;
        let (ls, lc) = self.lead_sc;
        let reference = self.amp * (cos * lc - sin * ls);
        let slope = rho * (self.dc - current) + self.emf * sin;
        let reference_slope = -self.amp * (sin * lc + cos * ls);
        (current - reference, slope - reference_slope)
    }

    /// The current at `s` of the periodic square wave switching to `+V`
    /// at `s`: `i(s + π) = -i(s)` gives `s(s) - (V/R) tanh(ρπ/2)`.
    fn periodic(&self, s: f64) -> f64 {
        self.response.steady(s) - self.dc * libm::tanh(0.5 * self.response.rho * PI)
    }

    /// Where the square wave switches to `+V`: the angle in
    /// `(start, start + wide)` at which [`Winding::periodic`] equals the
    /// reference, `α sin s + β cos s = D` with `α = a + I sin φ`,
    /// `β = b - I cos φ` and `D = (V/R) tanh(ρπ/2)`. The first of the
    /// two solutions from `start`; the middle of the range if neither lies
    /// in it (an edge that rounding alone reaches).
    fn switching(&self, start: f64, wide: f64) -> f64 {
        let (ls, lc) = self.lead_sc;
        let Response { a, b, rho } = self.response;
        let (alpha, beta) = (a + self.amp * ls, b - self.amp * lc);
        let size = libm::hypot(alpha, beta);
        let level = self.dc * libm::tanh(0.5 * rho * PI);
        let centre = libm::atan2(alpha, beta);
        let spread = libm::acos((level / size).clamp(-1.0, 1.0));
        let into = |s: f64| {
            let d = s - start;
            start + d - TAU * libm::floor(d / TAU)
        };
        let (x, y) = (into(centre - spread), into(centre + spread));
        let first = x.min(y);
        if first - start <= wide {
            first
        } else {
            start + 0.5 * wide
        }
    }

    /// An antiderivative of `-r(θ) sin θ`.
    fn reference_integral(&self, t: f64) -> f64 {
        self.amp * (0.5 * t * self.lead_sc.0 + 0.25 * libm::cos(2.0 * t + self.lead))
    }

    /// An antiderivative of `-i(θ) sin θ` for the current under `+V` from
    /// `from`.
    fn driven_integral(&self, t: f64, from: Start) -> f64 {
        self.response
            .integral(self.dc, from.offset - self.dc, from.t0, t)
    }
}

/// The largest of `f` over the field's lead in `(0, π)`: the best of
/// [`LEADS`] - 1 leads scanned, then Brent's method around it.
pub(super) fn largest_over_lead(f: &impl Fn(f64) -> f64) -> f64 {
    let step = PI / LEADS as f64;
    let mut best = (step, f(step));
    for k in 2..LEADS {
        let lead = step * k as f64;
        let q = f(lead);
        if q > best.1 {
            best = (lead, q);
        }
    }
    let (_, q) = brent_max(f, best.0 - step, best, best.0 + step);
    q.max(best.1)
}

/// The root of `f` (value and slope) in `[lo, hi]`, `f(lo) < 0 <= f(hi)`:
/// Newton's steps, a halving wherever a step would leave the bracket.
fn root(f: &impl Fn(f64) -> (f64, f64), mut lo: f64, mut hi: f64) -> f64 {
    let mut t = 0.5 * (lo + hi);
    for _ in 0..ROOT_STEPS {
        let (v, slope) = f(t);
        if v < 0.0 {
            lo = t;
        } else {
            hi = t;
        }
        let newton = t - v / slope;
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let resolution = 4.0 * f64::EPSILON * t.abs().max(1.0);
        if libm::fabs(next - t) <= resolution || hi - lo <= resolution {
            return next;
        }
        t = next;
    }
    t
}

/// The largest value of `f` on `[lo, hi]`, started from `best` (a point
/// inside and its value): Brent's method, a parabola through the three best
/// points where it falls inside the bracket and shrinks it, a golden-section
/// step where not.
pub(super) fn brent_max(
    f: &impl Fn(f64) -> f64,
    mut lo: f64,
    best: (f64, f64),
    mut hi: f64,
) -> (f64, f64) {
    let golden = 0.5 * (3.0 - libm::sqrt(5.0));
    // The best point, the second best and the one before; values negated
    // so that the search minimises.
    let (mut x, mut fx) = (best.0, -best.1);
    let (mut w, mut fw, mut v, mut fv) = (x, fx, x, fx);
    let (mut d, mut e) = (0.0f64, 0.0f64);
    for _ in 0..BRENT_STEPS {
        let mid = 0.5 * (lo + hi);
        let tol = LEAD_TOLERANCE;
        if libm::fabs(x - mid) <= 2.0 * tol - 0.5 * (hi - lo) {
            break;
        }
        let mut parabolic = false;
        if libm::fabs(e) > tol {
            let r = (x - w) * (fx - fv);
            let q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            let mut q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            }
            q = libm::fabs(q);
            if libm::fabs(p) < libm::fabs(0.5 * q * e) && p > q * (lo - x) && p < q * (hi - x) {
                e = d;
                d = p / q;
                let u = x + d;
                if u - lo < 2.0 * tol || hi - u < 2.0 * tol {
                    d = if x < mid { tol } else { -tol };
                }
                parabolic = true;
            }
        }
        if !parabolic {
            e = if x < mid { hi - x } else { lo - x };
            d = golden * e;
        }
        let u = if libm::fabs(d) >= tol {
            x + d
        } else if d > 0.0 {
            x + tol
        } else {
            x - tol
        };
        let fu = -f(u);
        if fu <= fx {
            if u < x {
                hi = x;
            } else {
                lo = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                lo = u;
            } else {
                hi = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
    }
    (x, -fx)
}
