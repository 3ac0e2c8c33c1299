//! Editing `profiles.toml` always rebuilds, through both paths: the
//! `include_profiles!` macro (which tracks the file with `include_bytes!`) and
//! a build script calling `Profiles::load(..)?.write_rust(OUT_DIR)` (which
//! prints `cargo::rerun-if-changed`).
//!
//! The test writes two scratch crates under `CARGO_TARGET_TMPDIR/rebuild-scratch`
//! that depend on this package by path: `macro-path` (no build script, so
//! nothing but the macro's tracking can trigger a rebuild) and `build-path`.
//! It runs each with `cargo run`, edits their `profiles.toml` twice and checks
//! that each edit reaches both. They share a target directory inside
//! `CARGO_TARGET_TMPDIR`, kept between runs, so only the first run builds the
//! dependencies.

use test_support as common;

use std::fs;
use std::time::{Duration, Instant, SystemTime};

use common::scratch::{ScratchCrate, target_dir};

use profile_codegen::Generated;
use profile_codegen::profiles::Profiles;

/// The macro path: no build script, so only the macro's `include_bytes!`
/// can make Cargo notice an edit.
const MACRO_CARGO_TOML: &str = r#"[package]
name = "macro-path"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
stepper-profiles = { path = "@ROOT@" }

# Not part of any enclosing workspace.
[workspace]
"#;

const MACRO_MAIN_RS: &str = r#"stepper_profiles::include_profiles!("profiles.toml");

fn main() {
    println!("macro {} {}", one::PERIODS[0], one::LEN);
}
"#;

/// The build-script path.
const BUILD_CARGO_TOML: &str = r#"[package]
name = "build-path"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
stepper-profiles = { path = "@ROOT@" }

[build-dependencies]
profile-codegen = { path = "@ROOT@/profile-codegen" }

# Not part of any enclosing workspace.
[workspace]
"#;

const BUILD_RS: &str = r#"fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out_dir = std::env::var("OUT_DIR")?;
    profile_codegen::profiles::Profiles::load("profiles.toml")?.write_rust(out_dir)?;
    Ok(())
}
"#;

const BUILD_MAIN_RS: &str = r#"// Only some of the figures are used here.
#[allow(dead_code)]
mod built {
    include!(concat!(env!("OUT_DIR"), "/profiles.rs"));
}

fn main() {
    println!("build {} {}", built::one::PERIODS[0], built::one::LEN);
}
"#;

/// The scratch crate's `profiles.toml` with `fmin` and `len`.
fn profiles_toml(fmin: u32, len: u32) -> String {
    format!(
        "# Rewritten by tests/rebuild.rs.\n[profiles.one]\ncurve = \"linear\"\n\
         fmin = {fmin}\nfmax = 5000\nlen = {len}\ntimer_hz = 1_000_000\n"
    )
}

/// `(PERIODS[0], LEN)` of profile `one`, computed here.
fn expected(source: &str) -> (u32, usize) {
    let profiles = Profiles::parse("profiles.toml", source).unwrap_or_else(|e| panic!("{e}"));
    match &profiles.profiles()[0].table {
        Generated::Steps(t) => (t.periods[0], t.periods.len()),
        Generated::Segments(_) | Generated::Runs(_) => unreachable!(),
        _ => panic!("a layout this test does not know"),
    }
}

/// The two scratch crates under `CARGO_TARGET_TMPDIR/rebuild-scratch`.
struct Scratch {
    crates: [ScratchCrate; 2],
    offline: bool,
}

impl Scratch {
    fn new() -> Self {
        let crates = [
            ScratchCrate::new(
                "rebuild-scratch/macro-path",
                &[
                    ("Cargo.toml", MACRO_CARGO_TOML),
                    ("src/main.rs", MACRO_MAIN_RS),
                ],
            ),
            ScratchCrate::new(
                "rebuild-scratch/build-path",
                &[
                    ("Cargo.toml", BUILD_CARGO_TOML),
                    ("src/main.rs", BUILD_MAIN_RS),
                    ("build.rs", BUILD_RS),
                ],
            ),
        ];
        // Offline when every dependency is already in Cargo's cache.
        let offline = crates.iter().all(|c| {
            c.cargo()
                .args(["metadata", "--offline", "--format-version", "1"])
                .output()
                .is_ok_and(|o| o.status.success())
        });
        Scratch { crates, offline }
    }

