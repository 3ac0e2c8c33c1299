//! The motor model: the compile-time torque check (`Motor::check`) and the
//! step-loss simulation (`simulate::run`) on the same ramps.
//!
//! The motor of most tests is a NEMA 17 with a 2.0e-5 kg·m² load, the
//! figures of `tests/ui/motor_*.rs` and `tests/toml_errors/motor_*.toml`
//! (whose messages are pinned there). Moves are played as firmware plays
//! them, with `Player`: up the table and down it again, ending at rest.
//!
//! Simulations print their figures (`cargo test --test motor -- --nocapture`).

use test_support as common;

use common::motors::CURVE;
use profile_codegen::Generated;
use profile_codegen::SpecTables;
use profile_codegen::motor::{MAX_CURVE_POINTS, Motor, MotorError, StartLimit, TorqueCurve};
use profile_codegen::profiles::Profiles;
use profile_codegen::simulate::{self, MAX_STEPS, SimError, SimOptions, SimResult};
use profile_core::player::{Player, Ramp};
use profile_core::{Curve, Key, Linear, LinearExtent, Spec, Timer};
use stepper_profiles::period_table;

/// The tests' motor at `microsteps`: its curve in the table's step
/// frequency, a 2.0e-5 kg·m² load, `safety = 1.5`, `max_start_hz = 1200`
/// full steps/s.
fn nema17(microsteps: u32) -> Motor {
    common::motors::nema17(microsteps, 2.0e-5)
        .with_safety(1.5)
        .with_max_start_hz(1200.0 * microsteps as f64)
}

/// A constant-acceleration ramp from 300 to 2000 full steps/s at `accel`
/// full steps/s², in table steps of `microsteps`.
fn ramp(accel: f64, microsteps: u32) -> (Spec, Vec<u32>) {
    let k = microsteps as f64;
    let timer = if microsteps == 1 {
        1_000_000
    } else {
        10_000_000
    };
    let spec = Spec::new(
        Curve::Linear(Linear {
            fmin: 300.0 * k,
            fmax: 2000.0 * k,
            extent: LinearExtent::Accel(accel * k),
        }),
        Timer::new(timer),
    );
    let periods = spec.table().unwrap().periods;
    (spec, periods)
}

/// The move a `Player` plays from `table`: up it and down it again.
fn round_trip(table: &[u32]) -> Vec<u32> {
    let mut player = Player::new(Ramp::steps(table));
    player.start(2 * table.len() as u32);
    std::iter::from_fn(|| player.next_period()).collect()
}

fn simulate(motor: &Motor, spec: &Spec, periods: &[u32], options: &SimOptions) -> SimResult {
    let result = simulate::run(motor, spec, periods, options).unwrap();
    println!(
        "  {} pulses, dt {:.3e} s: lost {} steps, {} slips (first at pulse {:?}), max lag {:.2}° ({:.3} steps) at pulse {}, overshoot {:.4} steps, final error {:.4} steps, settled {}, {} integration steps",
        periods.len(),
        options.dt_s,
        result.lost_steps,
        result.slips,
        result.first_slip_pulse,
        result.max_lag_deg,
        result.max_lag_steps,
        result.max_lag_pulse,
        result.overshoot_steps,
        result.final_error_steps,
        result.settled,
        result.steps
    );
    result
}

#[test]
fn torque_curve_interpolates_and_gives_nothing_beyond_its_last_point() {
    let c = TorqueCurve::new(&[(100.0, 0.4), (1000.0, 0.3), (3000.0, 0.1)]).unwrap();
    assert_eq!(c.points(), [(100.0, 0.4), (1000.0, 0.3), (3000.0, 0.1)]);
    assert_eq!(c.top(), 3000.0);
    // Below the first point, the first torque holds.
    assert_eq!(c.torque(0.0), 0.4);
    assert_eq!(c.torque(100.0), 0.4);
    // Linear between points.
    assert!((c.torque(550.0) - 0.35).abs() < 1e-12);
    assert_eq!(c.torque(1000.0), 0.3);
    assert!((c.torque(2000.0) - 0.2).abs() < 1e-12);
    assert!((c.torque(2500.0) - 0.15).abs() < 1e-12);
    // At the last point its torque; beyond it the motor is not
    // characterised and gives nothing.
    assert_eq!(c.torque(3000.0), 0.1);
    assert_eq!(c.torque(3000.001), 0.0);
    assert_eq!(c.torque(f64::INFINITY), 0.0);
    // One point: a flat curve up to its frequency.
    let one = TorqueCurve::new(&[(500.0, 0.2)]).unwrap();
    assert_eq!(
        (one.torque(0.0), one.torque(500.0), one.torque(501.0)),
        (0.2, 0.2, 0.0)
    );
    // From 1 to MAX_CURVE_POINTS points.
    assert!(TorqueCurve::new(&[]).is_none());
    assert!(TorqueCurve::new(&[(0.0, 1.0); MAX_CURVE_POINTS]).is_some());
    assert!(TorqueCurve::new(&[(0.0, 1.0); MAX_CURVE_POINTS + 1]).is_none());
}

/// Halving the integration step changes nothing that matters: the same
/// steps lost, the same slips, the largest lag within 1° electrical and the
/// overshoot within 0.05 table step.
#[test]
fn halving_the_integration_step_changes_nothing() {
    for (name, accel, microsteps) in [
        ("gentle, 1/8 steps", 2_000.0, 8),
        ("near the limit, full steps", 100_000.0, 1),
        ("too fast, full steps", 400_000.0, 1),
    ] {
        let motor = nema17(microsteps);
        let (spec, table) = ramp(accel, microsteps);
        let moves = round_trip(&table);
        let options = SimOptions::suggested(&motor, &spec, &moves);
        let half = SimOptions {
            dt_s: options.dt_s / 2.0,
            ..options
        };
        println!("{name} ({accel} full steps/s²):");
        let a = simulate(&motor, &spec, &moves, &options);
        let b = simulate(&motor, &spec, &moves, &half);
        assert_eq!(a.lost_steps, b.lost_steps, "{name}: lost steps");
        assert_eq!(a.slips, b.slips, "{name}: slips");
        assert_eq!(a.first_slip_pulse, b.first_slip_pulse, "{name}: first slip");
        assert!(
            (a.max_lag_deg - b.max_lag_deg).abs() < 1.0,
            "{name}: max lag {} vs {}",
            a.max_lag_deg,
            b.max_lag_deg
        );
        assert!(
            (a.overshoot_steps - b.overshoot_steps).abs() < 0.05,
            "{name}: overshoot {} vs {}",
            a.overshoot_steps,
            b.overshoot_steps
        );
        assert!(a.settled && b.settled, "{name}: settled");
        assert!(
            b.steps >= 2 * a.steps - 2 * moves.len() as u64,
            "{name}: steps"
        );
    }
}

