//! How much sooner the fastest ramp a motor allows (`torque_limited`)
//! reaches its top speed than the steepest ramp of each other shape that
//! passes the same motor check, on five motors and drives.
//!
//! The check is the motor's own, and at `margin = 0.5` at every edge: the
//! torque of the motor with its safety factor over the margin, so that
//! every ramp keeps half the pull-out torque back at every speed. The
//! `torque_limited` ramp passes it by construction, from its own start
//! (the fastest the start-from-rest check accepts, as a profile without
//! `fmin` takes it). From the same start to the same top, each other curve
//! is made as steep as that check allows (its acceleration scaled by
//! bisection, for a few shapes of each curve, the shortest kept): constant
//! acceleration (`linear`), Zeng's three stages (`three_stage`) and the
//! jerk-limited S-curve (`jerk_limited`). Beside them, the floor: the time
//! of a ramp at the check's limit at every speed, unrounded, and how much
//! shorter than the best other shape that floor is, the most any ramp
//! within the check could save. The times to the top are printed:
//!
//! ```text
//! cargo test --release --test fastest -- --nocapture
//! ```

use test_support::motors::QSH4218_CHART;

use profile_codegen::SpecTables;
use profile_codegen::motor::{CurrentSetting, Drive, Motor, MotorError, TorqueCurve, Windings};
use stepper_profiles::{
    Curve, JerkLimited, Linear, LinearExtent, Spec, ThreeStage, Timer, TorqueLimited,
};

const TIMER_HZ: u32 = 10_000_000;
const MARGIN: f64 = 0.5;

/// A motor, the top speed of its ramps (table steps per second), and what
/// it is.
struct Case {
    name: &'static str,
    motor: Motor,
    fmax: f64,
}

fn cases() -> Vec<Case> {
    // TRINAMIC's QSH4218-47-28-040 by its manual's chart (profiles.toml),
    // in 1/8 steps, up to the chart's end, 1500 rpm.
    let qsh = Motor::new(1.8, 8, 6.8e-6)
        .with_load_inertia(1.36e-5)
        .with_friction(0.02)
        .with_damping_ratio(0.1);
    let qsh_chart = qsh.with_torque_curve(TorqueCurve::new(&QSH4218_CHART).unwrap());
    // The same by its windings, 24 V, to 2500 rpm.
    let qsh_windings = qsh.with_windings(Windings::new(0.5, 0.6e-3, 2.8, 0.40, 24.0));
    // StepperOnline's 23HS32-4004S by its windings, on a DM542T at 4.2 A
    // peak from 48 V, in 1/8 steps, to 1200 rpm.
    let nema23 = Motor::new(1.8, 8, 5.3e-5)
        .with_windings(
            Windings::new(0.65, 3.2e-3, 4.0, 2.4, 48.0)
                .with_driver_current(4.2, CurrentSetting::Peak),
        )
        .with_load_inertia(1.0e-3)
        .with_friction(0.1)
        .with_damping_ratio(0.1);
    // StepperOnline's 23HS45-4204S by its windings, in half steps at
    // 4.2 A from 36 V, to 600 rpm.
    let half = Motor::new(1.8, 2, 6.8e-5)
        .with_windings(Windings::new(0.88, 3.4e-3, 4.2, 3.0, 36.0).with_drive(Drive::HalfStep))
        .with_load_inertia(1.4e-3)
        .with_friction(0.15)
        .with_damping_ratio(0.1);
    // Its 23HE45-4204S body on a DM556T at 4.1 A RMS from 36 V, in 1/10
    // steps, to 600 rpm: the sine-driven chart of the same windings.
    let dm556t = Motor::new(1.8, 10, 6.8e-5)
        .with_windings(
            Windings::new(0.88, 3.4e-3, 4.2, 3.0, 36.0)
                .with_driver_current(4.1, CurrentSetting::Rms),
        )
        .with_load_inertia(1.4e-3)
        .with_friction(0.15)
        .with_damping_ratio(0.1);
    vec![
        Case {
            name: "QSH4218-47-28-040, windings, to 2500 rpm",
            motor: qsh_windings,
            fmax: 2500.0 / 60.0 * 1600.0,
        },
        Case {
            name: "23HS32-4004S, windings, to 1200 rpm",
            motor: nema23,
            fmax: 1200.0 / 60.0 * 1600.0,
        },
        Case {
            name: "23HS45-4204S, half steps, to 600 rpm",
            motor: half,
            fmax: 600.0 / 60.0 * 400.0,
        },
        Case {
            name: "23HE45-4204S, DM556T 4.1 A, to 600 rpm",
            motor: dm556t,
            fmax: 600.0 / 60.0 * 2000.0,
        },
        Case {
            name: "QSH4218-47-28-040, chart, to 1500 rpm",
            motor: qsh_chart,
            fmax: 1500.0 / 60.0 * 1600.0,
        },
    ]
}

