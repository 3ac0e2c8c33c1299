//! Property tests over wide random parameters, for every curve and
//! discretization.
//!
//! Valid parameters: no panic; `len` entries; every entry fits the word and
//! lies between the periods of the curve's end frequencies; periods never
//! grow along an acceleration table (diffused rounding may tie by one
//! tick); in the default mode every pulse edge is within half a tick of the
//! continuous curve. Invalid parameters (NaN, infinities, zero, negative,
//! reversed, absurd lengths, contradicting options): always a typed error
//! or a table, never a panic, and bounded work.
//!
//! `PROPTEST_CASES` sets the cases per property (default 500, 100 for the
//! derived pull-out torque, 400 torques each); CI runs the default and
//! 2000 per property from an optimised build, `PROPTEST_CASES=20000` is the
//! long run.

use profile_codegen::SpecTables;
use profile_core::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, Rounding, Sigmoid, Spec, ThreeStage, Timer, Word,
};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(500)
}

/// `PROPTEST_CASES`, or 100: for the properties that compute hundreds of
/// torques a case.
fn torque_cases() -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(100)
}

/// Largest table generated in the valid-parameter properties.
const LEN: u32 = 400;

fn freqs() -> impl Strategy<Value = (f64, f64)> {
    (10.0f64..5000.0, 1.01f64..60.0).prop_map(|(fmin, ratio)| (fmin, fmin * ratio))
}

fn sigmoid() -> impl Strategy<Value = Curve> {
    (freqs(), 0.1f64..30.0, 1..=LEN).prop_map(|((fmin, fmax), flexible, len)| {
        Curve::Sigmoid(Sigmoid {
            fmin,
            fmax,
            flexible,
            len,
        })
    })
}

fn exponential() -> impl Strategy<Value = Curve> {
    (freqs(), 0.01f64..3.0, 1..=LEN, any::<bool>()).prop_map(|((fmin, fmax), q, steps, by_tau)| {
        let f_inf = fmax * (1.0 + q);
        let extent = if by_tau {
            // The time constant that takes about `steps` steps.
            let per_tau = f_inf * ((f_inf - fmin) / (f_inf - fmax)).ln() - (fmax - fmin);
            ExponentialExtent::Tau(steps as f64 / per_tau)
        } else {
            ExponentialExtent::Len(steps)
        };
        Curve::Exponential(Exponential {
            fmin,
            fmax,
            f_inf,
            extent,
        })
    })
}

fn linear() -> impl Strategy<Value = Curve> {
    (freqs(), 2..=LEN, any::<bool>()).prop_map(|((fmin, fmax), steps, by_accel)| {
        let extent = if by_accel {
            LinearExtent::Accel((fmax * fmax - fmin * fmin) / (2.0 * steps as f64))
        } else {
            LinearExtent::Len(steps)
        };
        Curve::Linear(Linear { fmin, fmax, extent })
    })
}

fn three_stage() -> impl Strategy<Value = Curve> {
    (
        10.0f64..2000.0,
        0.05f64..3.0,
        0.0f64..3.0,
        0.05f64..3.0,
        5.0f64..300.0,
        -0.95f64..10.0,
    )
        .prop_filter("shape must not be 0", |t| t.5.abs() > 0.01)
        .prop_map(|(f0, u1, u2, u3, steps, s)| {
            let f1 = f0 * (1.0 + u1);
            let f2 = f1 * (1.0 + u2);
            let fc = f2 * (1.0 + u3);
            // About `steps` steps: N ~ fc^2 / accel.
            let accel = fc * fc / steps;
            Curve::ThreeStage(ThreeStage {
                fmin: f0,
                fmax: fc,
                accel,
                f1,
                f2,
                shape: s * accel / (f1 - f0),
            })
        })
}

fn jerk_limited() -> impl Strategy<Value = Curve> {
    (freqs(), 5.0f64..300.0, 0.1f64..10.0).prop_map(|((fmin, fmax), steps, j)| {
        let accel = fmax * fmax / steps;
        Curve::JerkLimited(JerkLimited {
            fmin,
            fmax,
            accel,
            jerk: accel * accel / (fmax - fmin) * j,
        })
    })
}

fn options() -> impl Strategy<Value = (Discretization, Rounding, u8)> {
    (
        prop_oneof![
            Just(Discretization::Exact),
            Just(Discretization::LeftEndpoint),
            Just(Discretization::Index)
        ],
        prop_oneof![
            Just(Rounding::Truncate),
            Just(Rounding::Nearest),
            Just(Rounding::Diffuse)
        ],
        1u8..=2,
    )
}

