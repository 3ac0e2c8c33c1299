//! The main job: read a profiles file, print every profile's figures and an
//! accuracy comparison, and write plots, CSV files and a C header.
//!
//! ```text
//! cargo run --example report [-- PATH] [--docs]
//! ```
//!
//! PATH defaults to the `profiles.toml` at the root of this repository.
//! Output goes to `target/profiles/` (one SVG and one CSV per profile, an
//! overview, `profiles.h`, and `NAME_torque.svg` for each profile that names
//! a motor). `--docs` also regenerates the figures under `docs/` that the
//! README shows. A mistake in the file prints
//! `file:line:col: message` and exits with status 1.

mod plots;

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::mpsc;
use std::time::Duration;

use plotters::style::RGBColor;
use profile_core::Generated;
use profile_core::build::Profiles;
use profile_core::emit::Profile;
use profile_core::motor::Motor;
use profile_core::player::{Player, Ramp};
use profile_core::simulate::{self, SimOptions, SimResult};
use profile_core::{Discretization, Error, Rounding, Spec, Table};

use plots::Series;

const PALETTE: [RGBColor; 6] = [
    RGBColor(0x1f, 0x77, 0xb4),
    RGBColor(0xd6, 0x27, 0x28),
    RGBColor(0x2c, 0xa0, 0x2c),
    RGBColor(0xff, 0x7f, 0x0e),
    RGBColor(0x94, 0x67, 0xbd),
    RGBColor(0x8c, 0x56, 0x4b),
];

/// Pulse-edge error of a table against the continuous curve, in ticks:
/// `(largest |error|, error of the last edge)`.
fn edge_error(spec: &Spec, periods: &[u32]) -> Result<(f64, f64), Error> {
    let scale = spec.timer.timer_hz as f64 / spec.timer.ticks_per_step as f64;
    let mut played = 0u64;
    let mut worst = 0.0f64;
    let mut last = 0.0;
    spec.for_each_exact_edge(|k, t| {
        if let Some(p) = periods.get(k as usize - 1) {
            played += *p as u64;
            last = played as f64 - t * scale;
            worst = worst.max(last.abs());
        }
    })?;
    Ok((worst, last))
}

fn print_table(profiles: &[Profile]) -> Result<(), Error> {
    println!(
        "{:<21} {:<12} {:<22} {:>5} {:>9} {:>9} {:>8} {:>6} {:>9} {:>9} {:>8} {:>7}",
        "profile",
        "curve",
        "discretization/round",
        "len",
        "start Hz",
        "end Hz",
        "ramp s",
        "flash",
        "max a",
        "max jerk",
        "edge err",
        "margin"
    );
    println!(
        "{:<21} {:<12} {:<22} {:>5} {:>9} {:>9} {:>8} {:>6} {:>9} {:>9} {:>8} {:>7}",
        "", "", "", "steps", "", "", "", "bytes", "Hz/s", "Hz/s²", "ticks", "ticks"
    );
    for p in profiles {
        match &p.table {
            Generated::Steps(t) => {
                let (f, s) = (&t.figures, &t.spec);
                let (edge, _) = edge_error(s, &t.periods)?;
                println!(
                    "{:<21} {:<12} {:<22} {:>5} {:>9.1} {:>9.1} {:>8.5} {:>6} {:>9.3e} {:>9.2e} {:>8.3} {:>7}",
                    p.name,
                    s.curve.name(),
                    format!("{}/{}", s.discretization.name(), s.rounding.name()),
                    f.len,
                    f.start_hz,
                    f.final_hz,
                    f.duration_s,
                    f.len as usize * s.timer.word.bytes() as usize,
                    f.max_accel_hz_s,
                    f.max_jerk_hz_s2,
                    edge,
                    f.overflow_margin_ticks,
                );
            }
            Generated::Segments(t) => {
                let (f, s) = (&t.figures, &t.spec);
                let top = t.pairs.iter().map(|p| p.0).max().unwrap_or(0);
                println!(
                    "{:<21} {:<12} {:<22} {:>5} {:>9.1} {:>9.1} {:>8.5} {:>6} {:>9} {:>9} {:>8.3} {:>7}",
                    p.name,
                    s.curve.name(),
                    format!("{} segments", f.segments),
                    f.steps,
                    s.timer.timer_hz as f64 / t.pairs.first().map_or(1, |p| p.0) as f64,
                    s.timer.timer_hz as f64 / t.pairs.last().map_or(1, |p| p.0) as f64,
                    f.duration_s,
                    f.flash_bytes,
                    "-",
                    "-",
                    f.max_edge_error_ticks,
                    s.timer.word.max() - top,
                );
            }
        }
    }
    Ok(())
}

