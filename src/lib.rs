#![doc = include_str!("../README.md")]
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

// The API, item by item: what firmware uses from `profile-core`
// (no_std, allocation-free), and with the features `std`, `codegen` and
// `golden` what hosts use from `profile-codegen`. What the workspace's
// other crates share with `profile-codegen` and users do not (the schema,
// the pipeline, the emitter) is `profile_codegen::__private`, not
// re-exported here. ARCHITECTURE.md says where the API ends;
// tests/public_api.rs lists it.

// Tables, computed at compile time or at run time (no_std).
pub use profile_core::{
    AccelCurve, AccelWindows, Arithmetic, CheckedSpec, CompactFigures, Curve, Discretization,
    Error, Exponential, ExponentialExtent, Figures, JerkLimited, Key, Linear, LinearExtent,
    MAX_ACCEL_POINTS, MAX_FLEXIBLE, MAX_LEN, MAX_MARGIN, MessageNumber, Rounding, Sigmoid, Spec,
    TableWord, ThreeStage, Timer, TorqueLimited, Word,
};
// Playing tables, and compressed runs (no_std).
pub use profile_core::{player, runs};

/// The `fugit` crate whose durations [`player::Timed`] hands out (feature
/// `fugit`), so that a firmware names the same version.
#[cfg(feature = "fugit")]
pub use profile_core::fugit;

// Tables held on the host, the runs' fitter, the motor model and its
// simulation (feature `std`).
#[cfg(feature = "std")]
#[doc(inline)]
pub use profile_codegen::simulate;
#[cfg(feature = "std")]
pub use profile_codegen::{
    Generated, MAX_COMPRESS_TICKS, MIN_COMPRESS_TICKS, RunTable, SegmentTable, SpecTables, Table,
    motor,
};

// Profiles files, build scripts and C output (feature `codegen`).
#[cfg(feature = "codegen")]
pub use profile_codegen::profiles;

// Golden files of tables for users' tests (feature `golden`).
#[cfg(feature = "golden")]
pub use profile_codegen::golden;

pub use profile_macros::{include_profiles, period_table};

pub mod guide;
