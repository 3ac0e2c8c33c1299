//! The shipped `profiles.toml`, three ways: `include_profiles!` at compile
//! time, `Profiles::load` in a build script, and `Spec::generate` at run time
//! must give the same bits and the same figures for every profile.
//!
//! Adding a profile to `profiles.toml` without listing it in
//! [`every_profile_three_ways`] fails the test.

use std::path::{Path, PathBuf};
use std::process::Command;

use profile_codegen::Generated;
use profile_codegen::SpecTables;
use profile_codegen::profiles::Profiles;
use profile_core::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, Linear, LinearExtent,
    Rounding, Sigmoid, Spec, Timer,
};

stepper_profiles::include_profiles!("profiles.toml");

/// The same file with a trailing comma, as `include_str!` takes one.
mod with_comma {
    stepper_profiles::include_profiles!("profiles.toml",);
}

fn manifest_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("profiles.toml")
}

fn loaded() -> Profiles {
    Profiles::load(manifest_path()).unwrap_or_else(|e| panic!("profiles.toml does not load:\n{e}"))
}

fn find<'a>(profiles: &'a Profiles, name: &str) -> &'a Generated {
    &profiles
        .profiles()
        .iter()
        .find(|p| p.name == name)
        .unwrap_or_else(|| panic!("profile `{name}` is not in profiles.toml"))
        .table
}

/// The constants every layout's module has, of the documented types,
/// against the loaded table's spec and figures `f` (`total_ticks`,
/// `duration_s`).
macro_rules! timer_constants {
    ($name:ident, $spec:expr, $f:expr) => {{
        let name = stringify!($name);
        let timer_hz: u32 = $name::TIMER_HZ;
        let ticks_per_step: u8 = $name::TICKS_PER_STEP;
        let reload_offset: i32 = $name::RELOAD_OFFSET;
        assert_eq!(
            reload_offset, $spec.reload_offset,
            "`{name}`: RELOAD_OFFSET"
        );
        let total_ticks: u64 = $name::TOTAL_TICKS;
        let duration_s: f64 = $name::DURATION_S;
        assert_eq!(timer_hz, $spec.timer.timer_hz, "`{name}`: TIMER_HZ");
        assert_eq!(
            ticks_per_step, $spec.timer.ticks_per_step,
            "`{name}`: TICKS_PER_STEP"
        );
        assert_eq!(total_ticks, $f.total_ticks, "`{name}`: TOTAL_TICKS");
        assert_eq!(
            duration_s.to_bits(),
            $f.duration_s.to_bits(),
            "`{name}`: DURATION_S"
        );
    }};
}

