//! The seams between moves: a new target, the same target again, a
//! retarget that changes nothing, each in the last intervals of a move,
//! through `Buffered` and without, for `Player`, `Axis` and `Axes`; and the
//! positions at the extremes of `i64`, with overflow checks on.
//!
//! Each test here pins one case; `buffered_model.rs` draws them at random.

use profile_core::player::{Axes, Axis, Buffered, Direction, Player, Ramp};

static RAMP: [u16; 4] = [4000, 3000, 2000, 1500];

/// A buffered axis whose move ends while its last step is still in the
/// timer's hands: a new target then waits for that step, and the pin
/// takes it in the old move's direction.
#[test]
fn a_reversal_in_the_last_interval_waits_for_the_pending_step() {
    let mut stepper = Buffered::new(Axis::new(Player::new(Ramp::steps(&RAMP)), 0));
    let (direction, first, next) = stepper.move_to(3);
    assert_eq!(
        (direction, first, next),
        (Direction::Forward, Some(4000), Some(3000))
    );
    // Step 0 at the start; one interrupt takes step 1 and hands out the
    // last period: step 2 is pending.
    let mut pin = 1i64;
    assert!(stepper.step(|_| {}));
    pin += stepper.direction().sign();
    assert_eq!(stepper.inner().remaining(), 0);
    assert_eq!(stepper.remaining(), 1);
    assert_eq!(stepper.position(), 2);
    // A new target behind: nothing to load now, the old move's direction
    // stays for the pending step.
    let (direction, first, next) = stepper.move_to(-3);
    assert_eq!((direction, first, next), (Direction::Forward, None, None));
    assert_eq!(stepper.position(), 2);
    assert_eq!(stepper.direction(), Direction::Forward);
    let mut directions = vec![];
    while stepper.step(|_| {}) {
        let d = stepper.direction();
        directions.push(d);
        pin += d.sign();
        assert_eq!(stepper.position(), pin, "after {directions:?}");
    }
    assert_eq!(pin, -3);
    assert_eq!(stepper.position(), -3);
    assert_eq!(directions[0], Direction::Forward);
    assert!(directions[1..].iter().all(|&d| d == Direction::Backward));
}

/// The same with axes: the directions for the pending edge stay.
#[test]
fn axes_turn_after_the_pending_edge() {
    let mut stepper = Buffered::new(Axes::new(Player::new(Ramp::steps(&RAMP)), [0, 0]));
    let start = stepper.move_to([3, 1]);
    let mut pins = [0i64; 2];
    let take = |pins: &mut [i64; 2], mask: u32, directions: [Direction; 2]| {
        for (i, p) in pins.iter_mut().enumerate() {
            if mask >> i & 1 == 1 {
                *p += directions[i].sign();
            }
        }
    };
    take(&mut pins, start.mask, start.directions);
    let mask = stepper.step(|_| {});
    take(&mut pins, mask, stepper.directions());
    assert_eq!(stepper.inner().remaining(), 0);
    assert_eq!(stepper.remaining(), 1);
    let turned = stepper.move_to([-2, -2]);
    assert_eq!(turned.mask, 0);
    assert_eq!(turned.directions, [Direction::Forward; 2]);
    loop {
        let mask = stepper.step(|_| {});
        if mask == 0 {
            break;
        }
        take(&mut pins, mask, stepper.directions());
        assert_eq!(stepper.position(), pins);
    }
    assert_eq!(pins, [-2, -2]);
    assert_eq!(stepper.position(), [-2, -2]);
}