/// 300 to 2000 full steps/s at 2000 full steps/s² in 1/8 steps: the check
/// finds torque to spare at every step and the rotor, simulated, follows
/// with its lag well below the 90° electrical of pull-out. (The lag is not
/// near 0: starting at 300 full steps/s from rest is a jump in speed, and the
/// rotor, damped by friction only, swings about the command all along.)
#[test]
fn a_gentle_ramp_passes_the_check_and_the_simulation() {
    let motor = nema17(8);
    let (spec, table) = ramp(2_000.0, 8);
    let figures = motor.check(&spec, &table).unwrap();
    println!("gentle: {figures:?}");
    assert!(figures.min_margin_nm > 0.1, "{figures:?}");
    let moves = round_trip(&table);
    let result = simulate(
        &motor,
        &spec,
        &moves,
        &SimOptions::suggested(&motor, &spec, &moves),
    );
    assert_eq!(result.lost_steps, 0);
    assert_eq!(result.slips, 0);
    assert_eq!(result.first_slip_pulse, None);
    assert!(result.max_lag_deg < 60.0, "{result:?}");
    assert!(result.overshoot_steps < 8.0, "{result:?}");
    assert!(result.final_error_steps.abs() < 1.0, "{result:?}");
    assert!(result.settled);
}

/// 200 000 full steps/s²: step 7 needs more torque than the curve gives over
/// the safety factor. The macro and the profiles file refuse it with the same
/// words (`tests/ui/motor_cannot_follow.stderr`,
/// `tests/toml_errors/motor_cannot_follow.txt`).
#[test]
fn an_aggressive_ramp_fails_the_check() {
    let motor = nema17(1);
    let (spec, table) = ramp(200_000.0, 1);
    let error = motor.check(&spec, &table).unwrap_err();
    assert!(
        matches!(
            error,
            MotorError::Torque {
                step: 7,
                beyond_curve: false,
                ..
            }
        ),
        "{error:?}"
    );
    assert_eq!(error.key(), Key::MOTOR);
    assert_eq!(
        error.to_string(),
        "the motor cannot follow step 7 at 1757.5 Hz: it needs 0.1791 N·m but gives \
         0.1746 N·m after the safety factor, short by 0.0045 N·m"
    );
    // Figures far beyond any motor's (a `damping = 1e300`) read in
    // exponent form, not in 300 digits.
    let huge = MotorError::Torque {
        step: 0,
        hz: 303.27,
        needed_nm: 9.528640138276596e300,
        available_nm: 0.25863,
        beyond_curve: false,
        from_windings: None,
    };
    assert_eq!(
        huge.to_string(),
        "the motor cannot start at 303.3 Hz: it needs 9.52864e300 N·m but gives 0.2586 N·m \
         after the safety factor, short by 9.52864e300 N·m"
    );
    let start = MotorError::Start {
        hz: 1e20,
        limit: StartLimit::Corrected {
            hz: 1e19,
            max_start_hz: 1e300,
            factor: 1e281,
        },
    };
    assert_eq!(
        start.to_string(),
        "the motor cannot start at 1e20 Hz with its load: it starts at 1e19 Hz at most, \
         `max_start_hz = 1e300` (without load) over sqrt(1 + load_inertia / rotor_inertia) = \
         1e281"
    );
    // Beyond the curve's last point the motor gives nothing, and says so.
    let mut short = motor;
    short.torque_curve = TorqueCurve::new(&CURVE[..3]);
    let (spec, table) = ramp(2_000.0, 1);
    let error = short.check(&spec, &table).unwrap_err();
    assert!(
        error
            .to_string()
            .ends_with("(the frequency is beyond the last point of `torque_curve`)"),
        "{error}"
    );
}

/// 400 000 full steps/s²: the check refuses it even without a safety factor,
/// and the simulated rotor slips and ends whole electrical turns (4 full
/// steps each) behind.
#[test]
fn a_ramp_too_fast_loses_steps_and_the_check_refuses_it() {
    let motor = nema17(1);
    let (spec, table) = ramp(400_000.0, 1);
    let error = motor.check(&spec, &table).unwrap_err();
    assert!(
        matches!(error, MotorError::Torque { step: 1, .. }),
        "{error}"
    );
    let unsafe_motor = motor.with_safety(1.0);
    assert!(matches!(
        unsafe_motor.check(&spec, &table),
        Err(MotorError::Torque { step: 1, .. })
    ));

    // The ramp alone, then held.
    let up = simulate(
        &motor,
        &spec,
        &table,
        &SimOptions::suggested(&motor, &spec, &table),
    );
    // A whole move.
    let moves = round_trip(&table);
    let result = simulate(
        &motor,
        &spec,
        &moves,
        &SimOptions::suggested(&motor, &spec, &moves),
    );
    for r in [up, result] {
        assert!(r.lost_steps > 0, "{r:?}");
        assert_eq!(r.lost_steps % 4, 0, "whole electrical turns: {r:?}");
        assert!(r.slips > 0 && r.max_lag_deg > 180.0, "{r:?}");
        assert!(
            r.first_slip_pulse
                .is_some_and(|p| p as usize <= table.len())
        );
        assert!(r.settled);
        assert!(
            (r.final_error_steps - r.lost_steps as f64).abs() < 0.5,
            "{r:?}"
        );
    }
}

