//! `report`: every profile's parameters and figures, the accuracy of each
//! discretization and rounding, the motor check; and the files behind the
//! plots (`report -o DIR`, `plot`).

use std::fmt::Write as _;

use profile_codegen::__private::emit::start_note;
use profile_codegen::__private::schema::{describe, describe_motor};
use profile_codegen::motor::MotorError;
use profile_codegen::motor::{Drive, Motor};
use profile_codegen::profiles::{Profile, Profiles};
use profile_codegen::simulate::{self, SimOptions, SimResult};
use profile_codegen::{Generated, SpecTables};
use profile_core::CompactFigures;
use profile_core::player::{Player, Ramp};
use profile_core::{Curve, Linear, LinearExtent};
use profile_core::{Discretization, Error, Rounding, Spec};

/// The whole report of `profiles`, read from `path`.
pub fn text(path: &str, profiles: &Profiles) -> Result<String, Error> {
    let mut out = String::new();
    let _ = writeln!(out, "{path}: {} profiles\n", profiles.profiles().len());
    print_parameters(&mut out, profiles.profiles());
    print_table(&mut out, profiles.profiles())?;
    print_accuracy(&mut out, profiles.profiles())?;
    print_motors(&mut out, profiles.profiles());
    print_drivers(&mut out, profiles.profiles());
    print_cpu(&mut out, profiles.profiles());
    print_bands(&mut out, profiles.profiles());
    print_emergency(&mut out, profiles.profiles());
    Ok(out)
}

/// For each profile that names a step driver: its times, the shortest step
/// it takes against the table's shortest period, and the headroom.
fn print_drivers(out: &mut String, profiles: &[Profile]) {
    let bound = naming(profiles, |p| p.driver.as_ref());
    if bound.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nStep drivers (profiles that name one; periods in ticks of the profile's timer):"
    );
    let _ = writeln!(
        out,
        "{:<21} {:>10} {:>10} {:>10} {:>14} {:>14} {:>9}",
        "profile", "STEP high", "STEP low", "DIR setup", "driver's min", "table's min", "headroom"
    );
    for (p, d) in bound {
        let spec = p.table.spec();
        let shortest = d.shortest_entry(&spec.timer);
        let table_min = p.table.step_periods().into_iter().min().unwrap_or(0);
        let _ = writeln!(
            out,
            "{:<21} {:>10} {:>10} {:>10} {:>14} {:>14} {:>8.1}x",
            p.name,
            micros(d.step_pulse),
            micros(d.step_space),
            micros(d.dir_setup),
            shortest,
            table_min,
            f64::from(table_min) / f64::from(shortest.max(1)),
        );
    }
}

/// For each profile that names its core and clock: the step interrupt's
/// cycles and the CPU's load at the table's fastest entry.
fn print_cpu(out: &mut String, profiles: &[Profile]) {
    let bound = naming(profiles, |p| p.cpu.as_ref());
    if bound.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nStep interrupt (profiles that name their core; cycles a step, mean and largest, \
         from the measured figures; the load at the fastest entry):"
    );
    let _ = writeln!(
        out,
        "{:<21} {:>11} {:>9} {:>5} {:>7} {:>8} {:>10} {:>9} {:>16}",
        "profile",
        "core",
        "cpu",
        "axes",
        "cycles",
        "largest",
        "min ticks",
        "load",
        "serves, steps/s"
    );
    for (p, cpu) in bound {
        let spec = p.table.spec();
        let layout = profile_codegen::cpu::Layout::of(&p.table);
        let cost = cpu.cost(layout);
        let table_min = p.table.step_periods().into_iter().min().unwrap_or(0);
        let per_step = f64::from(spec.timer.ticks_per_step);
        let _ = writeln!(
            out,
            "{:<21} {:>11} {:>5} MHz {:>5} {:>7.1} {:>8.0} {:>10} {:>8.1}% {:>16.0}",
            p.name,
            cpu.core.name(),
            cpu.cpu_hz / 1e6,
            cpu.axes,
            cost.mean,
            cost.largest,
            table_min,
            100.0 * cpu.load(&spec.timer, layout, table_min),
            (cpu.max_rate(layout) / per_step).floor(),
        );
    }
}

