//! The compressed layout: a ramp as runs of steps whose period changes by a
//! constant amount, in fixed point, each pulse edge within a chosen number
//! of ticks of the curve.
//!
//! A run is five `u16` words, `[count, interval_hi, interval_lo, add_hi,
//! add_lo]`: `interval` is the run's first period and `add` what each step
//! adds to it, both in ticks with [`RUN_FRACTION_BITS`] fractional bits
//! (`add` in two's complement). Played, a run keeps the sub-tick remainder
//! of the edges so that rounding never accumulates:
//!
//! ```text
//! x = frac + interval;  period = x >> 16;  frac = x & 0xFFFF;  interval += add
//! ```
//!
//! with `frac` starting at [`RUN_START_FRACTION`] (half a tick: the edges are
//! rounded, not truncated) and carried from run to run. [`Expand`] is that
//! loop; the player, the C function and every check use it.

/// Fractional bits of a run's `interval` and `add`.
pub const RUN_FRACTION_BITS: u32 = 16;

/// The sub-tick remainder before the first step: half a tick.
pub const RUN_START_FRACTION: u32 = 1 << (RUN_FRACTION_BITS - 1);

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
/// runs a new cruise speed or a new target takes a tenth to under a fifth
/// of the instructions it takes without, a stop under a fifth, a start
/// 87 % (measured on a Cortex-M3: [the
/// measurements](https://github.com/stepper-profiles/stepper-profiles/blob/main/docs/performance.md)).
/// 16 bytes of flash a run, and 132 for the buckets: the
/// runs' own words are copied in, so that a firmware that plays the index
/// alone keeps no other copy of them.
///
/// ```
/// use profile_core::player::Player;
/// use profile_core::runs::RunIndex;
///
/// static RUNS: [[u16; 5]; 2] = [[3, 4000, 0x8000, 0xFE0C, 0], [2, 2000, 0, 0, 0]];
/// static INDEX: RunIndex<2> = RunIndex::new(&RUNS);
/// let mut player = Player::<u16, _>::compressed_indexed(&INDEX);
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
/// bisected to the last).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Buckets {
    pub(crate) shift: u32,
    pub(crate) first: [u16; BUCKETS],
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
            b += 1;
        }
        Buckets { shift, first }
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
mod tests {
    use super::*;

    #[test]
    fn a_run_encodes_and_decodes() {
        let run = LinearRun {
            count: 300,
            interval: 0x1234_5678,
            add: -70_000,
        };
        assert_eq!(LinearRun::decode(&run.encode()), run);
    }

    #[test]
    fn runs_play_a_quadratic_with_the_remainder_carried() {
        // 2.5 ticks, then 2.75, 3.0: edges at 0.5 + 2.5, + 2.75, + 3.0.
        let runs = [
            LinearRun {
                count: 3,
                interval: 5 << 15,
                add: 1 << 14,
            }
            .encode(),
            LinearRun {
                count: 2,
                interval: 1 << 16,
                add: 0,
            }
            .encode(),
        ];
        let periods: std::vec::Vec<u32> = Expand::new(&runs).collect();
        // Edges: 3.0, 5.75, 8.75, then 9.75, 10.75 (floor: 3, 5, 8, 9, 10).
        assert_eq!(periods, [3, 2, 3, 1, 1]);
        assert_eq!(run_steps(&runs), 5);
        assert_eq!(Expand::new(&runs).size_hint(), (5, Some(5)));
        // Offset, the same edges' remainders: every period one tick less.
        let less: std::vec::Vec<_> = runs.iter().map(|r| with_offset(r, -1)).collect();
        let stored: std::vec::Vec<u32> = Expand::new(&less).collect();
        assert_eq!(stored, [2, 1, 2, 0, 0]);
        let more: std::vec::Vec<_> = runs.iter().map(|r| with_offset(r, 3)).collect();
        assert_eq!(
            Expand::new(&more).collect::<std::vec::Vec<_>>(),
            [6, 5, 6, 4, 4]
        );
    }

