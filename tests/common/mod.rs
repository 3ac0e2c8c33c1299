//! Support shared by the integration tests, included with `mod common;`.
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
//! Every test crate that says `mod common;` compiles all of it but uses only
//! part, hence the `dead_code` allowances.

#[allow(dead_code)]
pub mod cc;
#[allow(dead_code)]
pub mod golden;
#[allow(dead_code)]
pub mod lcg;
#[allow(dead_code)]
pub mod motors;
#[allow(dead_code)]
pub mod oracle;
#[allow(dead_code)]
pub mod scratch;
#[allow(dead_code)]
pub mod seeds;
