//! `player::Timed` (feature `fugit`): a profile's `RAMP` carries its
//! timer's rate as a type and its `reload_offset`; the durations handed
//! out are the table's periods, the offset taken off, of that rate. (That
//! another rate is a type error is `tests/ui/fugit_rate_mismatch`.)

use stepper_profiles::fugit::TimerDurationU32;
use stepper_profiles::player::{OffsetMismatch, Player, Ramp, Rated, Timed};

mod shipped {
    stepper_profiles::include_profiles!("profiles.toml");
}
mod arr {
    stepper_profiles::include_profiles!("tests/profiles/reload_offset.toml");
}

/// A HAL's 10 MHz timer: it takes only durations of 10 MHz.
fn ticks_of_10mhz(d: TimerDurationU32<10_000_000>) -> u32 {
    d.ticks()
}

/// Every duration of a move, as a 10 MHz timer takes them, and the values
/// the plain player hands out on the same ramp.
fn durations_and_values(
    ramp: Rated<'static, u16, 10_000_000>,
    steps: u32,
    stop_at: Option<usize>,
) -> (Vec<u32>, Vec<u32>) {
    let mut timed = Timed::new(ramp);
    let mut plain = Player::new(ramp.ramp());
    timed.start(steps);
    plain.start(steps);
    let (mut durations, mut values) = (Vec::new(), Vec::new());
    loop {
        if Some(durations.len()) == stop_at {
            timed.stop();
            plain.stop();
        }
        match (timed.next_duration(), plain.next_period()) {
            (Some(d), Some(v)) => {
                durations.push(ticks_of_10mhz(d));
                values.push(u32::from(v));
            }
            (None, None) => return (durations, values),
            other => panic!("{other:?}"),
        }
    }
}

#[test]
fn a_profiles_ramp_has_its_rate_and_its_offset() {
    assert_eq!(shipped::sigmoid_exact::RAMP.reload_offset(), 0);
    assert_eq!(
        shipped::sigmoid_exact::RAMP.ramp(),
        Ramp::steps(&shipped::sigmoid_exact::PERIODS)
    );
    assert_eq!(
        Rated::<u16, { shipped::sigmoid_exact::TIMER_HZ }>::TIMER_HZ,
        10_000_000
    );
    assert_eq!(arr::arr::RAMP.reload_offset(), -1);
    assert_eq!(arr::arr_runs::RAMP.ramp(), Ramp::runs(&arr::arr_runs::RUNS));
    assert_eq!(
        arr::arr_segments::RAMP.ramp(),
        Ramp::segments(&arr::arr_segments::SEGMENTS)
    );
}

/// Without an offset the durations are the values; with `reload_offset =
/// -1` they are the values plus one: the periods of the same profile
/// without it, a stop included.
#[test]
fn durations_are_the_periods() {
    let (d, v) = durations_and_values(shipped::sigmoid_exact::RAMP, 5000, None);
    assert_eq!(d, v);
    assert_eq!(d.len(), 5000);
    let total: u64 = d.iter().map(|&t| u64::from(t)).sum();
    let top = u64::from(shipped::sigmoid_exact::LAST_TICKS);
    assert_eq!(total, 2 * shipped::sigmoid_exact::TOTAL_TICKS + 3000 * top);
    for (ramp, plain) in [
        (
            arr::arr::RAMP,
            Ramp::steps(&shipped::sigmoid_exact::PERIODS),
        ),
        (
            arr::arr_runs::RAMP,
            Ramp::runs(&shipped::microstep_runs::RUNS),
        ),
    ] {
        for stop_at in [None, Some(700)] {
            let (d, v) = durations_and_values(ramp, 20_000, stop_at);
            assert!(d.iter().zip(&v).all(|(&d, &v)| d == v + 1));
            // The periods of the table without the offset.
            let mut p = Player::new(plain);
            p.start(20_000);
            let mut periods = Vec::new();
            loop {
                if Some(periods.len()) == stop_at {
                    p.stop();
                }
                let Some(t) = p.next_period() else { break };
                periods.push(u32::from(t));
            }
            assert_eq!(d, periods);
        }
    }
}

#[test]
fn step_hands_out_durations_and_fill_the_stored_values() {
    let mut timed = Timed::new(arr::arr::RAMP);
    timed.start(3);
    let mut got = Vec::new();
    while timed.step(|d| got.push(ticks_of_10mhz(d))) {}
    let first = shipped::sigmoid_exact::FIRST_TICKS;
    let second = u32::from(shipped::sigmoid_exact::PERIODS[1]);
    assert_eq!(got, [first, second, first]);
    timed.start(3);
    let mut buf = [0u16; 4];
    assert_eq!(timed.fill(&mut buf), 3);
    assert_eq!(
        buf[..3],
        [first as u16 - 1, second as u16 - 1, first as u16 - 1]
    );
    assert!(timed.is_done() && timed.remaining() == 0);
}

#[test]
fn two_ramps_of_one_player_share_their_offset() {
    let accel = arr::arr::RAMP;
    let plain = Rated::<u16, 10_000_000>::new(accel.ramp(), 0);
    assert_eq!(
        Timed::with_decel(accel, plain).err(),
        Some(OffsetMismatch {
            accel: -1,
            decel: 0
        })
    );
    assert_eq!(
        OffsetMismatch {
            accel: -1,
            decel: 0
        }
        .to_string(),
        "the acceleration ramp stores `reload_offset = -1` and the deceleration ramp `0`: \
         one player needs one offset"
    );
    assert!(Timed::with_decel(accel, accel).is_ok());
}
