//! The `stepper-profiles` binary, run as a user runs it: every command, its
//! exit status, what it prints and the files it writes.

mod common;

use common::{BIN, run, text};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use profile_codegen::profiles::{CStyle, Profiles};

fn shipped() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("..")
        .join("profiles.toml")
}

fn work_dir(name: &str) -> PathBuf {
    common::work_dir("cli", name)
}

/// A profiles file with one mistake on line 7.
const BAD: &str = "[profiles.a]\ncurve = \"linear\"\nfmin = 100\nfmax = 1000\nlen = 10\n\
                   timer_hz = 1_000_000\nfoo = 3\n";

const BAD_MESSAGE: &str = "bad.toml:7:1: unknown key `foo`; expected one of `curve`, `len`, \
     `fmin`, `fmax`, `accel`, `timer_hz`, `word`, `ticks_per_step`, `reload_offset`, `discretization`, \
     `rounding`, `arithmetic`, `segments`, `compress`, or a motor's keys\n  |\n7 | foo = 3\n  | ^^^\n";

#[test]
fn every_command_answers_help() {
    let dir = work_dir("help");
    let top = run(&dir, &["--help"]);
    assert!(top.status.success());
    let top = text(&top.stdout);
    for command in [
        "report", "check", "header", "rust", "plot", "trace", "compare",
    ] {
        assert!(top.contains(&format!("\n  {command} ")), "{command}: {top}");
        let help = run(&dir, &[command, "--help"]);
        assert!(help.status.success(), "{command} --help");
        let help = text(&help.stdout);
        assert!(
            help.contains(&format!("Usage: stepper-profiles {command}")),
            "{help}"
        );
    }
}

#[test]
fn check_passes_a_good_file_and_fails_a_bad_one_with_the_caret() {
    let dir = work_dir("check");
    fs::write(dir.join("bad.toml"), BAD).unwrap();
    let shipped = shipped();
    let shipped = shipped.to_str().unwrap();
    let good = run(&dir, &["check", shipped]);
    assert!(good.status.success(), "{}", text(&good.stderr));
    assert!(text(&good.stdout).ends_with("profiles.toml: 15 profiles, no mistakes\n"));

    let bad = run(&dir, &["check", "bad.toml"]);
    assert_eq!(bad.status.code(), Some(1));
    assert_eq!(text(&bad.stderr), BAD_MESSAGE);
    assert_eq!(text(&bad.stdout), "");

    // Every file is checked; one bad file fails the run.
    let both = run(&dir, &["check", shipped, "bad.toml"]);
    assert_eq!(both.status.code(), Some(1));
    assert!(text(&both.stdout).contains("15 profiles, no mistakes"));
    assert_eq!(text(&both.stderr), BAD_MESSAGE);

    let missing = run(&dir, &["check", "nowhere.toml"]);
    assert_eq!(missing.status.code(), Some(1));
    assert!(
        text(&missing.stderr).starts_with("cannot read `nowhere.toml`: "),
        "{}",
        text(&missing.stderr)
    );
    // A usage mistake is clap's: status 2.
    assert_eq!(run(&dir, &["check"]).status.code(), Some(2));
}

/// Four segments of a ramp whose step 0 needs 70 634 ticks, more than
/// `u16` holds: the segments average it away, the per-step table the plot
/// draws them against cannot.
const SEGMENTS_OVERFLOW: &str = "[profiles.pp]\ncurve = \"jerk_limited\"\nfmin = 100\n\
     fmax = 5000\naccel = 50000\njerk = 5e6\ntimer_hz = \"10 MHz\"\nsegments = 4\n";

