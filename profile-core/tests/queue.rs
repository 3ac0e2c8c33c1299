//! Moves queued on an axis ([`Axis::queue`]) over random tables and random
//! queues, checked against a model of the rules computed here:
//!
//! - the motion obeys the rules of every move (`watch`): positions exact at
//!   every step, no jump in speed, reversals only at rest, every move
//!   starting and ending at the slowest entry;
//! - the axis comes to rest exactly at the model's turning points, in
//!   order: the targets with the same-way ones between them joined, where
//!   the motor does not stop;
//! - a chain of targets the same way queued before it starts plays as one
//!   move to its end would: the fastest speed at every vertex that still
//!   stops at the end of the queue;
//! - the queue refuses a turning point past its room, and the targets
//!   accepted are where the axis ends;
//! - played in between, the motion keeps the rules and ends at the last
//!   target accepted.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256).

use core_test_support as common;

use common::watch::{Watch, play};
use common::{cases, falling};
use profile_core::player::{Axis, Buffered, Direction, Player, QUEUE, QueueFull, Ramp};
use proptest::prelude::*;

/// The turning points of a path from `start` through `targets`: where it
/// reverses, and its end; the targets between two turning points, the same
/// way, are passed.
fn turning_points(start: i64, targets: &[i64]) -> Vec<i64> {
    let mut points: Vec<i64> = vec![];
    let mut last = start;
    let mut way = 0;
    for &t in targets {
        let step = (t - last).signum();
        if step == 0 {
            continue;
        }
        if step == way {
            *points.last_mut().unwrap() = t;
        } else {
            points.push(t);
        }
        way = step;
        last = t;
    }
    points
}

/// Plays the axis to its end: each step's position after it, direction
/// and period.
fn play_out(
    axis: &mut Axis<'_, u16>,
    watch: &mut Watch<'_>,
) -> Result<Vec<(i64, Direction, u16)>, String> {
    let mut steps = vec![];
    while let [period] = play(axis, watch, 1)?[..] {
        steps.push((axis.position(), axis.direction(), period));
    }
    Ok(steps)
}

/// Where the motion turned (the last step before each change of
/// direction) and ended.
fn turned(steps: &[(i64, Direction, u16)]) -> Vec<i64> {
    let mut points: Vec<i64> = steps
        .windows(2)
        .filter(|w| w[0].1 != w[1].1)
        .map(|w| w[0].0)
        .collect();
    points.extend(steps.last().map(|s| s.0));
    points
}

/// The periods a move of `steps` from rest plays on `table`.
fn one_move(table: &[u16], steps: u32) -> Vec<u16> {
    let mut player = Player::new(Ramp::steps(table));
    player.start(steps);
    core::iter::from_fn(|| player.next_period()).collect()
}

/// Targets queued before the first step: the motion turns at the model's
/// turning points, each chain plays as one move, and the queue refuses
/// what it has no room for.
fn check_ahead(table: &[u16], targets: &[i64]) -> Result<(), String> {
    let mut axis = Axis::new(Player::new(Ramp::steps(table)), 0);
    let mut accepted = vec![];
    for &t in targets {
        let full = turning_points(0, &accepted).len() >= QUEUE + 2
            && turning_points(0, &[&accepted[..], &[t]].concat()).len() > QUEUE + 2;
        match axis.queue(t) {
            Ok(_) if !full => accepted.push(t),
            Err(QueueFull { target }) if full && target == t => {}
            other => return Err(format!("queue({t}) after {accepted:?}: {other:?}")),
        }
    }
    let points = turning_points(0, &accepted);
    if axis.queued() != points.len().saturating_sub(1) {
        return Err(format!(
            "{} queued, not {}",
            axis.queued(),
            points.len() - 1
        ));
    }
    let mut watch = Watch::new(table, 0);
    let steps = play_out(&mut axis, &mut watch)?;
    if turned(&steps) != points {
        return Err(format!("turned at {:?}, not {points:?}", turned(&steps)));
    }
    // Each chain, from one turning point to the next, is one move.
    let mut from = 0;
    let mut at = 0i64;
    for &point in &points {
        let n = point.abs_diff(at) as usize;
        let periods: Vec<u16> = steps[from..from + n].iter().map(|s| s.2).collect();
        if periods != one_move(table, n as u32) {
            return Err(format!("the chain from {at} to {point} is not one move"));
        }
        (from, at) = (from + n, point);
    }
    Ok(())
}

#[derive(Clone, Debug)]
enum Op {
    Queue(i64),
    Play(u32),
}

fn ops() -> impl Strategy<Value = Vec<Op>> {
    let op = prop_oneof![
        3 => (-300i64..300).prop_map(Op::Queue),
        2 => (0u32..120).prop_map(Op::Play),
    ];
    proptest::collection::vec(op, 1..30)
}

/// Queued while playing: the rules of motion hold and the axis ends at the
/// last target accepted; what it turned at is a path through the targets.
fn check_between(table: &[u16], ops: &[Op]) -> Result<(), String> {
    let mut axis = Axis::new(Player::new(Ramp::steps(table)), 0);
    let mut watch = Watch::new(table, 0);
    let mut last = 0;
    let mut steps = vec![];
    for op in ops {
        match *op {
            Op::Queue(t) => {
                if axis.queue(t).is_ok() {
                    last = t;
                } else if axis.queued() < QUEUE + 1 {
                    return Err(format!("queue({t}) refused with {} queued", axis.queued()));
                }
            }
            Op::Play(n) => {
                for _ in 0..n {
                    let [period] = play(&mut axis, &mut watch, 1)?[..] else {
                        break;
                    };
                    steps.push((axis.position(), axis.direction(), period));
                }
            }
        }
    }
    steps.extend(play_out(&mut axis, &mut watch)?);
    if !axis.is_done() || axis.position() != last {
        return Err(format!("ended at {}, not at {last}", axis.position()));
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn queued_ahead_turns_where_the_path_does_and_joins_the_rest(
        table in falling(1usize..40, 300, 1),
        targets in proptest::collection::vec(-200i64..200, 1..16),
    ) {
        check_ahead(&table, &targets).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn queued_while_playing_keeps_the_rules_and_arrives(
        table in falling(1usize..40, 300, 1),
        ops in ops(),
    ) {
        check_between(&table, &ops).map_err(TestCaseError::fail)?;
    }
}

/// Through a buffered register: the pin's direction and position follow a
/// queue that joins and reverses.
#[test]
fn a_buffered_queue_joins_and_reverses_at_the_pin() {
    static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
    let mut axis = Buffered::new(Axis::new(Player::new(&RAMP), 0));
    let (direction, first, next) = axis.queue(6).unwrap();
    assert_eq!(
        (direction, first, next),
        (Direction::Forward, Some(4000), Some(3000))
    );
    axis.queue(12).unwrap();
    axis.queue(4).unwrap();
    let mut pin = vec![];
    while axis.step(|_| {}) {
        pin.push((axis.position(), axis.direction()));
    }
    // Up to 12 without a stop at 6, then back to 4.
    let turn = pin.iter().position(|p| p.1 == Direction::Backward).unwrap();
    assert_eq!(pin[turn - 1], (12, Direction::Forward));
    assert_eq!(pin[turn], (11, Direction::Backward));
    assert_eq!(pin.last(), Some(&(4, Direction::Backward)));
    // Step 0 was taken when the counter started.
    assert_eq!(1 + pin.len(), 12 + 8);
}
