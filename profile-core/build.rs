//! Tells the step paths which instruction set they are built for: on
//! Armv6-M (`thumbv6m-*`) most instructions reach only eight registers and
//! there is no `ldrd`/`strd`, so some hot paths order their loads and
//! stores differently there (cfg `thumb_low_registers`).

fn main() {
    println!("cargo:rustc-check-cfg=cfg(thumb_low_registers)");
    println!("cargo:rerun-if-changed=build.rs");
    let target = std::env::var("TARGET").unwrap_or_default();
    if target.starts_with("thumbv6m-") {
        println!("cargo:rustc-cfg=thumb_low_registers");
    }
}
