//! `profiles::build_script` in a user's crate, as the README and the guide show it: a
//! scratch crate under `CARGO_TARGET_TMPDIR/build-script-user` depending on
//! this package by path. A bad `profiles.toml` fails `cargo build` with
//! cargo's own `error:` lines (location, source line, caret); a good one
//! builds, runs and leaves the C header under `OUT_DIR`, not in the source
//! tree.

use test_support as common;

use std::process::Output;

use common::scratch::ScratchCrate;

const CARGO_TOML: &str = r#"[package]
name = "build-script-user"
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

const BUILD_RS: &str = r#"fn main() {
    if let Some(profiles) = profile_codegen::profiles::build_script("profiles.toml") {
        profiles.write_c_header("profiles.h").expect("OUT_DIR is writable");
    }
}
"#;

const MAIN_RS: &str = r#"include!(concat!(env!("OUT_DIR"), "/profiles.rs"));

fn main() {
    println!("{} {}", ramp::PERIODS[0], ramp::LEN);
}
"#;

fn profiles(fmax_key: &str) -> String {
    format!(
        "[profiles.ramp]\ncurve = \"linear\"\nfmin = 500\n{fmax_key} = \"5 kHz\"\nlen = 100\n\
         timer_hz = \"1 MHz\"\n"
    )
}

fn cargo(scratch: &ScratchCrate, args: &[&str]) -> Output {
    scratch
        .cargo()
        .args(args)
        .output()
        .expect("cannot run cargo")
}

#[test]
#[ignore = "slow: builds a scratch crate with cargo; CI runs it with --ignored"]
fn a_bad_file_fails_the_build_with_cargo_errors_and_a_good_one_builds() {
    let scratch = ScratchCrate::new(
        "build-script-user",
        &[
            ("Cargo.toml", CARGO_TOML),
            ("build.rs", BUILD_RS),
            ("src/main.rs", MAIN_RS),
        ],
    );
    scratch.write("profiles.toml", &profiles("fmx"));
    let bad = cargo(&scratch, &["build", "--quiet"]);
    let stderr = String::from_utf8_lossy(&bad.stderr);
    assert!(!bad.status.success(), "a bad file built:\n{stderr}");
    let prefix = "error: build-script-user@0.0.0: ";
    let expected = [
        format!("{prefix}profiles.toml:4:1: unknown key `fmx`; did you mean `fmax`?"),
        format!("{prefix}  |"),
        format!("{prefix}4 | fmx = \"5 kHz\""),
        format!("{prefix}  | ^^^"),
    ];
    let lines: Vec<&str> = stderr.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.starts_with(&expected[0]))
        .unwrap_or_else(|| panic!("no located error in:\n{stderr}"));
    assert_eq!(lines[at + 1..at + 4], expected[1..], "{stderr}");
    assert!(!stderr.contains("LoadError"), "{stderr}");

    scratch.write("profiles.toml", &profiles("fmax"));
    let good = cargo(&scratch, &["run", "--quiet"]);
    assert!(
        good.status.success(),
        "{}",
        String::from_utf8_lossy(&good.stderr)
    );
    // What the loader computes here, for the same file.
    let loaded =
        profile_codegen::profiles::Profiles::parse("profiles.toml", &profiles("fmax")).unwrap();
    let first = loaded.profiles()[0].table.step_periods()[0];
    assert_eq!(
        String::from_utf8_lossy(&good.stdout).trim(),
        format!("{first} 100")
    );
    assert!(
        !scratch.dir.join("profiles.h").exists(),
        "the header went into the source tree"
    );
}
