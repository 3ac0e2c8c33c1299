//! Where the tests' files go: what Cargo tells an integration test at
//! compile time (`CARGO_MANIFEST_DIR`, `CARGO_TARGET_TMPDIR`), for a
//! library that Cargo does not tell.

use std::path::{Path, PathBuf};

/// The folder of the `stepper-profiles` package: two above this crate's.
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("this crate is tests/support in the package")
}

/// The target directory's scratch folder, `<target>/tmp`, as Cargo names
/// it for integration tests: found from the running test's own path,
/// `<target>/<profile>/deps/<test>`, and created if need be.
pub fn target_tmpdir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test knows its own path");
    let target = exe
        .ancestors()
        .nth(3)
        .unwrap_or_else(|| panic!("expected {} under <target>/<profile>/deps", exe.display()));
    let tmp = target.join("tmp");
    std::fs::create_dir_all(&tmp)
        .unwrap_or_else(|e| panic!("cannot create {}: {e}", tmp.display()));
    tmp
}