/// A per-step profile: the macro's module, the loaded table and a run-time
/// `Spec::generate` into a fixed-size buffer agree; returns the name checked.
macro_rules! steps {
    ($profiles:expr, $name:ident) => {{
        let name = stringify!($name);
        let Generated::Steps(table) = find($profiles, name) else {
            panic!("`{name}`: the macro emitted `PERIODS` but the file holds segments");
        };
        let f = &table.figures;

        // Types of the constants, as documented.
        let len: usize = $name::LEN;
        let total_ticks: u64 = $name::TOTAL_TICKS;
        let first_ticks: u32 = $name::FIRST_TICKS;
        let last_ticks: u32 = $name::LAST_TICKS;

        // Macro == loaded file.
        let macro_periods: Vec<u32> = $name::PERIODS.iter().map(|&p| u32::from(p)).collect();
        assert_eq!(
            macro_periods, table.periods,
            "`{name}`: macro PERIODS vs loaded table"
        );
        assert_eq!(len, table.periods.len(), "`{name}`: LEN");
        assert_eq!(len, f.len as usize, "`{name}`: LEN vs figures");
        timer_constants!($name, table.spec, f);
        assert_eq!(first_ticks, f.first_ticks, "`{name}`: FIRST_TICKS");
        assert_eq!(last_ticks, f.last_ticks, "`{name}`: LAST_TICKS");
        assert_eq!(
            $name::START_HZ.to_bits(),
            f.start_hz.to_bits(),
            "`{name}`: START_HZ"
        );
        assert_eq!(
            $name::FINAL_HZ.to_bits(),
            f.final_hz.to_bits(),
            "`{name}`: FINAL_HZ"
        );

        // The figures describe the table itself.
        assert_eq!(
            total_ticks,
            macro_periods.iter().map(|&p| u64::from(p)).sum::<u64>(),
            "`{name}`: TOTAL_TICKS is the sum"
        );
        assert_eq!(
            first_ticks, macro_periods[0],
            "`{name}`: FIRST_TICKS is PERIODS[0]"
        );
        assert_eq!(
            last_ticks,
            macro_periods[len - 1],
            "`{name}`: LAST_TICKS is the last entry"
        );
        assert!(
            macro_periods
                .iter()
                .all(|&p| p >= 1 && p <= table.spec.timer.word.max()),
            "`{name}`: every period fits the word"
        );

        // Run time: the core into a buffer of the macro's own type and length.
        let mut buffer = $name::PERIODS;
        buffer.fill(0);
        let figures = table
            .spec
            .generate(&mut buffer)
            .unwrap_or_else(|e| panic!("`{name}`: Spec::generate: {e}"));
        assert_eq!(
            buffer,
            $name::PERIODS,
            "`{name}`: Spec::generate vs macro PERIODS"
        );
        assert_eq!(
            &figures, f,
            "`{name}`: Spec::generate figures vs loaded figures"
        );
        name
    }};
}

/// A segment profile: `SEGMENTS` and its constants, three ways.
macro_rules! segments {
    ($profiles:expr, $name:ident) => {{
        let name = stringify!($name);
        let Generated::Segments(table) = find($profiles, name) else {
            panic!("`{name}`: the macro emitted `SEGMENTS` but the file holds periods");
        };
        let f = &table.figures;

        let count: usize = $name::SEGMENT_COUNT;
        let len: usize = $name::LEN;
        let total_ticks: u64 = $name::TOTAL_TICKS;

        let macro_pairs: Vec<(u32, u32)> = $name::SEGMENTS
            .iter()
            .map(|&(p, c)| (u32::from(p), u32::from(c)))
            .collect();
        assert_eq!(
            macro_pairs, table.pairs,
            "`{name}`: macro SEGMENTS vs loaded table"
        );
        assert_eq!(count, table.pairs.len(), "`{name}`: SEGMENT_COUNT");
        assert_eq!(
            count, f.entries as usize,
            "`{name}`: SEGMENT_COUNT vs figures"
        );
        assert_eq!(len, f.steps as usize, "`{name}`: LEN");
        timer_constants!($name, table.spec, f);

        assert_eq!(
            len,
            macro_pairs.iter().map(|&(_, c)| c as usize).sum::<usize>(),
            "`{name}`: LEN is the sum of the counts"
        );
        assert_eq!(
            total_ticks,
            macro_pairs
                .iter()
                .map(|&(p, c)| u64::from(p) * u64::from(c))
                .sum::<u64>(),
            "`{name}`: TOTAL_TICKS is the sum of period times count"
        );

        let mut buffer = $name::SEGMENTS;
        buffer.fill((0, 0));
        let figures = table
            .spec
            .generate_segments(&mut buffer)
            .unwrap_or_else(|e| panic!("`{name}`: Spec::generate_segments: {e}"));
        assert_eq!(
            buffer,
            $name::SEGMENTS,
            "`{name}`: generate_segments vs macro SEGMENTS"
        );
        assert_eq!(
            &figures, f,
            "`{name}`: generate_segments figures vs loaded figures"
        );
        name
    }};
}