/// For each curve, every discretization and rounding against the continuous
/// curve: largest pulse-edge error and drift of the last edge, in ticks.
fn print_accuracy(profiles: &[Profile]) -> Result<(), Error> {
    println!(
        "\nAccuracy against the continuous curve (largest |edge error| / drift of the last edge, ticks):"
    );
    println!(
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
                println!("{row}");
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
fn print_motors(profiles: &[Profile]) {
    let bound: Vec<&Profile> = profiles.iter().filter(|p| p.motor.is_some()).collect();
    if bound.is_empty() {
        return;
    }
    println!(
        "\nMotor torque (profiles that name a motor; the move is the table up and down again, simulated):"
    );
    println!(
        "{:<21} {:>10} {:>6} {:>9} {:>9} {:>9}   {:>5} {:>5} {:>8} {:>9}",
        "profile",
        "margin",
        "step",
        "at Hz",
        "needed",
        "available",
        "lost",
        "slips",
        "max lag",
        "overshoot"
    );
    println!(
        "{:<21} {:>10} {:>6} {:>9} {:>9} {:>9}   {:>5} {:>5} {:>8} {:>9}",
        "", "N·m", "", "", "N·m", "N·m", "steps", "", "°el", "steps"
    );
    for p in bound {
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
        println!(
            "{:<21} {:>10.4} {:>6} {:>9.1} {:>9.4} {:>9.4}   {sim}",
            p.name, t.min_margin_nm, t.step, t.hz, t.needed_nm, t.available_nm
        );
    }
}

/// Needed and available torque at every edge of a motor-bound profile.
fn write_torque_plot(p: &Profile, path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    let Some(motor) = &p.motor else {
        return Ok(());
    };
    let mut edges = Vec::new();
    motor.check_with(
        p.table.spec(),
        &p.table.step_periods(),
        |step, hz, needed, available| edges.push((step, hz, needed, available)),
    )?;
    plots::torque(path, &p.name, &edges, motor.torque_curve.points())
}

fn series(label: &str, color: RGBColor, t: &Table) -> Series {
    let tps = t.spec.timer.timer_hz as f64 / t.spec.timer.ticks_per_step as f64;
    Series::from_periods(label, color, &t.periods, tps)
}

fn write_outputs(profiles: &Profiles, out: &Path) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all(out)?;
    let mut overview = Vec::new();
    for (i, p) in profiles.profiles().iter().enumerate() {
        let (periods, spec) = match &p.table {
            Generated::Steps(t) => (t.periods.clone(), t.spec),
            Generated::Segments(t) => (
                t.pairs
                    .iter()
                    .flat_map(|&(p, c)| std::iter::repeat_n(p, c as usize))
                    .collect(),
                t.spec,
            ),
        };
        let tps = spec.timer.timer_hz as f64 / spec.timer.ticks_per_step as f64;
        let s = Series::from_periods(&p.name, PALETTE[i % PALETTE.len()], &periods, tps);
        plots::profile(&out.join(format!("{}.svg", p.name)), &p.name, &s)?;
        let mut csv = String::from("step,period_ticks,start_s,frequency_hz\n");
        for (k, (&period, &(t, f))) in periods.iter().zip(&s.steps).enumerate() {
            csv.push_str(&format!("{k},{period},{t:.9},{f:.6}\n"));
        }
        std::fs::write(out.join(format!("{}.csv", p.name)), csv)?;
        write_torque_plot(p, &out.join(format!("{}_torque.svg", p.name)))?;
        overview.push(s);
    }
    plots::overlay(
        &out.join("overview.svg"),
        "All profiles: frequency against time",
        &overview,
        false,
    )?;
    profiles.write_c_header(out.join("profiles.h"))?;
    Ok(())
}

/// The README's figures: seed 000's four calls, and three discretizations of one curve.
fn write_docs(profiles: &Profiles, docs: &Path) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all(docs)?;
    let colors = [
        (
            "sigmoid_yellow",
            "yellow: (1000, 56000, 16000, 4)",
            RGBColor(0xe6, 0xb8, 0x00),
        ),
        (
            "sigmoid_orange",
            "orange: (1000, 64000, 500, 8)",
            RGBColor(0xff, 0x8c, 0x00),
        ),
        (
            "sigmoid_blue",
            "blue: (1000, 64000, 500, 15)",
            RGBColor(0x1f, 0x5f, 0xd0),
        ),
        (
            "sigmoid_gray",
            "gray: (1000, 40000, 500, 5)",
            RGBColor(0x80, 0x80, 0x80),
        ),
    ];
    let mut seed = Vec::new();
    for (name, label, color) in colors {
        let Some(Generated::Steps(t)) = profiles
            .profiles()
            .iter()
            .find(|p| p.name == name)
            .map(|p| &p.table)
        else {
            return Err(format!("profile `{name}` is missing from the file").into());
        };
        seed.push(series(label, color, t));
    }
    plots::overlay(
        &docs.join("seed000_curves.svg"),
        "CalculateSModelLine's four example calls: frequency against step",
        &seed,
        true,
    )?;
    // One curve, three discretizations: the orange sigmoid.
    let Some(Generated::Steps(orange)) = profiles
        .profiles()
        .iter()
        .find(|p| p.name == "sigmoid_exact")
        .map(|p| &p.table)
    else {
        return Err("profile `sigmoid_exact` is missing from the file".into());
    };
    let mut sides = Vec::new();
    for (i, d) in [
        Discretization::Index,
        Discretization::LeftEndpoint,
        Discretization::Exact,
    ]
    .into_iter()
    .enumerate()
    {
        let t = orange.spec.with_discretization(d).table()?;
        sides.push(series(d.name(), PALETTE[i], &t));
    }
    plots::side_by_side(
        &docs.join("discretizations.svg"),
        "One sigmoid (500 -> 64000 Hz, 1000 steps, flexible 8), three discretizations",
        &sides,
    )?;
    // The README's worked example: a real motor on the jerk-limited ramp.
    let Some(worked) = profiles
        .profiles()
        .iter()
        .find(|p| p.name == "jerk_limited" && p.motor.is_some())
    else {
        return Err("profile `jerk_limited` with a motor is missing from the file".into());
    };
    write_torque_plot(worked, &docs.join("motor_torque.svg"))?;
    Ok(())
}

