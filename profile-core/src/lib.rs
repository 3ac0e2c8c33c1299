//! Stepper-motor acceleration curves turned into timer-period tables.
//!
//! A step-pulse timer is reloaded once per step; entry `k` of a period table
//! is the number of timer ticks between step `k` and step `k + 1`. This crate
//! computes such tables from a curve ([`Curve`]), a timer ([`Timer`]) and a
//! choice of [`Discretization`] and [`Rounding`], bit-identically on every host
//! and target (`libm` everywhere, no fused multiply-add, integers out).
//!
//! It is `#![no_std]` and allocation-free: firmware can call
//! [`Spec::generate`] at run time and get the same bits the `period_table!`
//! macro puts in flash at compile time.
//!
//! ```
//! use profile_core::{Curve, Sigmoid, Spec, Timer};
//!
//! let spec = Spec::new(
//!     Curve::Sigmoid(Sigmoid { fmin: 500.0, fmax: 64_000.0, flexible: 8.0, len: 1000 }),
//!     Timer::new(10_000_000),
//! );
//! let mut table = [0u16; 1000];
//! let figures = spec.generate(&mut table)?;
//! // Default mode: every pulse edge within half a tick of the continuous curve.
//! assert!(figures.max_edge_error_ticks <= 0.5);
//! # Ok::<(), profile_core::Error>(())
//! ```
#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

#[cfg(test)]
extern crate std;

mod base;
mod curves;
pub mod player;
mod table;

/// The `fugit` crate whose durations [`player::Timed`] hands out (feature
/// `fugit`), so that a firmware names the same version.
#[cfg(feature = "fugit")]
pub use fugit;

pub use base::MAX_LEN;
pub use base::error::Error;
pub use base::key::Key;
pub use base::modes::{Arithmetic, Discretization, Rounding};
pub use base::numbers::MessageNumber;
pub use base::timer::{TableWord, Timer, Word};
pub use curves::public::*;
pub use table::quantize::{AccelWindows, Figures};
pub use table::runs;
pub use table::segments::CompactFigures;
pub use table::spec::{CheckedSpec, Spec};
