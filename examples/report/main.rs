//! The main job: read a profiles file and print every profile's figures.
//!
//! ```text
//! cargo run --example report [-- PATH]
//! ```
//!
//! PATH defaults to the `profiles.toml` at the root of this repository. A
//! mistake in the file prints `file:line:col: message` and exits with status 1.

use std::process::ExitCode;

use profile_core::build::Profiles;
use profile_core::emit::Generated;

fn main() -> ExitCode {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| concat!(env!("CARGO_MANIFEST_DIR"), "/profiles.toml").to_string());
    let profiles = match Profiles::load(&path) {
        Ok(p) => p,
        Err(e) => {
            eprintln!("{e}");
            return ExitCode::FAILURE;
        }
    };
    println!("{path}: {} profiles\n", profiles.profiles().len());
    println!(
        "{:<22} {:<13} {:<22} {:>5} {:>10} {:>10} {:>10} {:>7} {:>11} {:>10} {:>9}",
        "profile",
        "curve",
        "discretization/round",
        "len",
        "start Hz",
        "end Hz",
        "ramp s",
        "flash B",
        "max a Hz/s",
        "edge tick",
        "margin"
    );
    for p in profiles.profiles() {
        match &p.table {
            Generated::Steps(t) => {
                let f = &t.figures;
                let s = &t.spec;
                let word_bytes = match s.timer.word {
                    profile_core::Word::U16 => 2,
                    profile_core::Word::U32 => 4,
                };
                println!(
                    "{:<22} {:<13} {:<22} {:>5} {:>10.2} {:>10.2} {:>10.6} {:>7} {:>11.0} {:>10.3} {:>9}",
                    p.name,
                    s.curve.name(),
                    format!("{}/{}", s.discretization.name(), s.rounding.name()),
                    f.len,
                    f.start_hz,
                    f.final_hz,
                    f.duration_s,
                    f.len as usize * word_bytes,
                    f.max_accel_hz_s,
                    f.max_edge_error_ticks,
                    f.overflow_margin_ticks,
                );
            }
            Generated::Segments(t) => {
                let f = &t.figures;
                let s = &t.spec;
                println!(
                    "{:<22} {:<13} {:<22} {:>5} {:>10} {:>10} {:>10.6} {:>7} {:>11} {:>10.3} {:>9}",
                    p.name,
                    s.curve.name(),
                    format!("{} segments", f.segments),
                    f.steps,
                    "-",
                    "-",
                    f.duration_s,
                    f.flash_bytes,
                    "-",
                    f.max_edge_error_ticks,
                    "-",
                );
            }
        }
    }
    ExitCode::SUCCESS
}
