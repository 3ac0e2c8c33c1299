//! Fitting runs to a curve: the compressed layout's table, every step edge
//! within `compress` timer ticks of the curve's exact edge, and no period
//! shorter than the curve's shortest, rounded down.
//!
//! With `ticks_per_step = 2` each entry is a half period the timer plays
//! twice, so a step edge lies twice as far from the curve as the entries'
//! running sum: the runs are fitted to half the tolerance, in ticks of the
//! entries, and the figures give the step edges' distance in timer ticks.
//!
//! A run starting after edge `s` (at fixed-point position `P_s`) puts edge
//! `s + j` at `P_s + j I + j (j - 1) / 2 A`, linear in the run's `interval`
//! `I` and `add` `A`. Each edge's tolerance is a band for that position, so
//! the runs that keep edges `s + 1 ..= s + j` in their bands form a convex
//! polygon in the `(I, A)` plane, clipped once per edge. The fitter makes
//! each run as long as the polygon holds an integer point that, played by
//! [`Expand`]'s own arithmetic, keeps every edge in its
//! band: the longest run from every start, so never more runs than a fit
//! that gives up earlier.

use std::collections::VecDeque;
use std::vec;
use std::vec::Vec;

use profile_core::runs::{self, Expand, LinearRun};
use profile_core::{CheckedSpec, CompactFigures, Discretization, Error, Key, Rounding, Spec, Word};

/// The smallest `compress` allowed with one reload per step: an integer edge
/// cannot land nearer than half a tick to every point of the curve. With
/// `ticks_per_step = 2` step edges fall on every other tick, and the
/// smallest is twice this.
pub const MIN_COMPRESS_TICKS: f64 = 0.5;

/// The largest `compress` allowed: the longest period a run's 16-bit word
/// holds. An edge allowed further from the curve could lag it by more than
/// any step of the ramp.
pub const MAX_COMPRESS_TICKS: f64 = u16::MAX as f64;

const ONE: f64 = (1u64 << LinearRun::FRACTION_BITS) as f64;
/// The longest step a run plays, in fixed point: 65 535 whole ticks.
const LONGEST: f64 = u16::MAX as f64 * ONE;
/// Polygons kept to step back to when the longest run has no integer point.
const BACKTRACK: usize = 48;

/// A convex polygon in the `(interval, add)` plane.
type Polygon = Vec<(f64, f64)>;

/// Keeps the part of `poly` where `a x + b y <= c`, into `out`.
fn clip(poly: &Polygon, a: f64, b: f64, c: f64, out: &mut Polygon) {
    out.clear();
    let side = |p: (f64, f64)| a * p.0 + b * p.1 - c;
    let Some(&first) = poly.first() else {
        return;
    };
    // Each edge `p -> q` in turn, the last one back to the first vertex;
    // each vertex's side worked out once.
    let (mut p, mut vp) = (first, side(first));
    for k in 1..=poly.len() {
        let q = if k == poly.len() { first } else { poly[k] };
        let vq = side(q);
        if vp <= 0.0 {
            out.push(p);
        }
        if (vp < 0.0 && vq > 0.0) || (vp > 0.0 && vq < 0.0) {
            let t = vp / (vp - vq);
            out.push((p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)));
        }
        (p, vp) = (q, vq);
    }
}

/// Whether `poly` may hold an integer point: some whole `add` within its
/// rows, and, where those are few, a whole `interval` on one of them. It
/// only shrinks as edges are added, so once this fails no longer run has
/// an integer point.
fn has_integer(poly: &Polygon) -> bool {
    let (ylo, yhi) = poly
        .iter()
        .fold((f64::MAX, f64::MIN), |s, p| (s.0.min(p.1), s.1.max(p.1)));
    let (first, last) = (libm::ceil(ylo), libm::floor(yhi));
    if last < first {
        return false;
    }
    if last - first > 2.0 {
        return true;
    }
    let mut y = first;
    while y <= last {
        if let Some((xlo, xhi)) = row(poly, y) {
            if libm::ceil(xlo) <= libm::floor(xhi) {
                return true;
            }
        }
        y += 1.0;
    }
    false
}

/// The interval of `x` where the horizontal line `y` crosses `poly`.
fn row(poly: &Polygon, y: f64) -> Option<(f64, f64)> {
    let mut range: Option<(f64, f64)> = None;
    for (i, &p) in poly.iter().enumerate() {
        let q = poly[(i + 1) % poly.len()];
        let (lo, hi) = (p.1.min(q.1), p.1.max(q.1));
        if y < lo || y > hi {
            continue;
        }
        let xs: [f64; 2] = if hi - lo < 1e-12 {
            [p.0, q.0]
        } else {
            let x = p.0 + (y - p.1) / (q.1 - p.1) * (q.0 - p.0);
            [x, x]
        };
        for x in xs {
            range = Some(range.map_or((x, x), |(a, b)| (a.min(x), b.max(x))));
        }
    }
    range
}