    /// Each run's start against the steps added one by one: the step
    /// count before it, and the low 16 bits of the sum, in fixed point, of
    /// the half tick and every interval played before it.
    #[test]
    fn the_index_holds_each_runs_first_step_and_remainder() {
        let runs = [
            [3, 4000, 0x8000, 0xFE0C, 0],
            [0, 0, 0, 0, 0],
            [5, 2000, 0x1234, 0xFFFF, 0xF000],
            [2, 1500, 0x9999, 0, 0x0777],
        ];
        let index = RunIndex::new(&runs);
        let (mut step, mut edge) = (0u32, u64::from(RUN_START_FRACTION));
        for (run, indexed) in runs.iter().zip(index.runs()) {
            assert_eq!(indexed.step(), step);
            assert_eq!(u64::from(indexed.frac()), edge & 0xFFFF);
            assert_eq!(indexed.words(), run);
            let run = LinearRun::decode(run);
            let mut interval = i64::from(run.interval);
            for _ in 0..run.count {
                edge += interval as u64;
                interval += i64::from(run.add);
                step += 1;
            }
        }
        assert_eq!(index.runs()[2].step(), 3);
        assert_eq!(index.indexed().runs().len(), 4);
        assert_eq!(core::mem::size_of::<IndexedRun>(), 16);
        // The buckets: 132 bytes.
        assert_eq!(core::mem::size_of::<RunIndex<4>>(), 4 * 16 + 132);
    }

    /// The run holding each step (the last that begins at or before it,
    /// found by a walk over all the runs) is among those its bucket spans,
    /// on tables of 1 to 200 runs of 0 to 299 steps (runs of no steps
    /// among them), and the buckets are the smallest that cover the table.
    #[test]
    fn each_steps_run_is_among_those_its_bucket_spans() {
        fn check<const N: usize>(runs: &[[u16; 5]; N]) {
            let index = RunIndex::new(runs);
            let total = run_steps(runs);
            let buckets = index.indexed().buckets();
            let last = total.saturating_sub(1);
            assert!((last >> buckets.shift) < BUCKETS as u32, "{total}");
            if buckets.shift > 0 {
                assert!((last >> (buckets.shift - 1)) >= BUCKETS as u32, "{total}");
            }
            for pos in 0..total + 3 {
                let holding = index.runs().iter().rposition(|r| r.step() <= pos).unwrap();
                let (lo, hi) = buckets.span(pos, N);
                assert!(
                    lo <= holding && holding < hi,
                    "{pos}: {holding} in {lo}..{hi}"
                );
            }
        }
        let mut seed = 0x2545_f491_u32;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed
        };
        fn table<const N: usize>(mut count: impl FnMut(usize) -> u16) -> [[u16; 5]; N] {
            core::array::from_fn(|i| [count(i), 100, 0, 0, 0])
        }
        check(&table::<1>(|_| 7));
        check(&table::<1>(|_| 0));
        check(&table::<3>(|i| [0, 64, 0][i]));
        check(&table::<64>(|_| 1));
        check(&table::<65>(|_| 1));
        check(&table::<97>(|i| (i * i / 8) as u16 + 2));
        for _ in 0..20 {
            check(&table::<5>(|_| (next() % 300) as u16));
            check(&table::<200>(|_| match next() % 4 {
                0 => 0,
                _ => (next() % 300) as u16,
            }));
        }
    }

    /// A table of more runs than a bucket's `u16` counts: the buckets
    /// past run 65 535 span every run from there to the last.
    #[test]
    fn buckets_past_run_65535_span_to_the_last() {
        const N: usize = 70_000;
        let worker = std::thread::Builder::new().stack_size(64 << 20);
        let checked = worker.spawn(|| {
            let runs = std::boxed::Box::new([[1u16, 100, 0, 0, 0]; N]);
            let index = std::boxed::Box::new(RunIndex::new(&runs));
            let buckets = index.indexed().buckets();
            for pos in (0..N as u32 + 3).step_by(7) {
                let holding = (pos as usize).min(N - 1);
                let (lo, hi) = buckets.span(pos, N);
                assert!(
                    lo <= holding && holding < hi,
                    "{pos}: {holding} in {lo}..{hi}"
                );
            }
            assert_eq!(buckets.span(N as u32 - 1, N).1, N);
        });
        checked.unwrap().join().unwrap();
    }
}