/// A compressed profile: `RUNS` and its constants, three ways.
macro_rules! runs {
    ($profiles:expr, $name:ident) => {{
        let name = stringify!($name);
        let Generated::Runs(table) = find($profiles, name) else {
            panic!("`{name}`: the macro emitted `RUNS` but the file holds another layout");
        };
        let f = &table.figures;

        let count: usize = $name::RUN_COUNT;
        let len: usize = $name::LEN;
        let total_ticks: u64 = $name::TOTAL_TICKS;
        let edge: f64 = $name::MAX_EDGE_ERROR_TICKS;

        assert_eq!(
            $name::RUNS.as_slice(),
            table.runs.as_slice(),
            "`{name}`: macro RUNS vs loaded table"
        );
        assert_eq!(count, f.entries as usize, "`{name}`: RUN_COUNT vs figures");
        assert_eq!(len, f.steps as usize, "`{name}`: LEN");
        timer_constants!($name, table.spec, f);
        assert_eq!(
            edge.to_bits(),
            f.max_edge_error_ticks.to_bits(),
            "`{name}`: MAX_EDGE_ERROR_TICKS"
        );
        let tolerance = f.tolerance_ticks.expect("runs are fitted to a tolerance");
        assert!(
            edge <= tolerance,
            "`{name}`: largest edge error {edge} above `compress = {tolerance}`"
        );

        let played: Vec<u32> = profile_core::runs::Expand::new(&$name::RUNS).collect();
        assert_eq!(played.len(), len, "`{name}`: LEN is the sum of the counts");
        // The index: each run's words and first step (the counts before
        // it added).
        let mut first = 0u32;
        for (run, indexed) in $name::RUNS.iter().zip($name::RUN_INDEX.runs()) {
            assert_eq!(indexed.words(), run, "`{name}`: RUN_INDEX words");
            assert_eq!(indexed.step(), first, "`{name}`: RUN_INDEX first step");
            first += u32::from(run[0]);
        }
        assert_eq!(
            played.iter().map(|&p| u64::from(p)).sum::<u64>(),
            total_ticks,
            "`{name}`: TOTAL_TICKS is the sum of the played periods"
        );

        let again = table
            .spec
            .run_table(tolerance)
            .unwrap_or_else(|e| panic!("`{name}`: Spec::run_table: {e}"));
        assert_eq!(
            again.runs.as_slice(),
            $name::RUNS.as_slice(),
            "`{name}`: Spec::run_table vs macro RUNS"
        );
        assert_eq!(
            &again.figures, f,
            "`{name}`: Spec::run_table figures vs loaded figures"
        );
        name
    }};
}

#[test]
fn every_profile_three_ways() {
    let profiles = loaded();
    let p = &profiles;
    // In file order. A profile added to profiles.toml must be added here.
    let checked = [
        steps!(p, sigmoid_yellow),
        steps!(p, sigmoid_orange),
        steps!(p, sigmoid_blue),
        steps!(p, sigmoid_gray),
        steps!(p, sigmoid_exact),
        steps!(p, exponential),
        segments!(p, exponential_segments),
        steps!(p, linear_integer),
        steps!(p, linear_exact),
        steps!(p, linear_estop),
        steps!(p, microstep),
        runs!(p, microstep_runs),
        steps!(p, three_stage),
        steps!(p, jerk_limited),
        steps!(p, torque_limited),
    ];
    let in_file: Vec<&str> = profiles
        .profiles()
        .iter()
        .map(|p| p.name.as_str())
        .collect();
    assert_eq!(
        in_file.len(),
        checked.len(),
        "profiles.toml holds {} profiles but this test compares {}: add the new ones to \
         `every_profile_three_ways`",
        in_file.len(),
        checked.len()
    );
    assert_eq!(in_file, checked, "profiles in file order");
}

#[test]
fn a_trailing_comma_reads_the_same_file() {
    assert_eq!(with_comma::sigmoid_orange::PERIODS, sigmoid_orange::PERIODS);
    assert_eq!(with_comma::exponential::PERIODS, exponential::PERIODS);
}

