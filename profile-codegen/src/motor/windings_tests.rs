//! The windings' pull-out torque: the chopper's solution alone, and with
//! the losses and the driver's current setting.

use core::f64::consts::{FRAC_PI_4, PI, TAU};

use super::*;

/// A NEMA 17 behind an ideal chopper: the whole supply across the
/// winding, no iron loss (the chopper's own solution, alone).
fn nema17() -> Windings {
    Windings::new(0.7, 1.1e-3, 2.8, 0.40, 24.0)
        .with_supply_utilization(1.0)
        .with_iron_loss(0.0)
}

/// The defaults: the chopper at 0.76 of its supply, the iron's drag at
/// 0.11 of the holding torque at 1 kHz, growing as the frequency's
/// 0.4th power; a driver set to another current scales the torque.
#[test]
fn the_losses_and_the_driver_current() {
    let ideal = nema17();
    let real = Windings::new(0.7, 1.1e-3, 2.8, 0.40, 24.0);
    assert_eq!(real.supply_utilization, 0.76);
    assert!((real.iron_loss_at_1khz() - 0.044).abs() < 1e-15);
    // 250 Hz electrical: a drag of 0.044 · 0.25^0.4 = 0.02527 N·m.
    let drag = 0.044 * libm::pow(0.25, 0.4);
    assert!((real.iron_drag(250.0) - drag).abs() < 1e-15);
    assert!((real.iron_drag(-250.0) - drag).abs() < 1e-15);
    let omega = 250.0 * TAU / 50.0;
    let at_0_76 = Windings {
        supply_voltage: 24.0 * 0.76,
        ..ideal
    };
    let expected = at_0_76.pull_out(50.0, omega) - drag;
    let got = real.pull_out(50.0, omega);
    assert!((got - expected).abs() < 1e-12, "{got} against {expected}");
    // At rest, a driver at 3.5 A of a 2.8 A motor: 1.25 times the
    // holding torque, RMS; 3.5 A peak is 3.5 / (sqrt(2) · 2.8).
    let rms = ideal.with_driver_current(3.5, CurrentSetting::Rms);
    assert!((rms.pull_out(50.0, 0.0) - 0.5).abs() < 1e-12);
    let peak = ideal.with_driver_current(3.5, CurrentSetting::Peak);
    let share = 3.5 / (SQRT_2 * 2.8);
    assert!((peak.pull_out(50.0, 0.0) - 0.40 * share).abs() < 1e-12);
    // The stepped drives switch each phase to the setting.
    let half = ideal.with_drive(Drive::HalfStep);
    let lower = half.with_driver_current(1.4, CurrentSetting::Rms);
    let ratio = lower.pull_out(50.0, 0.0) / half.pull_out(50.0, 0.0);
    assert!((ratio - 0.5).abs() < 1e-9, "{ratio}");
}

#[test]
fn at_rest_the_holding_torque_unless_the_supply_cannot_drive_the_current() {
    assert_eq!(nema17().pull_out(50.0, 0.0), 0.40);
    // 2 V over 0.7 Ω drives 2.86 A of the 3.96 A set: the current
    // follows the sine up to 2.86 A and is clipped there. The mean
    // torque is `K_m` times the clipped sine's fundamental, here summed
    // over a half turn.
    let weak = Windings {
        supply_voltage: 2.0,
        ..nema17()
    };
    let (amp, cap) = (SQRT_2 * 2.8, 2.0 / 0.7);
    let n = 100_000;
    let fundamental = (0..n)
        .map(|k| {
            let t = PI * (k as f64 + 0.5) / n as f64;
            (amp * t.sin()).min(cap) * t.sin()
        })
        .sum::<f64>()
        * 2.0
        / n as f64;
    let expected = 0.40 / amp * fundamental;
    let at_rest = weak.pull_out(50.0, 0.0);
    assert!(
        (at_rest - expected).abs() < 1e-9,
        "{at_rest} against {expected}"
    );
    // Slowly turning, the same.
    let slowly = weak.pull_out(50.0, 1e-4);
    assert!(
        (slowly - at_rest).abs() < 1e-5,
        "{slowly} against {at_rest}"
    );
    let detent = nema17().with_detent_torque(0.015);
    assert!((detent.pull_out(50.0, 0.0) - 0.385).abs() < 1e-15);
}

#[test]
fn falls_with_speed_and_as_one_over_speed_at_the_top() {
    let w = nema17();
    let mut last = f64::INFINITY;
    for k in 0..400 {
        let t = w.pull_out(50.0, k as f64 * 2.0);
        assert!(t <= last, "rises at {k}");
        last = t;
    }
    // High up, `K_m (V - K_m R / (N_r L)) / (N_r L ω)`.
    let (km, nl) = (w.torque_constant(), 50.0 * w.inductance);
    let omega = 5000.0;
    let asymptote = km * (24.0 / FRAC_PI_4 - km * w.resistance / nl) / (nl * omega);
    let t = w.pull_out(50.0, omega);
    assert!(
        (t / asymptote - 1.0).abs() < 1e-3,
        "{t} against {asymptote}"
    );
}

