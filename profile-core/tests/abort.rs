//! The emergency ramp: [`Player::abort`] over random tables, at a random
//! step of random moves, checked against rules computed here from the
//! tables alone:
//!
//! - an abort plays the emergency ramp from its last entry not shorter
//!   than the period last played, down to its slowest entry, and the move
//!   ends there; at once when the motor runs slower than that entry or has
//!   not stepped yet;
//! - it never lengthens a move: when the move's own deceleration ends it
//!   sooner, the move plays on as it would have;
//! - [`Player::steps_to_abort`] counts the steps it then plays;
//! - while it plays, a stop, a new end, a cruise or a run change nothing;
//! - the next move plays as a player without an emergency ramp plays it.
//!
//! Runs, plain and indexed, abort as their expansion does.
//!
//! `PROPTEST_CASES` sets the number of cases (default 256).

use core_test_support as common;

use common::{cases, falling, falling_runs, padded};
use profile_core::player::{Axis, Buffered, Direction, Player, Ramp};
use profile_core::runs::{Expand, RunIndex};
use proptest::prelude::*;

/// What a move plays after an abort, from the tables alone: `played` the
/// periods played so far, `rest` what the move would play without it
/// (`None` for a run, which would play on).
fn after_abort(emergency: &[u16], played: &[u16], rest: Option<&[u16]>) -> Vec<u16> {
    let Some(&current) = played.last() else {
        return Vec::new();
    };
    // The last entry not shorter than the current period.
    let Some(entry) = emergency.iter().rposition(|&e| e >= current) else {
        // Slower than every entry: at rest now.
        return Vec::new();
    };
    let stop: Vec<u16> = emergency[..=entry].iter().rev().copied().collect();
    match rest {
        Some(rest) if stop.len() >= rest.len() => rest.to_vec(),
        _ => stop,
    }
}

/// Plays the move to its end.
fn drain(player: &mut Player<'_, u16, impl profile_core::player::Layout>) -> Vec<u16> {
    core::iter::from_fn(|| player.next_period()).collect()
}

/// A move of `steps` with cruise `cruise`, aborted after `at` steps (a run
/// when `steps` is 0), on a per-step acceleration ramp with an emergency
/// ramp: checked against [`after_abort`].
fn check_steps(
    accel: &[u16],
    emergency: &[u16],
    steps: u32,
    cruise: u32,
    at: u32,
    next: u32,
) -> Result<(), TestCaseError> {
    let mut player = Player::new(Ramp::steps(accel)).with_emergency(Ramp::steps(emergency));
    let mut twin = Player::new(Ramp::steps(accel));
    for p in [&mut player, &mut twin] {
        p.set_cruise(cruise);
        match steps {
            0 => p.run(),
            n => p.start(n),
        }
    }
    let mut played = Vec::new();
    for _ in 0..at {
        let (p, t) = (player.next_period(), twin.next_period());
        prop_assert_eq!(p, t);
        played.extend(p);
    }
    // What the move plays on without an abort (a run plays on).
    let rest = (steps > 0).then(|| drain(&mut twin.clone()));
    let want = after_abort(emergency, &played, rest.as_deref());
    let aborts = rest.as_ref() != Some(&want) && !want.is_empty();
    let counted = player.steps_to_abort();
    player.abort();
    prop_assert_eq!(player.remaining() as usize, want.len());
    prop_assert_eq!(counted as usize, want.len());
    prop_assert_eq!(player.is_aborting(), aborts);
    if aborts {
        // Nothing changes an abort but a stop, which is no shorter.
        let remaining = player.remaining();
        player.stop();
        player.set_cruise(0);
        player.run();
        prop_assert!(!player.retarget(remaining + 5));
        prop_assert!(player.retarget(remaining));
        player.abort();
        prop_assert_eq!(player.remaining(), remaining);
    }
    let got = drain(&mut player);
    prop_assert_eq!(&got, &want, "played {:?}", played);
    // The next move plays on the deceleration ramp again.
    player.start(next);
    twin.start(next);
    prop_assert_eq!(drain(&mut player), drain(&mut twin));
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn an_abort_plays_the_emergency_ramp_from_the_current_speed(
        accel in falling(1usize..80, 400, 1),
        emergency in falling(1usize..30, 2000, 1),
        steps in 0u32..300,
        cruise in 0u32..90,
        at in 0u32..320,
        next in 0u32..200,
    ) {
        check_steps(&accel, &emergency, steps, cruise, at.min(steps.max(1) * 2), next)?;
    }

    #[test]
    fn runs_plain_and_indexed_abort_as_their_expansion(
        accel in falling_runs(3 << 16),
        emergency in falling_runs(40 << 16),
        steps in 1u32..3000,
        at in 0u32..3000,
    ) {
        let expand = |runs: &[[u16; 5]]| -> Vec<u16> { Expand::new(runs).map(|p| p as u16).collect() };
        let (a_steps, e_steps) = (expand(&accel), expand(&emergency));
        let (a_all, e_all) = (padded::<40>(&accel), padded::<40>(&emergency));
        let (a_index, e_index) = (RunIndex::new(&a_all), RunIndex::new(&e_all));
        let mut reference = Player::new(Ramp::steps(&a_steps)).with_emergency(Ramp::steps(&e_steps));
        let mut plain = Player::<u16, _>::new(&accel[..]).with_emergency(&emergency[..]);
        let mut indexed = Player::<u16, _>::new(&a_index).with_emergency(&e_index);
        reference.start(steps);
        plain.start(steps);
        indexed.start(steps);
        for _ in 0..at.min(steps) {
            let want = reference.next_period();
            prop_assert_eq!([plain.next_period(), indexed.next_period()], [want; 2]);
        }
        let want = reference.steps_to_abort();
        prop_assert_eq!([plain.steps_to_abort(), indexed.steps_to_abort()], [want; 2]);
        reference.abort();
        plain.abort();
        indexed.abort();
        let want = drain(&mut reference);
        prop_assert_eq!(drain(&mut plain), want.clone());
        prop_assert_eq!(drain(&mut indexed), want);
        reference.start(steps);
        plain.start(steps);
        indexed.start(steps);
        let want = drain(&mut reference);
        prop_assert_eq!(drain(&mut plain), want.clone());
        prop_assert_eq!(drain(&mut indexed), want);
    }
}