#[test]
fn the_macro_and_the_loader_read_the_same_file() {
    // `include_profiles!` parses the file under its relative name; `load`
    // under the path it was given. The profiles are the same.
    let source = std::fs::read_to_string(manifest_path()).unwrap();
    let parsed = Profiles::parse("profiles.toml", &source).unwrap();
    let loaded = loaded();
    assert_eq!(parsed.profiles(), loaded.profiles());
    assert_eq!(parsed.rust_source(), loaded.rust_source());
    assert_eq!(parsed.file(), "profiles.toml");
    assert_eq!(loaded.file(), manifest_path().display().to_string());
}

#[test]
fn the_seeds_through_the_macro() {
    assert_eq!(
        (sigmoid_orange::PERIODS[0], sigmoid_orange::PERIODS[999]),
        (19183, 156)
    );
    assert_eq!(exponential::LEN, 120);
    assert_eq!(exponential::PERIODS.len(), 120);
    assert_eq!(exponential::TIMER_HZ, 1_000_000);
    assert_eq!(exponential_segments::LEN, 120);
    assert_eq!(exponential_segments::SEGMENTS.len(), 8);
    assert_eq!(linear_integer::PERIODS[0], 50_000);
    assert_eq!(linear_integer::PERIODS[200], 5_000);
    assert_eq!(linear_integer::LEN, 201);
    assert_eq!(linear_integer::TICKS_PER_STEP, 2);
}

/// A profile's bands as the periods that play in them, for the player:
/// `jerk_limited` avoids 100 to 150 full steps/s, in the motor's 1/8 steps
/// 800 to 1200 steps/s, on the file's 10 MHz timer 8334 to 12 500 ticks;
/// a cruise set inside the band cruises at the fastest entry slower.
#[test]
fn a_profile_s_bands_come_as_periods_for_the_player() {
    use stepper_profiles::player::{Player, Ramp};
    assert_eq!(jerk_limited::TIMER_HZ, 10_000_000);
    assert_eq!(jerk_limited::AVOID, [(8334, 12_500)]);
    let in_band = jerk_limited::PERIODS
        .iter()
        .position(|&p| (8334..=12_500).contains(&p))
        .unwrap();
    let mut player =
        Player::new(Ramp::steps(&jerk_limited::PERIODS)).avoiding(&jerk_limited::AVOID);
    player.set_cruise(in_band as u32);
    player.run();
    let cruise = (0..2000)
        .map(|_| player.next_period().unwrap())
        .last()
        .unwrap();
    let slow_side = jerk_limited::PERIODS
        .iter()
        .copied()
        .filter(|&p| p > 12_500)
        .min();
    assert_eq!(Some(cruise), slow_side);
}

/// The file maps onto the specs the README and DESIGN describe, defaults
/// (`[defaults] timer_hz`) included.
#[test]
fn specs_come_from_the_file_and_its_defaults() {
    let profiles = loaded();
    let spec = |name: &str| match find(&profiles, name) {
        Generated::Steps(t) => t.spec,
        Generated::Segments(t) => t.spec,
        Generated::Runs(t) => t.spec,
        _ => panic!("a layout this test does not know"),
    };
    let orange = Spec::new(
        Curve::Sigmoid(Sigmoid {
            fmin: 500.0,
            fmax: 64_000.0,
            flexible: 8.0,
            len: 1000,
        }),
        Timer::new(10_000_000),
    );
    assert_eq!(spec("sigmoid_exact"), orange);
    assert_eq!(
        spec("sigmoid_orange"),
        orange
            .with_discretization(Discretization::Index)
            .with_rounding(Rounding::Truncate)
            .with_arithmetic(Arithmetic::F32)
    );
    let exponential = Spec::new(
        Curve::Exponential(Exponential {
            fmin: 500.0,
            fmax: 10_000.0,
            f_inf: 15_000.0,
            extent: ExponentialExtent::Len(120),
        }),
        Timer::new(1_000_000),
    );
    assert_eq!(spec("exponential"), exponential);
    assert_eq!(spec("exponential_segments"), exponential);
    assert_eq!(
        spec("linear_integer"),
        Spec::new(
            Curve::Linear(Linear {
                fmin: 500.0,
                fmax: 5000.0,
                extent: LinearExtent::Len(201),
            }),
            Timer::new(50_000_000),
        )
        .with_ticks_per_step(2)
        .with_discretization(Discretization::Index)
        .with_rounding(Rounding::Truncate)
        .with_arithmetic(Arithmetic::Integer)
    );
}

