//! `golden::check` in a user's crate: a scratch crate under
//! `CARGO_TARGET_TMPDIR/golden-user` that depends on this package by path,
//! with the `golden` feature for its tests. Its test pins a `period_table!`
//! and every profile of its `profiles.toml`; the test here blesses them with
//! `UPDATE_GOLDEN=1`, checks them unchanged, then changes the table and reads
//! the failure.

use test_support as common;

use std::fs;
use std::process::Output;

use common::scratch::ScratchCrate;

const CARGO_TOML: &str = r#"[package]
name = "golden-user"
version = "0.0.0"
edition = "2024"
publish = false

[dependencies]
stepper-profiles = { path = "@ROOT@" }

[dev-dependencies]
stepper-profiles = { path = "@ROOT@", features = ["golden"] }

# Not part of any enclosing workspace.
[workspace]
"#;

const PROFILES_TOML: &str = r#"[profiles.slow]
curve = "linear"
fmin = "200 Hz"
fmax = "2 kHz"
len = 50
timer_hz = "1 MHz"

[profiles.compact]
curve = "exponential"
fmin = 500
fmax = 10_000
f_inf = 15_000
len = 120
timer_hz = 1_000_000
segments = 8
"#;

/// The user's test, pinning a table of `fmax`.
fn test_rs(fmax: &str) -> String {
    format!(
        r#"use stepper_profiles::{{golden, period_table}};

static RAMP: [u16; 100] = period_table!(
    curve = sigmoid, len = 100, fmin = 500, fmax = {fmax}, flexible = 6, timer_hz = 1MHz,
);

#[test]
fn ramp_is_unchanged() {{
    golden::check("tests/golden/ramp.txt", &golden::timed(&RAMP, 1_000_000));
}}

#[test]
fn profiles_are_unchanged() {{
    golden::check_file("tests/golden/profiles", "profiles.toml");
}}
"#
    )
}

struct Scratch(ScratchCrate);

impl Scratch {
    fn new() -> Self {
        let scratch = ScratchCrate::new(
            "golden-user",
            &[
                ("Cargo.toml", CARGO_TOML),
                ("src/lib.rs", ""),
                ("profiles.toml", PROFILES_TOML),
            ],
        );
        let _ = fs::remove_dir_all(scratch.dir.join("tests/golden"));
        Scratch(scratch)
    }

    fn test(&self, fmax: &str, bless: bool) -> Output {
        self.0.write("tests/tables.rs", &test_rs(fmax));
        let mut command = self.0.cargo();
        command.args(["test", "--quiet", "--test", "tables"]);
        if bless {
            command.env("UPDATE_GOLDEN", "1");
        }
        command.output().expect("cannot run cargo")
    }
}

fn text(output: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr)
    )
}

#[test]
#[ignore = "slow: builds a scratch crate with cargo; CI runs it with --ignored"]
fn a_user_crate_blesses_checks_and_reads_a_failure() {
    let scratch = Scratch::new();

    let blessed = scratch.test("20kHz", true);
    assert!(blessed.status.success(), "{}", text(&blessed));
    let ramp = fs::read_to_string(scratch.0.dir.join("tests/golden/ramp.txt")).unwrap();
    assert!(
        ramp.contains("# entries = 100\n# timer_hz = 1 MHz\n"),
        "{ramp}"
    );
    let slow = fs::read_to_string(scratch.0.dir.join("tests/golden/profiles/slow.txt")).unwrap();
    assert!(slow.contains("# fmax = 2 kHz\n"), "{slow}");
    let compact =
        fs::read_to_string(scratch.0.dir.join("tests/golden/profiles/compact.txt")).unwrap();
    assert!(
        compact.contains("# table = segments\n# entries = 8\n"),
        "{compact}"
    );

    let unchanged = scratch.test("20_000", false);
    assert!(unchanged.status.success(), "{}", text(&unchanged));

    let changed = scratch.test("21kHz", false);
    let out = text(&changed);
    assert!(!changed.status.success(), "a changed table passed:\n{out}");
    let message = out
        .lines()
        .find(|l| l.contains("tests/golden/ramp.txt: the table differs"))
        .unwrap_or_else(|| panic!("no golden failure in:\n{out}"));
    assert!(
        message.contains("entries differ, the first at entry ")
            && message.contains("the largest shift of a pulse edge is ")
            && message.contains(" us)")
            && message.ends_with("rerun with UPDATE_GOLDEN=1 and review the diff"),
        "{message}"
    );
}
