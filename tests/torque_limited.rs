//! `curve = torque_limited`: the fastest ramp a motor allows, with a
//! margin. The macro, a profiles file and the library give the same table;
//! it passes the motor check by construction; and a rotor simulated here,
//! by an integrator of its own (not `simulate`), follows it without losing
//! a step, and loses steps once the margin is gone and the load is raised.

use test_support::lcg::Lcg;
use test_support::motors::QSH4218_CHART as CHART;

use profile_codegen::__private::golden;
use profile_codegen::SpecTables;
use profile_codegen::motor::{Motor, MotorError, TorqueCurve, Windings};
use profile_codegen::profiles::Profiles;
use profile_core::player::{Player, Ramp};
use stepper_profiles::{Curve, Generated, Spec, Timer, Word, period_table};

/// The start a profile without `fmin` takes on the shipped
/// QSH4218-47-28-040 in 1/8 steps (its chart, twice its rotor's inertia as
/// load, 0.02 N·m of friction, undamped, no safety factor).
const FMIN: f64 = 4870.0;

fn qsh4218(load: f64) -> Motor {
    Motor::new(1.8, 8, 6.8e-6)
        .with_torque_curve(TorqueCurve::new(&CHART).unwrap())
        .with_load_inertia(load)
        .with_friction(0.02)
}

static FASTEST: [u16; 522] = period_table!(
    curve = torque_limited,
    fmax = 40_000,
    margin = 0.5,
    timer_hz = 10_000_000,
    step_angle = 1.8,
    microsteps = 8,
    rotor_inertia = 68gcm2,
    load_inertia = 136gcm2,
    friction = 0.02,
    torque_curve = [
        (0, 0.40),
        (4000, 0.404),
        (8000, 0.404),
        (12000, 0.389),
        (16000, 0.375),
        (20000, 0.344),
        (24000, 0.308),
        (28000, 0.281),
        (32000, 0.255),
        (36000, 0.245),
        (40000, 0.235)
    ],
);

const FILE: &str = r#"
[motors.qsh]
step_angle = 1.8
microsteps = 8
rotor_inertia = 6.8e-6
load_inertia = 1.36e-5
friction = 0.02
torque_curve = [[0, 0.40], [4000, 0.404], [8000, 0.404], [12000, 0.389], [16000, 0.375],
    [20000, 0.344], [24000, 0.308], [28000, 0.281], [32000, 0.255], [36000, 0.245],
    [40000, 0.235]]

[profiles.fastest]
curve = "torque_limited"
fmax = 40_000
margin = 0.5
timer_hz = 10_000_000
motor = "qsh"
"#;

/// The file's profile: its spec and table.
fn from_file() -> (Spec, Vec<u32>) {
    let profiles = Profiles::parse("profiles.toml", FILE).unwrap_or_else(|e| panic!("{e}"));
    match &profiles.profiles()[0].table {
        Generated::Steps(t) => (t.spec, t.periods.clone()),
        _ => panic!("a per-step table"),
    }
}

/// The table, pinned in `tests/golden/curves/torque_limited.txt` (the
/// format and the blessing of `tests/golden_curves.rs`:
/// `UPDATE_GOLDEN=1 cargo test --test torque_limited`).
#[test]
fn the_table_matches_its_golden_file() {
    let profiles = Profiles::parse("profiles.toml", FILE).unwrap_or_else(|e| panic!("{e}"));
    let path: std::path::PathBuf = [
        env!("CARGO_MANIFEST_DIR"),
        "tests",
        "golden",
        "curves",
        "torque_limited.txt",
    ]
    .iter()
    .collect();
    if let Err(problem) = golden::compare(path, &profiles.profiles()[0].table) {
        panic!("{problem}");
    }
}

#[test]
fn the_macro_the_file_and_the_library_give_the_same_table() {
    let (spec, periods) = from_file();
    let from_macro: Vec<u32> = FASTEST.iter().map(|&p| u32::from(p)).collect();
    assert_eq!(from_macro, periods);
    // Without `fmin` the start is the fastest the start check accepts,
    // written to three digits: the library gives the same ramp from it.
    let Curve::TorqueLimited(ramp) = spec.curve else {
        panic!("{spec:?}")
    };
    assert_eq!(ramp.fmin, FMIN);
    let motor = qsh4218(1.36e-5);
    let library = motor
        .torque_limited(Some(FMIN), 40_000.0, 0.5, Timer::new(10_000_000))
        .unwrap();
    assert_eq!(library, ramp);
    let table = Spec::new(Curve::TorqueLimited(library), Timer::new(10_000_000))
        .table()
        .unwrap();
    assert_eq!(table.periods, periods);
    // A start above the one the check accepts is refused, as any ramp's.
    let too_fast = format!("{FILE}fmin = 9000\n");
    let error = Profiles::parse("profiles.toml", &too_fast).unwrap_err();
    assert!(
        error
            .to_string()
            .contains("the motor cannot start on this ramp"),
        "{error}"
    );
}

