//! The motor check against the simulation over a grid of moves: the check's
//! verdict (`safety = 1`) and the simulation's (a step lost or gained) agree
//! on most moves, with the motor's electromagnetic damping on.
//!
//! Each move is a constant-acceleration ramp from a start rate to 2000 full
//! steps/s, played by the `Player` up and down again (symmetric), on the
//! NEMA 17 of `tests/motor.rs` at `damping_ratio = 0.1`, without
//! `max_start_hz` (the model judges the start). 240 moves, in about a
//! second; the disagreements are printed by
//!
//! ```text
//! cargo test --test agreement -- --nocapture
//! ```

use test_support as common;

use profile_codegen::SpecTables;
use profile_codegen::motor::{Motor, MotorError};
use profile_codegen::simulate::{self, SimOptions};
use profile_core::player::{Player, Ramp};
use profile_core::{Curve, Linear, LinearExtent, Spec, Timer};

const ACCELS: [f64; 10] = [
    50_000.0, 80_000.0, 100_000.0, 120_000.0, 140_000.0, 160_000.0, 180_000.0, 220_000.0,
    300_000.0, 450_000.0,
];
const STARTS: [f64; 4] = [200.0, 400.0, 600.0, 800.0];
const LOADS: [f64; 3] = [0.0, 1.0e-5, 2.0e-5];
const MICROSTEPS: [u32; 2] = [1, 8];

fn motor(load: f64, microsteps: u32) -> Motor {
    common::motors::nema17(microsteps, load).with_damping_ratio(0.1)
}

struct Case {
    accel: f64,
    start: f64,
    load: f64,
    microsteps: u32,
    check: Result<f64, String>,
    lost: i64,
    slips: u32,
    first_slip: Option<u32>,
    pulses: usize,
}

fn run(accel: f64, start: f64, load: f64, microsteps: u32) -> Case {
    let m = motor(load, microsteps);
    let k = microsteps as f64;
    let spec = Spec::new(
        Curve::Linear(Linear {
            fmin: start * k,
            fmax: 2000.0 * k,
            extent: LinearExtent::Accel(accel * k),
        }),
        Timer::new(if microsteps == 1 {
            1_000_000
        } else {
            10_000_000
        }),
    );
    let table = spec.table().unwrap().periods;
    let check = match m.check(&spec, &table) {
        Ok(f) => Ok(f.min_margin_nm),
        Err(
            e @ (MotorError::Torque { .. }
            | MotorError::Start { .. }
            | MotorError::PullIn { .. }
            | MotorError::ShortMove { .. }),
        ) => Err(e.to_string()),
        Err(e) => panic!("{e}"),
    };
    let mut player = Player::new(Ramp::steps(&table));
    player.start(2 * table.len() as u32);
    let moves: Vec<u32> = std::iter::from_fn(|| player.next_period()).collect();
    let result = simulate::run(&m, &spec, &moves, &SimOptions::suggested(&m, &spec, &moves))
        .unwrap_or_else(|e| panic!("{e}"));
    Case {
        accel,
        start,
        load,
        microsteps,
        check,
        lost: result.lost_steps,
        slips: result.slips,
        first_slip: result.first_slip_pulse,
        pulses: moves.len(),
    }
}

#[test]
fn the_check_and_the_simulation_agree_on_the_grid() {
    let mut cases = Vec::new();
    for &microsteps in &MICROSTEPS {
        for &load in &LOADS {
            for &start in &STARTS {
                for &accel in &ACCELS {
                    cases.push(run(accel, start, load, microsteps));
                }
            }
        }
    }
    let mut agree = 0;
    println!("disagreements (check with safety 1 against the simulated move, damping_ratio 0.1):");
    for c in &cases {
        let passes = c.check.is_ok();
        let keeps = c.lost == 0 && c.slips == 0;
        if passes == keeps {
            agree += 1;
        } else {
            println!(
                "  {:>7} full steps/s² from {:>3} full steps/s, load {:.1e} kg·m², 1/{} steps: \
                 check {}, simulation lost {} steps in {} slips, the first at pulse {:?} of {}",
                c.accel,
                c.start,
                c.load,
                c.microsteps,
                match &c.check {
                    Ok(margin) => format!("passes ({margin:.4} N·m to spare)"),
                    Err(e) => format!("refuses ({e})"),
                },
                c.lost,
                c.slips,
                c.first_slip,
                c.pulses
            );
        }
    }
    let refused = cases.iter().filter(|c| c.check.is_err()).count();
    let lost = cases.iter().filter(|c| c.lost != 0 || c.slips != 0).count();
    println!(
        "{} moves: agree on {agree} ({:.1} %); the check refuses {refused}, the simulation loses steps on {lost}",
        cases.len(),
        100.0 * agree as f64 / cases.len() as f64
    );
    assert_eq!(cases.len(), 240);
    // Both verdicts occur: the grid spans the boundary.
    assert!(
        refused > cases.len() / 10 && refused < cases.len() * 9 / 10,
        "{refused}"
    );
    assert!(
        agree * 100 >= 95 * cases.len(),
        "{agree} of {}",
        cases.len()
    );
}
