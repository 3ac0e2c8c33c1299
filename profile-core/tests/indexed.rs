//! Compressed ramps played as their expansion through every call that
//! plans: random runs (runs of no step included), runs that fall as
//! generated ramps do (up to 40, whose steps a plan finds through the
//! index), and random sequences of starts, stops, cruise positions, cruise
//! periods, new targets and steps.
//! The player of the per-step table the runs expand to is the reference
//! here (its moves are checked against the per-step model in `player.rs`
//! and against rules computed from the table alone in `motion.rs`); the
//! players of the runs (`Player::new(&RUNS)`, `Player::new(&RUN_INDEX)`,
//! and `Player::new` of an indexed ramp) must play every period it plays,
//! keep as many steps and take the same new targets, after every call.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256).

use core_test_support as common;

use common::{any_runs, cases, falling_runs, padded};
use profile_core::player::{Player, Ramp};
use profile_core::runs::{Expand, RunIndex};
use proptest::prelude::*;

#[derive(Clone, Debug)]
enum Op {
    Start(u32),
    Stop,
    Cruise(u32),
    CruisePeriod(u16),
    Retarget(u32),
    Play(u32),
}

fn ops() -> impl Strategy<Value = Vec<Op>> {
    let op = prop_oneof![
        3 => (0u32..600).prop_map(Op::Start),
        1 => Just(Op::Stop),
        1 => (0u32..300).prop_map(Op::Cruise),
        2 => prop_oneof![0u16..5000, any::<u16>()].prop_map(Op::CruisePeriod),
        2 => (0u32..800).prop_map(Op::Retarget),
        6 => (0u32..200).prop_map(Op::Play),
    ];
    proptest::collection::vec(op, 1..16)
}

fn check(accel: &[[u16; 5]], decel: &[[u16; 5]], ops: &[Op]) -> Result<u64, TestCaseError> {
    let expand = |runs: &[[u16; 5]]| -> Vec<u16> { Expand::new(runs).map(|p| p as u16).collect() };
    let (a_steps, d_steps) = (expand(accel), expand(decel));
    // Up to 40 runs, padded with runs of no step to 40 for an index.
    let (a_all, d_all) = (padded::<40>(accel), padded::<40>(decel));
    let (a_index, d_index) = (RunIndex::new(&a_all), RunIndex::new(&d_all));
    let mut reference = Player::new(Ramp::steps(&a_steps)).with_decel(Ramp::steps(&d_steps));
    let mut plain = Player::<u16, _>::new(accel).with_decel(decel);
    // One ramp both ways is one index, as `Player::new(&INDEX)` makes it
    // (the planner knows the two ramps for one); else two.
    let (mut indexed, mut any) = if accel == decel {
        (
            Player::<u16, _>::new(&a_index),
            Player::new(Ramp::indexed(&a_index)),
        )
    } else {
        (
            Player::<u16, _>::new(&a_index).with_decel(&d_index),
            Player::new(Ramp::indexed(&a_index)).with_decel(Ramp::indexed(&d_index)),
        )
    };
    let mut steps = 0u64;
    for (i, op) in ops.iter().enumerate() {
        match *op {
            Op::Start(n) => {
                reference.start(n);
                plain.start(n);
                indexed.start(n);
                any.start(n);
            }
            Op::Stop => {
                reference.stop();
                plain.stop();
                indexed.stop();
                any.stop();
            }
            Op::Cruise(pos) => {
                reference.set_cruise(pos);
                plain.set_cruise(pos);
                indexed.set_cruise(pos);
                any.set_cruise(pos);
            }
            Op::CruisePeriod(p) => {
                reference.set_cruise_period(p);
                plain.set_cruise_period(p);
                indexed.set_cruise_period(p);
                any.set_cruise_period(p);
            }
            Op::Retarget(n) => {
                let want = reference.retarget(n);
                let got = [plain.retarget(n), indexed.retarget(n), any.retarget(n)];
                prop_assert_eq!(got, [want; 3], "op {} ({:?}): taken", i, op);
            }
            Op::Play(n) => {
                for k in 0..n {
                    let want = reference.next_period();
                    let got = [
                        plain.next_period(),
                        indexed.next_period(),
                        any.next_period(),
                    ];
                    prop_assert_eq!(got, [want; 3], "op {} ({:?}), step {}", i, op, k);
                    steps += 1;
                    if want.is_none() {
                        break;
                    }
                }
            }
        }
        let want = reference.remaining();
        let got = [plain.remaining(), indexed.remaining(), any.remaining()];
        prop_assert_eq!(got, [want; 3], "after op {} ({:?})", i, op);
    }
    Ok(steps)
}

/// Every call that plans, on runs plain and indexed, plays what the
/// per-step player plays on their expansion.
#[test]
fn runs_plain_and_indexed_play_as_their_expansion() {
    use proptest::test_runner::{Config, TestRunner};
    let mut runner = TestRunner::new(Config {
        cases: cases() * 4,
        failure_persistence: None,
        ..Config::default()
    });
    let steps = std::cell::Cell::new(0u64);
    // Any runs, or runs that fall as generated ramps do (a plan finds their
    // steps through the index), by up to a tick a step or by little.
    let runs = || {
        prop_oneof![
            2 => any_runs(),
            1 => falling_runs(1 << 16),
            1 => falling_runs(1 << 10),
        ]
    };
    let ramps = (runs(), prop_oneof![Just(None), runs().prop_map(Some)]);
    runner
        .run(&(ramps, ops()), |((accel, decel), ops)| {
            let decel = decel.unwrap_or_else(|| accel.clone());
            steps.set(steps.get() + check(&accel, &decel, &ops)?);
            Ok(())
        })
        .unwrap();
    println!(
        "runs plain and indexed == their expansion: {} random sequences, {} steps compared",
        cases() * 4,
        steps.get()
    );
}
