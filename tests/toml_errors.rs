//! Golden tests of the messages a broken `profiles.toml` gets.
//!
//! Each `tests/toml_errors/NAME.toml` is parsed with
//! `Profiles::parse("profiles.toml", source)`; the full message (every
//! `profiles.toml:LINE:COL: message`, the source line and the caret) must equal
//! `tests/toml_errors/NAME.txt`. After a deliberate change run
//!
//! ```text
//! UPDATE_GOLDEN=1 cargo test --test toml_errors
//! ```
//!
//! and review `git diff tests/toml_errors`.

use test_support as common;

use std::fs;
use std::path::{Path, PathBuf};

use common::golden;
use profile_codegen::profiles::Profiles;

/// Cases the issue asks for; the directory may hold more.
const REQUIRED: &[&str] = &[
    "syntax_error",
    "unknown_table",
    "unknown_key",
    "unknown_default_key",
    "duplicate_key",
    "missing_key",
    "unknown_curve",
    "wrong_type_string",
    "wrong_type_bool",
    "wrong_type_array",
    "bad_name_space",
    "bad_name_upper",
    "bad_name_keyword",
    "duplicate_profile",
    "fmax_not_greater",
    "nan",
    "inf",
    "len_zero",
    "period_overflow",
    "integer_overflow",
    "defaults_error",
    "several_errors",
    "no_profiles",
    "missing_file",
    // The motor: its parameters, names, and ramps it cannot follow.
    "motor_step_angle_zero",
    "motor_microsteps_zero",
    "motor_rotor_inertia_nan",
    "motor_safety_below_one",
    "motor_curve_not_rising",
    "motor_curve_too_many_points",
    "motor_curve_not_points",
    "motor_missing_keys",
    "motor_unknown",
    "motor_no_motors",
    "motor_cannot_follow",
    "motor_start_too_fast",
    // Values at the edge of what a file can hold, and names C reserves.
    "motor_table_profile_key",
    "motor_unknown_many",
    "number_too_large_float",
    "number_too_large_int",
    "number_too_many_digits",
    "segments_count_overflow",
    "segments_period_overflow",
    "bad_name_errno",
    "file_too_large",
    // A file saved in another encoding than UTF-8 (a Windows code page).
    "not_utf8",
    // Numbers no profile takes: not finite, out of a motor key's range.
    "defaults_unused_out_of_range",
    // Messages that said too little or too much: a unit of another scale
    // suggested, a point's mistake on the whole curve, a point at infinity
    // "not rising", a number with a unit "not a number", 300 digits.
    "unit_prefix_not_accepted",
    "unit_prefix_torque",
    "motor_curve_point_not_number",
    "motor_curve_not_finite",
    "number_too_many_digits_unit",
    "motor_damping_huge",
    // `reload_offset`: its kind, its range, a stored value out of the word.
    "reload_offset_not_integer",
    "reload_offset_range",
    "reload_offset_entry_zero",
    "reload_offset_compress",
    // The step driver's timing.
    "driver_too_fast",
    "driver_keys_too_fast",
    "driver_unknown",
    "driver_time_zero",
    "driver_dir_setup",
    // The step interrupt's budget.
    "cpu_too_fast",
    "cpu_unknown_core",
    "cpu_without_clock",
    "cpu_load_above_one",
    // Resonance bands.
    "avoid_top_in_band",
    "avoid_band_reversed",
    "avoid_band_unit",
    // The emergency ramp: its name, its timer, its reach, its layout, its
    // motor.
    "emergency_unknown",
    "emergency_not_name",
    "emergency_itself",
    "emergency_timer",
    "emergency_slower",
    "emergency_compressed",
    "emergency_motor",
];

/// The file named in messages, as `include_profiles!("profiles.toml")` names it.
const FILE: &str = "profiles.toml";

/// A path that does not exist, relative to the package (the tests' working
/// directory), for `Profiles::load`.
const MISSING: &str = "tests/toml_errors/no_such_dir/profiles.toml";

fn dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/toml_errors")
}

/// Every case: its name and the message it produces.
fn cases() -> Vec<(String, String)> {
    let mut names: Vec<String> = fs::read_dir(dir())
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .map(|p| p.file_stem().unwrap().to_string_lossy().into_owned())
        .collect();
    names.sort();
    let mut cases: Vec<(String, String)> = names
        .into_iter()
        .map(|name| {
            let bytes = fs::read(dir().join(format!("{name}.toml"))).unwrap();
            let message = match Profiles::parse_bytes(FILE, &bytes) {
                Ok(p) => format!("<no error: {} profiles parsed>\n", p.profiles().len()),
                Err(e) => e.message().to_string(),
            };
            (name, message)
        })
        .collect();
    let missing = match Profiles::load(MISSING) {
        Ok(_) => "<no error>\n".to_string(),
        Err(e) => format!("{}\n", e.message()),
    };
    cases.push(("missing_file".to_string(), missing));
    cases
}