/// The start from rest, judged with the load: a datasheet's `max_start_hz`
/// (no load) is corrected by `sqrt(1 + J_load / J_rotor)`; without it the
/// model's rotor must follow the first period from rest. The simulation of
/// the whole move agrees with both verdicts
/// (`tests/ui/motor_start_too_fast.stderr`,
/// `tests/toml_errors/motor_start_too_fast.txt` pin the message).
#[test]
fn a_start_the_loaded_rotor_cannot_follow_is_an_error() {
    let motor = nema17(1);
    let spec = |fmin: f64| {
        Spec::new(
            Curve::Linear(Linear {
                fmin,
                fmax: 2000.0,
                extent: LinearExtent::Accel(2_000.0),
            }),
            Timer::new(1_000_000),
        )
    };
    let factor = (1.0f64 + 2.0e-5 / 5.4e-6).sqrt();
    let fast = spec(1190.0);
    let table = fast.table().unwrap().periods;
    let error = motor.check(&fast, &table).unwrap_err();
    let MotorError::Start {
        hz,
        limit:
            StartLimit::Corrected {
                hz: limit,
                max_start_hz,
                factor: f,
            },
    } = error
    else {
        panic!("{error:?}");
    };
    assert!((hz - 1_000_000.0 / table[0] as f64).abs() < 1e-9, "{hz}");
    assert_eq!(max_start_hz, 1200.0);
    assert!((f - factor).abs() < 1e-12 && (limit - 1200.0 / factor).abs() < 1e-9);
    assert_eq!(
        error.to_string(),
        "the motor cannot start at 1190.5 Hz with its load: it starts at 553.3 Hz at most, \
         `max_start_hz = 1200` (without load) over sqrt(1 + load_inertia / rotor_inertia) = 2.169"
    );
    // Below the corrected limit the start passes.
    let slow = spec(500.0);
    assert!(motor.check(&slow, &slow.table().unwrap().periods).is_ok());

    // Without `max_start_hz`, from the model: 1190 and 900 refused, 600 not.
    let mut model = motor;
    model.max_start_hz = None;
    let error = model.check(&fast, &table).unwrap_err();
    let MotorError::Start {
        limit: StartLimit::Model { hz: limit },
        ..
    } = error
    else {
        panic!("{error:?}");
    };
    println!("start limit from the model: {limit:.1} Hz");
    assert!((600.0..900.0).contains(&limit), "{limit}");
    assert!(!model.starts_at(limit * 1.01) && model.starts_at(limit));
    assert_eq!(
        error.to_string(),
        format!(
            "the motor cannot start at 1190.5 Hz with its load: it starts at {limit:.1} Hz at \
             most, the fastest rate found (by bisection below 1190.5 Hz) that the model's \
             rotor pulls in to from rest: it reaches the field's speed before lagging 180° \
             electrical (torque over the safety factor; give `max_start_hz` from the datasheet \
             to use it instead)"
        )
    );
    // The simulation predicts, without a safety factor: so does the check
    // here.
    let model = model.with_safety(1.0);
    for (fmin, follows) in [(600.0, true), (900.0, false), (1190.0, false)] {
        let spec = spec(fmin);
        let table = spec.table().unwrap().periods;
        assert_eq!(model.check(&spec, &table).is_ok(), follows, "{fmin}");
        // The simulated move, up and down, with the same verdict.
        let moves = round_trip(&table);
        let result = simulate(
            &model,
            &spec,
            &moves,
            &SimOptions::suggested(&model, &spec, &moves),
        );
        assert_eq!(result.lost_steps == 0, follows, "{fmin}: {result:?}");
    }
}

