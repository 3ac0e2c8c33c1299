//! Compile-fail tests for `period_table!`: every mistake is a compile error
//! at the offending token, saying what is expected.
//!
//! Each `tests/ui/*.rs` holds one mistake; its `.stderr` is the expected
//! output. Bless new or changed snapshots with
//! `TRYBUILD=overwrite cargo test --test compile_fail` and review them with
//! `git diff`. `tests/ui/README.md` lists which case covers which error.

#[test]
fn ui() {
    let t = trybuild::TestCases::new();
    t.compile_fail("tests/ui/*.rs");
}