/// For each profile that names an emergency ramp: a stop from the top
/// speed down the profile's own ramp against an abort down the emergency
/// ramp, in steps and in time.
fn print_emergency(out: &mut String, profiles: &[Profile]) {
    let bound = naming(profiles, |p| p.emergency.as_ref());
    if bound.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nEmergency ramps (profiles that name one; from the top speed, a stop down the profile's \
         own ramp and an abort, `STOP_STEPS`' last):"
    );
    let _ = writeln!(
        out,
        "{:<21} {:<21} {:>11} {:>11} {:>12} {:>12}",
        "profile", "emergency", "stop steps", "abort steps", "stop", "abort"
    );
    for (p, e) in bound {
        let Some(stop) = profiles.iter().find(|q| q.name == e.profile) else {
            continue;
        };
        let scale = p.table.spec().timer.frequency_scale();
        let millis =
            |periods: &[u32]| 1e3 * periods.iter().map(|&t| f64::from(t)).sum::<f64>() / scale;
        let own = p.table.step_periods();
        let steps = e.stop_steps.last().copied().unwrap_or(0);
        let emergency = stop.table.step_periods();
        let abort = &emergency[..(steps as usize).min(emergency.len())];
        let _ = writeln!(
            out,
            "{:<21} {:<21} {:>11} {:>11} {:>9.3} ms {:>9.3} ms",
            p.name,
            e.profile,
            own.len(),
            steps,
            millis(&own),
            millis(abort),
        );
    }
}

/// For each profile that names resonance bands: each band, in full steps/s
/// and in the table's steps/s, and the time the ramp spends in it.
fn print_bands(out: &mut String, profiles: &[Profile]) {
    let bound = naming(profiles, |p| p.avoid.as_ref());
    if bound.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nResonance bands (profiles that name them; the ramp crosses them, its top is outside):"
    );
    let _ = writeln!(
        out,
        "{:<21} {:>24} {:>24} {:>14}",
        "profile", "band, full steps/s", "band, steps/s", "ramp in it"
    );
    for (p, bands) in bound {
        let spec = p.table.spec();
        let periods = p.table.step_periods();
        let times = bands.time_in(&spec.timer, &periods);
        for ((full, steps), time) in bands.full_steps().iter().zip(bands.steps()).zip(times) {
            let _ = writeln!(
                out,
                "{:<21} {:>24} {:>24} {:>11.3} ms",
                p.name,
                format!("{} .. {}", full.0, full.1),
                format!("{} .. {}", steps.0, steps.1),
                time * 1e3,
            );
        }
    }
}

/// The profiles that name what `field` reads, with it.
fn naming<'a, T>(
    profiles: &'a [Profile],
    field: impl Fn(&'a Profile) -> Option<&'a T>,
) -> Vec<(&'a Profile, &'a T)> {
    profiles
        .iter()
        .filter_map(|p| Some((p, field(p)?)))
        .collect()
}

/// A driver's time in µs, to the nanosecond.
fn micros(seconds: f64) -> String {
    format!("{:.3} µs", seconds * 1e6)
}

/// Every profile's parameters, with their units, defaults included.
fn print_parameters(out: &mut String, profiles: &[Profile]) {
    let _ = writeln!(
        out,
        "Parameters (as written in a profiles file; defaults included):"
    );
    for p in profiles {
        let params: Vec<String> = describe(p.table.spec())
            .into_iter()
            .map(|(key, value)| format!("{key} = {value}"))
            .collect();
        let _ = writeln!(out, "{:<21} {}", p.name, params.join(", "));
    }
    let _ = writeln!(out);
    let bound: Vec<(&str, &Motor)> = profiles
        .iter()
        .filter_map(|p| Some((p.name.as_str(), p.motor.as_ref()?)))
        .collect();
    if bound.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "Motors (as the check reads them, in a datasheet's units; defaults included):"
    );
    for (name, motor) in bound {
        let figures: Vec<String> = describe_motor(motor)
            .into_iter()
            .map(|(key, value)| format!("{key} = {value}"))
            .collect();
        let _ = writeln!(out, "{name:<21} {}", figures.join(", "));
    }
    let _ = writeln!(out);
}

