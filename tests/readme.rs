//! The README's examples that cannot run on the host are files CI builds:
//! the README shows them as they are.

use std::fs;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The step-interrupt firmware in the README is
/// `examples/firmware/examples/step_interrupt.rs`, which CI builds for a
/// Cortex-M3.
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
        block.trim_end(),
        file.trim_end(),
        "the README's step interrupt differs from examples/firmware/examples/step_interrupt.rs"
    );
}
