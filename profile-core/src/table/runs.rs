//! The compressed layout: a ramp as runs of steps whose period changes by a
//! constant amount, in fixed point, each pulse edge within a chosen number
//! of ticks of the curve.
//!
//! A run is five `u16` words, `[count, interval_hi, interval_lo, add_hi,
//! add_lo]`: `interval` is the run's first period and `add` what each step
//! adds to it, both in ticks with [`LinearRun::FRACTION_BITS`] fractional bits
//! (`add` in two's complement). Played, a run keeps the sub-tick remainder
//! of the edges so that rounding never accumulates:
//!
//! ```text
//! x = frac + interval;  period = x >> 16;  frac = x & 0xFFFF;  interval += add
//! ```
//!
//! with `frac` starting at [`LinearRun::START_FRACTION`] (half a tick: the edges are
//! rounded, not truncated) and carried from run to run. [`Expand`] is that
//! loop; the player, the C function and every check use it.

use super::fall::Fall;

/// Fractional bits of a run's `interval` and `add`
/// ([`LinearRun::FRACTION_BITS`]).
pub(crate) const RUN_FRACTION_BITS: u32 = 16;

/// The sub-tick remainder before the first step: half a tick
/// ([`LinearRun::START_FRACTION`]).
pub(crate) const RUN_START_FRACTION: u32 = 1 << (RUN_FRACTION_BITS - 1);

pub(crate) const FRACTION_MASK: u32 = (1 << RUN_FRACTION_BITS) - 1;

/// One run, decoded: steps whose period changes by the same amount each
/// step (linearly); its step count, first period and per-step change, in ticks
/// scaled by `2^RUN_FRACTION_BITS`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LinearRun {
    /// Steps in the run, at least 1.
    pub count: u16,
    /// The first step's period, in 1/65 536 ticks.
    pub interval: u32,
    /// Added to the period after each step, in 1/65 536 ticks.
    pub add: i32,
}

impl LinearRun {
    /// Fractional bits of a run's `interval` and `add`: they count
    /// 1/65 536 ticks.
    pub const FRACTION_BITS: u32 = RUN_FRACTION_BITS;

    /// The sub-tick remainder the first run starts from: half a tick, so
    /// that the edges are the curve's rounded to the nearest tick.
    pub const START_FRACTION: u32 = RUN_START_FRACTION;

    /// The run's five words, as tables store them.
    pub const fn encode(&self) -> [u16; 5] {
        let add = self.add as u32;
        [
            self.count,
            (self.interval >> 16) as u16,
            self.interval as u16,
            (add >> 16) as u16,
            add as u16,
        ]
    }

    /// The run stored as `words`.
    pub const fn decode(words: &[u16; 5]) -> Self {
        LinearRun {
            count: words[0],
            interval: ((words[1] as u32) << 16) | words[2] as u32,
            add: (((words[3] as u32) << 16) | words[4] as u32) as i32,
        }
    }
}

/// The periods a run table plays, one per step, in ticks.
///
/// Wrapping arithmetic, as on the target: a table built by this crate never
/// wraps (every run is played through this iterator and checked when the
/// table is made).
#[derive(Clone, Debug)]
pub struct Expand<'a> {
    runs: &'a [[u16; 5]],
    left: u16,
    interval: u32,
    add: u32,
    frac: u32,
}

impl<'a> Expand<'a> {
    /// The periods of `runs`, from the first step.
    pub const fn new(runs: &'a [[u16; 5]]) -> Self {
        Expand {
            runs,
            left: 0,
            interval: 0,
            add: 0,
            frac: RUN_START_FRACTION,
        }
    }
}

impl Iterator for Expand<'_> {
    type Item = u32;

    fn next(&mut self) -> Option<u32> {
        while self.left == 0 {
            let (first, rest) = self.runs.split_first()?;
            let run = LinearRun::decode(first);
            self.runs = rest;
            self.left = run.count;
            self.interval = run.interval;
            self.add = run.add as u32;
        }
        self.left -= 1;
        let x = self.frac.wrapping_add(self.interval);
        self.frac = x & FRACTION_MASK;
        self.interval = self.interval.wrapping_add(self.add);
        Some(x >> RUN_FRACTION_BITS)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let steps = self.left as usize + self.runs.iter().map(|r| r[0] as usize).sum::<usize>();
        (steps, Some(steps))
    }
}

