//! What the command's tests share: the binary, a fresh folder per test,
//! running the binary there, and its output as text.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The `stepper-profiles` binary Cargo built for the tests.
pub const BIN: &str = env!("CARGO_BIN_EXE_stepper-profiles");

/// An empty folder for the test `name` of the file `group`.
pub fn work_dir(group: &str, name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(group)
        .join(name);
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// The binary run with `args` in `dir`.
pub fn run(dir: &Path, args: &[&str]) -> Output {
    Command::new(BIN)
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| panic!("cannot run {BIN}: {e}"))
}

/// Output as text.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).unwrap()
}
