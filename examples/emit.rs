//! Prints what a profiles file generates: Rust modules (the text
//! `include_profiles!` expands to and the build-script API writes) or, with
//! `--c`, the C header.
//!
//! ```text
//! cargo run --example emit -- profiles.toml > profiles.rs
//! cargo run --example emit -- profiles.toml --c > profiles.h
//! ```

use std::process::ExitCode;

use profile_core::build::Profiles;

fn main() -> ExitCode {
    let mut c = false;
    let mut path = None;
    for arg in std::env::args().skip(1) {
        if arg == "--c" {
            c = true;
        } else {
            path = Some(arg);
        }
    }
    let Some(path) = path else {
        eprintln!("usage: cargo run --example emit -- PATH [--c]");
        return ExitCode::FAILURE;
    };
    match Profiles::load(&path) {
        Ok(p) => {
            print!("{}", if c { p.c_header() } else { p.rust_source() });
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::FAILURE
        }
    }
}
