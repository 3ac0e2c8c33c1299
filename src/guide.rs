//! The guide: what the front page leaves out, one page per subject, each
//! example compiled and run by `cargo test --doc`.
//!
//! These modules hold no items, only their pages. The measurements (the
//! player's instructions per step on Cortex-M, generation on the host, build
//! cost) are in the repository's
//! [`docs/performance.md`](https://github.com/stepper-profiles/stepper-profiles/blob/main/docs/performance.md).

#[doc = include_str!("guide/tables.md")]
pub mod tables {}

#[doc = include_str!("guide/profiles_file.md")]
pub mod profiles_file {}

#[doc = include_str!("guide/compression.md")]
pub mod compression {}

#[doc = include_str!("guide/golden_tests.md")]
pub mod golden_tests {}

#[doc = include_str!("guide/motor.md")]
pub mod motor {}

#[doc = include_str!("guide/moves.md")]
pub mod moves {}

#[doc = include_str!("guide/rtic.md")]
pub mod rtic {}

#[doc = include_str!("guide/firmware.md")]
pub mod firmware {}

#[doc = include_str!("guide/pio.md")]
pub mod pio {}

#[doc = include_str!("guide/rmt.md")]
pub mod rmt {}

#[doc = include_str!("guide/command_line.md")]
pub mod command_line {}

#[doc = include_str!("guide/logic_analyzer.md")]
pub mod logic_analyzer {}

#[doc = include_str!("guide/c_output.md")]
pub mod c_output {}