/// The period of a run's step, in ticks: `(frac + interval) >> 16`, from
/// the remainder before it and its interval.
#[inline(always)]
pub(crate) const fn period(frac: u32, interval: u32) -> u32 {
    frac.wrapping_add(interval) >> RUN_FRACTION_BITS
}

/// `n (n - 1) / 2`, exact for any `n` up to 65 536 (a run's count is at
/// most 65 535), in 32-bit arithmetic.
pub(crate) const fn triangle(n: u32) -> u32 {
    n.wrapping_mul(n.saturating_sub(1)) >> 1
}

/// A run's state `(frac, interval)` `n` steps later: the remainder after
/// `n` more steps and the period of the step after them, in closed form.
pub(crate) const fn ahead(frac: u32, interval: u32, add: u32, n: u32) -> (u32, u32) {
    let frac = frac
        .wrapping_add(n.wrapping_mul(interval))
        .wrapping_add(triangle(n).wrapping_mul(add));
    (
        frac & FRACTION_MASK,
        interval.wrapping_add(n.wrapping_mul(add)),
    )
}

/// A run's state `(frac, interval)` `n` steps earlier.
pub(crate) const fn behind(frac: u32, interval: u32, add: u32, n: u32) -> (u32, u32) {
    let start = interval.wrapping_sub(n.wrapping_mul(add));
    let frac = frac
        .wrapping_sub(n.wrapping_mul(start))
        .wrapping_sub(triangle(n).wrapping_mul(add));
    (frac & FRACTION_MASK, start)
}

/// A run of an indexed table ([`RunIndex`]): its five words, its first step
/// along the table (the counts of the runs before it added) and the
/// edges' sub-tick remainder carried into it from every run before. 16
/// bytes, where a run alone is 10.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndexedRun {
    pub(crate) step: u32,
    pub(crate) words: [u16; 5],
    pub(crate) frac: u16,
}

impl IndexedRun {
    /// The run's five words, as [`LinearRun::encode`] gives them.
    pub const fn words(&self) -> &[u16; 5] {
        &self.words
    }

    /// The run's first step along the table (0 = the slowest).
    pub const fn step(&self) -> u32 {
        self.step
    }

    /// The remainder before that step, in 1/65 536 ticks.
    pub const fn frac(&self) -> u16 {
        self.frac
    }
}

/// A compressed table with where each of its runs begins, computed at
/// compile time: with it the player finds any step of the table without
/// carrying a step's remainder through every run before it, as it must
/// without. A step's run is looked up in a table of 64 buckets of steps
/// (the run holding each bucket's first step), then found by bisection
/// among the runs that bucket spans: a few probes where runs are long, a
/// full bisection's only where many runs share a bucket. On a ramp of 97
/// runs a new cruise speed or a new target takes 7 to 13 % of the
/// instructions it takes without, a stop 15 %, a start 78 % (measured on
/// a Cortex-M3: [the
/// measurements](https://github.com/stepper-profiles/stepper-profiles/blob/main/docs/performance.md)).
/// 16 bytes of flash a run, and 304 for the buckets (the run and the
/// period at each bucket's first step, so that two steps far apart are
/// often told apart in speed without reading either, and the ramp's
/// slack, its shortest period and how far ahead of itself it is faster
/// at every step, so that a player made on the index reads none of its
/// steps): the
/// runs' own words are copied in, so that a firmware that plays the index
/// alone keeps no other copy of them.
///
/// ```
/// use profile_core::player::Player;
/// use profile_core::runs::RunIndex;
///
/// static RUNS: [[u16; 5]; 2] = [[3, 4000, 0x8000, 0xFE0C, 0], [2, 2000, 0, 0, 0]];
/// static INDEX: RunIndex<2> = RunIndex::new(&RUNS);
/// let mut player = Player::<u16, _>::new(&INDEX);
/// player.start(5);
/// assert_eq!(player.next_period(), Some(4001));
/// assert_eq!(INDEX.runs()[1].step(), 3);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct RunIndex<const N: usize> {
    runs: [IndexedRun; N],
    buckets: Buckets,
}