static ACCEL: [u16; 6] = [5000, 3500, 2800, 2400, 2100, 1900];
static ESTOP: [u16; 3] = [5000, 2800, 1900];

/// An axis aborted at speed stops where the emergency ramp takes it, and
/// its position counts every step.
#[test]
fn an_axis_aborts_short_of_its_target() {
    let player = Player::new(&ACCEL).with_emergency(&ESTOP);
    let mut axis = Axis::new(player, 0);
    axis.move_to(100);
    for _ in 0..20 {
        axis.next_period();
    }
    assert_eq!(axis.position(), 20);
    axis.abort();
    let rest: Vec<u16> = core::iter::from_fn(|| axis.next_period()).collect();
    assert_eq!(rest, [1900, 2800, 5000]);
    assert_eq!(axis.position(), 23);
    assert_eq!(axis.direction(), Direction::Forward);
    // The next move uses the whole deceleration ramp again.
    axis.move_to(43);
    let periods: Vec<u16> = core::iter::from_fn(|| axis.next_period()).collect();
    assert_eq!(periods.len(), 20);
    assert_eq!(
        periods[14..],
        ACCEL.iter().rev().copied().collect::<Vec<_>>()[..]
    );
}

/// Through a buffered register, an abort starts from the first period not
/// yet in the timer's hands.
#[test]
fn a_buffered_abort_leaves_the_loaded_periods() {
    let player = Player::new(&ACCEL).with_emergency(&ESTOP);
    let mut buffered = Buffered::new(player);
    let (now, next) = buffered.start(50);
    assert_eq!((now, next), (Some(5000), Some(3500)));
    let mut loaded = Vec::new();
    for _ in 0..12 {
        buffered.step(|p| loaded.push(p));
    }
    buffered.abort();
    while buffered.step(|p| loaded.push(p)) {}
    // The twelve loads after the first two, then the emergency ramp from
    // its entry not faster than the last period loaded.
    assert_eq!(loaded[..4], [2800, 2400, 2100, 1900]);
    assert_eq!(loaded[12..], [1900, 2800, 5000]);
}