#[test]
fn messages_match_their_golden_files() {
    let cases = cases();
    for required in REQUIRED {
        assert!(
            cases.iter().any(|(n, _)| n == required),
            "case `{required}` is missing from tests/toml_errors"
        );
    }

    let mut failures = Vec::new();
    for (name, actual) in &cases {
        let path = dir().join(format!("{name}.txt"));
        if let Err(difference) = golden::text(&path, name, actual) {
            failures.push(difference);
        }
    }
    // No stale expectation without its input.
    for entry in fs::read_dir(dir()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "txt") {
            let stem = path.file_stem().unwrap().to_string_lossy();
            if !cases.iter().any(|(n, _)| *n == stem) {
                failures.push(format!("--- {}: no case produces it", path.display()));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} golden message(s) differ; if the change is intended run \
         `UPDATE_GOLDEN=1 cargo test --test toml_errors` and review `git diff`:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn every_case_is_an_error() {
    for (name, message) in cases() {
        assert!(
            !message.starts_with("<no error"),
            "{name}: expected an error, got {message}"
        );
    }
}

/// Each diagnostic is `profiles.toml:LINE:COL: message`, then ` |`, the
/// numbered source line, and a caret that starts at COL; messages are
/// lowercase with no trailing period.
#[test]
fn diagnostics_are_well_formed() {
    for (name, text) in cases() {
        if name == "missing_file" {
            continue;
        }
        // A byte that is not UTF-8 shows as U+FFFD on its line.
        let bytes = fs::read(dir().join(format!("{name}.toml"))).unwrap();
        let source = String::from_utf8_lossy(&bytes);
        let lines: Vec<&str> = text.lines().collect();
        let mut i = 0;
        let mut count = 0;
        while i < lines.len() {
            if lines[i].is_empty() {
                i += 1;
                continue;
            }
            let head = lines[i];
            let rest = head
                .strip_prefix("profiles.toml:")
                .unwrap_or_else(|| panic!("{name}: `{head}` does not start with the file"));
            let mut parts = rest.splitn(3, ':');
            let line: usize = parts.next().unwrap().parse().unwrap();
            let col: usize = parts.next().unwrap().parse().unwrap();
            let message = parts.next().unwrap().trim_start();
            assert!(
                !message.ends_with('.'),
                "{name}: message ends with a period: {message}"
            );
            assert!(
                !message.starts_with(|c: char| c.is_uppercase()),
                "{name}: message starts with a capital: {message}"
            );
            count += 1;
            if source.is_empty() {
                // No line to show.
                i += 1;
                continue;
            }
            let number = line.to_string();
            let pad = " ".repeat(number.len());
            assert_eq!(lines[i + 1], format!("{pad} |"), "{name}: gutter");
            let src_line = source.lines().nth(line - 1).unwrap_or("");
            assert_eq!(
                lines[i + 2],
                format!("{number} | {src_line}"),
                "{name}: source line {line}"
            );
            let caret = lines[i + 3]
                .strip_prefix(&format!("{pad} | "))
                .unwrap_or_else(|| panic!("{name}: caret line `{}`", lines[i + 3]));
            assert_eq!(
                caret.chars().take_while(|c| *c == ' ').count(),
                col - 1,
                "{name}: caret starts at column {col}"
            );
            assert!(
                caret.trim_start().chars().all(|c| c == '^'),
                "{name}: caret"
            );
            assert!(
                caret.chars().count() <= src_line.chars().count().max(col),
                "{name}: caret runs past the line"
            );
            i += 4;
        }
        assert!(count > 0, "{name}: no diagnostic");
    }
}

/// `Profiles::load` names the file by the path it was given.
#[test]
fn load_names_the_path() {
    let relative = "tests/toml_errors/missing_key.toml";
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(relative);
    let loaded = Profiles::load(&path).unwrap_err().message().to_string();
    let source = fs::read_to_string(&path).unwrap();
    let parsed = Profiles::parse(FILE, &source)
        .unwrap_err()
        .message()
        .to_string();
    assert_eq!(
        loaded,
        parsed.replace("profiles.toml:", &format!("{}:", path.display()))
    );

    let missing = Profiles::load(MISSING).unwrap_err().message().to_string();
    assert!(
        missing.starts_with(&format!("cannot read `{MISSING}`: ")),
        "{missing}"
    );
}

/// Windows line endings change neither positions nor the lines shown.
#[test]
fn crlf_sources_read_the_same() {
    for name in ["unknown_key", "several_errors", "multiline_value"] {
        let source = fs::read_to_string(dir().join(format!("{name}.toml"))).unwrap();
        let crlf = source.replace('\n', "\r\n");
        let lf = Profiles::parse(FILE, &source).unwrap_err();
        let crlf = Profiles::parse(FILE, &crlf).unwrap_err();
        assert_eq!(crlf.message(), lf.message(), "{name}");
    }
}

/// Many mistakes render in time and space linear in their number: 24 000
/// broken profiles, and 500 profiles naming unknown motors among 500
/// declared ones (each message lists a few motors, not all of them).
#[test]
fn many_mistakes_render_in_linear_time_and_space() {
    let broken: String = (0..24_000)
        .map(|i| format!("[profiles.p{i}]\ncurve = \"sigmoid\"\nlen = 0\n\n"))
        .collect();
    let message = Profiles::parse(FILE, &broken)
        .unwrap_err()
        .message()
        .to_string();
    // Each profile: `len` must be at least 1, and its missing keys.
    let diagnostics = message.matches("profiles.toml:").count();
    assert_eq!(diagnostics, 48_000, "{}", &message[..400]);

    let motors: String = (0..500)
        .map(|i| {
            format!(
                "[motors.motor_{i}]\nstep_angle = 1.8\nrotor_inertia = 5.4e-6\n\
                 torque_curve = [[0, 0.4], [6000, 0.06]]\n\n"
            )
        })
        .collect();
    let profiles: String = (0..500)
        .map(|i| {
            format!(
                "[profiles.p{i}]\ncurve = \"linear\"\nfmin = 300\nfmax = 2000\n\
                 timer_hz = 1_000_000\naccel = 2000\nmotor = \"unknown_{i}\"\n\n"
            )
        })
        .collect();
    let source = motors + &profiles;
    let message = Profiles::parse(FILE, &source)
        .unwrap_err()
        .message()
        .to_string();
    assert_eq!(message.matches("unknown motor").count(), 500);
    assert!(
        message.len() < 400 * 500,
        "{} bytes for 500 messages: {}",
        message.len(),
        &message[..600]
    );
}