/// Integer points of `poly` to try: up to 5 rows of `add` across it and up
/// to 3 `interval`s across each row, and on each row the two whole
/// `interval`s around `aim(add)`, where that row's run ends nearest its
/// exact edge.
fn candidates(poly: &Polygon, aim: impl Fn(f64) -> f64) -> Vec<(i64, i64)> {
    let (ylo, yhi) = poly
        .iter()
        .fold((f64::MAX, f64::MIN), |s, p| (s.0.min(p.1), s.1.max(p.1)));
    let spread = |lo: f64, hi: f64, n: usize| -> Vec<f64> {
        let (lo, hi) = (libm::ceil(lo), libm::floor(hi));
        if hi < lo {
            // No integer strictly inside: the nearest one, in case rounding
            // of the polygon's edges hid it.
            return std::vec![libm::round((lo + hi) / 2.0)];
        }
        let count = ((hi - lo) as usize + 1).min(n);
        (0..count)
            .map(|i| {
                let t = if count == 1 {
                    0.5
                } else {
                    i as f64 / (count - 1) as f64
                };
                libm::round(lo + t * (hi - lo))
            })
            .collect()
    };
    let mut out = Vec::new();
    for y in spread(ylo, yhi, 5) {
        let Some((xlo, xhi)) = row(poly, y.clamp(ylo, yhi)) else {
            continue;
        };
        for x in spread(xlo, xhi, 3) {
            out.push((x as i64, y as i64));
        }
        let x = aim(y).clamp(xlo, xhi);
        for x in [libm::floor(x), libm::ceil(x)] {
            out.push((x as i64, y as i64));
        }
    }
    out
}

/// Where the fitter stands: edges placed, and the fixed-point position of
/// the last one (remainder included).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct At {
    done: usize,
    pos: i64,
}

/// The exact edges and their tolerance.
struct Fit<'a> {
    /// Exact edge `k + 1` in ticks, at index `k`.
    exact: &'a [f64],
    /// The step edges' tolerance, in timer ticks.
    tolerance: f64,
    /// Edge `k`'s band of fixed-point positions (see [`Fit::band`]), at
    /// index `k`: worked out once, read for every run tried.
    bands: Vec<(i64, i64)>,
    /// The shortest period a run may play, in ticks: the curve's shortest
    /// period, rounded down, as the per-step table's shortest is at most.
    shortest: i64,
}

/// The longest run fitted. A run's polygon gains a vertex every few
/// edges while the band is wide, so fitting a run costs about the square of
/// its length: this bounds the work for the longest table at the largest
/// `compress` to a fraction of a second (optimised), at a cost of at most
/// 64 runs (640 bytes, against 131 072 per step) on a 65 536-step table.
const MAX_RUN_STEPS: usize = 1024;

/// How far the look at the next run goes: beyond, any choice is as good.
const REACH: usize = 256;

/// Shorter runs tried besides the longest: a run that ends where the next
/// one has room can beat the longest one that leaves none.
const SHORTER: [usize; 7] = [0, 1, 2, 4, 8, 16, 32];

impl<'a> Fit<'a> {
    /// `exact` holds at most [`MAX_LEN`](profile_core::MAX_LEN) edges of periods
    /// a word holds, and `tolerance` is at most [`MAX_COMPRESS_TICKS`]: every
    /// band lies below 2^33 ticks, 2^49 in fixed point.
    /// Step edges lie `repeat` times as far from the curve as the entries'
    /// running sum that the fit places: each band is `tolerance / repeat`
    /// wide on either side.
    fn new(exact: &'a [f64], tolerance: f64, repeat: f64) -> Self {
        let fixed = |ticks: f64| (ticks as i64).saturating_mul(1 << LinearRun::FRACTION_BITS);
        let half_width = tolerance / repeat;
        let bands = exact
            .iter()
            .map(|&t| {
                let lo = fixed(libm::ceil(t - half_width));
                let hi = fixed(libm::floor(t + half_width) + 1.0);
                (lo, hi.saturating_sub(1))
            })
            .collect();
        let mut shortest = f64::INFINITY;
        let mut before = 0.0;
        for &t in exact {
            shortest = shortest.min(t - before);
            before = t;
        }
        let shortest = if shortest.is_finite() {
            (libm::floor(shortest) as i64).max(1)
        } else {
            1
        };
        Fit {
            exact,
            tolerance,
            bands,
            shortest,
        }
    }

    /// The band of fixed-point positions that puts edge index `k` within
    /// the tolerance: from the first whole tick at least `tolerance` before
    /// the exact edge to the last fraction of the last whole tick at most
    /// `tolerance` after it.
    fn band(&self, k: usize) -> (i64, i64) {
        self.bands[k]
    }

