//! `player::Buffered` on a model of a timer whose reload register takes
//! effect at the next wrap (SysTick, `ARR` with preload), written here on
//! its own: every step the pin takes lands at the sum of the periods the
//! plain `Player` hands out before it, for per-step and compressed ramps and
//! an `Axis`, with stops and cruise changes at random interrupts.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256 per property).

use core_test_support as common;

use common::{Event, cases, events, falling};
use profile_core::player::{Axis, Buffered, Direction, Player, Ramp, Steps};
use proptest::prelude::*;

/// Runs from a per-step table: each entry a run of one step, so that
/// `Player::new(&RUNS)` plays them.
fn as_runs(t: &[u16]) -> Vec<[u16; 5]> {
    t.iter().map(|&p| [1, p, 0, 0, 0]).collect()
}

/// The timer: a counter that counts the interval it loaded, and a reload
/// register it loads from at each wrap, when its interrupt runs. Returns
/// the times of the steps the pin takes (the first at the start) and the
/// time the counter was stopped; `None` past `limit` interrupts.
fn buffered_timer<S: Steps<Word = u16>>(
    stepper: &mut Buffered<S>,
    mut before: impl FnMut(&mut Buffered<S>),
    begin: (Option<u16>, Option<u16>),
    limit: usize,
) -> Option<(Vec<u64>, u64)> {
    let (Some(first), next) = begin else {
        return Some((Vec::new(), 0));
    };
    // The counter counts `first`; the reload register holds `next` (or
    // still `first` when there is none).
    let mut reload = next.unwrap_or(first);
    let (mut now, mut counting) = (0u64, first);
    let mut steps = vec![0];
    for i in 0..limit {
        // The wrap: the interval ends, the counter loads the register.
        now += u64::from(counting);
        counting = reload;
        before(stepper);
        // Both calls, interleaved: `pulse_and_step` pulses exactly when it
        // returns `true`, and plays what `step` plays.
        let mut pulses = 0;
        let stepped = if i % 3 == 1 {
            stepper.step(|p| reload = p)
        } else {
            let taken = stepper.pulse_and_step(|| pulses += 1, |p| reload = p);
            assert_eq!(
                pulses,
                u32::from(taken),
                "a pulse for each step taken, at {i}"
            );
            taken
        };
        if !stepped {
            return Some((steps, now));
        }
        steps.push(now);
    }
    None
}

/// The periods the plain player hands out, with `events` applied before
/// the period of their index.
fn plain(mut player: Player<'_, u16>, steps: u32, events: &[(usize, Event)]) -> Vec<u16> {
    player.start(steps);
    let mut out = Vec::new();
    loop {
        for &(at, e) in events {
            if at == out.len() {
                match e {
                    Event::Stop => player.stop(),
                    Event::Cruise(pos) => player.set_cruise(pos),
                }
            }
        }
        match player.next_period() {
            Some(p) => out.push(p),
            None => return out,
        }
        assert!(out.len() < 1_000_000, "a move without end");
    }
}

/// Step `k` at the sum of the first `k` periods; the move over at the sum
/// of all.
fn expected_times(periods: &[u16]) -> (Vec<u64>, u64) {
    let mut t = 0u64;
    let mut times = Vec::new();
    for &p in periods {
        times.push(t);
        t += u64::from(p);
    }
    (times, t)
}