/// Buckets in a [`RunIndex`]'s lookup by step.
pub(crate) const BUCKETS: usize = 64;

/// A [`RunIndex`]'s lookup by step: the steps cut into [`BUCKETS`]
/// buckets of `1 << shift` steps, the fewest that cover the table, and
/// for each the run holding its first step (the last that begins at or
/// before it), saturated at `u16::MAX` (from there on the runs are
/// bisected to the last), and that step's period; and what planning
/// knows of the ramp as a whole, computed with them so that a player
/// made on the index reads no step to know it: its slack, its shortest
/// period and how far ahead of itself it is faster at every step.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Buckets {
    pub(crate) shift: u32,
    pub(crate) first: [u16; BUCKETS],
    /// The period of each bucket's first step, in ticks: `u16::MAX` when
    /// it is that or more, 0 for a bucket past the table's last step.
    pub(crate) period: [u16; BUCKETS],
    /// The most a step's period exceeds the shortest before it, in ticks.
    pub(crate) slack: u32,
    /// The shortest period, in ticks (0 without a step).
    pub(crate) fastest: u32,
    /// How far ahead of itself the ramp is faster at every step, read
    /// both ways ([`Fall`]).
    pub(crate) fall: Fall,
}

impl Buckets {
    /// The buckets of `runs` (each with its first step, ascending),
    /// `total` steps in all.
    const fn new(runs: &[IndexedRun], total: u32) -> Self {
        let mut shift = 0;
        while shift < 31 && (total.saturating_sub(1) >> shift) as usize >= BUCKETS {
            shift += 1;
        }
        let mut first = [0u16; BUCKETS];
        let mut period = [0u16; BUCKETS];
        let (mut b, mut i) = (0, 0usize);
        while b < BUCKETS {
            // `b << shift` fits: `shift` is at most 26 for any `total`.
            let step = (b as u32) << shift;
            while i + 1 < runs.len() && runs[i + 1].step <= step {
                i += 1;
            }
            first[b] = if i > u16::MAX as usize {
                u16::MAX
            } else {
                i as u16
            };
            if i < runs.len() && step < total {
                let run = &runs[i];
                let decoded = LinearRun::decode(&run.words);
                let within = step - run.step;
                let (frac, interval) = ahead(
                    run.frac as u32,
                    decoded.interval,
                    decoded.add as u32,
                    within,
                );
                let ticks = self::period(frac, interval);
                period[b] = if ticks > u16::MAX as u32 {
                    u16::MAX
                } else {
                    ticks as u16
                };
            }
            b += 1;
        }
        let (slack, fastest) = slack(runs);
        Buckets {
            shift,
            first,
            period,
            slack,
            fastest,
            fall: fall(runs, total, slack),
        }
    }

