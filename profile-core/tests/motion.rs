//! Moves that change while they play, over random tables and random
//! sequences of new targets, runs, stops and cruise speeds: checked step by
//! step against rules computed here from the table alone.
//!
//! - The position the test counts (one step each call, signed by the
//!   direction the axis says the pin must have) is the axis's, after every
//!   step.
//! - The speed never jumps: each period is the one before, or the entry
//!   next to it in the table.
//! - A reversal happens only at rest: the last period before it and the
//!   first after it are the table's slowest entry.
//! - A move from rest starts at the slowest entry, and every move ends
//!   there.
//! - After the last target, the axis arrives there exactly.
//! - A run at a cruise period plays, once there, the table's last entry
//!   not shorter than that period.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256).

use core_test_support as common;

use common::watch::{Watch, play};
use common::{cases, falling};
use profile_core::player::{Axis, Direction, Player, Ramp};
use proptest::prelude::*;

#[derive(Clone, Debug)]
enum Op {
    MoveTo(i64),
    Run(bool),
    Stop,
    Cruise(u32),
    CruisePeriod(u16),
    Play(u32),
}

fn ops() -> impl Strategy<Value = Vec<Op>> {
    let op = prop_oneof![
        4 => (-400i64..400).prop_map(Op::MoveTo),
        1 => any::<bool>().prop_map(Op::Run),
        1 => Just(Op::Stop),
        1 => (0u32..70).prop_map(Op::Cruise),
        1 => any::<u16>().prop_map(Op::CruisePeriod),
        6 => (0u32..150).prop_map(Op::Play),
    ];
    proptest::collection::vec(op, 1..14)
}

/// The last entry not shorter than `period` (on a table ordered slow to
/// fast, the fastest), or the slowest.
fn cruise_entry(table: &[u16], period: u16) -> u16 {
    table
        .iter()
        .copied()
        .rfind(|&p| p >= period)
        .unwrap_or(table[0])
}

fn check(table: &[u16], ops: &[Op]) -> Result<(), String> {
    let mut axis = Axis::new(Player::new(Ramp::steps(table)), 0);
    let mut watch = Watch {
        table,
        position: 0,
        last: None,
        steps: 0,
    };
    let mut target = 0i64;
    let mut cruise_period = None;
    for op in ops {
        match *op {
            Op::MoveTo(t) => {
                axis.move_to(t);
                target = t;
            }
            Op::Run(forward) => {
                let dir = if forward {
                    Direction::Forward
                } else {
                    Direction::Backward
                };
                axis.run(dir);
                // A run held long enough reaches its cruise speed.
                let periods = play(&mut axis, &mut watch, 4 * table.len() as u32 + 10)?;
                if let (Some(p), Some(&last)) = (cruise_period, periods.last()) {
                    let want = cruise_entry(table, p);
                    if axis.direction() == dir && last != want {
                        return Err(format!("run at {p} cruises at {last}, not {want}"));
                    }
                }
                axis.stop();
                target = i64::MIN;
            }
            Op::Stop => {
                axis.stop();
                target = i64::MIN;
            }
            Op::Cruise(pos) => {
                axis.set_cruise(pos);
                cruise_period = None;
            }
            Op::CruisePeriod(p) => {
                axis.set_cruise_period(p);
                cruise_period = Some(p);
            }
            Op::Play(n) => {
                play(&mut axis, &mut watch, n)?;
            }
        }
    }
    // Played out: at rest, at the last target when the last word was one.
    play(&mut axis, &mut watch, u32::MAX)?;
    if !axis.is_done() {
        return Err("not done".into());
    }
    if target != i64::MIN && axis.position() != target {
        return Err(format!("arrived at {}, not {target}", axis.position()));
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn new_targets_runs_and_stops_never_jump_and_arrive(table in falling(1usize..60, 300, 1), ops in ops()) {
        check(&table, &ops).map_err(TestCaseError::fail)?;
    }
}

/// The way back from a target behind, on a hand-checked table.
#[test]
fn a_target_behind_reverses_at_rest() {
    static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
    let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 0);
    axis.move_to(100);
    let mut periods = vec![];
    for _ in 0..6 {
        axis.step(|p| periods.push(p));
    }
    assert_eq!(axis.move_to(2), Direction::Forward);
    while axis.step(|p| periods.push(p)) {}
    assert_eq!(
        periods,
        [
            4000, 3000, 2000, 1500, 1500, 1500, 1500, 2000, 3000, 4000, 4000, 3000, 2000, 1500,
            1500, 2000, 3000, 4000
        ]
    );
    assert_eq!(axis.position(), 2);
}

