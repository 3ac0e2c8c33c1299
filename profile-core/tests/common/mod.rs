//! Support shared by the player's tests, included with `mod common;`:
//!
//! - [`reference`]: the unplanned reference model of the player;
//! - [`cases`]: the number of random cases per property (`PROPTEST_CASES`);
//! - [`any_table`] and [`any_runs`]: random per-step tables and compressed
//!   runs.
//!
//! Every test crate that says `mod common;` compiles all of it but uses only
//! part, hence the `dead_code` allowances.

#[allow(dead_code)]
pub mod reference;

use profile_core::runs::LinearRun as RunWords;
use proptest::prelude::*;

/// `PROPTEST_CASES`, or 256.
#[allow(dead_code)]
pub fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(256)
}

/// A table of any shape, up to `max_len` entries: falling with ties (as
/// generated), arbitrary, or tiny.
#[allow(dead_code)]
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
#[allow(dead_code)]
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