    /// A bucket past whose first step no step up to `top` is `ticks` long,
    /// `slack` the ramp's: that step past `top`, or its period more than
    /// `slack` short of `ticks` (every later step is at most that much
    /// longer). Bisected over the buckets, so that the one found has
    /// either no bucket before it or one that is not such a bucket: its
    /// first step, the run holding the bucket before's first step (0 for
    /// the first bucket) and the run holding its own. `None` when no
    /// bucket is found such, or the run's number does not fit the
    /// buckets' `u16`.
    pub(crate) fn first_short(
        &self,
        top: u32,
        ticks: u32,
        slack: u32,
    ) -> Option<(u32, usize, usize)> {
        // Short: a period below `ticks - slack` (a saturated one never is),
        // or a bucket from `end` on, which begins past `top`.
        let limit = ticks.saturating_sub(slack).min(u32::from(u16::MAX));
        let end = ((top >> self.shift) as usize)
            .saturating_add(1)
            .min(BUCKETS);
        let (mut lo, mut hi) = (0, end);
        while lo < hi {
            let mid = lo + (hi - lo) / 2;
            if self.period.get(mid).is_some_and(|&p| u32::from(p) < limit) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        let before = lo.checked_sub(1).and_then(|b| self.first.get(b)).copied();
        match self.first.get(lo) {
            Some(&run) if run < u16::MAX => Some((
                (lo as u32) << self.shift,
                usize::from(before.unwrap_or(0)),
                usize::from(run),
            )),
            _ => None,
        }
    }

    /// A bound on the period of step `pos` from above, `slack` the
    /// ramp's ([`search::slack`](crate::player)): its bucket's first
    /// step's period and the slack (a later step is at most that much
    /// longer); `None` when that period does not fit.
    #[inline(always)]
    pub(crate) fn at_most(&self, pos: u32, slack: u32) -> Option<u32> {
        let b = ((pos >> self.shift) as usize).min(BUCKETS - 1);
        match self.period.get(b) {
            Some(&p) if p < u16::MAX => Some(u32::from(p).saturating_add(slack)),
            _ => None,
        }
    }

    /// A bound on the period of step `pos` from below: the next bucket's
    /// first step's period less the slack (an earlier step is at most
    /// that much shorter); 0 in the last bucket or the one before a
    /// bucket past the table.
    #[inline(always)]
    pub(crate) fn at_least(&self, pos: u32, slack: u32) -> u32 {
        let b = (pos >> self.shift) as usize;
        self.period
            .get(b + 1)
            .map_or(0, |&p| u32::from(p).saturating_sub(slack))
    }

    /// The runs among which the one holding step `pos` is, of `len`: from
    /// the bucket's first to the next bucket's first, inclusive.
    #[inline(always)]
    pub(crate) fn span(&self, pos: u32, len: usize) -> (usize, usize) {
        let b = ((pos >> self.shift) as usize).min(BUCKETS - 1);
        let lo = self.first.get(b).map_or(0, |&f| usize::from(f));
        let hi = match self.first.get(b + 1) {
            Some(&f) if f < u16::MAX => usize::from(f) + 1,
            _ => len,
        };
        (lo, hi.min(len))
    }
}

/// The periods of indexed runs, step by step, each run played from its
/// own remainder as the index gives it (not carried from the run before,
/// as [`Expand`] carries it): the run being played and the runs after
/// it. Read in `const` code by [`IndexedSteps::step`], and as an
/// iterator.
#[derive(Clone, Debug)]
pub(crate) struct IndexedSteps<'a> {
    runs: &'a [IndexedRun],
    /// The next run to play.
    next: usize,
    left: u32,
    frac: u32,
    interval: u32,
    add: u32,
}

impl<'a> IndexedSteps<'a> {
    pub(crate) const fn new(runs: &'a [IndexedRun]) -> Self {
        IndexedSteps {
            runs,
            next: 0,
            left: 0,
            frac: 0,
            interval: 0,
            add: 0,
        }
    }

    /// The next step's period, in ticks; `None` past the last run.
    pub(crate) const fn step(&mut self) -> Option<u32> {
        while self.left == 0 {
            if self.next >= self.runs.len() {
                return None;
            }
            let run = &self.runs[self.next];
            let decoded = LinearRun::decode(&run.words);
            self.left = decoded.count as u32;
            self.frac = run.frac as u32;
            self.interval = decoded.interval;
            self.add = decoded.add as u32;
            self.next += 1;
        }
        self.left -= 1;
        let x = self.frac.wrapping_add(self.interval);
        self.frac = x & FRACTION_MASK;
        self.interval = self.interval.wrapping_add(self.add);
        Some(x >> RUN_FRACTION_BITS)
    }
}

impl Iterator for IndexedSteps<'_> {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        self.step()
    }
}

/// The most a step's period of `runs` exceeds the shortest before it,
/// and the shortest (0 without a step).
const fn slack(runs: &[IndexedRun]) -> (u32, u32) {
    let mut steps = IndexedSteps::new(runs);
    let (mut fastest, mut rise) = (u32::MAX, 0u32);
    while let Some(p) = steps.step() {
        if p.saturating_sub(fastest) > rise {
            rise = p.saturating_sub(fastest);
        }
        if p < fastest {
            fastest = p;
        }
    }
    (rise, if fastest == u32::MAX { 0 } else { fastest })
}