/// A timer fast enough for the curve, with a 32-bit word so periods fit.
fn spec(curve: Curve, (d, r, tps): (Discretization, Rounding, u8), timer_scale: f64) -> Spec {
    let (_, fmax) = curve.frequencies();
    let timer_hz = (fmax * 20.0 * timer_scale).min(4e9) as u32;
    let timer = Timer {
        timer_hz,
        word: Word::U32,
        ticks_per_step: tps,
    };
    Spec::new(curve, timer)
        .with_discretization(d)
        .with_rounding(r)
}

fn check_valid(spec: &Spec) -> Result<(), TestCaseError> {
    let index_ok = matches!(spec.curve, Curve::Sigmoid(_) | Curve::Linear(_));
    let table = match spec.table() {
        Ok(t) => t,
        Err(e) => {
            prop_assert!(
                spec.discretization == Discretization::Index && !index_ok,
                "valid spec failed: {e}: {spec:?}"
            );
            return Ok(());
        }
    };
    let p = &table.periods;
    prop_assert_eq!(p.len(), spec.len() as usize);
    let scale = spec.timer.timer_hz as f64 / spec.timer.ticks_per_step as f64;
    let (fmin, fmax) = spec.curve.frequencies();
    let (slowest, fastest) = (scale / fmin, scale / fmax);
    let tie = if spec.rounding == Rounding::Diffuse {
        1
    } else {
        0
    };
    for (k, &ticks) in p.iter().enumerate() {
        prop_assert!(
            ticks as f64 >= fastest.floor() - 1.0 && ticks as f64 <= slowest.ceil() + 1.0,
            "entry {k} = {ticks} outside [{fastest}, {slowest}]: {spec:?}"
        );
    }
    for (k, w) in p.windows(2).enumerate() {
        prop_assert!(
            w[1] <= w[0] + tie,
            "entry {} grows: {} -> {}: {spec:?}",
            k + 1,
            w[0],
            w[1]
        );
    }
    if spec.discretization == Discretization::Exact && spec.rounding == Rounding::Diffuse {
        let mut played = 0u64;
        let mut worst = 0.0f64;
        spec.for_each_exact_edge(|k, t| {
            played += p[k as usize - 1] as u64;
            worst = worst.max((played as f64 - t * scale).abs());
        })
        .unwrap();
        prop_assert!(
            worst <= 0.5 + 1e-6,
            "edge {worst} ticks from the curve: {spec:?}"
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases()))]

    #[test]
    fn sigmoid_tables(curve in sigmoid(), opts in options(), t in 1.0f64..50.0, f32 in any::<bool>()) {
        let mut s = spec(curve, opts, t);
        if f32 && s.discretization == Discretization::Index {
            s = s.with_arithmetic(Arithmetic::F32);
        }
        check_valid(&s)?;
    }

    #[test]
    fn exponential_tables(curve in exponential(), opts in options(), t in 1.0f64..50.0) {
        check_valid(&spec(curve, opts, t))?;
    }

    #[test]
    fn linear_tables(curve in linear(), opts in options(), t in 1.0f64..50.0) {
        check_valid(&spec(curve, opts, t))?;
    }

    #[test]
    fn linear_integer_tables(f0 in 1u32..3000, df in 1u32..20_000, len in 2u32..400, tps in 1u8..=2) {
        let curve = Curve::Linear(Linear {
            fmin: f0 as f64,
            fmax: (f0 + df) as f64,
            extent: LinearExtent::Len(len),
        });
        let s = Spec::new(curve, Timer { timer_hz: 50_000_000, word: Word::U16, ticks_per_step: tps })
            .with_discretization(Discretization::Index)
            .with_rounding(Rounding::Truncate)
            .with_arithmetic(Arithmetic::Integer);
        // Either the article's arithmetic holds and the table is right, or a
        // typed error says which intermediate overflows.
        match s.table() {
            Ok(_) => check_valid(&s)?,
            Err(e) => prop_assert!(e.key().is_some(), "{e}"),
        }
    }

    #[test]
    fn three_stage_tables(curve in three_stage(), opts in options(), t in 1.0f64..50.0) {
        let s = spec(curve, opts, t);
        prop_assume!(s.len() <= 3 * LEN);
        check_valid(&s)?;
    }

    #[test]
    fn jerk_limited_tables(curve in jerk_limited(), opts in options(), t in 1.0f64..50.0) {
        let s = spec(curve, opts, t);
        prop_assume!(s.len() <= 3 * LEN);
        check_valid(&s)?;
    }
}