    /// Plays `len` steps of a run from `at` with the player's arithmetic:
    /// the end position if every edge is in its band and every period fits
    /// a `u16`.
    fn play(&self, at: At, interval: i64, add: i64, len: usize) -> Option<i64> {
        let (mut pos, mut step) = (at.pos, interval);
        for j in 0..len {
            if !(0..=u32::MAX as i64).contains(&step) {
                return None;
            }
            let next = pos + step;
            let period = (next >> LinearRun::FRACTION_BITS) - (pos >> LinearRun::FRACTION_BITS);
            if !(self.shortest..=u16::MAX as i64).contains(&period) {
                return None;
            }
            let (lo, hi) = self.band(at.done + j);
            if next < lo || next > hi {
                return None;
            }
            pos = next;
            step += add;
        }
        Some(pos)
    }

    /// The polygons of the runs from `at`, by length, the last `keep` of
    /// them: every run of that length that keeps its edges lies inside.
    fn polygons(&self, at: At, keep: usize, most: usize) -> VecDeque<(usize, Polygon)> {
        let most = (self.exact.len() - at.done).min(most);
        let mut poly: Polygon = vec![
            (ONE, i32::MIN as f64),
            (u32::MAX as f64, i32::MIN as f64),
            (u32::MAX as f64, i32::MAX as f64),
            (ONE, i32::MAX as f64),
        ];
        let mut kept: VecDeque<(usize, Polygon)> = VecDeque::new();
        let (mut half, mut clipped) = (Polygon::new(), Polygon::new());
        let mut len = 0;
        while len < most {
            let j = (len + 1) as f64;
            let c = j * (j - 1.0) / 2.0;
            let (lo, hi) = self.band(at.done + len);
            let (lo, hi) = ((lo - at.pos) as f64, (hi - at.pos) as f64);
            clip(&poly, j, c, hi, &mut half);
            clip(&half, -j, -c, -lo, &mut clipped);
            // The period this step plays, `interval + len add`, stays
            // within the word and above the shortest: a step of at most
            // 65 535 ticks less one fraction never plays more than 65 535
            // whole ticks, and one of `shortest` whole ticks never fewer.
            let k = len as f64;
            clip(&clipped, 1.0, k, LONGEST - 1.0, &mut half);
            clip(&half, -1.0, -k, -(self.shortest as f64 * ONE), &mut clipped);
            if clipped.len() < 3 || !has_integer(&clipped) {
                break;
            }
            core::mem::swap(&mut poly, &mut clipped);
            len += 1;
            if keep > 0 {
                let mut slot = if kept.len() == keep {
                    kept.pop_front().map(|(_, p)| p).unwrap_or_default()
                } else {
                    Polygon::new()
                };
                slot.clone_from(&poly);
                kept.push_back((len, slot));
            }
        }
        if keep == 0 {
            kept.push_back((len, Polygon::new()));
        }
        kept
    }

    /// How far a run from `at` could reach, ignoring integer rounding.
    fn reach(&self, at: At) -> usize {
        if at.done == self.exact.len() {
            return 0;
        }
        self.polygons(at, 0, REACH)
            .back()
            .map_or(0, |(len, _)| *len)
    }

    /// Runs of `len` steps from `at` inside `poly` that keep every edge:
    /// the one ending nearest its exact edge.
    fn runs_of(&self, at: At, len: usize, poly: &Polygon) -> Vec<(LinearRun, i64)> {
        let target = (self.exact[at.done + len - 1] + 0.5) * ONE;
        let (j, c) = (len as f64, (len * (len - 1) / 2) as f64);
        let aim = |add: f64| (target - at.pos as f64 - c * add) / j;
        let mut found: Vec<(LinearRun, i64)> = candidates(poly, aim)
            .into_iter()
            .filter_map(|(interval, add)| {
                let run = LinearRun {
                    count: len as u16,
                    interval: u32::try_from(interval).ok()?,
                    add: i32::try_from(add).ok()?,
                };
                Some((run, self.play(at, interval, add, len)?))
            })
            .collect();
        let miss = |end: i64| libm::fabs(end as f64 - target);
        found.sort_by(|a, b| miss(a.1).total_cmp(&miss(b.1)));
        found.dedup_by_key(|r| r.1);
        found.truncate(1);
        found
    }