/// One verdict: a table that cannot be drawn is refused by `check` as by
/// every command that writes, at its profile, and nothing is left behind.
#[test]
fn check_refuses_what_plot_and_report_cannot_draw() {
    let dir = work_dir("one_verdict");
    fs::write(dir.join("pp.toml"), SEGMENTS_OVERFLOW).unwrap();
    let message = "pp.toml:3:8: entry 0 is 70634 ticks, more than `word = u16` holds (65535); \
                   at `timer_hz = 10000000` the lowest step frequency that fits is 152.59 Hz\n  \
                   |\n3 | fmin = 100\n  |        ^^^\n";
    for args in [
        &["check", "pp.toml"][..],
        &["plot", "pp.toml", "-o", "plots"],
        &["report", "pp.toml", "-o", "report"],
        &["header", "pp.toml", "-o", "pp.h"],
        &["rust", "pp.toml", "-o", "pp.rs"],
    ] {
        let out = run(&dir, args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        assert_eq!(text(&out.stderr), message, "{args:?}");
        assert_eq!(text(&out.stdout), "", "{args:?}");
    }
    assert_eq!(listing(&dir), ["pp.toml"]);
}

/// The names in a folder, sorted.
fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// A command that fails while writing leaves no file behind and keeps the
/// files it would have replaced: each file is written aside and moved into
/// place only once all of them are written.
#[test]
fn a_command_that_fails_leaves_no_file_behind() {
    let dir = work_dir("no_partial_files");
    fs::write(
        dir.join("p.toml"),
        "[profiles.p]\ncurve = \"linear\"\nfmin = 500\nfmax = 5000\nlen = 50\n\
         timer_hz = 1_000_000\n",
    )
    .unwrap();
    // A folder where a file is to go: the command fails after writing others.
    fs::create_dir_all(dir.join("plots/p.csv")).unwrap();
    fs::write(dir.join("plots/overview.svg"), "old").unwrap();
    fs::create_dir_all(dir.join("report/profiles.h")).unwrap();
    fs::create_dir_all(dir.join("c/ramps.c")).unwrap();
    fs::create_dir_all(dir.join("rust/p.rs")).unwrap();
    for (args, message, folder, left) in [
        (
            &["plot", "p.toml", "-o", "plots"][..],
            "cannot write `plots/p.csv`: it is a folder\n",
            "plots",
            &["overview.svg", "p.csv"][..],
        ),
        (
            &["report", "p.toml", "-o", "report"],
            "cannot write `report/profiles.h`: it is a folder\n",
            "report",
            &["profiles.h"],
        ),
        (
            &["header", "p.toml", "-o", "c/ramps.h", "--split"],
            "cannot write `c/ramps.c`: it is a folder\n",
            "c",
            &["ramps.c"],
        ),
        (
            &["header", "p.toml", "-o", "c/ramps.c"],
            "cannot write `c/ramps.c`: it is a folder\n",
            "c",
            &["ramps.c"],
        ),
        (
            &["rust", "p.toml", "-o", "rust/p.rs"],
            "cannot write `rust/p.rs`: it is a folder\n",
            "rust",
            &["p.rs"],
        ),
    ] {
        let out = run(&dir, args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        assert_eq!(text(&out.stderr), message, "{args:?}");
        assert_eq!(listing(&dir.join(folder)), left, "{args:?}");
    }
    assert_eq!(
        fs::read_to_string(dir.join("plots/overview.svg")).unwrap(),
        "old"
    );
    assert_eq!(listing(&dir), ["c", "p.toml", "plots", "report", "rust"]);
}

#[test]
fn header_writes_the_c_of_the_library_one_file_or_split() {
    let dir = work_dir("header");
    let profiles = Profiles::load(shipped()).unwrap_or_else(|e| panic!("{e}"));
    let file = shipped();
    let file = file.to_str().unwrap();

    let out = run(&dir, &["header", file]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(text(&out.stdout), profiles.c_header());

    let out = run(&dir, &["header", file, "-o", "include/ramps.h"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    // Named after the file it is written to.
    assert_eq!(
        fs::read_to_string(dir.join("include/ramps.h")).unwrap(),
        profiles.c_header_named("ramps.h", &CStyle::default())
    );

    let out = run(
        &dir,
        &[
            "header",
            file,
            "-o",
            "split/ramps.h",
            "--split",
            "--storage",
            "__code",
            "--attribute",
            "PROGMEM",
        ],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert_eq!(text(&out.stderr), "wrote split/ramps.h and split/ramps.c\n");
    let style = CStyle {
        storage: Some("__code".into()),
        attribute: Some("PROGMEM".into()),
        ..CStyle::default()
    };
    let want = profiles.c_split("ramps.h", &style);
    assert_eq!(
        fs::read_to_string(dir.join("split/ramps.h")).unwrap(),
        want.header
    );
    assert_eq!(
        fs::read_to_string(dir.join("split/ramps.c")).unwrap(),
        want.source
    );
    assert!(
        want.source
            .contains("const __code uint16_t SIGMOID_ORANGE_PERIODS[1000] PROGMEM = {")
    );

    let out = run(&dir, &["header", file, "-o", "ramps", "--split"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        text(&out.stderr),
        "`--split` writes a header and a `.c` beside it: give the header a name ending in \
         `.h` (got `ramps`)\n"
    );
    let out = run(&dir, &["header", file, "--attribute", "PROGMEM;"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        text(&out.stderr),
        "`--attribute` cannot hold `;`: give words such as `PROGMEM`, or \
         `__attribute__((...))` with balanced parentheses (got `PROGMEM;`)\n"
    );
    assert_eq!(
        run(&dir, &["header", file, "--split"]).status.code(),
        Some(2)
    );
}

#[test]
fn rust_writes_the_modules_include_profiles_expands_to() {
    let dir = work_dir("rust");
    let profiles = Profiles::load(shipped()).unwrap_or_else(|e| panic!("{e}"));
    let file = shipped();
    let out = run(
        &dir,
        &["rust", file.to_str().unwrap(), "-o", "gen/profiles.rs"],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let written = fs::read_to_string(dir.join("gen/profiles.rs")).unwrap();
    assert_eq!(written, profiles.rust_source());
    assert!(written.contains("pub mod sigmoid_orange {"));
}

#[test]
fn plot_writes_an_svg_and_a_csv_per_profile() {
    let dir = work_dir("plot");
    let profiles = Profiles::load(shipped()).unwrap_or_else(|e| panic!("{e}"));
    let file = shipped();
    let out = run(&dir, &["plot", file.to_str().unwrap(), "-o", "figures"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    // 15 profiles: SVG and CSV each, three torque plots, two compact
    // layouts over their curves, the overview.
    assert_eq!(text(&out.stdout), "wrote 36 files to figures\n");
    for p in profiles.profiles() {
        let svg = fs::read_to_string(dir.join(format!("figures/{}.svg", p.name))).unwrap();
        assert!(svg.starts_with("<svg"), "{}", p.name);
        let csv = fs::read_to_string(dir.join(format!("figures/{}.csv", p.name))).unwrap();
        let mut lines = csv.lines();
        assert_eq!(lines.next(), Some("step,period_ticks,start_s,frequency_hz"));
        // The CSV holds the table, step by step.
        let periods: Vec<u32> = lines
            .map(|l| l.split(',').nth(1).unwrap().parse().unwrap())
            .collect();
        assert_eq!(periods, p.table.step_periods(), "{}", p.name);
        assert_eq!(
            dir.join(format!("figures/{}_torque.svg", p.name)).exists(),
            p.motor.is_some(),
            "{}",
            p.name
        );
        let edges = dir.join(format!("figures/{}_edges.svg", p.name));
        assert_eq!(
            edges.exists(),
            !matches!(p.table, profile_codegen::Generated::Steps(_)),
            "{}",
            p.name
        );
    }
    // The compressed ramp over the curve, its edges against the bound and
    // against the table of one entry per step.
    let svg = fs::read_to_string(dir.join("figures/microstep_runs_edges.svg")).unwrap();
    for label in [
        "microstep_runs: frequency against time",
        "microstep_runs: pulse edge against the curve&apos;s",
        "97 runs",
        "bound: 1.000 ticks",
        "one entry per step",
    ] {
        assert!(svg.contains(label), "{label}");
    }
    assert!(dir.join("figures/overview.svg").exists());
    // Nothing but the files: the folder they were written in aside is gone.
    assert_eq!(listing(&dir.join("figures")).len(), 36);
}

#[test]
fn report_prints_parameters_with_units_and_says_when_a_table_starts_far_above_fmin() {
    let dir = work_dir("report");
    fs::write(
        dir.join("profiles.toml"),
        "[profiles.slow_start]\ncurve = \"sigmoid\"\nlen = 1000\nfmin = \"20 Hz\"\n\
         fmax = \"64 kHz\"\nflexible = 8\ntimer_hz = \"10 MHz\"\ndiscretization = \"exact\"\n",
    )
    .unwrap();
    // FILE defaults to `profiles.toml` in the current folder.
    let out = run(&dir, &["report"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let report = text(&out.stdout);
    assert!(
        report.starts_with("profiles.toml: 1 profiles\n"),
        "{report}"
    );
    assert!(
        report.contains(
            "slow_start            curve = sigmoid, len = 1000, fmin = 20 Hz, fmax = 64 kHz, \
             flexible = 8, timer_hz = 10 MHz,"
        ),
        "{report}"
    );
    assert!(
        report.contains(
            "note: slow_start: the first entry runs at 165.5 Hz, 8.3 times `fmin` = 20 Hz: the \
             curve starts at `fmin` but covers the first step at 165.5 Hz on average \
             (`discretization = exact`); `discretization = left_endpoint` starts at `fmin` \
             itself.\n"
        ),
        "{report}"
    );

    // With -o, the files behind it too: SVG, CSV, overview, header.
    let out = run(&dir, &["report", "-o", "out"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(text(&out.stdout).ends_with("\nwrote 4 files to out\n"));
    assert!(dir.join("out/profiles.h").exists());
    assert!(dir.join("out/slow_start.svg").exists());
}

#[test]
fn report_gives_a_compact_layout_flash_against_one_entry_per_step() {
    let dir = work_dir("report_compact");
    let out = run(&dir, &["report", shipped().to_str().unwrap()]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    let report = text(&out.stdout);
    for note in [
        "note: microstep_runs: 97 runs take 970 bytes of flash against 14384 for one entry per \
         step (14.8 times less); every step edge is within 1.000 ticks of the curve \
         (`compress = 1`).\n",
        "note: exponential_segments: 8 segments take 32 bytes of flash against 240 for one \
         entry per step (7.5 times less); every step edge is within 421.621 ticks of the \
         curve.\n",
    ] {
        assert!(report.contains(note), "{report}");
    }
    // The motor's fastest start from rest with its load, from the model.
    let motors = report
        .split("\nMotor torque")
        .nth(1)
        .unwrap_or_else(|| panic!("{report}"));
    let row = motors
        .lines()
        .find(|l| l.starts_with("linear_exact "))
        .unwrap_or_else(|| panic!("{report}"));
    assert_eq!(row.split_whitespace().nth(6), Some("7470.7"), "{row}");
    // The shipped motor gives its windings too: the curve they give, beside
    // the typed one (the manual's chart, in half steps), up to the typed
    // curve's last point (1500 rpm): as a sine, at the model's default
    // losses.
    let pull_out = motors
        .split("`linear_exact`: the motor's pull-out torque, N·m\n")
        .nth(1)
        .unwrap_or_else(|| panic!("{report}"));
    let rows: Vec<Vec<&str>> = pull_out
        .lines()
        .take(3)
        .map(|l| l.split_whitespace().rev().take(5).collect())
        .collect();
    assert_eq!(
        rows,
        [
            ["40000.0", "30000.0", "20000.0", "10000.0", "0.0"],
            ["0.2350", "0.2680", "0.3440", "0.3965", "0.4000"],
            ["0.3065", "0.3539", "0.3635", "0.3724", "0.4000"],
        ],
        "{pull_out}"
    );
}

/// A motor known by its windings alone (the QSH4218-47-28-040's, on a
/// 12 V supply): its derived curve is the one the check uses.
const WINDINGS_ONLY: &str = "[motors.m]\nstep_angle = 1.8\nrotor_inertia = 6.8e-6\n\
     load_inertia = 1.36e-5\nfriction = 0.02\nresistance = 0.5\ninductance = 0.6e-3\n\
     rated_current = 2.8\nholding_torque = 0.40\nsupply_voltage = 12\n\n\
     [profiles.p]\ncurve = \"linear\"\nfmin = 300\nfmax = 3000\naccel = 10_000\n\
     timer_hz = 1_000_000\nmotor = \"m\"\n";

/// A layout larger than one entry per step says so, not "0.2 times less".
#[test]
fn report_says_when_a_compact_layout_is_larger_than_the_table() {
    let report = report_of(
        "report_compact_larger",
        "[profiles.one]\ncurve = \"linear\"\nfmin = 1000\nfmax = 2000\nlen = 1\n\
         timer_hz = 1000000\ncompress = 1\n",
    );
    assert!(
        report.contains(
            "note: one: 1 runs take 10 bytes of flash against 2 for one entry per step (5.0 \
             times more: one entry per step is smaller here); every step edge is within"
        ),
        "{report}"
    );
}

/// The report of the profiles file `file`, written in a folder of its own.
fn report_of(name: &str, file: &str) -> String {
    let dir = work_dir(name);
    fs::write(dir.join("profiles.toml"), file).unwrap();
    let out = run(&dir, &["report", "profiles.toml"]);
    assert!(out.status.success(), "{}", text(&out.stderr));
    text(&out.stdout)
}

/// What follows `heading` in `report`.
fn after<'a>(report: &'a str, heading: &str) -> &'a str {
    report
        .split(heading)
        .nth(1)
        .unwrap_or_else(|| panic!("no {heading:?} in {report}"))
}

/// A start far above a tiny `fmin`: the note gives the ratio in exponent
/// form, not in 300 digits.
#[test]
fn report_writes_a_huge_ratio_in_exponent_form() {
    let report = report_of(
        "tiny_fmin",
        "[profiles.tiny]\ncurve = \"linear\"\nfmin = 1e-300\nfmax = 1000\n\
         accel = 1_000_000\ntimer_hz = 1_000_000\n",
    );
    let note = report
        .lines()
        .find(|l| l.starts_with("note: tiny:"))
        .unwrap_or_else(|| panic!("{report}"));
    assert!(
        note.starts_with(
            "note: tiny: the first entry runs at 666.7 Hz, 6.66667e302 times `fmin` = 1e-300 Hz:"
        ),
        "{note}"
    );
}

#[test]
fn report_labels_the_windings_curve_as_the_checked_one_when_it_is_the_only_one() {
    let report = report_of("report_windings_only", WINDINGS_ONLY);
    let pull_out = after(&report, "`p`: the motor's pull-out torque, N·m\n");
    let lines: Vec<&str> = pull_out.lines().take(3).collect();
    assert!(
        lines[0].starts_with("  at step frequency (Hz)"),
        "{pull_out}"
    );
    assert!(
        lines[1].starts_with("  derived from the windings (used by the check)"),
        "{pull_out}"
    );
    assert!(lines[2].trim().is_empty(), "{pull_out}");
    assert!(
        !report.contains("`torque_curve` (used by the check)"),
        "{report}"
    );
    // The start limit is searched up to where the derived torque falls to a
    // hundredth: a figure, not 0.
    let row = report
        .split("\nMotor torque")
        .nth(1)
        .and_then(|m| m.lines().find(|l| l.starts_with("p ")))
        .unwrap_or_else(|| panic!("{report}"));
    let start: f64 = row.split_whitespace().nth(6).unwrap().parse().unwrap();
    assert!(start > 300.0, "{row}");
}

#[test]
fn report_names_a_stepped_drive_and_keeps_the_figures_in_their_columns() {
    // A half-step driver's table steps are half steps.
    let half_steps = WINDINGS_ONLY
        .replace(
            "supply_voltage = 12\n",
            "supply_voltage = 12\ndrive = \"half_step\"\nmicrosteps = 2\n",
        )
        .replace(
            "fmin = 300\nfmax = 3000\naccel = 10_000\n",
            "fmin = 600\nfmax = 6000\naccel = 20_000\n",
        );
    let report = report_of("report_windings_half_step", &half_steps);
    let pull_out = after(&report, "`p`: the motor's pull-out torque, N·m\n");
    let lines: Vec<&str> = pull_out.lines().take(2).collect();
    assert!(
        lines[1].starts_with("  derived from the windings, half_step (used by the check)  "),
        "{pull_out}"
    );
    // The label is longer than the column the labels had: the frequencies
    // above move with the figures (each a column 9 wide), so the two lines
    // end together.
    assert_eq!(
        lines[0].chars().count(),
        lines[1].chars().count(),
        "{pull_out}"
    );
}

#[test]
fn report_shows_each_motor_as_the_check_reads_it_in_datasheet_units() {
    let expected = "p                     step_angle = 1.8°, microsteps = 1, \
                    rotor_inertia = 68 g·cm², load_inertia = 136 g·cm², resistance = 0.5 Ω, \
                    inductance = 0.6 mH, rated_current = 2.8 A, holding_torque = 0.4 N·m, \
                    supply_voltage = 12 V, detent_torque = 0 N·m, drive = sine, \
                    driver_current = 2.8 A, driver_current_is = rms, supply_utilization = 0.76, \
                    iron_loss = 0.044 N·m, friction = 0.02 N·m, damping = 0 N·m·s/rad, \
                    damping_ratio = 0, safety = 1";
    // In SI, and in the datasheet's units: the same figures.
    let in_units = WINDINGS_ONLY
        .replace("rotor_inertia = 6.8e-6", "rotor_inertia = \"68 g·cm²\"")
        .replace("load_inertia = 1.36e-5", "load_inertia = \"136gcm2\"")
        .replace("friction = 0.02", "friction = \"2 N·cm\"")
        .replace("inductance = 0.6e-3", "inductance = \"600 µH\"")
        .replace("holding_torque = 0.40", "holding_torque = \"400 mN·m\"");
    assert_ne!(in_units, WINDINGS_ONLY);
    for (name, file) in [
        ("report_motor_si", WINDINGS_ONLY),
        ("report_motor_units", &in_units),
    ] {
        let dir = work_dir(name);
        fs::write(dir.join("profiles.toml"), file).unwrap();
        let out = run(&dir, &["report", "profiles.toml"]);
        assert!(out.status.success(), "{}", text(&out.stderr));
        let report = text(&out.stdout);
        let motors = report
            .split("Motors (as the check reads them, in a datasheet's units; defaults included):\n")
            .nth(1)
            .unwrap_or_else(|| panic!("{report}"));
        assert_eq!(motors.lines().next(), Some(expected), "{file}");
    }
}

#[test]
fn a_reader_that_stops_early_is_not_an_error() {
    let dir = work_dir("pipe");
    let mut child = Command::new(BIN)
        .args(["report", shipped().to_str().unwrap()])
        .current_dir(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Close the pipe before reading anything, as `| head -0` would.
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{}", text(&out.stderr));
    assert!(!text(&out.stderr).contains("panicked"));
}

/// A generated file cut short is an error, unlike a report read by `head`:
/// `header` and `rust` into a pipe its reader closed fail with a message.
/// Four tables of 60 000 entries: more than 1 MiB of either, more than a
/// pipe holds, so that the command is still writing when the pipe closes,
/// however the two processes are scheduled.
#[test]
fn a_generated_file_that_cannot_be_written_whole_is_an_error() {
    let dir = work_dir("closed_stdout");
    let large: String = ["a", "b", "c", "d"]
        .map(|name| {
            format!(
                "[profiles.{name}]\ncurve = \"linear\"\nfmin = 100\nfmax = 1000\n\
                 len = 60000\ntimer_hz = 1_000_000\n"
            )
        })
        .concat();
    fs::write(dir.join("large.toml"), large).unwrap();
    for (command, what) in [("header", "the C header"), ("rust", "the Rust modules")] {
        let written = Command::new(BIN)
            .args([command, "large.toml"])
            .current_dir(&dir)
            .output()
            .unwrap();
        assert!(written.status.success(), "{}", text(&written.stderr));
        assert!(written.stdout.len() > 1 << 20, "{command}");
        let mut child = Command::new(BIN)
            .args([command, "large.toml"])
            .current_dir(&dir)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Close the pipe before reading anything, as `| head -c 0` would.
        drop(child.stdout.take());
        let out = child.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{command}");
        // Past a second of computing (a loaded machine), the tool says so
        // first.
        let stderr = text(&out.stderr);
        assert_eq!(
            stderr
                .strip_prefix("computing tables...\n")
                .unwrap_or(&stderr),
            format!(
                "cannot write {what} to standard output: its reader closed it before the end\n"
            )
        );
    }
}

#[test]
fn a_closed_standard_error_loses_the_message_but_not_the_exit_status() {
    let dir = work_dir("closed_stderr");
    fs::write(dir.join("bad.toml"), BAD).unwrap();
    let mut child = Command::new(BIN)
        .args(["check", "bad.toml"])
        .current_dir(&dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stderr.take());
    let out = child.wait_with_output().unwrap();
    // The file's error, not a panic (101).
    assert_eq!(out.status.code(), Some(1));
    let dir = work_dir("closed_stderr_plot");
    let mut child = Command::new(BIN)
        .args(["plot", shipped().to_str().unwrap(), "--out", "plots"])
        .current_dir(&dir)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stderr.take());
    assert!(child.wait().unwrap().success());
    assert!(dir.join("plots").is_dir());
}

/// The shipped `torque_limited` profile: the report gives its time to the
/// top against the steepest constant acceleration that passes the same
/// check, and that acceleration's time agrees with (fmax - fmin) / accel
/// to within a step at the top.
#[test]
fn report_gives_the_time_the_fastest_ramp_saves() {
    let out = run(
        &work_dir("report_fastest"),
        &["report", shipped().to_str().unwrap()],
    );
    assert!(out.status.success(), "{}", text(&out.stderr));
    let report = text(&out.stdout);
    let section = after(
        &report,
        "`torque_limited`: the fastest ramp the motor allows, planned on 0.65 of its torque",
    );
    let lines: Vec<&str> = section.lines().take(3).collect();
    let numbers = |line: &str| -> Vec<f64> {
        line.split(|c: char| !(c.is_ascii_digit() || c == '.' || c == 'e'))
            .filter_map(|w| w.trim_matches('.').parse().ok())
            .collect()
    };
    // "  at its top, 40000.0 Hz: available A N·m, planned P N·m ..."
    let top = numbers(lines[1]);
    assert_eq!(top[0], 40_000.0, "{}", lines[1]);
    assert!((top[1] * 0.65 - top[2]).abs() < 1e-4, "{}", lines[1]);
    // "  to 40000.0 Hz in T ms; ... from F Hz ..., A Hz/s, takes L ms: S % saved"
    let times = numbers(lines[2]);
    let (time, fmin, accel, linear, saved) = (times[1], times[2], times[3], times[4], times[5]);
    let expected = (40_000.0 - fmin) / accel * 1e3;
    assert!(
        (linear - expected).abs() < 1e3 / 40_000.0 + 0.01,
        "{linear} ms against {expected} ms: {}",
        lines[2]
    );
    assert!(time < linear, "{}", lines[2]);
    assert!(
        (saved - (1.0 - time / linear) * 100.0).abs() < 0.1,
        "{}",
        lines[2]
    );
}
