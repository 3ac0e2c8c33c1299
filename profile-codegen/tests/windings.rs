//! The pull-out torque derived from a motor's windings against an
//! independent computation: the two phases' currents integrated in time
//! under a chopper that switches the supply it puts across a winding on
//! each phase, the rotor turning at a steady speed and lagging the field by
//! a fixed angle, the torque averaged over an electrical turn, less the
//! iron's drag, and maximised over the lag.
//!
//! The production path solves the steady state in the rotor's frame in
//! closed form (phasors, the fundamental of the saturated voltage); this one
//! shares none of it: it chops the real square-wave voltage, carries every
//! harmonic of the current, and finds the pull-out torque by search. The
//! losses' definitions (the share of the supply, the iron's drag at 1 kHz
//! growing as the frequency's 0.4th power) and the driver's current
//! setting are read here from the `Windings`' documented figures.
//!
//! Published pull-out charts: `charts.rs`.

use core::f64::consts::{PI, SQRT_2, TAU};

use profile_codegen::motor::{CurrentSetting, Drive, Windings};

/// The current the driver is set to, in A: the sine's amplitude for a sine
/// drive (its RMS setting times `sqrt(2)`, or its peak setting), the level
/// each phase is switched to for the stepped drives.
fn set_current(w: &Windings) -> f64 {
    let setting = w.driver_current.unwrap_or(w.rated_current);
    match (w.drive, w.driver_current_is) {
        (Drive::Sine, CurrentSetting::Rms) => SQRT_2 * setting,
        _ => setting,
    }
}

/// The currents the driver sets on phases A and B with the field at
/// `field` (electrical radians): a sine and cosine of the set amplitude;
/// in half steps the field points at the nearest of eight directions, each
/// phase on (at the set level) where that direction has a component along
/// it; in full steps at the nearest diagonal, both phases on.
fn reference(w: &Windings, field: f64) -> (f64, f64) {
    let i = set_current(w);
    match w.drive {
        Drive::HalfStep => {
            let direction = (field / (PI / 4.0)).round() * (PI / 4.0);
            let on = |c: f64| if c.abs() < 0.5 { 0.0 } else { i * c.signum() };
            (on(direction.cos()), on(direction.sin()))
        }
        Drive::FullStep => (i * field.cos().signum(), i * field.sin().signum()),
        _ => (i * field.cos(), i * field.sin()),
    }
}

/// The iron's drag, in N·m, at an electrical frequency of `hz`: the figure
/// at 1 kHz (0.11 of the holding torque when not given) times `(hz / 1
/// kHz)^0.4`.
fn iron_drag(w: &Windings, hz: f64) -> f64 {
    let at_1khz = w.iron_loss.unwrap_or(0.11 * w.holding_torque);
    at_1khz * (hz / 1000.0).powf(0.4)
}

