//! Compile-fail tests for `period_table!`: every mistake is a compile error
//! at the offending token, saying what is expected.
//!
//! Each `tests/ui/*.rs` holds one mistake; its `.stderr` is the expected
//! output. Bless new or changed snapshots with
//! `TRYBUILD=overwrite cargo test --test compile_fail` and review them with
//! `git diff`. `tests/ui/README.md` lists which case covers which error.
//!
//! rustc's rendering of an error (the snippet, the notes it adds) changes
//! between releases, so the snapshots hold for the compiler they were written
//! with, named in `tests/ui/RUSTC_VERSION`. On any other the comparison is
//! skipped with a notice; CI installs that compiler and runs them there.

use std::process::Command;

/// `major.minor` of the compiler the snapshots were written with.
fn pinned() -> String {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/ui/RUSTC_VERSION");
    std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("cannot read {path}: {e}"))
        .trim()
        .to_string()
}

/// `major.minor` of the compiler that builds the cases (trybuild runs
/// `cargo`, which runs the same `rustc` as this process would).
fn running() -> String {
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let out = Command::new(&rustc)
        .arg("--version")
        .output()
        .unwrap_or_else(|e| panic!("cannot run `{rustc} --version`: {e}"));
    let version = String::from_utf8_lossy(&out.stdout);
    // "rustc 1.95.0 (59807616e 2026-...)"
    let number = version.split_whitespace().nth(1).unwrap_or("");
    number.splitn(3, '.').take(2).collect::<Vec<_>>().join(".")
}

#[test]
fn ui() {
    let (pinned, running) = (pinned(), running());
    if pinned != running {
        eprintln!(
            "notice: tests/ui snapshots were written with rustc {pinned}; this is rustc \
             {running}: not compared. Run `cargo +{pinned} test --test compile_fail`, or bless \
             them with this compiler (TRYBUILD=overwrite), review, and update \
             tests/ui/RUSTC_VERSION."
        );
        return;
    }
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
