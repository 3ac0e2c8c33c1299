//! Stepper-motor acceleration tables computed at compile time.
#![no_std]
pub use profile_core::*;
pub use profile_macros::period_table;