/// Through [`Buffered`](profile_core::player::Buffered), one period ahead
/// of the pin: at every step taken, the pin's position moves by one in the
/// direction the stepper says for that step, across a reversal too, and
/// ends at the target.
#[test]
fn through_buffered_the_pins_direction_follows_a_reversal() {
    use profile_core::player::Buffered;
    static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
    for turn_at in 0..12 {
        for target in [-3i64, 2, 5, 40] {
            let mut stepper = Buffered::new(Axis::new(Player::new(Ramp::steps(&RAMP)), 0));
            let (dir, first, _) = stepper.move_to(30);
            assert_eq!((dir, first.is_some()), (Direction::Forward, true));
            // The first step is taken at the start.
            let mut pin = 1i64;
            assert_eq!(stepper.position(), 1);
            for k in 0..200 {
                if k == turn_at {
                    stepper.move_to(target);
                }
                if !stepper.step(|_| {}) {
                    break;
                }
                pin += stepper.direction().sign();
                assert_eq!(
                    stepper.position(),
                    pin,
                    "turn at {turn_at}, to {target}, step {k}"
                );
            }
            assert_eq!(pin, target, "turn at {turn_at}");
            assert!(stepper.is_done());
        }
    }
}

/// Past the ends of `i64` the position wraps, as a hardware counter does,
/// exactly and without an overflow; a stop still ends the move.
#[test]
fn the_position_wraps_at_the_ends_of_i64() {
    static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
    for (start, direction) in [
        (i64::MAX, Direction::Forward),
        (i64::MAX - 2, Direction::Forward),
        (i64::MIN, Direction::Backward),
        (i64::MIN + 2, Direction::Backward),
    ] {
        let sign = if direction == Direction::Forward {
            1
        } else {
            -1
        };
        let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), start);
        axis.run(direction);
        for _ in 0..10 {
            assert!(axis.next_period().is_some());
        }
        assert_eq!(axis.position(), start.wrapping_add(sign * 10), "{start}");
        axis.stop();
        let mut steps = 10;
        while axis.next_period().is_some() {
            steps += 1;
        }
        assert_eq!(axis.position(), start.wrapping_add(sign * steps), "{start}");
    }
}

/// A cruise set inside a band the player avoids: the fastest entry not
/// shorter than asked and outside every band (the slowest where none is),
/// by `set_cruise_period` and `set_cruise`, against that rule written
/// directly, on pseudo-random tables, bands and speeds.
#[test]
fn a_cruise_keeps_out_of_the_bands_on_the_slow_side() {
    let mut next = common::xorshift(0x9e37_79b9_7f4a_7c15u64);
    let mut moved = 0;
    for _ in 0..2000 {
        // Strictly falling periods from about 6000.
        let len = 2 + next(30) as usize;
        let mut table = vec![6000u16];
        for _ in 1..len {
            let last = *table.last().unwrap();
            table.push(last - 1 - next(200) as u16);
        }
        let bands: Vec<(u32, u32)> = (0..1 + next(3))
            .map(|_| {
                let a = 100 + next(6000) as u32;
                (a, a + next(1500) as u32)
            })
            .collect();
        let inside = |p: u16| bands.iter().any(|&(s, l)| (s..=l).contains(&u32::from(p)));
        // The rule: the shortest period not shorter than `ticks` outside
        // every band; the slowest entry where none is.
        let rule = |ticks: u32| {
            table
                .iter()
                .copied()
                .filter(|&p| u32::from(p) >= ticks && !inside(p))
                .min()
                .unwrap_or(table[0])
        };
        let cruise = |player: &mut Player<'_, u16>| {
            player.run();
            let mut last = 0;
            for _ in 0..len + 3 {
                last = player.next_period().unwrap();
            }
            last
        };
        let ticks = u32::from(table[len - 1]) + next(6500) as u32;
        let mut player = Player::new(Ramp::steps(&table)).avoiding(&bands);
        player.set_cruise_period(ticks.min(u32::from(u16::MAX)) as u16);
        let want = rule(ticks.min(u32::from(u16::MAX)));
        assert_eq!(cruise(&mut player), want, "{table:?} {bands:?} {ticks}");
        // By index: the entry itself, or past its band.
        let pos = next(len as u64) as usize;
        let mut player = Player::new(Ramp::steps(&table)).avoiding(&bands);
        player.set_cruise(pos as u32);
        let want = match bands
            .iter()
            .find(|&&(s, l)| (s..=l).contains(&u32::from(table[pos])))
        {
            Some(&(_, longest)) => rule(longest + 1),
            None => table[pos],
        };
        if want != table[pos] {
            moved += 1;
        }
        assert_eq!(cruise(&mut player), want, "{table:?} {bands:?} at {pos}");
    }
    assert!(moved > 200, "{moved} cruises moved out of a band");
}