/// [`Fall::of`] the ramp of `runs` (`total` steps, `slack` its slack)
/// read both ways, in `const` code.
const fn fall(runs: &[IndexedRun], total: u32, slack: u32) -> Fall {
    let mut fall = Fall::empty(total);
    let (mut accel, mut decel) = (IndexedSteps::new(runs), IndexedSteps::new(runs));
    let mut fastest = u32::MAX;
    let (mut t, mut at_t) = (0u32, decel.step());
    let mut y = 0u32;
    while let Some(p) = accel.step() {
        if p < fastest {
            fastest = p;
        }
        while let Some(d) = at_t {
            if d.saturating_add(slack) < fastest {
                break;
            }
            t += 1;
            at_t = decel.step();
        }
        fall.take(y, t.saturating_sub(y));
        y += 1;
    }
    fall
}

impl<const N: usize> RunIndex<N> {
    /// The index of `runs`, in a `const` or a `static`.
    pub const fn new(runs: &[[u16; 5]; N]) -> Self {
        let mut indexed = [IndexedRun {
            step: 0,
            words: [0; 5],
            frac: 0,
        }; N];
        let (mut step, mut frac) = (0u32, RUN_START_FRACTION);
        let mut i = 0;
        while i < N {
            indexed[i] = IndexedRun {
                step,
                words: runs[i],
                frac: frac as u16,
            };
            let run = LinearRun::decode(&runs[i]);
            let count = run.count as u32;
            frac = ahead(frac, run.interval, run.add as u32, count).0;
            step = step.saturating_add(count);
            i += 1;
        }
        let buckets = Buckets::new(&indexed, step);
        RunIndex {
            runs: indexed,
            buckets,
        }
    }

    /// The runs, each with where it begins.
    pub const fn runs(&self) -> &[IndexedRun; N] {
        &self.runs
    }

    /// The runs, whatever their number, for a
    /// [`Ramp`](crate::player::Ramp).
    pub const fn indexed(&self) -> IndexedRuns<'_> {
        IndexedRuns {
            runs: &self.runs,
            buckets: &self.buckets,
        }
    }
}

/// The runs of a [`RunIndex`], whatever their number, and its lookup by
/// step: what [`Ramp::Indexed`](crate::player::Ramp::Indexed) holds. Made
/// only from a `RunIndex`, so that each run's start is that of the runs
/// before it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndexedRuns<'a> {
    runs: &'a [IndexedRun],
    buckets: &'a Buckets,
}

impl<'a> IndexedRuns<'a> {
    /// The runs, each with where it begins.
    pub const fn runs(&self) -> &'a [IndexedRun] {
        self.runs
    }

    /// The lookup by step.
    pub(crate) const fn buckets(&self) -> &'a Buckets {
        self.buckets
    }
}

/// `words` with every period it plays `offset` ticks longer (shorter when
/// negative): `offset * 2^16` added to its `interval`, which moves every
/// `x = frac + interval` by whole ticks and leaves the edges' sub-tick
/// remainder, and so every later run, as it was. How a compressed table
/// stores `reload_offset`: [`Expand`], the player (either way along the
/// ramp) and the C player then play each period plus `offset`, where every
/// such value is from 1 to 65 535 (checked when a table is made).
pub const fn with_offset(words: &[u16; 5], offset: i32) -> [u16; 5] {
    let run = LinearRun::decode(words);
    LinearRun {
        interval: run
            .interval
            .wrapping_add((offset as u32) << RUN_FRACTION_BITS),
        ..run
    }
    .encode()
}

/// Steps in a run table: the sum of its counts.
pub fn run_steps(runs: &[[u16; 5]]) -> u32 {
    runs.iter().map(|r| r[0] as u32).sum()
}

#[cfg(test)]
#[path = "runs_tests.rs"]
mod tests;