/// Step-edge error of a table against the continuous curve, in timer ticks:
/// `(largest |error|, error of the last edge)`.
fn edge_error(spec: &Spec, periods: &[u32]) -> Result<(f64, f64), Error> {
    let errors = crate::files::edge_errors(spec, periods)?;
    let worst = errors.iter().fold(0.0f64, |w, e| w.max(e.1.abs()));
    Ok((worst, errors.last().map_or(0.0, |e| e.1)))
}

fn print_table(out: &mut String, profiles: &[Profile]) -> Result<(), Error> {
    let row = table_row;
    row(
        out,
        [
            "profile",
            "curve",
            "discretization/round",
            "len",
            "start",
            "end",
            "ramp",
            "flash",
            "a table",
            "a curve",
            "j curve",
            "edge err",
            "margin",
        ],
    );
    row(
        out,
        [
            "", "", "", "steps", "Hz", "Hz", "s", "bytes", "Hz/s", "Hz/s", "Hz/s²", "ticks",
            "ticks",
        ],
    );
    for p in profiles {
        match &p.table {
            Generated::Steps(t) => {
                let (f, s) = (&t.figures, &t.spec);
                let (edge, _) = edge_error(s, &t.periods)?;
                row(
                    out,
                    [
                        &p.name,
                        s.curve.name(),
                        &format!("{}/{}", s.discretization.name(), s.rounding.name()),
                        &f.len.to_string(),
                        &format!("{:.1}", f.start_hz),
                        &format!("{:.1}", f.final_hz),
                        &format!("{:.4}", f.duration_s),
                        &(f.len as usize * s.timer.word.bytes() as usize).to_string(),
                        &format!("{:.3e}", f.max_accel_hz_s),
                        &format!("{:.3e}", f.curve_max_accel_hz_s),
                        &format!("{:.2e}", f.curve_max_jerk_hz_s2),
                        &format!("{edge:.3}"),
                        &f.overflow_margin_ticks.to_string(),
                    ],
                );
            }
            // Segments, runs and any layout to come: their compact figures.
            _ => {
                if let Some(c) = p.table.compact() {
                    compact_row(out, p, &c);
                }
            }
        }
    }
    let _ = writeln!(
        out,
        "\nlen: entries (a segment table: steps in all). start, end: step frequency of the \
         first and last entry. ramp: the table's duration as played. flash: the table's bytes.\n\
         a table: the integer table's largest acceleration, between the mean frequencies of \
         consecutive windows of at least 8 entries and 1/64 of the ramp, longer where one tick \
         of rounding could read as 5% of the ramp's mean acceleration (one entry's rounding \
         would read as acceleration). a curve, \
         j curve: the curve's own acceleration and jerk, from the unrounded periods.\n\
         edge err: the largest distance of a step edge from the continuous curve, in timer \
         ticks (a truncated \
         table drifts: each entry loses up to a tick). margin: ticks between the longest period \
         and the largest the word holds."
    );
    for p in profiles {
        if let Some(note) = start_note(&p.table) {
            let _ = writeln!(out, "note: {}: {note}", p.name);
        }
        if let Some(note) = compact_note(&p.table) {
            let _ = writeln!(out, "note: {}: {note}", p.name);
        }
    }
    Ok(())
}

/// A compact layout's flash against one entry per step, and its edge error
/// against what it was asked for.
fn compact_note(table: &Generated) -> Option<String> {
    let c = table.compact()?;
    let asked = c
        .tolerance_ticks
        .map_or(String::new(), |e| format!(" (`compress = {e}`)"));
    let (flash, per_step) = (f64::from(c.flash_bytes), f64::from(c.per_step_flash_bytes));
    let against = if c.flash_bytes < c.per_step_flash_bytes {
        format!("{:.1} times less", per_step / flash)
    } else {
        format!(
            "{:.1} times more: one entry per step is smaller here",
            flash / per_step.max(1.0)
        )
    };
    Some(format!(
        "{} {} take {} bytes of flash against {} for one entry per step ({against}); \
         every step edge is within {:.3} ticks of the curve{asked}.",
        c.entries, c.kind, c.flash_bytes, c.per_step_flash_bytes, c.max_edge_error_ticks
    ))
}