/// Plays `player` buffered with `events` at the same handout indexes as
/// [`plain`], on the timer model.
fn played(mut player: Player<'_, u16>, steps: u32, events: &[(usize, Event)]) -> (Vec<u64>, u64) {
    player.start(steps);
    let mut stepper = Buffered::new(player);
    let begin = stepper.begin();
    // Periods handed out so far: two at the start, one at each interrupt.
    let mut handed = begin.0.iter().count() + begin.1.iter().count();
    let apply = |s: &mut Buffered<Player<'_, u16>>| {
        for &(at, e) in events {
            if at == handed {
                match e {
                    Event::Stop => s.stop(),
                    Event::Cruise(pos) => s.set_cruise(pos),
                }
            }
        }
        handed += 1;
    };
    buffered_timer(&mut stepper, apply, begin, 2_000_000).expect("a move without end")
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    /// Per-step tables, with and without a deceleration table of its own.
    #[test]
    fn every_step_lands_at_the_sum_of_the_periods_before_it(
        accel in falling(1usize..80, 600, 2),
        decel in falling(1usize..80, 600, 2),
        own_decel in any::<bool>(),
        steps in 0u32..400,
        events in events(2usize..200),
    ) {
        let make = || if own_decel {
            Player::new(Ramp::steps(&accel)).with_decel(Ramp::steps(&decel))
        } else {
            Player::new(Ramp::steps(&accel))
        };
        // Events only where the plain player still hands out periods.
        let periods = plain(make(), steps, &events);
        let (times, end) = played(make(), steps, &events);
        prop_assert_eq!((times, end), expected_times(&periods));
    }

    /// Compressed ramps, played by the player of compressed tables.
    #[test]
    fn compressed_ramps_land_on_the_same_edges(
        accel in falling(1usize..80, 600, 2),
        steps in 0u32..400,
        events in events(2usize..200),
    ) {
        let runs = as_runs(&accel);
        let periods = plain(Player::new(Ramp::steps(&accel)), steps, &events);
        let mut stepper = Buffered::new(Player::<u16, _>::new(&runs[..]));
        let begin = stepper.start(steps);
        let mut handed = begin.0.iter().count() + begin.1.iter().count();
        let apply = |s: &mut Buffered<Player<'_, u16, _>>| {
            for &(at, e) in &events {
                if at == handed {
                    match e {
                        Event::Stop => s.stop(),
                        Event::Cruise(pos) => s.set_cruise(pos),
                    }
                }
            }
            handed += 1;
        };
        let got = buffered_timer(&mut stepper, apply, begin, 2_000_000).expect("an end");
        prop_assert_eq!(got, expected_times(&periods));
    }

    /// An axis: its steps at the same edges, and its position at the pin
    /// one behind what it has handed out until the last step is taken.
    #[test]
    fn an_axis_is_where_its_pin_has_taken_it(
        accel in falling(1usize..80, 600, 2),
        from in -1000i64..1000,
        delta in -300i64..300,
    ) {
        let periods = plain(Player::new(Ramp::steps(&accel)), delta.unsigned_abs() as u32, &[]);
        let mut stepper = Buffered::new(Axis::new(Player::new(Ramp::steps(&accel)), from));
        let (direction, first, next) = stepper.move_by(delta);
        let sign = if delta < 0 { -1 } else { 1 };
        prop_assert_eq!(direction, if delta < 0 { Direction::Backward } else { Direction::Forward });
        let taken = std::cell::Cell::new(i64::from(first.is_some()));
        let check = |s: &mut Buffered<Axis<'_, u16>>| {
            assert_eq!(s.position(), from + sign * taken.get());
            taken.set(taken.get() + 1);
        };
        let got = buffered_timer(&mut stepper, check, (first, next), 2_000_000).expect("an end");
        prop_assert_eq!(got, expected_times(&periods));
        prop_assert_eq!(stepper.position(), from + delta);
        prop_assert!(stepper.is_done());
        prop_assert_eq!(stepper.move_by(1).0, Direction::Forward);
    }
}

/// A move of one step: the step at the start, and the interrupt at the end
/// of its interval ends the move; no steps, no interval.
#[test]
fn the_shortest_moves() {
    static RAMP: [u16; 3] = [3000, 2000, 1500];
    let mut stepper = Buffered::new(Player::new(Ramp::steps(&RAMP)));
    assert_eq!(stepper.start(0), (None, None));
    assert!(stepper.is_done());
    assert_eq!(stepper.start(1), (Some(3000), None));
    assert!(stepper.is_done());
    assert!(!stepper.step(|_| panic!("nothing to load")));
    assert_eq!(stepper.start(2), (Some(3000), Some(3000)));
    assert_eq!(stepper.remaining(), 1);
    assert!(stepper.step(|_| panic!("nothing to load")));
    assert!(!stepper.step(|_| panic!("nothing to load")));
}

/// What `Buffered::new` finds ahead of the pin: nothing for a new player or
/// one whose step has returned `false`; the last period handed out for one
/// that has handed out periods since, whose step is then still to take.
#[test]
fn wrapping_a_player() {
    static RAMP: [u16; 3] = [3000, 2000, 1500];
    let mut pulses = 0;
    let mut stepper = Buffered::new(Player::new(Ramp::steps(&RAMP)));
    assert_eq!(stepper.remaining(), 0);
    assert!(!stepper.pulse_and_step(|| pulses += 1, |_| panic!("nothing to load")));
    assert_eq!(pulses, 0);

    let mut player = Player::new(Ramp::steps(&RAMP));
    player.start(2);
    while player.step(|_| {}) {}
    let mut stepper = Buffered::new(player);
    assert_eq!(stepper.remaining(), 0);
    assert!(!stepper.pulse_and_step(|| pulses += 1, |_| panic!("nothing to load")));
    assert_eq!(pulses, 0);

    let mut player = Player::new(Ramp::steps(&RAMP));
    player.start(2);
    assert_eq!(
        (player.next_period(), player.next_period()),
        (Some(3000), Some(3000))
    );
    let mut stepper = Buffered::new(player);
    assert_eq!(stepper.remaining(), 1);
    assert!(stepper.pulse_and_step(|| pulses += 1, |_| panic!("nothing to load")));
    assert!(!stepper.pulse_and_step(|| pulses += 1, |_| panic!("nothing to load")));
    assert_eq!(pulses, 1);
}

/// A move of `u32::MAX` steps left, the step ahead of the pin counted:
/// `u32::MAX`, not an overflow.
#[test]
fn the_steps_left_stop_at_u32_max() {
    static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];
    let mut b = Buffered::new(Player::new(Ramp::steps(&RAMP)));
    b.start(10);
    assert!(b.retarget(u32::MAX));
    assert_eq!(b.remaining(), u32::MAX);
}