#[test]
fn a_short_circuit_current_above_the_set_one_brakes_at_speed() {
    // `K_m / (N_r L)` = 0.101 / 0.01 = 10.1 A, above the 3.96 A set:
    // once the back-EMF drives more than the chopper is set to, the
    // windings give nothing, and never more again.
    let w = Windings {
        resistance: 0.5,
        inductance: 0.2e-3,
        ..nema17()
    };
    assert!(w.torque_constant() / (50.0 * w.inductance) > w.amplitude());
    let mut last = f64::INFINITY;
    let mut zero_from = None;
    for k in 0..10_000 {
        let omega = k as f64 * 0.5;
        let t = w.pull_out(50.0, omega);
        assert!(t <= last, "rises to {t} at {omega} rad/s");
        if t == 0.0 && zero_from.is_none() {
            zero_from = Some(omega);
        }
        last = t;
    }
    let zero_from = zero_from.expect("falls to nothing");
    // 508 rad/s: 16 170 full steps/s.
    assert!((450.0..550.0).contains(&zero_from), "{zero_from}");
}

/// The largest supply taken, 1e5 V, and one beyond: finite limits, and
/// a motor refused starts at no rate.
#[test]
fn a_supply_beyond_reason_gives_finite_limits() {
    let motor = Motor::new(1.8, 1, 5.4e-6)
        .with_windings(Windings {
            supply_voltage: 1e5,
            ..nema17()
        })
        .with_load_inertia(2.0e-5)
        .with_damping_ratio(0.1);
    let top = motor.top_hz();
    assert!(top.is_finite() && top > 1e5, "{top}");
    let mut beyond = motor;
    beyond.windings = Some(Windings {
        supply_voltage: 1e300,
        ..nema17()
    });
    assert!(beyond.top_hz().is_finite());
    assert_eq!(beyond.start_limit(1e6).hz(), 0.0);
    let start = motor.start_limit(top).hz();
    assert!(start > 100.0 && start < 1e6, "{start}");
    let unbounded = motor.start_limit(f64::INFINITY).hz();
    assert!(
        (unbounded / start - 1.0).abs() < 2e-3,
        "{unbounded} against {start}"
    );
}

/// Windings and motors `validate` refuses, and arguments the model has
/// no answer for, give no torque and no top frequency: not a figure
/// made of them (a resistance of -1 Ω gave 0.4 N·m up to 3.8 MHz).
#[test]
fn refused_figures_give_no_torque() {
    let bad = [-1e300, -1.0, 0.0, 1e-300, 1e300, f64::NAN, f64::INFINITY];
    for drive in [Drive::Sine, Drive::HalfStep, Drive::FullStep] {
        for field in 0..6 {
            for &value in &bad {
                let mut w = nema17().with_drive(drive);
                let slot = match field {
                    0 => &mut w.resistance,
                    1 => &mut w.inductance,
                    2 => &mut w.rated_current,
                    3 => &mut w.holding_torque,
                    4 => &mut w.supply_voltage,
                    _ => &mut w.detent_torque,
                };
                *slot = value;
                if w.validate().is_ok() {
                    continue;
                }
                let motor = Motor::new(1.8, drive_steps(drive), 5.4e-6).with_windings(w);
                let case = (drive, field, value);
                assert_eq!(w.pull_out(50.0, 10.0), 0.0, "{case:?}");
                assert_eq!(motor.pull_out(100.0), 0.0, "{case:?}");
                assert_eq!(motor.available(100.0), 0.0, "{case:?}");
                assert_eq!(motor.derived_pull_out(100.0), None, "{case:?}");
                assert_eq!(motor.peak_torque(), 0.0, "{case:?}");
                assert_eq!(motor.top_hz(), 0.0, "{case:?}");
                assert_eq!(motor.stiffness(), 0.0, "{case:?}");
            }
        }
    }
    let good = nema17();
    for (poles, omega) in [
        (0.0, 10.0),
        (-50.0, 10.0),
        (f64::NAN, 10.0),
        (50.0, f64::NAN),
    ] {
        assert_eq!(good.pull_out(poles, omega), 0.0, "{poles} {omega}");
    }
    assert!(good.pull_out(50.0, 10.0) > 0.3);
    let motor = Motor::new(1.8, 8, 5.4e-6).with_windings(good);
    assert!(motor.pull_out(100.0) > 0.3);
    for hz in [f64::NAN, f64::INFINITY] {
        assert_eq!(motor.pull_out(hz), 0.0);
        assert_eq!(motor.derived_pull_out(hz), None);
    }
    let refused = Motor::new(f64::NAN, 8, 5.4e-6).with_windings(good);
    assert_eq!((refused.pull_out(100.0), refused.top_hz()), (0.0, 0.0));
    let curve = crate::motor::TorqueCurve::new(&[(0.0, 0.4), (1000.0, 0.3)]).unwrap();
    let refused = Motor::new(1.8, 0, 5.4e-6).with_torque_curve(curve);
    assert_eq!((refused.pull_out(100.0), refused.peak_torque()), (0.0, 0.0));
}

fn drive_steps(drive: Drive) -> u32 {
    match drive {
        Drive::Sine => 8,
        Drive::HalfStep => 2,
        Drive::FullStep => 1,
    }
}