/// One row of the figures table.
fn table_row(out: &mut String, c: [&str; 13]) {
    let _ = writeln!(
        out,
        "{:<21} {:<14} {:<20} {:>5} {:>8} {:>8} {:>7} {:>5} {:>8} {:>8} {:>8} {:>8} {:>6}",
        c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10], c[11], c[12]
    );
}

/// A row of a compact layout (segments, runs): its frequencies from the
/// periods it plays.
fn compact_row(out: &mut String, p: &Profile, c: &CompactFigures) {
    let s = p.table.spec();
    let periods = p.table.step_periods();
    let hz = |ticks: Option<&u32>| s.timer.frequency_scale() / f64::from(*ticks.unwrap_or(&1));
    let top = periods.iter().copied().max().unwrap_or(0);
    table_row(
        out,
        [
            &p.name,
            s.curve.name(),
            &format!("{} {}", c.entries, c.kind),
            &c.steps.to_string(),
            &format!("{:.1}", hz(periods.first())),
            &format!("{:.1}", hz(periods.last())),
            &format!("{:.4}", c.total_ticks as f64 / s.timer.frequency_scale()),
            &c.flash_bytes.to_string(),
            "-",
            "-",
            "-",
            &format!("{:.3}", c.max_edge_error_ticks),
            &(s.timer.word.max() - top).to_string(),
        ],
    );
}

/// For each curve, every discretization and rounding against the continuous
/// curve: largest pulse-edge error and drift of the last edge, in ticks.
fn print_accuracy(out: &mut String, profiles: &[Profile]) -> Result<(), Error> {
    let _ = writeln!(
        out,
        "\nAccuracy against the continuous curve (largest |edge error| / drift of the last edge, ticks):"
    );
    let _ = writeln!(
        out,
        "{:<21} {:<14} {:>22} {:>22} {:>22}",
        "profile", "discretization", "truncate", "nearest", "diffuse"
    );
    for p in profiles {
        let Generated::Steps(t) = &p.table else {
            continue;
        };
        for d in [
            Discretization::Exact,
            Discretization::LeftEndpoint,
            Discretization::Index,
        ] {
            let mut row = format!("{:<21} {:<14}", p.name, d.name());
            let mut any = false;
            for r in [Rounding::Truncate, Rounding::Nearest, Rounding::Diffuse] {
                let mut spec = t.spec.with_discretization(d).with_rounding(r);
                if d != Discretization::Index {
                    spec = spec.with_arithmetic(profile_core::Arithmetic::F64);
                }
                let cell = match spec.table() {
                    Ok(table) => {
                        any = true;
                        let (worst, last) = edge_error(&spec, &table.periods)?;
                        format!("{worst:>10.3} / {last:>9.3}")
                    }
                    Err(_) => "-".to_string(),
                };
                row.push_str(&format!(" {cell:>22}"));
            }
            if any {
                let _ = writeln!(out, "{row}");
            }
        }
    }
    Ok(())
}

/// The move a `Player` plays from `table`: up it and down it again.
fn round_trip(table: &[u32]) -> Vec<u32> {
    let mut player = Player::new(Ramp::steps(table));
    player.start(2 * table.len() as u32);
    std::iter::from_fn(|| player.next_period()).collect()
}

/// The motor-bound profile's move (up the table and down), simulated.
fn simulate_move(motor: &Motor, spec: &Spec, table: &[u32]) -> Result<SimResult, String> {
    let moves = round_trip(table);
    let options = SimOptions::suggested(motor, spec, &moves);
    simulate::run(motor, spec, &moves, &options).map_err(|e| e.to_string())
}