    /// The next run from `at`: of the longest runs and a few shorter ones,
    /// the one that takes this run and the next furthest.
    fn next_run(&self, at: At) -> Result<(LinearRun, i64), Error> {
        let kept = self.polygons(at, BACKTRACK, MAX_RUN_STEPS);
        let longest = kept.back().map_or(0, |(len, _)| *len);
        let mut best: Option<(usize, LinearRun, i64)> = None;
        let mut tried = 0;
        for (len, poly) in kept.iter().rev() {
            if !SHORTER.contains(&(longest - len)) && tried > 0 {
                continue;
            }
            for (run, end) in self.runs_of(at, *len, poly) {
                tried += 1;
                let next = At {
                    done: at.done + len,
                    pos: end,
                };
                let score = len + self.reach(next);
                if best.as_ref().is_none_or(|b| score > b.0) {
                    best = Some((score, run, end));
                }
            }
        }
        if let Some((_, run, end)) = best {
            return Ok((run, end));
        }
        // Every kept length failed: one step, as near its edge as can be.
        let (lo, hi) = self.band(at.done);
        let target = ((lo + hi) / 2 - at.pos).max(self.shortest << LinearRun::FRACTION_BITS);
        if let (Some(end), Ok(interval)) = (self.play(at, target, 0, 1), u32::try_from(target)) {
            let run = LinearRun {
                count: 1,
                interval,
                add: 0,
            };
            return Ok((run, end));
        }
        Err(Error::CompressUnreachable {
            step: at.done as u32 + 1,
            tolerance: self.tolerance,
        })
    }
}

/// Checks that `checked`'s table can be compressed with step edges within
/// `tolerance` timer ticks: from half a tick (a whole tick with
/// `ticks_per_step = 2`) to [`MAX_COMPRESS_TICKS`], 16-bit periods.
pub(crate) fn check_compress(checked: &CheckedSpec, tolerance: f64) -> Result<(), Error> {
    let spec = checked.spec();
    let ticks_per_step = spec.timer.ticks_per_step;
    if tolerance.is_nan() || tolerance < MIN_COMPRESS_TICKS * f64::from(ticks_per_step) {
        return Err(Error::CompressTooSmall {
            value: tolerance,
            ticks_per_step,
        });
    }
    if tolerance > MAX_COMPRESS_TICKS {
        return Err(Error::CompressTooLarge { value: tolerance });
    }
    if spec.discretization == Discretization::LeftEndpoint {
        return Err(Error::Unsupported {
            key: Key::DISCRETIZATION,
            value: "left_endpoint",
            applies: "without `compress` (runs follow the curve's own edges: `exact`, or \
                      `index` for the articles' curves over the step index)",
        });
    }
    if spec.rounding != Rounding::Diffuse {
        return Err(Error::Unsupported {
            key: Key::ROUNDING,
            value: spec.rounding.name(),
            applies: "without `compress` (runs place every edge within `compress` ticks)",
        });
    }
    if spec.timer.word != Word::U16 {
        return Err(Error::Unsupported {
            key: Key::WORD,
            value: "u32",
            applies: "without `compress` (a run holds 16-bit periods)",
        });
    }
    Ok(())
}

/// Fits runs to `checked`'s exact edges
/// ([`SpecTables::run_table`](super::computed::SpecTables::run_table)).
pub(crate) fn run_table(checked: &CheckedSpec, tolerance: f64) -> Result<RunTable, Error> {
    check_compress(checked, tolerance)?;
    let spec = checked.spec();
    let scale = spec.timer.frequency_scale();
    let mut exact = Vec::with_capacity(checked.len() as usize);
    checked.for_each_period_and_edge(|_, _, t| exact.push(t * scale))?;
    let repeat = f64::from(spec.timer.ticks_per_step);
    let fit = Fit::new(&exact, tolerance, repeat);
    let mut at = At {
        done: 0,
        pos: LinearRun::START_FRACTION as i64,
    };
    let mut runs = Vec::new();
    while at.done < exact.len() {
        let (run, end) = fit.next_run(at)?;
        runs.push(run.encode());
        at = At {
            done: at.done + run.count as usize,
            pos: end,
        };
    }
    // What the runs store, each played period plus `reload_offset`.
    for (k, period) in Expand::new(&runs).enumerate() {
        Word::U16.stored(period, spec.reload_offset, "step", k as u32)?;
    }
    let figures = CompactFigures::of_runs(&runs, &exact, tolerance, scale, repeat);
    Ok(RunTable {
        spec: *spec,
        runs,
        figures,
    })
}

/// A compressed table with its spec and figures.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub struct RunTable {
    /// What the table was computed from.
    pub spec: Spec,
    /// The runs of the periods, five words each (see [`LinearRun`]), without
    /// `reload_offset`.
    pub runs: Vec<[u16; 5]>,
    /// What the table amounts to.
    pub figures: CompactFigures,
}

impl RunTable {
    /// The runs as the table stores them: each played period plus
    /// [`reload_offset`](Spec::reload_offset) ([`runs::with_offset`]).
    pub fn stored_runs(&self) -> Vec<[u16; 5]> {
        let offset = self.spec.reload_offset;
        self.runs
            .iter()
            .map(|r| runs::with_offset(r, offset))
            .collect()
    }
}
