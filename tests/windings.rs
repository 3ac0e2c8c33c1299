//! A motor given by its windings: the check and the simulation use the
//! pull-out torque they give, in the macro, in a profiles file and in the
//! library, and a typed curve takes precedence over them.

use profile_codegen::SpecTables;
use profile_codegen::motor::{Drive, Motor, MotorError, TorqueCurve, Windings};
use profile_codegen::profiles::Profiles;
use profile_codegen::simulate::{self, SimOptions};
use profile_core::player::{Player, Ramp};
use profile_core::{Curve, Linear, LinearExtent, Spec, Timer};
use stepper_profiles::period_table;

/// TRINAMIC's QSH4218-47-28-040 ("QMot QSH4218 Manual" V1.10, Table 2.1)
/// on a `volts` supply, with twice its rotor's inertia as load and 0.02 N·m
/// of friction, full steps, lightly damped.
fn qsh4218(volts: f64) -> Motor {
    Motor::new(1.8, 1, 6.8e-6)
        .with_windings(Windings::new(0.5, 0.6e-3, 2.8, 0.40, volts))
        .with_load_inertia(1.36e-5)
        .with_friction(0.02)
        .with_damping_ratio(0.1)
}

/// 300 to 5000 full steps/s at 50 000 full steps/s², on a 10 MHz timer.
fn ramp() -> (Spec, Vec<u32>) {
    ramp_in(1)
}

/// The same ramp in table steps of `1 / per_full_step` of a step.
fn ramp_in(per_full_step: u32) -> (Spec, Vec<u32>) {
    let k = f64::from(per_full_step);
    let spec = Spec::new(
        Curve::Linear(Linear {
            fmin: 300.0 * k,
            fmax: 5000.0 * k,
            extent: LinearExtent::Accel(50_000.0 * k),
        }),
        Timer::new(10_000_000),
    );
    let periods = spec.table().unwrap().periods;
    (spec, periods)
}

/// The table up and down again, as the player plays it, simulated: the
/// steps lost.
fn lost(motor: &Motor, spec: &Spec, table: &[u32]) -> i64 {
    let mut player = Player::new(Ramp::steps(table));
    player.start(2 * table.len() as u32);
    let moves: Vec<u32> = std::iter::from_fn(|| player.next_period()).collect();
    let options = SimOptions::suggested(motor, spec, &moves);
    simulate::run(motor, spec, &moves, &options)
        .unwrap()
        .lost_steps
}

#[test]
fn the_check_and_the_simulation_use_the_torque_the_windings_give() {
    let (spec, table) = ramp();
    // At 4 V the torque falls away at speed: the check refuses the ramp
    // where it falls short, and the simulated rotor slips.
    let weak = qsh4218(4.0);
    let error = weak.check(&spec, &table).unwrap_err();
    assert_eq!(
        error.to_string(),
        "the motor cannot follow step 66 at 2596.1 Hz: it needs 0.0521 N·m but gives \
         0.0517 N·m after the safety factor, short by 0.0004 N·m (the pull-out torque derived \
         from the windings)"
    );
    let MotorError::Torque {
        hz, available_nm, ..
    } = error
    else {
        panic!("{error:?}")
    };
    assert_eq!(Some(available_nm), weak.derived_pull_out(hz));
    assert_eq!(lost(&weak, &spec, &table), 16);
    // At 24 V the motor reaches 1500 rpm with torque to spare: the ramp
    // passes and the simulated rotor keeps every step.
    let strong = qsh4218(24.0);
    let figures = strong.check(&spec, &table).unwrap();
    assert!(figures.min_margin_nm > 0.0);
    assert_eq!(lost(&strong, &spec, &table), 0);
    // A typed curve is what the check uses; the windings stay for comparison.
    let typed = strong.with_torque_curve(TorqueCurve::new(&[(0.0, 0.40), (4000.0, 0.25)]).unwrap());
    let error = typed.check(&spec, &table).unwrap_err();
    assert!(
        error
            .to_string()
            .ends_with("(the frequency is beyond the last point of `torque_curve`)"),
        "{error}"
    );
    assert_eq!(typed.pull_out(2000.0), 0.325);
    assert_eq!(
        typed.derived_pull_out(2000.0),
        strong.derived_pull_out(2000.0)
    );
    assert_eq!(
        strong.derived_pull_out(2000.0),
        Some(strong.pull_out(2000.0))
    );
}

// The macro: the windings alone describe the motor's torque.
static STRONG: [u16; 250] = period_table!(
    curve = linear,
    fmin = 300,
    fmax = 5000,
    accel = 50_000,
    timer_hz = 10_000_000,
    step_angle = 1.8,
    rotor_inertia = 6.8e-6,
    load_inertia = 1.36e-5,
    friction = 0.02,
    resistance = 0.5,
    inductance = 0.6e-3,
    rated_current = 2.8,
    holding_torque = 0.40,
    supply_voltage = 24,
    damping_ratio = 0.1,
);