/// For each profile that names a motor: the smallest torque margin of the
/// compile-time check and where it is, and the simulated move.
fn print_motors(out: &mut String, profiles: &[Profile]) {
    let bound: Vec<&Profile> = profiles.iter().filter(|p| p.motor.is_some()).collect();
    if bound.is_empty() {
        return;
    }
    let _ = writeln!(
        out,
        "\nMotor torque (profiles that name a motor; the move is the table up and down again, simulated):"
    );
    let _ = writeln!(
        out,
        "{:<21} {:>10} {:>6} {:>9} {:>9} {:>9} {:>9}   {:>5} {:>5} {:>8} {:>9}",
        "profile",
        "margin",
        "step",
        "at Hz",
        "needed",
        "available",
        "start max",
        "lost",
        "slips",
        "max lag",
        "overshoot"
    );
    let _ = writeln!(
        out,
        "{:<21} {:>10} {:>6} {:>9} {:>9} {:>9} {:>9}   {:>5} {:>5} {:>8} {:>9}",
        "", "N·m", "", "", "N·m", "N·m", "Hz", "steps", "", "°el", "steps"
    );
    for p in &bound {
        let (Some(motor), Some(t)) = (&p.motor, &p.torque) else {
            continue;
        };
        let sim = match simulate_move(motor, p.table.spec(), &p.table.step_periods()) {
            Ok(r) => format!(
                "{:>5} {:>5} {:>8.1} {:>9.3}",
                r.lost_steps, r.slips, r.max_lag_deg, r.overshoot_steps
            ),
            Err(e) => format!("simulation: {e}"),
        };
        // The fastest start from rest with the load, searched up to where
        // the motor is characterised.
        let start = motor.start_limit(motor.top_hz()).hz();
        let _ = writeln!(
            out,
            "{:<21} {:>10.4} {:>6} {:>9.1} {:>9.4} {:>9.4} {:>9.1}   {sim}",
            p.name, t.min_margin_nm, t.step, t.hz, t.needed_nm, t.available_nm, start
        );
    }
    print_pull_out(out, &bound);
    print_fastest(out, &bound);
    let _ = writeln!(
        out,
        "\nmargin: the smallest torque to spare over the ramp, at that step and step \
         frequency, where the step needs `needed` and the motor gives `available` (its \
         pull-out curve over `safety`). start max: the fastest step rate the motor starts \
         at from rest with its load (`max_start_hz` over sqrt(1 + load_inertia / \
         rotor_inertia), or the fastest the model's rotor pulls in to, torque over `safety`).\nlost: table steps the simulated rotor ends behind (or, \
         negative, ahead); slips: times it fell into another stable position (a lag past \
         180° electrical); max lag: its largest lag behind the field, electrical degrees \
         (below 90° with torque to spare); overshoot: how far past its final position it \
         swings after the last pulse, table steps."
    );
}

/// For each motor-bound profile whose motor gives its windings: the
/// pull-out torque they give against the typed curve, from rest to the
/// ramp's fastest step.
fn print_pull_out(out: &mut String, bound: &[&Profile]) {
    for p in bound {
        let Some(motor) = &p.motor else { continue };
        if motor.windings.is_none() {
            continue;
        }
        // From rest to the ramp's fastest step or the curve's last point.
        let top = p
            .table
            .step_periods()
            .iter()
            .map(|&t| p.table.spec().timer.frequency_scale() / t as f64)
            .fold(motor.torque_curve.map_or(0.0, |c| c.top()), f64::max);
        let points: Vec<f64> = (0..=4).map(|k| top * k as f64 / 4.0).collect();
        let row = |f: &dyn Fn(f64) -> Option<f64>| -> String {
            points
                .iter()
                .map(|&hz| f(hz).map_or(format!("{:>9}", "-"), |nm| format!("{nm:>9.4}")))
                .collect()
        };
        let derived = row(&|hz| motor.derived_pull_out(hz));
        // The drive, where it is not the default sine.
        let drive = match motor.windings.map(|w| w.drive) {
            Some(Drive::Sine) | None => String::new(),
            Some(d) => format!(", {}", d.name()),
        };
        let frequencies: String = points.iter().map(|hz| format!("{hz:>9.1}")).collect();
        let mut rows = vec![("  at step frequency (Hz)".to_string(), frequencies)];
        match motor.torque_curve {
            Some(curve) => {
                let typed = row(&|hz| Some(curve.torque(hz)));
                rows.push(("  `torque_curve` (used by the check)".to_string(), typed));
                rows.push((format!("  derived from the windings{drive}"), derived));
            }
            None => rows.push((
                format!("  derived from the windings{drive} (used by the check)"),
                derived,
            )),
        }
        // The figures start in one column, after the longest label.
        let width = rows
            .iter()
            .map(|(label, _)| label.chars().count() + 2)
            .fold(50, usize::max);
        let _ = writeln!(out, "\n`{}`: the motor's pull-out torque, N·m", p.name);
        for (label, figures) in rows {
            let _ = writeln!(out, "{label:<width$}{figures}");
        }
    }
}