    /// Writes both crates' `profiles.toml`, making sure each mtime is later
    /// than the last build's output whatever the file system's timestamp
    /// granularity (Cargo compares mtimes).
    fn edit(&self, contents: &str) {
        for scratch in &self.crates {
            let path = scratch.dir.join("profiles.toml");
            fs::write(&path, contents).unwrap();
            let binary = target_dir()
                .join("debug")
                .join(scratch.dir.file_name().unwrap());
            if let Ok(built) = fs::metadata(&binary).and_then(|m| m.modified()) {
                let written = fs::metadata(&path).unwrap().modified().unwrap();
                if written <= built {
                    let later = built.max(SystemTime::now()) + Duration::from_secs(1);
                    fs::File::options()
                        .write(true)
                        .open(&path)
                        .unwrap()
                        .set_modified(later)
                        .unwrap();
                }
            }
        }
    }

    /// `cargo run` in each crate: `macro FIRST LEN` then `build FIRST LEN`.
    fn run(&self) -> (String, Duration) {
        let start = Instant::now();
        let mut stdout = String::new();
        for scratch in &self.crates {
            let mut command = scratch.cargo();
            command.args(["run", "--quiet"]);
            if self.offline {
                command.arg("--offline");
            }
            let output = command.output().expect("cannot run cargo");
            let out = String::from_utf8_lossy(&output.stdout);
            assert!(
                output.status.success(),
                "`cargo run` in {} failed:\n{out}{}",
                scratch.dir.display(),
                String::from_utf8_lossy(&output.stderr)
            );
            stdout.push_str(&out);
        }
        (stdout, start.elapsed())
    }

    /// Lines of the build script's recorded output (`target/.../build/*/output`).
    fn build_script_output(&self) -> Vec<String> {
        let build = target_dir().join("debug/build");
        let mut lines = Vec::new();
        for entry in fs::read_dir(&build).into_iter().flatten().flatten() {
            if entry
                .file_name()
                .to_string_lossy()
                .starts_with("build-path-")
            {
                if let Ok(text) = fs::read_to_string(entry.path().join("output")) {
                    lines.extend(text.lines().map(str::to_string));
                }
            }
        }
        lines
    }
}

fn expected_output(source: &str) -> String {
    let (first, len) = expected(source);
    format!("macro {first} {len}\nbuild {first} {len}\n")
}

#[test]
#[ignore = "slow: builds a scratch crate with cargo; CI runs it with --ignored"]
fn editing_profiles_toml_rebuilds_both_paths() {
    let scratch = Scratch::new();
    let versions = [
        profiles_toml(500, 200),
        // fmin changes the first period.
        profiles_toml(800, 200),
        // len changes LEN (and the file's length).
        profiles_toml(800, 1500),
    ];
    let values: Vec<(u32, usize)> = versions.iter().map(|v| expected(v)).collect();
    assert_ne!(
        values[0].0, values[1].0,
        "the fmin edit must change PERIODS[0]"
    );
    assert_ne!(values[1].1, values[2].1, "the len edit must change LEN");

    let mut times = Vec::new();
    for (i, version) in versions.iter().enumerate() {
        scratch.edit(version);
        let (stdout, elapsed) = scratch.run();
        times.push(elapsed);
        assert_eq!(
            stdout,
            expected_output(version),
            "run {i}: stale output after writing profiles.toml:\n{version}"
        );
    }

    // The build script asked Cargo to watch the file.
    let output = scratch.build_script_output();
    assert!(
        output
            .iter()
            .any(|l| l == "cargo::rerun-if-changed=profiles.toml"),
        "the build script's output lacks `cargo::rerun-if-changed=profiles.toml`: {output:?}"
    );

    eprintln!(
        "rebuild: cargo run took {} (offline: {})",
        times
            .iter()
            .map(|t| format!("{:.1} s", t.as_secs_f64()))
            .collect::<Vec<_>>()
            .join(", "),
        scratch.offline
    );
}