/// A `pub mod` of emitted Rust source: its name, its `(constant, value)`
/// pairs as written, and its `PERIODS` (empty for a segment table).
type Module = (String, Vec<(String, String)>, Vec<u64>);

/// Each `pub mod` in emitted Rust source, read as text, the way a reviewer
/// would read the generated file.
fn modules_in(source: &str) -> Vec<Module> {
    let mut modules = Vec::new();
    for line in source.lines() {
        let line = line.trim();
        if let Some(rest) = line.strip_prefix("pub mod ") {
            let name = rest.trim_end_matches(" {").to_string();
            modules.push((name, Vec::new(), Vec::new()));
        } else if let Some(rest) = line.strip_prefix("pub const ") {
            let (name, rest) = rest.split_once(':').expect("`pub const NAME: T = V;`");
            let value = rest.split_once('=').expect("`= V`").1;
            let module = modules.last_mut().expect("constant inside a module");
            module.1.push((
                name.trim().to_string(),
                value.trim().trim_end_matches(';').to_string(),
            ));
        } else if let Some(rest) = line.strip_prefix("pub static PERIODS: ") {
            let array = rest.split_once("= [").expect("`= [...]`").1;
            let array = array.trim_end_matches("];");
            let module = modules.last_mut().expect("table inside a module");
            module.2 = array
                .split(", ")
                .map(|v| {
                    v.trim_end_matches("u16")
                        .trim_end_matches("u32")
                        .parse()
                        .unwrap_or_else(|e| panic!("period `{v}`: {e}"))
                })
                .collect();
        }
    }
    modules
}

#[test]
fn the_build_script_writes_what_the_macro_expands_to() {
    let profiles = loaded();
    let out_dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("profiles_toml-out");
    let _ = std::fs::remove_dir_all(&out_dir);
    std::fs::create_dir_all(&out_dir).unwrap();
    let written = profiles.write_rust(&out_dir).unwrap();
    assert_eq!(written, out_dir.join("profiles.rs"));
    let text = std::fs::read_to_string(&written).unwrap();
    assert_eq!(text, profiles.rust_source());

    // The seeds' facts, read from the file itself.
    let modules = modules_in(&text);
    let names: Vec<&str> = modules.iter().map(|(n, _, _)| n.as_str()).collect();
    let in_file: Vec<&str> = profiles
        .profiles()
        .iter()
        .map(|p| p.name.as_str())
        .collect();
    assert_eq!(names, in_file, "one module per profile, in file order");
    let module = |name: &str| modules.iter().find(|(n, _, _)| n == name).unwrap();
    let constant = |name: &str, key: &str| -> String {
        module(name)
            .1
            .iter()
            .find(|(k, _)| k == key)
            .unwrap_or_else(|| panic!("`{name}::{key}` in profiles.rs"))
            .1
            .clone()
    };

    let orange = &module("sigmoid_orange").2;
    assert_eq!((orange[0], orange[999]), (19183, 156));
    assert_eq!(constant("sigmoid_orange", "FIRST_TICKS"), "19183");
    assert_eq!(constant("sigmoid_orange", "LAST_TICKS"), "156");
    assert!(text.contains("pub static PERIODS: [u16; 1000] = [19183u16, "));

    assert_eq!(module("exponential").2.len(), 120);
    assert_eq!(constant("exponential", "LEN"), "120");
    assert!(text.contains("pub static PERIODS: [u16; 120] = ["));

    let linear = &module("linear_integer").2;
    assert_eq!((linear[0], *linear.last().unwrap()), (50_000, 5_000));
    assert_eq!(linear.len(), 201);
    assert_eq!(constant("linear_integer", "TICKS_PER_STEP"), "2");
    assert_eq!(constant("linear_integer", "TIMER_HZ"), "50000000");

    // Every per-step module's constants agree with its own array.
    for (name, constants, periods) in &modules {
        if periods.is_empty() {
            continue;
        }
        let get = |key: &str| &constants.iter().find(|(k, _)| k == key).unwrap().1;
        assert_eq!(get("LEN"), &periods.len().to_string(), "{name}");
        assert_eq!(
            get("TOTAL_TICKS"),
            &periods.iter().sum::<u64>().to_string(),
            "{name}"
        );
    }
}

