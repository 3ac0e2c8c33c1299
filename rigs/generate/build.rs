//! Writes the memory map of the board the target is measured on, and puts it
//! on the linker's search path (as `rigs/measure` does); compiles the S-curve
//! article's C function (`c/article.c`) for the same core with
//! `arm-none-eabi-gcc -O2`, twice (the second time with `-ffp-contract=off`,
//! as `CalculateSModelLine_nocontract`), and links it with newlib's `libm.a`
//! (its `expf`) and `libc.a` (the `__errno` that `expf` sets).
//!
//! The soft-float helpers the C calls (`__aeabi_fmul`, `__aeabi_ddiv`, ...)
//! come from Rust's `compiler_builtins`: libgcc is not linked, so that no
//! helper is defined twice.

use std::{
    env, fs,
    path::{Path, PathBuf},
    process::Command,
};

type Result<T> = std::result::Result<T, Box<dyn std::error::Error>>;

/// Runs `command`, failing the build with its output if it fails.
fn run(command: &mut Command) -> Result<String> {
    let output = command
        .output()
        .map_err(|e| format!("{command:?}: {e} (is arm-none-eabi-gcc installed?)"))?;
    if !output.status.success() {
        return Err(format!(
            "{command:?} failed:\n{}{}",
            String::from_utf8_lossy(&output.stdout),
            String::from_utf8_lossy(&output.stderr)
        )
        .into());
    }
    Ok(String::from_utf8(output.stdout)?.trim().to_owned())
}

fn main() -> Result<()> {
    let target = env::var("TARGET")?;
    let out = PathBuf::from(env::var("OUT_DIR")?);
    // QEMU's boards: the micro:bit (nRF51822), the LM3S6965 evaluation
    // board, the MPS2 with the AN386 image; and gcc's flags for their cores.
    let (flash, ram, cpu): (_, _, &[&str]) = match target.as_str() {
        "thumbv6m-none-eabi" => ("256K", "16K", &["-mcpu=cortex-m0"]),
        "thumbv7m-none-eabi" => ("256K", "64K", &["-mcpu=cortex-m3"]),
        _ => (
            "4M",
            "64K",
            &["-mcpu=cortex-m4", "-mfloat-abi=hard", "-mfpu=fpv4-sp-d16"],
        ),
    };
    let memory = format!(
        "MEMORY\n{{\n  FLASH : ORIGIN = 0x00000000, LENGTH = {flash}\n  RAM : ORIGIN = 0x20000000, LENGTH = {ram}\n}}\n"
    );
    fs::write(out.join("memory.x"), memory)?;
    println!("cargo::rustc-link-search={}", out.display());

    // The article's function, as gcc compiles it by default (contraction
    // of `delt * deno + fre_min` into a fused multiply-add allowed where
    // the core has one) and without contraction.
    let gcc = || {
        let mut gcc = Command::new("arm-none-eabi-gcc");
        gcc.args(["-O2", "-mthumb", "-ffunction-sections", "-fdata-sections"])
            .args(cpu);
        gcc
    };
    let source = Path::new("c/article.c");
    let variants: [(&str, &[&str]); 2] = [
        ("article.o", &[]),
        (
            "article_nocontract.o",
            &[
                "-ffp-contract=off",
                "-DCalculateSModelLine=CalculateSModelLine_nocontract",
            ],
        ),
    ];
    let mut objects = Vec::new();
    for (name, flags) in variants {
        let object = out.join(name);
        run(gcc()
            .args(flags)
            .arg("-c")
            .arg(source)
            .arg("-o")
            .arg(&object))?;
        objects.push(object);
    }
    let archive = out.join("libarticle.a");
    let _ = fs::remove_file(&archive);
    run(Command::new("arm-none-eabi-ar")
        .arg("crs")
        .arg(&archive)
        .args(&objects))?;
    println!("cargo::rustc-link-lib=static=article");

    // newlib for this core's multilib: where gcc itself would find it.
    let libm = PathBuf::from(run(gcc().arg("-print-file-name=libm.a"))?);
    let newlib = libm
        .parent()
        .filter(|_| libm.is_absolute())
        .ok_or_else(|| format!("arm-none-eabi-gcc does not know libm.a: {}", libm.display()))?;
    println!("cargo::rustc-link-search=native={}", newlib.display());
    println!("cargo::rustc-link-lib=static=m");
    println!("cargo::rustc-link-lib=static=c");

    println!("cargo::rerun-if-changed=c/article.c");
    println!("cargo::rerun-if-changed=build.rs");
    Ok(())
}