/// For each `torque_limited` profile: the torque at its top with the
/// margin, and the time it saves against the steepest constant
/// acceleration from the same start that passes the same check.
fn print_fastest(out: &mut String, bound: &[&Profile]) {
    for p in bound {
        let (Some(motor), Curve::TorqueLimited(ramp)) = (&p.motor, p.table.spec().curve) else {
            continue;
        };
        let spec = p.table.spec();
        let ticks: u64 = p.table.step_periods().iter().map(|&t| u64::from(t)).sum();
        let time = ticks as f64 / spec.timer.frequency_scale();
        let (fmin, fmax, margin) = (ramp.fmin, ramp.fmax, ramp.margin);
        let available = motor.available(fmax);
        let _ = writeln!(
            out,
            "\n`{}`: the fastest ramp the motor allows, planned on {} of its torque (every \
             edge passes the check with `safety` {:.3} / {} = {:.3})",
            p.name,
            margin,
            motor.safety,
            margin,
            motor.safety / margin
        );
        let _ = writeln!(
            out,
            "  at its top, {fmax:.1} Hz: available {available:.4} N·m, planned {:.4} N·m \
             (`margin` of it), friction and damping {:.4} N·m",
            margin * available,
            motor.friction + motor.damping * motor.step_radians() * fmax
        );
        match steepest_linear(motor, spec, fmin, fmax, margin) {
            Some((accel, linear)) => {
                let _ = writeln!(
                    out,
                    "  to {fmax:.1} Hz in {:.2} ms; the steepest constant acceleration from \
                     {fmin:.1} Hz that passes the same check, {accel:.4e} Hz/s, takes {:.2} \
                     ms: {:.1} % saved",
                    time * 1e3,
                    linear * 1e3,
                    (1.0 - time / linear) * 100.0
                );
            }
            None => {
                let _ = writeln!(
                    out,
                    "  to {fmax:.1} Hz in {:.2} ms; no constant acceleration from {fmin:.1} Hz \
                     passes the same check",
                    time * 1e3
                );
            }
        }
    }
}

/// The steepest linear ramp from `fmin` to `fmax` on `spec`'s timer that
/// the motor's check passes with every edge at `safety / margin`: its
/// acceleration, Hz/s, and its time, s (bisection on the acceleration's
/// logarithm, 40 halvings, from 1 Hz/s to 1e12 Hz/s).
fn steepest_linear(
    motor: &Motor,
    spec: &Spec,
    fmin: f64,
    fmax: f64,
    margin: f64,
) -> Option<(f64, f64)> {
    let strict = motor.with_safety(motor.safety / margin);
    let time = |accel: f64| -> Option<f64> {
        let mut linear = *spec;
        linear.curve = Curve::Linear(Linear {
            fmin,
            fmax,
            extent: LinearExtent::Accel(accel),
        });
        let table = linear.table().ok()?;
        motor.check(&linear, &table.periods).ok()?;
        if let Err(MotorError::Torque { .. }) = strict.check(&linear, &table.periods) {
            return None;
        }
        let ticks: u64 = table.periods.iter().map(|&t| u64::from(t)).sum();
        Some(ticks as f64 / spec.timer.frequency_scale())
    };
    // The slowest that fits a table.
    let (mut lo, mut hi) = ((fmax - fmin) * (fmax + fmin) / 65_536.0, 1e12f64);
    time(lo)?;
    for _ in 0..40 {
        let mid = (lo * hi).sqrt();
        if time(mid).is_some() {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    time(lo).map(|t| (lo, t))
}
