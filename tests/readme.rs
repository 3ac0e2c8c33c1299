//! The README's examples that cannot run on the host are files CI builds:
//! the README shows them as they are.

use std::fs;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// What `examples/firmware/examples/step_interrupt.rs` holds after the
/// README's block: the harness that times its step pin in QEMU, and nothing
/// else.
const HARNESS: &str = "

// Not in the README: the harness that times the step pin in QEMU.
#[path = \"harness/step_interrupt.rs\"]
mod harness;";

/// The step-interrupt firmware in the README is
/// `examples/firmware/examples/step_interrupt.rs`, which CI runs on a
/// Cortex-M3 in QEMU: the README's code, then the harness.
#[test]
fn the_step_interrupt_example_is_the_file_ci_builds() {
    let readme = fs::read_to_string(root().join("README.md")).unwrap();
    let file =
        fs::read_to_string(root().join("examples/firmware/examples/step_interrupt.rs")).unwrap();
    let block = readme
        .split("```rust,ignore\n")
        .find(|b| b.contains("fn SysTick()"))
        .and_then(|b| b.split("\n```").next())
        .expect("a `rust,ignore` block with the SysTick handler in the README");
    assert_eq!(
        format!("{}{}", block.trim_end(), HARNESS),
        file.trim_end(),
        "the README's step interrupt differs from examples/firmware/examples/step_interrupt.rs"
    );
}

/// Every figure the README shows is in `docs/` (the README links them by
/// their address on the main branch), and every figure there is shown.
#[test]
fn the_readme_figures_are_in_docs() {
    let readme = fs::read_to_string(root().join("README.md")).unwrap();
    let prefix = "https://raw.githubusercontent.com/stepper-profiles/stepper-profiles/main/docs/";
    let mut shown: Vec<&str> = readme
        .split(prefix)
        .skip(1)
        .map(|rest| rest.split(')').next().unwrap())
        .collect();
    shown.sort_unstable();
    shown.dedup();
    let mut files: Vec<String> = fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort_unstable();
    assert_eq!(shown, files);
}