/// Average torque, in N·m, of a motor turning at `omega` (mechanical rad/s)
/// with the field `lag` electrical radians ahead of the rotor, the driver
/// chopping each phase's current towards its reference with the share of
/// the supply it puts across the winding, less the iron's drag.
fn chopped_torque(w: &Windings, poles: f64, omega: f64, lag: f64) -> f64 {
    // Two phases on at the rated current give the holding torque.
    let km = w.holding_torque / (SQRT_2 * w.rated_current);
    let supply = w.supply_voltage * w.supply_utilization;
    let electrical = poles * omega;
    let turn = TAU / electrical;
    // 8000 steps per electrical turn; the current changes by at most
    // `supply · dt / L` a step.
    let steps = 8000;
    let dt = turn / steps as f64;
    let decay = (-w.resistance * dt / w.inductance).exp();
    // Every turn passes the same angles: the rotor's sine and cosine and
    // the set currents, at the middle of each step of a turn.
    let angles: Vec<(f64, f64, f64, f64)> = (0..steps)
        .map(|k| {
            let rotor = electrical * (k as f64 + 0.5) * dt;
            let (ra, rb) = reference(w, rotor + lag);
            (rotor.sin(), rotor.cos(), ra, rb)
        })
        .collect();
    let (mut ia, mut ib) = (0.0f64, 0.0f64);
    let mut sum = 0.0;
    // Eight turns: the currents settle within a few `L / R`, short against
    // these speeds' turns; the last turn is averaged.
    let turns = 8;
    for k in 0..turns * steps {
        let (sin, cos, ra, rb) = angles[k % steps];
        let va = if ia < ra { supply } else { -supply };
        let vb = if ib < rb { supply } else { -supply };
        // Back-EMF of each phase; over one step the winding is an R-L
        // circuit under a constant voltage, solved exactly.
        let (ea, eb) = (-km * omega * sin, km * omega * cos);
        let (sa, sb) = ((va - ea) / w.resistance, (vb - eb) / w.resistance);
        ia = sa + (ia - sa) * decay;
        ib = sb + (ib - sb) * decay;
        if k >= (turns - 1) * steps {
            sum += km * (ib * cos - ia * sin);
        }
    }
    sum / steps as f64 - w.detent_torque - iron_drag(w, electrical / TAU)
}

