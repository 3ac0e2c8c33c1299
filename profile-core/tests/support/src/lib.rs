//! Support shared by `profile-core`'s player tests: a crate of its own,
//! compiled once and linked into every test that says `use
//! core_test_support as common;` (not published):
//!
//! - [`reference`](mod@reference): the unplanned reference model of the player;
//! - [`watch`]: an axis's motion checked step by step (positions, no jumps,
//!   reversals at rest);
//! - [`cases`]: the number of random cases per property (`PROPTEST_CASES`);
//! - [`any_table`] and [`any_runs`]: random per-step tables and compressed
//!   runs; [`falling`]: random tables ordered slow to fast, as generated;
//! - [`Shape`] and [`shape`]: a ramp of any kind (per-step and held,
//!   segments, runs) described for a test to build;
//! - [`Event`] and [`events`]: stops and cruise changes at random points of
//!   a move.

pub mod reference;
pub mod watch;

use core::ops::Range;
use profile_core::runs::LinearRun as RunWords;
use proptest::prelude::*;

/// `PROPTEST_CASES`, or 256.
pub fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(256)
}

/// A table of any shape, up to `max_len` entries: falling with ties (as
/// generated), arbitrary, or tiny.
pub fn any_table(max_len: usize) -> impl Strategy<Value = Vec<u32>> {
    prop_oneof![
        3 => (1usize..max_len, 2u32..5000).prop_flat_map(|(len, start)| {
            proptest::collection::vec(0u32..3, len).prop_map(move |drops| {
                let mut p = start;
                drops.iter().map(|d| { let v = p; p = p.saturating_sub(*d).max(1); v }).collect()
            })
        }),
        1 => proptest::collection::vec(1u32..400, 1..max_len),
        1 => proptest::collection::vec(1u32..4, 1..4),
    ]
}

/// Random compressed runs (empty ones included), each run's last period
/// between 1 and 4000 ticks or its increment dropped.
pub fn any_runs() -> impl Strategy<Value = Vec<[u16; 5]>> {
    let run = (0u16..40, 1u32..3000, 0u32..65_536, -400_000i32..400_000);
    proptest::collection::vec(run, 1..12).prop_map(|raw| {
        raw.into_iter()
            .map(|(count, ticks, frac, add)| {
                let interval = (ticks << 16) | frac;
                let end = i64::from(interval) + (i64::from(count.max(1)) - 1) * i64::from(add);
                let add = if (1 << 16..4000 << 16).contains(&end) {
                    add
                } else {
                    0
                };
                RunWords {
                    count,
                    interval,
                    add,
                }
                .encode()
            })
            .collect()
    })
}

/// `runs` padded with runs of no step to `N`, for a
/// [`RunIndex`](profile_core::runs::RunIndex) of a fixed length (at most
/// `N` runs).
pub fn padded<const N: usize>(runs: &[[u16; 5]]) -> [[u16; 5]; N] {
    let mut all = [[0u16; 5]; N];
    all[..runs.len()].copy_from_slice(runs);
    all
}

/// Compressed runs as generated ramps are: slow to fast, each run going on
/// from where the one before ended (a fraction of a tick lower at most),
/// its periods falling by up to `max_fall` 1/65 536 ticks a step, 8 to 40
/// runs of up to 60 steps (a run of no step now and then), none shorter
/// than a tick: the shape whose runs a plan finds through the index.
pub fn falling_runs(max_fall: i32) -> impl Strategy<Value = Vec<[u16; 5]>> {
    let run = (
        prop_oneof![1 => Just(0u16), 12 => 1u16..60],
        0..=max_fall,
        0u32..65_536,
    );
    (200u32..4000, proptest::collection::vec(run, 8..40)).prop_map(|(start, raw)| {
        let mut interval = i64::from(start) << 16;
        raw.into_iter()
            .map(|(count, fall, jump)| {
                let floor = 1i64 << 16;
                let last = i64::from(count.max(1)) - 1;
                // Falling by `fall` a step while the last step stays a tick.
                let fall = if interval - last * i64::from(fall) >= floor {
                    fall
                } else {
                    0
                };
                let words = RunWords {
                    count,
                    interval: interval as u32,
                    add: -fall,
                }
                .encode();
                interval -= i64::from(count) * i64::from(fall) + i64::from(jump);
                interval = interval.max(floor);
                words
            })
            .collect()
    })
}

/// A table ordered slow to fast, as generated tables are: a length drawn
/// from `len`, a first period from 200 ticks to `u16::MAX`, each next one
/// up to `max_drop` ticks shorter, none below `floor`.
pub fn falling(len: Range<usize>, max_drop: u16, floor: u32) -> impl Strategy<Value = Vec<u16>> {
    (len, 200u16..=u16::MAX).prop_flat_map(move |(len, start)| {
        proptest::collection::vec(0u16..max_drop, len).prop_map(move |drops| {
            let mut p = u32::from(start);
            drops
                .iter()
                .map(|d| {
                    let v = p as u16;
                    p = p.saturating_sub(u32::from(*d)).max(floor);
                    v
                })
                .collect()
        })
    })
}

/// What happens before an edge of a move, by the count of edges handed out
/// so far.
#[derive(Clone, Copy, Debug)]
pub enum Event {
    /// `stop()`.
    Stop,
    /// `set_cruise(position)`.
    Cruise(u32),
}

/// Up to two events, each at a count of edges drawn from `at`, cruise
/// positions from 0 to 79.
pub fn events(at: Range<usize>) -> impl Strategy<Value = Vec<(usize, Event)>> {
    proptest::collection::vec(
        (
            at,
            prop_oneof![Just(Event::Stop), (0u32..80).prop_map(Event::Cruise)],
        ),
        0..3,
    )
}

/// A ramp described for a test to build: a per-step table held `hold`
/// steps per entry, segments with their counts (empty ones included), or
/// compressed runs (empty ones included).
#[derive(Clone, Debug)]
pub enum Shape {
    /// Periods, and the steps each is held.
    Steps(Vec<u32>, u32),
    /// `(period, count)` pairs.
    Segments(Vec<(u32, u32)>),
    /// Encoded runs.
    Runs(Vec<[u16; 5]>),
}

/// Any [`Shape`]: per-step tables of up to `max_len` entries (weight 4,
/// held 1 step or now and then 0 to 5), 12 segments of `0..max_count`
/// steps (weight 1), runs (weight `runs`).
pub fn shape(max_len: usize, max_count: u32, runs: u32) -> impl Strategy<Value = Shape> {
    prop_oneof![
        4 => (any_table(max_len), prop_oneof![4 => Just(1u32), 1 => 0u32..6])
            .prop_map(|(t, hold)| Shape::Steps(t, hold)),
        1 => (any_table(12), proptest::collection::vec(0..max_count, 12)).prop_map(|(t, c)| {
            Shape::Segments(t.iter().zip(c).map(|(&p, c)| (p, c)).collect())
        }),
        runs => any_runs().prop_map(Shape::Runs),
    ]
}

/// A small deterministic generator (xorshift64) for tests that walk many
/// cases without proptest: each call gives a number below `m`.
pub fn xorshift(seed: u64) -> impl FnMut(u64) -> u64 {
    let mut state = seed.max(1);
    move |m: u64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        state % m
    }
}