/// Plays a buffered `Axes` to its end, the pins moved by the mask of each
/// edge in the directions the stepper says for it.
fn play_axes<const N: usize>(
    stepper: &mut Buffered<Axes<'_, u16, N>>,
    pins: &mut [i64; N],
    mut before_each: impl FnMut(&mut Buffered<Axes<'_, u16, N>>, usize),
) {
    let mut edge = 0;
    loop {
        before_each(stepper, edge);
        let mask = stepper.step(|_| {});
        if mask == 0 {
            return;
        }
        let directions = stepper.directions();
        for (i, p) in pins.iter_mut().enumerate() {
            if mask >> i & 1 == 1 {
                *p += directions[i].sign();
            }
        }
        edge += 1;
        assert!(edge < 10_000, "a move without end");
    }
}

/// The target the axes already go to, sent again while they decelerate,
/// changes nothing: every axis arrives.
#[test]
fn the_same_target_again_changes_nothing() {
    let mut stepper = Buffered::new(Axes::new(Player::new(Ramp::steps(&RAMP)), [0, 0]));
    let start = stepper.move_to([10, -4]);
    let mut pins = [0i64; 2];
    for (i, p) in pins.iter_mut().enumerate() {
        if start.mask >> i & 1 == 1 {
            *p += start.directions[i].sign();
        }
    }
    play_axes(&mut stepper, &mut pins, |s, edge| {
        // From the start of the deceleration to the last interval.
        if edge >= 6 {
            let again = s.move_to([10, -4]);
            assert_eq!(again.mask, 0);
        }
    });
    assert_eq!(pins, [10, -4]);
    assert_eq!(stepper.position(), [10, -4]);
    assert_eq!(
        stepper.inner().directions(),
        [Direction::Forward, Direction::Backward]
    );
}

/// Unbuffered axes: the same target again, at every step of a move, plays
/// the same periods as the move left alone.
#[test]
fn axes_sent_their_target_again_play_the_same_move() {
    let alone: Vec<(u16, u32)> = {
        let mut axes = Axes::new(Player::new(Ramp::steps(&RAMP)), [0, 0]);
        axes.move_to([10, -4]);
        core::iter::from_fn(|| axes.next_step()).collect()
    };
    for at in 0..alone.len() {
        let mut axes = Axes::new(Player::new(Ramp::steps(&RAMP)), [0, 0]);
        axes.move_to([10, -4]);
        let mut played = vec![];
        while let Some(edge) = axes.next_step() {
            played.push(edge);
            if played.len() == at {
                axes.move_to([10, -4]);
            }
        }
        assert_eq!(played, alone, "sent again after {at} edges");
        assert_eq!(axes.position(), [10, -4]);
    }
}

/// An axis sent its target again at every step plays the move left alone.
#[test]
fn an_axis_sent_its_target_again_plays_the_same_move() {
    let alone: Vec<u16> = {
        let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 0);
        axis.move_to(-9);
        core::iter::from_fn(|| axis.next_period()).collect()
    };
    for at in 0..alone.len() {
        let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 0);
        axis.move_to(-9);
        let mut played = vec![];
        while let Some(p) = axis.next_period() {
            played.push(p);
            if played.len() == at {
                assert_eq!(axis.move_to(-9), Direction::Backward);
            }
        }
        assert_eq!(played, alone, "sent again after {at} steps");
        assert_eq!(axis.position(), -9);
    }
}

/// A target farther than `u32::MAX` steps ahead of a moving axis: the move
/// goes on at cruise, no stop.
#[test]
fn a_target_beyond_u32_steps_ahead_goes_on_at_speed() {
    for target in [i64::MAX, 1 << 40, i64::from(u32::MAX) + 100] {
        let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 0);
        axis.move_to(100);
        for _ in 0..10 {
            axis.next_period();
        }
        assert_eq!(axis.move_to(target), Direction::Forward);
        let next: Vec<u16> = (0..1000).filter_map(|_| axis.next_period()).collect();
        assert_eq!(next, [1500; 1000], "to {target}");
        assert_eq!(axis.position(), 1010);
        assert!(axis.remaining() > 1_000_000);
        // Backward too.
        let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), 0);
        axis.move_to(-100);
        for _ in 0..10 {
            axis.next_period();
        }
        assert_eq!(axis.move_to(-target), Direction::Backward);
        let next: Vec<u16> = (0..1000).filter_map(|_| axis.next_period()).collect();
        assert_eq!(next, [1500; 1000], "to -{target}");
    }
}

/// `retarget` has one meaning for a player and a buffered one: at rest
/// there is no move to end later, and a retarget of no steps, which
/// changes nothing, is taken.
#[test]
fn a_retarget_at_rest_starts_nothing_either_way() {
    let mut player = Player::new(Ramp::steps(&RAMP));
    assert!(!player.retarget(5));
    assert_eq!(player.remaining(), 0);
    assert_eq!(player.next_period(), None);
    assert!(player.retarget(0));
    assert_eq!(player.next_period(), None);
    let mut stepper = Buffered::new(Player::new(Ramp::steps(&RAMP)));
    assert!(!stepper.retarget(5));
    assert_eq!(stepper.remaining(), 0);
    assert!(stepper.retarget(0));
    assert!(!stepper.step(|_| {}));
    // After a move, the same.
    let (first, next) = stepper.start(2);
    assert_eq!((first, next), (Some(4000), Some(4000)));
    assert!(stepper.step(|_| {}));
    assert!(!stepper.step(|_| {}));
    assert!(!stepper.retarget(5));
    assert_eq!(stepper.remaining(), 0);
}

