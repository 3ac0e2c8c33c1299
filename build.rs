//! Sets `cfg(ui_snapshots_compiler)` when the compiler building this package
//! is the one `tests/ui/RUSTC_VERSION` names (its `major.minor`): the
//! compile-fail snapshots (`tests/compile_fail.rs`) hold for that compiler
//! only, and are ignored on any other. Only the repository has this script;
//! the published package leaves it out, as it leaves out the tests.

use std::process::Command;

fn main() {
    println!("cargo::rustc-check-cfg=cfg(ui_snapshots_compiler)");
    println!("cargo::rerun-if-changed=tests/ui/RUSTC_VERSION");
    println!("cargo::rerun-if-changed=build.rs");
    let Ok(pinned) = std::fs::read_to_string("tests/ui/RUSTC_VERSION") else {
        return;
    };
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".into());
    let Ok(out) = Command::new(rustc).arg("--version").output() else {
        return;
    };
    // "rustc 1.95.0 (59807616e 2026-...)" -> "1.95"
    let version = String::from_utf8_lossy(&out.stdout);
    let number = version.split_whitespace().nth(1).unwrap_or("");
    let running: Vec<&str> = number.splitn(3, '.').take(2).collect();
    if running.join(".") == pinned.trim() {
        println!("cargo::rustc-cfg=ui_snapshots_compiler");
    }
}
