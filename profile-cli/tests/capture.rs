//! `trace` and `compare`, run as a user runs them: the VCD of a move read
//! back by a parser of this file's own and held to the move built from the
//! table alone; the trace compared with itself, with a capture one tick off
//! at one step, and with sigrok's CSV of it.

mod common;

use common::{run, text};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// A 1 MHz timer, so that a tick is a microsecond and a sample of a 1 MHz
/// capture; the driver's pulse 2 µs (a DRV8825's 1.9, rounded up).
const FILE: &str = "[profiles.ramp]\ncurve = \"linear\"\nfmin = 500\nfmax = 4000\nlen = 40\n\
                    timer_hz = \"1 MHz\"\ndriver = \"drv8825\"\n";
const CRUISE: u32 = 30;

fn work_dir(name: &str) -> PathBuf {
    let dir = common::work_dir("capture", name);
    fs::write(dir.join("ramps.toml"), FILE).unwrap();
    dir
}

/// `trace PROFILE` of a move of `steps` in `ramps.toml`, with `more`.
fn trace(dir: &Path, profile: &str, steps: &str, more: &[&str]) -> Output {
    let args = ["trace", profile, "-f", "ramps.toml", "--move", steps];
    run(dir, &[&args[..], more].concat())
}

/// `compare PROFILE CAPTURE` against a move of `steps` in `ramps.toml`,
/// with `more`.
fn compare(dir: &Path, profile: &str, capture: &str, steps: &str, more: &[&str]) -> Output {
    let args = [
        "compare",
        profile,
        capture,
        "-f",
        "ramps.toml",
        "--move",
        steps,
    ];
    run(dir, &[&args[..], more].concat())
}

/// The table's periods, from the library.
fn table() -> Vec<u32> {
    let profiles = profile_codegen::profiles::Profiles::parse("ramps.toml", FILE).unwrap();
    profiles.profiles()[0].table.step_periods()
}

/// A move up the whole table, `CRUISE` steps at its top and down, from the
/// table alone: each entry up, the top entry `CRUISE` times, each entry
/// down no faster than the top.
fn full_move(table: &[u32]) -> Vec<u32> {
    let top = *table.last().unwrap();
    let mut out = table.to_vec();
    out.extend(std::iter::repeat_n(top, CRUISE as usize));
    out.extend(table.iter().rev().map(|&p| p.max(top)));
    out
}

/// Step edges `from` the first at `origin`, each starting its period (so
/// the last period follows the last edge), or with `ends` each ending it
/// (the first period before the first edge).
fn edges(periods: &[u32], origin: u64, ends: bool) -> Vec<u64> {
    let between = match ends {
        false => &periods[..periods.len() - 1],
        true => &periods[1..],
    };
    let mut at = origin;
    std::iter::once(origin)
        .chain(between.iter().map(|&p| {
            at += u64::from(p);
            at
        }))
        .collect()
}

/// The times (`#` stamps) at which the VCD's `STEP` (id `!`) rises and
/// falls, read line by line.
fn stamps(vcd: &str) -> (Vec<u64>, Vec<u64>) {
    let (mut rises, mut falls, mut now) = (Vec::new(), Vec::new(), 0);
    for line in vcd.lines() {
        if let Some(t) = line.strip_prefix('#') {
            now = t.parse().unwrap();
        } else if line == "1!" {
            rises.push(now);
        } else if line == "0!" && now > 0 {
            falls.push(now);
        }
    }
    (rises, falls)
}