/// At every edge the ramp plans on `margin` of the pull-out torque: the
/// check passes with the safety factor over the margin (here 2), and keeps
/// half the torque to spare with the motor's own.
#[test]
fn it_passes_the_check_at_its_margin() {
    let (spec, periods) = from_file();
    let motor = qsh4218(1.36e-5);
    // Every edge passes with the safety factor at 2 (the start from rest
    // is the motor's own check's, with its own safety factor).
    let strict = motor.with_safety(1.0 / 0.5);
    let edges = strict.check(&spec, &periods);
    assert!(
        !matches!(edges, Err(MotorError::Torque { .. })),
        "{edges:?}"
    );
    // A tenth more and an edge is refused: the margin is what it keeps.
    let tighter = motor.with_safety(1.1 / 0.5);
    let edges = tighter.check(&spec, &periods);
    assert!(matches!(edges, Err(MotorError::Torque { .. })), "{edges:?}");
    let own = motor.check(&spec, &periods).unwrap();
    assert!(own.min_margin_nm > 0.4 * 0.235, "{own:?}");
    let seconds = periods.iter().map(|&p| f64::from(p)).sum::<f64>() / 1e7;
    println!("to 1500 rpm in {:.1} ms", seconds * 1e3);
}

/// A rotor on its own integrator: `J θ'' = T(f) sin(N_r (θ_field - θ)) -
/// friction - damping θ'`, the field a microstep further at each edge, the
/// torque's amplitude the pull-out torque at the step rate of the interval
/// being played (the sinusoid whose peak the chart measures), classical
/// fourth-order Runge-Kutta in steps of a fortieth of the shortest period.
/// Returns the full steps the rotor ends behind the field (or ahead,
/// negative) after the move and a held settling time.
fn steps_lost(motor: &Motor, periods: &[u32], timer_hz: f64) -> i64 {
    let poles = 50.0;
    let field_step = (1.8f64).to_radians() / 8.0;
    let inertia = motor.rotor_inertia + motor.load_inertia;
    let shortest = f64::from(*periods.iter().min().unwrap()) / timer_hz;
    let dt = shortest / 40.0;
    let (mut theta, mut omega, mut field) = (0.0f64, 0.0f64, 0.0f64);
    let accel = |theta: f64, omega: f64, field: f64, amplitude: f64| {
        let electromagnetic = amplitude * (poles * (field - theta)).sin();
        // Friction opposes motion; at rest it holds up to its value.
        let friction = if omega.abs() > 1e-9 {
            motor.friction * omega.signum()
        } else if electromagnetic.abs() > motor.friction {
            motor.friction * electromagnetic.signum()
        } else {
            electromagnetic
        };
        (electromagnetic - friction - motor.damping * omega) / inertia
    };
    let play = |duration: f64, hz: f64, theta: &mut f64, omega: &mut f64, field: f64| {
        let amplitude = motor.pull_out(hz);
        let n = (duration / dt).ceil() as usize;
        let h = duration / n as f64;
        for _ in 0..n {
            let (t0, w0) = (*theta, *omega);
            let k1 = (w0, accel(t0, w0, field, amplitude));
            let k2 = (
                w0 + 0.5 * h * k1.1,
                accel(t0 + 0.5 * h * k1.0, w0 + 0.5 * h * k1.1, field, amplitude),
            );
            let k3 = (
                w0 + 0.5 * h * k2.1,
                accel(t0 + 0.5 * h * k2.0, w0 + 0.5 * h * k2.1, field, amplitude),
            );
            let k4 = (
                w0 + h * k3.1,
                accel(t0 + h * k3.0, w0 + h * k3.1, field, amplitude),
            );
            *theta = t0 + h / 6.0 * (k1.0 + 2.0 * k2.0 + 2.0 * k3.0 + k4.0);
            *omega = w0 + h / 6.0 * (k1.1 + 2.0 * k2.1 + 2.0 * k3.1 + k4.1);
        }
    };
    for &p in periods {
        // The step now: the field moves on, then the interval plays.
        field += field_step;
        let duration = f64::from(p) / timer_hz;
        play(duration, 1.0 / duration, &mut theta, &mut omega, field);
    }
    // Held at the last position: the rotor settles (friction damps it).
    for _ in 0..200 {
        play(1e-3, 0.0, &mut theta, &mut omega, field);
    }
    // Electrical turns behind, each four full steps.
    let turns = (poles * (field - theta) / std::f64::consts::TAU).round();
    4 * turns as i64
}

/// The move the player makes of a table: up, 200 steps at the top, down.
fn move_of(periods: &[u32]) -> Vec<u32> {
    let mut player = Player::new(Ramp::steps(periods));
    player.start(2 * periods.len() as u32 + 200);
    std::iter::from_fn(|| player.next_period()).collect()
}