/// Every parameter is checked, with the message the front ends show.
#[test]
fn motor_parameters_are_checked() {
    let good = nema17(1);
    assert_eq!(good.validate(), Ok(()));
    let message = |m: Motor| m.validate().unwrap_err().to_string();
    // `good` with one field changed.
    let with = |change: fn(&mut Motor)| {
        let mut m = good;
        change(&mut m);
        m
    };
    // Every figure in its range, ends included, and nothing beyond: the
    // value outside each end, NaN and infinity refused with the range.
    type Field = fn(&mut Motor, f64);
    let fields: [(&str, Field, f64, f64, &str); 8] = [
        (
            "step_angle",
            |m, v| m.step_angle = v,
            0.01,
            180.0,
            "from 0.01 to 180 degrees",
        ),
        (
            "rotor_inertia",
            |m, v| m.rotor_inertia = v,
            1e-12,
            10.0,
            "from 1e-12 to 10 kg·m²",
        ),
        (
            "load_inertia",
            |m, v| m.load_inertia = v,
            0.0,
            1e4,
            "from 0 to 10000 kg·m²",
        ),
        (
            "friction",
            |m, v| m.friction = v,
            0.0,
            1e4,
            "from 0 to 10000 N·m",
        ),
        (
            "damping",
            |m, v| m.damping = v,
            0.0,
            1e4,
            "from 0 to 10000 N·m·s/rad",
        ),
        (
            "damping_ratio",
            |m, v| m.damping_ratio = v,
            0.0,
            1.0,
            "from 0 to 1, a fraction",
        ),
        ("safety", |m, v| m.safety = v, 1.0, 1000.0, "from 1 to 1000"),
        (
            "max_start_hz",
            |m, v| m.max_start_hz = Some(v),
            1e-3,
            1e8,
            "from 0.001 to 1e8 Hz",
        ),
    ];
    for (key, set, lo, hi, expected) in fields {
        for v in [lo, hi] {
            let mut m = good;
            set(&mut m, v);
            assert_eq!(m.validate(), Ok(()), "{key} = {v}");
        }
        let below = if lo > 0.0 { lo * 0.999 } else { -1e-9 };
        for v in [below, hi * 1.001, 1e300, f64::NAN, f64::INFINITY] {
            let mut m = good;
            set(&mut m, v);
            let e = message(m);
            assert!(
                e.starts_with(&format!("`{key}` must be {expected}")),
                "{key} = {v}: {e}"
            );
        }
    }
    assert_eq!(
        message(with(|m| m.step_angle = 0.0)),
        "`step_angle` must be from 0.01 to 180 degrees (got 0)"
    );
    assert_eq!(
        message(with(|m| m.microsteps = 0)),
        "`microsteps` must be from 1 to 1024 (got 0)"
    );
    assert_eq!(with(|m| m.microsteps = 1024).validate(), Ok(()));
    assert_eq!(
        message(with(|m| m.microsteps = 1025)),
        "`microsteps` must be from 1 to 1024 (got 1025)"
    );
    // A motor refused starts at no rate, whatever it reads: no answer
    // from figures the model cannot take, and no time spent on them.
    let refused = with(|m| m.microsteps = u32::MAX);
    assert!(!refused.starts_at(100.0));
    assert_eq!(refused.start_limit(1e4), StartLimit::Model { hz: 0.0 });
    assert_eq!(
        message(with(|m| m.rotor_inertia = f64::NAN)),
        "`rotor_inertia` must be from 1e-12 to 10 kg·m² (got NaN)"
    );
    assert_eq!(
        message(good.with_load_inertia(-1e-6)),
        "`load_inertia` must be from 0 to 10000 kg·m² (got -0.000001)"
    );
    assert_eq!(
        message(good.with_max_start_hz(1e300)),
        "`max_start_hz` must be from 0.001 to 1e8 Hz (got 1e300)"
    );
    let curve = |points: &[(f64, f64)]| {
        let mut m = good.with_torque_curve(TorqueCurve::new(points).unwrap());
        m.windings = None;
        m
    };
    assert_eq!(
        message(curve(&[(0.0, 0.4), (1000.0, 0.3), (1000.0, 0.2)])),
        "`torque_curve` point 3 (1000, 0.2) must have a frequency higher than the point before it and up to 1e8 Hz, and a torque above 0 and up to 10000 N·m"
    );
    assert_eq!(
        message(curve(&[(0.0, 0.4), (1000.0, 0.0)])),
        "`torque_curve` point 2 (1000, 0) must have a frequency higher than the point before it and up to 1e8 Hz, and a torque above 0 and up to 10000 N·m"
    );
    assert_eq!(
        message(curve(&[(-1.0, 0.4)])),
        "`torque_curve` point 1 (-1, 0.4) must have a frequency from 0 up to 1e8 Hz, and a torque above 0 and up to 10000 N·m"
    );
    // A point that is not a finite number is not "not rising".
    assert_eq!(
        message(curve(&[(0.0, 0.4), (f64::INFINITY, 0.3)])),
        "`torque_curve` point 2's frequency must be a finite number (got inf)"
    );
    assert_eq!(
        message(curve(&[(0.0, 0.4), (1000.0, f64::NAN)])),
        "`torque_curve` point 2's torque must be a finite number (got NaN)"
    );
    assert_eq!(
        message(curve(&[(f64::NAN, f64::INFINITY)])),
        "`torque_curve` point 1's frequency must be a finite number (got NaN)"
    );
    // Numbers far out of range in exponent form.
    assert_eq!(
        message(curve(&[(0.0, 0.4), (1e300, 0.3), (1e299, 0.2)])),
        "`torque_curve` point 2 (1e300, 0.3) must have a frequency higher than the point before it and up to 1e8 Hz, and a torque above 0 and up to 10000 N·m"
    );
    // The curve's ends: 1e8 Hz and 10 000 N·m, and no more.
    assert_eq!(curve(&[(0.0, 1e4), (1e8, 0.3)]).validate(), Ok(()));
    assert_eq!(
        message(curve(&[(0.0, 1.001e4)])),
        "`torque_curve` point 1 (0, 10010) must have a frequency from 0 up to 1e8 Hz, and a torque above 0 and up to 10000 N·m"
    );
    assert_eq!(
        message(curve(&[(0.0, 0.4), (1.001e8, 0.3)])),
        "`torque_curve` point 2 (100100000, 0.3) must have a frequency higher than the point before it and up to 1e8 Hz, and a torque above 0 and up to 10000 N·m"
    );
    let e = curve(&[(0.0, 0.4), (500.0, 0.3)])
        .validate()
        .map_err(|e| e.key());
    assert_eq!(e, Ok(()));
    assert_eq!(
        curve(&[(0.0, 0.4), (0.0, 0.3)])
            .validate()
            .unwrap_err()
            .key(),
        Key::TORQUE_CURVE
    );
}

/// The simulation refuses what it cannot run and never panics.
#[test]
fn the_simulation_refuses_bad_input() {
    let motor = nema17(1);
    let (spec, table) = ramp(2_000.0, 1);
    let run = |m: &Motor, s: &Spec, p: &[u32], dt_s: f64, settle_s: f64| {
        simulate::run(m, s, p, &SimOptions { dt_s, settle_s })
    };
    for (dt, settle) in [
        (0.0, 0.0),
        (-1e-6, 0.0),
        (f64::NAN, 0.0),
        (f64::INFINITY, 0.0),
        (1e-6, -1.0),
        (1e-6, f64::NAN),
        (1e-6, f64::INFINITY),
    ] {
        assert!(
            matches!(
                run(&motor, &spec, &table, dt, settle),
                Err(SimError::Options { .. })
            ),
            "dt {dt}, settle {settle}"
        );
    }
    assert_eq!(
        SimError::Options {
            dt_s: -1e300,
            settle_s: 0.5
        }
        .to_string(),
        "the integration step must be a finite number of seconds above 0 and the settle time \
         one of 0 or more (got dt_s = -1e300, settle_s = 0.5)"
    );
    // Too many steps: refused before running, with how many it needed.
    let e = run(&motor, &spec, &table, 1e-12, 0.0).unwrap_err();
    assert!(
        matches!(e, SimError::TooManySteps { needed, max: MAX_STEPS, .. } if needed > MAX_STEPS),
        "{e:?}"
    );
    assert!(e.to_string().starts_with("the simulation needs "), "{e}");
    // Beyond what 64 bits count: no made-up count.
    let e = run(&motor, &spec, &table, 1e-300, 0.0).unwrap_err();
    assert!(
        e.to_string().starts_with(
            "the simulation needs more integration steps than 64 bits count, more than the \
             20000000 allowed: "
        ),
        "{e}"
    );
    assert!(matches!(
        run(&motor, &spec, &[u32::MAX; 100], 1e-9, 0.0),
        Err(SimError::TooManySteps { .. })
    ));
    assert!(matches!(
        run(&motor, &spec, &table, 1e-6, 1e9),
        Err(SimError::TooManySteps { .. })
    ));
    // An invalid motor, a timer at 0 Hz.
    let mut bad = motor;
    bad.rotor_inertia = 0.0;
    assert_eq!(
        run(&bad, &spec, &table, 1e-5, 0.0),
        Err(SimError::Motor(MotorError::Invalid {
            key: Key::ROTOR_INERTIA,
            value: 0.0,
            expected: "from 1e-12 to 10 kg·m²"
        }))
    );
    let mut stopped = spec;
    stopped.timer.timer_hz = 0;
    assert_eq!(
        run(&motor, &stopped, &table, 1e-5, 0.0),
        Err(SimError::Timer)
    );
    // No pulses: the rotor stays. Zero-tick periods: pulses at one instant.
    let still = run(&motor, &spec, &[], 1e-5, 0.01).unwrap();
    assert_eq!((still.lost_steps, still.slips), (0, 0));
    assert_eq!(still.max_lag_deg, 0.0);
    assert!(still.settled);
    let burst = run(&motor, &spec, &[0, 0, 0, 0, 0, 0, 0, 0, 0], 1e-5, 0.05).unwrap();
    assert!(burst.max_lag_deg >= 810.0 - 1e-9, "{burst:?}");
    assert_eq!(burst.lost_steps % 4, 0);
}

