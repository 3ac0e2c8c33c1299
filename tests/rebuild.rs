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

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant, SystemTime};

use profile_core::Generated;
use profile_core::build::Profiles;

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
profile-core = { path = "@ROOT@/profile-core", features = ["codegen"] }

# Not part of any enclosing workspace.
[workspace]
"#;

const BUILD_RS: &str = r#"fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out_dir = std::env::var("OUT_DIR")?;
    profile_core::build::Profiles::load("profiles.toml")?.write_rust(out_dir)?;
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
        Generated::Segments(_) => unreachable!(),
    }
}

/// The two scratch crates under `CARGO_TARGET_TMPDIR/rebuild-scratch`,
/// built into one target directory.
struct Scratch {
    crates: [PathBuf; 2],
    target: PathBuf,
    offline: bool,
}

impl Scratch {
    fn new() -> Self {
        let tmp = Path::new(env!("CARGO_TARGET_TMPDIR"));
        let dir = tmp.join("rebuild-scratch");
        let root = env!("CARGO_MANIFEST_DIR");
        let macro_path = dir.join("macro-path");
        let build_path = dir.join("build-path");
        let files: [(&Path, &str, &str); 4] = [
            (&macro_path, "Cargo.toml", MACRO_CARGO_TOML),
            (&macro_path, "src/main.rs", MACRO_MAIN_RS),
            (&build_path, "Cargo.toml", BUILD_CARGO_TOML),
            (&build_path, "src/main.rs", BUILD_MAIN_RS),
        ];
        for (crate_dir, file, contents) in files {
            fs::create_dir_all(crate_dir.join("src")).unwrap();
            write_if_changed(&crate_dir.join(file), &contents.replace("@ROOT@", root));
        }
        write_if_changed(&build_path.join("build.rs"), BUILD_RS);
        let crates = [macro_path, build_path];
        for crate_dir in &crates {
            // Start from this workspace's lock file: the same, already
            // downloaded, versions; Cargo prunes what the crate does not use.
            if !crate_dir.join("Cargo.lock").exists() {
                fs::copy(
                    Path::new(root).join("Cargo.lock"),
                    crate_dir.join("Cargo.lock"),
                )
                .unwrap();
            }
        }
        // Offline when every dependency is already in Cargo's cache.
        let offline = crates.iter().all(|c| {
            cargo(c)
                .args(["metadata", "--offline", "--format-version", "1"])
                .output()
                .is_ok_and(|o| o.status.success())
        });
        Scratch {
            crates,
            target: tmp.join("rebuild-target"),
            offline,
        }
    }

    /// Writes both crates' `profiles.toml`, making sure each mtime is later
    /// than the last build's output whatever the file system's timestamp
    /// granularity (Cargo compares mtimes).
    fn edit(&self, contents: &str) {
        for crate_dir in &self.crates {
            let path = crate_dir.join("profiles.toml");
            fs::write(&path, contents).unwrap();
            let binary = self
                .target
                .join("debug")
                .join(crate_dir.file_name().unwrap());
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
        for crate_dir in &self.crates {
            let mut command = cargo(crate_dir);
            command
                .args(["run", "--quiet"])
                .env("CARGO_TARGET_DIR", &self.target);
            if self.offline {
                command.arg("--offline");
            }
            let output = command.output().expect("cannot run cargo");
            let out = String::from_utf8_lossy(&output.stdout);
            assert!(
                output.status.success(),
                "`cargo run` in {} failed:\n{out}{}",
                crate_dir.display(),
                String::from_utf8_lossy(&output.stderr)
            );
            stdout.push_str(&out);
        }
        (stdout, start.elapsed())
    }

    /// Lines of the build script's recorded output (`target/.../build/*/output`).
    fn build_script_output(&self) -> Vec<String> {
        let build = self.target.join("debug/build");
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

fn cargo(dir: &Path) -> Command {
    let mut command = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
    command.current_dir(dir);
    // The scratch crate is built on its own, not as part of this test run.
    for var in [
        "CARGO_TARGET_DIR",
        "CARGO_BUILD_TARGET_DIR",
        "RUSTC_WORKSPACE_WRAPPER",
    ] {
        command.env_remove(var);
    }
    command
}

fn write_if_changed(path: &Path, contents: &str) {
    if fs::read_to_string(path).ok().as_deref() != Some(contents) {
        fs::write(path, contents).unwrap();
    }
}

fn expected_output(source: &str) -> String {
    let (first, len) = expected(source);
    format!("macro {first} {len}\nbuild {first} {len}\n")
}

#[test]
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