#[test]
fn the_macro_and_a_profiles_file_take_the_windings() {
    let (_, table) = ramp();
    assert_eq!(STRONG.map(u32::from).as_slice(), table.as_slice());
    let text = r#"
[motors.qsh4218]
step_angle = 1.8
rotor_inertia = 6.8e-6
load_inertia = 1.36e-5
friction = 0.02
resistance = 0.5
inductance = 0.6e-3
rated_current = 2.8
holding_torque = 0.40
supply_voltage = 24
detent_torque = 0.01

[profiles.ramp]
curve = "linear"
fmin = 300
fmax = 5000
accel = 50_000
timer_hz = 10_000_000
motor = "qsh4218"
"#;
    let profiles = Profiles::parse("profiles.toml", text).unwrap();
    let motor = profiles.profiles()[0].motor.unwrap();
    assert_eq!(motor.torque_curve, None);
    let windings = motor.windings.unwrap();
    assert_eq!(windings.detent_torque, 0.01);
    assert!((motor.pull_out(0.0) - 0.39).abs() < 1e-15);
}

/// The motor on a driver of `drive`: a half-step driver's table steps are
/// half steps.
fn stepping(drive: Drive) -> Motor {
    let mut motor = qsh4218(24.0);
    if let Some(w) = motor.windings.as_mut() {
        w.drive = drive;
    }
    if drive == Drive::HalfStep {
        motor.microsteps = 2;
    }
    motor
}

/// A driver that steps the current gives its fundamental's share of the
/// torque: at rest `(4/π) cos(π/8) = 0.83` of the sine's in half steps,
/// `(4/π)/sqrt(2) = 0.90` in full steps; the ramp a sine drive follows
/// with torque to spare is refused in half steps.
#[test]
fn a_driver_that_steps_the_current_gives_its_fundamentals_share() {
    let (spec, table) = ramp();
    let sine = stepping(Drive::Sine);
    let mut half = stepping(Drive::HalfStep);
    let full = stepping(Drive::FullStep);
    let share = |m: &Motor| m.pull_out(0.0) / sine.pull_out(0.0);
    let pi = std::f64::consts::PI;
    assert!((share(&half) - 4.0 / pi * (pi / 8.0).cos() / 2f64.sqrt()).abs() < 1e-12);
    assert!((share(&full) - 4.0 / pi / 2f64.sqrt()).abs() < 1e-12);
    // The same ramp in half steps has less torque to spare where it ends:
    // the share of the half-step drive's fundamental at that speed.
    let (half_spec, half_table) = ramp_in(2);
    let on_sine = sine.check(&spec, &table).unwrap();
    let on_half = half.check(&half_spec, &half_table).unwrap();
    assert!(
        on_half.min_margin_nm < on_sine.min_margin_nm,
        "{on_half:?} {on_sine:?}"
    );
    let last_hz = on_sine.hz;
    let ratio = half.available(2.0 * last_hz) / sine.available(last_hz);
    assert!(ratio < 0.85, "{ratio}");
    // Where less torque is left than the ramp needs, the refusal says the
    // torque is derived in half steps.
    half.safety = 5.0;
    let refused = half.check(&half_spec, &half_table).unwrap_err().to_string();
    assert!(
        refused.ends_with("(the pull-out torque derived from the windings, in half steps)"),
        "{refused}"
    );
}

// The macro takes the drive by name, half steps in table steps.
static HALF_STEPS: [u16; 499] = period_table!(
    curve = linear,
    fmin = 600,
    fmax = 10000,
    accel = 100_000,
    timer_hz = 10_000_000,
    step_angle = 1.8,
    microsteps = 2,
    rotor_inertia = 6.8e-6,
    load_inertia = 1.36e-5,
    friction = 0.02,
    resistance = 0.5,
    inductance = 0.6e-3,
    rated_current = 2.8,
    holding_torque = 0.40,
    supply_voltage = 24,
    damping_ratio = 0.1,
    drive = half_step,
    safety = 1.5,
);

#[test]
fn the_macro_and_a_profiles_file_take_the_drive() {
    let (_, table) = ramp_in(2);
    assert_eq!(HALF_STEPS.map(u32::from).as_slice(), table.as_slice());
    let text = r#"
[motors.qsh4218]
step_angle = 1.8
rotor_inertia = 6.8e-6
resistance = 0.5
inductance = 0.6e-3
rated_current = 2.8
holding_torque = 0.40
supply_voltage = 24
drive = "full_step"

[profiles.ramp]
curve = "linear"
fmin = 300
fmax = 2000
accel = 20_000
timer_hz = 10_000_000
motor = "qsh4218"
"#;
    let profiles = Profiles::parse("profiles.toml", text).unwrap();
    let motor = profiles.profiles()[0].motor.unwrap();
    assert_eq!(motor.windings.unwrap().drive, Drive::FullStep);
    assert_eq!(Drive::FullStep.name(), "full_step");
}