/// `period_table!` takes the motor keys inline: the table is the same, the
/// check passes at compile time (a refused one is in `tests/ui`).
#[test]
fn the_macro_checks_inline_motor_keys() {
    static WITH_MOTOR: [u16; 978] = period_table!(
        curve = linear,
        fmin = 300,
        fmax = 2000,
        accel = 2000,
        timer_hz = 1_000_000,
        step_angle = 1.8,
        rotor_inertia = 5.4e-6,
        load_inertia = 2.0e-5,
        torque_curve = [
            (0, 0.40),
            (500, 0.38),
            (1000, 0.33),
            (2000, 0.24),
            (4000, 0.12),
            (6000, 0.06)
        ],
        friction = 0.02,
        damping = 0,
        safety = 1.5,
        max_start_hz = 1200,
    );
    let (_, table) = ramp(2_000.0, 1);
    let plain: Vec<u32> = WITH_MOTOR.iter().map(|&p| u32::from(p)).collect();
    assert_eq!(plain, table);
}

/// The profiles file: a `[motors.NAME]` table fills the keys of the profiles
/// that name it, and the loaded profile carries the motor and its figures.
#[test]
fn profiles_name_their_motor() {
    let source = r#"
[motors.nema17]
step_angle = 1.8
rotor_inertia = 5.4e-6
load_inertia = 2.0e-5
torque_curve = [[0, 0.40], [500, 0.38], [1000, 0.33], [2000, 0.24], [4000, 0.12], [6000, 0.06]]
friction = 0.02
damping = 0.0
safety = 1.5
max_start_hz = 1200

[profiles.gentle]
curve = "linear"
fmin = 300
fmax = 2000
accel = 2000
timer_hz = 1_000_000
motor = "nema17"

[profiles.unbound]
curve = "linear"
fmin = 300
fmax = 2000
accel = 2000
timer_hz = 1_000_000
"#;
    let profiles = Profiles::parse("profiles.toml", source).unwrap();
    let [gentle, unbound] = profiles.profiles() else {
        panic!("two profiles");
    };
    assert_eq!(gentle.motor, Some(nema17(1)));
    assert_eq!(unbound.motor, None);
    assert_eq!(unbound.torque, None);
    let Generated::Steps(table) = &gentle.table else {
        panic!("a per-step table");
    };
    let figures = nema17(1).check(&table.spec, &table.periods).unwrap();
    assert_eq!(gentle.torque, Some(figures));
    // The emitted module carries the margin, to the last bit.
    let source = profiles.rust_source();
    let value = |name: &str| -> String {
        let at = source.find(&format!("pub const {name}: ")).expect(name);
        let value = source[at..].split('=').nth(1).expect("a value");
        value
            .split(';')
            .next()
            .expect("a statement")
            .trim()
            .to_string()
    };
    let margin: f64 = value("TORQUE_MARGIN_NM").parse().unwrap();
    assert_eq!(margin.to_bits(), figures.min_margin_nm.to_bits());
    assert_eq!(value("TORQUE_MARGIN_STEP"), figures.step.to_string());
}

/// `[defaults]` may name the motor and hold motor keys: the motor's keys
/// fill what a profile omits, defaults what is still missing, and a profile
/// that names no motor takes no motor key from the defaults.
#[test]
fn defaults_name_the_motor_and_hold_its_keys() {
    let source = r#"
[defaults]
timer_hz = 1_000_000
motor = "nema17"
safety = 1.5
max_start_hz = 1200

[motors.nema17]
step_angle = 1.8
rotor_inertia = 5.4e-6
load_inertia = 2.0e-5
torque_curve = [[0, 0.40], [500, 0.38], [1000, 0.33], [2000, 0.24], [4000, 0.12], [6000, 0.06]]
friction = 0.02

[profiles.gentle]
curve = "linear"
fmin = 300
fmax = 2000
accel = 2000
"#;
    let profiles = Profiles::parse("profiles.toml", source).unwrap();
    assert_eq!(profiles.profiles()[0].motor, Some(nema17(1)));
    // Without `motor` in the defaults, `safety` there makes no motor.
    let source = source.replace("motor = \"nema17\"\n", "");
    let profiles = Profiles::parse("profiles.toml", &source).unwrap();
    assert_eq!(profiles.profiles()[0].motor, None);
}

/// The worked example: every profile of the shipped `profiles.toml` that
/// names a motor passes the check and, played as a whole move, loses no step.
#[test]
fn shipped_profiles_with_a_motor_follow_their_ramps() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("profiles.toml");
    let profiles = Profiles::load(&path).unwrap();
    let mut bound = 0;
    for p in profiles.profiles() {
        let Some(motor) = &p.motor else {
            continue;
        };
        bound += 1;
        let spec = *p.table.spec();
        let table = p.table.step_periods();
        let figures = motor.check(&spec, &table).unwrap();
        assert_eq!(p.torque, Some(figures), "{}", p.name);
        println!(
            "{}: smallest margin {:.4} N·m at step {} ({:.1} Hz): {:.4} needed of {:.4} available",
            p.name,
            figures.min_margin_nm,
            figures.step,
            figures.hz,
            figures.needed_nm,
            figures.available_nm
        );
        let moves = round_trip(&table);
        let options = SimOptions::suggested(motor, &spec, &moves);
        let result = simulate(motor, &spec, &moves, &options);
        assert_eq!(result.lost_steps, 0, "{}", p.name);
        assert_eq!(result.slips, 0, "{}", p.name);
        assert!(result.max_lag_deg < 90.0, "{}: {result:?}", p.name);
        assert!(result.settled, "{}", p.name);
    }
    assert!(bound >= 1, "no shipped profile names a motor");
}