/// `write_rust` on a loaded file prints `cargo::rerun-if-changed=<path>` for
/// Cargo, and nothing for a parsed source (no file to watch); checked in a
/// child process whose stdout is not captured.
#[test]
fn write_rust_asks_cargo_to_watch_the_file() {
    const CHILD: &str = "PROFILES_TOML_RERUN_CHILD";
    let out_dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("profiles_toml-rerun");
    if std::env::var_os(CHILD).is_some() {
        std::fs::create_dir_all(&out_dir).unwrap();
        let source = std::fs::read_to_string(manifest_path()).unwrap();
        let parsed = Profiles::parse("profiles.toml", &source).unwrap();
        println!("<parsed>");
        parsed.write_rust(&out_dir).unwrap();
        println!("</parsed>");
        println!("<loaded>");
        loaded().write_rust(&out_dir).unwrap();
        println!("</loaded>");
        return;
    }
    let output = Command::new(std::env::current_exe().unwrap())
        .args([
            "--exact",
            "write_rust_asks_cargo_to_watch_the_file",
            "--nocapture",
            "--test-threads=1",
        ])
        .env(CHILD, "1")
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "child failed:\n{stdout}");
    let between = |tag: &str| -> Vec<&str> {
        stdout
            .lines()
            .skip_while(|l| *l != format!("<{tag}>"))
            .skip(1)
            .take_while(|l| *l != format!("</{tag}>"))
            .collect()
    };
    assert!(
        stdout.contains("</loaded>"),
        "the child did not run the check:\n{stdout}"
    );
    assert_eq!(
        between("parsed"),
        Vec::<&str>::new(),
        "parsed: no file to watch"
    );
    assert_eq!(
        between("loaded"),
        [format!(
            "cargo::rerun-if-changed={}",
            manifest_path().display()
        )],
        "loaded: the file is watched"
    );
}

/// A profile's own `accel`, `tau` or `segments` displaces a default `len`
/// or `compress`: the default applies only where it does not contradict the
/// profile.
#[test]
fn a_profile_s_own_length_and_layout_displace_the_defaults() {
    let source = r#"
[defaults]
timer_hz = 1_000_000
len = 500
compress = 1

[profiles.by_accel]
curve = "linear"
fmin = 200
fmax = 2000
accel = 5000

[profiles.by_tau]
curve = "exponential"
fmin = 200
fmax = 2000
f_inf = 2100
tau = 0.1
segments = 8

[profiles.by_default]
curve = "linear"
fmin = 200
fmax = 2000
"#;
    let profiles = Profiles::parse("profiles.toml", source).unwrap_or_else(|e| panic!("{e}"));
    let by_accel = profiles.profiles()[0].table.spec().curve;
    assert_eq!(
        by_accel,
        Curve::Linear(Linear {
            fmin: 200.0,
            fmax: 2000.0,
            extent: LinearExtent::Accel(5000.0),
        })
    );
    assert!(matches!(profiles.profiles()[0].table, Generated::Runs(_)));
    let by_tau = &profiles.profiles()[1].table;
    assert!(matches!(by_tau, Generated::Segments(_)));
    assert!(matches!(
        by_tau.spec().curve,
        Curve::Exponential(Exponential {
            extent: ExponentialExtent::Tau(_),
            ..
        })
    ));
    let by_default = profiles.profiles()[2].table.spec();
    assert_eq!(by_default.len(), 500);
}
