//! Tells the step paths which instruction set they are built for: on
//! Armv6-M and Armv8-M Baseline (`thumbv6m-*`, `thumbv8m.base-*`) most
//! instructions reach only eight registers and no instruction loads or
//! stores two words, so some hot paths order their loads and stores
//! differently there (cfg `thumb_low_registers`).

fn main() {
    println!("cargo:rustc-check-cfg=cfg(thumb_low_registers)");
    println!("cargo:rerun-if-changed=build.rs");
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv6m-") || target.starts_with("thumbv8m.base-") {
        println!("cargo:rustc-cfg=thumb_low_registers");
    }
}