/// Numbers that break naive code.
fn hostile() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(-1.0),
        Just(f64::MIN_POSITIVE),
        Just(1e-300),
        Just(1e300),
        Just(f64::MAX),
        -1e6f64..1e6,
        1.0f64..1e5,
    ]
}

fn hostile_len() -> impl Strategy<Value = u32> {
    prop_oneof![
        Just(0u32),
        Just(1),
        Just(2),
        Just(65_536),
        Just(65_537),
        Just(u32::MAX),
        0u32..5000
    ]
}

fn hostile_curve() -> impl Strategy<Value = Curve> {
    prop_oneof![
        (hostile(), hostile(), hostile(), hostile_len()).prop_map(|(fmin, fmax, flexible, len)| {
            Curve::Sigmoid(Sigmoid {
                fmin,
                fmax,
                flexible,
                len,
            })
        }),
        (
            hostile(),
            hostile(),
            hostile(),
            hostile_len(),
            hostile(),
            any::<bool>()
        )
            .prop_map(|(fmin, fmax, f_inf, len, tau, by_tau)| {
                let extent = if by_tau {
                    ExponentialExtent::Tau(tau)
                } else {
                    ExponentialExtent::Len(len)
                };
                Curve::Exponential(Exponential {
                    fmin,
                    fmax,
                    f_inf,
                    extent,
                })
            }),
        (
            hostile(),
            hostile(),
            hostile_len(),
            hostile(),
            any::<bool>()
        )
            .prop_map(|(fmin, fmax, len, a, by_a)| {
                let extent = if by_a {
                    LinearExtent::Accel(a)
                } else {
                    LinearExtent::Len(len)
                };
                Curve::Linear(Linear { fmin, fmax, extent })
            }),
        (
            hostile(),
            hostile(),
            hostile(),
            hostile(),
            hostile(),
            hostile()
        )
            .prop_map(
                |(fmin, fmax, accel, f1, f2, shape)| Curve::ThreeStage(ThreeStage {
                    fmin,
                    fmax,
                    accel,
                    f1,
                    f2,
                    shape
                })
            ),
        (hostile(), hostile(), hostile(), hostile()).prop_map(|(fmin, fmax, accel, jerk)| {
            Curve::JerkLimited(JerkLimited {
                fmin,
                fmax,
                accel,
                jerk,
            })
        }),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(cases() * 4))]

    /// Anything a caller of the core API can pass: a typed error or a valid
    /// table, never a panic.
    #[test]
    fn hostile_parameters_never_panic(
        curve in hostile_curve(),
        timer_hz in prop_oneof![Just(0u32), Just(1), Just(u32::MAX), 1u32..100_000_000],
        tps in 0u8..4,
        word in prop_oneof![Just(Word::U16), Just(Word::U32)],
        opts in options(),
        arithmetic in prop_oneof![Just(Arithmetic::F64), Just(Arithmetic::F32), Just(Arithmetic::Integer)],
        segments in prop_oneof![Just(0u32), Just(1), Just(u32::MAX), 1u32..100],
    ) {
        let s = Spec::new(curve, Timer { timer_hz, word, ticks_per_step: tps })
            .with_discretization(opts.0)
            .with_rounding(opts.1)
            .with_arithmetic(arithmetic);
        match s.validate() {
            Err(e) => {
                // Display never panics and says something.
                prop_assert!(!e.to_string().is_empty());
                prop_assert!(s.figures().is_err());
            }
            // Valid: computing is bounded by MAX_LEN; keep the run short.
            Ok(()) if s.len() <= 5000 => {
                if let Ok(t) = s.table() {
                    prop_assert_eq!(t.periods.len(), s.len() as usize);
                    prop_assert!(t.periods.iter().all(|&p| p >= 1 && p <= word.max()));
                }
                let _ = s.segment_table(segments);
            }
            Ok(()) => prop_assert!(s.len() <= profile_core::MAX_LEN + 1),
        }
    }
}

/// Any motor, any pulse train: the check and the simulation give a result
/// or a typed error, never a panic, and the simulation's work stays bounded.
mod motors {
    use super::*;
    use profile_codegen::motor::{Drive, Motor, TorqueCurve, Windings};
    use profile_codegen::simulate::{self, SimOptions};

