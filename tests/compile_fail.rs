//! Compile-fail tests for `period_table!`: every mistake is a compile error
//! at the offending token, saying what is expected.
//!
//! Each `tests/ui/*.rs` holds one mistake; its `.stderr` is the expected
//! output. Bless new or changed snapshots with
//! `TRYBUILD=overwrite cargo test --test compile_fail -- --ignored` and
//! review them with `git diff`. `tests/ui/README.md` lists which case
//! covers which error.
//!
//! rustc's rendering of an error (the snippet, the notes it adds) changes
//! between releases, so the snapshots hold for the compiler they were written
//! with, named in `tests/ui/RUSTC_VERSION`. The package's build script
//! (`build.rs`) compares it with the compiler at hand; on any other the test
//! is ignored, and `cargo test` says so. On that compiler it is ignored too,
//! as slow (it builds a crate per case): `cargo test -- --ignored` runs it.
//! CI installs that compiler, runs the ignored tests there and fails unless
//! this one ran (`.ci/run`).

#[test]
#[cfg_attr(
    not(ui_snapshots_compiler),
    ignore = "the snapshots hold for the compiler named in tests/ui/RUSTC_VERSION: run \
              `cargo +VERSION test --test compile_fail -- --ignored` with it, or bless them with this one \
              (TRYBUILD=overwrite), review, and update RUSTC_VERSION"
)]
#[cfg_attr(
    ui_snapshots_compiler,
    ignore = "slow: builds a crate per case; CI runs it with --ignored"
)]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