/// The largest average torque over the lag: a scan, then a golden-section
/// search around the best, each torque computed once (the inner point kept
/// from one bracket to the next is the golden ratio's).
fn chopped_pull_out(w: &Windings, poles: f64, omega: f64) -> f64 {
    let f = |lag: f64| chopped_torque(w, poles, omega, lag);
    let scan = 24;
    let best = (1..scan)
        .map(|k| {
            let lag = PI * k as f64 / scan as f64;
            (lag, f(lag))
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap()
        .0;
    let (mut lo, mut hi) = (best - PI / scan as f64, best + PI / scan as f64);
    let g = (5f64.sqrt() - 1.0) / 2.0;
    let (mut a, mut b) = (hi - g * (hi - lo), lo + g * (hi - lo));
    let (mut fa, mut fb) = (f(a), f(b));
    for _ in 0..20 {
        if fa < fb {
            (lo, a, fa) = (a, b, fb);
            b = lo + g * (hi - lo);
            fb = f(b);
        } else {
            (hi, b, fb) = (b, a, fa);
            a = hi - g * (hi - lo);
            fa = f(a);
        }
    }
    f(0.5 * (lo + hi)).max(0.0)
}

/// Full steps per second to mechanical rad/s, for a 1.8° motor.
fn omega(full_steps: f64) -> f64 {
    full_steps * 1.8f64.to_radians()
}

fn motors() -> [(&'static str, Windings); 5] {
    [
        (
            "NEMA 17, 2.8 A, 24 V",
            Windings::new(0.7, 1.1e-3, 2.8, 0.40, 24.0),
        ),
        (
            "NEMA 17, 1.0 A, 12 V, detent",
            Windings::new(4.4, 8.0e-3, 1.0, 0.44, 12.0).with_detent_torque(0.02),
        ),
        (
            "NEMA 23, 4.2 A, 48 V",
            Windings::new(0.55, 2.6e-3, 4.2, 1.9, 48.0),
        ),
        (
            "NEMA 23, 4.0 A, 36 V, 4.2 A peak",
            Windings::new(0.65, 3.2e-3, 4.0, 2.4, 36.0)
                .with_driver_current(4.2, CurrentSetting::Peak),
        ),
        (
            "NEMA 17, 2.8 A, 24 V at 2 A, ideal",
            Windings::new(0.7, 1.1e-3, 2.8, 0.40, 24.0)
                .with_driver_current(2.0, CurrentSetting::Rms)
                .with_supply_utilization(1.0)
                .with_iron_loss(0.0),
        ),
    ]
}

/// The derived and the chopped pull-out torque of a 1.8° motor at
/// `full_steps` per second, printed, and how far the derived one is above,
/// as a fraction of the holding torque.
fn compare(name: &str, w: &Windings, full_steps: f64) -> (f64, f64, f64) {
    let derived = w.pull_out(50.0, omega(full_steps));
    let chopped = chopped_pull_out(w, 50.0, omega(full_steps));
    let off = (derived - chopped) / w.holding_torque;
    println!(
        "{name:<30} {full_steps:>6} full steps/s: derived {derived:.4} N·m, \
         chopped {chopped:.4} N·m ({:+.1} % of holding)",
        off * 100.0
    );
    (derived, chopped, off)
}

#[test]
fn derived_pull_out_agrees_with_the_chopped_windings_in_time() {
    let mut worst = 0.0f64;
    for (name, w) in motors() {
        for full_steps in [50.0, 250.0, 500.0, 1000.0, 2000.0, 4000.0, 8000.0] {
            let (derived, chopped, off) = compare(name, &w, full_steps);
            worst = worst.max(off.abs());
            // Where the chopper holds the current, where it holds it through
            // part of each turn, and where it has given up (a square wave on
            // each phase), the two agree within 1 % of the holding torque:
            // the chopper's ripple, here a switching every 1/8000 of a turn.
            assert!(
                (-0.005..0.01).contains(&off),
                "{name} at {full_steps} full steps/s: derived {derived} N·m, chopped {chopped} N·m"
            );
        }
    }
    println!(
        "largest difference: {:.1} % of the holding torque",
        worst * 100.0
    );
}

/// TRINAMIC's QSH4218-47-28-040 (manual V1.10, Table 2.1) on a 24 V supply.
fn qsh4218() -> Windings {
    Windings::new(0.5, 0.6e-3, 2.8, 0.40, 24.0)
}

/// Where the back-EMF is large against the resistance, the speeds at which
/// the chopper holds the current through only part of each turn span a wide
/// band: on the QSH4218-47-28-040's windings (0.5 Ω, 0.6 mH, 2.8 A,
/// 0.40 N·m, 24 V) from 5000 to beyond 10 000 full steps/s, and on a
/// low-inductance winding whose short-circuit current `K_m / (N_r L)`
/// (10.1 A) exceeds the set amplitude (3.96 A), which at speed brakes the
/// rotor (here behind an ideal chopper, the whole supply across the
/// winding and no iron loss, so that the braking alone takes the torque).
/// The derived torque follows the chopped phases through both, and gives
/// nothing where they give nothing.
#[test]
fn where_the_back_emf_dominates_the_derived_torque_follows_as_well() {
    let qsh = qsh4218();
    let mut brake = qsh.with_supply_utilization(1.0).with_iron_loss(0.0);
    brake.inductance = 0.2e-3;
    for (name, w) in [("QSH4218-47-28-040", qsh), ("0.2 mH, braking", brake)] {
        let mut worst = 0.0f64;
        for k in 1..=20 {
            let full_steps = 1000.0 * k as f64;
            let (derived, chopped, off) = compare(name, &w, full_steps);
            assert!(
                (-0.005..0.01).contains(&off),
                "{name} at {full_steps} full steps/s: derived {derived} N·m, chopped {chopped} N·m"
            );
            if derived == 0.0 {
                assert!(chopped < 0.005 * w.holding_torque, "{name} at {full_steps}");
            }
            worst = worst.max(off.abs());
        }
        println!(
            "{name}: at most {:.1} % of the holding torque apart",
            worst * 100.0
        );
    }
    // The braking winding gives nothing from 17 000 full steps/s on.
    assert!(brake.pull_out(50.0, omega(16_000.0)) > 0.004);
    for full_steps in [17_000.0, 20_000.0, 40_000.0, 1e6] {
        assert_eq!(brake.pull_out(50.0, omega(full_steps)), 0.0);
    }
}

/// Windings drawn at random (a fixed sequence) over the figures of real
/// two-phase motors and drivers, each at speeds from where its torque
/// starts to fall to four times that: held, partly held and square-wave
/// phases, the corner between included. The derived torque is the chopped
/// one within 1 % of the holding torque, or within 1.5 times the chopper's
/// own ripple where that is larger: the current one switching interval
/// moves, `supply · dt / L`, over the set amplitude (a low-inductance
/// winding at low speed, where 8000 switchings a turn are coarse).
#[test]
fn random_windings_agree_with_the_chopped_phases() {
    let mut state = 0x9E37_79B9_7F4A_7C15u64;
    let mut uniform = move || {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut spread = |low: f64, high: f64| low * (high / low).powf(uniform());
    let mut worst = 0.0f64;
    for n in 0..10 {
        // In this order: resistance, inductance, rated current, holding
        // torque, supply voltage.
        let w = Windings::new(
            spread(0.2, 5.0),
            spread(0.3e-3, 10e-3),
            spread(0.3, 4.0),
            spread(0.1, 3.0),
            spread(12.0, 48.0),
        );
        // Where the derived torque has fallen by 5 %: bisection on full
        // steps per second.
        let falls = |fs: f64| w.pull_out(50.0, omega(fs)) < 0.95 * w.holding_torque;
        let (mut lo, mut hi) = (0.0, 1e6);
        if !falls(hi) {
            continue;
        }
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if falls(mid) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        for factor in [0.8, 1.0, 1.3, 2.0, 4.0] {
            let full_steps = hi * factor;
            let (derived, chopped, off) = compare(&format!("random {n}"), &w, full_steps);
            let dt = TAU / (50.0 * omega(full_steps)) / 8000.0;
            let supply = w.supply_voltage * w.supply_utilization;
            let ripple = supply * dt / w.inductance / set_current(&w);
            let allowed = 0.01f64.max(1.5 * ripple);
            assert!(
                (-0.005..allowed).contains(&off),
                "{w:?} at {full_steps} full steps/s: derived {derived} N·m, chopped {chopped} N·m"
            );
            worst = worst.max(off.abs());
        }
    }
    println!(
        "random windings: at most {:.2} % of the holding torque apart",
        worst * 100.0
    );
}

/// The drives that step the current, against the chopped phases: half
/// steps and full steps on the three sets of figures from rest to where the
/// current is lost. At rest the mean torque is the staircase's fundamental
/// (`K_m` times the mean over a turn of the set current against the field's
/// direction, summed here over the test's own staircase); at speed the two
/// routes agree within 1 % of the holding torque.
#[test]
fn stepped_drives_agree_with_the_chopped_phases() {
    let mut worst = 0.0f64;
    for drive in [Drive::HalfStep, Drive::FullStep] {
        for (name, w) in motors() {
            let w = w.with_drive(drive);
            // The fundamental of the set current along the field, by sums.
            let n = 1 << 16;
            let fundamental = (0..n)
                .map(|k| {
                    let field = TAU * (k as f64 + 0.5) / n as f64;
                    reference(&w, field).0 * field.cos()
                })
                .sum::<f64>()
                * 2.0
                / n as f64;
            let km = w.holding_torque / (SQRT_2 * w.rated_current);
            let at_rest = w.pull_out(50.0, 0.0);
            assert!(
                (at_rest - (km * fundamental - w.detent_torque)).abs() < 1e-6 * w.holding_torque,
                "{name}, {drive:?}: {at_rest} at rest"
            );
            for full_steps in [50.0, 250.0, 500.0, 1000.0, 2000.0, 4000.0, 8000.0] {
                let label = format!("{name}, {drive:?}");
                let (_, _, off) = compare(&label, &w, full_steps);
                assert!(
                    off.abs() < 0.01,
                    "{label} at {full_steps} full steps/s: {off}"
                );
                worst = worst.max(off.abs());
            }
        }
    }
    println!(
        "stepped drives: at most {:.2} % of the holding torque apart",
        worst * 100.0
    );
}
