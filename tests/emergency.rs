//! Emergency ramps declared in a profiles file (`emergency = "NAME"`): the
//! `STOP_STEPS` a profile's module and C header hold are the steps
//! `Player::abort` plays after each step of its ramp, on a per-step table
//! and on compressed runs, and the periods it plays are the emergency
//! ramp's, read down from its last entry not shorter than the current
//! period.

use profile_codegen::profiles::Profiles;
use profile_core::player::{Player, Ramp};
use profile_core::runs::Expand;

mod profiles {
    stepper_profiles::include_profiles!("tests/profiles/emergency.toml");
}

/// Every step of the ramp a move's last before the abort: the abort plays
/// `STOP_STEPS` of that step, the emergency ramp's entries down to rest.
fn check_each_step<L: profile_core::player::Layout>(
    make: impl Fn() -> Player<'static, u16, L>,
    accel: &[u16],
    emergency: &[u16],
    stop_steps: &[u16],
) {
    assert_eq!(stop_steps.len(), accel.len());
    for k in 1..=accel.len() {
        let mut player = make();
        player.start(10 * accel.len() as u32);
        for _ in 0..k {
            player.next_period();
        }
        let want = stop_steps[k - 1];
        assert_eq!(player.steps_to_abort(), u32::from(want), "after {k} steps");
        player.abort();
        let played: Vec<u16> = core::iter::from_fn(|| player.next_period()).collect();
        let down: Vec<u16> = emergency[..usize::from(want)]
            .iter()
            .rev()
            .copied()
            .collect();
        assert_eq!(played, down, "after {k} steps");
        // The entry not shorter than the last step played, and no later one.
        if let Some(&first) = played.first() {
            assert!(first >= accel[k - 1]);
            assert!(
                emergency[usize::from(want)..]
                    .iter()
                    .all(|&e| e < accel[k - 1])
            );
        }
    }
}

#[test]
fn stop_steps_are_what_an_abort_plays_on_a_per_step_table() {
    use profiles::{estop, travel};
    check_each_step(
        || Player::new(&travel::PERIODS).with_emergency(&estop::PERIODS),
        &travel::PERIODS,
        &estop::PERIODS,
        &travel::STOP_STEPS,
    );
    // From the top, the abort is far shorter than the ramp's own stop.
    let top = *travel::STOP_STEPS.last().unwrap();
    assert!(usize::from(top) * 4 < travel::PERIODS.len(), "{top}");
}

#[test]
fn stop_steps_are_what_an_abort_plays_on_compressed_runs() {
    use profiles::{estop_runs, travel_runs};
    let accel: Vec<u16> = Expand::new(&travel_runs::RUNS).map(|p| p as u16).collect();
    let emergency: Vec<u16> = Expand::new(&estop_runs::RUNS).map(|p| p as u16).collect();
    check_each_step(
        || Player::new(&travel_runs::RUN_INDEX).with_emergency(&estop_runs::RUN_INDEX),
        &accel,
        &emergency,
        &travel_runs::STOP_STEPS,
    );
    check_each_step(
        || {
            Player::new(Ramp::runs(&travel_runs::RUNS))
                .with_emergency(Ramp::runs(&estop_runs::RUNS))
        },
        &accel,
        &emergency,
        &travel_runs::STOP_STEPS,
    );
}

#[test]
fn the_c_header_holds_the_same_stop_steps() {
    let profiles = Profiles::load("tests/profiles/emergency.toml").unwrap();
    let header = profiles.c_header();
    for (name, steps) in [
        ("TRAVEL", &profiles::travel::STOP_STEPS[..]),
        ("TRAVEL_RUNS", &profiles::travel_runs::STOP_STEPS[..]),
    ] {
        let start = header
            .find(&format!("{name}_STOP_STEPS[{}] = {{", steps.len()))
            .unwrap_or_else(|| panic!("{name}_STOP_STEPS in the header"));
        let body = &header[start..];
        let body = &body[body.find('{').unwrap() + 1..body.find('}').unwrap()];
        let values: Vec<u16> = body
            .split(',')
            .map(str::trim)
            .filter(|v| !v.is_empty())
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(values, steps, "{name}");
    }
    assert!(!header.contains("ESTOP_STOP_STEPS"));
}