    fn curve() -> impl Strategy<Value = Vec<(f64, f64)>> {
        proptest::collection::vec((hostile(), hostile()), 0..40)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(cases()))]

        #[test]
        fn hostile_motors_never_panic(
            points in curve(),
            step_angle in hostile(),
            microsteps in prop_oneof![Just(0u32), Just(1), Just(16), Just(u32::MAX)],
            inertia in (hostile(), hostile()),
            friction in hostile(),
            damping in hostile(),
            safety in hostile(),
            max_start in proptest::option::of(hostile()),
            periods in proptest::collection::vec(prop_oneof![Just(0u32), Just(1), Just(u32::MAX), 1u32..100_000], 0..40),
            timer_hz in prop_oneof![Just(0u32), Just(1_000_000), Just(u32::MAX)],
            dt in prop_oneof![Just(f64::NAN), Just(0.0), Just(-1.0), Just(1e-3), Just(1e-5)],
            windings in proptest::option::of((hostile(), hostile(), hostile(), hostile(), hostile(), hostile())),
        ) {
            let torque_curve = TorqueCurve::new(&points);
            prop_assert_eq!(
                torque_curve.is_none(),
                points.is_empty() || points.len() > profile_codegen::motor::MAX_CURVE_POINTS
            );
            let windings = windings.map(|w| {
                Windings::new(w.0, w.1, w.2, w.3, w.4).with_detent_torque(w.5)
            });
            let mut motor = Motor::new(step_angle, microsteps, inertia.0)
                .with_load_inertia(inertia.1)
                .with_friction(friction)
                .with_damping(damping)
                .with_safety(safety);
            // Absent or not, as drawn.
            motor.torque_curve = torque_curve;
            motor.windings = windings;
            motor.max_start_hz = max_start;
            let curve = Curve::Linear(Linear { fmin: 100.0, fmax: 1000.0, extent: LinearExtent::Len(10) });
            let spec = Spec::new(curve, Timer { timer_hz, word: Word::U32, ticks_per_step: 1 });
            if let Err(e) = motor.check(&spec, &periods) {
                prop_assert!(!e.to_string().is_empty());
            }
            let options = SimOptions { dt_s: dt, settle_s: 1e-3 };
            if let Err(e) = simulate::run(&motor, &spec, &periods, &options) {
                prop_assert!(!e.to_string().is_empty());
            }
        }
    }

    /// A positive value spread over `decades` decades from `low`.
    fn spread(low: f64, decades: f64) -> impl Strategy<Value = f64> {
        (0.0..decades).prop_map(move |d| low * 10f64.powf(d))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(torque_cases()))]

        /// Any valid windings, from watch motors to ones no one makes
        /// (short-circuit current far above and far below the set one): the
        /// derived pull-out torque is finite, at most the holding torque less
        /// the detent torque, and never rises with speed, whatever the drive.
        #[test]
        fn derived_pull_out_falls_with_speed(
            resistance in spread(0.01, 4.0),
            inductance in spread(1e-5, 4.0),
            rated_current in spread(0.05, 3.0),
            holding_torque in spread(0.005, 4.0),
            supply_voltage in spread(1.0, 3.0),
            detent in 0.0..0.5f64,
            poles in prop_oneof![Just(50.0), Just(100.0), Just(12.5)],
            drive in prop_oneof![Just(Drive::Sine), Just(Drive::HalfStep), Just(Drive::FullStep)],
        ) {
            let w = Windings::new(resistance, inductance, rated_current, holding_torque, supply_voltage)
                .with_detent_torque(detent * holding_torque)
                .with_drive(drive);
            prop_assert!(w.validate().is_ok());
            let top = holding_torque - w.detent_torque;
            // The stepped drives, 25 times the sine's work a speed, at a
            // quarter of its speeds.
            let speeds = if drive == Drive::Sine { 400 } else { 100 };
            // They sum stretches under the full supply in closed form,
            // whose terms scale with the short-circuit current `V / R`: up
            // to a million times the set current here, which leaves the
            // torque to within 1e-9 of itself.
            let flat = if drive == Drive::Sine { 1e-12 } else { 1e-9 };
            let mut last = f64::INFINITY;
            for k in 0..speeds {
                // 0 to 1e6 mechanical rad/s, finely at first.
                let omega = 1e6 * (k as f64 / speeds as f64).powi(4);
                let t = w.pull_out(poles, omega);
                prop_assert!(t.is_finite() && t >= 0.0, "{t} at {omega}");
                prop_assert!(t <= top * (1.0 + 1e-12), "{t} above {top} at {omega}");
                prop_assert!(t <= last * (1.0 + flat) + 1e-15, "{t} above {last} at {omega}");
                last = t;
            }
        }
    }
}
