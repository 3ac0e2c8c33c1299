//! Support shared by the integration tests of `stepper-profiles`: a crate
//! of its own, compiled once and linked into every test that says `use
//! test_support as common;` (not published).
//!
//! - [`golden`]: golden files of tables (`# key = value` header, then the
//!   entries), read, written under `UPDATE_GOLDEN=1`, and compared with the
//!   mismatches described;
//! - [`cc`]: a C program written to a temporary folder, compiled with `cc` (or
//!   `$CC`) once per test process, and run;
//! - [`oracle`]: pulse-edge times by numeric integration of each curve's
//!   frequency, sharing no formula with `profile-core`;
//! - [`scratch`]: user crates on disk, depending on this package by path,
//!   built by Cargo into one shared target directory;
//! - [`lcg`]: a fixed, dependency-free stream of pseudo-random numbers;
//! - [`motors`]: the NEMA 17 of the motor tests;
//! - [`seeds`]: the seeds' own curves and calls, as specs and as
//!   `period_table!` expands them.
//!
//! [`paths`]: the package's folder and the target's scratch folder.

pub mod cc;
pub mod golden;
pub mod lcg;
pub mod motors;
pub mod oracle;
pub mod paths;
pub mod scratch;
pub mod seeds;