fn main() -> ExitCode {
    let mut docs = false;
    let mut path = None;
    for arg in std::env::args().skip(1) {
        match arg.as_str() {
            "--docs" => docs = true,
            "-h" | "--help" => {
                println!("usage: cargo run --example report [-- PATH] [--docs]");
                return ExitCode::SUCCESS;
            }
            _ => path = Some(PathBuf::from(arg)),
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let path = path.unwrap_or_else(|| root.join("profiles.toml"));

    // Say what is happening only if it takes a noticeable time.
    let (done, waiting) = mpsc::channel::<()>();
    let notice = std::thread::spawn(move || {
        if waiting.recv_timeout(Duration::from_secs(1)).is_err() {
            eprintln!("computing tables...");
        }
    });
    let loaded = Profiles::load(&path);
    let _ = done.send(());
    let _ = notice.join();
    let profiles = match loaded {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::FAILURE;
        }
    };

    println!(
        "{}: {} profiles\n",
        path.display(),
        profiles.profiles().len()
    );
    if let Err(e) =
        print_table(profiles.profiles()).and_then(|_| print_accuracy(profiles.profiles()))
    {
        eprintln!("{e}");
        return ExitCode::FAILURE;
    }
    print_motors(profiles.profiles());
    let target =
        std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root.join("target"), PathBuf::from);
    let out = target.join("profiles");
    if let Err(e) = write_outputs(&profiles, &out) {
        eprintln!("cannot write {}: {e}", out.display());
        return ExitCode::FAILURE;
    }
    println!(
        "\nwrote plots, CSV files and profiles.h to {}",
        out.display()
    );
    if docs {
        if let Err(e) = write_docs(&profiles, &root.join("docs")) {
            eprintln!("cannot write the docs figures: {e}");
            return ExitCode::FAILURE;
        }
        println!(
            "wrote docs/seed000_curves.svg, docs/discretizations.svg and docs/motor_torque.svg"
        );
    }
    ExitCode::SUCCESS
}