/// The start is judged on every table: a one-entry table whose friction the
/// motor cannot overcome does not pass, and its message says it is the start.
#[test]
fn every_table_is_checked_at_its_start() {
    let spec = Spec::new(
        Curve::Linear(Linear {
            fmin: 400.0,
            fmax: 500.0,
            extent: LinearExtent::Len(1),
        }),
        Timer::new(1_000_000),
    );
    let table = spec.table().unwrap().periods;
    assert_eq!(table.len(), 1);
    let stuck = nema17(1).with_friction(10.0);
    let error = stuck.check(&spec, &table).unwrap_err();
    assert!(
        matches!(error, MotorError::Torque { step: 0, .. }),
        "{error:?}"
    );
    assert_eq!(
        error.to_string(),
        "the motor cannot start at 450.0 Hz: it needs 10.0000 N·m but gives 0.2547 N·m after \
         the safety factor, short by 9.7453 N·m"
    );
    // The same motor with its real friction starts; the start is the only edge.
    let figures = nema17(1).check(&spec, &table).unwrap();
    assert_eq!(figures.step, 0);
    // 2222 ticks at 1 MHz: 450.045 Hz, where the curve gives 0.38199 N·m.
    let available = (0.4 - 0.02 * (1e6 / 2222.0) / 500.0) / 1.5;
    assert!(
        (figures.min_margin_nm - (available - 0.02)).abs() < 1e-12,
        "{figures:?}"
    );
    // And the check reports the start edge for plots, before the others.
    let (ramp_spec, ramp_table) = ramp(2_000.0, 1);
    let mut steps = Vec::new();
    nema17(1)
        .check_with(&ramp_spec, &ramp_table, |step, _, _, _| steps.push(step))
        .unwrap();
    assert_eq!(steps.len(), ramp_table.len());
    assert_eq!(steps[..3], [0, 1, 2]);
}

/// No torque the check computes is ever a NaN or an infinity: figures
/// beyond any motor's are refused, and the largest figures taken, on the
/// fastest timer, give finite torques.
#[test]
fn the_check_never_passes_a_non_finite_torque() {
    let (spec, table) = ramp(2_000.0, 1);
    let error = nema17(1)
        .with_load_inertia(1e308)
        .check(&spec, &table)
        .unwrap_err();
    assert_eq!(
        error.to_string(),
        "`load_inertia` must be from 0 to 10000 kg·m² (got 1e308)"
    );
    assert_eq!(error.key(), Key::LOAD_INERTIA);
    let error = nema17(1)
        .with_damping(1e308)
        .check(&spec, &table)
        .unwrap_err();
    assert_eq!(
        error.to_string(),
        "`damping` must be from 0 to 10000 N·m·s/rad (got 1e308)"
    );
    // Every figure at the end of its range that makes torques largest, a
    // table of 1-tick steps on a 4 GHz timer: the check refuses it for
    // want of torque, in finite figures.
    let mut extreme = nema17(1)
        .with_load_inertia(1e4)
        .with_friction(1e4)
        .with_damping(1e4);
    (extreme.rotor_inertia, extreme.step_angle) = (10.0, 180.0);
    let fast = Spec::new(
        Curve::Linear(Linear {
            fmin: 1e9,
            fmax: 2e9,
            extent: LinearExtent::Accel(1e18),
        }),
        Timer::new(4_000_000_000),
    );
    let periods = fast.table().unwrap().periods;
    match extreme.check(&fast, &periods) {
        Err(MotorError::Torque {
            needed_nm,
            available_nm,
            ..
        }) => assert!(needed_nm.is_finite() && available_nm.is_finite()),
        other => panic!("{other:?}"),
    }
    // An inertia too large to accelerate is refused, whatever it reads.
    let mut heavy = nema17(1).with_load_inertia(0.0);
    heavy.rotor_inertia = 1.7e308;
    assert!(heavy.check(&spec, &table).is_err());
    assert_eq!(
        nema17(1).check(&spec, &[]),
        Err(MotorError::EmptyTable),
        "an empty table"
    );
}

/// A step too long for the integrator to be stable is refused, with the
/// bound; a run too long says which step would fit, and that step works.
#[test]
fn the_simulation_refuses_unstable_steps_and_says_what_fits() {
    let motor = nema17(1);
    let (spec, table) = ramp(2_000.0, 1);
    // ω = sqrt(0.4 N·m · 50 / 2.54e-5 kg·m²) = 887 rad/s: at most 1.13 ms.
    let error = simulate::run(
        &motor,
        &spec,
        &table,
        &SimOptions {
            dt_s: 2e-3,
            settle_s: 0.0,
        },
    )
    .unwrap_err();
    assert_eq!(
        error.to_string(),
        "the integration step of 2.000e-3 s is too long for this rotor: the model is \
         integrated stably with steps of at most 1.127e-3 s"
    );
    let SimError::TooManySteps {
        fits_with_dt_s: Some(fits),
        ..
    } = simulate::run(
        &motor,
        &spec,
        &table,
        &SimOptions {
            dt_s: 1e-10,
            settle_s: 0.1,
        },
    )
    .unwrap_err()
    else {
        panic!("expected a step that fits")
    };
    let result = simulate::run(
        &motor,
        &spec,
        &table,
        &SimOptions {
            dt_s: fits,
            settle_s: 0.1,
        },
    );
    assert!(result.is_ok(), "{result:?}");
    // A settle time no step can fit says so.
    let error = simulate::run(
        &motor,
        &spec,
        &table,
        &SimOptions {
            dt_s: 1e-6,
            settle_s: 1e6,
        },
    )
    .unwrap_err();
    assert!(
        error
            .to_string()
            .ends_with("no stable step fits; simulate a shorter table or a shorter settle time"),
        "{error}"
    );
    // The suggested options are always accepted, even for a stiff, damped rotor.
    let stiff = motor.with_damping(0.5).with_torque_curve(
        TorqueCurve::new(&[(0.0, 4000.0), (2000.0, 3000.0), (4000.0, 100.0)]).unwrap(),
    );
    let options = SimOptions::suggested(&stiff, &spec, &table);
    assert!(simulate::run(&stiff, &spec, &table, &options).is_ok());
}

