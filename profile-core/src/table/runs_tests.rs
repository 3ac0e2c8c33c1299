//! Tests of the runs, their expansion and their index ([`RunIndex`]).

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
    // The buckets, the slack, the shortest period and the fall: 304 bytes.
    assert_eq!(core::mem::size_of::<RunIndex<4>>(), 4 * 16 + 304);
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

/// Each bucket's period is the one its first step plays (0 past the
/// table), and every step's period is within the bounds the buckets
/// give with the table's slack (the most a step is longer than the
/// shortest before it), each computed here from the expansion: on
/// tables of 1 to 120 runs of 0 to 299 steps, rising, falling or
/// holding, a few ticks to thousands.
#[test]
fn each_steps_period_is_within_its_buckets_bounds() {
    fn check<const N: usize>(runs: &[[u16; 5]; N]) -> usize {
        let index = RunIndex::new(runs);
        let buckets = index.indexed().buckets();
        let steps: std::vec::Vec<u32> = Expand::new(runs).collect();
        let mut slack = 0;
        for (i, &p) in steps.iter().enumerate() {
            let shortest = steps[..i].iter().copied().min().unwrap_or(u32::MAX);
            slack = slack.max(p.saturating_sub(shortest));
        }
        // The slack and the fall the index computed at compile time: the
        // slack computed here, the fall as a player computes it for two
        // ramps, read off the expansion.
        assert_eq!(buckets.slack, slack);
        assert_eq!(buckets.fastest, steps.iter().copied().min().unwrap_or(0));
        let (one, other) = (Expand::new(runs), Expand::new(runs));
        let fall = super::super::fall::Fall::of(one, other, steps.len() as u32, slack);
        assert_eq!(buckets.fall, fall);
        for (b, &period) in buckets.period.iter().enumerate() {
            let first = (b as u32) << buckets.shift;
            let want = steps.get(first as usize).map_or(0, |&p| p.min(65_535));
            assert_eq!(u32::from(period), want, "bucket {b}");
        }
        let mut shown = 0;
        for (pos, &p) in steps.iter().enumerate() {
            let pos = pos as u32;
            if let Some(most) = buckets.at_most(pos, slack) {
                assert!(p <= most, "{pos}: {p} above {most}");
            }
            let least = buckets.at_least(pos, slack);
            assert!(p >= least, "{pos}: {p} below {least}");
            shown += usize::from(least > 0);
        }
        shown
    }
    let mut seed = 0x9e37_79b9_u32;
    let mut next = move |n: u32| {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed % n
    };
    let mut shown = 0;
    for _ in 0..40 {
        let start = 20 + next(3000);
        let slope = next(3) as i32 - 1;
        let mut ticks = start as i32;
        let runs: [[u16; 5]; 120] = core::array::from_fn(|_| {
            let count = if next(5) == 0 { 0 } else { next(300) };
            // Each run's intervals from about `ticks`, changing by a
            // few 1/65 536 ticks a step, rising, falling or holding.
            let add = slope * next(40) as i32;
            let run = LinearRun {
                count: count as u16,
                interval: ((ticks.max(2) as u32) << 16) | next(65_536),
                add,
            };
            ticks += (add * count as i32) >> 16;
            run.encode()
        });
        shown += check(&runs);
        shown += check(&[runs[0]]);
    }
    // The lower bounds say something on most steps.
    assert!(shown > 40 * 120 * 50, "{shown}");
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