/// A cruise set on axes lasts for their moves, as on an axis.
#[test]
fn a_cruise_set_on_axes_lasts() {
    let mut axes = Axes::new(Player::new(Ramp::steps(&RAMP)), [0, 0]);
    axes.set_cruise(1);
    axes.move_to([8, 3]);
    let periods: Vec<u16> = core::iter::from_fn(|| axes.next_step().map(|(p, _)| p)).collect();
    assert_eq!(periods, [4000, 3000, 3000, 3000, 3000, 3000, 3000, 4000]);
    // Set during a move, it lasts for the move queued after it.
    axes.set_cruise(3);
    axes.move_to([20, 0]);
    for _ in 0..5 {
        axes.next_step();
    }
    axes.set_cruise(2);
    axes.move_to([0, 0]);
    let mut periods: Vec<u16> = vec![];
    while let Some((p, _)) = axes.next_step() {
        periods.push(p);
    }
    assert_eq!(axes.position(), [0, 0]);
    let fastest = periods[periods.len() / 2..].iter().min().copied();
    assert_eq!(fastest, Some(2000), "{periods:?}");
}

/// No arithmetic on positions panics, at the ends of `i64`, with overflow
/// checks on (this test's profile has them): an axis and a buffered one
/// running past the ends, axes moved to them.
#[test]
fn positions_at_the_extremes_never_panic() {
    for (from, direction) in [
        (i64::MAX - 1, Direction::Forward),
        (i64::MIN + 1, Direction::Backward),
    ] {
        let mut stepper = Buffered::new(Axis::new(Player::new(Ramp::steps(&RAMP)), from));
        stepper.run(direction);
        let mut seen = vec![stepper.position()];
        for _ in 0..6 {
            stepper.step(|_| {});
            seen.push(stepper.position());
        }
        // The first step at the start, one at each interrupt.
        let wrapped = from.wrapping_add(direction.sign() * 6);
        assert_eq!(
            stepper.position(),
            wrapped.wrapping_add(direction.sign()),
            "{seen:?}"
        );
        stepper.stop();
        while stepper.step(|_| {}) {}
        let _ = stepper.move_by(i64::MAX);
        let _ = stepper.move_by(i64::MIN);
        let _ = stepper.position();

        let mut axis = Axis::new(Player::new(Ramp::steps(&RAMP)), from);
        axis.run(direction);
        for _ in 0..6 {
            axis.next_period();
        }
        assert_eq!(axis.position(), wrapped);
        axis.move_to(if from > 0 { i64::MIN } else { i64::MAX });
        axis.move_by(i64::MAX);
        axis.move_by(i64::MIN);
        for _ in 0..20 {
            axis.next_period();
            let _ = axis.position();
        }
    }
    let mut axes = Axes::new(
        Player::new(Ramp::steps(&RAMP)),
        [i64::MAX - 2, i64::MIN + 2],
    );
    axes.move_to([i64::MIN, i64::MAX]);
    for _ in 0..20 {
        axes.next_step();
        let _ = axes.position();
    }
    axes.move_by([i64::MAX, i64::MIN]);
    let _ = axes.position();
    let mut stepper = Buffered::new(Axes::new(
        Player::new(Ramp::steps(&RAMP)),
        [i64::MAX, i64::MIN],
    ));
    stepper.move_by([3, -3]);
    stepper.move_to([i64::MIN, i64::MAX]);
    for _ in 0..20 {
        stepper.step(|_| {});
        let _ = stepper.position();
    }
}

/// A retarget to the steps that remain changes nothing: a later retarget
/// plays as it would have without it, at every step of moves of every
/// length.
#[test]
fn a_retarget_to_where_the_move_ends_is_a_no_op() {
    for steps in 1..14u32 {
        for at in 0..steps {
            for later in [1u32, 3, 6, 12, 40] {
                let play = |noop: bool| {
                    let mut player = Player::new(Ramp::steps(&RAMP));
                    player.start(steps);
                    let mut out: Vec<u16> = (0..at).filter_map(|_| player.next_period()).collect();
                    if noop {
                        let remaining = player.remaining();
                        assert!(player.retarget(remaining));
                        assert_eq!(player.remaining(), remaining);
                    }
                    let taken = player.retarget(later);
                    out.extend(core::iter::from_fn(|| player.next_period()));
                    (taken, out)
                };
                assert_eq!(
                    play(true),
                    play(false),
                    "start({steps}), {at} steps, retarget({later})"
                );
            }
        }
    }
}