/// Electromagnetic damping, `damping_ratio`: near the check's limit the
/// undamped rotor's swing loses or gains steps on moves whose every edge has
/// torque to spare; with the field-referenced damping of a real motor
/// (ζ = 0.1) those moves keep every step, and the check, which plays the
/// ends of the move to the same damped rotor, passes them.
#[test]
fn electromagnetic_damping_calms_the_swing_the_check_cannot_see() {
    let mut undamped = nema17(1).with_safety(1.0);
    undamped.max_start_hz = None;
    let damped = undamped.with_damping_ratio(0.1);
    // D = 2 ζ sqrt(K J), K = N_r T_hold.
    let k = 50.0 * 0.40;
    let d = 2.0 * 0.1 * (k * (5.4e-6f64 + 2.0e-5)).sqrt();
    assert!((damped.field_damping() - d).abs() < 1e-15);
    assert!((damped.stiffness() - k).abs() < 1e-9);
    // What the check says of these moves undamped (the motor page's figures).
    for accel in [
        100_000.0, 120_000.0, 140_000.0, 160_000.0, 180_000.0, 200_000.0,
    ] {
        let (spec, table) = ramp(accel, 1);
        for (motor, safety) in [(nema17(1), "1.5"), (undamped, "1")] {
            match motor.check(&spec, &table) {
                Ok(f) => println!(
                    "{accel} full steps/s², safety {safety}: {:.3} N·m to spare",
                    f.min_margin_nm
                ),
                Err(e) => println!("{accel} full steps/s², safety {safety}: {e}"),
            }
        }
    }
    for (accel, undamped_loses) in [
        (120_000.0, true),
        (140_000.0, false),
        (160_000.0, true),
        (180_000.0, true),
    ] {
        let (spec, table) = ramp(accel, 1);
        let moves = round_trip(&table);
        let lost = |motor: &Motor| {
            simulate(
                motor,
                &spec,
                &moves,
                &SimOptions::suggested(motor, &spec, &moves),
            )
            .lost_steps
        };
        let (bare, calm) = (lost(&undamped), lost(&damped));
        let check = damped.check(&spec, &table);
        println!(
            "{accel} full steps/s²: lost undamped {bare}, with ζ = 0.1 {calm}; check with ζ = 0.1: {check:?}"
        );
        assert_eq!(bare != 0, undamped_loses, "{accel}");
        assert_eq!(calm, 0, "{accel}");
        assert!(check.is_ok(), "{accel}: {check:?}");
    }
}

/// A profiles file of one linear ramp on a motor given by its TOML lines.
fn motor_file(motor: &str, fmin: f64, fmax: f64, accel: f64, timer_hz: u32) -> String {
    format!(
        "[motors.m]\n{motor}\n\n[profiles.r]\ncurve = \"linear\"\nfmin = {fmin}\nfmax = {fmax}\n\
         accel = {accel}\ntimer_hz = {timer_hz}\nmotor = \"m\"\n"
    )
}

/// The motor check's verdict on a profiles file: `Ok` or the message.
fn verdict(source: &str) -> Result<(), String> {
    Profiles::parse("profiles.toml", source)
        .map(|_| ())
        .map_err(|e| e.to_string())
}

/// The motor page's 17HS-like windings, undamped unless `extra` says otherwise.
fn windings_17hs(extra: &str) -> String {
    format!(
        "step_angle = 1.8\nrotor_inertia = 5.4e-6\nresistance = 1.65\ninductance = 2.8e-3\n\
         rated_current = 1.68\nholding_torque = 0.44\nsupply_voltage = 24\n{extra}"
    )
}

/// `damping_ratio` is a fraction of critical damping, at most 1: a larger
/// one no longer makes the start check pass what the ratio 1 refuses.
#[test]
fn damping_ratio_above_critical_is_refused() {
    let motor = |zeta: &str| {
        format!(
            "step_angle = 1.8\nmicrosteps = 8\nrotor_inertia = 6.8e-6\nload_inertia = 1e-4\n\
             torque_curve = [[0, 0.4], [32000, 0.25]]\ndamping_ratio = {zeta}"
        )
    };
    let file = |zeta: &str| motor_file(&motor(zeta), 30_000.0, 31_000.0, 20_000.0, 10_000_000);
    for zeta in ["0", "1"] {
        let e = verdict(&file(zeta)).unwrap_err();
        assert!(e.contains("the motor cannot start at"), "ζ = {zeta}: {e}");
    }
    for zeta in ["1.5", "10", "1e6", "1e300"] {
        let e = verdict(&file(zeta)).unwrap_err();
        assert!(
            e.contains(
                "`damping_ratio` must be from 0 to 1, a fraction of critical damping: a motor's \
                 own electromagnetic damping is a small fraction of critical, and a larger ratio \
                 would drag the model's rotor along with any field (got "
            ),
            "ζ = {zeta}: {e}"
        );
        assert!(e.starts_with("profiles.toml:7:17: "), "ζ = {zeta}: {e}");
    }
}

/// No damping makes the model unable to integrate: the damping is taken
/// on the new speed, so the simulation plays a ramp at any `damping` and at
/// every allowed `damping_ratio`, and the start check judges it.
#[test]
fn no_damping_makes_the_model_unable_to_integrate() {
    let (spec, periods) = ramp(2000.0, 1);
    for damping in [0.0, 1e-3, 1.0, 1e3] {
        for damping_ratio in [0.0, 0.5, 1.0] {
            let motor = nema17(1)
                .with_damping(damping)
                .with_damping_ratio(damping_ratio);
            let options = SimOptions::suggested(&motor, &spec, &periods);
            let run = simulate::run(&motor, &spec, &periods, &options);
            assert!(
                run.is_ok(),
                "damping {damping}, ζ {damping_ratio}: {:?}",
                run.err()
            );
        }
    }
}

/// An undamped rotor rings at low step rates: the refusal says that
/// damping helps, and with `damping_ratio = 0.1` the same ramp passes;
/// starting slower does not help, and the message says so.
#[test]
fn an_undamped_refusal_advises_damping_and_damping_helps() {
    for fmin in [50.0, 100.0, 200.0] {
        let e = verdict(&motor_file(
            &windings_17hs(""),
            fmin,
            1000.0,
            2000.0,
            1_000_000,
        ))
        .unwrap_err();
        assert!(
            e.contains(
                "(with `damping_ratio = 0.1` the model's rotor makes it: give the motor's own \
                 damping, as a rotor without rings; at half the rate it slips too, so starting \
                 slower does not help)"
            ),
            "fmin = {fmin}: {e}"
        );
        let damped = windings_17hs("damping_ratio = 0.1");
        assert_eq!(
            verdict(&motor_file(&damped, fmin, 1000.0, 2000.0, 1_000_000)),
            Ok(()),
            "fmin = {fmin} with the advised damping"
        );
        // And the advice not given does not help: half the rate slips too.
        let half = motor_file(&windings_17hs(""), fmin / 2.0, 1000.0, 500.0, 1_000_000);
        assert!(verdict(&half).is_err(), "fmin = {}", fmin / 2.0);
    }
}

