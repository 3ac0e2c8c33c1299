#![doc = include_str!("../README.md")]
#![no_std]
#![forbid(unsafe_code)]

pub use profile_core::*;
pub use profile_macros::{include_profiles, period_table};

pub mod guide;