/// The seconds a table takes; `None` when the check refuses it (or it has
/// no table): the motor's own check, and at every edge the torque of the
/// motor with its safety factor over the margin.
fn judged(motor: &Motor, curve: Curve) -> Option<f64> {
    let spec = Spec::new(curve, Timer::new(TIMER_HZ));
    let table = spec.table().ok()?;
    motor.check(&spec, &table.periods).ok()?;
    let strict = motor.with_safety(motor.safety / MARGIN);
    if let Err(MotorError::Torque { .. }) = strict.check(&spec, &table.periods) {
        return None;
    }
    let ticks: u64 = table.periods.iter().map(|&p| u64::from(p)).sum();
    Some(ticks as f64 / f64::from(TIMER_HZ))
}

/// The shortest time of `family(scale)` over the scales at which the
/// check passes: bisection on the scale (in its logarithm, 16 halvings:
/// to a twenty-thousandth of it, finer than the times' printed tenth of a
/// millisecond) between `lo`, which passes, and `hi`, which does not.
fn steepest(
    motor: &Motor,
    (mut lo, mut hi): (f64, f64),
    family: &dyn Fn(f64) -> Option<Curve>,
) -> Option<f64> {
    let passes = |scale: f64| family(scale).and_then(|c| judged(motor, c));
    passes(lo)?;
    if passes(hi).is_some() {
        return passes(hi);
    }
    for _ in 0..16 {
        let mid = (lo * hi).sqrt();
        if passes(mid).is_some() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    passes(lo)
}

/// The floor: the time from `fmin` to `fmax` of a ramp that accelerates
/// at every step frequency exactly as hard as the check allows (the
/// needed torque equal to the available, the motor's safety over the
/// margin), `dt = df / a(f)` integrated by Simpson's rule on 4096
/// intervals from the motor's torque alone. No rounded periods and no
/// torque held back: a ramp whose acceleration stays within the check's
/// at every speed takes at least this long.
fn floor(motor: &Motor, fmin: f64, fmax: f64) -> f64 {
    let strict = motor.with_safety(motor.safety / MARGIN);
    let theta = motor.step_radians();
    let inertia = motor.rotor_inertia + motor.load_inertia;
    let per_accel = |f: f64| {
        let spare = strict.available(f) - motor.friction - motor.damping * theta * f;
        assert!(spare > 0.0, "no torque to spare at {f} Hz");
        inertia * theta / spare
    };
    let n = 4096;
    let h = (fmax - fmin) / f64::from(n);
    let mut sum = per_accel(fmin) + per_accel(fmax);
    for k in 1..n {
        let weight = if k % 2 == 1 { 4.0 } else { 2.0 };
        sum += weight * per_accel(fmin + h * f64::from(k));
    }
    sum * h / 3.0
}

/// One motor's figures: the fastest ramp's time, the steepest of each
/// other shape that passes (`None` where none does), and the floor.
struct Row {
    time: f64,
    others: [Option<f64>; 3],
    least: f64,
}

fn row(case: &Case) -> Row {
    let motor = &case.motor;
    let fmax = case.fmax;
    // The ramp: its own start, as a profile without `fmin` takes it.
    let mut fmin = motor.start_limit(fmax).hz() * MARGIN;
    let mut ramp = None;
    for _ in 0..20 {
        let r = motor
            .torque_limited(Some(fmin), fmax, MARGIN, Timer::new(TIMER_HZ))
            .unwrap();
        if judged(motor, Curve::TorqueLimited(r)).is_some() {
            ramp = Some(r);
            break;
        }
        fmin *= 0.8;
    }
    let ramp = ramp.unwrap_or_else(|| panic!("{}: no start the check accepts", case.name));
    let time = judged(motor, Curve::TorqueLimited(ramp)).unwrap();
    let span = fmax - fmin;
    // The others' accelerations, in spans a second, from an eighth to
    // three times the fastest ramp's mean.
    let mean = 1.0 / time;
    let bracket = (mean / 8.0, 3.0 * mean);
    let shortest = |families: &mut dyn Iterator<Item = Option<f64>>| {
        families.fold(None::<f64>, |best, t| match (best, t) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        })
    };
    let linear = steepest(motor, bracket, &|a| {
        Some(Curve::Linear(Linear {
            fmin,
            fmax,
            extent: LinearExtent::Accel(a * span),
        }))
    });
    // Three stages: where they meet, and the exponential's shape, a few
    // ways; the peak acceleration scaled.
    let three = shortest(
        &mut [
            (0.1, 0.5, 1.0),
            (0.2, 0.6, 2.0),
            (0.3, 0.7, 4.0),
            (0.1, 0.8, 8.0),
            (0.05, 0.9, 2.0),
        ]
        .into_iter()
        .map(|(f1, f2, shape)| {
            steepest(motor, bracket, &|a| {
                let accel = a * span;
                Some(Curve::ThreeStage(ThreeStage {
                    fmin,
                    fmax,
                    accel,
                    f1: fmin + f1 * span,
                    f2: fmin + f2 * span,
                    shape: shape * accel / span,
                }))
            })
        }),
    );
    // Jerk-limited: the jerk in proportion to the acceleration's square
    // over the span, a few ways.
    let jerk = shortest(&mut [1.0, 4.0, 16.0, 64.0].into_iter().map(|k| {
        steepest(motor, bracket, &|a| {
            let accel = a * span;
            Some(Curve::JerkLimited(JerkLimited {
                fmin,
                fmax,
                accel,
                jerk: k * accel * accel / span,
            }))
        })
    }));
    Row {
        time,
        others: [linear, three, jerk],
        least: floor(motor, fmin, fmax),
    }
}