#[test]
fn trace_writes_every_step_edge_at_its_tick() {
    let dir = work_dir("trace");
    let table = table();
    let steps = 2 * table.len() as u32 + CRUISE;
    let out = trace(&dir, "ramp", &steps.to_string(), &["-o", "move.vcd"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let vcd = fs::read_to_string(dir.join("move.vcd")).unwrap();
    assert!(vcd.contains("$timescale 1 us $end"), "{vcd}");
    assert!(
        vcd.contains("timer 1000000 Hz, a tick is 1 of 1 us"),
        "{vcd}"
    );
    // Time 0 a pulse (the driver's 2 ticks) before the first step; each
    // step's period from its edge to the next.
    let (rises, falls) = stamps(&vcd);
    assert_eq!(rises, edges(&full_move(&table), 2, false));
    assert!(rises.iter().zip(&falls).all(|(r, f)| f - r == 2));
    // Each edge ending its period instead: the first period before it.
    let out = trace(&dir, "ramp", &steps.to_string(), &["--edge-ends-period"]);
    let (rises, _) = stamps(&text(&out.stdout));
    assert_eq!(rises, edges(&full_move(&table), 2, true));
    // Stopped after 10 steps up: down the table from the entry just
    // played, each entry again.
    let out = trace(&dir, "ramp", &steps.to_string(), &["--stop-at", "10"]);
    let (rises, _) = stamps(&text(&out.stdout));
    let stopped: Vec<u32> = table[..10]
        .iter()
        .chain(table[..10].iter().rev())
        .copied()
        .collect();
    assert_eq!(rises, edges(&stopped, 2, false));
}

#[test]
fn compare_finds_the_step_one_tick_off() {
    let dir = work_dir("compare");
    let table = table();
    let steps = (2 * table.len() as u32 + CRUISE).to_string();
    let trace = trace(&dir, "ramp", &steps, &[]);
    assert!(trace.status.success());
    let vcd = text(&trace.stdout);
    fs::write(dir.join("same.vcd"), &vcd).unwrap();
    let same = compare(&dir, "ramp", "same.vcd", &steps, &["--summary"]);
    assert!(same.status.success(), "{}", text(&same.stderr));
    assert_eq!(
        text(&same.stdout),
        format!(
            "{steps} steps compared on `STEP`: the largest error 0.000 ticks, at step 0; every \
             step within the tolerance of 0.5 ticks\n"
        )
    );
    // The period before step 25 one tick longer: every edge from it on
    // comes a tick late.
    let (rises, _) = stamps(&vcd);
    let late = rises[25];
    let edited: String = vcd
        .lines()
        .map(|line| match line.strip_prefix('#') {
            Some(t) if t.parse::<u64>().unwrap() >= late => {
                format!("#{}\n", t.parse::<u64>().unwrap() + 1)
            }
            _ => format!("{line}\n"),
        })
        .collect();
    fs::write(dir.join("late.vcd"), edited).unwrap();
    let late = compare(&dir, "ramp", "late.vcd", &steps, &[]);
    assert_eq!(late.status.code(), Some(1));
    let printed = text(&late.stdout);
    assert!(
        printed.starts_with("step  reference  captured  error (ticks)\n   0 "),
        "{printed}"
    );
    assert!(
        printed.contains("\n  24 ") && printed.contains("  +0.000\n  25 "),
        "{printed}"
    );
    assert!(printed.contains("  +1.000  out\n"), "{printed}");
    assert!(
        printed.ends_with(
            "the largest error 1.000 ticks, at step 25; step 25 is the first out of the tolerance \
             of 0.5 ticks (+1.000)\n"
        ),
        "{printed}"
    );
    assert_eq!(
        text(&late.stderr),
        "`late.vcd` is not the move of `ramp` within 0.5 ticks\n"
    );
    // With a tolerance of a tick, it passes.
    let loose = compare(&dir, "ramp", "late.vcd", &steps, &["--tolerance", "1"]);
    assert!(loose.status.success());
}

/// The trace as a 1 MHz logic analyzer samples it, in the CSV sigrok-cli
/// writes (`; Channels`, `META samplerate`, a row a sample), with a
/// second channel that never steps; a capture that ends early.
#[test]
fn compare_reads_sigrok_s_csv() {
    let dir = work_dir("csv");
    let table = table();
    let steps = 2 * table.len() as u32 + CRUISE;
    let mut csv = String::from(
        "; CSV generated by libsigrok 0.5.2\n; Channels (2/2): D0, D1\n\
         META samplerate: 1000000\nlogic,logic\n",
    );
    let rises: std::collections::HashSet<u64> =
        edges(&full_move(&table), 5, false).into_iter().collect();
    let end = rises.iter().max().unwrap() + 10;
    for sample in 0..end {
        let high = (0..2).any(|k| sample >= k && rises.contains(&(sample - k)));
        csv.push_str(if high { "0,1\n" } else { "0,0\n" });
    }
    fs::write(dir.join("capture.csv"), &csv).unwrap();
    let out = compare(
        &dir,
        "ramp",
        "capture.csv",
        &steps.to_string(),
        &["--summary"],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(text(&out.stdout).starts_with(&format!(
        "{steps} steps compared on `D1`: the largest error 0.000 ticks"
    )));
    // A longer move than the capture holds: its missing steps fail.
    let long = compare(
        &dir,
        "ramp",
        "capture.csv",
        &(steps + 5).to_string(),
        &["--summary"],
    );
    assert_eq!(long.status.code(), Some(1));
    assert!(
        text(&long.stdout).contains("; the capture ends 5 steps short of the move"),
        "{}",
        text(&long.stdout)
    );
    // Read as a pin whose edges end their periods, it is a period off from
    // the second step.
    let ends = compare(
        &dir,
        "ramp",
        "capture.csv",
        &steps.to_string(),
        &["--summary", "--edge-ends-period"],
    );
    assert_eq!(ends.status.code(), Some(1));
    assert!(
        text(&ends.stdout).contains("step 1 is the first out of the tolerance"),
        "{}",
        text(&ends.stdout)
    );
}

#[test]
fn trace_and_compare_say_what_is_wrong() {
    let dir = work_dir("wrong");
    let out = trace(&dir, "ramps", "10", &[]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        text(&out.stderr),
        "`ramps.toml` has no profile `ramps`; its profiles: ramp\n"
    );
    let out = trace(&dir, "ramp", "0", &[]);
    assert_eq!(
        text(&out.stderr),
        "a move of 0 steps has no edges: give `--move` 1 or more\n"
    );
    fs::write(
        dir.join("flat.vcd"),
        "$timescale 1ns $end\n$var wire 1 ! STEP $end\n#0\n0!\n",
    )
    .unwrap();
    let out = compare(&dir, "ramp", "flat.vcd", "10", &[]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        text(&out.stderr),
        "`flat.vcd`: the channel `STEP` has no step edges (no rising edge: try `--edges both` \
         for a pin that toggles)\n"
    );
    let out = compare(&dir, "ramp", "flat.vcd", "10", &["--channel", "DIR"]);
    assert_eq!(
        text(&out.stderr),
        "`flat.vcd`: the capture has no channel `DIR`; its channels: `STEP`\n"
    );
}

/// sigrok-cli's own CSV of the trace (`sigrok-cli -I vcd -O csv`), as a
/// user converts a capture: compared, every step at its tick.
#[test]
#[ignore = "slow: runs sigrok-cli (apt-get install sigrok-cli); CI runs it with --ignored"]
fn compare_reads_what_sigrok_cli_writes() {
    let dir = work_dir("sigrok");
    let table = table();
    let steps = (2 * table.len() as u32 + CRUISE).to_string();
    let trace = trace(&dir, "ramp", &steps, &["-o", "move.vcd"]);
    assert!(trace.status.success());
    let csv = Command::new("sigrok-cli")
        .args(["-I", "vcd", "-i", "move.vcd", "-O", "csv"])
        .current_dir(&dir)
        .output()
        .unwrap_or_else(|e| panic!("sigrok-cli (apt-get install sigrok-cli): {e}"));
    assert!(csv.status.success(), "{}", text(&csv.stderr));
    fs::write(dir.join("move.csv"), &csv.stdout).unwrap();
    let out = compare(&dir, "ramp", "move.csv", &steps, &["--summary"]);
    assert!(
        out.status.success(),
        "{}{}",
        text(&out.stdout),
        text(&out.stderr)
    );
    assert!(
        text(&out.stdout).starts_with(&format!(
            "{steps} steps compared on `STEP`: the largest error 0.000 ticks"
        )),
        "{}",
        text(&out.stdout)
    );
}