/// A damped rotor that slips on a steep start: the refusal advises half the
/// rate and a quarter of the acceleration, and that ramp passes.
#[test]
fn a_start_too_steep_advises_a_slower_start_and_it_helps() {
    let motor = windings_17hs("load_inertia = 1e-4\ndamping_ratio = 0.1");
    let e = verdict(&motor_file(&motor, 600.0, 3000.0, 20_000.0, 1_000_000)).unwrap_err();
    assert!(
        e.contains(
            "the motor cannot start on this ramp with its load: from rest at 616.1 Hz the model's \
             rotor slips before pulse 5, before it reaches the field's speed (start slower and \
             accelerate less: at half the rate throughout (half the start frequency, a quarter \
             of the acceleration) the model's rotor makes it)"
        ),
        "{e}"
    );
    assert_eq!(
        verdict(&motor_file(&motor, 300.0, 3000.0, 5000.0, 1_000_000)),
        Ok(())
    );
}

/// A start above the model's limit: started below the limit it names, the
/// rotor pulls in; the acceleration right after is judged next, and its
/// own advice, followed, passes.
#[test]
fn a_start_above_the_limit_names_one_that_starts() {
    let motor = windings_17hs("load_inertia = 1e-4\ndamping_ratio = 0.1");
    let e = verdict(&motor_file(&motor, 1000.0, 3000.0, 2000.0, 1_000_000)).unwrap_err();
    let limit: f64 = e
        .split("it starts at ")
        .nth(1)
        .and_then(|s| s.split(" Hz at most").next())
        .and_then(|s| s.parse().ok())
        .unwrap_or_else(|| panic!("{e}"));
    // The first entry is a little faster than `fmin`: start below the limit.
    let fmin = (limit * 0.99).floor();
    let e = verdict(&motor_file(&motor, fmin, 3000.0, 2000.0, 1_000_000)).unwrap_err();
    assert!(
        !e.contains("the motor cannot start at"),
        "fmin = {fmin}: {e}"
    );
    assert!(
        e.contains("(start slower and accelerate less: at half the rate throughout"),
        "{e}"
    );
    assert_eq!(
        verdict(&motor_file(&motor, fmin / 2.0, 3000.0, 500.0, 1_000_000)),
        Ok(()),
        "fmin = {}, as advised",
        fmin / 2.0
    );
}

/// A driver that steps the current plays its own steps: half steps are two
/// table steps a full step, full steps one; any other `microsteps` is
/// refused at that key.
#[test]
fn a_stepped_drive_takes_its_own_steps() {
    let file = |drive: &str, microsteps: u32| {
        let motor = windings_17hs(&format!(
            "drive = \"{drive}\"\nmicrosteps = {microsteps}\ndamping_ratio = 0.1"
        ));
        let k = f64::from(microsteps);
        motor_file(&motor, 400.0 * k, 1000.0 * k, 2000.0 * k, 1_000_000)
    };
    assert_eq!(verdict(&file("half_step", 2)), Ok(()));
    assert_eq!(verdict(&file("full_step", 1)), Ok(()));
    assert_eq!(verdict(&file("sine", 8)), Ok(()));
    for (drive, microsteps, expected) in [
        (
            "half_step",
            8,
            "2 with `drive = half_step`: the driver moves half a step per pulse, so each table \
             step is a half step (got 8)",
        ),
        (
            "half_step",
            1,
            "2 with `drive = half_step`: the driver moves half a step per pulse, so each table \
             step is a half step (got 1)",
        ),
        (
            "full_step",
            256,
            "1 with `drive = full_step`: the driver moves a full step per pulse, so each table \
             step is a full step (got 256)",
        ),
    ] {
        let e = verdict(&file(drive, microsteps)).unwrap_err();
        assert!(
            e.contains(&format!("`microsteps` must be {expected}")),
            "{drive}, {microsteps}: {e}"
        );
        assert!(e.starts_with("profiles.toml:10:14: "), "{e}");
    }
}

/// One tick of rounding is no torque: a 1/8-step ramp to 31 kHz on a
/// 1e-4 kg·m² load needs about 0.008 N·m to accelerate at 20 000 Hz/s, and
/// passes on a 1, 2 and 10 MHz timer alike. Along the ramp the torque the
/// check reads stays within 0.02 N·m of that need (one entry's tick at
/// 28 kHz on 1 MHz read 0.29 N·m over windows of a full step); only at the
/// table's end, where the player goes on at the whole-tick last period, a
/// step of speed the rotor does feel is read.
#[test]
fn rounding_is_not_read_as_torque() {
    let motor = "step_angle = 1.8\nmicrosteps = 8\nrotor_inertia = 6.8e-6\nload_inertia = 1e-4\n\
                 torque_curve = [[0, 0.4], [32000, 0.25]]\ndamping_ratio = 0.1";
    // J α: the load's inertia times the ramp's angular acceleration.
    let ramp_needs = (6.8e-6 + 1e-4) * 20_000.0 * (1.8f64 / 8.0).to_radians();
    for timer_hz in [1_000_000, 2_000_000, 10_000_000] {
        let source = motor_file(motor, 1000.0, 31_000.0, 20_000.0, timer_hz);
        let profiles = Profiles::parse("profiles.toml", &source)
            .unwrap_or_else(|e| panic!("{timer_hz} Hz: {e}"));
        let p = &profiles.profiles()[0];
        let Generated::Steps(table) = &p.table else {
            panic!("a per-step table");
        };
        let motor = p.motor.expect("a motor");
        // The last 2.5 ms, where the window reaches past the table's end.
        let end = table.periods.len() as u32 - 80;
        let mut worst = 0.0f64;
        motor
            .check_with(&table.spec, &table.periods, |step, _, needed, _| {
                if step > 0 && step < end {
                    worst = worst.max(needed);
                }
            })
            .unwrap();
        assert!(
            worst < ramp_needs + 0.02,
            "{timer_hz} Hz: the check reads {worst} N·m where the ramp needs {ramp_needs:.4}"
        );
    }
}