#[test]
fn the_fastest_ramp_against_the_steepest_of_each_shape() {
    let cases = cases();
    // One thread a motor: the searches are independent.
    let rows: Vec<Row> = std::thread::scope(|scope| {
        let handles: Vec<_> = cases
            .iter()
            .map(|case| scope.spawn(move || row(case)))
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    println!(
        "{:<42} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "motor", "torque_l", "linear", "3-stage", "jerk_lim", "shorter", "floor", "at most"
    );
    let mut quarter_shorter = 0;
    for (case, row) in cases.iter().zip(&rows) {
        let Row {
            time,
            others,
            least,
        } = *row;
        let best = others
            .iter()
            .flatten()
            .copied()
            .fold(f64::INFINITY, f64::min);
        let shorter = 1.0 - time / best;
        let ms = |t: Option<f64>| t.map_or("-".to_string(), |t| format!("{:.1} ms", t * 1e3));
        println!(
            "{:<42} {:>9} {:>9} {:>9} {:>9} {:>8.1} % {:>9} {:>7.1} %",
            case.name,
            ms(Some(time)),
            ms(others[0]),
            ms(others[1]),
            ms(others[2]),
            shorter * 100.0,
            ms(Some(least)),
            (1.0 - least / best) * 100.0
        );
        assert!(shorter > 0.0, "{}: not shorter than the best", case.name);
        if shorter >= 0.25 {
            quarter_shorter += 1;
        }
        // Within 3 % of the floor, and no ramp below it.
        assert!(
            time >= least && time < least * 1.03,
            "{}: {time} s against {least} s",
            case.name
        );
        for other in others.iter().flatten() {
            assert!(
                *other >= least,
                "{}: {other} s against {least} s",
                case.name
            );
        }
    }
    // At least a quarter shorter than the best of the others on three
    // motors (where the floor allows it).
    assert!(
        quarter_shorter >= 3,
        "{quarter_shorter} rows a quarter shorter"
    );
}

/// A ramp with a larger `margin` plans on more of the torque: it is
/// shorter, and the check with the motor's own safety finds less to spare
/// over it.
#[test]
fn a_larger_margin_is_shorter_and_leaves_less_to_spare() {
    let case = &cases()[4];
    let figures = |margin: f64| {
        let ramp: TorqueLimited = case
            .motor
            .torque_limited(Some(1000.0), case.fmax, margin, Timer::new(TIMER_HZ))
            .unwrap();
        let spec = Spec::new(Curve::TorqueLimited(ramp), Timer::new(TIMER_HZ));
        let table = spec.table().unwrap();
        let ticks: u64 = table.periods.iter().map(|&p| u64::from(p)).sum();
        let spare = case
            .motor
            .check(&spec, &table.periods)
            .unwrap()
            .min_margin_nm;
        (ticks, spare)
    };
    let (a, b, c) = (figures(0.3), figures(0.4), figures(0.5));
    assert!(a.0 > b.0 && b.0 > c.0, "{a:?} {b:?} {c:?}");
    assert!(a.1 > b.1 && b.1 > c.1, "{a:?} {b:?} {c:?}");
}