/// The ramp at `margin` from the start a profile takes.
fn at_margin(motor: &Motor, margin: f64) -> Vec<u32> {
    let ramp = motor
        .torque_limited(Some(FMIN), 40_000.0, margin, Timer::new(10_000_000))
        .unwrap();
    let table = Spec::new(Curve::TorqueLimited(ramp), Timer::new(10_000_000))
        .table()
        .unwrap();
    move_of(&table.periods)
}

/// The rotor of this file's integrator, undamped, swings about its lag
/// from the start on: a ramp planned on 0.3 of the torque leaves it the
/// rest, with its own load and half as much again; planned on all of it
/// (0.99), it slips with the heavier load.
#[test]
fn the_rotor_follows_it_and_slips_without_the_margin_under_more_load() {
    let motor = qsh4218(1.36e-5);
    let heavier = qsh4218(1.36e-5 * 1.5);
    let kept = at_margin(&motor, 0.3);
    for (name, m) in [("its own load", &motor), ("1.5 times the load", &heavier)] {
        let lost = steps_lost(m, &kept, 1e7);
        println!("margin 0.3, {name}: {lost} full steps lost");
        assert_eq!(lost, 0, "{name}");
    }
    let greedy = at_margin(&motor, 0.99);
    let lost = steps_lost(&heavier, &greedy, 1e7);
    println!("margin 0.99, 1.5 times the load: {lost} full steps lost");
    assert!(lost != 0, "{lost}");
}

/// 1000 random motors (by a chart or by their windings, 1 to 32
/// microsteps, loads up to ten times the rotor), margins and timers (1 to
/// 72 MHz): every ramp `Motor::torque_limited` gives passes the check at
/// `safety / margin` at every edge of its table; where it cannot, it says
/// so (`MarginUnkept`) rather than give a ramp that keeps less.
#[test]
fn every_ramp_keeps_its_margin_on_its_timer_or_says_it_cannot() {
    let mut rng = Lcg(0x070c_ab1e);
    let (mut kept, mut unkept) = (0, 0);
    for case in 0..1000 {
        let micro = rng.pick(&[1u32, 2, 4, 8, 16, 32]);
        let hold = rng.log_uniform(0.1, 3.0);
        let rotor = hold * rng.log_uniform(1e-5, 3e-5);
        let mut motor = Motor::new(1.8, micro, rotor)
            .with_load_inertia(rotor * 10.0 * rng.next_unit())
            .with_friction(hold * 0.1 * rng.next_unit())
            .with_damping_ratio(0.3 * rng.next_unit());
        // The top of the motor's torque, full steps a second.
        let top = rng.log_uniform(500.0, 5000.0);
        if rng.next_unit() < 0.5 {
            let ohms = rng.log_uniform(0.3, 3.0);
            motor = motor.with_windings(Windings::new(
                ohms,
                ohms * rng.log_uniform(1e-3, 5e-3),
                rng.log_uniform(0.5, 4.0),
                hold,
                rng.log_uniform(12.0, 48.0),
            ));
        } else {
            let n = 3 + (rng.next_unit() * 8.0) as usize;
            let mut nm = hold;
            let points: Vec<(f64, f64)> = (0..n)
                .map(|k| {
                    let point = (top * f64::from(micro) * k as f64 / (n - 1) as f64, nm);
                    nm *= 0.6 + 0.42 * rng.next_unit();
                    point
                })
                .collect();
            motor = motor.with_torque_curve(TorqueCurve::new(&points).unwrap());
        }
        let fmax = top * f64::from(micro) * (0.3 + 0.7 * rng.next_unit());
        let margin = 0.2 + 0.79 * rng.next_unit();
        let mut timer =
            Timer::new(rng.pick(&[1_000_000, 2_000_000, 8_000_000, 16_000_000, 72_000_000]));
        timer.word = Word::U32;
        let ramp = match motor.torque_limited(None, fmax, margin, timer) {
            Ok(ramp) => ramp,
            Err(MotorError::MarginUnkept { .. }) => {
                unkept += 1;
                continue;
            }
            // No torque to spare below `fmax`: nothing to check.
            Err(_) => continue,
        };
        let spec = Spec::new(Curve::TorqueLimited(ramp), timer);
        let Ok(table) = spec.table() else { continue };
        let strict = motor.with_safety(motor.safety / margin);
        let edges = strict.check(&spec, &table.periods);
        assert!(
            !matches!(edges, Err(MotorError::Torque { .. })),
            "case {case}: {motor:?}, fmax {fmax}, margin {margin}, {timer:?}: {edges:?}"
        );
        kept += 1;
    }
    println!("{kept} ramps keep their margin; {unkept} cannot, and say so");
    // Most ramps are made; a few say they cannot keep the margin.
    assert!(kept > 800 && unkept < 20, "{kept} kept, {unkept} unkept");
}
