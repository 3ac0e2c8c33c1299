//! Writes the memory map of the board the target is measured on, and puts it
//! on the linker's search path.

use std::{env, fs, path::PathBuf};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let target = env::var("TARGET")?;
    // QEMU's boards: the micro:bit (nRF51822), the LM3S6965 evaluation
    // board, the MPS2 with the AN386 image.
    let (flash, ram) = match target.as_str() {
        "thumbv6m-none-eabi" => ("256K", "16K"),
        "thumbv7m-none-eabi" => ("256K", "64K"),
        _ => ("4M", "64K"),
    };
    let memory = format!(
        "MEMORY\n{{\n  FLASH : ORIGIN = 0x00000000, LENGTH = {flash}\n  RAM : ORIGIN = 0x20000000, LENGTH = {ram}\n}}\n"
    );
    // RTIC's backend (src/bin/rtic.rs) exists for the M3 and M4F only.
    println!("cargo::rustc-check-cfg=cfg(rtic)");
    if target != "thumbv6m-none-eabi" {
        println!("cargo::rustc-cfg=rtic");
    }
    let out = PathBuf::from(env::var("OUT_DIR")?);
    fs::write(out.join("memory.x"), memory)?;
    println!("cargo::rustc-link-search={}", out.display());
    println!("cargo::rerun-if-changed=build.rs");
    Ok(())
}
