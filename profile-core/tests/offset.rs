//! A player of tables that hold register values (each period plus a
//! `reload_offset`) plays the same moves as a player of the periods, each
//! value the period plus the offset: over random tables (per-step, held,
//! segments, compressed runs stored with `runs::with_offset`), random
//! offsets and random starts, stops, cruise changes, steps and fills.
//!
//! `PROPTEST_CASES` sets the number of operation sequences (default 256,
//! times 4 here).

use core_test_support as common;

use common::{Shape, cases};
use profile_core::player::{Compressed, Player, Ramp};
use profile_core::runs::{Expand, LinearRun as RunWords, with_offset};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};

/// Periods from `low`: falling with ties, or arbitrary.
fn table(low: u32) -> impl Strategy<Value = Vec<u32>> {
    prop_oneof![
        3 => (1usize..150, low + 1..6000).prop_flat_map(move |(len, start)| {
            proptest::collection::vec(0u32..4, len).prop_map(move |drops| {
                let mut p = start;
                drops.iter().map(|d| { let v = p; p = p.saturating_sub(*d).max(low); v }).collect()
            })
        }),
        1 => proptest::collection::vec(low..low + 400, 1..150),
    ]
}

/// Runs whose every period is at least `low` ticks.
fn runs(low: u32) -> impl Strategy<Value = Vec<[u16; 5]>> {
    let run = (0u16..40, low..3000, 0u32..65_536, -300_000i32..300_000);
    proptest::collection::vec(run, 1..10)
        .prop_map(|raw| {
            raw.into_iter()
                .map(|(count, ticks, frac, add)| {
                    let interval = (ticks << 16) | frac;
                    let end = i64::from(interval) + i64::from(count) * i64::from(add);
                    let add = if end >= i64::from(ticks.max(2)) << 16 && end < 4000 << 16 {
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
                .collect::<Vec<_>>()
        })
        .prop_filter("every period at least `low`", move |r| {
            Expand::new(r).all(|p| p >= low)
        })
}

#[derive(Clone, Debug)]
enum Op {
    Start(u32),
    Steps(u32),
    Fill(usize),
    Stop,
    Cruise(u32),
}

fn ops() -> impl Strategy<Value = Vec<Op>> {
    let op = prop_oneof![
        2 => (0u32..1200).prop_map(Op::Start),
        4 => (0u32..300).prop_map(Op::Steps),
        3 => (0usize..200).prop_map(Op::Fill),
        2 => Just(Op::Stop),
        2 => (0u32..200).prop_map(Op::Cruise),
    ];
    proptest::collection::vec(op, 1..14)
}

/// Plays `ops` on a player of the periods and one of the stored values:
/// every value is the period plus `offset`, the steps left the same.
fn compare<L: profile_core::player::Layout>(
    periods: &mut Player<'_, u16, L>,
    stored: &mut Player<'_, u16, L>,
    offset: i32,
    ops: &[Op],
) -> Result<(), TestCaseError> {
    let plus = |p: u16| (i32::from(p) + offset) as u16;
    for (i, op) in ops.iter().enumerate() {
        match *op {
            Op::Start(n) => {
                periods.start(n);
                stored.start(n);
            }
            Op::Stop => {
                periods.stop();
                stored.stop();
            }
            Op::Cruise(pos) => {
                periods.set_cruise(pos);
                stored.set_cruise(pos);
            }
            Op::Steps(n) => {
                for k in 0..n {
                    let (p, s) = (periods.next_period(), stored.next_period());
                    prop_assert_eq!(p.map(plus), s, "op {} ({:?}), step {}", i, op, k);
                    if p.is_none() {
                        break;
                    }
                }
            }
            Op::Fill(size) => {
                let (mut a, mut b) = (vec![0u16; size], vec![0u16; size]);
                let (n, m) = (periods.fill(&mut a), stored.fill(&mut b));
                prop_assert_eq!(n, m, "op {}", i);
                let want: Vec<u16> = a[..n].iter().map(|&p| plus(p)).collect();
                prop_assert_eq!(&b[..m], &want[..], "op {} ({:?})", i, op);
            }
        }
        prop_assert_eq!(periods.remaining(), stored.remaining(), "after op {}", i);
    }
    Ok(())
}

#[test]
fn tables_of_register_values_play_as_their_periods() {
    // The offset, and a shape whose every period leaves a stored value of
    // at least 1 with it.
    let case = prop_oneof![Just(-1i32), Just(-2), Just(1), Just(3)].prop_flat_map(|offset| {
        let low = (1 - offset).max(1) as u32;
        let shape = prop_oneof![
            3 => (table(low), prop_oneof![3 => Just(1u32), 1 => 2u32..5])
                .prop_map(|(t, hold)| Shape::Steps(t, hold)),
            1 => (table(low), proptest::collection::vec(0u32..20, 150)).prop_map(|(t, c)| {
                Shape::Segments(t.iter().zip(c).map(|(&p, c)| (p, c)).collect())
            }),
            2 => runs(low).prop_map(Shape::Runs),
        ];
        (Just(offset), shape, ops())
    });
    let mut runner = TestRunner::new(Config {
        cases: cases() * 4,
        failure_persistence: None,
        ..Config::default()
    });
    runner
        .run(&case, |(offset, shape, ops)| {
            let add = |p: u32| (p as i64 + i64::from(offset)) as u16;
            match &shape {
                Shape::Steps(t, hold) => {
                    let periods: Vec<u16> = t.iter().map(|&p| p as u16).collect();
                    let stored: Vec<u16> = t.iter().map(|&p| add(p)).collect();
                    let mut a = Player::new(Ramp::held(&periods, *hold));
                    let mut b = Player::new(Ramp::held(&stored, *hold));
                    compare(&mut a, &mut b, offset, &ops)
                }
                Shape::Segments(t) => {
                    let periods: Vec<(u16, u16)> =
                        t.iter().map(|&(p, c)| (p as u16, c as u16)).collect();
                    let stored: Vec<(u16, u16)> =
                        t.iter().map(|&(p, c)| (add(p), c as u16)).collect();
                    let mut a = Player::new(Ramp::segments(&periods));
                    let mut b = Player::new(Ramp::segments(&stored));
                    compare(&mut a, &mut b, offset, &ops)
                }
                Shape::Runs(r) => {
                    let stored: Vec<[u16; 5]> = r.iter().map(|w| with_offset(w, offset)).collect();
                    let mut a = Player::new(Ramp::runs(r));
                    let mut b = Player::new(Ramp::runs(&stored));
                    compare(&mut a, &mut b, offset, &ops)?;
                    let mut a = Player::<u16, Compressed>::new(&r[..]);
                    let mut b = Player::<u16, Compressed>::new(&stored[..]);
                    compare(&mut a, &mut b, offset, &ops)
                }
            }
        })
        .unwrap_or_else(|e| panic!("{e}"));
}
