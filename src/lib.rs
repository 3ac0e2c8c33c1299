#![doc = include_str!("../README.md")]
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

// The API, item by item: what firmware and hosts use. What the workspace's
// other crates share with `profile-core` and users do not (the schema, the
// pipeline, the emitter) is `profile_core::__private`, not re-exported here.
// ARCHITECTURE.md says where the API ends; tests/public_api.rs lists it.

// Tables, computed at compile time or at run time (no_std).
pub use profile_core::{
    AccelCurve, AccelWindows, Arithmetic, CheckedSpec, Curve, Discretization, Error, Exponential,
    ExponentialExtent, Figures, JerkLimited, Key, Linear, LinearExtent, MAX_ACCEL_POINTS,
    MAX_FLEXIBLE, MAX_LEN, MAX_MARGIN, Rounding, SegmentFigures, Sigmoid, Spec, TableWord,
    ThreeStage, Timer, TorqueLimited, Word,
};
// Playing tables, compressed runs, the motor and its simulation (no_std).
#[doc(inline)]
pub use profile_core::simulate;
pub use profile_core::{motor, player, runs};

/// The `fugit` crate whose durations [`player::Timed`] hands out (feature
/// `fugit`), so that a firmware names the same version.
#[cfg(feature = "fugit")]
pub use profile_core::fugit;

// Tables held on the host, and the runs' fitter (feature `std`).
#[cfg(feature = "std")]
pub use profile_core::{
    Compact, Generated, MAX_COMPRESS_TICKS, MIN_COMPRESS_TICKS, RunFigures, RunTable, SegmentTable,
    Table,
};

// Profiles files, build scripts and C output (feature `codegen`).
#[cfg(feature = "codegen")]
pub use profile_core::profiles;

// Golden files of tables for users' tests (feature `golden`).
#[cfg(feature = "golden")]
pub use profile_core::golden;

pub use profile_macros::{include_profiles, period_table};

pub mod guide;
