//! The NEMA 17 of the motor tests: a 1.8° motor, 0.40 N·m holding torque,
//! rotor inertia 5.4e-6 kg·m², friction 0.02 N·m, its pull-out curve in full
//! steps per second scaled to the table's steps; and the chart of the
//! shipped QSH4218-47-28-040.

use profile_codegen::motor::{Motor, TorqueCurve};

/// Pull-out torque against full steps per second, N·m.
pub const CURVE: [(f64, f64); 6] = [
    (0.0, 0.40),
    (500.0, 0.38),
    (1000.0, 0.33),
    (2000.0, 0.24),
    (4000.0, 0.12),
    (6000.0, 0.06),
];

/// The motor at `microsteps` with a load of `load` kg·m²: undamped, no
/// safety factor, no `max_start_hz` (each test sets what it judges).
pub fn nema17(microsteps: u32, load: f64) -> Motor {
    let points: Vec<(f64, f64)> = CURVE
        .iter()
        .map(|&(hz, nm)| (hz * microsteps as f64, nm))
        .collect();
    Motor::new(1.8, microsteps, 5.4e-6)
        .with_torque_curve(TorqueCurve::new(&points).unwrap())
        .with_load_inertia(load)
        .with_friction(0.02)
}

/// TRINAMIC's QSH4218-47-28-040 by its manual's pull-out chart, as the
/// shipped `profiles.toml` gives it: N·m against steps per second in 1/8
/// steps, up to 1500 rpm.
pub const QSH4218_CHART: [(f64, f64); 11] = [
    (0.0, 0.40),
    (4000.0, 0.404),
    (8000.0, 0.404),
    (12000.0, 0.389),
    (16000.0, 0.375),
    (20000.0, 0.344),
    (24000.0, 0.308),
    (28000.0, 0.281),
    (32000.0, 0.255),
    (36000.0, 0.245),
    (40000.0, 0.235),
];
