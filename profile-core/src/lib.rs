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

#[cfg(feature = "std")]
extern crate std;

#[cfg(feature = "codegen")]
pub mod build;
mod curves;
#[cfg(feature = "codegen")]
pub mod emit;
mod error;
mod exponential;
mod generate;
mod jerk;
mod linear;
mod math;
pub mod motor;
#[cfg(feature = "codegen")]
pub mod params;
pub mod player;
mod segments;
mod sigmoid;
#[cfg(feature = "std")]
pub mod simulate;
mod solve;
mod spec;
#[cfg(feature = "std")]
mod table;
mod three_stage;
mod validate;

pub use error::{Error, Key};
pub use generate::{Figures, TableWord};
pub use segments::SegmentFigures;
pub use spec::{
    Arithmetic, Curve, Discretization, Exponential, ExponentialExtent, JerkLimited, Linear,
    LinearExtent, MAX_LEN, Rounding, Sigmoid, Spec, ThreeStage, Timer, Word,
};
#[cfg(feature = "std")]
pub use table::{SegmentTable, Table};
pub use validate::MAX_FLEXIBLE;
